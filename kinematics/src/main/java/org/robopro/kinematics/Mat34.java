package org.robopro.kinematics;

/**
 * Allocation-free helpers on row-major 3x4 rigid transforms [R | t] stored in double[12]
 * (entry (i, j) at 4 i + j, column 3 the translation). Post-multiplication by elementary
 * transformations touches only the columns they mix, which keeps FK and Jacobians cheap.
 */
final class Mat34 {
    private Mat34() { }

    static void identity(double[] m) {
        java.util.Arrays.fill(m, 0, 12, 0.0);
        m[0] = 1; m[5] = 1; m[10] = 1;
    }

    /** m = m * R_axis(c, s) (rotation with cosine c and sine s about local axis 0/1/2). */
    static void rotate(double[] m, int axis, double c, double s) {
        int a, b; // columns mixed: col_a' = c col_a + s col_b ; col_b' = -s col_a + c col_b
        switch (axis) {
            case 0 -> { a = 1; b = 2; }
            case 1 -> { a = 2; b = 0; }
            default -> { a = 0; b = 1; }
        }
        for (int i = 0; i < 12; i += 4) {
            double ma = m[i + a], mb = m[i + b];
            m[i + a] = c * ma + s * mb;
            m[i + b] = -s * ma + c * mb;
        }
    }

    /** m = m * T_axis(d). */
    static void translate(double[] m, int axis, double d) {
        m[3] += d * m[axis];
        m[7] += d * m[4 + axis];
        m[11] += d * m[8 + axis];
    }

    /** m = m * f, in place. */
    static void mulInPlace(double[] m, double[] f) {
        for (int i = 0; i < 12; i += 4) {
            double r0 = m[i], r1 = m[i + 1], r2 = m[i + 2];
            m[i] = r0 * f[0] + r1 * f[4] + r2 * f[8];
            m[i + 1] = r0 * f[1] + r1 * f[5] + r2 * f[9];
            m[i + 2] = r0 * f[2] + r1 * f[6] + r2 * f[10];
            m[i + 3] += r0 * f[3] + r1 * f[7] + r2 * f[11];
        }
    }

    static void apply(double[] m, Elementary.Op op, double value, double c, double s) {
        if (op.isRotation()) rotate(m, op.axis(), c, s);
        else translate(m, op.axis(), value);
    }

    static Pose toPose(double[] m) {
        return Pose.ofTrusted(new double[] {m[0], m[1], m[2], m[4], m[5], m[6], m[8], m[9], m[10]},
                m[3], m[7], m[11]);
    }

    static void fromPose(Pose p, double[] m) {
        for (int i = 0; i < 3; i++) for (int j = 0; j < 3; j++) m[4 * i + j] = p.rot(i, j);
        m[3] = p.x(); m[7] = p.y(); m[11] = p.z();
    }
}
