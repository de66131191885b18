package org.robopro.calibration.identification;

/** SO(3) exp/log on row-major 3x3 arrays (Rodrigues), for the identification hot loop. */
final class Rotations {
    private Rotations() { }

    /** R = Exp(w) for a rotation vector w (rad). */
    static void exp(double wx, double wy, double wz, double[] r) {
        double th2 = wx * wx + wy * wy + wz * wz, th = Math.sqrt(th2);
        double a, b;
        if (th < 1e-6) { a = 1 - th2 / 6; b = 0.5 - th2 / 24; }
        else { a = Math.sin(th) / th; b = (1 - Math.cos(th)) / th2; }
        r[0] = 1 - b * (wy * wy + wz * wz); r[1] = b * wx * wy - a * wz; r[2] = b * wx * wz + a * wy;
        r[3] = b * wx * wy + a * wz; r[4] = 1 - b * (wx * wx + wz * wz); r[5] = b * wy * wz - a * wx;
        r[6] = b * wx * wz - a * wy; r[7] = b * wy * wz + a * wx; r[8] = 1 - b * (wx * wx + wy * wy);
    }

    /** w = Log(R), the rotation vector (rad), writes 3 values at out[off..off+2]. */
    static void log(double[] r, double[] out, int off) {
        double c = Math.max(-1, Math.min(1, (r[0] + r[4] + r[8] - 1) / 2));
        double th = Math.acos(c);
        double vx = r[7] - r[5], vy = r[2] - r[6], vz = r[3] - r[1];
        if (th < 1e-6) {
            out[off] = vx / 2; out[off + 1] = vy / 2; out[off + 2] = vz / 2;
            return;
        }
        if (Math.PI - th < 1e-4) {
            // Near pi: axis from the symmetric part, sign from the skew part.
            double xx = Math.sqrt(Math.max(0, (r[0] + 1) / 2)), yy = Math.sqrt(Math.max(0, (r[4] + 1) / 2)),
                    zz = Math.sqrt(Math.max(0, (r[8] + 1) / 2));
            double ax, ay, az;
            if (xx >= yy && xx >= zz) { ax = xx; ay = (r[1] + r[3]) / (4 * xx); az = (r[2] + r[6]) / (4 * xx); }
            else if (yy >= zz) { ay = yy; ax = (r[1] + r[3]) / (4 * yy); az = (r[5] + r[7]) / (4 * yy); }
            else { az = zz; ax = (r[2] + r[6]) / (4 * zz); ay = (r[5] + r[7]) / (4 * zz); }
            if (ax * vx + ay * vy + az * vz < 0) { ax = -ax; ay = -ay; az = -az; }
            double n = Math.sqrt(ax * ax + ay * ay + az * az);
            out[off] = th * ax / n; out[off + 1] = th * ay / n; out[off + 2] = th * az / n;
            return;
        }
        double k = th / (2 * Math.sin(th));
        out[off] = vx * k; out[off + 1] = vy * k; out[off + 2] = vz * k;
    }

    /** out = a * b (3x3 row-major); out may not alias. */
    static void mul(double[] a, double[] b, double[] out) {
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                out[3 * i + j] = a[3 * i] * b[j] + a[3 * i + 1] * b[3 + j] + a[3 * i + 2] * b[6 + j];
    }

    /** out = a * bᵀ. */
    static void mulT(double[] a, double[] b, double[] out) {
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                out[3 * i + j] = a[3 * i] * b[3 * j] + a[3 * i + 1] * b[3 * j + 1] + a[3 * i + 2] * b[3 * j + 2];
    }

    /** The new rotation vector of Exp(d) * Exp(w). */
    static void leftCompose(double[] w, int wOff, double[] d, int dOff, double[] out, int outOff) {
        double[] a = new double[9], b = new double[9], c = new double[9];
        exp(d[dOff], d[dOff + 1], d[dOff + 2], a);
        exp(w[wOff], w[wOff + 1], w[wOff + 2], b);
        mul(a, b, c);
        log(c, out, outOff);
    }
}
