package org.robopro.bench;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.robopro.kinematics.IkSolution;
import org.robopro.kinematics.IkSolver;
import org.robopro.kinematics.InverseKinematics;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.CouplingTerm;
import org.robopro.models.FrameDescription;
import org.robopro.models.JointDescription;
import org.robopro.models.JointType;
import org.robopro.models.RobotDescription;
import org.robopro.models.Vec3;

/**
 * Speed targets (docs/performance.md) on the IRB-2000 (single thread): FK <= 150 ns, identification
 * Jacobian (all parameters, position) <= 2 us, closed-form IK all solutions <= 1.5 us,
 * numerical IK <= 30 us. The robot is built here from robots.md so the benchmark does not
 * depend on the robot files. {@code IkSolver} benchmarks are the allocation-free paths; the
 * others are the convenience API (which allocates its results).
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
public class KinematicsBench {
    KinematicModel model;
    KinematicModel calibrated;
    InverseKinematics ik, ikCalibrated;
    IkSolver solver;
    double[] qOut = new double[6];
    KinematicModel.Workspace ws;
    double[] q = {0.3, 0.2, -0.1, 0.5, 0.7, -0.4};
    double[] seed = {0.25, 0.25, -0.05, 0.45, 0.75, -0.35};
    double[] out12 = new double[12], pos = new double[3], jac, point = {0, 0, 0.1};
    double[] target12 = new double[12];
    double[][] thetas = new double[8][6];
    Pose target, targetCalibrated;

    static RobotDescription irb2000() {
        double d = Math.PI / 180;
        return new RobotDescription("irb2000", "ABB IRB 2000", List.of(
                new JointDescription("j1", JointType.REVOLUTE, new Vec3(0, 0, 0), Vec3.Z, -180 * d, 180 * d, 150 * d),
                new JointDescription("j2", JointType.REVOLUTE, new Vec3(0, 0, 0.78), Vec3.Y, -100 * d, 100 * d, 150 * d),
                new JointDescription("j3", JointType.REVOLUTE, new Vec3(0, 0, 1.49), Vec3.Y, -60 * d, 60 * d, 150 * d),
                new JointDescription("j4", JointType.REVOLUTE, new Vec3(0, 0, 1.615), Vec3.X, -200 * d, 200 * d, 360 * d),
                new JointDescription("j5", JointType.REVOLUTE, new Vec3(0.85, 0, 1.615), Vec3.Y, -120 * d, 120 * d, 360 * d),
                new JointDescription("j6", JointType.REVOLUTE, new Vec3(0.85, 0, 1.615), Vec3.X, -200 * d, 200 * d, 450 * d)),
                new FrameDescription(new Vec3(1.0, 0, 1.615), new Vec3(0, 0, -1), Vec3.X),
                List.of(new CouplingTerm(3, 3, 1), new CouplingTerm(3, 2, -1)), Optional.empty(), List.of(), List.of(),
                "robots.md", Map.of());
    }

    @Setup
    public void setup() {
        model = KinematicModel.build(irb2000());
        ws = model.newWorkspace();
        jac = new double[3 * model.parameters().size()];
        ik = InverseKinematics.of(model);
        solver = ik.newSolver();
        target = model.flange(q);
        model.flange(q, ws, target12);
        double[] p = model.parameterValues();
        java.util.Random r = new java.util.Random(1);
        for (int i = 0; i < p.length; i++) p[i] += 1e-3 * r.nextGaussian();
        calibrated = KinematicModel.build(model.withParameterValues(p).toDescription());
        ikCalibrated = InverseKinematics.of(calibrated);
        targetCalibrated = calibrated.flange(q);
    }

    @Benchmark
    public double[] forwardKinematics() {
        model.flange(q, ws, out12);
        return out12;
    }

    @Benchmark
    public double[] identificationJacobianPosition() {
        model.pointJacobian(q, point, ws, pos, jac);
        return jac;
    }

    @Benchmark
    public double[][] closedFormIkAllSolutions() {
        ik.closedFormThetas(target12, thetas);
        return thetas;
    }

    /** All solutions with confdata, limits and manipulability, allocation-free (the fast public path). */
    @Benchmark
    public int closedFormIkSolverSolveAll() {
        return solver.solveAll(target12) + solver.cfx(0);
    }

    @Benchmark
    public List<IkSolution> closedFormIkSolveAllApi() {
        return ik.solveAll(target);
    }

    @Benchmark
    public InverseKinematics.NumericalOutcome numericalIkFromNearbySeed() {
        return ik.solveNumerical(target, seed);
    }

    @Benchmark
    public double[] numericalIkSolverFromNearbySeed() {
        solver.solveNumerical(target12, seed, qOut);
        return qOut;
    }

    @Benchmark
    public Optional<IkSolution> numericalIkCalibratedSolveNear() {
        return ikCalibrated.solveNear(targetCalibrated, seed);
    }
}
