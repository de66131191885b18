package org.robopro.programs.project;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import org.robopro.kinematics.ConfData;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Units;
import org.robopro.models.InputException;
import org.robopro.models.RobotLibrary;
import org.robopro.models.Vec3;
import org.robopro.programs.Comment;
import org.robopro.programs.ExtJoints;
import org.robopro.programs.JointTarget;
import org.robopro.programs.LoadData;
import org.robopro.programs.Move;
import org.robopro.programs.ProcCall;
import org.robopro.programs.Quaternion;
import org.robopro.programs.RapidModule;
import org.robopro.programs.RapidPose;
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
 * A program project file ("robopro-program 1", JSON, docs/programs.md): module name, robot,
 * tools, work objects, speeds, zones, targets (typed poses or taught joint values) and
 * procedures. Units at this edge are mm and degrees, as in RAPID.
 */
public final class ProgramProject {
    private ProgramProject() { }

    public static RapidModule read(Path file) {
        try {
            return parse(Files.readString(file), file.toString());
        } catch (IOException e) {
            throw new InputException(file.toString(), 0, 0, null, "cannot read: " + e.getMessage(), e);
        }
    }

    public static RapidModule parse(String text, String file) {
        JsonNode root;
        try {
            root = new ObjectMapper().readTree(text);
        } catch (JsonProcessingException e) {
            int line = e.getLocation() == null ? 0 : e.getLocation().getLineNr();
            int col = e.getLocation() == null ? 0 : e.getLocation().getColumnNr();
            throw new InputException(file, line, col, null, "not JSON: " + e.getOriginalMessage());
        }
        return new Reader(file).module(root);
    }

    private static final class Reader {
        final String file;
        KinematicModel robot;

        Reader(String file) { this.file = file; }

        InputException bad(String field, String problem) { return new InputException(file, 0, 0, field, problem); }

        RapidModule module(JsonNode root) {
            if (root == null || !root.isObject()) throw bad(null, "expected a JSON object");
            if (!"robopro-program".equals(text(root, "format")) || root.path("version").asInt(-1) != 1)
                throw bad("format", "expected \"format\": \"robopro-program\", \"version\": 1");
            RapidModule.Builder b = RapidModule.builder(text(root, "module"));
            if (root.has("robot")) {
                try {
                    robot = KinematicModel.build(RobotLibrary.load(text(root, "robot")));
                } catch (InputException e) {
                    throw e;
                } catch (RuntimeException e) {
                    throw bad("robot", "cannot load robot: " + e.getMessage());
                }
            }
            Map<String, ToolData> tools = new java.util.LinkedHashMap<>();
            Map<String, WObjData> wobjs = new java.util.LinkedHashMap<>();
            for (var e : fields(root, "tools")) {
                JsonNode t = e.getValue();
                String f = "tools." + e.getKey();
                JsonNode load = t.path("load");
                LoadData ld = load.isMissingNode() ? LoadData.LOAD0 : new LoadData(num(load, "mass_kg", f + ".load"),
                        vecMm(load.path("cog_mm"), f + ".load.cog_mm"), Quaternion.IDENTITY, 0, 0, 0);
                ToolData td = new ToolData(t.path("robhold").asBoolean(true), pose(t.path("tframe"), f + ".tframe"), ld);
                tools.put(e.getKey(), td);
                b.pers(e.getKey(), td);
            }
            for (var e : fields(root, "wobjs")) {
                JsonNode w = e.getValue();
                String f = "wobjs." + e.getKey();
                WObjData wd = new WObjData(false, true, "", pose(w.path("uframe"), f + ".uframe"),
                        w.has("oframe") ? pose(w.path("oframe"), f + ".oframe") : RapidPose.IDENTITY);
                wobjs.put(e.getKey(), wd);
                b.pers(e.getKey(), wd);
            }
            for (var e : fields(root, "speeds")) {
                JsonNode s = e.getValue();
                b.var(e.getKey(), SpeedData.ofRapid(num(s, "tcp_mm_s", "speeds." + e.getKey()), s.path("ori_deg_s").asDouble(500), 5000, 1000));
            }
            for (var e : fields(root, "zones")) {
                double r = num(e.getValue(), "tcp_mm", "zones." + e.getKey());
                b.var(e.getKey(), ZoneData.ofRapid(false, r, 1.5 * r, 1.5 * r, 0.15 * r, 1.5 * r, 0.15 * r));
            }
            for (var e : fields(root, "jointtargets"))
                b.constant(e.getKey(), JointTarget.of(Units.degToRad(array(e.getValue().path("joints_deg"), 6, "jointtargets." + e.getKey() + ".joints_deg"))));
            for (var e : fields(root, "targets")) {
                JsonNode t = e.getValue();
                String f = "targets." + e.getKey();
                if (t.has("joints_deg")) {
                    if (robot == null) throw bad(f, "a taught target (joints_deg) needs \"robot\"");
                    double[] q = Units.degToRad(array(t.path("joints_deg"), robot.dof(), f + ".joints_deg"));
                    ToolData tool = tools.getOrDefault(t.path("tool").asText("tool0"), ToolData.TOOL0);
                    WObjData wobj = wobjs.getOrDefault(t.path("wobj").asText("wobj0"), WObjData.WOBJ0);
                    b.constant(e.getKey(), Teach.taught(robot, q, tool, wobj));
                } else {
                    RapidPose p = pose(t, f);
                    double[] cf = t.has("conf") ? array(t.path("conf"), 4, f + ".conf") : new double[4];
                    b.constant(e.getKey(), new RobTarget(p.trans(), p.rot(), new ConfData((int) cf[0], (int) cf[1], (int) cf[2], (int) cf[3]), ExtJoints.NONE));
                }
            }
            for (var e : fields(root, "procedures")) {
                List<Statement> body = new ArrayList<>();
                JsonNode list = e.getValue();
                if (!list.isArray()) throw bad("procedures." + e.getKey(), "expected a list of statements");
                for (int k = 0; k < list.size(); k++) body.add(statement(list.get(k), "procedures." + e.getKey() + "[" + k + "]"));
                b.procedure(e.getKey(), body);
            }
            return b.build();
        }

        Statement statement(JsonNode s, String f) {
            if (s.has("comment")) return new Comment(s.path("comment").asText());
            if (s.has("call")) return new ProcCall(s.path("call").asText());
            if (s.has("wait_s")) return new WaitTime(num(s, "wait_s", f));
            String kind = text(s, "move");
            String tool = s.path("tool").asText("tool0");
            String wobj = s.has("wobj") ? s.path("wobj").asText() : null;
            Ref<SpeedData> speed = Ref.to(s.path("speed").asText("v100"));
            Ref<ZoneData> zone = Ref.to(s.path("zone").asText("fine"));
            try {
                return switch (kind) {
                    case "MoveJ" -> Move.moveJ(Ref.to(text(s, "to")), speed, zone, tool, wobj);
                    case "MoveL" -> Move.moveL(Ref.to(text(s, "to")), speed, zone, tool, wobj);
                    case "MoveC" -> Move.moveC(Ref.to(text(s, "via")), Ref.to(text(s, "to")), speed, zone, tool, wobj);
                    case "MoveAbsJ" -> Move.moveAbsJ(Ref.to(text(s, "to")), speed, zone, tool, wobj);
                    default -> throw bad(f + ".move", "expected MoveJ, MoveL, MoveC or MoveAbsJ, found " + kind);
                };
            } catch (IllegalArgumentException e) {
                throw bad(f, e.getMessage());
            }
        }

        String text(JsonNode n, String k) {
            JsonNode v = n.get(k);
            if (v == null || !v.isTextual() || v.asText().isEmpty()) throw bad(k, "expected a non-empty string");
            return v.asText();
        }

        double num(JsonNode n, String k, String f) {
            JsonNode v = n.get(k);
            if (v == null || !v.isNumber() || !Double.isFinite(v.asDouble())) throw bad(f + "." + k, "expected a number");
            return v.asDouble();
        }

        double[] array(JsonNode n, int len, String f) {
            if (!n.isArray() || n.size() != len) throw bad(f, "expected " + len + " numbers");
            double[] a = new double[len];
            for (int i = 0; i < len; i++) {
                if (!n.get(i).isNumber()) throw bad(f + "[" + i + "]", "expected a number");
                a[i] = n.get(i).asDouble();
            }
            return a;
        }

        Vec3 vecMm(JsonNode n, String f) {
            double[] a = array(n, 3, f);
            return new Vec3(Units.mmToM(a[0]), Units.mmToM(a[1]), Units.mmToM(a[2]));
        }

        RapidPose pose(JsonNode n, String f) {
            Vec3 p = vecMm(n.path("pos_mm"), f + ".pos_mm");
            double[] q = n.has("quat") ? array(n.path("quat"), 4, f + ".quat") : new double[] {1, 0, 0, 0};
            try {
                return new RapidPose(p, new Quaternion(q[0], q[1], q[2], q[3]).normalized());
            } catch (IllegalArgumentException e) {
                throw bad(f + ".quat", e.getMessage());
            }
        }

        Iterable<Map.Entry<String, JsonNode>> fields(JsonNode root, String k) {
            JsonNode n = root.path(k);
            if (n.isMissingNode()) return List.of();
            if (!n.isObject()) throw bad(k, "expected an object of named entries");
            Iterator<Map.Entry<String, JsonNode>> it = n.fields();
            return () -> it;
        }
    }
}
