package org.robopro.programs.rapid;

import java.math.BigDecimal;
import java.math.RoundingMode;

/**
 * How robopro writes RAPID numbers. A value is first rounded to the file's precision (a fixed
 * number of decimals per quantity: e.g. 6 decimals of a millimetre) and then written in the
 * shortest plain decimal form of that rounded value. Parsing the text gives the double nearest
 * to that decimal, and writing it again gives the same text, so export(parse(export(p))) is
 * byte-identical to export(p). The controller's {@code num} is single precision (about 7
 * significant digits), so the file precision is far finer than what the controller keeps.
 */
public final class RapidNumbers {
    private RapidNumbers() { }

    /** RAPID's value of an unused external axis (9E9), written "9E+09" as RobotStudio does. */
    public static final double UNUSED_AXIS = 9E9;

    /** The text of {@code value} rounded to {@code decimals} decimals; 9E9 (unused external axis) as 9E+09. */
    public static String format(double value, int decimals) {
        if (!Double.isFinite(value)) throw new IllegalArgumentException("RAPID has no " + value);
        if (value == UNUSED_AXIS) return "9E+09";
        // Reading converts units (mm -> m) and writing back (m -> mm) moves a value by a few ulps;
        // the rounding step must stay far above that, or a huge value (1e10 mm) would not write
        // back to the same text. So at most 14 significant digits (a no-op below 1e8).
        double a = Math.abs(value);
        if (a >= 1) decimals = Math.min(decimals, 14 - ((int) Math.floor(Math.log10(a)) + 1));
        BigDecimal bd = new BigDecimal(value).setScale(decimals, RoundingMode.HALF_EVEN).stripTrailingZeros();
        if (bd.signum() == 0) return "0";
        // stripTrailingZeros makes 110 "1.1E+2": plain digits below 1e15, the exponent form only for huge values.
        return bd.scale() < 0 && a >= 1e15 ? bd.toString() : bd.toPlainString();
    }

    /** A plain RAPID num (no unit conversion): the shortest text that parses back to the same double. */
    public static String formatExact(double value) {
        if (!Double.isFinite(value)) throw new IllegalArgumentException("RAPID has no " + value);
        if (value == 0) return "0";
        if (value == UNUSED_AXIS) return "9E+09";
        BigDecimal shortest = shortest(value);
        double a = Math.abs(value);
        if (a >= 1e-6 && a < 1e15) return shortest.toPlainString();
        // RAPID accepts 1.5E-07; BigDecimal writes 1.5E-7, which is the same number.
        return shortest.toString();
    }

    /** The decimal with the fewest significant digits that parses back to exactly {@code value}. */
    static BigDecimal shortest(double value) {
        BigDecimal exact = new BigDecimal(value);
        for (int p = 1; p <= 17; p++) {
            BigDecimal c = exact.round(new java.math.MathContext(p, RoundingMode.HALF_EVEN));
            if (c.doubleValue() == value) return c.stripTrailingZeros();
        }
        return exact.stripTrailingZeros();
    }
}
