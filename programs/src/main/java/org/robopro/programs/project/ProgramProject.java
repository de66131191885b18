package org.robopro.programs.project;

import org.robopro.programs.rapid.RapidAst;
import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.core.JsonToken;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.robopro.kinematics.ConfData;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Units;
import org.robopro.models.InputException;
import org.robopro.models.RobotLibrary;
import org.robopro.models.Vec3;
import org.robopro.programs.Comment;
import org.robopro.programs.Declaration;
import org.robopro.programs.ExtJoints;
import org.robopro.programs.JointTarget;
import org.robopro.programs.LoadData;
import org.robopro.programs.ModuleItem;
import org.robopro.programs.Move;
import org.robopro.programs.ProcCall;
import org.robopro.programs.Procedure;
import org.robopro.programs.Quaternion;
import org.robopro.programs.RapidModule;
import org.robopro.programs.RapidPose;
import org.robopro.programs.RapidValue;
import org.robopro.programs.Ref;
import org.robopro.programs.RobTarget;
import org.robopro.programs.SpeedData;
import org.robopro.programs.Statement;
import org.robopro.programs.Teach;
import org.robopro.programs.ToolData;
import org.robopro.programs.WObjData;
import org.robopro.programs.WaitTime;
import org.robopro.programs.ZoneData;

/**
 * Reads program files of the former "robopro-program" format (JSON, docs/programs.md): module
 * name, robot, tools, work objects, speeds, zones, targets (typed poses or taught joint values)
 * and procedures, mm and degrees at this edge. Nothing writes this format any more: the one
 * project format is the workbench's "robopro-project", which opens these files migrated, and
 * {@code robopro program export} still turns them into RAPID. Errors name file, line, column and
 * field.
 */
public final class ProgramProject {
    /** The value of the file's "format" field. */
    public static final String FORMAT = "robopro-program";

    private ProgramProject() { }

    public static RapidModule read(Path file) {
        try {
            return parse(Files.readString(file), file.toString());
        } catch (IOException e) {
            throw new InputException(file.toString(), 0, 0, null, "cannot read: " + e.getMessage(), e);
        }
    }

    public static RapidModule parse(String text, String file) {
        Located tree = Located.read(text, file);
        return new Reader(file, tree.where).module(tree.root);
    }

    /**
     * A JSON tree with where each value was written, keyed by field path as the reader names
     * fields ({@code tools.tTorch.load.mass_kg}, {@code procedures.main[2].to}). Jackson's own
     * tree keeps no locations, so it is built here from the token stream.
     */
    private static final class Located {
        final JsonNode root;
        final Map<String, JsonLocation> where = new HashMap<>();
        private final String file;

        private Located(String file, String text) {
            this.file = file;
            try (JsonParser p = new JsonFactory().createParser(text)) {
                if (p.nextToken() == null) throw new InputException(file, 1, 1, null, "empty file, expected a JSON object");
                root = value(p, "");
                if (p.nextToken() != null)
                    throw new InputException(file, p.currentTokenLocation().getLineNr(), p.currentTokenLocation().getColumnNr(), null,
                            "text after the JSON object");
            } catch (JsonProcessingException e) {
                JsonLocation l = e.getLocation();
                throw new InputException(file, l == null ? 0 : l.getLineNr(), l == null ? 0 : l.getColumnNr(), null,
                        "not JSON: " + e.getOriginalMessage());
            } catch (IOException e) {
                throw new InputException(file, 0, 0, null, "cannot read: " + e.getMessage(), e);
            }
        }

        static Located read(String text, String file) { return new Located(file, text); }

        private JsonNode value(JsonParser p, String path) throws IOException {
            JsonLocation at = p.currentTokenLocation();
            where.putIfAbsent(path, at); // a member keeps its key's location
            JsonNodeFactory nf = JsonNodeFactory.instance;
            switch (p.currentToken()) {
                case START_OBJECT -> {
                    ObjectNode o = nf.objectNode();
                    while (p.nextToken() == JsonToken.FIELD_NAME) {
                        String k = p.currentName();
                        String child = path.isEmpty() ? k : path + "." + k;
                        JsonLocation kl = p.currentTokenLocation();
                        if (o.has(k)) throw new InputException(file, kl.getLineNr(), kl.getColumnNr(), child, "duplicate key \"" + k + "\"");
                        where.put(child, kl);
                        p.nextToken();
                        o.set(k, value(p, child));
                    }
                    return o;
                }
                case START_ARRAY -> {
                    ArrayNode a = nf.arrayNode();
                    for (int k = 0; p.nextToken() != JsonToken.END_ARRAY; k++) a.add(value(p, path + "[" + k + "]"));
                    return a;
                }
                case VALUE_STRING -> { return nf.textNode(p.getText()); }
                case VALUE_NUMBER_INT -> { return nf.numberNode(p.getBigIntegerValue()); }
                case VALUE_NUMBER_FLOAT -> { return nf.numberNode(p.getDoubleValue()); }
                case VALUE_TRUE -> { return nf.booleanNode(true); }
                case VALUE_FALSE -> { return nf.booleanNode(false); }
                case VALUE_NULL -> { return nf.nullNode(); }
                default -> throw new InputException(file, at.getLineNr(), at.getColumnNr(), path, "unexpected " + p.currentToken());
            }
        }
    }

    private static final class Reader {
        final String file;
        final Map<String, JsonLocation> where;
        KinematicModel robot;

        Reader(String file, Map<String, JsonLocation> where) {
            this.file = file;
            this.where = where;
        }

        /** An error at {@code field}; a missing field is reported where its nearest enclosing value was written. */
        InputException bad(String field, String problem) {
            String f = field == null ? "" : field;
            while (!where.containsKey(f) && !f.isEmpty()) {
                int cut = f.endsWith("]") ? f.lastIndexOf('[') : f.lastIndexOf('.');
                f = cut < 0 ? "" : f.substring(0, cut);
            }
            JsonLocation l = where.get(f);
            return new InputException(file, l == null ? 0 : l.getLineNr(), l == null ? 0 : l.getColumnNr(), field, problem);
        }

        RapidModule module(JsonNode root) {
            if (root == null || !root.isObject()) throw bad(null, "expected a JSON object");
            if (!"robopro-program".equals(root.path("format").asText()) || !root.path("version").isIntegralNumber() || root.path("version").asInt() != 1)
                throw bad("format", "expected \"format\": \"robopro-program\", \"version\": 1");
            RapidModule.Builder b = RapidModule.builder(text(root, "module", ""));
            if (root.has("robot")) {
                try {
                    robot = KinematicModel.build(RobotLibrary.load(text(root, "robot", "")));
                } catch (InputException e) {
                    throw e;
                } catch (RuntimeException e) {
                    throw bad("robot", "cannot load robot: " + e.getMessage());
                }
            }
            JsonNode comments = root.path("comments");
            if (!comments.isMissingNode()) {
                if (!comments.isArray()) throw bad("comments", "expected a list of comment lines");
                for (int k = 0; k < comments.size(); k++) b.comment(comment(comments.get(k), "comments[" + k + "]"));
            }
            Map<String, ToolData> tools = new LinkedHashMap<>();
            Map<String, WObjData> wobjs = new LinkedHashMap<>();
            for (var e : fields(root, "tools")) {
                JsonNode t = e.getValue();
                String f = "tools." + e.getKey();
                JsonNode load = t.path("load");
                LoadData ld = LoadData.LOAD0;
                if (!load.isMissingNode()) {
                    double[] inertia = load.has("inertia_kgm2") ? array(load.path("inertia_kgm2"), 3, f + ".load.inertia_kgm2") : new double[3];
                    ld = new LoadData(num(load, "mass_kg", f + ".load"), vecMm(load.path("cog_mm"), f + ".load.cog_mm"),
                            load.has("aom") ? quat(load.path("aom"), f + ".load.aom") : Quaternion.IDENTITY, inertia[0], inertia[1], inertia[2]);
                }
                ToolData td = new ToolData(bool(t, "robhold", f, true), pose(t.path("tframe"), f + ".tframe"), ld);
                tools.put(e.getKey(), td);
                b.declare(declaration(t, f, RapidAst.Storage.PERS, e.getKey(), td));
            }
            for (var e : fields(root, "wobjs")) {
                JsonNode w = e.getValue();
                String f = "wobjs." + e.getKey();
                WObjData wd = new WObjData(bool(w, "robhold", f, false), bool(w, "ufprog", f, true), optText(w, "ufmec", f, ""),
                        pose(w.path("uframe"), f + ".uframe"), w.has("oframe") ? pose(w.path("oframe"), f + ".oframe") : RapidPose.IDENTITY);
                wobjs.put(e.getKey(), wd);
                b.declare(declaration(w, f, RapidAst.Storage.PERS, e.getKey(), wd));
            }
            for (var e : fields(root, "speeds")) {
                JsonNode sp = e.getValue();
                String f = "speeds." + e.getKey();
                SpeedData sd = wrap(f, () -> SpeedData.ofRapid(num(sp, "tcp_mm_s", f), optNum(sp, "ori_deg_s", f, 500),
                        optNum(sp, "leax_mm_s", f, 5000), optNum(sp, "reax_deg_s", f, 1000)));
                b.declare(declaration(sp, f, RapidAst.Storage.VAR, e.getKey(), sd));
            }
            for (var e : fields(root, "zones")) {
                JsonNode z = e.getValue();
                String f = "zones." + e.getKey();
                double r = num(z, "tcp_mm", f);
                // Defaults follow the predefined zones' proportions (z10: 10, 15, 15, 1.5, 15, 1.5).
                ZoneData zd = wrap(f, () -> ZoneData.ofRapid(bool(z, "finep", f, false), r, optNum(z, "ori_mm", f, 1.5 * r),
                        optNum(z, "eax_mm", f, 1.5 * r), optNum(z, "ori_deg", f, 0.15 * r), optNum(z, "leax_mm", f, 1.5 * r),
                        optNum(z, "reax_deg", f, 0.15 * r)));
                b.declare(declaration(z, f, RapidAst.Storage.VAR, e.getKey(), zd));
            }
            for (var e : fields(root, "jointtargets")) {
                JsonNode j = e.getValue();
                String f = "jointtargets." + e.getKey();
                JointTarget jt = JointTarget.of(Units.degToRad(array(j.path("joints_deg"), 6, f + ".joints_deg")), extax(j, f));
                b.declare(declaration(j, f, RapidAst.Storage.CONST, e.getKey(), jt));
            }
            for (var e : fields(root, "targets")) {
                JsonNode t = e.getValue();
                String f = "targets." + e.getKey();
                RobTarget rt;
                if (t.has("joints_deg")) {
                    if (robot == null) throw bad(f + ".joints_deg", "a taught target (joints_deg) needs \"robot\"");
                    double[] q = Units.degToRad(array(t.path("joints_deg"), robot.dof(), f + ".joints_deg"));
                    ToolData tool = tools.getOrDefault(optText(t, "tool", f, "tool0"), ToolData.TOOL0);
                    WObjData wobj = wobjs.getOrDefault(optText(t, "wobj", f, "wobj0"), WObjData.WOBJ0);
                    rt = wrap(f + ".joints_deg", () -> Teach.taught(robot, q, tool, wobj));
                } else {
                    RapidPose p = pose(t, f);
                    double[] cf = t.has("conf") ? array(t.path("conf"), 4, f + ".conf") : new double[4];
                    for (int k = 0; k < 4; k++)
                        if (cf[k] != Math.rint(cf[k]) || Math.abs(cf[k]) > 1e6) throw bad(f + ".conf[" + k + "]", "expected an integer");
                    rt = new RobTarget(p.trans(), p.rot(), new ConfData((int) cf[0], (int) cf[1], (int) cf[2], (int) cf[3]), extax(t, f));
                }
                b.declare(declaration(t, f, RapidAst.Storage.CONST, e.getKey(), rt));
            }
            for (var e : fields(root, "data")) {
                JsonNode d = e.getValue();
                String f = "data." + e.getKey();
                RapidValue v;
                if (d.has("num")) v = new RapidValue.Num(num(d, "num", f));
                else if (d.has("bool")) v = new RapidValue.Bool(bool(d, "bool", f, false));
                else if (d.has("string")) {
                    if (!d.get("string").isTextual()) throw bad(f + ".string", "expected a string");
                    v = wrap(f + ".string", () -> new RapidValue.Str(d.get("string").asText()));
                } else throw bad(f, "expected \"num\", \"bool\" or \"string\"");
                b.declare(declaration(d, f, RapidAst.Storage.CONST, e.getKey(), v));
            }
            List<Procedure> procs = new ArrayList<>();
            for (var e : fields(root, "procedures")) {
                List<Statement> body = new ArrayList<>();
                JsonNode list = e.getValue();
                String f = "procedures." + e.getKey();
                if (!list.isArray()) throw bad(f, "expected a list of statements");
                for (int k = 0; k < list.size(); k++) body.add(statement(list.get(k), f + "[" + k + "]"));
                procs.add(wrap(f, () -> new Procedure(e.getKey(), body)));
            }
            RapidModule head = wrap("module", b::build);
            List<ModuleItem> items = new ArrayList<>(head.items());
            items.addAll(procs);
            return head.withItems(items);
        }

        /** A declaration with the entry's optional "storage" (CONST, PERS, VAR) and "scope" (LOCAL, TASK). */
        Declaration declaration(JsonNode n, String f, RapidAst.Storage usual, String name, RapidValue v) {
            RapidAst.Storage st = usual;
            RapidAst.Scope sc = RapidAst.Scope.GLOBAL;
            try {
                if (n.has("storage")) st = RapidAst.Storage.valueOf(optText(n, "storage", f, ""));
            } catch (IllegalArgumentException e) {
                throw bad(f + ".storage", "expected CONST, PERS or VAR");
            }
            try {
                if (n.has("scope")) sc = RapidAst.Scope.valueOf(optText(n, "scope", f, ""));
            } catch (IllegalArgumentException e) {
                throw bad(f + ".scope", "expected LOCAL or TASK");
            }
            RapidAst.Storage storage = st;
            RapidAst.Scope scope = sc;
            return wrap(f, () -> new Declaration(scope, storage, name, v));
        }

        Statement statement(JsonNode s, String f) {
            if (!s.isObject()) throw bad(f, "expected a statement object");
            if (s.has("comment")) return new Comment(comment(s.get("comment"), f + ".comment"));
            if (s.has("call")) return new ProcCall(text(s, "call", f));
            if (s.has("wait_s")) {
                double w = num(s, "wait_s", f);
                return wrap(f + ".wait_s", () -> new WaitTime(w));
            }
            String kind = text(s, "move", f);
            String tool = optText(s, "tool", f, "tool0");
            String wobj = s.has("wobj") ? text(s, "wobj", f) : null;
            Ref<SpeedData> speed = Ref.to(optText(s, "speed", f, "v100"));
            Ref<ZoneData> zone = Ref.to(optText(s, "zone", f, "fine"));
            Move m = switch (kind) {
                case "MoveJ" -> Move.moveJ(Ref.to(text(s, "to", f)), speed, zone, tool, wobj);
                case "MoveL" -> Move.moveL(Ref.to(text(s, "to", f)), speed, zone, tool, wobj);
                case "MoveC" -> Move.moveC(Ref.to(text(s, "via", f)), Ref.to(text(s, "to", f)), speed, zone, tool, wobj);
                case "MoveAbsJ" -> Move.moveAbsJ(Ref.to(text(s, "to", f)), speed, zone, tool, wobj);
                default -> throw bad(f + ".move", "expected MoveJ, MoveL, MoveC or MoveAbsJ, found " + kind);
            };
            Move base = m;
            return wrap(f, () -> {
                Move out = base.withConc(bool(s, "conc", f, false));
                java.util.OptionalDouble v = s.has("v_mm_s") ? java.util.OptionalDouble.of(Units.mmToM(num(s, "v_mm_s", f))) : java.util.OptionalDouble.empty();
                java.util.OptionalDouble t = s.has("t_s") ? java.util.OptionalDouble.of(num(s, "t_s", f)) : java.util.OptionalDouble.empty();
                out = out.withSpeedOverride(v, t);
                if (s.has("z_mm")) out = out.withZoneOverride(java.util.OptionalDouble.of(Units.mmToM(num(s, "z_mm", f))));
                if (bool(s, "noeoffs", f, false))
                    out = new Move(out.kind(), out.conc(), out.circPoint(), out.toPoint(), true, out.speed(), out.v(), out.t(), out.zone(), out.z(),
                            out.tool(), out.wobj());
                return out;
            });
        }

        /** Model constructors refuse bad values with IllegalArgumentException: name the field. */
        <T> T wrap(String f, java.util.function.Supplier<T> make) {
            try {
                return make.get();
            } catch (IllegalArgumentException e) {
                throw bad(f, e.getMessage());
            }
        }

        String comment(JsonNode n, String f) {
            if (n == null || !n.isTextual() || n.asText().indexOf('\n') >= 0 || n.asText().indexOf('\r') >= 0)
                throw bad(f, "expected one line of text");
            return n.asText();
        }

        String text(JsonNode n, String k, String prefix) {
            String f = prefix.isEmpty() ? k : prefix + "." + k;
            JsonNode v = n.get(k);
            if (v == null || !v.isTextual() || v.asText().isEmpty()) throw bad(f, "expected a non-empty string");
            return v.asText();
        }

        String optText(JsonNode n, String k, String prefix, String dflt) {
            if (!n.has(k)) return dflt;
            JsonNode v = n.get(k);
            if (!v.isTextual() || (v.asText().isEmpty() && !dflt.isEmpty())) throw bad(prefix + "." + k, "expected a non-empty string");
            return v.asText();
        }

        boolean bool(JsonNode n, String k, String prefix, boolean dflt) {
            if (!n.has(k)) return dflt;
            if (!n.get(k).isBoolean()) throw bad(prefix + "." + k, "expected true or false");
            return n.get(k).asBoolean();
        }

        double num(JsonNode n, String k, String f) {
            JsonNode v = n.get(k);
            if (v == null || !v.isNumber() || !Double.isFinite(v.asDouble())) throw bad(f + "." + k, "expected a number");
            return v.asDouble();
        }

        double optNum(JsonNode n, String k, String f, double dflt) { return n.has(k) ? num(n, k, f) : dflt; }

        double[] array(JsonNode n, int len, String f) {
            if (!n.isArray() || n.size() != len) throw bad(f, "expected " + len + " numbers");
            double[] a = new double[len];
            for (int i = 0; i < len; i++) {
                if (!n.get(i).isNumber() || !Double.isFinite(n.get(i).asDouble())) throw bad(f + "[" + i + "]", "expected a number");
                a[i] = n.get(i).asDouble();
            }
            return a;
        }

        ExtJoints extax(JsonNode n, String f) {
            return n.has("extax") ? ExtJoints.of(array(n.path("extax"), 6, f + ".extax")) : ExtJoints.NONE;
        }

        Vec3 vecMm(JsonNode n, String f) {
            double[] a = array(n, 3, f);
            return new Vec3(Units.mmToM(a[0]), Units.mmToM(a[1]), Units.mmToM(a[2]));
        }

        /** A quaternion as written when already unit (to 1e-12), else normalised. */
        Quaternion quat(JsonNode n, String f) {
            double[] q = array(n, 4, f);
            Quaternion r = new Quaternion(q[0], q[1], q[2], q[3]);
            if (Math.abs(r.norm() - 1) <= 1e-12) return r;
            Quaternion u = wrap(f, r::normalized);
            // components near the double range overflow the norm: no usable direction
            if (!(Math.abs(u.norm() - 1) <= 1e-12)) throw bad(f, "quaternion " + r + " cannot be normalised");
            return u;
        }

        RapidPose pose(JsonNode n, String f) {
            Vec3 p = vecMm(n.path("pos_mm"), f + ".pos_mm");
            return new RapidPose(p, n.has("quat") ? quat(n.path("quat"), f + ".quat") : Quaternion.IDENTITY);
        }

        Iterable<Map.Entry<String, JsonNode>> fields(JsonNode root, String k) {
            JsonNode n = root.path(k);
            if (n.isMissingNode()) return List.of();
            if (!n.isObject()) throw bad(k, "expected an object of named entries");
            for (Iterator<Map.Entry<String, JsonNode>> it = n.fields(); it.hasNext(); ) {
                var e = it.next();
                if (!e.getValue().isObject() && !k.equals("procedures")) throw bad(k + "." + e.getKey(), "expected an object");
            }
            return () -> n.fields();
        }
    }
}
