package org.robopro.calibration.measurement;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.robopro.kinematics.Units;
import org.robopro.models.AtomicFiles;
import org.robopro.models.JointType;

/**
 * Writes measurement files, version 1, in mm and degrees (metres for prismatic joints' values
 * would break the one length unit, so prismatic joint values are written in mm). Optional columns
 * are written when every row has them. Files are written atomically and never overwrite
 * existing data unless asked.
 */
public final class MeasurementWriter {
    private MeasurementWriter() { }

    /** Which optional columns a file has. */
    public record Columns(boolean orientation, boolean directions, boolean time, boolean temp, boolean payload, boolean split) {
        /** The optional columns every row of {@code set} has. */
        public static Columns of(MeasurementSet set) {
            return new Columns(set.hasOrientation(), set.hasDirections(), set.hasTime(), set.hasTemperature(),
                    set.hasPayload(), set.hasSplit());
        }

        /** The optional columns {@code m} has. */
        public static Columns of(Measurement m) {
            return new Columns(m.orientation() != null, m.directions() != null, !Double.isNaN(m.timeS()),
                    !Double.isNaN(m.tempC()), !Double.isNaN(m.payloadKg()), m.set() != null);
        }
    }

    /** The file's text. {@code jointTypes} null treats every joint as revolute. */
    public static String format(MeasurementSet set, List<JointType> jointTypes) {
        StringBuilder sb = new StringBuilder();
        Columns c = Columns.of(set);
        if (set.pointNames().isEmpty() && !set.isDistance()) {
            header(sb, set.metadata(), set.frame(), set.dof(), c);
            for (Measurement m : set.rows()) row(sb, m, set.dof(), jointTypes, c);
            return sb.toString();
        }
        // Several points per pose: the long form, one row per pose and point; distances: a distance column.
        for (String n : set.pointNames())
            if (n.contains(",") || n.contains("\n") || n.startsWith("#") || n.isBlank())
                throw new IllegalArgumentException("point name '" + n + "' cannot be written (comma, newline, leading # or blank)");
        header(sb, set.metadata(), set.frame(), set.dof(), c, !set.pointNames().isEmpty(), set.isDistance(), set.anchor(), set.isPairs());
        for (Measurement m : set.rows()) {
            if (set.isDistance()) {
                row(sb, m, set.dof(), jointTypes, c, null, m.distance(), null);
                continue;
            }
            for (int k = 0; k < set.pointCount(); k++) row(sb, m, set.dof(), jointTypes, c, set.pointNames().get(k), Double.NaN, m.point(k));
        }
        return sb.toString();
    }

    /** The magic line, metadata, units and the header row. */
    static void header(StringBuilder sb, Map<String, String> metadata, String frame, int dof, Columns c) {
        header(sb, metadata, frame, dof, c, false, false, null, false);
    }

    /**
     * The header with a point column ({@code points}) or a distance column instead of x, y, z, and an
     * anchor line; {@code pairs}: the first pose's joints (and directions) of distances between two poses.
     */
    static void header(StringBuilder sb, Map<String, String> metadata, String frame, int dof, Columns c, boolean points,
                       boolean distance, org.robopro.models.Vec3 anchor, boolean pairs) {
        sb.append("# robopro-measurements 1\n");
        boolean wroteFrame = false;
        for (Map.Entry<String, String> e : metadata.entrySet()) {
            String k = e.getKey();
            if (k.equals("length-unit") || k.equals("angle-unit") || k.equals("robopro-measurements 1") || k.equals("anchor")) continue;
            if (k.equals("frame")) {
                wroteFrame = true;
                if (!distance) sb.append("# frame: ").append(frame).append('\n');
                continue;
            }
            sb.append("# ").append(k).append(": ").append(e.getValue().replace('\n', ' ')).append('\n');
        }
        if (!wroteFrame && !distance) sb.append("# frame: ").append(frame).append('\n');
        if (anchor != null)
            sb.append("# anchor: ").append(num(Units.mToMm(anchor.x()), 6)).append(", ").append(num(Units.mToMm(anchor.y()), 6))
              .append(", ").append(num(Units.mToMm(anchor.z()), 6)).append('\n');
        sb.append("# length-unit: mm\n# angle-unit: deg\n");
        sb.append("pose");
        if (points) sb.append(",point");
        for (int k = 1; k <= dof; k++) sb.append(",q").append(k);
        if (pairs) for (int k = 1; k <= dof; k++) sb.append(",from_q").append(k);
        sb.append(distance ? ",distance" : ",x,y,z");
        if (c.orientation()) sb.append(",qw,qx,qy,qz");
        if (c.directions()) for (int k = 1; k <= dof; k++) sb.append(",dir").append(k);
        if (c.directions() && pairs) for (int k = 1; k <= dof; k++) sb.append(",from_dir").append(k);
        if (c.time()) sb.append(",time_s");
        if (c.temp()) sb.append(",temp_c");
        if (c.payload()) sb.append(",payload_kg");
        if (c.split()) sb.append(",set");
        sb.append('\n');
    }

    /** One data row with the columns {@code c}. */
    static void row(StringBuilder sb, Measurement m, int dof, List<JointType> jointTypes, Columns c) {
        row(sb, m, dof, jointTypes, c, null, Double.NaN, m.position());
    }

    /** A data row: {@code point} the point's name (long form) or null; {@code distance} (m) or the position {@code p}. */
    static void row(StringBuilder sb, Measurement m, int dof, List<JointType> jointTypes, Columns c, String point, double distance,
                    org.robopro.models.Vec3 p) {
        String id = m.poseId();
        if (id.contains(",") || id.contains("\n") || id.startsWith("#"))
            throw new IllegalArgumentException("pose id '" + id + "' cannot be written (comma, newline or leading #)");
        sb.append(id);
        if (point != null) sb.append(',').append(point);
        joints(sb, m.q(), dof, jointTypes);
        double[] from = m.fromQ();
        if (from != null) joints(sb, from, dof, jointTypes);
        if (p == null) sb.append(',').append(num(Units.mToMm(distance), 6));
        else sb.append(',').append(num(Units.mToMm(p.x()), 6))
                .append(',').append(num(Units.mToMm(p.y()), 6))
                .append(',').append(num(Units.mToMm(p.z()), 6));
        if (c.orientation()) for (double v : m.orientation()) sb.append(',').append(num(v, 12));
        if (c.directions()) for (int v : m.directions()) sb.append(',').append(v);
        if (c.directions() && from != null) for (int v : m.fromDirections()) sb.append(',').append(v);
        if (c.time()) sb.append(',').append(num(m.timeS(), 3));
        if (c.temp()) sb.append(',').append(num(m.tempC(), 3));
        if (c.payload()) sb.append(',').append(num(m.payloadKg(), 3));
        if (c.split()) sb.append(',').append(m.set().fileName());
        sb.append('\n');
    }

    /** The first {@code dof} joint values of {@code q}, each after a comma, in the file's units (degrees, mm for a prismatic joint). */
    private static void joints(StringBuilder sb, double[] q, int dof, List<JointType> jointTypes) {
        for (int k = 0; k < dof; k++) {
            boolean prismatic = jointTypes != null && jointTypes.get(k) == JointType.PRISMATIC;
            sb.append(',').append(num(prismatic ? Units.mToMm(q[k]) : Units.radToDeg(q[k]), 9));
        }
    }

    public static void write(MeasurementSet set, List<JointType> jointTypes, Path file, boolean overwrite) throws IOException {
        AtomicFiles.writeString(file, format(set, jointTypes), overwrite);
    }

    private static String num(double v, int decimals) {
        String s = String.format(Locale.ROOT, "%." + decimals + "f", v);
        // Trim trailing zeros so files stay readable; keep at least one digit after the point.
        int end = s.length();
        while (end > 0 && s.charAt(end - 1) == '0') end--;
        if (end > 0 && s.charAt(end - 1) == '.') end++;
        s = s.substring(0, end);
        return s.equals("-0.0") ? "0.0" : s;
    }
}
