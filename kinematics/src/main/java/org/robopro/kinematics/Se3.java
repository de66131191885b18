package org.robopro.kinematics;

import java.util.Arrays;

/**
 * Rigid-body transforms (SE(3)) and rotations (SO(3)) on plain arrays, allocation-free: every
 * function writes into an array the caller owns. This is the fast level under {@link Pose} (the
 * convenient, immutable level, which uses the same formulas), for hot loops such as forward
 * kinematics, Jacobians, identification and batch compensation.
 *
 * <p>Layouts: a <em>rotation</em> is a row-major 3x3 matrix in {@code double[9]} (entry (i, j)
 * at 3 i + j); a <em>transform</em> is a row-major 3x4 matrix [R | t] in {@code double[12]}
 * (entry (i, j) at 4 i + j, column 3 the translation, metres). A rotation vector w (rad) is
 * axis times angle; quaternions are (w, x, y, z), scalar first, as in RAPID.
 *
 * <p>Exp is Rodrigues' formula; Log recovers the angle with atan2(|v|/2, (tr R - 1)/2), well
 * conditioned at every angle, and the axis from the skew part of R below 90° and from its
 * symmetric part above (R + Rᵀ = 2 cos θ I + 2 (1 - cos θ) a aᵀ), which stays exact near 180°
 * where the skew part vanishes. (J. Solà, D. Atchuthan, J. Deray, "A micro Lie theory for state
 * estimation in robotics", arXiv:1812.01537, its SO(3) appendix.)
 */
public final class Se3 {
    private Se3() { }

    // ------------------------------------------------------------------ SO(3), double[9]

    /** r = Exp(w) for the rotation vector (wx, wy, wz), rad. */
    public static void rotExp(double wx, double wy, double wz, double[] r) {
        exp(wx, wy, wz, r, 0);
    }

    /** w = Log(r), the rotation vector (rad, angle in [0, π]), written at w[off..off+2]. */
    public static void rotLog(double[] r, double[] w, int off) {
        log(r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7], r[8], w, off);
    }

    /** out = a b; out must not alias a or b. */
    public static void rotMul(double[] a, double[] b, double[] out) {
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                out[3 * i + j] = a[3 * i] * b[j] + a[3 * i + 1] * b[3 + j] + a[3 * i + 2] * b[6 + j];
    }

    /** out = a bᵀ; out must not alias a or b. */
    public static void rotMulT(double[] a, double[] b, double[] out) {
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                out[3 * i + j] = a[3 * i] * b[3 * j] + a[3 * i + 1] * b[3 * j + 1] + a[3 * i + 2] * b[3 * j + 2];
    }

    /** The rotation of the quaternion (w, x, y, z), normalised here; rejects one of length 0 or not finite. */
    public static void rotFromQuaternion(double qw, double qx, double qy, double qz, double[] r) {
        double n = Math.sqrt(qw * qw + qx * qx + qy * qy + qz * qz);
        if (!(n > 1e-9) || !Double.isFinite(n))
            throw new IllegalArgumentException("quaternion (" + qw + ", " + qx + ", " + qy + ", " + qz + ") has no direction");
        double w = qw / n, x = qx / n, y = qy / n, z = qz / n;
        r[0] = 1 - 2 * (y * y + z * z); r[1] = 2 * (x * y - z * w); r[2] = 2 * (x * z + y * w);
        r[3] = 2 * (x * y + z * w); r[4] = 1 - 2 * (x * x + z * z); r[5] = 2 * (y * z - x * w);
        r[6] = 2 * (x * z - y * w); r[7] = 2 * (y * z + x * w); r[8] = 1 - 2 * (x * x + y * y);
    }

    /** The unit quaternion (w, x, y, z), w ≥ 0, of a rotation, written at q[off..off+3]. */
    public static void rotQuaternion(double[] r, double[] q, int off) {
        quaternion(r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7], r[8], q, off);
    }

    /**
     * The rotation vector of Exp(d) Exp(w) (a left update of w by d), written at out[outOff..];
     * {@code work} holds at least 27 values and may not alias the others.
     */
    public static void rotLeftCompose(double[] w, int wOff, double[] d, int dOff, double[] out, int outOff, double[] work) {
        double[] a = work; // Exp(d) at 0, Exp(w) at 9, their product at 18
        exp(d[dOff], d[dOff + 1], d[dOff + 2], a, 0);
        exp(w[wOff], w[wOff + 1], w[wOff + 2], a, 9);
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                a[18 + 3 * i + j] = a[3 * i] * a[9 + j] + a[3 * i + 1] * a[12 + j] + a[3 * i + 2] * a[15 + j];
        log(a[18], a[19], a[20], a[21], a[22], a[23], a[24], a[25], a[26], out, outOff);
    }

    /**
     * out = J_l⁻¹(e) = I − ½[e]× + (1/θ² − (1 + cos θ)/(2 θ sin θ)) [e]×², the inverse of SO(3)'s
     * left Jacobian at the rotation vector e (θ = |e|), which maps a left perturbation of Exp(e) to
     * the change of e (Solà et al., SO(3) appendix); [e]×² is written as e eᵀ − θ² I.
     */
    public static void rotLeftJacobianInverse(double[] e, double[] out) {
        double ex = e[0], ey = e[1], ez = e[2];
        double th2 = ex * ex + ey * ey + ez * ez, th = Math.sqrt(th2);
        double c = th < 1e-4 ? 1.0 / 12 + th2 / 720 : 1 / th2 - (1 + Math.cos(th)) / (2 * th * Math.sin(th));
        out[0] = 1 + c * (ex * ex - th2); out[1] = 0.5 * ez + c * ex * ey;     out[2] = -0.5 * ey + c * ex * ez;
        out[3] = -0.5 * ez + c * ey * ex; out[4] = 1 + c * (ey * ey - th2);    out[5] = 0.5 * ex + c * ey * ez;
        out[6] = 0.5 * ey + c * ez * ex;  out[7] = -0.5 * ex + c * ez * ey;    out[8] = 1 + c * (ez * ez - th2);
    }

    // ------------------------------------------------------------------ SE(3), double[12]

    /** m = identity. */
    public static void identity(double[] m) {
        Arrays.fill(m, 0, 12, 0.0);
        m[0] = 1; m[5] = 1; m[10] = 1;
    }

    /** m = m R_axis, a rotation with cosine c and sine s about local axis 0 (x), 1 (y) or 2 (z); touches only the two columns it mixes. */
    public static void rotate(double[] m, int axis, double c, double s) {
        int a, b; // col_a' = c col_a + s col_b ; col_b' = -s col_a + c col_b
        switch (axis) {
            case 0 -> { a = 1; b = 2; }
            case 1 -> { a = 2; b = 0; }
            case 2 -> { a = 0; b = 1; }
            default -> throw new IllegalArgumentException("axis " + axis + " is not 0, 1 or 2");
        }
        for (int i = 0; i < 12; i += 4) {
            double ma = m[i + a], mb = m[i + b];
            m[i + a] = c * ma + s * mb;
            m[i + b] = -s * ma + c * mb;
        }
    }

    /** m = m T_axis(d): a translation by d (m) along local axis 0, 1 or 2. */
    public static void translate(double[] m, int axis, double d) {
        m[3] += d * m[axis];
        m[7] += d * m[4 + axis];
        m[11] += d * m[8 + axis];
    }

    /** m = m f, in place. */
    public static void mulInPlace(double[] m, double[] f) {
        for (int i = 0; i < 12; i += 4) {
            double r0 = m[i], r1 = m[i + 1], r2 = m[i + 2];
            m[i] = r0 * f[0] + r1 * f[4] + r2 * f[8];
            m[i + 1] = r0 * f[1] + r1 * f[5] + r2 * f[9];
            m[i + 2] = r0 * f[2] + r1 * f[6] + r2 * f[10];
            m[i + 3] += r0 * f[3] + r1 * f[7] + r2 * f[11];
        }
    }

    /** out = a b ({@code aTb} times {@code bTc} is {@code aTc}); out must not alias a or b. */
    public static void mul(double[] a, double[] b, double[] out) {
        for (int i = 0; i < 3; i++) {
            double a0 = a[4 * i], a1 = a[4 * i + 1], a2 = a[4 * i + 2];
            out[4 * i] = a0 * b[0] + a1 * b[4] + a2 * b[8];
            out[4 * i + 1] = a0 * b[1] + a1 * b[5] + a2 * b[9];
            out[4 * i + 2] = a0 * b[2] + a1 * b[6] + a2 * b[10];
            out[4 * i + 3] = a0 * b[3] + a1 * b[7] + a2 * b[11] + a[4 * i + 3];
        }
    }

    /** m = the transform of a pose. */
    public static void fromPose(Pose p, double[] m) {
        for (int i = 0; i < 3; i++) for (int j = 0; j < 3; j++) m[4 * i + j] = p.rot(i, j);
        m[3] = p.x(); m[7] = p.y(); m[11] = p.z();
    }

    /** The pose of a transform (allocates the pose; the rotation is trusted to be orthonormal). */
    public static Pose toPose(double[] m) {
        return Pose.ofTrusted(new double[] {m[0], m[1], m[2], m[4], m[5], m[6], m[8], m[9], m[10]}, m[3], m[7], m[11]);
    }

    /** m = [R(q) | p] from a quaternion q = (w, x, y, z) (normalised here) and a position p (m). */
    public static void fromQuaternion(double[] q, double[] p, double[] m) {
        double n = Math.sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        if (!(n > 1e-9) || !Double.isFinite(n))
            throw new IllegalArgumentException("quaternion (" + q[0] + ", " + q[1] + ", " + q[2] + ", " + q[3] + ") has no direction");
        double w = q[0] / n, x = q[1] / n, y = q[2] / n, z = q[3] / n;
        m[0] = 1 - 2 * (y * y + z * z); m[1] = 2 * (x * y - z * w); m[2] = 2 * (x * z + y * w); m[3] = p[0];
        m[4] = 2 * (x * y + z * w); m[5] = 1 - 2 * (x * x + z * z); m[6] = 2 * (y * z - x * w); m[7] = p[1];
        m[8] = 2 * (x * z - y * w); m[9] = 2 * (y * z + x * w); m[10] = 1 - 2 * (x * x + y * y); m[11] = p[2];
    }

    /** The unit quaternion (w, x, y, z), w ≥ 0, of a transform's rotation, written at q[off..off+3]. */
    public static void quaternion(double[] m, double[] q, int off) {
        quaternion(m[0], m[1], m[2], m[4], m[5], m[6], m[8], m[9], m[10], q, off);
    }

    /**
     * w = Log(R_a R_bᵀ), the rotation vector (base axes, rad) that turns b's orientation into a's,
     * for two transforms; written at w[off..off+2].
     */
    public static void rotationLogBetween(double[] a, double[] b, double[] w, int off) {
        double c00 = a[0] * b[0] + a[1] * b[1] + a[2] * b[2], c01 = a[0] * b[4] + a[1] * b[5] + a[2] * b[6],
                c02 = a[0] * b[8] + a[1] * b[9] + a[2] * b[10];
        double c10 = a[4] * b[0] + a[5] * b[1] + a[6] * b[2], c11 = a[4] * b[4] + a[5] * b[5] + a[6] * b[6],
                c12 = a[4] * b[8] + a[5] * b[9] + a[6] * b[10];
        double c20 = a[8] * b[0] + a[9] * b[1] + a[10] * b[2], c21 = a[8] * b[4] + a[9] * b[5] + a[10] * b[6],
                c22 = a[8] * b[8] + a[9] * b[9] + a[10] * b[10];
        log(c00, c01, c02, c10, c11, c12, c20, c21, c22, w, off);
    }

    // ------------------------------------------------------------------ shared formulas

    /** Rodrigues: Exp(w) written at r[off..off+8]. */
    private static void exp(double wx, double wy, double wz, double[] r, int off) {
        double th2 = wx * wx + wy * wy + wz * wz, th = Math.sqrt(th2);
        double a, b; // sin θ / θ and (1 - cos θ) / θ², by their series below 1e-4 rad
        if (th < 1e-4) { a = 1 - th2 / 6; b = 0.5 - th2 / 24; }
        else { a = Math.sin(th) / th; b = (1 - Math.cos(th)) / th2; }
        r[off] = 1 - b * (wy * wy + wz * wz); r[off + 1] = b * wx * wy - a * wz; r[off + 2] = b * wx * wz + a * wy;
        r[off + 3] = b * wx * wy + a * wz; r[off + 4] = 1 - b * (wx * wx + wz * wz); r[off + 5] = b * wy * wz - a * wx;
        r[off + 6] = b * wx * wz - a * wy; r[off + 7] = b * wy * wz + a * wx; r[off + 8] = 1 - b * (wx * wx + wy * wy);
    }

    /** Log of the rotation with entries r00..r22 (see the class comment for the method). */
    static void log(double r00, double r01, double r02, double r10, double r11, double r12, double r20, double r21, double r22,
                    double[] w, int off) {
        double vx = r21 - r12, vy = r02 - r20, vz = r10 - r01; // 2 sin θ a
        double s2 = Math.sqrt(vx * vx + vy * vy + vz * vz);      // 2 sin θ
        double c = (r00 + r11 + r22 - 1) / 2;                     // cos θ
        double th = Math.atan2(s2 / 2, c);
        if (c >= 0) {
            double k = th < 1e-4 ? 0.5 + th * th / 12 : th / s2; // θ / (2 sin θ)
            w[off] = vx * k; w[off + 1] = vy * k; w[off + 2] = vz * k;
            return;
        }
        // Above 90°: a_i a_j = (R_ij + R_ji - 2 cos θ δ_ij) / (2 (1 - cos θ)), from the largest diagonal
        // entry; the skew part gives the sign (at exactly 180° either sign is the same rotation).
        double d = 1 - c;
        double xx = (r00 - c) / d, yy = (r11 - c) / d, zz = (r22 - c) / d;
        double ax, ay, az;
        if (xx >= yy && xx >= zz) {
            ax = Math.sqrt(Math.max(0, xx));
            ay = (r01 + r10) / (2 * d * ax); az = (r02 + r20) / (2 * d * ax);
        } else if (yy >= zz) {
            ay = Math.sqrt(Math.max(0, yy));
            ax = (r01 + r10) / (2 * d * ay); az = (r12 + r21) / (2 * d * ay);
        } else {
            az = Math.sqrt(Math.max(0, zz));
            ax = (r02 + r20) / (2 * d * az); ay = (r12 + r21) / (2 * d * az);
        }
        if (ax * vx + ay * vy + az * vz < 0) { ax = -ax; ay = -ay; az = -az; }
        double n = Math.sqrt(ax * ax + ay * ay + az * az);
        w[off] = th * ax / n; w[off + 1] = th * ay / n; w[off + 2] = th * az / n;
    }

    /** Unit quaternion (w ≥ 0) of the rotation with entries r00..r22 (Shepperd's method: divide by the largest component). */
    static void quaternion(double r00, double r01, double r02, double r10, double r11, double r12, double r20, double r21, double r22,
                           double[] q, int off) {
        double t = r00 + r11 + r22, qw, qx, qy, qz;
        if (t > 0) {
            double s = Math.sqrt(t + 1) * 2;
            qw = 0.25 * s; qx = (r21 - r12) / s; qy = (r02 - r20) / s; qz = (r10 - r01) / s;
        } else if (r00 > r11 && r00 > r22) {
            double s = Math.sqrt(1 + r00 - r11 - r22) * 2;
            qw = (r21 - r12) / s; qx = 0.25 * s; qy = (r01 + r10) / s; qz = (r02 + r20) / s;
        } else if (r11 > r22) {
            double s = Math.sqrt(1 + r11 - r00 - r22) * 2;
            qw = (r02 - r20) / s; qx = (r01 + r10) / s; qy = 0.25 * s; qz = (r12 + r21) / s;
        } else {
            double s = Math.sqrt(1 + r22 - r00 - r11) * 2;
            qw = (r10 - r01) / s; qx = (r02 + r20) / s; qy = (r12 + r21) / s; qz = 0.25 * s;
        }
        double n = Math.sqrt(qw * qw + qx * qx + qy * qy + qz * qz) * (qw < 0 ? -1 : 1);
        q[off] = qw / n; q[off + 1] = qx / n; q[off + 2] = qy / n; q[off + 3] = qz / n;
    }
}
