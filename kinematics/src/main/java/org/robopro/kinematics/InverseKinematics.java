package org.robopro.kinematics;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.Optional;
import org.ejml.data.DMatrixRMaj;
import org.ejml.dense.row.SingularOps_DDRM;

/**
 * Inverse kinematics of a {@link KinematicModel}: closed form for six-axis arms with a
 * spherical wrist whose axis 2 is perpendicular to axis 1 and parallel to axis 3 (detected from
 * the model's geometry, see {@link ClosedFormIk}), damped least squares for any model (seeded
 * by the closed form of the nearly-spherical geometry for calibrated arms). Immutable; each call
 * allocates its own buffers, so one instance may be shared between threads.
 *
 * <p>Configuration data follows ABB's confdata: cf1, cf4, cf6 are the quadrants
 * floor(q / 90 deg) of axes 1, 4 and 6; cfx = 4 (wrist centre behind axis 1) + 2 (wrist centre
 * behind the lower arm) + 1 (axis 5 negative), where "in front" is the side the wrist centre
 * is on at the zero position. See docs/kinematics.md.
 */
public final class InverseKinematics {
    /** Convergence of the numerical solver: position (m) and orientation (rad). */
    public static final double TOLERANCE = 1e-10;
    private static final int MAX_ITERATIONS = 100;

    private final KinematicModel model;
    private final ClosedFormIk closed;
    private final double len;
    private final boolean[] integerColumn;

    private InverseKinematics(KinematicModel model) {
        this.model = model;
        this.closed = ClosedFormIk.of(model);
        this.len = model.characteristicLength();
        int n = model.dof();
        double[][] c = model.couplingMatrix();
        integerColumn = new boolean[n];
        for (int j = 0; j < n; j++) {
            boolean ok = !model.isPrismatic(j);
            for (int i = 0; i < n; i++) if (c[i][j] != Math.rint(c[i][j]) || (c[i][j] != 0 && model.isPrismatic(i))) ok = false;
            integerColumn[j] = ok;
        }
    }

    public static InverseKinematics of(KinematicModel model) { return new InverseKinematics(model); }

    public KinematicModel model() { return model; }

    /** True when the closed form applies exactly (spherical wrist etc.); false for approximate or none. */
    public boolean hasExactClosedForm() { return closed != null && closed.exact; }

    /** True when a closed form (exact, or approximate as a seed) is available. */
    public boolean hasClosedForm() { return closed != null; }

    /** Every solution reaching baseTflange (closed form where the geometry allows, else numerical). */
    public List<IkSolution> solveAll(Pose baseTflange) {
        double[] target = new double[12];
        Mat34.fromPose(baseTflange, target);
        List<double[]> qs = new ArrayList<>();
        int n = model.dof();
        if (closed != null) {
            double[][] th = new double[8][6];
            int count = closed.solve(target, th);
            KinematicModel.Workspace ws = model.newWorkspace();
            for (int i = 0; i < count; i++) {
                double[] q = model.q(th[i]);
                if (!closed.exact && !dls(target, q, ws, false).converged) continue;
                qs.add(q);
            }
        } else {
            KinematicModel.Workspace ws = model.newWorkspace();
            List<double[]> seeds = new ArrayList<>();
            seeds.add(new double[n]);
            seeds.addAll(Arrays.asList(model.randomConfigurations(31, 97)));
            for (double[] s : seeds) {
                double[] q = s.clone();
                if (dls(target, q, ws, true).converged) qs.add(q);
            }
        }
        List<IkSolution> out = new ArrayList<>();
        for (double[] q : qs) for (double[] v : variants(q)) addUnique(out, v);
        out.sort(Comparator.comparing((IkSolution s) -> !s.withinLimits()));
        return out;
    }

    private void addUnique(List<IkSolution> out, double[] q) {
        for (IkSolution s : out) {
            double d = 0;
            for (int i = 0; i < q.length; i++) d = Math.max(d, Math.abs(s.q()[i] - q[i]));
            if (d < 1e-7) return;
        }
        out.add(solution(q));
    }

    /** Turn variants (+-2 pi) of q within the limits; the wrapped q itself when none is. */
    private List<double[]> variants(double[] q0) {
        int n = q0.length;
        double[] q = q0.clone();
        for (int i = 0; i < n; i++) if (integerColumn[i]) q[i] = ClosedFormIk.wrap(q[i]);
        List<double[]> acc = new ArrayList<>();
        acc.add(q);
        for (int i = 0; i < n; i++) {
            if (!integerColumn[i]) continue;
            List<double[]> next = new ArrayList<>();
            for (double[] a : acc)
                for (int k = -2; k <= 2; k++) {
                    double v = a[i] + 2 * Math.PI * k;
                    if (v >= model.qMin(i) - 1e-9 && v <= model.qMax(i) + 1e-9) {
                        double[] b = a.clone();
                        b[i] = v;
                        next.add(b);
                    }
                }
            if (next.isEmpty()) return List.of(q);
            acc = next;
        }
        return acc;
    }

    /** The solution nearest to qSeed (numerical refinement), or empty when unreachable. */
    public Optional<IkSolution> solveNear(Pose baseTflange, double[] qSeed) {
        if (qSeed.length != model.dof()) throw new IllegalArgumentException("seed needs " + model.dof() + " values");
        if (closed != null) {
            IkSolution best = null;
            double bestD = Double.POSITIVE_INFINITY;
            List<IkSolution> candidates = new ArrayList<>(solveAll(baseTflange));
            // approximate closed form: the branch the seed lies on may refine to a neighbour
            if (!closed.exact) solveNumerical(baseTflange, qSeed).solution().ifPresent(candidates::add);
            for (IkSolution s : candidates) {
                if (!s.withinLimits()) continue;
                double d = 0;
                for (int i = 0; i < qSeed.length; i++) d += (s.q()[i] - qSeed[i]) * (s.q()[i] - qSeed[i]);
                if (d < bestD) { bestD = d; best = s; }
            }
            if (best != null) return Optional.of(best);
        }
        return solveNumerical(baseTflange, qSeed).solution();
    }

    /** The solution with the given configuration data (inside the limits), or empty. */
    public Optional<IkSolution> solveWithConf(Pose baseTflange, ConfData conf) {
        for (IkSolution s : solveAll(baseTflange)) if (s.withinLimits() && s.conf().equals(conf)) return Optional.of(s);
        return Optional.empty();
    }

    /** ABB configuration data of joint values q. */
    public ConfData confOf(double[] q) {
        int n = model.dof();
        if (q.length != n) throw new IllegalArgumentException("expected " + n + " joint values");
        double quarter = Math.PI / 2;
        int cf1 = (int) Math.floor(q[0] / quarter + 1e-12);
        int cf4 = n > 3 ? (int) Math.floor(q[3] / quarter + 1e-12) : 0;
        int cf6 = n > 5 ? (int) Math.floor(q[5] / quarter + 1e-12) : 0;
        int cfx = n > 4 && q[4] < 0 ? 1 : 0;
        if (closed != null) {
            double[] f = new double[12];
            model.flange(q, model.newWorkspace(), f);
            double[] th = model.theta(q);
            cfx |= closed.cfxArmBits(f, th[0], th[1]);
        }
        return new ConfData(cf1, cf4, cf6, cfx);
    }

    /**
     * Closed-form core for benchmarks and batch use: writes up to 8 model-angle solutions
     * (unwrapped turns, no limit check, not refined) into {@code thetaOut} (8 x 6) and returns
     * how many; 0 when the model has no closed form or the pose is unreachable.
     */
    public int closedFormThetas(double[] baseTflange12, double[][] thetaOut) {
        return closed == null ? 0 : closed.solve(baseTflange12, thetaOut);
    }

    // ---------------------------------------------------------------- numerical

    /** Result of the numerical solver with its diagnostics. */
    public record NumericalResult(boolean converged, double[] q, int iterations, double positionError,
                                  double orientationError) { }

    /** Outcome of a numerical solve, with the solution when it converged inside the limits. */
    public record NumericalOutcome(NumericalResult diagnostics, Optional<IkSolution> solution) { }

    /**
     * Damped least squares (Levenberg-Marquardt) from {@code qSeed} with the analytic geometric
     * Jacobian, keeping q inside the joint limits. Position rows are scaled by the robot's
     * size so metres and radians weigh alike.
     */
    public NumericalOutcome solveNumerical(Pose baseTflange, double[] qSeed) {
        if (qSeed.length != model.dof()) throw new IllegalArgumentException("seed needs " + model.dof() + " values");
        double[] target = new double[12];
        Mat34.fromPose(baseTflange, target);
        double[] q = qSeed.clone();
        NumericalResult r = dls(target, q, model.newWorkspace(), true);
        Optional<IkSolution> sol = r.converged && model.withinLimits(q) ? Optional.of(solution(q)) : Optional.empty();
        return new NumericalOutcome(r, sol);
    }

    /** In-place DLS on q; allocation-light (a few small arrays per call). */
    NumericalResult dls(double[] target, double[] q, KinematicModel.Workspace ws, boolean clampToLimits) {
        int n = model.dof();
        if (clampToLimits) clamp(q);
        double[] j = new double[6 * n], f = new double[12], e = new double[6], a = new double[n * n], g = new double[n];
        double[] qTry = new double[n], eTry = new double[6], fTry = new double[12];
        model.geometricJacobian(q, ws, j);
        model.lastFlange(ws, f);
        double err = error(target, f, e);
        double mu = 1e-3;
        int it = 0;
        while (it < MAX_ITERATIONS && !(pos(e) < TOLERANCE && rot(e) < TOLERANCE)) {
            it++;
            // scaled rows: position / len
            for (int r = 0; r < n; r++) {
                for (int c = 0; c < n; c++) {
                    double s = 0;
                    for (int k = 0; k < 6; k++) s += j[k * n + r] * j[k * n + c] / (k < 3 ? len * len : 1);
                    a[r * n + c] = s;
                }
                double s = 0;
                for (int k = 0; k < 6; k++) s += j[k * n + r] * e[k] / (k < 3 ? len * len : 1);
                g[r] = s;
            }
            boolean accepted = false;
            for (int tries = 0; tries < 12 && !accepted; tries++) {
                double[] dq = solveDamped(a, g, n, mu);
                for (int i = 0; i < n; i++) qTry[i] = q[i] + dq[i];
                if (clampToLimits) clamp(qTry);
                model.flange(qTry, ws, fTry);
                double errTry = error(target, fTry, eTry);
                if (errTry < err) {
                    System.arraycopy(qTry, 0, q, 0, n);
                    err = errTry;
                    mu = Math.max(mu * 0.1, 1e-12);
                    accepted = true;
                } else {
                    mu *= 10;
                }
            }
            if (!accepted) break;
            model.geometricJacobian(q, ws, j);
            model.lastFlange(ws, f);
            err = error(target, f, e);
        }
        boolean ok = pos(e) < TOLERANCE * 10 && rot(e) < TOLERANCE * 10;
        return new NumericalResult(ok, q.clone(), it, pos(e), rot(e));
    }

    private static double pos(double[] e) { return Math.sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]); }

    private static double rot(double[] e) { return Math.sqrt(e[3] * e[3] + e[4] * e[4] + e[5] * e[5]); }

    /** e = (target position - position, rotation vector of Rtarget R^T); returns the scaled squared norm. */
    private double error(double[] t, double[] f, double[] e) {
        e[0] = t[3] - f[3]; e[1] = t[7] - f[7]; e[2] = t[11] - f[11];
        // Rerr = Rt R^T
        double[] r = new double[9];
        for (int i = 0; i < 3; i++)
            for (int k = 0; k < 3; k++) r[3 * i + k] = t[4 * i] * f[4 * k] + t[4 * i + 1] * f[4 * k + 1] + t[4 * i + 2] * f[4 * k + 2];
        double cos = Math.max(-1, Math.min(1, (r[0] + r[4] + r[8] - 1) / 2));
        double angle = Math.acos(cos);
        double vx = r[7] - r[5], vy = r[2] - r[6], vz = r[3] - r[1];
        if (angle < 1e-6) { e[3] = vx / 2; e[4] = vy / 2; e[5] = vz / 2; }
        else if (Math.PI - angle < 1e-4) {
            org.robopro.models.Vec3 w = Pose.of(r, 0, 0, 0).rotationVector();
            e[3] = w.x(); e[4] = w.y(); e[5] = w.z();
        } else {
            double k = angle / (2 * Math.sin(angle));
            e[3] = vx * k; e[4] = vy * k; e[5] = vz * k;
        }
        return (e[0] * e[0] + e[1] * e[1] + e[2] * e[2]) / (len * len) + e[3] * e[3] + e[4] * e[4] + e[5] * e[5];
    }

    /** (A + mu (diag(A) + 1e-9) ) x = g by Cholesky; A symmetric positive semi-definite. */
    private static double[] solveDamped(double[] a, double[] g, int n, double mu) {
        double[] l = new double[n * n];
        for (int i = 0; i < n; i++)
            for (int k = 0; k <= i; k++) {
                double s = a[i * n + k];
                if (i == k) s += mu * (a[i * n + i] + 1e-9);
                for (int p = 0; p < k; p++) s -= l[i * n + p] * l[k * n + p];
                if (i == k) l[i * n + i] = Math.sqrt(Math.max(s, 1e-300));
                else l[i * n + k] = s / l[k * n + k];
            }
        double[] y = new double[n];
        for (int i = 0; i < n; i++) {
            double s = g[i];
            for (int p = 0; p < i; p++) s -= l[i * n + p] * y[p];
            y[i] = s / l[i * n + i];
        }
        for (int i = n - 1; i >= 0; i--) {
            double s = y[i];
            for (int p = i + 1; p < n; p++) s -= l[p * n + i] * y[p];
            y[i] = s / l[i * n + i];
        }
        return y;
    }

    private void clamp(double[] q) {
        for (int i = 0; i < q.length; i++) q[i] = Math.max(model.qMin(i), Math.min(model.qMax(i), q[i]));
    }

    private IkSolution solution(double[] q) {
        return new IkSolution(q, confOf(q), model.withinLimits(q), singularityMeasure(q));
    }

    /**
     * Smallest singular value of the geometric Jacobian with position rows divided by the
     * robot's size (dimensionless; 0 at a singularity, about 0.1-1 far from one).
     */
    public double singularityMeasure(double[] q) {
        double[][] j = model.geometricJacobian(q);
        for (int r = 0; r < 3; r++) for (int c = 0; c < j[r].length; c++) j[r][c] /= len;
        double[] s = SingularOps_DDRM.singularValues(new DMatrixRMaj(j));
        double min = Double.POSITIVE_INFINITY;
        for (double v : s) min = Math.min(min, v);
        return min;
    }
}
