package org.robopro.calibration.diagnosis;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.measurement.MeasurementSet;

/**
 * Approach directions of a campaign: the recorded {@code dir1..dirN} columns, or, without them,
 * inferred from the order the poses were measured in. A joint's direction at a pose is the side of
 * the play its gear rests on: the sign of its last motion that took up the play.
 *
 * <p>The physics (lost motion as a dead zone, e.g. Nordin &amp; Gutman, "Controlling mechanical
 * systems with backlash: a survey", Automatica 38 (2002), §2): the output follows its motor only
 * while the motor pushes it on one flank; after a reversal the motor must cross the whole play
 * before the output moves again. So a joint that did not move, or reversed by less than
 * {@link #PLAY_TOLERANCE} (a controller's read-back jitter, far below any lost motion worth
 * modelling), stays on the flank of its last real motion, and small moves in one direction add up
 * from where the joint stood (the mean of its readings since its last real move). The direction
 * is on the drive, so it is inferred from the controller's values q (the file's columns), not from
 * model angles: on a parallel-arm robot (theta3 = q3 - q2) drive 3's direction is that of q3,
 * whatever theta3 does.
 *
 * <p>The first pose: a campaign program starts from the controller's zero position (the
 * synchronisation position every axis reads 0 in, where a robot is parked and a measuring program
 * begins), so a joint's first direction is the sign of its first value; a joint whose first value
 * is within the tolerance of 0 stays unknown (0) until it moves. When the robot really started
 * elsewhere the first pose's directions can be wrong: record the dir columns to be sure.
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
    public record Prepared(MeasurementSet train, MeasurementSet validate, Source source, List<String> notes) {
        public Prepared(MeasurementSet train, MeasurementSet validate, Source source) { this(train, validate, source, List.of()); }
    }

    /**
     * A reversal smaller than this (rad, or m for a prismatic joint) does not change a joint's
     * direction: 1e-5 rad is 0.0006°, above a controller's joint read-back jitter and well below
     * the smallest lost motion worth modelling (about 0.005°); 10 µm on a linear axis.
     */
    static final double PLAY_TOLERANCE = 1e-5;

    private Directions() { }

    /**
     * The sets with directions: as recorded when the training rows all have them, else inferred
     * from the measuring order (see the class comment). Rows that already have directions keep them.
     */
    public static Prepared prepare(MeasurementSet train, MeasurementSet validate) {
        if (train.size() == 0) return new Prepared(train, validate, Source.NONE);
        if (train.hasDirections()) return recorded(train, validate);
        List<List<Measurement>> seqs = sequences(train, validate);
        Source src = orderSource(seqs.get(0));
        Map<String, int[]> dirs = infer(seqs.get(0));
        MeasurementSet t = apply(train, dirs);
        MeasurementSet v = validate;
        if (validate != null && validate.size() > 0 && !validate.hasDirections())
            v = apply(validate, seqs.size() > 1 ? infer(seqs.get(1)) : dirs);
        return new Prepared(t, v, src);
    }

    /**
     * Recorded directions, each kept but where a joint's move onto the pose (in the measuring order)
     * is within {@link #PLAY_TOLERANCE} and its recorded direction is against the joint's last real
     * move: read-back jitter, or a move far shorter than any play, does not take up the play the
     * other way (the deadband of a backlash: the output stays until the input has crossed the play;
     * Nordin &amp; Gutman, "Controlling mechanical systems with backlash — a survey", Automatica 38
     * (2002) 1633, §2), so the joint rests on the flank of its last real move, whatever sign the
     * controller logged for the jitter. The rows so read are said in the notes.
     */
    private static Prepared recorded(MeasurementSet train, MeasurementSet validate) {
        List<List<Measurement>> seqs = sequences(train, validate);
        Map<Measurement, int[]> kept = new HashMap<>();
        List<String> changed = new ArrayList<>();
        for (List<Measurement> seq : seqs) {
            StillPoints at = null;
            int[] last = null;
            for (Measurement m : seq) {
                int n = m.dof();
                // from the zero position a measuring program starts at, as the moves are taken (see moves)
                if (at == null) { at = new StillPoints(n, new double[n]); last = new int[n]; }
                int[] d = m.directions(), e = d == null ? null : d.clone();
                for (int j = 0; j < n; j++) {
                    double moved = at.moved(j, m.q(j));
                    if (moved != 0) last[j] = moved > 0 ? 1 : -1;
                    else if (e != null && last[j] != 0 && d[j] != 0 && d[j] != last[j]) {
                        e[j] = last[j];
                        changed.add(m.poseId() + " j" + (j + 1));
                    }
                }
                if (e != null && !Arrays.equals(e, d)) kept.put(m, e);
            }
        }
        if (kept.isEmpty()) return new Prepared(train, validate, Source.RECORDED);
        String note = String.format(java.util.Locale.ROOT, "recorded directions against the joint's last real move after a move of "
                + "less than %.4f deg (read-back jitter, which takes up no play) were read as that move's: %s", Math.toDegrees(PLAY_TOLERANCE),
                String.join(", ", changed));
        return new Prepared(withDirections(train, kept), validate == null ? null : withDirections(validate, kept), Source.RECORDED,
                List.of(note));
    }

    private static MeasurementSet withDirections(MeasurementSet s, Map<Measurement, int[]> dirs) {
        return s.map(m -> dirs.containsKey(m) ? m.withConditions(dirs.get(m), m.timeS(), m.tempC(), m.payloadKg()) : m);
    }

    /**
     * The campaign's measuring sequences, each in measuring order ({@link #ordered}): the training
     * rows together with the validation rows of the same file (same {@link MeasurementSet#source()}),
     * then a validation set from another file on its own. Pose ids are unique within a sequence only.
     */
    private static List<List<Measurement>> sequences(MeasurementSet train, MeasurementSet validate) {
        boolean otherRows = validate != null && validate.size() > 0;
        boolean sameFile = otherRows && Objects.equals(train.source(), validate.source());
        List<Measurement> file = new ArrayList<>(train.rows());
        if (sameFile) file.addAll(validate.rows());
        return otherRows && !sameFile ? List.of(ordered(file), ordered(validate.rows())) : List.of(ordered(file));
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

    /** Directions per pose id for rows already in measuring order, the robot starting from its zero position. */
    static Map<String, int[]> infer(List<Measurement> inOrder) {
        return inOrder.isEmpty() ? new HashMap<>() : infer(inOrder, new double[inOrder.get(0).dof()]);
    }

    /**
     * Directions per pose id for rows already in measuring order, the robot starting at
     * {@code start} (null: where it started is unknown, so the first pose's directions are 0).
     * Per joint, the flank it rests on and the motor position where it last took that flank
     * (or moved further along it).
     */
    static Map<String, int[]> infer(List<Measurement> inOrder, double[] start) {
        Map<String, int[]> out = new HashMap<>();
        StillPoints at = null;
        int[] d = null;
        for (Measurement m : inOrder) {
            int n = m.dof();
            if (at == null) at = new StillPoints(n, start);
            if (d == null) d = new int[n];
            for (int j = 0; j < n; j++) {
                double moved = at.moved(j, m.q(j));
                if (moved != 0) d[j] = moved > 0 ? 1 : -1;                      // further along its flank, or took up the play the other way
            }
            out.put(m.poseId(), d.clone());
        }
        return out;
    }

    /**
     * A pose at which joint {@code joint}'s output rests at {@code side} within its play (+1 on the
     * flank a rising move leaves it on, −1 on the other, between them inside the play), not on the
     * flank its direction gives.
     */
    record InPlay(Measurement row, int joint, double side) { }

    /**
     * The poses at which joint {@code j}'s output, moved through a play of {@code play} (rad, at the
     * joint's value q) by the joint values of the measuring order (training and validation rows of
     * one file merged, as {@link #prepare}), does not rest on the flank its direction gives: a
     * reversal shorter than the play leaves the output where it stood, and only a move beyond it
     * puts the output on the far flank. The play operator of a backlash (Nordin &amp; Gutman,
     * "Controlling mechanical systems with backlash — a survey", Automatica 38 (2002) 1633, §2): the
     * output's lag o = −(b/2)·s moved to clamp(o − move, −b'/2, b'/2), b' the play where the move
     * ends, s the place in the play in flank units, starting on the first pose's direction; listed
     * where s differs from the direction by more than 5 % of the play. Moves the file does not hold
     * (an approach pose between two rows) are not seen here, so the caller must check the list
     * against the measurements.
     */
    static List<InPlay> inPlay(MeasurementSet train, MeasurementSet validate, int j, java.util.function.DoubleUnaryOperator play) {
        List<InPlay> out = new ArrayList<>();
        if (train.size() == 0 || train.isPairs()) return out;
        for (List<Measurement> seq : sequences(train, validate)) {
            double side = 0, prev = Double.NaN;
            for (Measurement m : seq) {
                int[] d = m.directions();
                if (d == null) { prev = Double.NaN; side = 0; continue; }
                double q = m.q(j);
                double b0 = Double.isFinite(prev) ? play.applyAsDouble(prev) : 0, b1 = play.applyAsDouble(q);
                if (Double.isFinite(prev) && side != 0 && b0 > 0 && b1 > 0) {
                    double lag = Math.max(-0.5 * b1, Math.min(0.5 * b1, -0.5 * b0 * side - (q - prev)));
                    side = -2 * lag / b1;
                    if (d[j] != 0 && Math.abs(side - d[j]) > 0.1) out.add(new InPlay(m, j, side));
                } else side = d[j];
                prev = q;
            }
        }
        return out;
    }

    /**
     * The rows whose inferred direction on joint {@code j} rests on where the campaign started (the
     * zero position is assumed): in the measuring order of the whole file, those before the joint's
     * first move of more than {@link #PLAY_TOLERANCE}. Their flank is unknown when the robot really
     * started elsewhere. Empty when the directions were recorded.
     */
    public static List<Measurement> fromStart(MeasurementSet train, MeasurementSet validate, int j) {
        List<Measurement> out = new ArrayList<>();
        if (train.size() == 0 || train.isPairs()) return out;
        for (List<Measurement> seq : sequences(train, validate)) startRows(seq, j, out);
        return out;
    }

    private static void startRows(List<Measurement> inOrder, int j, List<Measurement> out) {
        Map<String, int[]> unknownStart = infer(inOrder, null);
        for (Measurement m : inOrder) {
            if (unknownStart.get(m.poseId())[j] != 0) break;
            out.add(m);
        }
    }

    /**
     * Each pose's last move per joint, signed (rad, or m for a prismatic joint), in the measuring
     * order of the whole file (as {@link #prepare}: training and validation rows of one file merged,
     * by {@code time_s}, else by file line): the move from the previous pose, a joint that moved by
     * less than {@link #PLAY_TOLERANCE} keeping its last real move (read-back jitter is no move);
     * the first pose's move is from the zero position a measuring program starts at. Taken from the
     * joint values whether or not the directions were recorded: a lost motion that builds up over
     * the move (friction wind-up) depends on its size.
     */
    public static Moves moves(MeasurementSet train, MeasurementSet validate) {
        if (train.size() == 0 || train.isPairs()) return Moves.NONE;
        Map<Measurement, double[]> out = new HashMap<>();
        for (List<Measurement> seq : sequences(train, validate)) lastMoves(seq, out);
        return new Moves(out);
    }

    private static void lastMoves(List<Measurement> inOrder, Map<Measurement, double[]> out) {
        StillPoints at = null;
        double[] last = null;
        for (Measurement m : inOrder) {
            if (at == null) { at = new StillPoints(m.dof(), new double[m.dof()]); last = new double[m.dof()]; }
            for (int j = 0; j < m.dof(); j++) {
                double moved = at.moved(j, m.q(j));
                if (moved != 0) last[j] = moved;
            }
            out.put(m, last.clone());
        }
    }

    /**
     * Where each joint stands since its last real move: the mean of its readings since then. A
     * reading within {@link #PLAY_TOLERANCE} of that mean is read-back jitter, not a move: it
     * neither turns the joint nor moves its standing point, and joins the mean. Against the mean
     * a jitter of σ differs by about σ, where against one earlier reading it would differ by
     * √2·σ, and against the jitter's running extreme (taking every reading "further along the
     * flank" as a move) by more with every pose, until an ordinary reading crosses the tolerance
     * and turns a joint that never moved.
     */
    private static final class StillPoints {
        /** Per joint: the sum of its readings since its last real move, or the known start position. */
        private final double[] sum;
        /** Per joint: how many readings {@link #sum} holds; -1: it holds the known start; 0: nothing yet. */
        private final int[] count;

        /**
         * {@code n} joints starting at {@code start}, a known position (the zero a program starts at),
         * or, when null, where the first reading finds them.
         */
        StillPoints(int n, double[] start) {
            sum = start == null ? new double[n] : start.clone();
            count = new int[n];
            if (start != null) java.util.Arrays.fill(count, -1);
        }

        /** The real move to reading {@code q} of joint {@code j} (then standing there), or 0 when within the tolerance. */
        double moved(int j, double q) {
            if (count[j] == 0) { sum[j] = q; count[j] = 1; return 0; }
            double here = count[j] < 0 ? sum[j] : sum[j] / count[j];
            double moved = q - here;
            if (Math.abs(moved) <= PLAY_TOLERANCE) {
                if (count[j] > 0) { sum[j] += q; count[j]++; }
                return 0;
            }
            sum[j] = q;
            count[j] = 1;
            return moved;
        }
    }

    /** Each pose's last move per joint ({@link #moves}); looked up by the row (pose id, joint values and conditions). */
    public static final class Moves {
        /** No move known: a lost motion is taken at its full size. */
        public static final Moves NONE = new Moves(Map.of());
        private final Map<Measurement, double[]> byRow;

        Moves(Map<Measurement, double[]> byRow) { this.byRow = byRow; }

        /** The signed last move of joint j before row m was measured, NaN when unknown. */
        public double of(Measurement m, int j) {
            double[] v = byRow.get(m);
            return v == null ? Double.NaN : v[j];
        }

        public boolean isEmpty() { return byRow.isEmpty(); }
    }

    /**
     * Joint {@code j}'s moves in measuring order: the time of each pose (s) and the signed move of the
     * joint from the pose before (rad; the first from where the first pose stands, none), over the
     * {@code rows} given (training and validation of one campaign), by time. Null unless every row
     * has a time and there are at least two.
     */
    public static double[][] movesInTime(List<Measurement> rows, int j) {
        if (rows.size() < 2 || !rows.stream().allMatch(m -> Double.isFinite(m.timeS()))) return null;
        List<Measurement> inOrder = ordered(rows);
        double[] t = new double[inOrder.size()], d = new double[inOrder.size()];
        for (int i = 0; i < t.length; i++) {
            t[i] = inOrder.get(i).timeS();
            d[i] = i == 0 ? 0 : inOrder.get(i).q(j) - inOrder.get(i - 1).q(j);
        }
        return new double[][] {t, d};
    }

    private static MeasurementSet apply(MeasurementSet s, Map<String, int[]> dirs) {
        return s.map(m -> m.withConditions(m.directions() != null ? m.directions() : dirs.get(m.poseId()), m.timeS(), m.tempC(),
                m.payloadKg()));
    }
}
