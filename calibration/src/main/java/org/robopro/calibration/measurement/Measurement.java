package org.robopro.calibration.measurement;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.robopro.models.Vec3;

/**
 * One measured robot pose, SI units: controller joint values {@code q} (rad, or m for prismatic
 * joints), the measured position of the target point in the file's frame (m), and the optional
 * columns of the measurement file (NaN / null when absent).
 *
 * @param poseId      the pose identifier, unique in its file
 * @param q           controller joint values (copied; rad or m)
 * @param position    measured position of the measured point, in the measurement frame, m
 * @param orientation measured tool orientation as a unit quaternion (w, x, y, z), or null
 * @param directions  sign of the last motion of each joint (-1, 0, 1), or null
 * @param timeS       seconds since the start of the campaign, or NaN
 * @param tempC       temperature near the robot, degrees Celsius, or NaN
 * @param payloadKg   mass at the flange, kg, or NaN
 * @param set         the split chosen by whoever took the data, or null
 * @param line        line of the file this pose came from (0 when not read from a file)
 * @param points      every measured point of the pose, in the set's point order (the first is
 *                    {@code position}); a single-point pose has one; empty for a distance row
 * @param distance    distance-only row: the measured length from the fixed anchor to the
 *                    measured point, m ({@code position} null, {@code points} empty); NaN otherwise
 * @param fromQ       a distance between two poses: the controller values of the first pose (the
 *                    row's {@code q} is the second's; the distance is between the measured point's
 *                    places at the two); null for a length to an anchor and for positions
 * @param fromDirections the first pose's approach directions (with {@code fromQ}, when the row has
 *                    directions), else null
 */
public record Measurement(String poseId, double[] q, Vec3 position, double[] orientation, int[] directions,
                         double timeS, double tempC, double payloadKg, Split set, int line, List<Vec3> points,
                         double distance, double[] fromQ, int[] fromDirections) {

    /** The {@code set} column's values. */
    public enum Split {
        TRAIN, VALIDATE;

        public String fileName() { return this == TRAIN ? "train" : "validate"; }
    }

    public Measurement {
        if (poseId == null || poseId.isEmpty()) throw new IllegalArgumentException("pose id must not be empty");
        if (q == null) throw new IllegalArgumentException("q is required");
        if (Double.isNaN(distance)) {
            if (position == null && (points == null || points.isEmpty()))
                throw new IllegalArgumentException("a measured position (or a distance) is required");
            if (points == null || points.isEmpty()) points = List.of(position);
            else points = List.copyOf(points);
            if (position == null) position = points.get(0);
            if (!points.get(0).equals(position)) throw new IllegalArgumentException("the first point must be the position");
        } else {
            if (position != null || points != null && !points.isEmpty() || orientation != null)
                throw new IllegalArgumentException("a distance row has no position or orientation");
            points = List.of();
        }
        q = q.clone();
        if (orientation != null) {
            if (orientation.length != 4) throw new IllegalArgumentException("orientation needs 4 entries (w, x, y, z)");
            orientation = orientation.clone();
        }
        if (directions != null) {
            if (directions.length != q.length)
                throw new IllegalArgumentException("directions " + Arrays.toString(directions) + " do not match " + q.length + " joints");
            directions = directions.clone();
        }
        if (fromQ != null) {
            if (Double.isNaN(distance)) throw new IllegalArgumentException("a first pose goes with a distance between two poses");
            if (fromQ.length != q.length) throw new IllegalArgumentException("the first pose has " + fromQ.length + " joints, the second " + q.length);
            fromQ = fromQ.clone();
            if ((fromDirections == null) != (directions == null))
                throw new IllegalArgumentException("approach directions at both poses of a distance, or at neither");
            if (fromDirections != null) {
                if (fromDirections.length != q.length) throw new IllegalArgumentException("first pose's directions do not match " + q.length + " joints");
                fromDirections = fromDirections.clone();
            }
        } else if (fromDirections != null) throw new IllegalArgumentException("directions of a first pose without one");
    }

    /** A measurement as the formats without pairs of poses have it. */
    public Measurement(String poseId, double[] q, Vec3 position, double[] orientation, int[] directions,
                       double timeS, double tempC, double payloadKg, Split set, int line, List<Vec3> points, double distance) {
        this(poseId, q, position, orientation, directions, timeS, tempC, payloadKg, set, line, points, distance, null, null);
    }

    /** A measurement of one point (or with an orientation) as the single-point format has it. */
    public Measurement(String poseId, double[] q, Vec3 position, double[] orientation, int[] directions,
                       double timeS, double tempC, double payloadKg, Split set, int line) {
        this(poseId, q, position, orientation, directions, timeS, tempC, payloadKg, set, line, null, Double.NaN);
    }

    /** A measurement of several points on the tool at one pose (the first is {@link #position()}). */
    public static Measurement ofPoints(String poseId, double[] q, List<Vec3> points) {
        return new Measurement(poseId, q, null, null, null, Double.NaN, Double.NaN, Double.NaN, null, 0, points, Double.NaN);
    }

    /** A distance between two poses: the length between the measured point's places at {@code fromQ} and at {@code q}, m. */
    public static Measurement ofPair(String poseId, double[] fromQ, double[] q, double distanceM) {
        return new Measurement(poseId, q, null, null, null, Double.NaN, Double.NaN, Double.NaN, null, 0, null, distanceM, fromQ, null);
    }

    /** A distance-only measurement: the length from the fixed anchor to the measured point, m. */
    public static Measurement ofDistance(String poseId, double[] q, double distanceM) {
        return new Measurement(poseId, q, null, null, null, Double.NaN, Double.NaN, Double.NaN, null, 0, null, distanceM);
    }

    /** A position-only measurement with no optional columns. */
    public static Measurement of(String poseId, double[] q, Vec3 position) {
        return new Measurement(poseId, q, position, null, null, Double.NaN, Double.NaN, Double.NaN, null, 0);
    }

    @Override public double[] q() { return q.clone(); }
    @Override public double[] orientation() { return orientation == null ? null : orientation.clone(); }
    @Override public int[] directions() { return directions == null ? null : directions.clone(); }
    @Override public double[] fromQ() { return fromQ == null ? null : fromQ.clone(); }
    @Override public int[] fromDirections() { return fromDirections == null ? null : fromDirections.clone(); }

    /** A distance between two poses (the first's joints in {@link #fromQ()}). */
    public boolean isPair() { return fromQ != null; }

    /**
     * The first pose of a pair as a pose of its own: its joints and directions, the row's time,
     * temperature, payload and set; the measured point at the origin (a placeholder: what is
     * measured is the distance).
     */
    public Measurement firstPose() {
        if (fromQ == null) throw new IllegalStateException("not a distance between two poses");
        return new Measurement(poseId, fromQ, Vec3.ZERO, null, fromDirections, timeS, tempC, payloadKg, set, line);
    }

    /** The row's own (second) pose as a position row: the measured point at the origin (a placeholder). */
    public Measurement secondPose() {
        return new Measurement(poseId, q, Vec3.ZERO, null, directions, timeS, tempC, payloadKg, set, line);
    }

    /** Joint value i (0-based) without copying the array. */
    public double q(int i) { return q[i]; }

    public int dof() { return q.length; }

    public boolean hasOrientation() { return orientation != null; }

    /** A distance-only row (no position). */
    public boolean isDistance() { return !Double.isNaN(distance); }

    /** Measured point k (0-based). */
    public Vec3 point(int k) { return points.get(k); }

    /**
     * Largest believable coordinate of a measured point, m: beyond any industrial robot's reach
     * seen from any instrument's range (laser trackers measure to about 80 m, Leica AT960
     * datasheet). A value beyond it is a misread number, not a measurement.
     */
    public static final double GROSS_POSITION_M = 100;
    /** Largest believable joint value, rad or m (100 m, or about 16 turns of a revolute joint). */
    public static final double GROSS_JOINT = 100;

    /** The first field (q1.., x, y, z) that is non-finite or beyond the gross limits, or null. */
    public String grossField() {
        for (int k = 0; k < q.length; k++) if (!(Math.abs(q[k]) <= GROSS_JOINT)) return "q" + (k + 1);
        if (fromQ != null) for (int k = 0; k < fromQ.length; k++) if (!(Math.abs(fromQ[k]) <= GROSS_JOINT)) return "from_q" + (k + 1);
        if (isDistance()) return distance >= 0 && distance <= GROSS_POSITION_M ? null : "distance";
        for (int k = 0; k < points.size(); k++) {
            Vec3 p = points.get(k);
            String n = points.size() == 1 ? "" : Integer.toString(k + 1);
            if (!(Math.abs(p.x()) <= GROSS_POSITION_M)) return "x" + n;
            if (!(Math.abs(p.y()) <= GROSS_POSITION_M)) return "y" + n;
            if (!(Math.abs(p.z()) <= GROSS_POSITION_M)) return "z" + n;
        }
        return null;
    }

    /** Why a value of {@code field} named by {@link #grossField()} is refused, in words. */
    public static String grossReason(String field) {
        if (field.equals("distance"))
            return String.format(java.util.Locale.ROOT, "distance is negative, not finite or beyond %.0f m: "
                    + "a misread value; correct or delete this row", GROSS_POSITION_M);
        return field.startsWith("q") || field.startsWith("from_q")
                ? String.format(java.util.Locale.ROOT, "joint value is not finite or beyond %.0f rad (or m): "
                        + "not a joint position; correct or delete this row", GROSS_JOINT)
                : String.format(java.util.Locale.ROOT, "coordinate is not finite or beyond %.0f m, outside any "
                        + "robot's reach: a misread value; correct or delete this row", GROSS_POSITION_M);
    }

    /** The same row with its (first) measured point replaced. */
    public Measurement withPosition(Vec3 p) {
        List<Vec3> pts = new ArrayList<>(points);
        pts.set(0, p);
        return new Measurement(poseId, q, p, orientation, directions, timeS, tempC, payloadKg, set, line, pts, distance, fromQ, fromDirections);
    }

    /** The same row with the controller's joint values {@code q} (the pose read otherwise: a reading corrected or moved). */
    public Measurement withQ(double[] q) {
        return new Measurement(poseId, q, position, orientation, directions, timeS, tempC, payloadKg, set, line, points, distance, fromQ, fromDirections);
    }

    public Measurement withOrientation(double[] quaternionWxyz) {
        return new Measurement(poseId, q, position, quaternionWxyz, directions, timeS, tempC, payloadKg, set, line, points, distance, fromQ, fromDirections);
    }

    public Measurement withSet(Split s) {
        return new Measurement(poseId, q, position, orientation, directions, timeS, tempC, payloadKg, s, line, points, distance, fromQ, fromDirections);
    }

    public Measurement withConditions(int[] dirs, double time, double temp, double payload) {
        // A pair keeps its first pose's directions when the row keeps directions (the first's or, if it had none, the same).
        return new Measurement(poseId, q, position, orientation, dirs, time, temp, payload, set, line, points, distance, fromQ,
                fromQ == null || dirs == null ? null : fromDirections != null ? fromDirections : dirs);
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Measurement m && poseId.equals(m.poseId) && Arrays.equals(q, m.q)
                && java.util.Objects.equals(position, m.position) && points.equals(m.points)
                && Double.compare(distance, m.distance) == 0 && Arrays.equals(fromQ, m.fromQ)
                && Arrays.equals(fromDirections, m.fromDirections) && Arrays.equals(orientation, m.orientation)
                && Arrays.equals(directions, m.directions) && Double.compare(timeS, m.timeS) == 0
                && Double.compare(tempC, m.tempC) == 0 && Double.compare(payloadKg, m.payloadKg) == 0
                && set == m.set;
    }

    @Override
    public int hashCode() { return poseId.hashCode() * 31 + Arrays.hashCode(q); }

    @Override
    public String toString() {
        return "Measurement[" + poseId + ", q=" + Arrays.toString(q)
                + (isPair() ? ", from=" + Arrays.toString(fromQ) + ", d=" + distance : isDistance() ? ", d=" + distance : points.size() > 1 ? ", points=" + points : ", p=" + position) + "]";
    }
}
