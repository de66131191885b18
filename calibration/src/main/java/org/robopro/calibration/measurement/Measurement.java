package org.robopro.calibration.measurement;

import java.util.Arrays;
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
 */
public record Measurement(String poseId, double[] q, Vec3 position, double[] orientation, int[] directions,
                          double timeS, double tempC, double payloadKg, Split set, int line) {

    /** The {@code set} column's values. */
    public enum Split {
        TRAIN, VALIDATE;

        public String fileName() { return this == TRAIN ? "train" : "validate"; }
    }

    public Measurement {
        if (poseId == null || poseId.isEmpty()) throw new IllegalArgumentException("pose id must not be empty");
        if (q == null || position == null) throw new IllegalArgumentException("q and position are required");
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
    }

    /** A position-only measurement with no optional columns. */
    public static Measurement of(String poseId, double[] q, Vec3 position) {
        return new Measurement(poseId, q, position, null, null, Double.NaN, Double.NaN, Double.NaN, null, 0);
    }

    @Override public double[] q() { return q.clone(); }
    @Override public double[] orientation() { return orientation == null ? null : orientation.clone(); }
    @Override public int[] directions() { return directions == null ? null : directions.clone(); }

    /** Joint value i (0-based) without copying the array. */
    public double q(int i) { return q[i]; }

    public int dof() { return q.length; }

    public boolean hasOrientation() { return orientation != null; }

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
        if (!(Math.abs(position.x()) <= GROSS_POSITION_M)) return "x";
        if (!(Math.abs(position.y()) <= GROSS_POSITION_M)) return "y";
        if (!(Math.abs(position.z()) <= GROSS_POSITION_M)) return "z";
        return null;
    }

    /** Why a value of {@code field} named by {@link #grossField()} is refused, in words. */
    public static String grossReason(String field) {
        return field.startsWith("q")
                ? String.format(java.util.Locale.ROOT, "joint value is not finite or beyond %.0f rad (or m): "
                        + "not a joint position; correct or delete this row", GROSS_JOINT)
                : String.format(java.util.Locale.ROOT, "coordinate is not finite or beyond %.0f m, outside any "
                        + "robot's reach: a misread value; correct or delete this row", GROSS_POSITION_M);
    }

    public Measurement withPosition(Vec3 p) {
        return new Measurement(poseId, q, p, orientation, directions, timeS, tempC, payloadKg, set, line);
    }

    public Measurement withOrientation(double[] quaternionWxyz) {
        return new Measurement(poseId, q, position, quaternionWxyz, directions, timeS, tempC, payloadKg, set, line);
    }

    public Measurement withSet(Split s) {
        return new Measurement(poseId, q, position, orientation, directions, timeS, tempC, payloadKg, s, line);
    }

    public Measurement withConditions(int[] dirs, double time, double temp, double payload) {
        return new Measurement(poseId, q, position, orientation, dirs, time, temp, payload, set, line);
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Measurement m && poseId.equals(m.poseId) && Arrays.equals(q, m.q)
                && position.equals(m.position) && Arrays.equals(orientation, m.orientation)
                && Arrays.equals(directions, m.directions) && Double.compare(timeS, m.timeS) == 0
                && Double.compare(tempC, m.tempC) == 0 && Double.compare(payloadKg, m.payloadKg) == 0
                && set == m.set;
    }

    @Override
    public int hashCode() { return poseId.hashCode() * 31 + Arrays.hashCode(q); }

    @Override
    public String toString() {
        return "Measurement[" + poseId + ", q=" + Arrays.toString(q) + ", p=" + position + "]";
    }
}
