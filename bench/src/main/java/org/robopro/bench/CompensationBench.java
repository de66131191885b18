package org.robopro.bench;

import java.util.List;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OperationsPerInvocation;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;
import org.robopro.calibration.compensation.Compensator;
import org.robopro.calibration.simulation.Campaign;
import org.robopro.calibration.simulation.CampaignSimulator;
import org.robopro.calibration.simulation.PoseSampler;
import org.robopro.calibration.simulation.SimulationSettings;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.RobotLibrary;

/**
 * Target (docs/performance.md): compensation (seed paper Fig. 5, iterated to 1e-8 m / 1e-8 rad) of at least
 * 100,000 targets per second, single thread, IRB-2000 with a 10 mm-error calibrated model.
 * Throughput in targets per second = 1 / (time per target).
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.SECONDS)
@Warmup(iterations = 3, time = 2)
@Measurement(iterations = 5, time = 2)
@Fork(1)
public class CompensationBench {
    static final int N = 1000;
    Compensator.Batch batch;
    double[][] pos = new double[N][], quat = new double[N][];
    double[][] pathPos = new double[N][], pathQuat = new double[N][];
    double[] pathStart;
    final double[] q = new double[6], cmd = new double[7], res = new double[2];

    @Setup
    public void setup() {
        KinematicModel nominal = KinematicModel.build(RobotLibrary.load("irb2000"));
        Campaign c = CampaignSimulator.simulate(nominal, SimulationSettings.defaults().withSeed(7).withBaseFrame(true));
        Pose tool = Pose.translation(0, 0, 0.1);
        batch = new Compensator(nominal, c.truth().model(), tool, tool).batch();
        List<double[]> qs = new PoseSampler(nominal).sample(N, new Random(3));
        for (int i = 0; i < N; i++) {
            Pose t = nominal.flange(qs.get(i)).times(tool);
            pos[i] = new double[] {t.x(), t.y(), t.z()};
            quat[i] = t.quaternion();
        }
        // A path: joints sweep smoothly between two poses; targets every ~2 mm along it.
        double[] a = qs.get(0), b = qs.get(1);
        pathStart = a.clone();
        for (int i = 0; i < N; i++) {
            double[] qi = new double[6];
            for (int j = 0; j < 6; j++) qi[j] = a[j] + (b[j] - a[j]) * i / (N - 1.0);
            Pose t = nominal.flange(qi).times(tool);
            pathPos[i] = new double[] {t.x(), t.y(), t.z()};
            pathQuat[i] = t.quaternion();
        }
    }

    /** Unrelated targets: every one needs the closed-form nominal IK (seed far away), then Newton. */
    @Benchmark
    @OperationsPerInvocation(N)
    public double compensateRandomTargets() {
        double acc = 0;
        for (int i = 0; i < N; i++) {
            java.util.Arrays.fill(q, 0);
            batch.compensate(pos[i], quat[i], q, cmd, res);
            acc += cmd[0];
        }
        return acc;
    }

    /** Targets along a path, each seeded by the previous one's joints (how programs are compensated). */
    @Benchmark
    @OperationsPerInvocation(N)
    public double compensatePathTargets() {
        double acc = 0;
        System.arraycopy(pathStart, 0, q, 0, 6);
        for (int i = 0; i < N; i++) {
            batch.compensate(pathPos[i], pathQuat[i], q, cmd, res);
            acc += cmd[0];
        }
        return acc;
    }
}
