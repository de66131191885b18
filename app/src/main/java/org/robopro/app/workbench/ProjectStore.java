package org.robopro.app.workbench;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.core.JsonToken;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Supplier;
import javax.swing.Timer;
import org.robopro.app.workbench.model.CellObject;
import org.robopro.app.workbench.model.Instruction;
import org.robopro.app.workbench.model.ProjectData;
import org.robopro.app.workbench.model.Robots;
import org.robopro.app.workbench.model.Target;
import org.robopro.app.workbench.model.Tool;
import org.robopro.app.workbench.model.WorkObject;
import org.robopro.app.workbench.model.WorkbenchModel;
import org.robopro.kinematics.ConfData;
import org.robopro.kinematics.Pose;
import org.robopro.kinematics.Units;
import org.robopro.models.AtomicFiles;
import org.robopro.models.InputException;
import org.robopro.models.RobotDescription;
import org.robopro.models.Vec3;

/**
 * Reads and writes workbench project files (docs/project-file.md): JSON, mm and degrees /
 * quaternions at the edge, written atomically. A damaged file is reported with its line, column
 * and the JSON path of the bad field, and nothing half-read is returned.
 */
public final class ProjectStore {
    public static final String FORMAT = "robopro-project";
    public static final int VERSION = 1;
    private static final ObjectMapper JSON = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);

    private ProjectStore() { }

    // ---- writing -----------------------------------------------------------------------------

    public static String toJson(ProjectData p) {
        ObjectNode root = JSON.createObjectNode();
        root.put("format", FORMAT);
        root.put("version", VERSION);
        ObjectNode robot = root.putObject("robot");
        robot.put("ref", p.robotRef());
        robot.set("placement", pose(p.worldTbase()));
        ObjectNode tool = root.putObject("tool");
        tool.put("name", p.tool().name());
        tool.set("tcp", pose(p.tool().flangeTtcp()));
        tool.put("body_radius_mm", round(Units.mToMm(p.tool().bodyRadius()), 1e-6));
        tool.put("body_length_mm", round(Units.mToMm(p.tool().bodyLength()), 1e-6));
        tool.put("mass_kg", p.tool().massKg());
        ArrayNode objs = root.putArray("objects");
        for (CellObject o : p.objects()) {
            ObjectNode n = objs.addObject();
            n.put("id", o.id());
            n.put("name", o.name());
            n.put("kind", o.kind().name().toLowerCase(Locale.ROOT));
            n.set("pose", pose(o.worldTobject()));
            if (o.meshPath() != null) {
                n.put("mesh", o.meshPath());
                n.put("mesh_scale", o.size().x());
            } else {
                ArrayNode s = n.putArray("size_mm");
                s.add(round(Units.mToMm(o.size().x()), 1e-6)).add(round(Units.mToMm(o.size().y()), 1e-6)).add(round(Units.mToMm(o.size().z()), 1e-6));
            }
            n.put("color", String.format(Locale.ROOT, "#%06X", o.rgb()));
        }
        ArrayNode wobjs = root.putArray("work_objects");
        for (WorkObject w : p.workObjects()) {
            ObjectNode n = wobjs.addObject();
            n.put("name", w.name());
            n.set("user_frame", pose(w.worldTuser()));
        }
        ArrayNode targets = root.putArray("targets");
        for (Target t : p.targets()) {
            ObjectNode n = targets.addObject();
            n.put("name", t.name());
            n.set("pose", pose(t.worldTtcp()));
            ArrayNode j = n.putArray("joints_deg");
            for (double v : t.qTaught()) j.add(round(Math.toDegrees(v), 1e-6));
            ArrayNode c = n.putArray("conf");
            c.add(t.conf().cf1()).add(t.conf().cf4()).add(t.conf().cf6()).add(t.conf().cfx());
        }
        ArrayNode programs = root.putArray("programs");
        ObjectNode main = programs.addObject();
        main.put("name", "main");
        ArrayNode ins = main.putArray("instructions");
        for (Instruction i : p.program()) {
            ObjectNode n = ins.addObject();
            n.put("type", i.type().rapid());
            n.put("target", i.target());
            n.put("speed_mm_s", i.speedMmPerS());
            n.put("zone_mm", i.zoneMm());
        }
        ObjectNode cal = root.putObject("calibration");
        if (p.calibrationReference() == null) cal.putNull("reference"); else cal.put("reference", p.calibrationReference());
        try {
            return JSON.writeValueAsString(root) + "\n";
        } catch (JsonProcessingException e) {
            throw new IllegalStateException(e);
        }
    }

    private static double round(double v, double step) { return Math.round(v / step) * step; }

    private static ObjectNode pose(Pose p) {
        ObjectNode n = JSON.createObjectNode();
        n.putArray("position_mm").add(round(Units.mToMm(p.x()), 1e-6)).add(round(Units.mToMm(p.y()), 1e-6))
                .add(round(Units.mToMm(p.z()), 1e-6));
        double[] q = p.quaternion();
        n.putArray("quaternion").add(round(q[0], 1e-12)).add(round(q[1], 1e-12)).add(round(q[2], 1e-12)).add(round(q[3], 1e-12));
        return n;
    }

    public static void write(ProjectData p, Path file, boolean overwrite) throws IOException {
        AtomicFiles.writeString(file, toJson(p), overwrite);
    }

    // ---- reading -----------------------------------------------------------------------------

    public static ProjectData read(Path file) throws IOException {
        String text;
        try {
            text = Files.readString(file, StandardCharsets.UTF_8);
        } catch (NoSuchFileException e) {
            throw new InputException(file.toString(), 0, 0, "", "no such project file");
        }
        return parse(text, file.toString(), file.toAbsolutePath().getParent());
    }

    /** Parses project JSON; {@code baseDir} resolves a robot file given by relative path. */
    public static ProjectData parse(String text, String fileName, Path baseDir) {
        Located doc = Located.parse(text, fileName);
        return new Reader(doc, fileName, baseDir).project();
    }

    /** A JSON tree plus where each value started (by JSON pointer), for error messages. */
    record Located(JsonNode root, Map<String, JsonLocation> where) {
        static Located parse(String text, String file) {
            try (JsonParser p = new JsonFactory().createParser(text)) {
                Map<String, JsonLocation> where = new HashMap<>();
                JsonToken t = p.nextToken();
                if (t == null) throw new InputException(file, 1, 1, "", "empty file");
                JsonNode root = value(p, "", where);
                if (p.nextToken() != null)
                    throw new InputException(file, p.currentLocation().getLineNr(), p.currentLocation().getColumnNr(), "",
                            "unexpected content after the project object");
                return new Located(root, where);
            } catch (JsonProcessingException e) {
                JsonLocation l = e.getLocation();
                throw new InputException(file, l == null ? 0 : l.getLineNr(), l == null ? 0 : l.getColumnNr(), "",
                        "not valid JSON: " + e.getOriginalMessage(), e);
            } catch (IOException e) {
                throw new InputException(file, 0, 0, "", "cannot read: " + e.getMessage(), e);
            }
        }

        private static JsonNode value(JsonParser p, String ptr, Map<String, JsonLocation> where) throws IOException {
            where.put(ptr, p.currentTokenLocation());
            JsonNodeFactory f = JsonNodeFactory.instance;
            switch (p.currentToken()) {
                case START_OBJECT -> {
                    ObjectNode o = f.objectNode();
                    while (p.nextToken() == JsonToken.FIELD_NAME) {
                        String name = p.currentName();
                        p.nextToken();
                        o.set(name, value(p, ptr + "/" + name, where));
                    }
                    return o;
                }
                case START_ARRAY -> {
                    ArrayNode a = f.arrayNode();
                    int i = 0;
                    while (p.nextToken() != JsonToken.END_ARRAY) a.add(value(p, ptr + "/" + i++, where));
                    return a;
                }
                case VALUE_STRING -> { return f.textNode(p.getText()); }
                case VALUE_NUMBER_INT, VALUE_NUMBER_FLOAT -> { return f.numberNode(p.getDoubleValue()); }
                case VALUE_TRUE, VALUE_FALSE -> { return f.booleanNode(p.getBooleanValue()); }
                case VALUE_NULL -> { return f.nullNode(); }
                default -> throw new IOException("unexpected token " + p.currentToken());
            }
        }
    }

    private static final class Reader {
        private final Located doc;
        private final String file;
        private final Path baseDir;

        Reader(Located doc, String file, Path baseDir) {
            this.doc = doc;
            this.file = file;
            this.baseDir = baseDir;
        }

        InputException bad(String ptr, String problem) {
            String p = ptr;
            JsonLocation l = doc.where().get(p);
            while (l == null && p.contains("/")) {
                p = p.substring(0, p.lastIndexOf('/'));
                l = doc.where().get(p);
            }
            return new InputException(file, l == null ? 0 : l.getLineNr(), l == null ? 0 : l.getColumnNr(),
                    ptr.isEmpty() ? "" : ptr.substring(1).replace('/', '.'), problem);
        }

        JsonNode at(String ptr) { return doc.root().at(ptr.isEmpty() ? "" : ptr); }

        JsonNode need(String ptr) {
            JsonNode n = at(ptr);
            if (n.isMissingNode() || n.isNull()) throw bad(ptr, "missing");
            return n;
        }

        String text(String ptr) {
            JsonNode n = need(ptr);
            if (!n.isTextual() || n.asText().isBlank()) throw bad(ptr, "expected a non-empty string");
            return n.asText();
        }

        double number(String ptr) {
            JsonNode n = need(ptr);
            if (!n.isNumber() || !Double.isFinite(n.asDouble())) throw bad(ptr, "expected a number");
            return n.asDouble();
        }

        double positive(String ptr) {
            double v = number(ptr);
            if (!(v > 0)) throw bad(ptr, "must be > 0, got " + v);
            return v;
        }

        double[] numbers(String ptr, int count) {
            JsonNode n = need(ptr);
            if (!n.isArray() || (count > 0 && n.size() != count))
                throw bad(ptr, "expected an array of " + (count > 0 ? count + " " : "") + "numbers");
            double[] out = new double[n.size()];
            for (int i = 0; i < out.length; i++) out[i] = number(ptr + "/" + i);
            return out;
        }

        Pose pose(String ptr) {
            double[] p = numbers(ptr + "/position_mm", 3);
            double[] q = numbers(ptr + "/quaternion", 4);
            try {
                return Pose.fromQuaternion(q[0], q[1], q[2], q[3], Units.mmToM(p[0]), Units.mmToM(p[1]), Units.mmToM(p[2]));
            } catch (IllegalArgumentException e) {
                throw bad(ptr + "/quaternion", e.getMessage());
            }
        }

        int size(String ptr) {
            JsonNode n = at(ptr);
            if (n.isMissingNode() || n.isNull()) return 0;
            if (!n.isArray()) throw bad(ptr, "expected an array");
            return n.size();
        }

        ProjectData project() {
            if (!doc.root().isObject()) throw bad("", "a project file holds one JSON object");
            if (!FORMAT.equals(at("/format").asText(null))) throw bad("/format", "expected \"" + FORMAT + "\"");
            double v = number("/version");
            if (v != VERSION) throw bad("/version", "this robopro reads version " + VERSION + ", the file is version " + v);
            String ref = text("/robot/ref");
            RobotDescription robot;
            try {
                boolean isPath = ref.contains("/") || ref.contains("\\") || ref.endsWith(".json");
                robot = Robots.load(isPath && baseDir != null ? baseDir.resolve(ref).toString() : ref);
            } catch (InputException e) {
                throw e;
            } catch (RuntimeException e) {
                throw bad("/robot/ref", "cannot load robot: " + e.getMessage());
            }
            Pose placement = at("/robot/placement").isMissingNode() ? Pose.IDENTITY : pose("/robot/placement");
            Tool tool = new Tool(text("/tool/name"), pose("/tool/tcp"), Units.mmToM(positive("/tool/body_radius_mm")),
                    Units.mmToM(number("/tool/body_length_mm")), positive("/tool/mass_kg"));
            List<CellObject> objects = new ArrayList<>();
            List<String> ids = new ArrayList<>();
            for (int i = 0; i < size("/objects"); i++) {
                String p = "/objects/" + i;
                String id = text(p + "/id");
                if (ids.contains(id)) throw bad(p + "/id", "duplicate object id " + id);
                ids.add(id);
                CellObject.Kind kind;
                try {
                    kind = CellObject.Kind.valueOf(text(p + "/kind").toUpperCase(Locale.ROOT));
                } catch (IllegalArgumentException e) {
                    throw bad(p + "/kind", "expected table, fixture, part or mesh");
                }
                String mesh = at(p + "/mesh").isTextual() ? at(p + "/mesh").asText() : null;
                Vec3 size;
                if (mesh != null) {
                    double s = at(p + "/mesh_scale").isMissingNode() ? 1 : positive(p + "/mesh_scale");
                    size = new Vec3(s, s, s);
                } else {
                    double[] s = numbers(p + "/size_mm", 3);
                    for (int k = 0; k < 3; k++) if (!(s[k] > 0)) throw bad(p + "/size_mm/" + k, "must be > 0");
                    size = new Vec3(Units.mmToM(s[0]), Units.mmToM(s[1]), Units.mmToM(s[2]));
                }
                int rgb = 0x9AA5B1;
                if (!at(p + "/color").isMissingNode()) {
                    String c = text(p + "/color");
                    if (!c.matches("#[0-9A-Fa-f]{6}")) throw bad(p + "/color", "expected #RRGGBB");
                    rgb = Integer.parseInt(c.substring(1), 16);
                }
                String name = at(p + "/name").isTextual() ? at(p + "/name").asText() : id;
                objects.add(new CellObject(id, name, kind, pose(p + "/pose"), size, mesh, rgb));
            }
            List<WorkObject> wobjs = new ArrayList<>();
            for (int i = 0; i < size("/work_objects"); i++)
                wobjs.add(new WorkObject(text("/work_objects/" + i + "/name"), pose("/work_objects/" + i + "/user_frame")));
            List<Target> targets = new ArrayList<>();
            for (int i = 0; i < size("/targets"); i++) {
                String p = "/targets/" + i;
                String name = text(p + "/name");
                if (!name.matches("[A-Za-z][A-Za-z0-9_]{0,31}")) throw bad(p + "/name", "not a RAPID identifier: " + name);
                if (targets.stream().anyMatch(t -> t.name().equals(name))) throw bad(p + "/name", "duplicate target " + name);
                double[] qd = numbers(p + "/joints_deg", robot.dof());
                double[] c = numbers(p + "/conf", 4);
                targets.add(new Target(name, pose(p + "/pose"), Units.degToRad(qd),
                        new ConfData((int) c[0], (int) c[1], (int) c[2], (int) c[3])));
            }
            List<Instruction> program = new ArrayList<>();
            if (size("/programs") > 0) {
                for (int i = 0; i < size("/programs/0/instructions"); i++) {
                    String p = "/programs/0/instructions/" + i;
                    String type = text(p + "/type");
                    Instruction.Type t = switch (type.toLowerCase(Locale.ROOT)) {
                        case "movej" -> Instruction.Type.MOVEJ;
                        case "movel" -> Instruction.Type.MOVEL;
                        default -> throw bad(p + "/type", "expected MoveJ or MoveL, got " + type);
                    };
                    String target = text(p + "/target");
                    if (targets.stream().noneMatch(x -> x.name().equals(target)))
                        throw bad(p + "/target", "no target named " + target);
                    double zone = number(p + "/zone_mm");
                    if (zone < 0) throw bad(p + "/zone_mm", "must be >= 0");
                    program.add(new Instruction(t, target, positive(p + "/speed_mm_s"), zone));
                }
            }
            JsonNode cal = at("/calibration/reference");
            String calRef = cal.isTextual() ? cal.asText() : null;
            return new ProjectData(ref, robot, placement, tool, objects, wobjs, targets, program, calRef);
        }
    }

    // ---- autosave and recovery ---------------------------------------------------------------

    /** PROJECT.autosave next to a project; for an unsaved cell, untitled.robopro.json.autosave in ~/.robopro (or -Drobopro.autosaveDir). */
    public static Path autosavePath(Path project) {
        if (project != null) return project.resolveSibling(project.getFileName() + ".autosave");
        String dir = System.getProperty("robopro.autosaveDir", System.getProperty("user.home") + "/.robopro");
        return Path.of(dir, "untitled.robopro.json.autosave");
    }

    /** An autosave newer than its project (left by a crash), if any. */
    public static java.util.Optional<Path> recoverable(Path project) throws IOException {
        Path a = autosavePath(project);
        if (!Files.exists(a)) return java.util.Optional.empty();
        if (project != null && Files.exists(project)
                && Files.getLastModifiedTime(a).compareTo(Files.getLastModifiedTime(project)) <= 0)
            return java.util.Optional.empty();
        return java.util.Optional.of(a);
    }

    public static void deleteAutosave(Path project) throws IOException { Files.deleteIfExists(autosavePath(project)); }

    /** Writes the model to its autosave file every period while it has unsaved changes. */
    public static final class Autosave {
        private final Supplier<Path> target;
        private final WorkbenchModel model;
        private final Timer timer;

        public Autosave(Supplier<Path> target, WorkbenchModel model, int periodMs) {
            this.target = target;
            this.model = model;
            this.timer = new Timer(periodMs, e -> saveNow());
        }

        public void start() { timer.start(); }
        public void stop() { timer.stop(); }

        /** Writes now if there are unsaved changes; returns whether it wrote. */
        public boolean saveNow() {
            if (!model.dirty()) return false;
            try {
                AtomicFiles.writeString(target.get(), toJson(model.snapshot()), true);
                return true;
            } catch (IOException | RuntimeException e) {
                java.util.logging.Logger.getLogger(Autosave.class.getName()).warning("autosave failed: " + e.getMessage());
                return false;
            }
        }
    }
}
