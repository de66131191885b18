package org.robopro.calibration.diagnosis;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.robopro.calibration.measurement.Measurement;

/**
 * When the robot worked and when it rested during a campaign, from its reading times: the drives
 * heat the arm while it moves from pose to pose, and stop heating it while it stands in a pause.
 * <p>
 * The history is the whole file's reading times in time order (training and validation rows: when
 * the robot moved is a condition, not a measured position). The robot is taken to work from time
 * 0 of the file's clock on. A gap between two readings longer than {@link #PAUSE_GAPS} times the
 * file's typical gap (the median) is a pause: the robot rests for the gap less one typical gap, then
 * moves to the next pose. A link heated at a constant rate while the robot works and cooling to the
 * air always is a first-order body: its rise above the air, as a share s of its warmed-through
 * rise, follows ds/dt = (u − s)/τ with u = 1 working and 0 resting, so s → s e^(−h/τ) + u (1 −
 * e^(−h/τ)) over a stretch h (the lumped-capacitance model: F. P. Incropera, D. P. DeWitt,
 * "Fundamentals of Heat and Mass Transfer", §5.2; a robot warms up while running and cools while
 * stopped, which is why ISO 9283 §6.2 asks for a warm-up run before measuring). Without pauses
 * the share is 1 − e^(−t/τ). Immutable and thread-safe (shares are cached per time constant).
 */
public final class Pauses {
    /** A gap between readings this many times the typical one is a pause. */
    static final double PAUSE_GAPS = 10;

    private final double[] t;           // distinct reading times, ascending
    private final boolean[] pauseAfter; // whether the gap after reading i is a pause
    private final double typicalGap;
    private final int firstPause;       // index of the reading a pause follows first (t.length when none)
    private final Map<Double, double[]> shares = new ConcurrentHashMap<>();

    private Pauses(double[] t, boolean[] pauseAfter, double typicalGap) {
        this.t = t;
        this.pauseAfter = pauseAfter;
        this.typicalGap = typicalGap;
        int first = t.length;
        for (int i = 0; i < pauseAfter.length; i++) if (pauseAfter[i]) { first = i; break; }
        this.firstPause = first;
    }

    /** The pauses among the rows' times (rows without a time skipped), or null when fewer than 3 distinct times are known. */
    public static Pauses of(List<Measurement> rows) {
        double[] ts = rows.stream().mapToDouble(Measurement::timeS).filter(Double::isFinite).sorted().distinct().toArray();
        if (ts.length < 3) return null;
        double[] gaps = new double[ts.length - 1];
        for (int i = 0; i < gaps.length; i++) gaps[i] = ts[i + 1] - ts[i];
        double[] sorted = gaps.clone();
        Arrays.sort(sorted);
        double typical = Stats.median(sorted);
        boolean[] pause = new boolean[ts.length];
        for (int i = 0; i < gaps.length; i++) pause[i] = typical > 0 && gaps[i] > PAUSE_GAPS * typical;
        return new Pauses(ts, pause, typical);
    }

    /** The pauses, each as {start, end} of the gap between its two readings, s. */
    public List<double[]> pauses() {
        List<double[]> out = new ArrayList<>();
        for (int i = 0; i + 1 < t.length; i++) if (pauseAfter[i]) out.add(new double[] {t[i], t[i + 1]});
        return out;
    }

    /** Whether the robot rested somewhere in the campaign. */
    public boolean any() { return firstPause < t.length; }

    /**
     * The share of its warmed-through rise a body heated by the drives with time constant
     * {@code tauS} has at {@code timeS}: 1 − e^(−t/τ) up to the first pause, then cooling through
     * each pause; 1 (warmed through) at an unknown time.
     */
    public double share(double tauS, double timeS) {
        if (!Double.isFinite(timeS)) return 1;
        if (firstPause == t.length || timeS <= t[firstPause]) return 1 - Math.exp(-Math.max(0, timeS) / tauS);
        double[] s = shares.computeIfAbsent(tauS, this::filter);
        int i = Arrays.binarySearch(t, timeS);
        if (i >= 0) return s[i];
        i = -i - 2; // t[i] < timeS (< t[i + 1] when inside the campaign)
        return step(s[i], timeS - t[i], i + 1 < t.length && pauseAfter[i] ? t[i + 1] - t[i] : Double.NaN, tauS);
    }

    /** The share at every reading time. */
    private double[] filter(double tauS) {
        double[] s = new double[t.length];
        for (int i = 0; i <= firstPause; i++) s[i] = 1 - Math.exp(-Math.max(0, t[i]) / tauS);
        for (int i = firstPause + 1; i < t.length; i++)
            s[i] = step(s[i - 1], t[i] - t[i - 1], pauseAfter[i - 1] ? t[i] - t[i - 1] : Double.NaN, tauS);
        return s;
    }

    /**
     * The share {@code h} after a reading where it was {@code s}, in a gap of {@code pauseGap} that
     * is a pause (NaN: the robot works through the gap): resting for the gap less one typical gap,
     * then working.
     */
    private double step(double s, double h, double pauseGap, double tauS) {
        double work = h;
        if (!Double.isNaN(pauseGap)) {
            double rest = Math.min(h, pauseGap - typicalGap);
            s *= Math.exp(-rest / tauS);
            work = h - rest;
        }
        double d = Math.exp(-work / tauS);
        return s * d + (1 - d);
    }
}
