package org.robopro.calibration.diagnosis;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.robopro.calibration.measurement.Measurement;

/**
 * The temperature a body of the arm has when it follows the measured air temperature with a
 * first-order lag. A link exchanges heat with the air through its surface: m c dT_b/dt =
 * h A (T_air − T_b), so T_b follows T_air with the time constant τ = m c / (h A) (Newton's law of
 * cooling for a body of uniform temperature, the lumped-capacitance model: F. P. Incropera,
 * D. P. DeWitt, "Fundamentals of Heat and Mass Transfer", §5.1–5.2). A heavy casting (a base, a
 * column) has a long τ; a thin arm tube a short one. The sensor in the file (temp_c) is one point
 * in the air, so the links' growth follows the lagged temperature, not the reading.
 * <p>
 * The history is the whole campaign's (time_s, temp_c) in time order, every row of the file
 * (training and validation: the air's temperature is a condition, not a measured position). The
 * arm is taken in equilibrium with the air at the first reading. Between readings the air's
 * temperature is taken linear in time, for which the lag has the exact solution used here.
 * Outside the campaign (a time not in it, or unknown) the body is taken in equilibrium with the
 * air: the lagged temperature is the reading. Immutable and thread-safe (filtered series are cached).
 */
public final class ThermalLag {
    /** Time constants tried for the lag, s: none, then 150 s to 4800 s in factors of two. */
    static final double[] TAUS = {0, 150, 300, 600, 1200, 2400, 4800};

    private final double[] t, temp;
    /** The filtered series made so far, by time constant: few (one per τ tried), read for every pose of every fit. */
    private volatile Series[] series = new Series[0];

    private record Series(double tauS, double[] temps) { }

    private ThermalLag(double[] t, double[] temp) {
        this.t = t;
        this.temp = temp;
    }

    /**
     * The history of the rows' time and temperature (rows without either are skipped; rows at the
     * same time averaged), or null when fewer than 3 distinct times are known or the temperature
     * does not change.
     */
    public static ThermalLag of(List<Measurement> rows) {
        List<double[]> pts = new ArrayList<>();
        for (Measurement m : rows)
            if (Double.isFinite(m.timeS()) && Double.isFinite(m.tempC())) pts.add(new double[] {m.timeS(), m.tempC()});
        pts.sort((a, b) -> Double.compare(a[0], b[0]));
        List<double[]> merged = new ArrayList<>();
        for (int i = 0; i < pts.size(); ) {
            int j = i;
            double s = 0;
            while (j < pts.size() && pts.get(j)[0] == pts.get(i)[0]) s += pts.get(j++)[1];
            merged.add(new double[] {pts.get(i)[0], s / (j - i)});
            i = j;
        }
        if (merged.size() < 3) return null;
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
        for (double[] p : merged) { lo = Math.min(lo, p[1]); hi = Math.max(hi, p[1]); }
        if (!(hi > lo)) return null;
        return new ThermalLag(merged.stream().mapToDouble(p -> p[0]).toArray(), merged.stream().mapToDouble(p -> p[1]).toArray());
    }

    /** The campaign's duration, s. */
    public double durationS() { return t[t.length - 1] - t[0]; }

    /**
     * The temperature of a body with time constant {@code tauS} at {@code timeS}; {@code tempC} (the
     * reading at that time) when τ is 0, or the time is unknown or outside the campaign.
     */
    public double at(double tauS, double timeS, double tempC) {
        if (!(tauS > 0) || !Double.isFinite(timeS) || timeS < t[0] || timeS > t[t.length - 1]) return tempC;
        double[] b = lagged(tauS);
        int i = Arrays.binarySearch(t, timeS);
        if (i >= 0) return b[i];
        i = -i - 1; // t[i-1] < timeS < t[i]
        double w = (timeS - t[i - 1]) / (t[i] - t[i - 1]);
        return b[i - 1] + w * (b[i] - b[i - 1]);
    }

    /**
     * How far the temperature of a body with time constant {@code tauS} moves over the campaign
     * (its largest less its smallest, K); the air's own with τ = 0.
     */
    public double span(double tauS) {
        double[] b = tauS > 0 ? lagged(tauS) : temp;
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
        for (double x : b) { lo = Math.min(lo, x); hi = Math.max(hi, x); }
        return hi - lo;
    }

    /** The lagged series at {@code tauS}, filtered on first use. */
    private double[] lagged(double tauS) {
        for (Series x : series) if (x.tauS() == tauS) return x.temps();
        synchronized (this) {
            for (Series x : series) if (x.tauS() == tauS) return x.temps();
            Series added = new Series(tauS, filter(tauS));
            Series[] more = Arrays.copyOf(series, series.length + 1);
            more[series.length] = added;
            series = more;
            return added.temps();
        }
    }

    /**
     * The lagged series: with the air linear between readings, T_air = T_{i−1} + s (t − t_{i−1}),
     * the body's excess e = T_b − T_air obeys de/dt = −e/τ − s, so after h = t_i − t_{i−1}
     * e_i = e_{i−1} exp(−h/τ) − s τ (1 − exp(−h/τ)).
     */
    private double[] filter(double tauS) {
        double[] b = new double[t.length];
        b[0] = temp[0];
        double e = 0;
        for (int i = 1; i < t.length; i++) {
            double h = t[i] - t[i - 1], s = (temp[i] - temp[i - 1]) / h, d = Math.exp(-h / tauS);
            e = e * d - s * tauS * (1 - d);
            b[i] = temp[i] + e;
        }
        return b;
    }
}
