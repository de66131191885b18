package org.robopro.kinematics;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * Allocation-free inverse kinematics for one thread (made by {@link InverseKinematics#newSolver()}):
 * every buffer is made in the constructor, results and diagnostics are read back after each
 * call (KDL solver style). The solution store only grows when a call finds more solutions than
 * any call before it.
 *
 * <p>{@link #solveAll(double[])} gives exactly the solutions of
 * {@link InverseKinematics#solveAll(Pose)} in the same order (within the limits first), with
 * their configuration data and manipulability; {@link #solveNumerical} is the damped
 * least-squares solver with its iterations and residuals. Results are valid until the next call.
 */
public final class IkSolver {
    private static final int MAX_ITERATIONS = 100;
    private static final double TWO_PI = 2 * Math.PI, INV_TWO_PI = 1 / TWO_PI;

    private final InverseKinematics ik;
    private final KinematicModel model;
    private final ClosedFormIk closed;
    private final int n;
    private final double len;
    private final boolean[] integerColumn;
    private final double[] qMin, qMax;
    private final double[] qLo, qHi; // limits with the 1e-9 rounding slack of KinematicModel.withinLimits
    private final KinematicModel.Workspace ws;
    // closed form
    private final double[][] thetas = new double[8][6];
    private final int[] armBits = new int[8];
    private final double[] detFactor = new double[8];
    private final double[] scratch = new double[ClosedFormIk.SCRATCH];
    // solutions (grown on demand) and their order (within limits first)
    private double[][] sq;
    private int[] sConf; // 4 per solution: cf1 cf4 cf6 cfx
    private boolean[] sWithin;
    private double[] sManip;
    private int[] order;
    private int count;
    // variant enumeration
    private final double[] base, variant, thetaBuf;
    private final double[][] cand;
    private final int[] candCount, odo;
    // numerical
    private final double[] target = new double[12], jac, f = new double[12], e = new double[6];
    private final double[] a, g, qTry, eTry = new double[6], fTry = new double[12], chol, y;
    private final double[] lu = new double[36];
    // solveNear
    private final double[][] branchQ = new double[8][6];
    private final double[] branchD = new double[8], nearBest, nearTry;
    private final boolean[] branchDone = new boolean[8];
    private int iterations;
    private double positionError, orientationError;
    private boolean converged;

    IkSolver(InverseKinematics ik, ClosedFormIk closed, boolean[] integerColumn) {
        this.ik = ik;
        this.model = ik.model();
        this.closed = closed;
        this.n = model.dof();
        this.len = model.characteristicLength();
        this.integerColumn = integerColumn;
        ws = model.newWorkspace();
        qMin = new double[n];
        qMax = new double[n];
        qLo = new double[n];
        qHi = new double[n];
        for (int i = 0; i < n; i++) {
            qMin[i] = model.qMin(i); qMax[i] = model.qMax(i);
            qLo[i] = qMin[i] - 1e-9; qHi[i] = qMax[i] + 1e-9;
        }
        int cap = 16;
        sq = new double[cap][n];
        sConf = new int[4 * cap];
        sWithin = new boolean[cap];
        sManip = new double[cap];
        order = new int[cap];
        base = new double[n];
        variant = new double[n];
        thetaBuf = new double[n];
        cand = new double[n][5];
        candCount = new int[n];
        odo = new int[n];
        jac = new double[6 * n];
        a = new double[n * n];
        g = new double[n];
        qTry = new double[n];
        chol = new double[n * n];
        y = new double[n];
        nearBest = new double[n];
        nearTry = new double[n];
    }

    public KinematicModel model() { return model; }

    double[] scratch() { return scratch; }

    // ---------------------------------------------------------------- all solutions

    /**
     * Every solution reaching baseTflange (row-major 3x4 [R | t], metres), as
     * {@link InverseKinematics#solveAll(Pose)}; returns how many. Read them with {@link #q},
     * {@link #cf1} ... {@link #manipulability}; index 0..count-1, those inside the limits first.
     */
    public int solveAll(double[] baseTflange12) {
        count = 0;
        if (closed != null) {
            int m = closed.solve(baseTflange12, thetas, armBits, detFactor, scratch);
            for (int i = 0; i < m; i++) {
                model.q(thetas[i], base);
                if (closed.exact) {
                    addVariants(armBits[i], closed.manipulability(detFactor[i]));
                } else {
                    if (!dls(baseTflange12, base, false)) continue;
                    model.theta(base, thetaBuf);
                    addVariants(closed.cfxArmBits(baseTflange12, thetaBuf[0], thetaBuf[1]), manipulabilityAt(base));
                }
            }
        } else {
            for (double[] s : ik.numericalSeeds()) {
                System.arraycopy(s, 0, base, 0, n);
                if (dls(baseTflange12, base, true)) addVariants(0, manipulabilityAt(base));
            }
        }
        // stable partition: within the limits first
        int k = 0;
        for (int i = 0; i < count; i++) if (sWithin[i]) order[k++] = i;
        for (int i = 0; i < count; i++) if (!sWithin[i]) order[k++] = i;
        return count;
    }

    /**
     * Turn variants (+-2 pi on whole-turn columns) of {@link #base} within the limits, each added
     * once. Usually every joint has exactly one in-limit turn (its wrapped value), so that case
     * is tested first and goes straight to {@link #addUnique}; the general enumeration only
     * runs for joints whose range spans more than a turn around their value.
     */
    private void addVariants(int cfxArm, double manip) {
        // common case first: every whole-turn joint's wrapped value is the one turn inside its range
        boolean simple = true, within = true, none = false;
        for (int i = 0; i < n; i++) {
            double v = base[i], lo = qLo[i], hi = qHi[i];
            if (integerColumn[i]) {
                v = ClosedFormIk.wrap(v);
                base[i] = v;
                boolean in = v >= lo && v <= hi;
                if (!(in && v + TWO_PI > hi && v - TWO_PI < lo)) {
                    simple = false;
                    // outside, and the next turn towards the range already overshoots it: no turn fits
                    if (!in && (v < lo ? v + TWO_PI > hi : v - TWO_PI < lo)) none = true;
                }
            } else if (!(v >= lo && v <= hi)) {
                within = false;
            }
        }
        if (none) { // the wrapped q, outside the limits
            addUnique(base, cfxArm, manip, false);
            return;
        }
        if (simple) {
            addUnique(base, cfxArm, manip, within);
            return;
        }
        boolean single = true;
        for (int i = 0; i < n; i++) {
            double lo = qLo[i], hi = qHi[i];
            if (!integerColumn[i]) {
                cand[i][0] = base[i];
                candCount[i] = 1;
                continue;
            }
            double w = base[i]; // wrapped above
            if (w >= lo && w <= hi && w + TWO_PI > hi && w - TWO_PI < lo) { // exactly one turn fits: w
                cand[i][0] = w;
                candCount[i] = 1;
                continue;
            }
            int c = 0;
            // only the turns k that can land in [lo, hi] (one more each side for rounding), k in -2..2
            int kLo = (int) Math.max(-2, Math.ceil((lo - w) * INV_TWO_PI) - 1);
            int kHi = (int) Math.min(2, Math.floor((hi - w) * INV_TWO_PI) + 1);
            for (int k = kLo; k <= kHi; k++) {
                double v = w + TWO_PI * k;
                if (v >= lo && v <= hi) cand[i][c++] = v;
            }
            if (c == 0) { // no in-limit turn for this joint: the wrapped q, outside the limits
                addUnique(base, cfxArm, manip, false);
                return;
            }
            candCount[i] = c;
            if (c > 1) single = false;
        }
        if (single) { // one variant (a joint outside its range by a turn may have moved by one)
            for (int i = 0; i < n; i++) variant[i] = cand[i][0];
            addUnique(variant, cfxArm, manip, within);
            return;
        }
        Arrays.fill(odo, 0);
        while (true) {
            for (int i = 0; i < n; i++) variant[i] = cand[i][odo[i]];
            addUnique(variant, cfxArm, manip, within);
            int i = n - 1; // odometer, last joint fastest (the order of InverseKinematics before this class)
            while (i >= 0 && ++odo[i] == candCount[i]) odo[i--] = 0;
            if (i < 0) return;
        }
    }

    /** Adds q unless a stored solution is within 1e-7 rad (every joint) of it. */
    private void addUnique(double[] q, int cfxArm, double manip, boolean within) {
        double[][] store = sq;
        // the closed form's branches differ in joint 4 (wrist flip: theta4 + pi) and joint 1
        // (shoulder) almost always, so those two decide before the loop over the rest
        int first = n > 3 ? 3 : 0;
        double qa = q[first], q0 = q[0];
        for (int s = 0; s < count; s++) {
            double[] o = store[s];
            if (!(Math.abs(o[first] - qa) < 1e-7) || !(Math.abs(o[0] - q0) < 1e-7)) continue;
            int i = 1;
            while (i < n && Math.abs(o[i] - q[i]) < 1e-7) i++;
            if (i == n) return;
        }
        if (count == store.length) grow();
        System.arraycopy(q, 0, sq[count], 0, n);
        InverseKinematics.confInto(q, cfxArm, sConf, 4 * count);
        sWithin[count] = within;
        sManip[count] = manip;
        count++;
    }

    private void grow() {
        int cap = 2 * sq.length;
        double[][] nq = Arrays.copyOf(sq, cap);
        for (int i = sq.length; i < cap; i++) nq[i] = new double[n];
        sq = nq;
        sConf = Arrays.copyOf(sConf, 4 * cap);
        sWithin = Arrays.copyOf(sWithin, cap);
        sManip = Arrays.copyOf(sManip, cap);
        order = new int[cap];
    }

    /** Number of solutions of the last {@link #solveAll}. */
    public int count() { return count; }

    /** Joint value {@code joint} of solution i. */
    public double q(int i, int joint) { return sq[idx(i)][joint]; }

    /** Copies the joint values of solution i into {@code out}. */
    public void q(int i, double[] out) { System.arraycopy(sq[idx(i)], 0, out, 0, n); }

    public int cf1(int i) { return sConf[4 * idx(i)]; }

    public int cf4(int i) { return sConf[4 * idx(i) + 1]; }

    public int cf6(int i) { return sConf[4 * idx(i) + 2]; }

    public int cfx(int i) { return sConf[4 * idx(i) + 3]; }

    public boolean withinLimits(int i) { return sWithin[idx(i)]; }

    /** Manipulability |det J| of solution i (see {@link IkSolution#singularityMeasure()}). */
    public double manipulability(int i) { return sManip[idx(i)]; }

    /** Solution i as a value (allocates). */
    public IkSolution solution(int i) {
        int k = idx(i);
        return new IkSolution(sq[k].clone(), new ConfData(sConf[4 * k], sConf[4 * k + 1], sConf[4 * k + 2], sConf[4 * k + 3]),
                sWithin[k], sManip[k]);
    }

    /** All solutions of the last {@link #solveAll} as values (allocates). */
    public List<IkSolution> solutions() {
        List<IkSolution> out = new ArrayList<>(count);
        for (int i = 0; i < count; i++) out.add(solution(i));
        return out;
    }

    private int idx(int i) {
        if (i < 0 || i >= count) throw new IndexOutOfBoundsException("solution " + i + " of " + count);
        return order[i];
    }

    // ---------------------------------------------------------------- nearest solution

    /**
     * The solution inside the limits nearest to {@code qSeed} (Euclidean distance in q), as
     * {@link InverseKinematics#solveNear}: written into {@code qOut}; false when there is none.
     *
     * <p>For an approximate closed form (calibrated arm) the candidates are the damped
     * least-squares solution from the seed and the refined closed-form branches. Branches are
     * refined nearest first and the search stops when the next branch, even moved by twice the
     * largest refinement correction seen (at least 0.1 rad), cannot beat the best so far; usually
     * one or two refinements instead of eight.
     */
    public boolean solveNear(double[] baseTflange12, double[] qSeed, double[] qOut) {
        if (qSeed.length != n || qOut.length != n) throw new IllegalArgumentException("seed and output need " + n + " values");
        if (closed == null) return solveNumerical(baseTflange12, qSeed, qOut);
        double bestD = Double.POSITIVE_INFINITY;
        if (closed.exact) {
            solveAll(baseTflange12);
            for (int i = 0; i < count; i++) {
                int k = order[i];
                if (!sWithin[k]) continue;
                double d = dist2(sq[k], qSeed);
                if (d < bestD) { bestD = d; System.arraycopy(sq[k], 0, nearBest, 0, n); }
            }
        } else {
            System.arraycopy(qSeed, 0, nearTry, 0, n);
            if (dls(baseTflange12, nearTry, true) && model.withinLimits(nearTry)) {
                bestD = dist2(nearTry, qSeed);
                System.arraycopy(nearTry, 0, nearBest, 0, n);
            }
            int m = closed.solve(baseTflange12, thetas, null, null, scratch);
            for (int i = 0; i < m; i++) {
                model.q(thetas[i], branchQ[i]);
                System.arraycopy(branchQ[i], 0, nearTry, 0, n);
                branchD[i] = nearestVariant(nearTry, qSeed);
                branchDone[i] = false;
            }
            double slack = 0.1;
            while (true) {
                int next = -1;
                for (int i = 0; i < m; i++) if (!branchDone[i] && (next < 0 || branchD[i] < branchD[next])) next = i;
                if (next < 0 || branchD[next] == Double.POSITIVE_INFINITY) break;
                branchDone[next] = true;
                if (bestD < Double.POSITIVE_INFINITY && Math.sqrt(bestD) < Math.sqrt(branchD[next]) - slack) break;
                System.arraycopy(branchQ[next], 0, nearTry, 0, n);
                if (!dls(baseTflange12, nearTry, false)) continue;
                double moved = 0;
                for (int i = 0; i < n; i++) {
                    double dq = nearTry[i] - branchQ[next][i];
                    moved += dq * dq;
                }
                slack = Math.max(slack, 2 * Math.sqrt(moved));
                double d = nearestVariant(nearTry, qSeed);
                if (d < bestD) { bestD = d; System.arraycopy(nearTry, 0, nearBest, 0, n); }
            }
        }
        if (bestD < Double.POSITIVE_INFINITY) {
            System.arraycopy(nearBest, 0, qOut, 0, n);
            return true;
        }
        return solveNumerical(baseTflange12, qSeed, qOut) && model.withinLimits(qOut);
    }

    /**
     * Moves q (in place) to its turn variant inside the limits nearest to the seed and returns
     * the squared distance; infinite when no variant is inside the limits.
     */
    private double nearestVariant(double[] q, double[] seed) {
        double d = 0;
        for (int i = 0; i < n; i++) {
            if (integerColumn[i]) {
                double w = ClosedFormIk.wrap(q[i]), best = Double.NaN, bd = Double.POSITIVE_INFINITY;
                for (int k = -2; k <= 2; k++) {
                    double v = w + 2 * Math.PI * k;
                    if (v >= model.qMin(i) - 1e-9 && v <= model.qMax(i) + 1e-9 && Math.abs(v - seed[i]) < bd) {
                        bd = Math.abs(v - seed[i]);
                        best = v;
                    }
                }
                if (Double.isNaN(best)) return Double.POSITIVE_INFINITY;
                q[i] = best;
            } else if (!(q[i] >= model.qMin(i) - 1e-9 && q[i] <= model.qMax(i) + 1e-9)) {
                return Double.POSITIVE_INFINITY;
            }
            d += (q[i] - seed[i]) * (q[i] - seed[i]);
        }
        return d;
    }

    private double dist2(double[] a0, double[] b0) {
        double d = 0;
        for (int i = 0; i < n; i++) d += (a0[i] - b0[i]) * (a0[i] - b0[i]);
        return d;
    }

    // ---------------------------------------------------------------- manipulability

    /**
     * |det J| of the geometric Jacobian at q with position rows divided by the robot's size
     * (Yoshikawa's manipulability for a square Jacobian); LU with partial pivoting. 0 for
     * non-six-axis models.
     */
    public double manipulabilityAt(double[] q) {
        if (n != 6) return 0;
        model.geometricJacobian(q, ws, lu);
        for (int i = 0; i < 18; i++) lu[i] /= len;
        return Math.abs(det6(lu));
    }

    /** Determinant of a row-major 6x6 matrix, destroying it. */
    static double det6(double[] m) {
        double d = 1;
        for (int c = 0; c < 6; c++) {
            int piv = c;
            double best = Math.abs(m[6 * c + c]);
            for (int r = c + 1; r < 6; r++) {
                double v = Math.abs(m[6 * r + c]);
                if (v > best) { best = v; piv = r; }
            }
            if (best == 0) return 0;
            if (piv != c) {
                for (int j = c; j < 6; j++) { double t = m[6 * c + j]; m[6 * c + j] = m[6 * piv + j]; m[6 * piv + j] = t; }
                d = -d;
            }
            double p = m[6 * c + c];
            d *= p;
            for (int r = c + 1; r < 6; r++) {
                double fct = m[6 * r + c] / p;
                if (fct != 0) for (int j = c + 1; j < 6; j++) m[6 * r + j] -= fct * m[6 * c + j];
            }
        }
        return d;
    }

    // ---------------------------------------------------------------- numerical

    /**
     * Damped least squares from {@code qSeed}, keeping q inside the joint limits; writes the
     * result into {@code qOut} and returns whether it converged (position and orientation
     * within 10 {@link InverseKinematics#TOLERANCE}). Diagnostics: {@link #iterations()},
     * {@link #positionError()}, {@link #orientationError()}.
     */
    public boolean solveNumerical(double[] baseTflange12, double[] qSeed, double[] qOut) {
        if (qSeed.length != n || qOut.length != n) throw new IllegalArgumentException("seed and output need " + n + " values");
        System.arraycopy(qSeed, 0, qOut, 0, n);
        return dls(baseTflange12, qOut, true);
    }

    /** Iterations of the last numerical solve. */
    public int iterations() { return iterations; }

    /** Position error (m) at the end of the last numerical solve. */
    public double positionError() { return positionError; }

    /** Orientation error (rad) at the end of the last numerical solve. */
    public double orientationError() { return orientationError; }

    /** Whether the last numerical solve converged. */
    public boolean converged() { return converged; }

    /**
     * In-place Levenberg-Marquardt on q with the analytic geometric Jacobian: normal equations
     * (J^T W J + mu diag) dq = J^T W e with W = diag(1/len^2 x3, 1 x3) so metres and radians
     * weigh alike, solved by Cholesky; mu shrinks tenfold on success (Gauss-Newton near the
     * solution, quadratic convergence) and grows tenfold on failure.
     */
    boolean dls(double[] tgt, double[] q, boolean clampToLimits) {
        System.arraycopy(tgt, 0, target, 0, 12);
        if (clampToLimits) clamp(q);
        double w = 1 / (len * len);
        model.flange(q, ws, f);
        double err = error(target, f, e);
        double mu = 1e-3;
        int it = 0;
        boolean jacobianFresh = false;
        while (it < MAX_ITERATIONS && !(pos(e) < InverseKinematics.TOLERANCE && rot(e) < InverseKinematics.TOLERANCE)) {
            it++;
            if (!jacobianFresh) model.geometricJacobian(q, ws, jac);
            jacobianFresh = true;
            for (int r = 0; r < n; r++) {
                for (int c = r; c < n; c++) {
                    double sp = jac[r] * jac[c] + jac[n + r] * jac[n + c] + jac[2 * n + r] * jac[2 * n + c];
                    double so = jac[3 * n + r] * jac[3 * n + c] + jac[4 * n + r] * jac[4 * n + c] + jac[5 * n + r] * jac[5 * n + c];
                    a[r * n + c] = sp * w + so;
                    a[c * n + r] = a[r * n + c];
                }
                g[r] = (jac[r] * e[0] + jac[n + r] * e[1] + jac[2 * n + r] * e[2]) * w
                        + jac[3 * n + r] * e[3] + jac[4 * n + r] * e[4] + jac[5 * n + r] * e[5];
            }
            boolean accepted = false;
            for (int tries = 0; tries < 12 && !accepted; tries++) {
                solveDamped(mu);
                for (int i = 0; i < n; i++) qTry[i] = q[i] + y[i];
                if (clampToLimits) clamp(qTry);
                model.flange(qTry, ws, fTry);
                double errTry = error(target, fTry, eTry);
                if (errTry < err) {
                    System.arraycopy(qTry, 0, q, 0, n);
                    System.arraycopy(eTry, 0, e, 0, 6);
                    err = errTry;
                    mu = Math.max(mu * 0.1, 1e-12);
                    accepted = true;
                    jacobianFresh = false;
                } else {
                    mu *= 10;
                }
            }
            if (!accepted) break;
        }
        iterations = it;
        positionError = pos(e);
        orientationError = rot(e);
        converged = positionError < InverseKinematics.TOLERANCE * 10 && orientationError < InverseKinematics.TOLERANCE * 10;
        return converged;
    }

    private static double pos(double[] e) { return Math.sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]); }

    private static double rot(double[] e) { return Math.sqrt(e[3] * e[3] + e[4] * e[4] + e[5] * e[5]); }

    /** e = (target position - position, rotation vector of Rtarget R^T); returns the weighted squared norm. */
    private double error(double[] t, double[] fl, double[] err) {
        err[0] = t[3] - fl[3]; err[1] = t[7] - fl[7]; err[2] = t[11] - fl[11];
        // Rerr = Rt R^T: only the trace and the skew part are needed
        double r00 = t[0] * fl[0] + t[1] * fl[1] + t[2] * fl[2];
        double r11 = t[4] * fl[4] + t[5] * fl[5] + t[6] * fl[6];
        double r22 = t[8] * fl[8] + t[9] * fl[9] + t[10] * fl[10];
        double r01 = t[0] * fl[4] + t[1] * fl[5] + t[2] * fl[6], r10 = t[4] * fl[0] + t[5] * fl[1] + t[6] * fl[2];
        double r02 = t[0] * fl[8] + t[1] * fl[9] + t[2] * fl[10], r20 = t[8] * fl[0] + t[9] * fl[1] + t[10] * fl[2];
        double r12 = t[4] * fl[8] + t[5] * fl[9] + t[6] * fl[10], r21 = t[8] * fl[4] + t[9] * fl[5] + t[10] * fl[6];
        double vx = r21 - r12, vy = r02 - r20, vz = r10 - r01;
        double cos = Math.max(-1, Math.min(1, (r00 + r11 + r22 - 1) / 2));
        if (cos > 1 - 5e-13) { // angle < 1e-6: sin(angle) ~ angle, the skew part is the rotation vector
            err[3] = vx / 2; err[4] = vy / 2; err[5] = vz / 2;
        } else {
            double angle = FastTrig.acos(cos);
            if (Math.PI - angle < 1e-4) {
                org.robopro.models.Vec3 rv = Pose.of(new double[] {r00, r01, r02, r10, r11, r12, r20, r21, r22}, 0, 0, 0)
                        .rotationVector(); // far from the solution only
                err[3] = rv.x(); err[4] = rv.y(); err[5] = rv.z();
            } else {
                double k = angle / (2 * Math.sin(angle));
                err[3] = vx * k; err[4] = vy * k; err[5] = vz * k;
            }
        }
        return (err[0] * err[0] + err[1] * err[1] + err[2] * err[2]) / (len * len)
                + err[3] * err[3] + err[4] * err[4] + err[5] * err[5];
    }

    /** (A + mu (diag(A) + 1e-9)) y = g by Cholesky; A symmetric positive semi-definite. */
    private void solveDamped(double mu) {
        double[] l = chol;
        for (int i = 0; i < n; i++)
            for (int k = 0; k <= i; k++) {
                double s = a[i * n + k];
                if (i == k) s += mu * (a[i * n + i] + 1e-9);
                for (int p = 0; p < k; p++) s -= l[i * n + p] * l[k * n + p];
                if (i == k) l[i * n + i] = Math.sqrt(Math.max(s, 1e-300));
                else l[i * n + k] = s / l[k * n + k];
            }
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
    }

    private void clamp(double[] q) {
        for (int i = 0; i < n; i++) q[i] = Math.max(model.qMin(i), Math.min(model.qMax(i), q[i]));
    }
}
