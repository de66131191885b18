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
     * sin x for joint angles: x = k pi/2 + r, |r| <= pi/4, then the Taylor series of sin and cos
     * of r to degree 17/16 (truncation below 1e-19); |x| >= 1e5 goes to {@link Math#sin}. Used in
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

    private static double sinPoly(double r) {
        double r2 = r * r;
        return r + r * r2 * (-1.0 / 6 + r2 * (1.0 / 120 + r2 * (-1.0 / 5040 + r2 * (1.0 / 362880 + r2 * (-1.0 / 39916800
                + r2 * (1.0 / 6227020800.0 + r2 * (-1.0 / 1307674368000.0 + r2 * (1.0 / 355687428096000.0))))))));
    }

    private static double cosPoly(double r) {
        double r2 = r * r;
        return 1 + r2 * (-0.5 + r2 * (1.0 / 24 + r2 * (-1.0 / 720 + r2 * (1.0 / 40320 + r2 * (-1.0 / 3628800
                + r2 * (1.0 / 479001600 + r2 * (-1.0 / 87178291200.0 + r2 * (1.0 / 20922789888000.0))))))));
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
