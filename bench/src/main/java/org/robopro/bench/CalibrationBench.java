package org.robopro.bench;

import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;
import org.robopro.calibration.identification.CalibrationResult;
import org.robopro.calibration.identification.Calibrator;
import org.robopro.calibration.simulation.Campaign;
import org.robopro.calibration.simulation.CampaignSimulator;
import org.robopro.calibration.simulation.SimulationSettings;
import org.robopro.kinematics.KinematicModel;
import org.robopro.models.RobotLibrary;

/**
 * Target (docs/performance.md): identification of the IRB-2000 from 200 position measurements (σ 0.02 mm,
 * 10 mm of initial error, unknown instrument frame) in ≤ 25 ms warm, single thread. Measures the
 * whole {@link Calibrator#calibrate} (nominal fit, identifiability, LM, outlier check, σ, per-pose
 * errors); the structural identifiability analysis is cached per model after the first call.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 3, time = 2)
@Measurement(iterations = 5, time = 2)
@Fork(1)
public class CalibrationBench {
    KinematicModel nominal;
    Campaign campaign;

    @Setup
    public void setup() {
        nominal = KinematicModel.build(RobotLibrary.load("irb2000"));
        campaign = CampaignSimulator.simulate(nominal, SimulationSettings.defaults().withSeed(7));
    }

    @Benchmark
    public CalibrationResult identifyIrb2000From200Positions() {
        return Calibrator.calibrate(nominal, campaign.measurements(), null);
    }
}
