package org.robopro.calibration.workflow;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.Set;
import org.robopro.calibration.measurement.Measurement;

/**
 * Says what the outliers a calibration dropped suggest. Gross measurement errors (a bumped
 * target, a lost laser beam) are rare and strike poses at random; when many poses are dropped,
 * or the dropped poses share one joint region, the likelier cause is a systematic effect the
 * geometric model lacks (backlash, compliance, a gear error), which the diagnosis tests for —
 * and dropping those poses hides the evidence.
 */
public final class OutlierHint {
    /** More outliers than this share of the poses is not random gross error. */
    public static final double MANY = 0.05;
    /** Outliers within this share of a joint's range over all poses cluster on that joint. */
    public static final double BAND = 0.25;
    /** Fewer outliers than this never count as a pattern. */
    public static final int MIN = 3;

    private OutlierHint() { }

    /**
     * The sentence for the warnings: how many poses were dropped, and when they cluster (many of
     * them, or in one joint band) the advice to run the diagnosis; empty when none were dropped.
     */
    public static Optional<String> sentence(List<String> outlierIds, List<Measurement> poses) {
        if (outlierIds.isEmpty()) return Optional.empty();
        Set<String> ids = Set.copyOf(outlierIds);
        List<double[]> out = new ArrayList<>(), all = new ArrayList<>();
        for (Measurement m : poses) {
            all.add(m.q());
            if (ids.contains(m.poseId())) out.add(m.q());
        }
        int n = outlierIds.size(), total = Math.max(poses.size(), n);
        String list = outlierIds.size() <= 12 ? String.join(", ", outlierIds)
                : String.join(", ", outlierIds.subList(0, 12)) + ", …";
        String head = String.format(Locale.ROOT, "%d of %d training poses were left out of the fit as outliers (%s)", n, total, list);
        String why = null;
        if (n >= MIN) {
            String band = band(out, all);
            if (band != null) why = "they lie together (" + band + ")";
            else if (n > MANY * total) why = String.format(Locale.ROOT, "that is %.0f %% of the poses, more than random measurement slips",
                    100.0 * n / total);
        }
        if (why == null) return Optional.of(head + "; re-measure them if they matter");
        return Optional.of(head + "; " + why + ": a systematic effect the geometric model lacks (backlash, compliance, a gear error) is "
                + "likelier than bad measurements — run the diagnosis (robopro diagnose, or Diagnose in the workbench) before trusting "
                + "these figures");
    }

    /** "joint 2 between 10.0 and 25.0 deg" when the outliers occupy a narrow band of one joint's range, else null. */
    static String band(List<double[]> out, List<double[]> all) {
        if (out.size() < MIN || all.isEmpty()) return null;
        int joints = all.get(0).length;
        String best = null;
        double bestShare = BAND;
        for (int j = 0; j < joints; j++) {
            final int jj = j;
            double[] a = all.stream().mapToDouble(q -> q[jj]).toArray(), o = out.stream().mapToDouble(q -> q[jj]).toArray();
            double lo = Arrays.stream(a).min().orElse(0), hi = Arrays.stream(a).max().orElse(0);
            if (!(hi - lo > 1e-9)) continue;
            double olo = Arrays.stream(o).min().orElse(0), ohi = Arrays.stream(o).max().orElse(0);
            double share = (ohi - olo) / (hi - lo);
            if (share <= bestShare) {
                bestShare = share;
                best = String.format(Locale.ROOT, "joint %d between %.1f and %.1f deg, %.0f %% of its range", j + 1, Math.toDegrees(olo),
                        Math.toDegrees(ohi), 100 * share);
            }
        }
        return best;
    }
}
