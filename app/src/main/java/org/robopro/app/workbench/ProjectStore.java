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
import org.robopro.app.workbench.model.Target;
import org.robopro.app.workbench.model.Tool;
import org.robopro.app.workbench.model.WorkObject;
import org.robopro.app.workbench.model.WorkbenchModel;
import org.robopro.kinematics.ConfData;
import org.robopro.kinematics.Pose;
import org.robopro.kinematics.Units;
import org.robopro.app.workbench.model.DefaultCell;
import org.robopro.models.AtomicFiles;
import org.robopro.models.CellDescription;
import org.robopro.models.CellFile;
import org.robopro.models.LocatedJson;
import org.robopro.models.PoseDescription;
import org.robopro.models.Rgba;
import org.robopro.models.ToolDescription;
import org.robopro.models.WorkObjectDescription;
import org.robopro.models.InputException;
import org.robopro.models.RobotDescription;
import org.robopro.models.Vec3;
import org.robopro.models.RobotLibrary;
import org.robopro.programs.project.ProgramProject;

/**
 * Reads and writes workbench project files (docs/project-file.md): JSON, mm and degrees /
 * quaternions at the edge, written atomically. A damaged file is reported with its line, column
 * and the JSON path of the bad field, and nothing half-read is returned.
 */
public final class ProjectStore {
    public static final String FORMAT = "robopro-project";
    /** Version written: 2 embeds the cell-file structure; version 1 files (own object section) are still read. */
    public static final int VERSION = 2;
    private static final ObjectMapper JSON = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);

    private ProjectStore() { }

    // ---- writing -----------------------------------------------------------------------------

    public static String toJson(ProjectData p) {
        ObjectNode root = JSON.createObjectNode();
        root.put("format", FORMAT);
        root.put("version", VERSION);
        try {
            root.set("cell", JSON.readTree(CellFile.format(toCell(p))));
        } catch (JsonProcessingException e) {
            throw new IllegalStateException("cell file writer gave invalid JSON", e);
        }
        ObjectNode tool = root.putObject("mounted_tool");
        tool.put("name", p.tool().name());
        tool.put("body_radius_mm", round(Units.mToMm(p.tool().bodyRadius()), 1e-6));
        tool.put("body_length_mm", round(Units.mToMm(p.tool().bodyLength()), 1e-6));
        ObjectNode extra = root.putObject("workbench_objects");
        for (CellObject o : p.objects()) {
            ObjectNode n = extra.putObject(o.id());
            n.put("label", o.name());
            n.put("kind", o.kind().name().toLowerCase(Locale.ROOT));
        }
        ArrayNode targets = root.putArray("targets");
        for (Target t : p.targets()) {
            ObjectNode n = targets.addObject();
            n.put("name", t.name());
            n.set("pose", pose(t.worldTtcp()));
            ArrayNode j = n.putArray("joints_deg");
            for (double v : t.qTaught()) j.add(Math.toDegrees(v)); // unrounded: the target reopens at the joints it was taught at
            ArrayNode c = n.putArray("conf");
            c.add(t.conf().cf1()).add(t.conf().cf4()).add(t.conf().cf6()).add(t.conf().cfx());
            if (!t.wobj().equals(Target.WOBJ0)) n.put("wobj", t.wobj());
        }
        ArrayNode programs = root.putArray("programs");
        ObjectNode main = programs.addObject();
        main.put("name", "main");
        // An imported program keeps its module: the RAPID text, and per line the statement of the
        // entry procedure it stands for (by index).
        List<org.robopro.programs.rapid.RapidAst.Stmt> entryBody = List.of();
        if (p.source() != null) {
            main.put("name", p.source().entry());
            main.put("rapid_module", org.robopro.programs.rapid.RapidAstWriter.write(p.source().module().tree()));
            entryBody = entryBody(p.source());
        }
        ArrayNode ins = main.putArray("instructions");
        for (Instruction i : p.program()) {
            ObjectNode n = ins.addObject();
            n.put("type", i.type().rapid());
            int at = indexOf(entryBody, i.statement());
            if (at >= 0) n.put("statement", at);
            if (!i.type().motion()) continue;
            n.put("target", i.target());
            if (i.via() != null) n.put("via", i.via());
            n.put("speed_mm_s", i.speedMmPerS());
            n.put("zone_mm", i.zoneMm());
        }
        ObjectNode cal = root.putObject("calibration");
        if (p.calibrationReference() == null) cal.putNull("reference"); else cal.put("reference", p.calibrationReference());
        ObjectNode state = root.putObject("workbench_state");
        state.put("teach_in_wobj", p.activeWorkObject());
        if (p.q() != null) {
            ArrayNode j = state.putArray("joints_deg");
            for (double v : p.q()) j.add(Math.toDegrees(v));
        }
        try {
            return JSON.writeValueAsString(root) + "\n";
        } catch (JsonProcessingException e) {
            throw new IllegalStateException(e);
        }
    }

    /**
     * The cell part of a project as a cell file describes it (docs/cell-file.md): boxes and
     * cylinders placed by their centre (the workbench places them by their underside), object
     * names are the workbench ids, the mounted tool is the cell's one tool.
     */
    public static CellDescription toCell(ProjectData p) {
        List<org.robopro.models.CellObject> objects = new ArrayList<>();
        for (CellObject o : p.objects()) {
            Rgba colour = new Rgba(((o.rgb() >> 16) & 255) / 255.0, ((o.rgb() >> 8) & 255) / 255.0, (o.rgb() & 255) / 255.0, 1);
            if (o.meshPath() != null) {
                objects.add(new org.robopro.models.CellObject(o.id(), org.robopro.models.CellObject.Kind.MESH, desc(o.worldTobject()),
                        Vec3.ZERO, colour, o.meshPath(), o.size().x()));
            } else {
                Pose centre = o.worldTobject().times(Pose.translation(0, 0, o.size().z() / 2));
                var kind = o.kind() == CellObject.Kind.CYLINDER ? org.robopro.models.CellObject.Kind.CYLINDER : org.robopro.models.CellObject.Kind.BOX;
                objects.add(new org.robopro.models.CellObject(o.id(), kind, desc(centre), o.size(), colour, "", 1));
            }
        }
        Tool t = p.tool();
        List<ToolDescription> tools = List.of(new ToolDescription(t.name(), desc(t.flangeTtcp()), t.massKg(), new Vec3(0, 0, round(t.bodyLength() / 2, 1e-9))));
        List<WorkObjectDescription> wobjs = new ArrayList<>();
        for (WorkObject w : p.workObjects()) wobjs.add(new WorkObjectDescription(w.name(), desc(w.worldTuser())));
        return new CellDescription("workbench_cell", p.robotRef(), desc(p.worldTbase()), objects, tools, wobjs);
    }

    private static PoseDescription desc(Pose p) {
        double[] q = p.quaternion();
        return new PoseDescription(p.position(), q[0], q[1], q[2], q[3]);
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

    /** Whether {@code text} is a program file of the former "robopro-program" format (bad JSON: InputException). */
    public static boolean isProgramFile(String text, String fileName) {
        return ProgramProject.FORMAT.equals(Located.parse(text, fileName).root().path("format").asText(null));
    }

    /** Parses project JSON; {@code baseDir} resolves a robot file given by relative path. */
    public static ProjectData parse(String text, String fileName, Path baseDir) {
        Located doc = Located.parse(text, fileName);
        if (ProgramProject.FORMAT.equals(doc.root().path("format").asText(null))) return migrated(text, fileName, doc.root());
        return new Reader(doc, fileName, baseDir, text).project();
    }

    /**
     * A program file of the former "robopro-program" format (docs/programs.md), migrated on read:
     * the shipped welding cell (or, when the file names another robot, that robot alone) with the
     * file's tool, work objects, targets and {@code main} imported as a RAPID module is
     * (ProgramModule.fromRapid). Saving writes it as a project.
     */
    private static ProjectData migrated(String text, String fileName, JsonNode root) {
        // The module as a RAPID file holds it (the file's precision), so an export writes it as read.
        org.robopro.programs.RapidModule module = org.robopro.programs.RapidParser.parse(
                org.robopro.programs.RapidWriter.export(ProgramProject.parse(text, fileName)).text(), fileName);
        String robotName = root.path("robot").asText("irb2000");
        ProjectData cell = DefaultCell.irb2000Welding();
        if (!robotName.equalsIgnoreCase(cell.robotRef())) {
            RobotDescription robot;
            try {
                robot = RobotLibrary.load(robotName);
            } catch (RuntimeException e) {
                throw new InputException(fileName, 0, 0, "robot", "cannot load robot: " + e.getMessage(), e);
            }
            cell = new ProjectData(robotName, robot, Pose.IDENTITY, cell.tool(), List.of(), List.of(), List.of(), List.of(), null);
        }
        WorkbenchModel model = new WorkbenchModel(cell.robotRef(), cell.robot());
        model.load(cell);
        model.replaceProgram(org.robopro.app.workbench.model.ProgramModule.fromRapid(module, model, "main"));
        return model.snapshot();
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
        private final String text;

        Reader(Located doc, String file, Path baseDir, String text) {
            this.doc = doc;
            this.file = file;
            this.baseDir = baseDir;
            this.text = text;
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
            if (v != 1 && v != VERSION) throw bad("/version", "this robopro reads versions 1 and " + VERSION + ", the file is version " + v);
            ProjectData cellPart = v == 1 ? cellV1() : cellV2();
            List<WorkObject> wobjs = cellPart.workObjects();
            RobotDescription robot = cellPart.robot();
            return rest(cellPart.robotRef(), robot, cellPart.worldTbase(), cellPart.tool(), cellPart.objects(), wobjs);
        }

        /** Version 2: the embedded cell file (read by the models module's cell reader) plus the workbench's extras. */
        ProjectData cellV2() {
            LocatedJson.Node root = LocatedJson.parse(file, text);
            if (!root.has("cell")) throw bad("/cell", "missing");
            CellDescription cell = CellFile.fromTree(root.get("cell"));
            ProjectData d;
            try {
                d = DefaultCell.fromCell(cell, baseDir == null ? null : baseDir.resolve("project.robopro.json"));
            } catch (InputException e) {
                throw e;
            } catch (RuntimeException e) {
                throw bad("/cell/robot/ref", "cannot load robot: " + e.getMessage());
            }
            if (cell.tools().size() > 1) throw bad("/cell/tools", "a project mounts one tool; the cell lists " + cell.tools().size());
            Tool tool = d.tool();
            if (!at("/mounted_tool").isMissingNode()) {
                String name = text("/mounted_tool/name");
                if (!name.equals(tool.name())) throw bad("/mounted_tool/name", "no tool " + name + " in the cell");
                tool = new Tool(tool.name(), tool.flangeTtcp(), Units.mmToM(positive("/mounted_tool/body_radius_mm")),
                        Units.mmToM(number("/mounted_tool/body_length_mm")), tool.massKg());
            }
            List<CellObject> objects = new ArrayList<>();
            for (CellObject o : d.objects()) {
                String p = "/workbench_objects/" + o.id();
                if (at(p).isMissingNode()) { objects.add(o); continue; }
                CellObject.Kind kind = o.kind();
                if (!at(p + "/kind").isMissingNode()) {
                    try {
                        kind = CellObject.Kind.valueOf(text(p + "/kind").toUpperCase(Locale.ROOT));
                    } catch (IllegalArgumentException e) {
                        throw bad(p + "/kind", "expected table, fixture, part, cylinder or mesh");
                    }
                    if ((kind == CellObject.Kind.MESH) != (o.kind() == CellObject.Kind.MESH))
                        throw bad(p + "/kind", "does not match the cell object's kind");
                }
                String label = at(p + "/label").isTextual() ? at(p + "/label").asText() : o.name();
                objects.add(new CellObject(o.id(), label, kind, o.worldTobject(), o.size(), o.meshPath(), o.rgb()));
            }
            return new ProjectData(cell.robot(), d.robot(), d.worldTbase(), tool, objects, d.workObjects(), List.of(), List.of(), null);
        }

        /** Version 1: the project's own robot, tool and object sections. */
        ProjectData cellV1() {
            String ref = text("/robot/ref");
            RobotDescription robot;
            try {
                boolean isPath = ref.contains("/") || ref.contains("\\") || ref.endsWith(".json");
                robot = RobotLibrary.load(isPath && baseDir != null ? baseDir.resolve(ref).toString() : ref);
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
            return new ProjectData(ref, robot, placement, tool, objects, wobjs, List.of(), List.of(), null);
        }

        /** Targets, programs and the calibration reference (the same in versions 1 and 2). */
        ProjectData rest(String ref, RobotDescription robot, Pose placement, Tool tool, List<CellObject> objects, List<WorkObject> wobjs) {
            List<Target> targets = new ArrayList<>();
            for (int i = 0; i < size("/targets"); i++) {
                String p = "/targets/" + i;
                String name = text(p + "/name");
                if (!name.matches("[A-Za-z][A-Za-z0-9_]{0,31}")) throw bad(p + "/name", "not a RAPID identifier: " + name);
                if (targets.stream().anyMatch(t -> t.name().equals(name))) throw bad(p + "/name", "duplicate target " + name);
                double[] qd = numbers(p + "/joints_deg", robot.dof());
                double[] c = numbers(p + "/conf", 4);
                String wobj = Target.WOBJ0;
                if (!at(p + "/wobj").isMissingNode()) {
                    wobj = text(p + "/wobj");
                    String w = wobj;
                    if (!w.equals(Target.WOBJ0) && wobjs.stream().noneMatch(x -> x.name().equals(w)))
                        throw bad(p + "/wobj", "no work object named " + w);
                }
                targets.add(new Target(name, pose(p + "/pose"), Units.degToRad(qd),
                        new ConfData((int) c[0], (int) c[1], (int) c[2], (int) c[3]), wobj));
            }
            List<Instruction> program = new ArrayList<>();
            org.robopro.app.workbench.model.ProgramModule.Source source = null;
            List<org.robopro.programs.rapid.RapidAst.Stmt> entryBody = List.of();
            if (size("/programs") > 0 && !at("/programs/0/rapid_module").isMissingNode()) {
                String entry = text("/programs/0/name");
                String rapid = text("/programs/0/rapid_module");
                org.robopro.programs.RapidModule module;
                try {
                    module = org.robopro.programs.RapidParser.parse(rapid, file + " programs.0.rapid_module");
                } catch (InputException e) {
                    throw bad("/programs/0/rapid_module", e.getMessage());
                }
                source = new org.robopro.app.workbench.model.ProgramModule.Source(module, entry);
                if (module.procedure(entry).isEmpty()) throw bad("/programs/0/name", "the module has no procedure " + entry);
                entryBody = entryBody(source);
            }
            if (size("/programs") > 0) {
                for (int i = 0; i < size("/programs/0/instructions"); i++) {
                    String p = "/programs/0/instructions/" + i;
                    String type = text(p + "/type");
                    org.robopro.programs.rapid.RapidAst.Stmt stmt = null;
                    if (!at(p + "/statement").isMissingNode()) {
                        double k = number(p + "/statement");
                        if (k != Math.rint(k) || k < 0 || k >= entryBody.size())
                            throw bad(p + "/statement", "no statement " + k + " in the program's rapid_module");
                        stmt = entryBody.get((int) k);
                    }
                    if (type.equals(Instruction.Type.RAPID.rapid())) {
                        if (stmt == null) throw bad(p + "/statement", "a RAPID line needs the index of its statement in rapid_module");
                        program.add(Instruction.kept(stmt));
                        continue;
                    }
                    Instruction.Type t;
                    try {
                        t = Instruction.Type.ofRapid(type);
                    } catch (IllegalArgumentException e) {
                        throw bad(p + "/type", e.getMessage());
                    }
                    String target = text(p + "/target");
                    if (targets.stream().noneMatch(x -> x.name().equals(target)))
                        throw bad(p + "/target", "no target named " + target);
                    String via = null;
                    if (t == Instruction.Type.MOVEC) {
                        via = text(p + "/via");
                        String viaName = via;
                        if (targets.stream().noneMatch(x -> x.name().equals(viaName))) throw bad(p + "/via", "no target named " + via);
                    } else if (!at(p + "/via").isMissingNode()) throw bad(p + "/via", t.rapid() + " takes no circle point");
                    double zone = number(p + "/zone_mm");
                    if (zone < 0) throw bad(p + "/zone_mm", "must be >= 0");
                    program.add(new Instruction(t, target, positive(p + "/speed_mm_s"), zone, via, stmt));
                }
            }
            JsonNode cal = at("/calibration/reference");
            String calRef = cal.isTextual() ? cal.asText() : null;
            String active = Target.WOBJ0;
            if (!at("/workbench_state/teach_in_wobj").isMissingNode()) {
                active = text("/workbench_state/teach_in_wobj");
                String a = active;
                if (!a.equalsIgnoreCase(Target.WOBJ0) && wobjs.stream().noneMatch(x -> x.name().equals(a)))
                    throw bad("/workbench_state/teach_in_wobj", "no work object named " + a);
            }
            double[] q = at("/workbench_state/joints_deg").isMissingNode() ? null
                    : Units.degToRad(numbers("/workbench_state/joints_deg", robot.dof()));
            return new ProjectData(ref, robot, placement, tool, objects, wobjs, targets, program, calRef, active, q, source);
        }
    }

    /** The statements of an imported program's entry procedure (the module's tree). */
    private static List<org.robopro.programs.rapid.RapidAst.Stmt> entryBody(org.robopro.app.workbench.model.ProgramModule.Source s) {
        for (org.robopro.programs.rapid.RapidAst.Item it : s.module().tree().items())
            if (it instanceof org.robopro.programs.rapid.RapidAst.Routine r && r.name().equalsIgnoreCase(s.entry())) return r.body();
        return List.of();
    }

    /** Index of this very statement node in {@code body}, -1 when absent. */
    private static int indexOf(List<org.robopro.programs.rapid.RapidAst.Stmt> body, org.robopro.programs.rapid.RapidAst.Stmt s) {
        for (int k = 0; s != null && k < body.size(); k++) if (body.get(k) == s) return k;
        return -1;
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
