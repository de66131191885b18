package org.robopro.calibration.compensation;

import java.util.Optional;
import org.robopro.calibration.PoseConditions;
import org.robopro.calibration.diagnosis.ExtendedModel;
import org.robopro.kinematics.IkSolution;
import org.robopro.kinematics.InverseKinematics;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.RobotDescription;
import org.robopro.models.Vec3;

/**
 * Base-coordinate compensation, seed paper Fig. 5: a target X_target goes through the nominal
 * inverse model to q_N, the calibrated model predicts where the robot really goes at q_N, the
 * difference moves the commanded coordinates X_comp, and this repeats until the calibrated
 * prediction at the commanded joint values lands on the target. The controller, which knows only
 * the nominal model, is then sent X_comp (or the joint values q). Positions and orientations
 * are both compensated. Immutable and thread-safe apart from {@link Batch}, which is one per thread.
 */
public final class Compensator {
    /** Convergence: position (m) and orientation (rad) residual of the calibrated prediction. */
    public static final double POSITION_TOLERANCE = 1e-8, ROTATION_TOLERANCE = 1e-8;
    public static final int MAX_ITERATIONS = 30;

    /** How a compensation ended. */
    public enum Status { CONVERGED, NOT_CONVERGED, UNREACHABLE, OUT_OF_LIMITS }

    /**
     * @param commanded  X_comp: the coordinates to send to the nominal controller (same frame as the target)
     * @param q          the joint values the nominal controller computes for X_comp (send these instead if it takes joints)
     * @param residualM  distance between the target and the calibrated prediction at q, m
     * @param residualRad angle between them, rad
     * @param iterations Fig. 5 iterations used
     * @param status     how it ended
     */
    public record Result(Pose commanded, double[] q, double residualM, double residualRad, int iterations, Status status) { }

    private final KinematicModel nominal, calibrated;
    private final ExtendedModel extended; // null: geometry only
    private final PoseConditions conditions;
    private final Pose toolNominal, toolCalibrated;
    private final InverseKinematics ik;

    /**
     * @param nominal         the controller's model
     * @param calibrated      the identified model
     * @param toolNominal     flangeTtool as the controller knows it
     * @param toolCalibrated  flangeTtool as calibrated (often the same tool)
     */
    public Compensator(KinematicModel nominal, KinematicModel calibrated, Pose toolNominal, Pose toolCalibrated) {
        this(nominal, calibrated, toolNominal, toolCalibrated, null, PoseConditions.NONE);
    }

    /**
     * With an extended model (geometry plus non-geometric effects, from diagnosis): the real
     * robot's pose is predicted under {@code conditions} (approach directions, temperature,
     * payload, time the program will run with; unknown ones contribute nothing).
     */
    public Compensator(KinematicModel nominal, ExtendedModel calibrated, Pose toolNominal, Pose toolCalibrated,
                       PoseConditions conditions) {
        this(nominal, calibrated.geometry(), toolNominal, toolCalibrated, calibrated.hasEffects() ? calibrated : null, conditions);
    }

    /** For a robot file: its effects are used when it has any (see {@link ExtendedModel#of}). */
    public static Compensator forRobotFile(KinematicModel nominal, RobotDescription calibrated, String file, Pose toolNominal,
                                           Pose toolCalibrated, PoseConditions conditions) {
        return new Compensator(nominal, ExtendedModel.of(calibrated, file), toolNominal, toolCalibrated, conditions);
    }

    private Compensator(KinematicModel nominal, KinematicModel calibrated, Pose toolNominal, Pose toolCalibrated,
                        ExtendedModel extended, PoseConditions conditions) {
        this.extended = extended;
        this.conditions = conditions;
        if (nominal.dof() != calibrated.dof())
            throw new IllegalArgumentException("nominal has " + nominal.dof() + " joints, calibrated " + calibrated.dof());
        this.nominal = nominal;
        this.calibrated = calibrated;
        this.toolNominal = toolNominal;
        this.toolCalibrated = toolCalibrated;
        this.ik = InverseKinematics.of(nominal);
    }

    public KinematicModel nominal() { return nominal; }
    public KinematicModel calibrated() { return calibrated; }

    /**
     * Reference path: compensates one target baseTtool, choosing the nominal IK solution nearest
     * to {@code qSeed} (controller values) first and then staying on its branch.
     */
    public Result compensate(Pose baseTtarget, double[] qSeed) {
        Pose comp = baseTtarget;
        double[] q = qSeed.clone();
        double resP = Double.NaN, resR = Double.NaN;
        for (int it = 1; it <= MAX_ITERATIONS; it++) {
            Optional<IkSolution> s = ik.solveNear(comp.times(toolNominal.inverse()), q);
            if (s.isEmpty()) return new Result(comp, q, resP, resR, it, Status.UNREACHABLE);
            q = s.get().q();
            Pose actual = extended != null ? extended.tool(q, toolCalibrated, conditions) : calibrated.flange(q).times(toolCalibrated);
            Vec3 dp = baseTtarget.position().minus(actual.position());
            Vec3 dr = baseTtarget.times(actual.inverse()).rotationVector(); // Log(R_t R_aᵀ), base axes
            resP = dp.norm();
            resR = dr.norm();
            if (resP <= POSITION_TOLERANCE && resR <= ROTATION_TOLERANCE)
                return new Result(comp, q, resP, resR, it, nominal.withinLimits(q) ? Status.CONVERGED : Status.OUT_OF_LIMITS);
            Pose rot = resR > 0 ? Pose.rotAxis(dr, resR) : Pose.IDENTITY;
            Pose rotated = rot.times(Pose.of(comp.rotationRowMajor(), 0, 0, 0));
            comp = Pose.of(rotated.rotationRowMajor(), comp.x() + dp.x(), comp.y() + dp.y(), comp.z() + dp.z());
        }
        return new Result(comp, q, resP, resR, MAX_ITERATIONS, Status.NOT_CONVERGED);
    }

    /** Compensates a target in world coordinates for a robot placed at worldTbase; the result is in world too. */
    public Result compensateWorld(Pose worldTtarget, Pose worldTbase, double[] qSeed) {
        Result r = compensate(worldTbase.inverse().times(worldTtarget), qSeed);
        return new Result(worldTbase.times(r.commanded()), r.q(), r.residualM(), r.residualRad(), r.iterations(), r.status());
    }

    /** A fast, allocation-light compensator for many targets (closed-form IK); one per thread. */
    public Batch batch() { return new Batch(); }

    /**
     * Fast path for large target lists: closed-form nominal IK picking the branch nearest to
     * the previous joint values, allocation-free FK of the calibrated model; falls back to the
     * reference path when the nominal model has no closed form.
     */
    public final class Batch {
        private final KinematicModel.Workspace ws = calibrated.newWorkspace();
        private final double[][] th = new double[8][Math.max(6, nominal.dof())];
        private final double[] comp = new double[12], flangeCmd = new double[12], f = new double[12], act = new double[12],
                tn = new double[12], tc = new double[12], tnInv = new double[12], target = new double[12], tmp = new double[9],
                rot = new double[9];
        private final double[] theta;
        private final int n = nominal.dof();

        private Batch() {
            toArray(toolNominal, tn);
            toArray(toolCalibrated, tc);
            toArray(toolNominal.inverse(), tnInv);
            theta = new double[n];
        }

        /**
         * Compensates one target given as position (m) and unit quaternion (w, x, y, z) in base
         * coordinates. {@code qInOut} holds the seed (controller values) and receives the joint
         * values; {@code commandedOut} receives X_comp as x, y, z, qw, qx, qy, qz;
         * {@code residualOut} receives position (m) and rotation (rad) residuals. Returns the status.
         */
        public Status compensate(double[] pos, double[] quat, double[] qInOut, double[] commandedOut, double[] residualOut) {
            if (!ik.hasClosedForm() || n != 6 || extended != null) { // effects: the reference path
                Result r = Compensator.this.compensate(Pose.fromQuaternion(quat[0], quat[1], quat[2], quat[3], pos[0], pos[1], pos[2]), qInOut);
                System.arraycopy(r.q(), 0, qInOut, 0, n);
                double[] qq = r.commanded().quaternion();
                commandedOut[0] = r.commanded().x(); commandedOut[1] = r.commanded().y(); commandedOut[2] = r.commanded().z();
                System.arraycopy(qq, 0, commandedOut, 3, 4);
                residualOut[0] = r.residualM();
                residualOut[1] = r.residualRad();
                return r.status();
            }
            quatTo12(quat, pos, target);
            System.arraycopy(target, 0, comp, 0, 12);
            double[] thetaPrev = nominal.theta(qInOut);
            double rp = Double.NaN, rr = Double.NaN;
            for (int it = 1; it <= MAX_ITERATIONS; it++) {
                mul12(comp, tnInv, flangeCmd);
                int count = ik.closedFormThetas(flangeCmd, th);
                if (count == 0) return finish(comp, commandedOut, residualOut, rp, rr, Status.UNREACHABLE);
                int best = -1;
                double bestD = Double.POSITIVE_INFINITY;
                for (int s = 0; s < count; s++) {
                    double d = 0;
                    for (int j = 0; j < n; j++) {
                        double diff = wrap(th[s][j] - thetaPrev[j]);
                        d += diff * diff;
                    }
                    if (d < bestD) { bestD = d; best = s; }
                }
                // Stay on the previous turn: theta = previous + wrapped difference.
                for (int j = 0; j < n; j++) theta[j] = thetaPrev[j] + wrap(th[best][j] - thetaPrev[j]);
                System.arraycopy(theta, 0, thetaPrev, 0, n);
                double[] q = nominal.q(theta);
                calibrated.flange(q, ws, f);
                mul12(f, tc, act);
                double dx = target[3] - act[3], dy = target[7] - act[7], dz = target[11] - act[11];
                // rotation error Log(R_t R_aᵀ)
                for (int i = 0; i < 3; i++)
                    for (int j = 0; j < 3; j++)
                        tmp[3 * i + j] = target[4 * i] * act[4 * j] + target[4 * i + 1] * act[4 * j + 1] + target[4 * i + 2] * act[4 * j + 2];
                double[] w = new double[3];
                log(tmp, w);
                rp = Math.sqrt(dx * dx + dy * dy + dz * dz);
                rr = Math.sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
                System.arraycopy(q, 0, qInOut, 0, n);
                if (rp <= POSITION_TOLERANCE && rr <= ROTATION_TOLERANCE)
                    return finish(comp, commandedOut, residualOut, rp, rr, nominal.withinLimits(q) ? Status.CONVERGED : Status.OUT_OF_LIMITS);
                comp[3] += dx; comp[7] += dy; comp[11] += dz;
                exp(w, rot);
                for (int i = 0; i < 3; i++)
                    for (int j = 0; j < 3; j++)
                        tmp[3 * i + j] = rot[3 * i] * comp[j] + rot[3 * i + 1] * comp[4 + j] + rot[3 * i + 2] * comp[8 + j];
                for (int i = 0; i < 3; i++) for (int j = 0; j < 3; j++) comp[4 * i + j] = tmp[3 * i + j];
            }
            return finish(comp, commandedOut, residualOut, rp, rr, Status.NOT_CONVERGED);
        }

        private Status finish(double[] c, double[] commandedOut, double[] residualOut, double rp, double rr, Status s) {
            commandedOut[0] = c[3]; commandedOut[1] = c[7]; commandedOut[2] = c[11];
            double[] r = {c[0], c[1], c[2], c[4], c[5], c[6], c[8], c[9], c[10]};
            double[] qq = Pose.of(orthonormalize(r), 0, 0, 0).quaternion();
            System.arraycopy(qq, 0, commandedOut, 3, 4);
            residualOut[0] = rp;
            residualOut[1] = rr;
            return s;
        }
    }

    // ------------------------------------------------------------------ small 3x4 helpers

    static void toArray(Pose p, double[] m) {
        for (int i = 0; i < 3; i++) for (int j = 0; j < 3; j++) m[4 * i + j] = p.rot(i, j);
        m[3] = p.x(); m[7] = p.y(); m[11] = p.z();
    }

    static void quatTo12(double[] q, double[] p, double[] m) {
        double n = Math.sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        double w = q[0] / n, x = q[1] / n, y = q[2] / n, z = q[3] / n;
        m[0] = 1 - 2 * (y * y + z * z); m[1] = 2 * (x * y - z * w); m[2] = 2 * (x * z + y * w); m[3] = p[0];
        m[4] = 2 * (x * y + z * w); m[5] = 1 - 2 * (x * x + z * z); m[6] = 2 * (y * z - x * w); m[7] = p[1];
        m[8] = 2 * (x * z - y * w); m[9] = 2 * (y * z + x * w); m[10] = 1 - 2 * (x * x + y * y); m[11] = p[2];
    }

    static void mul12(double[] a, double[] b, double[] out) {
        for (int i = 0; i < 3; i++) {
            double a0 = a[4 * i], a1 = a[4 * i + 1], a2 = a[4 * i + 2];
            out[4 * i] = a0 * b[0] + a1 * b[4] + a2 * b[8];
            out[4 * i + 1] = a0 * b[1] + a1 * b[5] + a2 * b[9];
            out[4 * i + 2] = a0 * b[2] + a1 * b[6] + a2 * b[10];
            out[4 * i + 3] = a0 * b[3] + a1 * b[7] + a2 * b[11] + a[4 * i + 3];
        }
    }

    static double wrap(double a) {
        return a - 2 * Math.PI * Math.rint(a / (2 * Math.PI));
    }

    static void log(double[] r, double[] w) {
        double c = Math.max(-1, Math.min(1, (r[0] + r[4] + r[8] - 1) / 2));
        double th = Math.acos(c);
        double vx = r[7] - r[5], vy = r[2] - r[6], vz = r[3] - r[1];
        double k = th < 1e-6 ? 0.5 : th / (2 * Math.sin(th));
        w[0] = vx * k; w[1] = vy * k; w[2] = vz * k;
    }

    static void exp(double[] w, double[] r) {
        double th2 = w[0] * w[0] + w[1] * w[1] + w[2] * w[2], th = Math.sqrt(th2);
        double a = th < 1e-6 ? 1 - th2 / 6 : Math.sin(th) / th, b = th < 1e-6 ? 0.5 - th2 / 24 : (1 - Math.cos(th)) / th2;
        double x = w[0], y = w[1], z = w[2];
        r[0] = 1 - b * (y * y + z * z); r[1] = b * x * y - a * z; r[2] = b * x * z + a * y;
        r[3] = b * x * y + a * z; r[4] = 1 - b * (x * x + z * z); r[5] = b * y * z - a * x;
        r[6] = b * x * z - a * y; r[7] = b * y * z + a * x; r[8] = 1 - b * (x * x + y * y);
    }

    static double[] orthonormalize(double[] r) {
        double[] x = {r[0], r[3], r[6]}, y = {r[1], r[4], r[7]};
        double nx = Math.sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
        for (int i = 0; i < 3; i++) x[i] /= nx;
        double d = x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
        for (int i = 0; i < 3; i++) y[i] -= d * x[i];
        double ny = Math.sqrt(y[0] * y[0] + y[1] * y[1] + y[2] * y[2]);
        for (int i = 0; i < 3; i++) y[i] /= ny;
        double[] z = {x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
        return new double[] {x[0], y[0], z[0], x[1], y[1], z[1], x[2], y[2], z[2]};
    }
}
