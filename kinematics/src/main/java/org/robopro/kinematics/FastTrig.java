package org.robopro.kinematics;

/**
 * Pure-Java sin / cos / atan2 / acos / asin for the kinematics hot paths. On OpenJDK 17 {@link Math#atan2},
 * {@link Math#acos} and {@link Math#asin} are not JIT intrinsics but calls into native fdlibm
 * (a few hundred instructions each), and closed-form IK needs about 30 of them per pose.
 *
 * <p>Method: reduce to t = min/max in [0, 1], pick c = round(16 t) / 16 and use
 * atan t = atan c + atan u, u = (t - c) / (1 + t c), |u| <= 1/32, where atan c comes from a
 * table filled by {@link StrictMath#atan} and atan u from its Taylor series to u^13 (truncation
 * below 1e-19). Agrees with {@link Math#atan2} within a few 1e-16 rad (tested); non-finite and
 * zero inputs go to {@link Math#atan2}.
 */
final class FastTrig {
    private FastTrig() { }

    private static final double[] ATAN_TABLE = new double[17];

    static {
        for (int i = 0; i <= 16; i++) ATAN_TABLE[i] = StrictMath.atan(i / 16.0);
    }

    // pi/2 in three parts: HI has 33 significant bits (k * HI exact for |k| < 2^20), MID the rest
    // of the double Math.PI / 2 (20 bits), LO = pi/2 - Math.PI/2 (Cody-Waite reduction)
    private static final double PIO2_HI = Double.longBitsToDouble(Double.doubleToRawLongBits(Math.PI / 2) & 0xFFFFFFFFFE000000L);
    private static final double PIO2_MID = Math.PI / 2 - PIO2_HI;
    private static final double PIO2_LO = 6.123233995736766e-17;

    /**
     * sin x for joint angles: x = k pi/2 + r, |r| <= pi/4, then fdlibm's kernel polynomials for
     * sin and cos of r; |x| >= 1e5 goes to {@link Math#sin}. Used in
     * forward kinematics, where sin and cos of the same angle share the reduction after inlining.
     */
    static double sin(double x) {
        if (!(Math.abs(x) < 1e5)) return Math.sin(x);
        double k = Math.rint(x * (2 / Math.PI));
        double r = ((x - k * PIO2_HI) - k * PIO2_MID) - k * PIO2_LO;
        switch ((int) k & 3) {
            case 0: return sinPoly(r);
            case 1: return cosPoly(r);
            case 2: return -sinPoly(r);
            default: return -cosPoly(r);
        }
    }

    /** cos x, as {@link #sin}. */
    static double cos(double x) {
        if (!(Math.abs(x) < 1e5)) return Math.cos(x);
        double k = Math.rint(x * (2 / Math.PI));
        double r = ((x - k * PIO2_HI) - k * PIO2_MID) - k * PIO2_LO;
        switch ((int) k & 3) {
            case 0: return cosPoly(r);
            case 1: return -sinPoly(r);
            case 2: return -cosPoly(r);
            default: return sinPoly(r);
        }
    }

    /** r = x - k pi/2 (three-part Cody-Waite), k = rint(x * 2 / pi), for |x| < 1e5. */
    static double reduce(double x, double k) {
        return ((x - k * PIO2_HI) - k * PIO2_MID) - k * PIO2_LO;
    }

    // minimax coefficients of fdlibm's __kernel_sin / __kernel_cos (k_sin.c, k_cos.c) on |r| <= pi/4:
    // degree 13 / 14, error below 2^-58, i.e. within an ulp like Math.sin / Math.cos
    private static final double S1 = -1.66666666666666324348e-01, S2 = 8.33333333332248946124e-03,
            S3 = -1.98412698298579493134e-04, S4 = 2.75573137070700676789e-06,
            S5 = -2.50507602534068634195e-08, S6 = 1.58969099521155010221e-10;
    private static final double C1 = 4.16666666666666019037e-02, C2 = -1.38888888888741095749e-03,
            C3 = 2.48015872894767294178e-05, C4 = -2.75573143513906633035e-07,
            C5 = 2.08757232129817482790e-09, C6 = -1.13596475577881948265e-11;

    /**
     * sin r for |r| <= pi/4. The polynomial in z = r^2 is split in two halves evaluated side by
     * side (z and z^2 = w available early) instead of one Horner chain: about half the latency,
     * which is what a chain of six joints waits for.
     */
    static double sinPoly(double r) {
        double z = r * r, w = z * z;
        double p = (S2 + z * (S3 + z * S4)) + z * w * (S5 + z * S6);
        return r + r * z * (S1 + z * p);
    }

    /** cos r for |r| <= pi/4; 1 - z/2 is formed with its rounding error carried (as fdlibm does). */
    static double cosPoly(double r) {
        double z = r * r, w = z * z;
        double p = z * (C1 + z * (C2 + z * C3)) + w * w * (C4 + z * (C5 + z * C6));
        double hz = 0.5 * z, h = 1 - hz;
        return h + (((1 - h) - hz) + z * p);
    }

    static double atan2(double y, double x) {
        double ax = Math.abs(x), ay = Math.abs(y), s = ax + ay;
        if (!(s > 0) || s == Double.POSITIVE_INFINITY) return Math.atan2(y, x);
        boolean swap = ay > ax;
        double t = swap ? ax / ay : ay / ax;
        int i = (int) (t * 16 + 0.5);
        double c = i * 0.0625;
        double u = (t - c) / (1 + t * c), u2 = u * u;
        double a = ATAN_TABLE[i] + u * (1 + u2 * (-1.0 / 3 + u2 * (1.0 / 5 + u2 * (-1.0 / 7
                + u2 * (1.0 / 9 + u2 * (-1.0 / 11 + u2 * (1.0 / 13)))))));
        if (swap) a = Math.PI / 2 - a;
        if (x < 0 || (x == 0 && 1 / x < 0)) a = Math.PI - a;
        return Math.copySign(a, y);
    }

    /** acos of x in [-1, 1] (callers clamp). */
    static double acos(double x) { return atan2(Math.sqrt((1 - x) * (1 + x)), x); }

    /** asin of x in [-1, 1] (callers clamp). */
    static double asin(double x) { return atan2(x, Math.sqrt((1 - x) * (1 + x))); }
}
