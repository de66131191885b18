package org.robopro.calibration.measurement;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.regex.Pattern;
import org.robopro.kinematics.Units;
import org.robopro.models.InputException;
import org.robopro.models.JointType;
import org.robopro.models.RobotDescription;
import org.robopro.models.TextFiles;
import org.robopro.models.Vec3;

/**
 * Reads measurement files, version 1 (/work/shared/formats/measurements.md,
 * docs/measurement-file.md). Every violation of the format is an {@link InputException} naming
 * file, line, column and field; nothing is returned half-read. Accepts more than the spec
 * requires: separators {@code ;}, tab or blanks besides {@code ,} (chosen from the header row),
 * extra columns (ignored), blank lines, and {@code #} comment lines among the data.
 */
public final class MeasurementReader {
    private static final Pattern NUMBER = Pattern.compile("[+-]?(\\d+\\.?\\d*|\\.\\d+)([eE][+-]?\\d+)?");
    private static final Pattern Q_COL = Pattern.compile("q([1-9]\\d{0,2})");
    private static final Pattern DIR_COL = Pattern.compile("dir([1-9]\\d{0,2})");
    private static final Pattern MULTI_POINT_COL = Pattern.compile("[xyz][1-9]\\d{0,2}");
    private static final String MAGIC = "robopro-measurements";

    private MeasurementReader() { }

    /** Reads a file for a robot: the joint count must match and prismatic joints take the length unit. */
    public static MeasurementSet read(Path file, RobotDescription robot) throws IOException {
        List<JointType> types = new ArrayList<>();
        robot.joints().forEach(j -> types.add(j.type()));
        return read(file, types);
    }

    /** Reads a file; {@code jointTypes} null means "any joint count, all revolute". */
    public static MeasurementSet read(Path file, List<JointType> jointTypes) throws IOException {
        return parse(file.toString(), TextFiles.readUtf8(file), jointTypes);
    }

    /**
     * Parses the text of a measurement file. {@code fileName} is used in messages only;
     * {@code jointTypes} null accepts any joint count and treats every joint as revolute.
     */
    public static MeasurementSet parse(String fileName, String text, List<JointType> jointTypes) {
        return new Parser(fileName, text, jointTypes).run();
    }

    private static final class Parser {
        final String file;
        final String[] lines;
        final List<JointType> types;

        Parser(String file, String text, List<JointType> types) {
            this.file = file;
            String t = text.startsWith("\uFEFF") ? text.substring(1) : text;
            this.lines = t.split("\r\n|\n|\r", -1);
            this.types = types;
        }

        InputException error(int line, int col, String field, String problem) {
            return new InputException(file, line, col, field, problem);
        }

        MeasurementSet run() {
            if (lines.length == 0 || !isMagic(lines[0]))
                throw error(1, 1, null, "not a measurement file: the first line must be '# " + MAGIC + " 1'");
            String version = lines[0].trim().substring(1).trim().substring(MAGIC.length()).trim();
            if (!version.equals("1"))
                throw error(1, lines[0].indexOf(MAGIC) + MAGIC.length() + 2, null,
                        "unsupported format version '" + version + "' (this robopro reads version 1)");
            Map<String, String> meta = new LinkedHashMap<>();
            Map<String, int[]> metaPos = new HashMap<>();
            int i = 1;
            for (; i < lines.length; i++) {
                String l = lines[i];
                String s = l.trim();
                if (s.isEmpty()) continue;
                if (!s.startsWith("#")) break;
                int colon = l.indexOf(':');
                if (colon < 0) continue; // a plain comment
                String key = l.substring(l.indexOf('#') + 1, colon).trim().toLowerCase(Locale.ROOT);
                String value = l.substring(colon + 1).trim();
                if (key.isEmpty()) continue;
                if (meta.containsKey(key))
                    throw error(i + 1, l.indexOf('#') + 2, key, "metadata key given twice (first on line " + metaPos.get(key)[0] + ")");
                meta.put(key, value);
                int valueCol = colon + 2;
                while (valueCol <= l.length() && valueCol - 1 < l.length() && Character.isWhitespace(l.charAt(valueCol - 1))) valueCol++;
                metaPos.put(key, new int[] {i + 1, valueCol});
            }
            if (i >= lines.length)
                throw error(lines.length, 1, null, "no header row (pose,q1,...,x,y,z) after the metadata lines");
            int headerLine = i + 1;
            double lengthScale = unit(meta, metaPos, headerLine, "length-unit", "mm", Units.MM, "m", 1.0);
            double angleScale = unit(meta, metaPos, headerLine, "angle-unit", "deg", Math.PI / 180, "rad", 1.0);

            String header = lines[i];
            char sep = separator(header);
            List<Field> cols = split(header, sep);
            Map<String, Integer> index = new HashMap<>();
            int maxQ = 0, maxDir = 0;
            for (int c = 0; c < cols.size(); c++) {
                Field f = cols.get(c);
                String name = f.text.toLowerCase(Locale.ROOT);
                if (name.isEmpty()) throw error(headerLine, f.col, null, "empty column name in the header row");
                if (index.containsKey(name)) throw error(headerLine, f.col, name, "column named twice in the header row");
                index.put(name, c);
                var qm = Q_COL.matcher(name);
                if (qm.matches()) maxQ = Math.max(maxQ, Integer.parseInt(qm.group(1)));
                var dm = DIR_COL.matcher(name);
                if (dm.matches()) maxDir = Math.max(maxDir, Integer.parseInt(dm.group(1)));
            }
            // Several measured points per pose need one tool point each in identification, which
            // is not supported yet: refuse such a file rather than ignore its extra points or fit
            // several reflectors as one.
            for (Field f : cols) {
                String name = f.text.toLowerCase(Locale.ROOT);
                if (name.equals("point") || MULTI_POINT_COL.matcher(name).matches())
                    throw error(headerLine, f.col, name, "several measured points per pose are not supported yet; "
                            + "give one measured point per pose (columns x, y, z; one file per reflector)");
            }
            for (String req : new String[] {"pose", "x", "y", "z"})
                if (!index.containsKey(req))
                    throw error(headerLine, 1, req, "required column '" + req + "' is missing from the header row");
            if (maxQ == 0) throw error(headerLine, 1, "q1", "required joint columns q1..qN are missing from the header row");
            for (int k = 1; k <= maxQ; k++)
                if (!index.containsKey("q" + k))
                    throw error(headerLine, 1, "q" + k, "joint column 'q" + k + "' is missing (the header has q" + maxQ + ")");
            int dof = maxQ;
            if (types != null && types.size() != dof)
                throw error(headerLine, cols.get(index.get("q" + maxQ)).col, "q" + maxQ,
                        "the file has " + dof + " joint columns (q1..q" + dof + ") but the robot has " + types.size()
                                + " joints; measure with the robot the file was taken on");
            int[] qIdx = new int[dof];
            for (int k = 0; k < dof; k++) qIdx[k] = index.get("q" + (k + 1));
            int[] dIdx = null;
            if (maxDir > 0) {
                if (maxDir != dof)
                    throw error(headerLine, cols.get(index.get("dir" + maxDir)).col, "dir" + maxDir,
                            "direction columns go to dir" + maxDir + " but there are " + dof + " joints");
                dIdx = new int[dof];
                for (int k = 0; k < dof; k++) {
                    Integer c = index.get("dir" + (k + 1));
                    if (c == null) throw error(headerLine, 1, "dir" + (k + 1), "direction column 'dir" + (k + 1) + "' is missing (all of dir1..dir" + dof + " or none)");
                    dIdx[k] = c;
                }
            }
            int[] oIdx = null;
            String[] quat = {"qw", "qx", "qy", "qz"};
            int present = 0;
            for (String s : quat) if (index.containsKey(s)) present++;
            if (present > 0 && present < 4) {
                for (String s : quat)
                    if (!index.containsKey(s))
                        throw error(headerLine, 1, s, "orientation column '" + s + "' is missing (all of qw, qx, qy, qz or none)");
            }
            if (present == 4) {
                oIdx = new int[4];
                for (int k = 0; k < 4; k++) oIdx[k] = index.get(quat[k]);
            }
            int poseIdx = index.get("pose"), xIdx = index.get("x"), yIdx = index.get("y"), zIdx = index.get("z");
            Integer tIdx = index.get("time_s"), tempIdx = index.get("temp_c"), payIdx = index.get("payload_kg"),
                    setIdx = index.get("set");

            double[] qScale = new double[dof];
            for (int k = 0; k < dof; k++)
                qScale[k] = types != null && types.get(k) == JointType.PRISMATIC ? lengthScale : angleScale;

            List<Measurement> rows = new ArrayList<>();
            Map<String, Integer> seen = new HashMap<>();
            for (int li = i + 1; li < lines.length; li++) {
                String l = lines[li];
                String s = l.trim();
                if (s.isEmpty() || s.startsWith("#")) continue;
                int lineNo = li + 1;
                List<Field> fs = split(l, sep);
                if (fs.size() != cols.size())
                    throw error(lineNo, fs.size() > cols.size() ? fs.get(cols.size()).col : l.length() + 1, null,
                            "row has " + fs.size() + " values but the header has " + cols.size() + " columns");
                Field pf = fs.get(poseIdx);
                String id = pf.text;
                if (id.isEmpty()) throw error(lineNo, pf.col, "pose", "empty pose id");
                Integer prev = seen.putIfAbsent(id, lineNo);
                if (prev != null) throw error(lineNo, pf.col, "pose", "duplicate pose id '" + id + "' (first on line " + prev + ")");
                double[] q = new double[dof];
                for (int k = 0; k < dof; k++) q[k] = number(lineNo, fs.get(qIdx[k]), "q" + (k + 1)) * qScale[k];
                Vec3 p = new Vec3(number(lineNo, fs.get(xIdx), "x") * lengthScale,
                        number(lineNo, fs.get(yIdx), "y") * lengthScale, number(lineNo, fs.get(zIdx), "z") * lengthScale);
                double[] o = null;
                if (oIdx != null) {
                    o = new double[4];
                    double n2 = 0;
                    for (int k = 0; k < 4; k++) {
                        o[k] = number(lineNo, fs.get(oIdx[k]), quat[k]);
                        n2 += o[k] * o[k];
                    }
                    double n = Math.sqrt(n2);
                    if (!(Math.abs(n - 1) <= 1e-3))
                        throw error(lineNo, fs.get(oIdx[0]).col, "qw", String.format(Locale.ROOT,
                                "orientation quaternion has length %.6g; it must be a unit quaternion", n));
                    for (int k = 0; k < 4; k++) o[k] /= n;
                }
                int[] dirs = null;
                if (dIdx != null) {
                    dirs = new int[dof];
                    for (int k = 0; k < dof; k++) {
                        Field f = fs.get(dIdx[k]);
                        double v = number(lineNo, f, "dir" + (k + 1));
                        if (v != 1 && v != -1 && v != 0)
                            throw error(lineNo, f.col, "dir" + (k + 1), "direction must be 1, -1 or 0, not '" + f.text + "'");
                        dirs[k] = (int) v;
                    }
                }
                double time = tIdx == null ? Double.NaN : number(lineNo, fs.get(tIdx), "time_s");
                double temp = tempIdx == null ? Double.NaN : number(lineNo, fs.get(tempIdx), "temp_c");
                double pay = payIdx == null ? Double.NaN : number(lineNo, fs.get(payIdx), "payload_kg");
                if (pay < 0) throw error(lineNo, fs.get(payIdx).col, "payload_kg", "payload must not be negative");
                Measurement.Split split = null;
                if (setIdx != null) {
                    Field f = fs.get(setIdx);
                    switch (f.text.toLowerCase(Locale.ROOT)) {
                        case "train" -> split = Measurement.Split.TRAIN;
                        case "validate" -> split = Measurement.Split.VALIDATE;
                        default -> throw error(lineNo, f.col, "set", "set must be 'train' or 'validate', not '" + f.text + "'");
                    }
                }
                Measurement row = new Measurement(id, q, p, o, dirs, time, temp, pay, split, lineNo);
                String gross = row.grossField();
                if (gross != null)
                    throw error(lineNo, fs.get(gross.startsWith("q") ? qIdx[Integer.parseInt(gross.substring(1)) - 1]
                            : index.get(gross)).col, gross, Measurement.grossReason(gross));
                rows.add(row);
            }
            if (rows.isEmpty()) throw error(headerLine, 1, null, "no measurement rows after the header row");
            String frame = meta.getOrDefault("frame", "instrument");
            if (frame.isEmpty()) {
                int[] pos = metaPos.get("frame");
                throw error(pos[0], pos[1], "frame", "empty frame name; write 'base' or the instrument's name");
            }
            return new MeasurementSet(file, Collections.unmodifiableMap(meta), frame, rows);
        }

        double unit(Map<String, String> meta, Map<String, int[]> pos, int headerLine, String key,
                    String a, double aScale, String b, double bScale) {
            String v = meta.get(key);
            if (v == null)
                throw error(headerLine, 1, key, "metadata '" + key + "' is missing; add a line '# " + key + ": " + a
                        + "' (or " + b + ") before the header row");
            String u = v.toLowerCase(Locale.ROOT);
            if (u.equals(a)) return aScale;
            if (u.equals(b)) return bScale;
            int[] p = pos.get(key);
            throw error(p[0], p[1], key, "unknown unit '" + v + "'; use '" + a + "' or '" + b + "'");
        }

        double number(int line, Field f, String field) {
            String t = f.text;
            if (!NUMBER.matcher(t).matches())
                throw error(line, f.col, field, t.isEmpty() ? "missing value" : "'" + abbreviate(t) + "' is not a number");
            double v = Double.parseDouble(t);
            if (!Double.isFinite(v)) throw error(line, f.col, field, "'" + abbreviate(t) + "' is not finite");
            return v;
        }
    }

    private static String abbreviate(String s) {
        return s.length() > 40 ? s.substring(0, 40) + "..." : s;
    }

    private static boolean isMagic(String first) {
        String s = first.trim();
        if (!s.startsWith("#")) return false;
        s = s.substring(1).trim();
        return s.startsWith(MAGIC) && (s.length() == MAGIC.length() || Character.isWhitespace(s.charAt(MAGIC.length())));
    }

    private static char separator(String header) {
        if (header.indexOf(',') >= 0) return ',';
        if (header.indexOf(';') >= 0) return ';';
        if (header.indexOf('\t') >= 0) return '\t';
        return ' ';
    }

    /** A trimmed value and the 1-based column where its text starts. */
    private record Field(String text, int col) { }

    private static List<Field> split(String line, char sep) {
        List<Field> out = new ArrayList<>();
        if (sep == ' ') {
            int k = 0, n = line.length();
            while (k < n) {
                while (k < n && Character.isWhitespace(line.charAt(k))) k++;
                if (k >= n) break;
                int start = k;
                while (k < n && !Character.isWhitespace(line.charAt(k))) k++;
                out.add(new Field(line.substring(start, k), start + 1));
            }
            return out;
        }
        int start = 0;
        for (int k = 0; k <= line.length(); k++) {
            if (k == line.length() || line.charAt(k) == sep) {
                String raw = line.substring(start, k);
                int lead = 0;
                while (lead < raw.length() && Character.isWhitespace(raw.charAt(lead))) lead++;
                out.add(new Field(raw.trim(), start + 1 + Math.min(lead, raw.length())));
                start = k + 1;
            }
        }
        return out;
    }

    /** Unused-set guard so a caller can list the columns this reader understands. */
    public static Set<String> knownColumns(int dof) {
        Set<String> s = new HashSet<>(List.of("pose", "x", "y", "z", "qw", "qx", "qy", "qz", "time_s", "temp_c", "payload_kg", "set"));
        for (int k = 1; k <= dof; k++) { s.add("q" + k); s.add("dir" + k); }
        return s;
    }
}
