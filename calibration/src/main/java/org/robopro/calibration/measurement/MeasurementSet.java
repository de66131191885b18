package org.robopro.calibration.measurement;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.function.Predicate;
import org.robopro.models.Vec3;

/**
 * The contents of a measurement file (docs/measurement-file.md), SI units inside. Immutable.
 *
 * @param source     where the data came from (file name), for messages
 * @param metadata   every {@code # key: value} line in order (keys lower-case), unknown keys included
 * @param frame      the frame the positions are expressed in; "base" means the robot base frame
 * @param rows       the measured poses, in file order
 * @param pointNames names of the measured points of every pose, in order, when there are several
 *                   (tool points 1..P); empty for one point per pose and for distance rows
 * @param anchor     distance rows: the fixed anchor's position in the robot base frame when the
 *                   file gives it ({@code # anchor:}), m; null when unknown (identified) and for
 *                   distances between pairs of poses
 */
public record MeasurementSet(String source, Map<String, String> metadata, String frame, List<Measurement> rows,
                             List<String> pointNames, Vec3 anchor) {
    public static final String BASE_FRAME = "base";

    public MeasurementSet {
        metadata = Collections.unmodifiableMap(new LinkedHashMap<>(metadata));
        rows = List.copyOf(rows);
        pointNames = pointNames == null ? List.of() : List.copyOf(pointNames);
        if (frame == null || frame.isBlank()) frame = "instrument";
        if (pointNames.size() == 1) throw new IllegalArgumentException("one measured point per pose needs no point names");
        for (Measurement m : rows) {
            int want = pointNames.isEmpty() ? 1 : pointNames.size();
            if (m.isDistance() ? !pointNames.isEmpty() : m.points().size() != want)
                throw new IllegalArgumentException("pose " + m.poseId() + " has " + m.points().size() + " points, the set " + want);
        }
        if (rows.stream().map(Measurement::isDistance).distinct().count() > 1)
            throw new IllegalArgumentException("positions and distances in one set");
        if (anchor != null && rows.stream().anyMatch(m -> !m.isDistance()))
            throw new IllegalArgumentException("an anchor belongs to distance rows only");
        if (rows.stream().map(Measurement::isPair).distinct().count() > 1)
            throw new IllegalArgumentException("lengths to an anchor and lengths between two poses in one set");
        if (anchor != null && rows.stream().anyMatch(Measurement::isPair))
            throw new IllegalArgumentException("a length between two poses has no anchor");
    }

    /** One measured point per pose (or distance rows), no anchor. */
    public MeasurementSet(String source, Map<String, String> metadata, String frame, List<Measurement> rows) {
        this(source, metadata, frame, rows, multi(rows), null);
    }

    private static List<String> multi(List<Measurement> rows) {
        int p = rows.isEmpty() || rows.get(0).isDistance() ? 1 : rows.get(0).points().size();
        if (p == 1) return List.of();
        List<String> names = new ArrayList<>();
        for (int k = 1; k <= p; k++) names.add(Integer.toString(k));
        return names;
    }

    /** Measured points per pose (1 for single-point and distance data). */
    public int pointCount() { return pointNames.isEmpty() ? 1 : pointNames.size(); }

    /** Distance-only data: every row a length to the anchor, or between two poses. */
    public boolean isDistance() { return !rows.isEmpty() && rows.get(0).isDistance(); }

    /** Distances between pairs of poses (a length artefact or ballbar probed by the robot): no anchor. */
    public boolean isPairs() { return !rows.isEmpty() && rows.get(0).isPair(); }

    /** Positions are in the robot base frame: no instrument frame to identify. */
    public boolean inBaseFrame() { return BASE_FRAME.equalsIgnoreCase(frame.trim()); }

    /** The robot named in the file's metadata, or null. */
    public String robot() { return metadata.get("robot"); }

    public int size() { return rows.size(); }

    public int dof() { return rows.isEmpty() ? 0 : rows.get(0).dof(); }

    /** True when every row carries an orientation (6-D data). */
    public boolean hasOrientation() { return !rows.isEmpty() && rows.stream().allMatch(Measurement::hasOrientation); }

    public boolean hasDirections() { return !rows.isEmpty() && rows.stream().allMatch(m -> m.directions() != null); }
    public boolean hasTime() { return !rows.isEmpty() && rows.stream().allMatch(m -> !Double.isNaN(m.timeS())); }
    public boolean hasTemperature() { return !rows.isEmpty() && rows.stream().allMatch(m -> !Double.isNaN(m.tempC())); }
    public boolean hasPayload() { return !rows.isEmpty() && rows.stream().allMatch(m -> !Double.isNaN(m.payloadKg())); }
    public boolean hasSplit() { return !rows.isEmpty() && rows.stream().allMatch(m -> m.set() != null); }

    /** The rows that satisfy {@code keep}, same metadata. */
    public MeasurementSet filter(Predicate<Measurement> keep) {
        List<Measurement> out = new ArrayList<>();
        for (Measurement m : rows) if (keep.test(m)) out.add(m);
        return new MeasurementSet(source, metadata, frame, out, pointNames, anchor);
    }

    /** Rows of the given split (rows without a {@code set} value count as training data). */
    public MeasurementSet split(Measurement.Split s) {
        return filter(m -> (m.set() == null ? Measurement.Split.TRAIN : m.set()) == s);
    }

    /** Each row replaced by {@code f}'s row for it, in the same order, same metadata. */
    public MeasurementSet map(java.util.function.UnaryOperator<Measurement> f) {
        List<Measurement> out = new ArrayList<>(rows.size());
        for (Measurement m : rows) out.add(f.apply(m));
        return withRows(out);
    }

    public MeasurementSet withRows(List<Measurement> newRows) {
        return new MeasurementSet(source, metadata, frame, newRows, pointNames, anchor);
    }

    /** One fold of a K-fold split: the rows of the other folds (training) and the fold's own rows (held out). */
    public record FoldSplit(MeasurementSet train, MeasurementSet heldOut) { }

    /** The rows in fold {@code f} of {@code fold} (one entry a row, as {@link #folds} deals them) held out, the others for training; each in file order. */
    public FoldSplit foldSplit(int[] fold, int f) {
        List<Measurement> tr = new ArrayList<>(), va = new ArrayList<>();
        for (int i = 0; i < rows.size(); i++) (fold[i] == f ? va : tr).add(rows.get(i));
        return new FoldSplit(withRows(tr), withRows(va));
    }

    /**
     * Fold of each of {@code poses} poses (0..K-1) for K-fold cross-validation: the poses shuffled with
     * {@code new Random(seed)} (specified by the JDK, so the same on every machine), then dealt
     * round-robin, so fold sizes differ by at most one.
     */
    public static int[] folds(int poses, int k, long seed) {
        if (k < 2) throw new IllegalArgumentException("--folds must be at least 2, got " + k);
        if (k > poses) throw new IllegalArgumentException("--folds " + k + " is more than the " + poses + " training poses");
        List<Integer> order = new ArrayList<>();
        for (int i = 0; i < poses; i++) order.add(i);
        Collections.shuffle(order, new Random(seed));
        int[] fold = new int[poses];
        for (int i = 0; i < poses; i++) fold[order.get(i)] = i % k;
        return fold;
    }
}
