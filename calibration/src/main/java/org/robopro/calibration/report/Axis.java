package org.robopro.calibration.report;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Axis ranges and tick marks for every plot robopro draws (report SVG and workbench panels):
 * ticks at round values — 1, 2 or 5 times a power of ten on a linear axis, decades (with 2 and
 * 5 when the axis spans less than two decades) on a log axis — the axis widened to the ticks
 * around the data, and labels with just the decimals the step needs ("0.05", not "0.050000";
 * never "0.187" or "3.2" between round ticks).
 */
public final class Axis {
    private Axis() { }

    /**
     * Ticks of an axis: {@code lo}..{@code hi} is the range to draw (it contains the data),
     * {@code values} the tick positions, {@code labels} their text; for a log axis all in data
     * units (not log10).
     */
    public record Ticks(double lo, double hi, double[] values, String[] labels, boolean log) {
        /** Where {@code v} falls on the axis, 0 at lo and 1 at hi (log10 on a log axis). */
        public double fraction(double v) {
            if (log) return (Math.log10(v) - Math.log10(lo)) / (Math.log10(hi) - Math.log10(lo));
            return (v - lo) / (hi - lo);
        }
    }

    /** The round step (1, 2 or 5 x 10^n) that cuts {@code range} into at most {@code maxTicks} intervals. */
    public static double step(double range, int maxTicks) {
        if (!(range > 0) || !Double.isFinite(range)) return 1;
        double raw = range / Math.max(1, maxTicks);
        double p = Math.pow(10, Math.floor(Math.log10(raw)));
        for (double m : new double[] {1, 2, 5, 10}) if (m * p >= raw * (1 - 1e-9)) return m * p;
        return 10 * p;
    }

    /** A linear axis covering {@code min}..{@code max} with at most {@code maxTicks} round intervals. */
    public static Ticks linear(double min, double max, int maxTicks) {
        if (!Double.isFinite(min) || !Double.isFinite(max)) { min = 0; max = 1; }
        if (max < min) { double t = min; min = max; max = t; }
        if (max == min) { double d = min == 0 ? 1 : Math.abs(min) * 0.1; min -= d; max += d; }
        double step = step(max - min, maxTicks);
        double lo = Math.floor(min / step + 1e-9) * step, hi = Math.ceil(max / step - 1e-9) * step;
        int n = (int) Math.round((hi - lo) / step);
        double[] v = new double[n + 1];
        String[] l = new String[n + 1];
        for (int i = 0; i <= n; i++) {
            v[i] = lo + i * step;
            if (Math.abs(v[i]) < step * 1e-9) v[i] = 0;
            l[i] = label(v[i], step);
        }
        return new Ticks(lo, hi, v, l, false);
    }

    /** A log10 axis covering the positive {@code min}..{@code max}: whole decades, with 2 and 5 between when it spans less than two. */
    public static Ticks log(double min, double max) {
        if (!(min > 0) || !Double.isFinite(min)) min = Math.max(1e-12, max > 0 ? max / 10 : 1e-3);
        if (!(max > 0) || !Double.isFinite(max)) max = min * 10;
        if (max < min) { double t = min; min = max; max = t; }
        int d0 = (int) Math.floor(Math.log10(min) + 1e-9), d1 = (int) Math.ceil(Math.log10(max) - 1e-9);
        if (d1 == d0) d1++;
        List<Double> v = new ArrayList<>();
        boolean fine = d1 - d0 < 2;
        for (int d = d0; d <= d1; d++) {
            double p = Math.pow(10, d);
            v.add(p);
            if (fine && d < d1) { v.add(2 * p); v.add(5 * p); }
        }
        double[] vs = v.stream().mapToDouble(Double::doubleValue).toArray();
        String[] ls = new String[vs.length];
        for (int i = 0; i < vs.length; i++) ls[i] = label(vs[i], vs[i]);
        return new Ticks(Math.pow(10, d0), Math.pow(10, d1), vs, ls, true);
    }

    /** {@code v} with the decimals a step of {@code step} needs; powers of ten below 1e-4 or from 1e6 as 1e-5, 1e6. */
    public static String label(double v, double step) {
        double a = Math.abs(v);
        if (a != 0 && (a < 1e-4 || a >= 1e6)) {
            int e = (int) Math.floor(Math.log10(a) + 1e-9);
            double m = v / Math.pow(10, e);
            String ms = Math.abs(Math.abs(m) - 1) < 1e-9 ? (m < 0 ? "-" : "") : label(m, Math.max(step / Math.pow(10, e), 0.1)) + "×";
            return ms + "1e" + e;
        }
        int decimals = Math.max(0, (int) Math.ceil(-Math.log10(step) - 1e-9));
        return String.format(Locale.ROOT, "%." + decimals + "f", v);
    }
}
