package org.robopro.calibration.measurement;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.robopro.models.InputException;
import org.robopro.models.JointType;
import org.robopro.models.Vec3;

/**
 * Builds a campaign from the two files a real session leaves: the instrument's point list
 * ({@code name} or {@code time} column, then {@code x,y,z}) and the controller's joint log
 * ({@code name} or {@code time}, then {@code q1..qN}), matched by name when both have names,
 * else by time (the log row nearest each point, within {@code maxDtS}). Comma-separated, one
 * header row; {@code #} lines are comments, except {@code # length-unit: mm|m} (points, default
 * mm), {@code # angle-unit: deg|rad} (log, default deg), {@code # frame: NAME} and
 * {@code # instrument: TEXT} (points) and {@code # robot: NAME} (log), which are carried into the
 * campaign. A {@code point} column in the point list names the reflector when a pose measures
 * several: the points of a pose share its name (or, matched by time, its log row) and the
 * campaign has one row per pose with every point. Every bad row is an {@link InputException} naming file, line and field
 * (docs/measurement-file.md, "Joining a point list and a joint log").
 */
public final class MeasurementJoin {
    private MeasurementJoin() { }

    /** A parsed table: its metadata, header and rows with their line numbers. */
    private record Table(String file, Map<String, String> meta, List<String> header, List<String[]> rows, List<Integer> lines) {
        int col(String name) { return header.indexOf(name); }
    }

    private static Table table(String file, String text) {
        Map<String, String> meta = new LinkedHashMap<>();
        List<String> header = null;
        List<String[]> rows = new ArrayList<>();
        List<Integer> lines = new ArrayList<>();
        String[] ls = text.split("\r\n|\n|\r", -1);
        for (int i = 0; i < ls.length; i++) {
            String l = ls[i].strip();
            if (i == 0 && l.startsWith("\uFEFF")) l = l.substring(1).strip();
            if (l.isEmpty()) continue;
            if (l.startsWith("#")) {
                int c = l.indexOf(':');
                if (c > 0) meta.put(l.substring(1, c).strip().toLowerCase(Locale.ROOT), l.substring(c + 1).strip());
                continue;
            }
            String[] cells = l.split(",", -1);
            for (int k = 0; k < cells.length; k++) cells[k] = cells[k].strip();
            if (header == null) {
                header = new ArrayList<>();
                for (int k = 0; k < cells.length; k++) {
                    String h = cells[k].toLowerCase(Locale.ROOT);
                    if (h.equals("time_s")) h = "time";
                    if (h.isEmpty()) throw new InputException(file, i + 1, 1, null, "empty column name in the header (column " + (k + 1) + ")");
                    if (header.contains(h)) throw new InputException(file, i + 1, 1, h, "column given twice");
                    header.add(h);
                }
                continue;
            }
            if (cells.length != header.size())
                throw new InputException(file, i + 1, 1, null, "row has " + cells.length + " fields but the header has " + header.size());
            rows.add(cells);
            lines.add(i + 1);
        }
        if (header == null || rows.isEmpty()) throw new InputException(file, 0, 0, null, "no header and rows");
        return new Table(file, meta, header, rows, lines);
    }

    private static double number(Table t, int row, String column) {
        int c = t.col(column);
        if (c < 0) throw new InputException(t.file(), 0, 0, column, "missing column '" + column + "'");
        String s = t.rows().get(row)[c];
        double v;
        try {
            v = Double.parseDouble(s);
        } catch (NumberFormatException e) {
            throw new InputException(t.file(), t.lines().get(row), c + 1, column, "'" + s + "' is not a number");
        }
        if (!Double.isFinite(v) || Math.abs(v) > 1e9)
            throw new InputException(t.file(), t.lines().get(row), c + 1, column, "'" + s + "' is out of range");
        return v;
    }

    private static double unit(Table t, String key, String dflt, Map<String, Double> units) {
        String u = t.meta().getOrDefault(key, dflt).toLowerCase(Locale.ROOT);
        Double f = units.get(u);
        if (f == null) throw new InputException(t.file(), 0, 0, key, "unknown unit '" + u + "'; expected one of " + units.keySet());
        return f;
    }

    /**
     * Joins a point list and a joint log into a campaign for a robot with these joint types.
     *
     * @param maxDtS largest time difference accepted when matching by time, s
     */
    public static MeasurementSet join(String pointsFile, String pointsText, String logFile, String logText, List<JointType> types,
                                      double maxDtS) {
        Table p = table(pointsFile, pointsText), j = table(logFile, logText);
        double lengthToM = unit(p, "length-unit", "mm", Map.of("mm", 1e-3, "m", 1.0));
        double angleToRad = unit(j, "angle-unit", "deg", Map.of("deg", Math.PI / 180, "rad", 1.0));
        double logLengthToM = unit(j, "length-unit", "mm", Map.of("mm", 1e-3, "m", 1.0));
        int n = types.size();
        for (int k = 1; k <= n; k++)
            if (j.col("q" + k) < 0) throw new InputException(logFile, 0, 0, "q" + k, "missing column 'q" + k + "' (the robot has " + n + " joints)");
        boolean byName = p.col("name") >= 0 && j.col("name") >= 0;
        if (!byName && (p.col("time") < 0 || j.col("time") < 0))
            throw new InputException(pointsFile, 0, 0, null, "cannot match the files: both need a 'name' column, or both a 'time' column");
        Map<String, Integer> names = new HashMap<>();
        double[] logTimes = new double[j.rows().size()];
        for (int r = 0; r < j.rows().size(); r++) {
            if (byName) {
                String name = j.rows().get(r)[j.col("name")];
                if (name.isEmpty()) throw new InputException(logFile, j.lines().get(r), j.col("name") + 1, "name", "empty name");
                Integer prev = names.put(name, r);
                if (prev != null)
                    throw new InputException(logFile, j.lines().get(r), j.col("name") + 1, "name", "'" + name + "' also on line " + j.lines().get(prev));
            } else {
                logTimes[r] = number(j, r, "time");
                if (r > 0 && logTimes[r] < logTimes[r - 1])
                    throw new InputException(logFile, j.lines().get(r), j.col("time") + 1, "time", "times must not decrease");
            }
        }
        int pointCol = p.col("point");
        // With a point column: the rows of each pose (by name, or by the log row matched in time) in first-seen order.
        Map<String, List<Integer>> byPose = new LinkedHashMap<>();
        Map<String, Integer> logRowOf = new HashMap<>();
        List<Measurement> rows = new ArrayList<>();
        for (int r = 0; r < p.rows().size(); r++) {
            int line = p.lines().get(r);
            int lr;
            String id;
            double time = Double.NaN;
            if (byName) {
                id = p.rows().get(r)[p.col("name")];
                if (id.isEmpty()) throw new InputException(pointsFile, line, p.col("name") + 1, "name", "empty name");
                Integer m = names.get(id);
                if (m == null) throw new InputException(pointsFile, line, p.col("name") + 1, "name", "'" + id + "' is not in " + logFile);
                lr = m;
            } else {
                time = number(p, r, "time");
                lr = nearest(logTimes, time);
                if (Math.abs(logTimes[lr] - time) > maxDtS)
                    throw new InputException(pointsFile, line, p.col("time") + 1, "time", String.format(Locale.ROOT,
                            "no joint-log row within %.3g s of %.3f s (nearest: %.3f s, line %d of %s)", maxDtS, time, logTimes[lr],
                            j.lines().get(lr), logFile));
                id = pointCol >= 0 ? Integer.toString(lr + 1) : Integer.toString(r + 1);
            }
            if (pointCol >= 0) {
                if (p.rows().get(r)[pointCol].isEmpty()) throw new InputException(pointsFile, line, pointCol + 1, "point", "empty point name");
                byPose.computeIfAbsent(id, k -> new ArrayList<>()).add(r);
                logRowOf.put(id, lr);
                continue;
            }
            double[] q = new double[n];
            for (int k = 0; k < n; k++) q[k] = number(j, lr, "q" + (k + 1)) * (types.get(k) == JointType.PRISMATIC ? logLengthToM : angleToRad);
            Vec3 pos = new Vec3(number(p, r, "x") * lengthToM, number(p, r, "y") * lengthToM, number(p, r, "z") * lengthToM);
            rows.add(new Measurement(id, q, pos, null, null, time, Double.NaN, Double.NaN, null, line));
        }
        List<String> pointNames = List.of();
        if (pointCol >= 0) {
            List<String> first = null;
            for (Map.Entry<String, List<Integer>> e : byPose.entrySet()) {
                List<String> have = new ArrayList<>();
                for (int r : e.getValue()) {
                    String pt = p.rows().get(r)[pointCol];
                    if (have.contains(pt))
                        throw new InputException(pointsFile, p.lines().get(r), pointCol + 1, "point", "point '" + pt + "' of pose '" + e.getKey()
                                + "' is given twice (first on line " + p.lines().get(e.getValue().get(have.indexOf(pt))) + ")");
                    if (first != null && !first.contains(pt))
                        throw new InputException(pointsFile, p.lines().get(r), pointCol + 1, "point", "point '" + pt + "' of pose '" + e.getKey()
                                + "' is not measured at the first pose (points " + String.join(", ", first) + ")");
                    have.add(pt);
                }
                if (first == null) first = have;
                for (String pt : first)
                    if (!have.contains(pt))
                        throw new InputException(pointsFile, p.lines().get(e.getValue().get(0)), pointCol + 1, "point", "pose '" + e.getKey()
                                + "' has no point '" + pt + "' (every pose measures points " + String.join(", ", first) + ")");
                int lr = logRowOf.get(e.getKey());
                double[] q = new double[n];
                for (int k = 0; k < n; k++) q[k] = number(j, lr, "q" + (k + 1)) * (types.get(k) == JointType.PRISMATIC ? logLengthToM : angleToRad);
                List<Vec3> pts = new ArrayList<>();
                for (String pt : first) {
                    int r = e.getValue().get(have.indexOf(pt));
                    pts.add(new Vec3(number(p, r, "x") * lengthToM, number(p, r, "y") * lengthToM, number(p, r, "z") * lengthToM));
                }
                int r0 = e.getValue().get(0);
                rows.add(new Measurement(e.getKey(), q, null, null, null, byName ? Double.NaN : number(p, r0, "time"), Double.NaN, Double.NaN,
                        null, p.lines().get(r0), pts, Double.NaN));
            }
            if (first.size() > 1) pointNames = first;
        }
        Map<String, String> meta = new LinkedHashMap<>();
        if (j.meta().containsKey("robot")) meta.put("robot", j.meta().get("robot"));
        String frame = p.meta().getOrDefault("frame", "instrument");
        meta.put("frame", frame);
        if (p.meta().containsKey("instrument")) meta.put("instrument", p.meta().get("instrument"));
        meta.put("joined-from", pointsFile + " + " + logFile + (byName ? " (by name)" : " (by time)"));
        return new MeasurementSet(pointsFile, meta, frame, rows, pointNames, null);
    }

    private static int nearest(double[] sorted, double t) {
        int lo = 0, hi = sorted.length - 1;
        while (hi - lo > 1) {
            int mid = (lo + hi) >>> 1;
            if (sorted[mid] <= t) lo = mid;
            else hi = mid;
        }
        return Math.abs(sorted[lo] - t) <= Math.abs(sorted[hi] - t) ? lo : hi;
    }
}
