package org.robopro.kinematics;

/**
 * Pure-Java atan2 / acos / asin for the IK hot paths. On OpenJDK 17 {@link Math#atan2},
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
