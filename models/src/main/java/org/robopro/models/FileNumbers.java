package org.robopro.models;

import java.math.BigDecimal;
import java.math.MathContext;
import java.math.RoundingMode;

/**
 * Numbers at the file edge: robopro files hold millimetres and degrees, the records SI. The
 * conversions here are correctly rounded functions of the decimal text in the file, and the
 * writer picks the shortest decimal that reads back to exactly the same double, so that
 * write-then-read returns equal records (calibrated models change parameters by nanometres and
 * must survive a save).
 *
 * <p>Equivalent to {@code org.robopro.kinematics.Units} for ordinary values (mm * 1e-3,
 * deg * pi/180) but exact in the last bit; {@code Units} lives in a module above this one.
 */
public final class FileNumbers {
    private FileNumbers() { }

    private static final MathContext WIDE = new MathContext(60, RoundingMode.HALF_EVEN);
    /** pi/180 to 60 digits. */
    private static final BigDecimal RAD_PER_DEG = new BigDecimal(
            "3.14159265358979323846264338327950288419716939937510582097494").divide(BigDecimal.valueOf(180), WIDE);
    private static final BigDecimal DEG_PER_RAD = BigDecimal.valueOf(180).divide(new BigDecimal(
            "3.14159265358979323846264338327950288419716939937510582097494"), WIDE);

    /** Millimetres (file text) to metres. */
    public static double mmToM(LocatedJson.Node n) {
        n.asDouble(); // range check first: a huge exponent must not reach BigDecimal arithmetic
        return signed(n, n.asDecimal().movePointLeft(3).doubleValue());
    }

    /** Degrees (file text) to radians. */
    public static double degToRad(LocatedJson.Node n) {
        n.asDouble();
        return signed(n, n.asDecimal().multiply(RAD_PER_DEG, WIDE).doubleValue());
    }

    /** Plain SI number (file text) to double. */
    public static double plain(LocatedJson.Node n) {
        return n.asDouble();
    }

    private static double signed(LocatedJson.Node n, double v) {
        return v == 0 && n.isNegativeText() ? -0.0 : v;
    }

    public static double mmToM(BigDecimal mm) { return mm.movePointLeft(3).doubleValue(); }

    public static double degToRad(BigDecimal deg) { return deg.multiply(RAD_PER_DEG, WIDE).doubleValue(); }

    /** Shortest decimal text of millimetres that reads back as exactly {@code m} metres. */
    public static String formatMm(double m) {
        check(m);
        if (m == 0) return zero(m);
        BigDecimal exact = new BigDecimal(m).movePointRight(3);
        for (int digits = 1; digits <= 25; digits++) {
            BigDecimal d = exact.round(new MathContext(digits, RoundingMode.HALF_EVEN));
            if (mmToM(d) == m) return text(d);
        }
        return text(exact);
    }

    /** Shortest decimal text of degrees that reads back as exactly {@code rad} radians. */
    public static String formatDeg(double rad) {
        check(rad);
        if (rad == 0) return zero(rad);
        BigDecimal exact = new BigDecimal(rad).multiply(DEG_PER_RAD, WIDE);
        for (int digits = 1; digits <= 40; digits++) {
            BigDecimal d = exact.round(new MathContext(digits, RoundingMode.HALF_EVEN));
            if (degToRad(d) == rad) return text(d);
        }
        return text(exact.round(WIDE));
    }

    /** Shortest decimal text of a plain number (Java's shortest round-trip form). */
    public static String formatPlain(double v) {
        check(v);
        if (v == 0) return zero(v);
        return text(new BigDecimal(Double.toString(v)));
    }

    private static String zero(double v) { return 1 / v < 0 ? "-0" : "0"; }

    private static void check(double v) {
        if (!Double.isFinite(v)) throw new IllegalArgumentException("cannot write non-finite number " + v);
    }

    /** Plain notation for ordinary magnitudes, JSON exponent notation otherwise. */
    private static String text(BigDecimal d) {
        d = d.stripTrailingZeros();
        int exp = d.precision() - d.scale() - 1; // decimal exponent of the leading digit
        if (exp >= -6 && exp < 16) return d.toPlainString();
        return d.toString().replace("E+", "e").replace("E", "e");
    }
}
