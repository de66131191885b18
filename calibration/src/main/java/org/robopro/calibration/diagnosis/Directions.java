package org.robopro.calibration.diagnosis;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.measurement.MeasurementSet;

/**
 * Approach directions of a campaign: the recorded {@code dir1..dirN} columns, or, without them,
 * inferred from the order the poses were measured in. A joint's direction at a pose is the sign
 * of its last motion before that pose was measured: the sign of its move from the previous pose,
 * or, when it did not move, the direction it had there (the gear stays on the same flank). The
 * first pose's direction is unknown (0) until a joint has moved.
 *
 * <p>The order is the whole file's, not the training rows': training and validation rows of one
 * file (same {@link MeasurementSet#source()}, split by the {@code set} column) are merged and
 * sorted by {@code time_s} when every row has it, else by file line when every row has one,
 * else kept in the order given. A validation set from another file is ordered on its own.
 */
public final class Directions {
    /** Where a diagnosis' directions came from. */
    public enum Source {
        RECORDED("recorded"), TIME_ORDER("inferred from the measuring order (time_s)"),
        FILE_ORDER("inferred from the measuring order (file order)"), NONE("none");

        /** In words, for reports and JSON. */
        public final String words;

        Source(String words) { this.words = words; }

        public boolean inferred() { return this == TIME_ORDER || this == FILE_ORDER; }
    }

    /** Training and validation sets with directions on every row, and where they came from. */
    public record Prepared(MeasurementSet train, MeasurementSet validate, Source source) { }

    /** A joint that moved less than this (rad or m) between two poses counts as not moved. */
    static final double STILL = 1e-9;

    private Directions() { }

    /**
     * The sets with directions: as recorded when the training rows all have them, else inferred
     * from the measuring order (see the class comment). Rows that already have directions keep them.
     */
    public static Prepared prepare(MeasurementSet train, MeasurementSet validate) {
        if (train.size() == 0 || train.hasDirections())
            return new Prepared(train, validate, train.size() > 0 ? Source.RECORDED : Source.NONE);
        boolean sameFile = validate != null && validate.size() > 0 && Objects.equals(train.source(), validate.source());
        List<Measurement> file = new ArrayList<>(train.rows());
        if (sameFile) file.addAll(validate.rows());
        Source src = orderSource(file);
        Map<String, int[]> dirs = infer(ordered(file));
        MeasurementSet t = apply(train, dirs);
        MeasurementSet v = validate;
        if (validate != null && validate.size() > 0 && !validate.hasDirections())
            v = apply(validate, sameFile ? dirs : infer(ordered(validate.rows())));
        return new Prepared(t, v, src);
    }

    private static Source orderSource(List<Measurement> rows) {
        return rows.stream().allMatch(m -> Double.isFinite(m.timeS())) ? Source.TIME_ORDER : Source.FILE_ORDER;
    }

    /** The rows in measuring order: by time_s if every row has it, else by file line if every row has one, else as given. */
    static List<Measurement> ordered(List<Measurement> rows) {
        List<Measurement> out = new ArrayList<>(rows);
        if (out.stream().allMatch(m -> Double.isFinite(m.timeS()))) out.sort(Comparator.comparingDouble(Measurement::timeS));
        else if (out.stream().allMatch(m -> m.line() > 0)) out.sort(Comparator.comparingInt(Measurement::line));
        return out;
    }

    /** Directions per pose id for rows already in measuring order. */
    static Map<String, int[]> infer(List<Measurement> inOrder) {
        Map<String, int[]> out = new HashMap<>();
        double[] prev = null;
        int[] last = null;
        for (Measurement m : inOrder) {
            int n = m.dof();
            int[] d = new int[n];
            for (int j = 0; j < n; j++) {
                double dq = prev == null ? 0 : m.q(j) - prev[j];
                d[j] = Math.abs(dq) > STILL ? (int) Math.signum(dq) : last == null ? 0 : last[j];
            }
            out.put(m.poseId(), d);
            prev = m.q();
            last = d;
        }
        return out;
    }

    private static MeasurementSet apply(MeasurementSet s, Map<String, int[]> dirs) {
        List<Measurement> rows = new ArrayList<>();
        for (Measurement m : s.rows()) {
            int[] d = m.directions() != null ? m.directions() : dirs.get(m.poseId());
            rows.add(m.withConditions(d, m.timeS(), m.tempC(), m.payloadKg()));
        }
        return s.withRows(rows);
    }
}
