package org.robopro.bench;

import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;
import org.robopro.calibration.diagnosis.ConcealedEffectBenchmark;
import org.robopro.calibration.diagnosis.Diagnoser;
import org.robopro.calibration.diagnosis.Diagnosis;
import org.robopro.calibration.simulation.Campaign;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;

/**
 * Speed target (docs/performance.md): a full diagnosis (geometric calibration, ~50 candidates, stepwise
 * selection with joint re-identification) of 300 IRB-2000 poses in under 5 s on one core.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 2)
@Measurement(iterations = 3)
@Fork(value = 1, jvmArgs = {"-XX:ActiveProcessorCount=1"})
public class DiagnosisBench {
    @Param({"null (geometric errors only)", "backlash j2 + thermal-expansion", "joint-compliance j2 + j3"})
    String scenario;

    RobotDescription robot;
    Campaign campaign;

    @Setup
    public void setup() {
        robot = RobotLibrary.shipped("irb2000");
        campaign = ConcealedEffectBenchmark.campaign(scenario, 20260401L, 300);
    }

    @Benchmark
    public Diagnosis diagnose300Poses() {
        return Diagnoser.diagnose(robot, campaign.measurements(), campaign.validation());
    }
}
