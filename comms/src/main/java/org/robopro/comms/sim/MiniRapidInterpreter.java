package org.robopro.comms.sim;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.robopro.comms.SpeedData;
import org.robopro.kinematics.Pose;
import org.robopro.kinematics.Units;

/**
 * A deliberately small RAPID subset for the simulated controller: a MODULE with data
 * declarations ({@code robtarget}, {@code jointtarget}, {@code speeddata}, {@code tooldata},
 * {@code wobjdata}) and a {@code PROC main()} whose MoveAbsJ / MoveJ / MoveL instructions are
 * executed in order. Other simple instructions (TPWrite, WaitTime, ...) are skipped; MoveC and
 * procedure calls are refused, so a program is never half understood.
 */
public final class MiniRapidInterpreter implements ProgramInterpreter {

    @Override
    public String check(String text, int dof) {
        try {
            compile(text, dof);
            return null;
        } catch (IllegalArgumentException e) {
            return e.getMessage();
        }
    }

    @Override
    public List<Step> compile(String text, int dof) {
        String src = stripComments(text);
        if (!src.matches("(?is)\\s*MODULE\\s+\\w+.*ENDMODULE\\s*"))
            throw new IllegalArgumentException("line 1: expected MODULE name ... ENDMODULE");
        Map<String, Object> data = new HashMap<>();
        data.put("tool0", Pose.IDENTITY);
        data.put("wobj0", Pose.IDENTITY);
        List<Step> steps = new ArrayList<>();
        boolean inMain = false, inProc = false, sawMain = false;
        int start = firstStatementStart(src);
        while (start < src.length()) {
            int end = src.indexOf(';', start);
            String chunk = end < 0 ? src.substring(start) : src.substring(start, end);
            int chunkLine = lineOf(src, start);
            // PROC / ENDPROC / ENDMODULE headers appear without ';' before the next statement.
            for (Piece piece : splitHeaders(chunk)) {
                String s = piece.text().strip();
                int line = chunkLine + piece.lineOffset();
                if (s.isEmpty()) continue;
                String upper = s.toUpperCase(Locale.ROOT);
                if (upper.startsWith("PROC ")) {
                    if (inProc) throw new IllegalArgumentException("line " + line + ": PROC inside PROC");
                    inProc = true;
                    inMain = upper.matches("PROC\\s+MAIN\\s*\\(\\s*\\)");
                    sawMain |= inMain;
                } else if (upper.equals("ENDPROC")) {
                    if (!inProc) throw new IllegalArgumentException("line " + line + ": ENDPROC without PROC");
                    inProc = false;
                    inMain = false;
                } else if (upper.equals("ENDMODULE")) {
                    if (inProc) throw new IllegalArgumentException("line " + line + ": ENDMODULE inside PROC");
                } else if (!inProc) {
                    declaration(s, line, data, dof);
                } else if (inMain) {
                    Step st = instruction(s, line, data, dof);
                    if (st != null) steps.add(st);
                }
            }
            if (end < 0) break;
            start = end + 1;
        }
        if (inProc) throw new IllegalArgumentException("line " + lineOf(src, src.length()) + ": PROC without ENDPROC");
        if (!sawMain) throw new IllegalArgumentException("line 1: no PROC main()");
        return steps;
    }

    private static int firstStatementStart(String src) {
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("(?is)\\s*MODULE\\s+\\w+[^\\n]*\\n?").matcher(src);
        return m.lookingAt() ? m.end() : 0;
    }

    /** Part of a statement chunk and the line (relative to the chunk's first line) where its text starts. */
    private record Piece(String text, int lineOffset) { }

    /** Splits "PROC main()\n  MoveJ ..." into the header lines and the statement. */
    private static List<Piece> splitHeaders(String chunk) {
        List<Piece> out = new ArrayList<>();
        StringBuilder cur = new StringBuilder();
        int curStart = -1;
        String[] lines = chunk.split("\n", -1);
        for (int i = 0; i < lines.length; i++) {
            String ln = lines[i];
            String t = ln.strip().toUpperCase(Locale.ROOT);
            if (t.startsWith("PROC ") || t.equals("ENDPROC") || t.equals("ENDMODULE") || t.startsWith("MODULE ")) {
                if (cur.toString().strip().length() > 0) out.add(new Piece(cur.toString(), curStart));
                cur.setLength(0);
                curStart = -1;
                if (!t.startsWith("MODULE ")) out.add(new Piece(ln, i));
            } else {
                if (curStart < 0 && !t.isEmpty()) curStart = i;
                cur.append(ln).append('\n');
            }
        }
        out.add(new Piece(cur.toString(), Math.max(curStart, 0)));
        return out;
    }

    private static String stripComments(String text) {
        StringBuilder sb = new StringBuilder(text.length());
        boolean inString = false, inComment = false;
        for (char c : text.toCharArray()) {
            if (c == '\n') {
                inComment = false;
                inString = false;
                sb.append(c);
                continue;
            }
            if (inComment) continue;
            if (c == '"') inString = !inString;
            if (c == '!' && !inString) {
                inComment = true;
                continue;
            }
            sb.append(c == '\r' ? ' ' : c);
        }
        return sb.toString();
    }

    private static int lineOf(String src, int index) {
        int line = 1;
        for (int i = 0; i < Math.min(index, src.length()); i++) if (src.charAt(i) == '\n') line++;
        return line;
    }

    private static void declaration(String s, int line, Map<String, Object> data, int dof) {
        java.util.regex.Matcher m = java.util.regex.Pattern
                .compile("(?is)(?:LOCAL\\s+)?(CONST|VAR|PERS)\\s+(\\w+)\\s+(\\w+)\\s*(?::=\\s*(.*))?").matcher(s);
        if (!m.matches()) throw new IllegalArgumentException("line " + line + ": expected a data declaration, got '" + clip(s) + "'");
        String type = m.group(2).toLowerCase(Locale.ROOT);
        String name = m.group(3);
        String value = m.group(4);
        if (value == null) return; // declared without value: unusable as a target, fine unless used
        Object v = switch (type) {
            case "robtarget" -> robtarget(Aggregate.parse(value, line), line);
            case "jointtarget" -> jointtarget(Aggregate.parse(value, line), line, dof);
            case "speeddata" -> speeddata(Aggregate.parse(value, line), line);
            case "tooldata" -> tooldata(Aggregate.parse(value, line), line);
            case "wobjdata" -> wobjdata(Aggregate.parse(value, line), line);
            default -> null; // num, string, ...: not needed for motion
        };
        if (v != null) data.put(name.toLowerCase(Locale.ROOT), v);
    }

    private static Step instruction(String s, int line, Map<String, Object> data, int dof) {
        String[] head = s.split("\\s+", 2);
        String op = head[0].toLowerCase(Locale.ROOT);
        switch (op) {
            case "moveabsj", "movej", "movel" -> { }
            case "movec", "moveabsjdo", "movejdo", "moveldo", "movecdo", "movelsync", "movejsync" ->
                    throw new IllegalArgumentException("line " + line + ": " + head[0] + " is not supported by the simulator");
            default -> {
                if (op.matches("tpwrite|waittime|confl|confj|singarea|accset|velset|tperase|stop|exit|return"))
                    return null;
                if (op.contains(":=")) return null;
                throw new IllegalArgumentException("line " + line + ": instruction '" + clip(s) + "' is not supported by the simulator");
            }
        }
        if (head.length < 2) throw new IllegalArgumentException("line " + line + ": " + head[0] + " needs arguments");
        List<String> args = splitArgs(head[1]);
        if (args.size() < 4)
            throw new IllegalArgumentException("line " + line + ": " + head[0] + " needs target, speed, zone, tool");
        String target = args.get(0).replaceAll("(?i)\\\\NoEOffs", "").strip();
        SpeedData speed = speedArg(args.get(1).replaceAll("(?i)\\\\[VT]\\s*:=.*", "").strip(), line, data);
        Pose tool = null, wobj = null;
        for (int i = 3; i < args.size(); i++) {
            String a = args.get(i).strip();
            String[] parts = a.split("(?i)\\\\WObj\\s*:=", 2);
            if (i == 3 && !parts[0].isBlank()) tool = lookup(parts[0].strip(), Pose.class, "tooldata", line, data);
            if (parts.length == 2) wobj = lookup(parts[1].strip(), Pose.class, "wobjdata", line, data);
        }
        if (wobj == null) wobj = Pose.IDENTITY;
        if (op.equals("moveabsj")) {
            double[] q = target.startsWith("[") ? jointtarget(Aggregate.parse(target, line), line, dof)
                    : lookup(target, double[].class, "jointtarget", line, data);
            return new Step(ProgramInterpreter.Kind.ABS_JOINTS, q, null, speed, tool, wobj, line);
        }
        Pose p = target.startsWith("[") ? robtarget(Aggregate.parse(target, line), line)
                : lookup(target, Pose.class, "robtarget", line, data);
        return new Step(op.equals("movej") ? ProgramInterpreter.Kind.JOINT_TO_POSE : ProgramInterpreter.Kind.LINEAR,
                null, p, speed, tool, wobj, line);
    }

    private static <T> T lookup(String name, Class<T> type, String what, int line, Map<String, Object> data) {
        Object v = data.get(name.toLowerCase(Locale.ROOT));
        if (!type.isInstance(v)) throw new IllegalArgumentException("line " + line + ": unknown " + what + " '" + clip(name) + "'");
        return type.cast(v);
    }

    private static SpeedData speedArg(String s, int line, Map<String, Object> data) {
        if (s.startsWith("[")) return speeddata(Aggregate.parse(s, line), line);
        String l = s.toLowerCase(Locale.ROOT);
        if (l.equals("vmax") || l.equals("v_max")) return new SpeedData(5.0, Math.toRadians(500), 5.0, Math.toRadians(1000));
        if (l.matches("v\\d+")) {
            double mm = Double.parseDouble(l.substring(1));
            if (mm <= 0) throw new IllegalArgumentException("line " + line + ": speed " + s + " must be > 0");
            return new SpeedData(Units.mmToM(mm), Math.toRadians(500), Units.mmToM(5000), Math.toRadians(1000));
        }
        return lookup(s, SpeedData.class, "speeddata", line, data);
    }

    private static List<String> splitArgs(String s) {
        List<String> out = new ArrayList<>();
        int depth = 0, start = 0;
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            if (c == '[') depth++;
            else if (c == ']') depth--;
            else if (c == ',' && depth == 0) {
                out.add(s.substring(start, i));
                start = i + 1;
            }
        }
        out.add(s.substring(start));
        return out;
    }

    private static Pose robtarget(Aggregate a, int line) {
        Aggregate trans = a.item(0, line), rot = a.item(1, line);
        return pose(trans, rot, line);
    }

    private static Pose pose(Aggregate trans, Aggregate rot, int line) {
        double[] t = trans.numbers(3, line), qq = rot.numbers(4, line);
        double n = Math.sqrt(qq[0] * qq[0] + qq[1] * qq[1] + qq[2] * qq[2] + qq[3] * qq[3]);
        if (Math.abs(n - 1) > 1e-3) throw new IllegalArgumentException("line " + line + ": quaternion norm " + n + " is not 1");
        return Pose.fromQuaternion(qq[0], qq[1], qq[2], qq[3], Units.mmToM(t[0]), Units.mmToM(t[1]), Units.mmToM(t[2]));
    }

    private static double[] jointtarget(Aggregate a, int line, int dof) {
        double[] deg = a.item(0, line).numbers(6, line);
        if (dof != 6) throw new IllegalArgumentException("line " + line + ": jointtarget needs a 6-axis robot");
        return Units.degToRad(deg);
    }

    private static SpeedData speeddata(Aggregate a, int line) {
        double[] v = a.numbers(4, line);
        try {
            return new SpeedData(Units.mmToM(v[0]), Math.toRadians(v[1]), Units.mmToM(v[2]), Math.toRadians(v[3]));
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("line " + line + ": " + e.getMessage());
        }
    }

    private static Pose tooldata(Aggregate a, int line) {
        Aggregate tframe = a.item(1, line);
        return pose(tframe.item(0, line), tframe.item(1, line), line);
    }

    private static Pose wobjdata(Aggregate a, int line) {
        Aggregate u = a.item(3, line), o = a.item(4, line);
        return pose(u.item(0, line), u.item(1, line), line).times(pose(o.item(0, line), o.item(1, line), line));
    }

    private static String clip(String s) {
        String t = s.strip().replaceAll("\\s+", " ");
        return t.length() > 60 ? t.substring(0, 60) + "..." : t;
    }

    /** A RAPID aggregate value: a number, a word/string, or a bracketed list. */
    record Aggregate(List<Aggregate> items, String atom) {
        static Aggregate parse(String s, int line) {
            int[] pos = {0};
            Aggregate a = parse(s.strip(), pos, line);
            if (pos[0] != s.strip().length()) throw new IllegalArgumentException("line " + line + ": unexpected text after value: '" + clip(s.strip().substring(pos[0])) + "'");
            return a;
        }

        private static Aggregate parse(String s, int[] pos, int line) {
            skip(s, pos);
            if (pos[0] >= s.length()) throw new IllegalArgumentException("line " + line + ": value ends early");
            if (s.charAt(pos[0]) == '[') {
                pos[0]++;
                List<Aggregate> items = new ArrayList<>();
                skip(s, pos);
                if (pos[0] < s.length() && s.charAt(pos[0]) == ']') {
                    pos[0]++;
                    return new Aggregate(items, null);
                }
                while (true) {
                    items.add(parse(s, pos, line));
                    skip(s, pos);
                    if (pos[0] >= s.length()) throw new IllegalArgumentException("line " + line + ": missing ']'");
                    char c = s.charAt(pos[0]++);
                    if (c == ']') return new Aggregate(items, null);
                    if (c != ',') throw new IllegalArgumentException("line " + line + ": expected ',' or ']' in value, got '" + c + "'");
                }
            }
            int st = pos[0];
            if (s.charAt(st) == '"') {
                int e = s.indexOf('"', st + 1);
                if (e < 0) throw new IllegalArgumentException("line " + line + ": unterminated string");
                pos[0] = e + 1;
                return new Aggregate(null, s.substring(st, e + 1));
            }
            while (pos[0] < s.length() && "[],".indexOf(s.charAt(pos[0])) < 0) pos[0]++;
            String atom = s.substring(st, pos[0]).strip();
            if (atom.isEmpty()) throw new IllegalArgumentException("line " + line + ": empty value");
            return new Aggregate(null, atom);
        }

        private static void skip(String s, int[] pos) {
            while (pos[0] < s.length() && Character.isWhitespace(s.charAt(pos[0]))) pos[0]++;
        }

        Aggregate item(int i, int line) {
            if (items == null || i >= items.size())
                throw new IllegalArgumentException("line " + line + ": value has no component " + (i + 1));
            return items.get(i);
        }

        double[] numbers(int n, int line) {
            if (items == null || items.size() != n)
                throw new IllegalArgumentException("line " + line + ": expected " + n + " numbers");
            double[] r = new double[n];
            for (int i = 0; i < n; i++) {
                String a = items.get(i).atom;
                try {
                    r[i] = Double.parseDouble(a);
                    if (!Double.isFinite(r[i])) throw new NumberFormatException();
                } catch (RuntimeException e) {
                    throw new IllegalArgumentException("line " + line + ": '" + a + "' is not a number");
                }
            }
            return r;
        }
    }
}
