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
    private static final Pattern FROM_Q_COL = Pattern.compile("from_q([1-9]\\d{0,2})");
    private static final Pattern FROM_DIR_COL = Pattern.compile("from_dir([1-9]\\d{0,2})");
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
            int maxQ = 0, maxDir = 0, maxFromQ = 0, maxFromDir = 0;
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
                var fm = FROM_Q_COL.matcher(name);
                if (fm.matches()) maxFromQ = Math.max(maxFromQ, Integer.parseInt(fm.group(1)));
                var fdm = FROM_DIR_COL.matcher(name);
                if (fdm.matches()) maxFromDir = Math.max(maxFromDir, Integer.parseInt(fdm.group(1)));
            }
            if (!index.containsKey("pose"))
                throw error(headerLine, 1, "pose", "required column 'pose' is missing from the header row");
            // The form of the file: one point per pose (x, y, z), several per pose in long form
            // (a point column, one row per pose and point) or wide form (x1, y1, z1, x2, ...), or
            // distance-only rows (distance, no coordinates).
            Integer pointIdx = index.get("point");
            int maxWide = 0;
            Field firstWide = null;
            for (Field f : cols) {
                String name = f.text.toLowerCase(Locale.ROOT);
                if (MULTI_POINT_COL.matcher(name).matches()) {
                    maxWide = Math.max(maxWide, Integer.parseInt(name.substring(1)));
                    if (firstWide == null) firstWide = f;
                }
            }
            // 'd' is the short name of 'distance' only in a file without coordinates: next to x, y, z
            // it stays an extra column, ignored as before.
            Integer distIdx = index.get("distance");
            boolean coordinates = index.containsKey("x") || index.containsKey("y") || index.containsKey("z") || firstWide != null;
            if (distIdx != null && index.containsKey("d"))
                throw error(headerLine, cols.get(index.get("d")).col, "d", "columns 'd' and 'distance' name the same value; keep one");
            if (distIdx == null && !coordinates) distIdx = index.get("d");
            String[] quat = {"qw", "qx", "qy", "qz"};
            if (distIdx != null) {
                String distName = cols.get(distIdx).text.toLowerCase(Locale.ROOT);
                for (String c : new String[] {"x", "y", "z", "point", "qw", "qx", "qy", "qz"})
                    if (index.containsKey(c))
                        throw error(headerLine, cols.get(index.get(c)).col, c, "a distance file has no coordinates, points or orientations: "
                                + "column '" + c + "' cannot stand next to '" + distName + "' (one file holds positions or distances, not both)");
                if (firstWide != null)
                    throw error(headerLine, firstWide.col, firstWide.text.toLowerCase(Locale.ROOT), "a distance file has no coordinates: column '"
                            + firstWide.text + "' cannot stand next to '" + distName + "'");
            } else if (firstWide != null) {
                String w = firstWide.text.toLowerCase(Locale.ROOT);
                for (String c : new String[] {"x", "y", "z"})
                    if (index.containsKey(c))
                        throw error(headerLine, cols.get(index.get(c)).col, c, "column '" + c + "' mixes the one-point form (x, y, z) with the "
                                + "numbered form ('" + w + "'); number every point's columns (x1, y1, z1, x2, ...)");
                if (pointIdx != null)
                    throw error(headerLine, cols.get(pointIdx).col, "point", "a 'point' column (one row per point) and numbered columns ('"
                            + w + "') are two forms of several points per pose; use one");
                if (maxWide < 2)
                    throw error(headerLine, firstWide.col, w, "numbered coordinate columns need at least two points (x1..z1 and x2..z2); "
                            + "for one point name the columns x, y, z");
                for (int k = 1; k <= maxWide; k++)
                    for (String a : new String[] {"x", "y", "z"})
                        if (!index.containsKey(a + k))
                            throw error(headerLine, 1, a + k, "coordinate column '" + a + k + "' is missing (the header has points 1 to " + maxWide
                                    + "; each needs x, y and z)");
            }
            if (distIdx == null && firstWide == null)
                for (String req : new String[] {"x", "y", "z"})
                    if (!index.containsKey(req))
                        throw error(headerLine, 1, req, "required column '" + req + "' is missing from the header row");
            if ((pointIdx != null || firstWide != null))
                for (String s : quat)
                    if (index.containsKey(s))
                        throw error(headerLine, cols.get(index.get(s)).col, s, "orientations with several points per pose are not "
                                + "supported (the points determine the flange orientation); drop the qw, qx, qy, qz columns or give one point per pose");
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
            int[] dIdx = maxDir > 0 ? numbered(headerLine, cols, index, "dir", maxDir, dof, "direction", " or none") : null;
            int[] oIdx = null;
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
            // Coordinate columns of each point on a row: one point (x, y, z or the long form's) or P wide.
            int perRow = distIdx != null ? 0 : firstWide != null ? maxWide : 1;
            int[][] pIdx = new int[perRow][3];
            String[][] pName = new String[perRow][3];
            for (int k = 0; k < perRow; k++)
                for (int a = 0; a < 3; a++) {
                    String c = "xyz".charAt(a) + (firstWide != null ? Integer.toString(k + 1) : "");
                    pIdx[k][a] = index.get(c);
                    pName[k][a] = c;
                }
            // Distances between two poses: the first pose's joints (and directions) in from_q1..from_qN (from_dir1..N).
            int[] fqIdx = null, fdIdx = null;
            if (maxFromQ > 0 || maxFromDir > 0) {
                String first = maxFromQ > 0 ? "from_q" + maxFromQ : "from_dir" + maxFromDir;
                int firstCol = cols.get(index.get(first)).col;
                if (distIdx == null)
                    throw error(headerLine, firstCol, first, "columns from_q1..from_q" + dof + " give the first pose of a distance "
                            + "between two poses; this file has no 'distance' column (a position file has no first pose)");
                if (maxFromQ == 0)
                    throw error(headerLine, firstCol, first, "first-pose directions without the first pose's joints: add from_q1..from_q" + dof);
                fqIdx = numbered(headerLine, cols, index, "from_q", maxFromQ, dof, "first-pose joint", "");
                if ((maxFromDir > 0) != (dIdx != null))
                    throw error(headerLine, maxFromDir > 0 ? cols.get(index.get("from_dir" + maxFromDir)).col : cols.get(dIdx[0]).col,
                            maxFromDir > 0 ? "from_dir" + maxFromDir : "dir1", "a distance between two poses needs the approach "
                            + "directions of both poses (dir1..dir" + dof + " and from_dir1..from_dir" + dof + ") or of neither");
                if (maxFromDir > 0) fdIdx = numbered(headerLine, cols, index, "from_dir", maxFromDir, dof, "first-pose direction", "");
                if (meta.containsKey("anchor")) {
                    int[] pos = metaPos.get("anchor");
                    throw error(pos[0], pos[1], "anchor", "a distance between two poses (from_q columns) has no anchor; delete the "
                            + "'# anchor' line, or the from_q columns if the lengths are to a fixed anchor");
                }
            }
            int poseIdx = index.get("pose");
            Integer tIdx = index.get("time_s"), tempIdx = index.get("temp_c"), payIdx = index.get("payload_kg"),
                    setIdx = index.get("set");

            double[] qScale = new double[dof];
            for (int k = 0; k < dof; k++)
                qScale[k] = types != null && types.get(k) == JointType.PRISMATIC ? lengthScale : angleScale;

            Vec3 anchor = null;
            if (meta.containsKey("anchor")) {
                int[] pos = metaPos.get("anchor");
                if (distIdx == null)
                    throw error(pos[0], pos[1], "anchor", "an anchor belongs to distance measurements ('distance' column); "
                            + "this file measures positions");
                anchor = anchor(meta.get("anchor"), pos, lengthScale);
            }

            List<Measurement> rows = new ArrayList<>();
            Map<String, Integer> seen = new HashMap<>();
            // Long form: the rows of each pose, by pose id in order of first appearance.
            Map<String, List<Measurement>> byPose = new LinkedHashMap<>();
            Map<String, List<String>> pointsOf = new HashMap<>();
            Map<String, List<Integer>> linesOf = new HashMap<>();
            Map<String, Integer> pointCols = new HashMap<>();
            List<String> order = new ArrayList<>();
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
                String pointName = null;
                if (pointIdx != null) {
                    Field nf = fs.get(pointIdx);
                    pointName = nf.text;
                    if (pointName.isEmpty()) throw error(lineNo, nf.col, "point", "empty point name");
                    List<String> names = pointsOf.computeIfAbsent(id, k -> new ArrayList<>());
                    int dup = names.indexOf(pointName);
                    if (dup >= 0)
                        throw error(lineNo, nf.col, "point", "point '" + pointName + "' of pose '" + id + "' is given twice (first on line "
                                + linesOf.get(id).get(dup) + ")");
                    names.add(pointName);
                    linesOf.computeIfAbsent(id, k -> new ArrayList<>()).add(lineNo);
                    pointCols.put(id + "\u0000" + pointName, nf.col);
                } else {
                    Integer prev = seen.putIfAbsent(id, lineNo);
                    if (prev != null) throw error(lineNo, pf.col, "pose", "duplicate pose id '" + id + "' (first on line " + prev + ")");
                }
                double[] q = joints(lineNo, fs, qIdx, "q", qScale);
                List<Vec3> pts = new ArrayList<>();
                for (int k = 0; k < perRow; k++)
                    pts.add(new Vec3(number(lineNo, fs.get(pIdx[k][0]), pName[k][0]) * lengthScale,
                            number(lineNo, fs.get(pIdx[k][1]), pName[k][1]) * lengthScale,
                            number(lineNo, fs.get(pIdx[k][2]), pName[k][2]) * lengthScale));
                double dist = Double.NaN;
                if (distIdx != null) {
                    Field f = fs.get(distIdx);
                    dist = number(lineNo, f, cols.get(distIdx).text.toLowerCase(Locale.ROOT)) * lengthScale;
                    if (dist < 0) throw error(lineNo, f.col, cols.get(distIdx).text.toLowerCase(Locale.ROOT), "a distance must not be negative");
                }
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
                int[] dirs = directions(lineNo, fs, dIdx, "dir");
                double[] fromQ = fqIdx == null ? null : joints(lineNo, fs, fqIdx, "from_q", qScale);
                int[] fromDirs = directions(lineNo, fs, fdIdx, "from_dir");
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
                Measurement row = new Measurement(id, q, null, o, dirs, time, temp, pay, split, lineNo,
                        distIdx != null ? null : pts, dist, fromQ, fromDirs);
                String gross = row.grossField();
                if (gross != null) {
                    int col;
                    if (gross.startsWith("q")) col = fs.get(qIdx[Integer.parseInt(gross.substring(1)) - 1]).col;
                    else if (gross.startsWith("from_q")) col = fs.get(fqIdx[Integer.parseInt(gross.substring(6)) - 1]).col;
                    else if (gross.equals("distance")) col = fs.get(distIdx).col;
                    else {
                        int k = gross.length() > 1 ? Integer.parseInt(gross.substring(1)) - 1 : 0;
                        col = fs.get(pIdx[k]["xyz".indexOf(gross.charAt(0))]).col;
                    }
                    throw error(lineNo, col, gross.equals("distance") ? cols.get(distIdx).text.toLowerCase(Locale.ROOT) : gross,
                            Measurement.grossReason(gross));
                }
                if (pointIdx == null) rows.add(row);
                else {
                    if (!byPose.containsKey(id)) order.add(id);
                    byPose.computeIfAbsent(id, k -> new ArrayList<>()).add(row);
                }
            }
            List<String> pointNames = List.of();
            if (pointIdx != null) {
                if (byPose.isEmpty()) throw error(headerLine, 1, null, "no measurement rows after the header row");
                List<String> names = pointsOf.get(order.get(0));
                for (String id : order) rows.add(merge(id, byPose.get(id), names, pointsOf.get(id), linesOf.get(id), pointCols, cols.get(pointIdx).col, dIdx != null));
                if (names.size() > 1) pointNames = names;
            } else if (perRow > 1) {
                List<String> names = new ArrayList<>();
                for (int k = 1; k <= perRow; k++) names.add(Integer.toString(k));
                pointNames = names;
            }
            if (rows.isEmpty()) throw error(headerLine, 1, null, "no measurement rows after the header row");
            String frame = meta.getOrDefault("frame", "instrument");
            if (frame.isEmpty()) {
                int[] pos = metaPos.get("frame");
                throw error(pos[0], pos[1], "frame", "empty frame name; write 'base' or the instrument's name");
            }
            return new MeasurementSet(file, Collections.unmodifiableMap(meta), frame, rows, pointNames, anchor);
        }

        /**
         * The rows of one pose in long form turned into one measurement: the same joint values,
         * directions and split on every row, every point of the first pose once, in that pose's
         * order; time, temperature and payload from the pose's first row.
         */
        Measurement merge(String id, List<Measurement> rs, List<String> names, List<String> have, List<Integer> lineNos,
                          Map<String, Integer> pointCols, int pointCol, boolean dirs) {
            Measurement first = rs.get(0);
            for (int r = 1; r < rs.size(); r++) {
                Measurement m = rs.get(r);
                for (int k = 0; k < first.dof(); k++)
                    if (m.q(k) != first.q(k))
                        throw error(m.line(), 1, "q" + (k + 1), "pose '" + id + "' has other joint values than on line " + first.line()
                                + "; every point of a pose repeats the pose's joint values (give the pose another id if the robot moved)");
                if (m.set() != first.set())
                    throw error(m.line(), 1, "set", "pose '" + id + "' is in set '" + name(m.set()) + "' here but '" + name(first.set())
                            + "' on line " + first.line() + "; the points of one pose belong to one set");
                if (dirs && !java.util.Arrays.equals(m.directions(), first.directions()))
                    throw error(m.line(), 1, "dir1", "pose '" + id + "' has other directions than on line " + first.line()
                            + "; the points of one pose share its approach directions");
            }
            for (String n : have)
                if (!names.contains(n))
                    throw error(lineNos.get(have.indexOf(n)), pointCols.get(id + "\u0000" + n), "point", "point '" + n + "' of pose '" + id
                            + "' is not measured at the first pose (points " + String.join(", ", names) + "); every pose measures the same points");
            for (String n : names)
                if (!have.contains(n))
                    throw error(first.line(), pointCol, "point", "pose '" + id + "' has no point '" + n + "' (every pose measures points "
                            + String.join(", ", names) + "); measure it or delete the pose's rows");
            List<Vec3> pts = new ArrayList<>();
            for (String n : names) pts.add(rs.get(have.indexOf(n)).position());
            return new Measurement(id, first.q(), null, null, first.directions(), first.timeS(), first.tempC(), first.payloadKg(),
                    first.set(), first.line(), pts, Double.NaN);
        }

        /**
         * The columns {@code prefix}1..{@code prefix}{@code dof} (one per joint; the header's highest
         * is {@code max}), each present, or a header error naming the first wrong one; {@code orNone} ends
         * the missing column's message (" or none" where the columns are optional, else "").
         */
        int[] numbered(int headerLine, List<Field> cols, Map<String, Integer> index, String prefix, int max, int dof, String what,
                       String orNone) {
            if (max != dof)
                throw error(headerLine, cols.get(index.get(prefix + max)).col, prefix + max,
                        what + " columns go to " + prefix + max + " but there are " + dof + " joints");
            int[] idx = new int[dof];
            for (int k = 0; k < dof; k++) {
                Integer c = index.get(prefix + (k + 1));
                if (c == null) throw error(headerLine, 1, prefix + (k + 1), what + " column '" + prefix + (k + 1)
                        + "' is missing (all of " + prefix + "1.." + prefix + dof + orNone + ")");
                idx[k] = c;
            }
            return idx;
        }

        /** The joint values in columns {@code idx} ({@code prefix}1..N) of a row, times each joint's unit scale. */
        double[] joints(int lineNo, List<Field> fs, int[] idx, String prefix, double[] qScale) {
            double[] q = new double[idx.length];
            for (int k = 0; k < idx.length; k++) q[k] = number(lineNo, fs.get(idx[k]), prefix + (k + 1)) * qScale[k];
            return q;
        }

        /** The directions in columns {@code idx} (null: none) of a row; each 1, -1 or 0. */
        int[] directions(int lineNo, List<Field> fs, int[] idx, String prefix) {
            if (idx == null) return null;
            int[] dirs = new int[idx.length];
            for (int k = 0; k < idx.length; k++) {
                Field f = fs.get(idx[k]);
                double v = number(lineNo, f, prefix + (k + 1));
                if (v != 1 && v != -1 && v != 0)
                    throw error(lineNo, f.col, prefix + (k + 1), "direction must be 1, -1 or 0, not '" + f.text + "'");
                dirs[k] = (int) v;
            }
            return dirs;
        }

        private static String name(Measurement.Split s) { return s == null ? "(none)" : s.fileName(); }

        Vec3 anchor(String text, int[] pos, double scale) {
            String[] parts = text.split("[,;\\s]+");
            if (parts.length != 3)
                throw error(pos[0], pos[1], "anchor", "the anchor needs three coordinates 'x, y, z' (robot base frame, length unit), not '"
                        + abbreviate(text) + "'");
            double[] v = new double[3];
            for (int k = 0; k < 3; k++) {
                if (!NUMBER.matcher(parts[k]).matches() || !Double.isFinite(Double.parseDouble(parts[k]))
                        || !(Math.abs(Double.parseDouble(parts[k]) * scale) <= Measurement.GROSS_POSITION_M))
                    throw error(pos[0], pos[1], "anchor", "anchor coordinate '" + abbreviate(parts[k]) + "' is not a number within "
                            + (int) Measurement.GROSS_POSITION_M + " m");
                v[k] = Double.parseDouble(parts[k]) * scale;
            }
            return new Vec3(v[0], v[1], v[2]);
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
        Set<String> s = new HashSet<>(List.of("pose", "x", "y", "z", "qw", "qx", "qy", "qz", "time_s", "temp_c", "payload_kg", "set",
                "point", "distance", "d"));
        for (int k = 1; k <= dof; k++) { s.add("q" + k); s.add("dir" + k); }
        return s;
    }
}
