package org.robopro.calibration.compensation;

import java.util.Optional;
import org.robopro.calibration.PoseConditions;
import org.robopro.calibration.diagnosis.ExtendedModel;
import org.robopro.kinematics.IkSolution;
import org.robopro.kinematics.InverseKinematics;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.kinematics.Se3;
import org.robopro.models.RobotDescription;
import org.robopro.models.Vec3;

/**
 * Base-coordinate compensation, seed paper Fig. 5: a target X_target goes through the nominal
 * inverse model to q_N, the calibrated model predicts where the robot really goes at q_N, the
 * difference moves the commanded coordinates X_comp, and this repeats until the calibrated
 * prediction at the commanded joint values lands on the target. The controller, which knows only
 * the nominal model, is then sent X_comp (or the joint values q). Positions and orientations
 * are both compensated. Immutable and thread-safe apart from {@link Batch}, which is one per thread.
 *
 * <p>The calibrated model is either geometric ({@link KinematicModel}) or extended with
 * non-geometric effects ({@link ExtendedModel}, predicted under given {@link PoseConditions}).
 */
public final class Compensator implements TargetCompensator {
    /** Convergence: position (m) and orientation (rad) residual of the calibrated prediction. */
    public static final double POSITION_TOLERANCE = 1e-8, ROTATION_TOLERANCE = 1e-8;
    public static final int MAX_ITERATIONS = 30;

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
     * Reference path: compensates one target baseTtool (the constructor's tools), choosing the
     * nominal IK solution nearest to {@code qSeed} (controller values) first and then staying on its branch.
     */
    public Result compensate(Pose baseTtarget, double[] qSeed) {
        return fixedPoint(baseTtarget, toolNominal, toolCalibrated, qSeed);
    }

    /**
     * {@inheritDoc} When {@code flangeTtool} is the nominal tool this compensator was made with,
     * the calibrated tool stands in for it in the prediction; any other tool is taken as the
     * program defines it (calibration identified only the one tool).
     */
    @Override
    public Result compensate(Pose baseTtarget, Pose flangeTtool, double[] qSeed) {
        boolean same = flangeTtool.distanceTo(toolNominal) <= SAME_TOOL_M && flangeTtool.angleTo(toolNominal) <= SAME_TOOL_RAD;
        return fixedPoint(baseTtarget, flangeTtool, same ? toolCalibrated : flangeTtool, qSeed);
    }

    /** A program's tool within this of the nominal tool (m, rad; file rounding) is that tool. */
    private static final double SAME_TOOL_M = 1e-9, SAME_TOOL_RAD = 1e-9;

    /** The Fig. 5 iteration for a tool as the controller knows it and as the calibrated model predicts it. */
    private Result fixedPoint(Pose baseTtarget, Pose flangeTtoolNominal, Pose flangeTtoolCalibrated, double[] qSeed) {
        Pose comp = baseTtarget;
        double[] q = qSeed.clone();
        Pose toolNominalInv = flangeTtoolNominal.inverse();
        double resP = Double.NaN, resR = Double.NaN;
        for (int it = 1; it <= MAX_ITERATIONS; it++) {
            Optional<IkSolution> s = ik.solveNear(comp.times(toolNominalInv), q);
            if (s.isEmpty()) return new Result(comp, q, resP, resR, it, Status.UNREACHABLE);
            q = s.get().q();
            Pose actual = extended != null ? extended.tool(q, flangeTtoolCalibrated, conditions)
                    : calibrated.flange(q).times(flangeTtoolCalibrated);
            Vec3 dp = baseTtarget.position().minus(actual.position());
            Vec3 dr = baseTtarget.times(actual.inverse()).rotationVector(); // Log(R_t R_aᵀ), base axes
            resP = dp.norm();
            resR = dr.norm();
            if (resP <= POSITION_TOLERANCE && resR <= ROTATION_TOLERANCE)
                return new Result(comp, q, resP, resR, it, nominal.withinLimits(q) ? Status.CONVERGED : Status.OUT_OF_LIMITS);
            Pose rot = resR > 1e-12 ? Pose.rotAxis(dr, resR) : Pose.IDENTITY; // below: round-off, no axis to normalise
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
     * Fast path for large target lists. It computes the same fixed point as the Fig. 5 iteration
     * (joint values q* where the calibrated model reaches the target, X_comp = nominal FK at q*)
     * but converges quadratically: q starts at the seed when the nominal model puts the seed
     * within {@link #SEED_RADIUS_M} / {@link #SEED_ANGLE_RAD} of the target (paths: the previous
     * target's joints), else at the closed-form nominal IK branch nearest to the seed; then
     * Newton steps on the calibrated model (its geometric Jacobian) until the residual is below
     * the tolerances; X_comp is the nominal forward kinematics at q*. Checked against the
     * reference path in the tests. Allocation-free per target for six-axis arms.
     */
    public final class Batch {
        private final KinematicModel.Workspace wsC = calibrated.newWorkspace(), wsN = nominal.newWorkspace();
        private final int n = nominal.dof();
        private final double[][] th = new double[8][Math.max(6, n)];
        private final double[] f = new double[12], act = new double[12], tn = new double[12], tc = new double[12],
                tnInv = new double[12], target = new double[12], flangeCmd = new double[12],
                jac = new double[6 * n], a = new double[36], e = new double[6], w = new double[3], qWork = new double[n],
                thetaSeed = new double[n];

        private Batch() {
            Se3.fromPose(toolNominal, tn);
            Se3.fromPose(toolCalibrated, tc);
            Se3.fromPose(toolNominal.inverse(), tnInv);
        }

        /**
         * Compensates one target given as position (m) and unit quaternion (w, x, y, z) in base
         * coordinates. {@code qInOut} holds the seed (controller values) and receives the joint
         * values; {@code commandedOut} receives X_comp as x, y, z, qw, qx, qy, qz;
         * {@code residualOut} receives position (m) and rotation (rad) residuals. Returns the status.
         */
        public Status compensate(double[] pos, double[] quat, double[] qInOut, double[] commandedOut, double[] residualOut) {
            if (n != 6 || extended != null) return reference(pos, quat, qInOut, commandedOut, residualOut); // effects: reference path
            Se3.fromQuaternion(quat, pos, target);
            System.arraycopy(qInOut, 0, qWork, 0, n);
            nominal.flange(qWork, wsN, f);
            Se3.mul(f, tn, act);
            if (error(target, act) > SEED_RADIUS_M || Math.sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]) > SEED_ANGLE_RAD) {
                if (!ik.hasClosedForm()) return reference(pos, quat, qInOut, commandedOut, residualOut);
                Se3.mul(target, tnInv, flangeCmd);
                int count = ik.closedFormThetas(flangeCmd, th);
                if (count == 0) return finish(qInOut, commandedOut, residualOut, Double.NaN, Double.NaN, Status.UNREACHABLE);
                // The branch nearest to the seed (in q, on the seed's turn), preferring ones inside the limits.
                double[] ts = nominal.theta(qInOut);
                double bestD = Double.POSITIVE_INFINITY;
                boolean bestInside = false;
                for (int s = 0; s < count; s++) {
                    for (int j = 0; j < n; j++) thetaSeed[j] = ts[j] + wrap(th[s][j] - ts[j]);
                    double[] qc = nominal.q(thetaSeed);
                    boolean inside = nominal.withinLimits(qc);
                    double d = 0;
                    for (int j = 0; j < n; j++) d += (qc[j] - qInOut[j]) * (qc[j] - qInOut[j]);
                    if ((inside && !bestInside) || (inside == bestInside && d < bestD)) {
                        bestD = d;
                        bestInside = inside;
                        System.arraycopy(qc, 0, qWork, 0, n);
                    }
                }
            }
            double rp = Double.NaN, rr = Double.NaN;
            for (int it = 0; it <= MAX_ITERATIONS; it++) {
                calibrated.flange(qWork, wsC, f);
                Se3.mul(f, tc, act);
                rp = error(target, act);
                rr = Math.sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
                if (rp <= POSITION_TOLERANCE && rr <= ROTATION_TOLERANCE) {
                    System.arraycopy(qWork, 0, qInOut, 0, n);
                    nominal.flange(qWork, wsN, f);
                    Se3.mul(f, tn, act);
                    return finish(qInOut, commandedOut, residualOut, rp, rr,
                            nominal.withinLimits(qWork) ? Status.CONVERGED : Status.OUT_OF_LIMITS);
                }
                // Newton step on the calibrated model: J dq = e, J of the tool point (v + ω x r; ω).
                calibrated.geometricJacobian(qWork, wsC, jac);
                double ox = act[3] - f[3], oy = act[7] - f[7], oz = act[11] - f[11];
                for (int c = 0; c < 6; c++) {
                    double wx = jac[3 * n + c], wy = jac[4 * n + c], wz = jac[5 * n + c];
                    a[c] = jac[c] + wy * oz - wz * oy;
                    a[6 + c] = jac[n + c] + wz * ox - wx * oz;
                    a[12 + c] = jac[2 * n + c] + wx * oy - wy * ox;
                    a[18 + c] = wx; a[24 + c] = wy; a[30 + c] = wz;
                }
                e[0] = target[3] - act[3]; e[1] = target[7] - act[7]; e[2] = target[11] - act[11];
                e[3] = w[0]; e[4] = w[1]; e[5] = w[2];
                if (!solve6(a, e)) return finish(qInOut, commandedOut, residualOut, rp, rr, Status.NOT_CONVERGED);
                for (int j = 0; j < 6; j++) qWork[j] += e[j];
            }
            System.arraycopy(qWork, 0, qInOut, 0, n);
            return finish(qInOut, commandedOut, residualOut, rp, rr, Status.NOT_CONVERGED);
        }

        /** Position error |target - actual| (m); leaves the rotation error Log(R_t R_aᵀ) in w. */
        private double error(double[] t, double[] a) {
            double dx = t[3] - a[3], dy = t[7] - a[7], dz = t[11] - a[11];
            Se3.rotationLogBetween(t, a, w, 0);
            return Math.sqrt(dx * dx + dy * dy + dz * dz);
        }

        private Status reference(double[] pos, double[] quat, double[] qInOut, double[] commandedOut, double[] residualOut) {
            Result r = Compensator.this.compensate(Pose.fromQuaternion(quat[0], quat[1], quat[2], quat[3], pos[0], pos[1], pos[2]), qInOut);
            System.arraycopy(r.q(), 0, qInOut, 0, n);
            double[] qq = r.commanded().quaternion();
            commandedOut[0] = r.commanded().x(); commandedOut[1] = r.commanded().y(); commandedOut[2] = r.commanded().z();
            System.arraycopy(qq, 0, commandedOut, 3, 4);
            residualOut[0] = r.residualM();
            residualOut[1] = r.residualRad();
            return r.status();
        }

        /** Writes X_comp (the nominal tool pose left in {@code act}) and residuals. */
        private Status finish(double[] q, double[] commandedOut, double[] residualOut, double rp, double rr, Status s) {
            commandedOut[0] = act[3]; commandedOut[1] = act[7]; commandedOut[2] = act[11];
            Se3.quaternion(act, commandedOut, 3);
            residualOut[0] = rp;
            residualOut[1] = rr;
            return s;
        }
    }

    /** Seed closeness below which the batch path skips the closed-form IK. */
    public static final double SEED_RADIUS_M = 0.05, SEED_ANGLE_RAD = 0.2;

    /** Solves the 6x6 system a x = b in place (b becomes x), partial pivoting; false when singular. */
    static boolean solve6(double[] a, double[] b) {
        for (int c = 0; c < 6; c++) {
            int p = c;
            for (int r = c + 1; r < 6; r++) if (Math.abs(a[6 * r + c]) > Math.abs(a[6 * p + c])) p = r;
            if (Math.abs(a[6 * p + c]) < 1e-12) return false;
            if (p != c) {
                for (int k = 0; k < 6; k++) { double t = a[6 * c + k]; a[6 * c + k] = a[6 * p + k]; a[6 * p + k] = t; }
                double t = b[c]; b[c] = b[p]; b[p] = t;
            }
            for (int r = c + 1; r < 6; r++) {
                double fct = a[6 * r + c] / a[6 * c + c];
                if (fct == 0) continue;
                for (int k = c; k < 6; k++) a[6 * r + k] -= fct * a[6 * c + k];
                b[r] -= fct * b[c];
            }
        }
        for (int r = 5; r >= 0; r--) {
            double s = b[r];
            for (int k = r + 1; k < 6; k++) s -= a[6 * r + k] * b[k];
            b[r] = s / a[6 * r + r];
        }
        return true;
    }

    static double wrap(double a) {
        return a - 2 * Math.PI * Math.rint(a / (2 * Math.PI));
    }
}
