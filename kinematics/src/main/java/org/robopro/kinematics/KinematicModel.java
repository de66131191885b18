package org.robopro.kinematics;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import org.ejml.data.DMatrixRMaj;
import org.ejml.dense.row.SingularOps_DDRM;
import org.robopro.models.FrameDescription;
import org.robopro.models.JointDescription;
import org.robopro.models.JointType;
import org.robopro.models.RobotDescription;
import org.robopro.models.Vec3;

/**
 * An immutable, thread-safe kinematic model built from a {@link RobotDescription} by the seed
 * paper's method (§4 frame assignment, Table 1 elementary transformations). SI units.
 * q = controller joint values, theta = model joint angles (theta = C q, the coupling).
 *
 * <p>The chain is baseTflange = F_0 * J_1(theta_1) F_1 * ... * J_n(theta_n) F_n, where F_0 is
 * the base row of Table 1, F_k (k = 1..n-1) the constant part of the transformation out of
 * joint k (DH or Hayati), F_n the last joint to flange row, and J_k = R_Z(theta_k) for a
 * revolute joint or T_Z(theta_k) for a prismatic one. Each F_k is a product of
 * {@link Elementary} transformations; those marked identified form the complete, minimal,
 * model-continuous parameter vector {@link #parameters()} (4R + 2P + 6 of them).
 *
 * <p>Hot paths ({@link #flange(double[], Workspace, double[])}, {@link #pointJacobian},
 * {@link #poseJacobian}) write into caller buffers and a per-thread {@link Workspace}.
 */
public final class KinematicModel {
    private final RobotDescription description;
    private final ModelBuilder.Convention convention;
    private final int n;
    private final boolean[] prismatic;
    private final double[][] c, cInv;
    private final boolean couplingIdentity;
    private final int[] cStart, cCol; // C in compressed rows
    private final double[] cVal;
    private final int[] ciStart, ciCol; // C^-1 in compressed rows (IK: q from theta per solution)
    private final int[] qFrom; // j when row i of C^-1 is exactly e_j (q_i = theta_j), else -1
    private final double[] ciVal;
    private final double[] qMin, qMax;
    private final List<Transformation> transformations;
    // compiled element arrays (all transformations, in chain order)
    private final int nEl;
    private final int[] elOp;
    private final double[] elVal, elCos, elSin;
    private final int[] elParam; // parameter index or -1
    private final int[] trStart; // first element of transformation k; trStart[n + 1] = nEl
    private final double[][] fixed; // F_k as 3x4
    // FK fast path (see flange(q, ws, out12)): joint k's angle offset folded into its R_Z, the
    // rest F'_k of transformation k as 3x4 and whether its rotation is exactly R_X-shaped
    private final double[] jointOffset;
    private final double[][] fastFixed;
    private final boolean[] fastRx;
    private final int[] thetaFrom; // j when row k of C is exactly e_j (theta_k = q_j), else -1
    private final List<ModelParameter> parameters;
    private final int[] paramElem;
    private final String identifiabilityNote;

    private KinematicModel(RobotDescription description, ModelBuilder.Convention convention,
                           List<Transformation> transformations, String identifiabilityNote) {
        this.description = description;
        this.convention = convention;
        this.n = description.dof();
        this.transformations = List.copyOf(transformations);
        this.identifiabilityNote = identifiabilityNote;
        prismatic = new boolean[n];
        qMin = new double[n];
        qMax = new double[n];
        for (int i = 0; i < n; i++) {
            JointDescription j = description.joints().get(i);
            prismatic[i] = j.type() == JointType.PRISMATIC;
            qMin[i] = j.min();
            qMax[i] = j.max();
        }
        c = description.couplingMatrix();
        cInv = invert(c, description.name());
        boolean id = true;
        for (int i = 0; i < n; i++) for (int j = 0; j < n; j++) if (c[i][j] != (i == j ? 1 : 0)) id = false;
        couplingIdentity = id;
        cStart = new int[n + 1];
        int nz = 0;
        for (double[] row : c) for (double v : row) if (v != 0) nz++;
        cCol = new int[nz];
        cVal = new double[nz];
        nz = 0;
        for (int i = 0; i < n; i++) {
            cStart[i] = nz;
            for (int j = 0; j < n; j++) if (c[i][j] != 0) { cCol[nz] = j; cVal[nz++] = c[i][j]; }
        }
        cStart[n] = nz;
        ciStart = new int[n + 1];
        nz = 0;
        for (double[] row : cInv) for (double v : row) if (v != 0) nz++;
        ciCol = new int[nz];
        ciVal = new double[nz];
        qFrom = new int[n];
        nz = 0;
        for (int i = 0; i < n; i++) {
            ciStart[i] = nz;
            for (int j = 0; j < n; j++) if (cInv[i][j] != 0) { ciCol[nz] = j; ciVal[nz++] = cInv[i][j]; }
            qFrom[i] = nz - ciStart[i] == 1 && ciVal[ciStart[i]] == 1 ? ciCol[ciStart[i]] : -1;
        }
        ciStart[n] = nz;

        int count = 0;
        for (Transformation t : transformations) count += t.elements().size();
        nEl = count;
        elOp = new int[nEl];
        elVal = new double[nEl];
        elCos = new double[nEl];
        elSin = new double[nEl];
        elParam = new int[nEl];
        trStart = new int[n + 2];
        fixed = new double[n + 1][12];
        List<ModelParameter> params = new ArrayList<>();
        List<Integer> pe = new ArrayList<>();
        int e = 0;
        for (Transformation t : transformations) {
            trStart[t.index()] = e;
            double[] f = fixed[t.index()];
            Se3.identity(f);
            for (Elementary el : t.elements()) {
                elOp[e] = el.op().ordinal();
                elVal[e] = el.value();
                elCos[e] = Math.cos(el.value());
                elSin[e] = Math.sin(el.value());
                Elementary.apply(f, el.op(), el.value(), elCos[e], elSin[e]);
                if (el.identified()) {
                    elParam[e] = params.size();
                    params.add(new ModelParameter(el.name(), el.kind(), t.index(), el.value()));
                    pe.add(e);
                } else {
                    elParam[e] = -1;
                }
                e++;
            }
        }
        trStart[n + 1] = nEl;
        jointOffset = new double[n];
        fastFixed = new double[n + 1][];
        fastRx = new boolean[n + 1];
        fastFixed[0] = fixed[0];
        for (int k = 1; k <= n; k++) {
            int first = trStart[k], end = trStart[k + 1];
            // R_Z(theta) R_Z(offset) = R_Z(theta + offset): one rotation instead of a 3x4 product's worth
            boolean fold = !prismatic[k - 1] && first < end && elOp[first] == Elementary.Op.RZ.ordinal();
            double[] f = new double[12];
            Se3.identity(f);
            for (int e2 = fold ? first + 1 : first; e2 < end; e2++)
                Elementary.apply(f, Elementary.Op.values()[elOp[e2]], elVal[e2], elCos[e2], elSin[e2]);
            jointOffset[k - 1] = fold ? elVal[first] : 0;
            fastFixed[k] = f;
            // exact structure only (it comes from the element list, not from the values): a DH row
            // T_Z T_X R_X T_Z leaves column 0 and row 0 of the rotation exactly (1, 0, 0)
            fastRx[k] = f[0] == 1 && f[1] == 0 && f[2] == 0 && f[4] == 0 && f[8] == 0;
        }
        thetaFrom = new int[n];
        for (int i = 0; i < n; i++) {
            thetaFrom[i] = -1;
            if (cStart[i + 1] - cStart[i] == 1 && cVal[cStart[i]] == 1) thetaFrom[i] = cCol[cStart[i]];
        }
        parameters = List.copyOf(params);
        paramElem = pe.stream().mapToInt(Integer::intValue).toArray();
    }

    /** Builds the complete, minimal, model-continuous model of a robot description. */
    public static KinematicModel build(RobotDescription description) {
        KinematicModel m = new KinematicModel(description, ModelBuilder.Convention.TABLE1,
                ModelBuilder.build(description, ModelBuilder.Convention.TABLE1), "");
        return m.checkedIdentifiability();
    }

    /**
     * The same robot parameterized by plain Denavit-Hartenberg transformations everywhere
     * (Eq. 5, identifying theta-offset, d, a, alpha of every joint), for comparison: singular
     * for parallel axes (§3), so its identification Jacobian loses rank on the IRB-2000.
     */
    public static KinematicModel buildPlainDh(RobotDescription description) {
        return new KinematicModel(description, ModelBuilder.Convention.PLAIN_DH,
                ModelBuilder.build(description, ModelBuilder.Convention.PLAIN_DH), "plain DH: not checked");
    }

    public RobotDescription description() { return description; }

    public int dof() { return n; }

    /** True for the plain-DH comparison model of {@link #buildPlainDh}. */
    public boolean isPlainDh() { return convention == ModelBuilder.Convention.PLAIN_DH; }

    /** Whether joint i (0-based) is prismatic. */
    public boolean isPrismatic(int i) { return prismatic[i]; }

    /** Every transformation with all its elementary transformations (identified and fixed). */
    public List<Transformation> transformations() { return transformations; }

    /**
     * Empty when the explicit rules gave a full-rank identified set; otherwise says which
     * elements the numerical check exchanged (see {@link #checkedIdentifiability()}).
     */
    public String identifiabilityNote() { return identifiabilityNote; }

    /** 4R + 2P + 6: the number of identifiable parameters of a serial chain. */
    public int expectedParameterCount() {
        int r = 0;
        for (boolean p : prismatic) if (!p) r++;
        return 4 * r + 2 * (n - r) + 6;
    }

    // ---------------------------------------------------------------- coupling and limits

    /** Model angles theta from controller values q (coupling). */
    public double[] theta(double[] q) {
        double[] t = new double[n];
        theta(q, t);
        return t;
    }

    void theta(double[] q, double[] out) {
        checkLength(q);
        if (couplingIdentity) {
            System.arraycopy(q, 0, out, 0, n);
            return;
        }
        for (int i = 0; i < n; i++) { // sparse rows of C: usually one or two terms
            double s = 0;
            for (int t = cStart[i], end = cStart[i + 1]; t < end; t++) s += cVal[t] * q[cCol[t]];
            out[i] = s;
        }
    }

    /** Controller values q from model angles theta (inverse coupling). */
    public double[] q(double[] theta) {
        double[] q = new double[n];
        q(theta, q);
        return q;
    }

    /** Allocation-free inverse coupling: writes q for model angles theta into {@code out}. */
    void q(double[] theta, double[] out) {
        checkLength(theta);
        if (couplingIdentity) {
            System.arraycopy(theta, 0, out, 0, n);
            return;
        }
        // a unit row of C^-1 is a copy; the others are sparse sums (usually one or two rows)
        for (int i = 0; i < n; i++) {
            int from = qFrom[i];
            if (from >= 0) {
                out[i] = theta[from];
                continue;
            }
            double s = 0;
            for (int t = ciStart[i], end = ciStart[i + 1]; t < end; t++) s += ciVal[t] * theta[ciCol[t]];
            out[i] = s;
        }
    }

    /** The coupling matrix C (theta = C q), a copy. */
    public double[][] couplingMatrix() {
        double[][] r = new double[n][];
        for (int i = 0; i < n; i++) r[i] = c[i].clone();
        return r;
    }

    /** True when every q is inside its joint limits (with 1e-9 slack for rounding). */
    public boolean withinLimits(double[] q) {
        checkLength(q);
        for (int i = 0; i < n; i++) if (!(q[i] >= qMin[i] - 1e-9 && q[i] <= qMax[i] + 1e-9)) return false;
        return true;
    }

    public double qMin(int i) { return qMin[i]; }

    public double qMax(int i) { return qMax[i]; }

    // ---------------------------------------------------------------- forward kinematics

    /** Preallocated buffers for allocation-free hot loops (FK, Jacobians); one per thread. */
    public Workspace newWorkspace() { return new Workspace(n, nEl); }

    /** Buffers owned by one thread; made by {@link #newWorkspace()}. Contents are implementation-defined. */
    public static final class Workspace {
        final double[] theta;
        final double[] m = new double[12];
        final double[] cs; // FK: cos, sin (revolute) or the displacement (prismatic) of each joint
        final double[] axes, origins;
        final int forDof, forElements;

        private Workspace(int dof, int elements) {
            theta = new double[dof];
            cs = new double[2 * dof];
            axes = new double[3 * elements];
            origins = new double[3 * elements];
            forDof = dof;
            forElements = elements;
        }
    }

    /** baseTflange at controller joint values q. */
    public Pose flange(double[] q) {
        double[] out = new double[12];
        flange(q, newWorkspace(), out);
        return Se3.toPose(out);
    }

    /** baseTtool = baseTflange(q) * flangeTtool. */
    public Pose tool(double[] q, Pose flangeTtool) { return flange(q).times(flangeTtool); }

    /**
     * Allocation-free FK: writes baseTflange at q into {@code out12} as a row-major 3x4 matrix
     * [R | t] (metres). One sine/cosine and one 3x4 product per joint.
     *
     * <p>Fast path: the matrix lives in twelve locals (no array round trip per joint); each
     * joint's constant R_Z(offset) is folded into its angle, so the step is M R_Z(theta + offset) F'
     * with the rotation's columns 0 and 1 mixed by (c, s) (12 multiplications) and F' multiplied
     * in (36, or 21 when F' is exactly R_X-shaped, as DH rows are); sine and cosine share one
     * reduction. {@link #flangeReference} is the plain element-by-element product it is tested against.
     */
    public void flange(double[] q, Workspace ws, double[] out12) {
        checkWorkspace(ws);
        checkLength(q);
        // 1: every joint's cosine and sine (independent of each other, so they overlap in the
        // CPU instead of each one stalling the product chain)
        double[] cs = ws.cs;
        for (int k = 0; k < n; k++) {
            int from = thetaFrom[k];
            double th;
            if (from >= 0) th = q[from];
            else {
                th = 0;
                for (int t = cStart[k], end = cStart[k + 1]; t < end; t++) th += cVal[t] * q[cCol[t]];
            }
            if (prismatic[k]) {
                cs[2 * k] = th;
                continue;
            }
            double x = th + jointOffset[k];
            if (Math.abs(x) < 1e5) { // FastTrig.sin / cos with one shared reduction, quadrant by table (no branch)
                double kq = Math.rint(x * (2 / Math.PI));
                double r = FastTrig.reduce(x, kq);
                double sp = FastTrig.sinPoly(r), cp = FastTrig.cosPoly(r);
                int quad = (int) kq & 3;
                cs[2 * k] = QC_C[quad] * cp + QC_S[quad] * sp;
                cs[2 * k + 1] = QS_C[quad] * cp + QS_S[quad] * sp;
            } else {
                cs[2 * k] = Math.cos(x);
                cs[2 * k + 1] = Math.sin(x);
            }
        }
        // 2: the product chain
        double[] f = fixed[0];
        double m00 = f[0], m01 = f[1], m02 = f[2], m03 = f[3];
        double m10 = f[4], m11 = f[5], m12 = f[6], m13 = f[7];
        double m20 = f[8], m21 = f[9], m22 = f[10], m23 = f[11];
        for (int k = 0; k < n; k++) {
            if (prismatic[k]) {
                double th = cs[2 * k];
                m03 += th * m02; m13 += th * m12; m23 += th * m22;
            } else {
                double c = cs[2 * k], s = cs[2 * k + 1];
                double a0 = c * m00 + s * m01, a1 = c * m10 + s * m11, a2 = c * m20 + s * m21;
                m01 = c * m01 - s * m00; m11 = c * m11 - s * m10; m21 = c * m21 - s * m20;
                m00 = a0; m10 = a1; m20 = a2;
            }
            f = fastFixed[k + 1];
            if (fastRx[k + 1]) {
                double f3 = f[3], f5 = f[5], f6 = f[6], f7 = f[7], f9 = f[9], f10 = f[10], f11 = f[11];
                m03 += m00 * f3 + m01 * f7 + m02 * f11;
                m13 += m10 * f3 + m11 * f7 + m12 * f11;
                m23 += m20 * f3 + m21 * f7 + m22 * f11;
                double b0 = m01 * f5 + m02 * f9, b1 = m11 * f5 + m12 * f9, b2 = m21 * f5 + m22 * f9;
                m02 = m01 * f6 + m02 * f10; m12 = m11 * f6 + m12 * f10; m22 = m21 * f6 + m22 * f10;
                m01 = b0; m11 = b1; m21 = b2;
            } else {
                double f0 = f[0], f1 = f[1], f2 = f[2], f3 = f[3], f4 = f[4], f5 = f[5];
                double f6 = f[6], f7 = f[7], f8 = f[8], f9 = f[9], f10 = f[10], f11 = f[11];
                double r0 = m00, r1 = m01, r2 = m02;
                m00 = r0 * f0 + r1 * f4 + r2 * f8; m01 = r0 * f1 + r1 * f5 + r2 * f9;
                m02 = r0 * f2 + r1 * f6 + r2 * f10; m03 += r0 * f3 + r1 * f7 + r2 * f11;
                r0 = m10; r1 = m11; r2 = m12;
                m10 = r0 * f0 + r1 * f4 + r2 * f8; m11 = r0 * f1 + r1 * f5 + r2 * f9;
                m12 = r0 * f2 + r1 * f6 + r2 * f10; m13 += r0 * f3 + r1 * f7 + r2 * f11;
                r0 = m20; r1 = m21; r2 = m22;
                m20 = r0 * f0 + r1 * f4 + r2 * f8; m21 = r0 * f1 + r1 * f5 + r2 * f9;
                m22 = r0 * f2 + r1 * f6 + r2 * f10; m23 += r0 * f3 + r1 * f7 + r2 * f11;
            }
        }
        out12[0] = m00; out12[1] = m01; out12[2] = m02; out12[3] = m03;
        out12[4] = m10; out12[5] = m11; out12[6] = m12; out12[7] = m13;
        out12[8] = m20; out12[9] = m21; out12[10] = m22; out12[11] = m23;
    }

    // cos and sin of x = k pi/2 + r from cosPoly(r) and sinPoly(r) by quadrant k & 3 (coefficients 0, +-1: exact)
    private static final double[] QC_C = {1, 0, -1, 0}, QC_S = {0, -1, 0, 1};
    private static final double[] QS_C = {0, 1, 0, -1}, QS_S = {1, 0, -1, 0};

    /** How many transformations the FK fast path multiplies as exactly R_X-shaped (tests). */
    int fastRxCount() {
        int c = 0;
        for (boolean b : fastRx) if (b) c++;
        return c;
    }

    /**
     * Reference FK for tests: the chain product element by element (Table 1 elements and the
     * joints' own R_Z / T_Z), with no folding or structure exploited. Allocates.
     */
    double[] flangeReference(double[] q) {
        double[] th = theta(q), m = new double[12];
        Se3.identity(m);
        for (int k = 0; k <= n; k++) {
            if (k > 0) {
                if (prismatic[k - 1]) Se3.translate(m, 2, th[k - 1]);
                else Se3.rotate(m, 2, Math.cos(th[k - 1]), Math.sin(th[k - 1]));
            }
            for (int e = trStart[k], end = trStart[k + 1]; e < end; e++)
                Elementary.apply(m, Elementary.Op.values()[elOp[e]], elVal[e], elCos[e], elSin[e]);
        }
        return m;
    }

    private void joint(double[] m, int k, double t) {
        if (prismatic[k]) Se3.translate(m, 2, t);
        else Se3.rotate(m, 2, FastTrig.cos(t), FastTrig.sin(t)); // pure Java: the reduction is shared
    }

    /**
     * Frames of every link at q, in base coordinates: index 0 the base (identity), index i the
     * frame attached to the link moved by joint i, last index (dof+1) the flange.
     * Frame i has its z axis on joint axis i and its origin on that axis.
     */
    public Pose[] linkFrames(double[] q) {
        double[] th = theta(q);
        Pose[] frames = new Pose[n + 2];
        frames[0] = Pose.IDENTITY;
        double[] m = fixed[0].clone();
        for (int k = 0; k < n; k++) {
            joint(m, k, th[k]);
            frames[k + 1] = Se3.toPose(m);
            Se3.mulInPlace(m, fixed[k + 1]);
        }
        frames[n + 1] = Se3.toPose(m);
        return frames;
    }

    /**
     * Joint frames at model angles theta, before each joint's own motion: index k (0-based)
     * is frame k+1 whose z axis is joint axis k+1; index n is the flange. 3x4 each.
     */
    double[][] jointFramesAtTheta(double[] th) {
        double[][] out = new double[n + 1][];
        double[] m = fixed[0].clone();
        for (int k = 0; k < n; k++) {
            out[k] = m.clone();
            joint(m, k, th[k]);
            Se3.mulInPlace(m, fixed[k + 1]);
        }
        out[n] = m;
        return out;
    }

    /** Constant part F_k of transformation k (0 = base), a copy. */
    double[] fixedPart(int k) { return fixed[k].clone(); }

    /** Constant part F_k, the model's own array: callers must not write to it. */
    double[] fixedRef(int k) { return fixed[k]; }

    /** 6 x dof geometric Jacobian of the flange w.r.t. q (rows vx vy vz wx wy wz, base frame). */
    public double[][] geometricJacobian(double[] q) {
        double[] out = new double[6 * n];
        geometricJacobian(q, newWorkspace(), out);
        double[][] j = new double[6][n];
        for (int r = 0; r < 6; r++) System.arraycopy(out, r * n, j[r], 0, n);
        return j;
    }

    /**
     * Allocation-free geometric Jacobian: writes baseTflange into {@code ws} and the row-major
     * 6 x dof Jacobian w.r.t. q (through the coupling: J_q = J_theta C) into {@code out}.
     */
    public void geometricJacobian(double[] q, Workspace ws, double[] out) {
        checkWorkspace(ws);
        double[] th = ws.theta;
        theta(q, th);
        double[] m = ws.m;
        double[] ax = ws.axes, org = ws.origins; // reuse: joint k axis at 3k, origin at 3k
        System.arraycopy(fixed[0], 0, m, 0, 12);
        for (int k = 0; k < n; k++) {
            ax[3 * k] = m[2]; ax[3 * k + 1] = m[6]; ax[3 * k + 2] = m[10];
            org[3 * k] = m[3]; org[3 * k + 1] = m[7]; org[3 * k + 2] = m[11];
            joint(m, k, th[k]);
            Se3.mulInPlace(m, fixed[k + 1]);
        }
        double px = m[3], py = m[7], pz = m[11];
        Arrays.fill(out, 0, 6 * n, 0.0);
        for (int k = 0; k < n; k++) {
            double zx = ax[3 * k], zy = ax[3 * k + 1], zz = ax[3 * k + 2];
            double v0, v1, v2, w0, w1, w2;
            if (prismatic[k]) {
                v0 = zx; v1 = zy; v2 = zz; w0 = 0; w1 = 0; w2 = 0;
            } else {
                double rx = px - org[3 * k], ry = py - org[3 * k + 1], rz = pz - org[3 * k + 2];
                v0 = zy * rz - zz * ry; v1 = zz * rx - zx * rz; v2 = zx * ry - zy * rx;
                w0 = zx; w1 = zy; w2 = zz;
            }
            // column k of J_theta spreads over the q columns j with C[k][j] != 0
            double[] ck = c[k];
            for (int j = 0; j < n; j++) {
                double f = ck[j];
                if (f == 0) continue;
                out[j] += f * v0; out[n + j] += f * v1; out[2 * n + j] += f * v2;
                out[3 * n + j] += f * w0; out[4 * n + j] += f * w1; out[5 * n + j] += f * w2;
            }
        }
    }

    // ---------------------------------------------------------------- parameters

    /** The identifiable parameters (Table 1), named, in order. */
    public List<ModelParameter> parameters() { return parameters; }

    public double[] parameterValues() {
        double[] v = new double[paramElem.length];
        for (int i = 0; i < v.length; i++) v[i] = elVal[paramElem[i]];
        return v;
    }

    /** Index of the named parameter, or -1. */
    public int parameterIndex(String name) {
        for (int i = 0; i < parameters.size(); i++) if (parameters.get(i).name().equals(name)) return i;
        return -1;
    }

    /** The same structure with other parameter values (e.g. identified ones). */
    public KinematicModel withParameterValues(double[] values) {
        if (values.length != paramElem.length)
            throw new IllegalArgumentException("expected " + paramElem.length + " parameter values, got " + values.length);
        for (double v : values) if (!Double.isFinite(v)) throw new IllegalArgumentException("non-finite parameter value " + Arrays.toString(values));
        List<Transformation> ts = new ArrayList<>(transformations.size());
        int p = 0;
        for (Transformation t : transformations) {
            List<Elementary> els = new ArrayList<>(t.elements().size());
            for (Elementary el : t.elements()) els.add(el.identified() ? el.withValue(values[p++]) : el);
            ts.add(t.withElements(els));
        }
        return new KinematicModel(description, convention, ts, identifiabilityNote);
    }

    /**
     * This model written back as a robot description (joint axes and flange at the zero
     * position, computed from the current parameters), so a calibrated model is an ordinary
     * robot file. Names, limits, speeds, coupling and the rest are kept.
     */
    public RobotDescription toDescription() {
        double[][] frames = jointFramesAtTheta(new double[n]);
        List<JointDescription> joints = new ArrayList<>(n);
        for (int k = 0; k < n; k++) {
            double[] f = frames[k];
            JointDescription j = description.joints().get(k);
            joints.add(new JointDescription(j.name(), j.type(), new Vec3(f[3], f[7], f[11]),
                    new Vec3(f[2], f[6], f[10]), j.min(), j.max(), j.maxSpeed()));
        }
        double[] fl = frames[n];
        FrameDescription flange = new FrameDescription(new Vec3(fl[3], fl[7], fl[11]),
                new Vec3(fl[0], fl[4], fl[8]), new Vec3(fl[2], fl[6], fl[10]));
        return description.withJointsAndFlange(joints, flange);
    }

    // ---------------------------------------------------------------- identification Jacobians

    /**
     * Walks the chain element by element at model angles theta (already in ws.theta), storing
     * the world axis and origin of every element that has a column (identified ones, or all
     * when {@code all}); leaves baseTflange in ws.m. A rotation about world axis a through o
     * moves a point p by a x (p - o) and turns the frame about a; a translation moves it by a.
     */
    private void walk(Workspace ws, boolean all) {
        double[] m = ws.m, th = ws.theta, ax = ws.axes, org = ws.origins;
        Se3.identity(m);
        for (int k = 0; k <= n; k++) {
            if (k > 0) joint(m, k - 1, th[k - 1]);
            for (int e = trStart[k], end = trStart[k + 1]; e < end; e++) {
                int op = elOp[e];
                int a = op % 3;
                if (all || elParam[e] >= 0) {
                    ax[3 * e] = m[a]; ax[3 * e + 1] = m[4 + a]; ax[3 * e + 2] = m[8 + a];
                    org[3 * e] = m[3]; org[3 * e + 1] = m[7]; org[3 * e + 2] = m[11];
                }
                if (op >= 3) Se3.rotate(m, a, elCos[e], elSin[e]);
                else Se3.translate(m, a, elVal[e]);
            }
        }
    }

    /**
     * Identification Jacobian (analytic) of a point fixed on the flange: writes the point's
     * position in base coordinates (m) into {@code posOut} (length 3) and d(position)/d(parameter)
     * into {@code jacOut}, row-major 3 x P with P = parameters().size(). {@code pointInFlange}
     * is in flange coordinates (m).
     */
    public void pointJacobian(double[] q, double[] pointInFlange, Workspace ws, double[] posOut, double[] jacOut) {
        checkWorkspace(ws);
        theta(q, ws.theta);
        walk(ws, false);
        double[] m = ws.m;
        double x = pointInFlange[0], y = pointInFlange[1], z = pointInFlange[2];
        double px = m[0] * x + m[1] * y + m[2] * z + m[3];
        double py = m[4] * x + m[5] * y + m[6] * z + m[7];
        double pz = m[8] * x + m[9] * y + m[10] * z + m[11];
        posOut[0] = px; posOut[1] = py; posOut[2] = pz;
        int np = paramElem.length;
        double[] ax = ws.axes, org = ws.origins;
        for (int c0 = 0; c0 < np; c0++) {
            int e = paramElem[c0];
            double ux = ax[3 * e], uy = ax[3 * e + 1], uz = ax[3 * e + 2];
            if (elOp[e] >= 3) {
                double rx = px - org[3 * e], ry = py - org[3 * e + 1], rz = pz - org[3 * e + 2];
                jacOut[c0] = uy * rz - uz * ry;
                jacOut[np + c0] = uz * rx - ux * rz;
                jacOut[2 * np + c0] = ux * ry - uy * rx;
            } else {
                jacOut[c0] = ux;
                jacOut[np + c0] = uy;
                jacOut[2 * np + c0] = uz;
            }
        }
    }

    /**
     * Identification Jacobian of the full pose of a tool frame {@code flangeTtool}: writes the
     * 3x4 [R | t] of baseTtool into {@code pose12} and a row-major 6 x P Jacobian into
     * {@code jacOut}: rows 0-2 d(position)/dp (m per unit), rows 3-5 the small rotation
     * (rad per unit) about base x, y, z.
     */
    public void poseJacobian(double[] q, Pose flangeTtool, Workspace ws, double[] pose12, double[] jacOut) {
        checkWorkspace(ws);
        theta(q, ws.theta);
        walk(ws, false);
        toolPose(ws.m, flangeTtool, pose12);
        columns(ws, pose12, paramElem, jacOut);
    }

    /** 6 x (all elements) pose Jacobian at q, identified or not (for the identifiability check). */
    void elementPoseJacobian(double[] q, Pose flangeTtool, Workspace ws, double[] pose12, double[] jacOut) {
        theta(q, ws.theta);
        walk(ws, true);
        toolPose(ws.m, flangeTtool, pose12);
        int[] all = new int[nEl];
        for (int i = 0; i < nEl; i++) all[i] = i;
        columns(ws, pose12, all, jacOut);
    }

    private static void toolPose(double[] m, Pose tool, double[] out) {
        if (tool == null || tool == Pose.IDENTITY) {
            System.arraycopy(m, 0, out, 0, 12);
            return;
        }
        double[] t = new double[12];
        Se3.fromPose(tool, t);
        System.arraycopy(m, 0, out, 0, 12);
        Se3.mulInPlace(out, t);
    }

    private void columns(Workspace ws, double[] pose12, int[] elems, double[] jacOut) {
        double px = pose12[3], py = pose12[7], pz = pose12[11];
        int np = elems.length;
        double[] ax = ws.axes, org = ws.origins;
        for (int c0 = 0; c0 < np; c0++) {
            int e = elems[c0];
            double ux = ax[3 * e], uy = ax[3 * e + 1], uz = ax[3 * e + 2];
            if (elOp[e] >= 3) {
                double rx = px - org[3 * e], ry = py - org[3 * e + 1], rz = pz - org[3 * e + 2];
                jacOut[c0] = uy * rz - uz * ry;
                jacOut[np + c0] = uz * rx - ux * rz;
                jacOut[2 * np + c0] = ux * ry - uy * rx;
                jacOut[3 * np + c0] = ux;
                jacOut[4 * np + c0] = uy;
                jacOut[5 * np + c0] = uz;
            } else {
                jacOut[c0] = ux;
                jacOut[np + c0] = uy;
                jacOut[2 * np + c0] = uz;
                jacOut[3 * np + c0] = 0;
                jacOut[4 * np + c0] = 0;
                jacOut[5 * np + c0] = 0;
            }
        }
    }

    // ---------------------------------------------------------------- identifiability

    /** A length (m) to make translation and rotation columns comparable: the robot's size. */
    public double characteristicLength() {
        double l = description.flange().origin().norm();
        for (JointDescription j : description.joints()) l = Math.max(l, j.point().norm());
        return Math.max(l, 0.1);
    }

    /** Random controller values inside the limits (ranges wider than a turn use +-pi), seeded. */
    public double[][] randomConfigurations(int count, long seed) {
        Random r = new Random(seed);
        double[][] qs = new double[count][n];
        for (int i = 0; i < count; i++)
            for (int k = 0; k < n; k++) {
                double lo = qMin[k], hi = qMax[k];
                double span = prismatic[k] ? 2.0 : 2 * Math.PI;
                if (!(hi - lo <= span)) { double mid = 0.5 * (lo + hi); lo = mid - span / 2; hi = mid + span / 2; }
                if (!Double.isFinite(lo) || !Double.isFinite(hi)) { lo = -span / 2; hi = span / 2; }
                qs[i][k] = lo + r.nextDouble() * (hi - lo);
            }
        return qs;
    }

    /**
     * The stacked, scaled identification Jacobian of the full flange pose over random
     * configurations: position rows divided by {@link #characteristicLength()}, every column
     * normalised to unit length. Columns are the given element indices.
     */
    double[][] scaledElementJacobian(int[] elems, int configs, long seed) {
        double len = characteristicLength();
        double[][] qs = randomConfigurations(configs, seed);
        Workspace ws = newWorkspace();
        double[] pose = new double[12], jac = new double[6 * nEl];
        double[][] out = new double[6 * configs][elems.length];
        for (int i = 0; i < configs; i++) {
            elementPoseJacobian(qs[i], Pose.IDENTITY, ws, pose, jac);
            for (int r = 0; r < 6; r++)
                for (int c0 = 0; c0 < elems.length; c0++)
                    out[6 * i + r][c0] = jac[r * nEl + elems[c0]] / (r < 3 ? len : 1);
        }
        for (int c0 = 0; c0 < elems.length; c0++) {
            double s = 0;
            for (double[] row : out) s += row[c0] * row[c0];
            s = Math.sqrt(s);
            if (s > 0) for (double[] row : out) row[c0] /= s;
        }
        return out;
    }

    /** Singular values (descending) of the scaled identification Jacobian of the identified parameters. */
    public double[] identificationSingularValues() {
        double[][] j = scaledElementJacobian(paramElem, 24, 20240607L);
        double[] s = SingularOps_DDRM.singularValues(new DMatrixRMaj(j));
        Arrays.sort(s);
        for (int i = 0; i < s.length / 2; i++) { double t = s[i]; s[i] = s[s.length - 1 - i]; s[s.length - 1 - i] = t; }
        return s;
    }

    /** Numerical rank of the identification Jacobian (relative tolerance 1e-9). */
    public int identificationRank() {
        double[] s = identificationSingularValues();
        int r = 0;
        for (double v : s) if (v > 1e-9 * s[0]) r++;
        return r;
    }

    /** Condition number of the scaled identification Jacobian (infinite when rank-deficient). */
    public double identificationConditionNumber() {
        double[] s = identificationSingularValues();
        double min = s[s.length - 1];
        return min > 1e-12 * s[0] ? s[0] / min : Double.POSITIVE_INFINITY;
    }

    /**
     * Verifies numerically that the identified set has full column rank with 4R + 2P + 6
     * columns; if the explicit rules fall short for an unusual geometry, exchanges elements
     * greedily (rule-identified first, in chain order; then the fixed ones) keeping those that
     * raise the rank, and says so in {@link #identifiabilityNote()}.
     */
    private KinematicModel checkedIdentifiability() {
        int expected = expectedParameterCount();
        if (paramElem.length == expected && identificationRank() == expected) return this;
        List<Integer> order = new ArrayList<>();
        for (int e : paramElem) order.add(e);
        int idx = 0;
        for (Transformation t : transformations)
            for (Elementary el : t.elements()) {
                if (!el.identified() && !el.name().endsWith(".r0")) order.add(idx);
                idx++;
            }
        int[] cand = order.stream().mapToInt(Integer::intValue).toArray();
        double[][] j = scaledElementJacobian(cand, 24, 20240607L);
        int rows = j.length;
        List<double[]> basis = new ArrayList<>();
        boolean[] keep = new boolean[nEl];
        for (int c0 = 0; c0 < cand.length && basis.size() < expected; c0++) {
            double[] v = new double[rows];
            for (int r = 0; r < rows; r++) v[r] = j[r][c0];
            for (int pass = 0; pass < 2; pass++) // modified Gram-Schmidt, twice for stability
                for (double[] b : basis) {
                    double d = 0;
                    for (int r = 0; r < rows; r++) d += b[r] * v[r];
                    for (int r = 0; r < rows; r++) v[r] -= d * b[r];
                }
            double norm = 0;
            for (double x : v) norm += x * x;
            norm = Math.sqrt(norm);
            if (norm > 1e-6) {
                for (int r = 0; r < rows; r++) v[r] /= norm;
                basis.add(v);
                keep[cand[c0]] = true;
            }
        }
        List<String> dropped = new ArrayList<>(), added = new ArrayList<>();
        List<Transformation> ts = new ArrayList<>();
        idx = 0;
        for (Transformation t : transformations) {
            List<Elementary> els = new ArrayList<>();
            for (Elementary el : t.elements()) {
                if (el.identified() && !keep[idx]) dropped.add(el.name());
                if (!el.identified() && keep[idx]) added.add(el.name());
                els.add(el.withIdentified(keep[idx]));
                idx++;
            }
            ts.add(t.withElements(els));
        }
        String note = "numerical identifiability check: fixed " + dropped + ", identified " + added
                + (basis.size() < expected ? "; rank " + basis.size() + " < " + expected + " (degenerate geometry)" : "");
        return new KinematicModel(description, convention, ts, note);
    }

    // ---------------------------------------------------------------- helpers

    private void checkLength(double[] v) {
        if (v.length != n) throw new IllegalArgumentException("expected " + n + " joint values, got " + v.length);
    }

    private void checkWorkspace(Workspace ws) {
        if (ws.forDof != n || ws.forElements != nEl)
            throw new IllegalArgumentException("workspace was made for another model");
    }

    private static double[][] invert(double[][] a, String robot) {
        int n = a.length;
        double[][] m = new double[n][2 * n];
        for (int i = 0; i < n; i++) {
            System.arraycopy(a[i], 0, m[i], 0, n);
            m[i][n + i] = 1;
        }
        for (int col = 0; col < n; col++) {
            int piv = col;
            for (int r = col + 1; r < n; r++) if (Math.abs(m[r][col]) > Math.abs(m[piv][col])) piv = r;
            if (Math.abs(m[piv][col]) < 1e-12)
                throw new org.robopro.models.InputException(robot, 0, 0, "coupling", "coupling matrix is singular");
            double[] t = m[piv]; m[piv] = m[col]; m[col] = t;
            double p = m[col][col];
            for (int j = 0; j < 2 * n; j++) m[col][j] /= p;
            for (int r = 0; r < n; r++) {
                if (r == col) continue;
                double f = m[r][col];
                if (f != 0) for (int j = 0; j < 2 * n; j++) m[r][j] -= f * m[col][j];
            }
        }
        double[][] inv = new double[n][n];
        for (int i = 0; i < n; i++) System.arraycopy(m[i], n, inv[i], 0, n);
        return inv;
    }

    @Override
    public String toString() {
        return "KinematicModel[" + description.name() + ", " + n + " joints, " + parameters.size() + " parameters]";
    }
}
