package org.robopro.kinematics.importers;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.regex.Pattern;
import org.robopro.kinematics.Pose;
import org.robopro.kinematics.Units;
import org.robopro.models.FrameDescription;
import org.robopro.models.InputException;
import org.robopro.models.JointDescription;
import org.robopro.models.JointType;
import org.robopro.models.RobotDescription;
import org.robopro.models.TextFiles;

/**
 * Imports a Denavit-Hartenberg table (standard or modified/Craig) from robopro's DH text format
 * (docs/robot-file.md, "DH and modified DH tables") and computes the seed paper's inputs: every
 * joint's axis and a point on it, in base coordinates at the zero position, by chaining the
 * table's transforms.
 *
 * <ul>
 * <li>standard: {@code A_i = Rz(theta_i) Tz(d_i) Tx(a_i) Rx(alpha_i)}; joint i turns about
 *     z_{i-1} through the origin of frame i-1; base = frame 0, flange = frame n.</li>
 * <li>modified (Craig 1986): {@code A_i = Rx(alpha_{i-1}) Tx(a_{i-1}) Rz(theta_i) Tz(d_i)}, each
 *     row holding alpha_{i-1}, a_{i-1}, theta_i, d_i; joint i turns about z_i through the origin of
 *     frame i; base = frame 0, flange = frame n.</li>
 * </ul>
 * The zero position is theta_i = theta-offset (revolute) and d_i = d (prismatic).
 */
public final class DhImporter {
    /** Which DH convention a table uses. */
    public enum Convention {
        STANDARD, MODIFIED;

        String fileName() { return name().toLowerCase(Locale.ROOT); }
    }

    private static final Pattern NUMBER = Pattern.compile("[-+]?(\\d+\\.?\\d*|\\.\\d+)([eE][-+]?\\d+)?");
    private static final Set<String> COLUMNS = Set.of("joint", "type", "d", "a", "alpha", "theta", "min", "max", "max_speed");
    private static final Set<String> DIRECTIVES = Set.of("format", "convention", "name", "display_name", "source", "units");

    private DhImporter() { }

    public static RobotDescription read(Path file, Convention convention) {
        String text = TextFiles.readUtf8(file);
        String base = file.getFileName() == null ? "robot" : file.getFileName().toString();
        return parse(file.toString(), text, convention, base.replaceFirst("\\..*$", ""));
    }

    /**
     * Parses a DH table. {@code defaultName} names the robot if the file has no {@code name:}.
     */
    public static RobotDescription parse(String fileName, String text, Convention convention, String defaultName) {
        Map<String, String> directives = new LinkedHashMap<>();
        Map<String, int[]> directiveLines = new HashMap<>();
        List<String> header = null;
        List<Row> rows = new ArrayList<>();
        String[] lines = text.split("\r\n|\n|\r", -1);
        for (int ln = 1; ln <= lines.length; ln++) {
            String raw = lines[ln - 1];
            int hash = raw.indexOf('#');
            String line = hash >= 0 ? raw.substring(0, hash) : raw;
            if (line.isBlank()) continue;
            if (header == null) {
                int colon = line.indexOf(':');
                if (colon > 0 && !line.substring(0, colon).contains(",")) {
                    String key = line.substring(0, colon).trim().toLowerCase(Locale.ROOT);
                    int col = line.indexOf(line.trim()) + 1;
                    if (!DIRECTIVES.contains(key))
                        throw new InputException(fileName, ln, col, key, "unknown header line; expected one of "
                                + new java.util.TreeSet<>(DIRECTIVES) + " or the column names");
                    if (directives.containsKey(key))
                        throw new InputException(fileName, ln, col, key, "given twice");
                    directives.put(key, line.substring(colon + 1).trim());
                    directiveLines.put(key, new int[] {ln, col});
                    continue;
                }
                header = new ArrayList<>();
                for (Cell c : cells(line)) {
                    String name = c.text.toLowerCase(Locale.ROOT);
                    if (!COLUMNS.contains(name))
                        throw new InputException(fileName, ln, c.column, c.text, "unknown column; expected some of "
                                + new java.util.TreeSet<>(COLUMNS));
                    if (header.contains(name)) throw new InputException(fileName, ln, c.column, name, "column given twice");
                    header.add(name);
                }
                for (String required : List.of("d", "a", "alpha"))
                    if (!header.contains(required))
                        throw new InputException(fileName, ln, 1, required, "required column missing from the header");
                continue;
            }
            List<Cell> cells = cells(line);
            if (cells.size() != header.size())
                throw new InputException(fileName, ln, 1, null, "expected " + header.size() + " cells ("
                        + String.join(", ", header) + "), got " + cells.size());
            rows.add(new Row(ln, cells));
        }
        if (header == null) throw new InputException(fileName, lines.length, 1, null, "no column header and no table");
        if (rows.isEmpty()) throw new InputException(fileName, lines.length, 1, null, "the table has no joints");
        if (rows.size() > RobotDescription.MAX_JOINTS)
            throw new InputException(fileName, rows.get(RobotDescription.MAX_JOINTS).line(), 1, null, "the table has "
                    + rows.size() + " joints; a robot may have at most " + RobotDescription.MAX_JOINTS);

        // units: length=mm|m, angle=deg|rad
        int[] uLoc = directiveLines.getOrDefault("units", new int[] {1, 1});
        if (!directives.containsKey("units"))
            throw new InputException(fileName, 1, 1, "units", "missing header line 'units: length=mm, angle=deg' (or m, rad)");
        double lengthToM = 0, angleToRad = 0;
        for (String part : directives.get("units").split(",")) {
            String[] kv = part.split("=");
            String k = kv[0].trim().toLowerCase(Locale.ROOT), v = kv.length == 2 ? kv[1].trim().toLowerCase(Locale.ROOT) : "";
            if (k.equals("length") && v.equals("mm")) lengthToM = Units.MM;
            else if (k.equals("length") && v.equals("m")) lengthToM = 1;
            else if (k.equals("angle") && v.equals("deg")) angleToRad = Math.PI / 180;
            else if (k.equals("angle") && v.equals("rad")) angleToRad = 1;
            else throw new InputException(fileName, uLoc[0], uLoc[1], "units", "cannot read '" + part.trim()
                        + "'; expected length=mm or m, angle=deg or rad");
        }
        if (lengthToM == 0 || angleToRad == 0)
            throw new InputException(fileName, uLoc[0], uLoc[1], "units", "give both length and angle units");
        if (directives.containsKey("convention")) {
            String c = directives.get("convention").toLowerCase(Locale.ROOT);
            int[] l = directiveLines.get("convention");
            if (!c.equals("standard") && !c.equals("modified"))
                throw new InputException(fileName, l[0], l[1], "convention", "expected standard or modified, got '" + c + "'");
            if (!c.equals(convention.fileName()))
                throw new InputException(fileName, l[0], l[1], "convention", "the file says " + c
                        + " but it is being imported as " + convention.fileName() + " DH (--dh is standard, --mdh modified)");
        }
        if (directives.containsKey("format") && !directives.get("format").equals("robopro-dh 1")) {
            int[] l = directiveLines.get("format");
            throw new InputException(fileName, l[0], l[1], "format", "unknown format '" + directives.get("format")
                    + "'; this robopro reads robopro-dh 1");
        }

        // rows -> joints (checked first, then chained)
        Pose t = Pose.IDENTITY;
        List<JointDescription> joints = new ArrayList<>();
        Set<String> names = new java.util.HashSet<>();
        for (int i = 0; i < rows.size(); i++) {
            Row row = rows.get(i);
            Map<String, Cell> c = new HashMap<>();
            for (int k = 0; k < header.size(); k++) c.put(header.get(k), row.cells.get(k));
            String name = c.containsKey("joint") && !c.get("joint").text.isEmpty() ? c.get("joint").text : "j" + (i + 1);
            if (!names.add(name))
                throw new InputException(fileName, row.line, c.get("joint").column, "joint", "duplicate joint name '" + name + "'");
            JointType type = JointType.REVOLUTE;
            if (c.containsKey("type") && !c.get("type").text.isEmpty()) {
                type = JointType.parse(c.get("type").text);
                if (type == null)
                    throw new InputException(fileName, row.line, c.get("type").column, "type", "unknown joint type '"
                            + c.get("type").text + "' in joint " + (i + 1) + "; expected revolute or prismatic");
            }
            double d = number(fileName, row, c, "d", true, i) * lengthToM;
            double a = number(fileName, row, c, "a", true, i) * lengthToM;
            double alpha = number(fileName, row, c, "alpha", true, i) * angleToRad;
            double theta = number(fileName, row, c, "theta", false, i) * angleToRad;
            double scale = type == JointType.REVOLUTE ? angleToRad : lengthToM;
            double min = c.containsKey("min") && !c.get("min").text.isEmpty()
                    ? exact(fileName, row, c, "min", i, scale) : Double.NEGATIVE_INFINITY;
            double max = c.containsKey("max") && !c.get("max").text.isEmpty()
                    ? exact(fileName, row, c, "max", i, scale) : Double.POSITIVE_INFINITY;
            if (min > max)
                throw new InputException(fileName, row.line, c.get("min").column, "min", "minimum greater than maximum in joint " + (i + 1));
            double speed = Double.POSITIVE_INFINITY;
            if (c.containsKey("max_speed") && !c.get("max_speed").text.isEmpty()) {
                speed = exact(fileName, row, c, "max_speed", i, scale);
                if (!(speed > 0))
                    throw new InputException(fileName, row.line, c.get("max_speed").column, "max_speed",
                            "must be greater than zero in joint " + (i + 1));
            }
            Pose axisFrame;
            if (convention == Convention.STANDARD) {
                axisFrame = t;
                t = t.times(Pose.rotZ(theta)).times(Pose.translation(0, 0, d)).times(Pose.translation(a, 0, 0))
                        .times(Pose.rotX(alpha));
            } else {
                t = t.times(Pose.rotX(alpha)).times(Pose.translation(a, 0, 0)).times(Pose.rotZ(theta))
                        .times(Pose.translation(0, 0, d));
                axisFrame = t;
            }
            joints.add(CleanNumbers.joint(name, type, axisFrame.position(), axisFrame.zAxis(), min, max, speed));
        }
        FrameDescription flange = CleanNumbers.frame(t.position(), t.xAxis(), t.zAxis());
        String robotName = directives.getOrDefault("name", sanitize(defaultName));
        if (!robotName.matches("[A-Za-z0-9_.\\-]+")) {
            int[] l = directiveLines.getOrDefault("name", new int[] {1, 1});
            throw new InputException(fileName, l[0], l[1], "name", "'" + robotName + "' is not a valid name (letters, digits, '_', '.', '-')");
        }
        String source = directives.getOrDefault("source", "imported from " + fileName + " (" + convention.fileName() + " DH table)");
        return new RobotDescription(robotName, directives.getOrDefault("display_name", robotName), joints, flange,
                List.of(), java.util.Optional.empty(), List.of(), List.of(), source,
                Map.of("imported-from", fileName, "importer", convention.fileName() + " DH"));
    }

    static String sanitize(String s) {
        String r = s.replaceAll("[^A-Za-z0-9_.\\-]", "_");
        return r.isEmpty() ? "robot" : r;
    }

    private static double number(String file, Row row, Map<String, Cell> c, String column, boolean required, int i) {
        Cell cell = c.get(column);
        if (cell == null || cell.text.isEmpty()) {
            if (!required || cell == null && !List.of("d", "a", "alpha").contains(column)) return 0;
            throw new InputException(file, row.line, cell == null ? 1 : cell.column, column, "missing value in joint " + (i + 1));
        }
        if (!NUMBER.matcher(cell.text).matches())
            throw new InputException(file, row.line, cell.column, column, "'" + cell.text + "' is not a number (joint " + (i + 1) + ")");
        double v = Double.parseDouble(cell.text);
        if (!Double.isFinite(v))
            throw new InputException(file, row.line, cell.column, column, "number out of range (joint " + (i + 1) + ")");
        return v;
    }

    /** A required number converted to SI exactly from its decimal text ({@code factor}: the column's unit in SI). */
    private static double exact(String file, Row row, Map<String, Cell> c, String column, int i, double factor) {
        number(file, row, c, column, true, i);
        return CleanNumbers.fromFile(c.get(column).text, factor);
    }

    private record Cell(String text, int column) { }

    private record Row(int line, List<Cell> cells) { }

    private static List<Cell> cells(String line) {
        List<Cell> out = new ArrayList<>();
        int start = 0;
        while (true) {
            int comma = line.indexOf(',', start);
            String part = comma < 0 ? line.substring(start) : line.substring(start, comma);
            int lead = 0;
            while (lead < part.length() && Character.isWhitespace(part.charAt(lead))) lead++;
            out.add(new Cell(part.trim(), start + lead + 1));
            if (comma < 0) return out;
            start = comma + 1;
        }
    }
}
