package org.robopro.models;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

/**
 * Reader and writer of cell files, format "robopro-cell 1" (docs/cell-file.md): JSON with comments,
 * mm and degrees in the file, SI in {@link CellDescription}. Same error quality as
 * {@link RobotFile}: every problem is an {@link InputException} with file, line, column and field,
 * and nothing is built from a bad file. Writing then reading gives an equal cell.
 */
public final class CellFile {
    public static final String FORMAT = "robopro-cell";
    public static final int VERSION = 1;
    private static final String SHIPPED_DIR = "/org/robopro/models/cells/";
    private static final List<String> SHIPPED = List.of("irb2000-welding");

    private CellFile() { }

    /** Names of the shipped cells (irb2000-welding). */
    public static List<String> shippedNames() { return SHIPPED; }

    /** A shipped cell by name. */
    public static CellDescription shipped(String name) {
        if (!SHIPPED.contains(name))
            throw new InputException(null, 0, 0, "cell", "no shipped cell '" + name + "' (shipped: " + String.join(", ", SHIPPED) + ")");
        return parse("shipped:" + name + ".cell.json", RobotLibrary.resourceText(SHIPPED_DIR + name + ".cell.json"));
    }

    public static CellDescription read(Path file) {
        return parse(file.toString(), TextFiles.readUtf8(file));
    }

    public static CellDescription parse(String fileName, String text) {
        return fromTree(LocatedJson.parse(fileName, text));
    }

    /**
     * The cell's robot: a shipped name, or a robot file path resolved against the cell file's
     * folder ({@code cellFile} may be null for a cell not read from disk).
     */
    public static RobotDescription loadRobot(CellDescription cell, Path cellFile) {
        if (RobotLibrary.shippedNames().contains(cell.robot())) return RobotLibrary.shipped(cell.robot());
        Path p = Path.of(cell.robot());
        if (!p.isAbsolute() && cellFile != null && cellFile.toAbsolutePath().getParent() != null)
            p = cellFile.toAbsolutePath().getParent().resolve(p);
        return RobotLibrary.load(p.toString());
    }

    /** Builds a cell from a parsed tree (e.g. the cell embedded in a workbench project file). */
    public static CellDescription fromTree(LocatedJson.Node root) {
        root.onlyFields(Set.of("format", "name", "robot", "objects", "tools", "work_objects", "signals"));
        RobotFile.checkFormat(root.get("format"), FORMAT, VERSION);
        String name = RobotFile.identifier(root.get("name"));
        LocatedJson.Node robot = root.get("robot").onlyFields(Set.of("ref", "base"));
        String ref = robot.get("ref").asNonEmptyString();
        PoseDescription base = robot.has("base") ? pose(robot.get("base")) : PoseDescription.IDENTITY;

        List<CellObject> objects = new ArrayList<>();
        Set<String> names = new HashSet<>();
        if (root.has("objects")) for (LocatedJson.Node o : root.get("objects").items()) objects.add(object(o, names));
        List<ToolDescription> tools = new ArrayList<>();
        Set<String> toolNames = new HashSet<>();
        if (root.has("tools"))
            for (LocatedJson.Node t : root.get("tools").items()) {
                t.onlyFields(Set.of("name", "tcp", "mass_kg", "centre_of_mass"));
                String n = unique(t.get("name"), toolNames, "tool");
                PoseDescription tcp = pose(t.get("tcp"));
                double mass = t.has("mass_kg") ? t.get("mass_kg").asDouble() : 0;
                if (mass < 0) throw t.get("mass_kg").error("must not be negative");
                Vec3 com = t.has("centre_of_mass") ? RobotFile.pointMm(t.get("centre_of_mass")) : Vec3.ZERO;
                tools.add(new ToolDescription(n, tcp, mass, com));
            }
        List<WorkObjectDescription> wobjs = new ArrayList<>();
        Set<String> wobjNames = new HashSet<>();
        if (root.has("work_objects"))
            for (LocatedJson.Node w : root.get("work_objects").items()) {
                w.onlyFields(Set.of("name", "user_frame"));
                wobjs.add(new WorkObjectDescription(unique(w.get("name"), wobjNames, "work object"), pose(w.get("user_frame"))));
            }
        List<SignalDescription> signals = new ArrayList<>();
        if (root.has("signals")) signals = signals(root.get("signals"));
        return new CellDescription(name, ref, base, objects, tools, wobjs, signals);
    }

    /**
     * {@code [{"name": "diPart", "type": "DI", "value": 0, "script": [{"t_s": 1.5, "value": 1}]},
     * {"name": "diClosed", "type": "DI", "follows": "doClose", "delay_s": 0.2}]}.
     */
    private static List<SignalDescription> signals(LocatedJson.Node list) {
        List<SignalDescription> out = new ArrayList<>();
        Set<String> seen = new HashSet<>();
        for (LocatedJson.Node s : list.items()) {
            s.onlyFields(Set.of("name", "type", "value", "script", "follows", "delay_s"));
            LocatedJson.Node nameNode = s.get("name");
            String name = nameNode.asNonEmptyString();
            if (!name.matches("[A-Za-z][A-Za-z0-9_]{0,31}")) throw nameNode.error("a signal name is a RAPID identifier (letter, then letters, digits, _; at most 32)");
            if (!seen.add(name.toLowerCase(java.util.Locale.ROOT))) throw nameNode.error("duplicate signal name '" + name + "'");
            LocatedJson.Node typeNode = s.get("type");
            SignalDescription.Type type = SignalDescription.Type.parse(typeNode.asString());
            if (type == null) throw typeNode.error("unknown signal type '" + typeNode.asString() + "'; expected DI, DO, AI, AO, GI or GO");
            double value = s.has("value") ? signalValue(s.get("value"), type) : 0;
            List<SignalDescription.Change> script = new ArrayList<>();
            if (s.has("script")) {
                if (!type.input()) throw s.get("script").error("only inputs are scripted; " + name + " is an output");
                double last = -1;
                for (LocatedJson.Node c : s.get("script").items()) {
                    c.onlyFields(Set.of("t_s", "value"));
                    double t = c.get("t_s").asDouble();
                    if (!(t >= 0) || !Double.isFinite(t)) throw c.get("t_s").error("must be a finite time >= 0");
                    if (t <= last) throw c.get("t_s").error("script times must increase");
                    last = t;
                    script.add(new SignalDescription.Change(t, signalValue(c.get("value"), type)));
                }
            }
            String follows = "";
            double delay = 0;
            if (s.has("follows")) {
                if (!type.input()) throw s.get("follows").error("only inputs follow an output; " + name + " is an output");
                follows = s.get("follows").asNonEmptyString();
                if (s.has("delay_s")) {
                    delay = s.get("delay_s").asDouble();
                    if (!(delay >= 0) || !Double.isFinite(delay)) throw s.get("delay_s").error("must be a finite time >= 0");
                }
            } else if (s.has("delay_s")) throw s.get("delay_s").error("delay_s belongs to an input that follows an output");
            out.add(new SignalDescription(name, type, value, script, follows, delay));
        }
        java.util.Map<String, SignalDescription> byName = new java.util.HashMap<>();
        for (SignalDescription d : out) byName.put(d.key(), d);
        for (int k = 0; k < out.size(); k++) {
            if (out.get(k).follows().isEmpty()) continue;
            SignalDescription f = byName.get(out.get(k).follows().toLowerCase(java.util.Locale.ROOT));
            if (f == null) throw list.items().get(k).get("follows").error("no signal '" + out.get(k).follows() + "' in the cell");
            if (f.type().input()) throw list.items().get(k).get("follows").error("an input follows an output; " + f.name() + " is an input");
        }
        return out;
    }

    private static double signalValue(LocatedJson.Node n, SignalDescription.Type type) {
        double v = n.asDouble();
        if (!Double.isFinite(v)) throw n.error("must be finite");
        if (type.digital() && v != 0 && v != 1) throw n.error("a digital signal is 0 or 1");
        if ((type == SignalDescription.Type.GI || type == SignalDescription.Type.GO) && (v < 0 || v != Math.rint(v)))
            throw n.error("a group signal is a whole number >= 0");
        return v;
    }

    private static String unique(LocatedJson.Node n, Set<String> seen, String what) {
        String s = n.asNonEmptyString();
        if (!seen.add(s)) throw n.error("duplicate " + what + " name '" + s + "'");
        return s;
    }

    private static CellObject object(LocatedJson.Node o, Set<String> names) {
        o.onlyFields(Set.of("name", "kind", "pose", "size", "colour", "mesh", "mesh_scale"));
        String name = unique(o.get("name"), names, "object");
        LocatedJson.Node kindNode = o.get("kind");
        CellObject.Kind kind = CellObject.Kind.parse(kindNode.asString());
        if (kind == null) throw kindNode.error("unknown kind '" + kindNode.asString() + "'; expected box, cylinder or mesh");
        PoseDescription pose = o.has("pose") ? pose(o.get("pose")) : PoseDescription.IDENTITY;
        Vec3 size = Vec3.ZERO;
        String mesh = "";
        double scale = 1;
        if (kind == CellObject.Kind.MESH) {
            mesh = o.get("mesh").asNonEmptyString();
            if (o.has("mesh_scale")) {
                scale = o.get("mesh_scale").asDouble();
                if (!(scale > 0)) throw o.get("mesh_scale").error("must be greater than zero");
            } else {
                scale = 0.001;
            }
            if (o.has("size")) throw o.get("size").error("a mesh has no size (use mesh_scale)");
        } else {
            LocatedJson.Node s = o.get("size");
            size = RobotFile.pointMm(s);
            if (!(size.x() > 0 && size.y() > 0 && size.z() > 0)) throw s.error("sizes must be greater than zero");
            if (o.has("mesh")) throw o.get("mesh").error("only a mesh object has a mesh");
            if (o.has("mesh_scale")) throw o.get("mesh_scale").error("only a mesh object has a mesh_scale");
        }
        Rgba colour = new Rgba(0.7, 0.7, 0.7, 1);
        if (o.has("colour")) {
            List<LocatedJson.Node> c = o.get("colour").items();
            if (c.size() != 3 && c.size() != 4) throw o.get("colour").error("expected [r, g, b] or [r, g, b, a], components 0..1");
            double[] v = {0, 0, 0, 1};
            for (int i = 0; i < c.size(); i++) {
                v[i] = c.get(i).asDouble();
                if (v[i] < 0 || v[i] > 1) throw c.get(i).error("colour components must be in 0..1");
            }
            colour = new Rgba(v[0], v[1], v[2], v[3]);
        }
        return new CellObject(name, kind, pose, size, colour, mesh, scale);
    }

    /** {"position": [mm], "quaternion": [w, x, y, z]} or {"position": [mm], "rpy": [deg]}. */
    static PoseDescription pose(LocatedJson.Node p) {
        p.onlyFields(Set.of("position", "quaternion", "rpy"));
        Vec3 position = p.has("position") ? RobotFile.pointMm(p.get("position")) : Vec3.ZERO;
        if (p.has("quaternion") && p.has("rpy")) throw p.get("rpy").error("give either quaternion or rpy, not both");
        if (p.has("rpy")) {
            List<LocatedJson.Node> r = p.get("rpy").items(3);
            return PoseDescription.fromRpy(position, FileNumbers.degToRad(r.get(0)), FileNumbers.degToRad(r.get(1)),
                    FileNumbers.degToRad(r.get(2)));
        }
        if (!p.has("quaternion")) return new PoseDescription(position, 1, 0, 0, 0);
        LocatedJson.Node qn = p.get("quaternion");
        List<LocatedJson.Node> q = qn.items(4);
        double w = q.get(0).asDouble(), x = q.get(1).asDouble(), y = q.get(2).asDouble(), z = q.get(3).asDouble();
        double n = Math.sqrt(w * w + x * x + y * y + z * z);
        if (!Double.isFinite(n)) throw qn.error("quaternion too large to normalise");
        if (n < 1e-9) throw qn.error("quaternion must not be zero");
        if (Math.abs(n - 1) > 1e-12) {
            w /= n; x /= n; y /= n; z /= n;
        }
        return new PoseDescription(position, w, x, y, z);
    }

    // ------------------------------------------------------------------ writing

    public static String format(CellDescription cell) {
        JsonOut o = new JsonOut().beginObject(null);
        o.string("format", FORMAT + " " + VERSION).string("name", cell.name());
        o.beginObject("robot").string("ref", cell.robot());
        writePose(o, "base", cell.worldTbase());
        o.endObject();
        o.beginArray("objects");
        for (CellObject c : cell.objects()) {
            o.beginObject(null).string("name", c.name()).string("kind", c.kind().fileName());
            writePose(o, "pose", c.worldTobject());
            if (c.kind() == CellObject.Kind.MESH)
                o.string("mesh", c.meshPath()).number("mesh_scale", FileNumbers.formatPlain(c.meshScale()));
            else
                o.numbers("size", RobotFile.mm(c.size()));
            Rgba k = c.colour();
            if (k.a() == 1)
                o.numbers("colour", FileNumbers.formatPlain(k.r()), FileNumbers.formatPlain(k.g()), FileNumbers.formatPlain(k.b()));
            else
                o.numbers("colour", FileNumbers.formatPlain(k.r()), FileNumbers.formatPlain(k.g()), FileNumbers.formatPlain(k.b()),
                        FileNumbers.formatPlain(k.a()));
            o.endObject();
        }
        o.endArray();
        o.beginArray("tools");
        for (ToolDescription t : cell.tools()) {
            o.beginObject(null).string("name", t.name());
            writePose(o, "tcp", t.flangeTtcp());
            o.number("mass_kg", FileNumbers.formatPlain(t.massKg())).numbers("centre_of_mass", RobotFile.mm(t.centreOfMass()));
            o.endObject();
        }
        o.endArray();
        o.beginArray("work_objects");
        for (WorkObjectDescription w : cell.workObjects()) {
            o.beginObject(null).string("name", w.name());
            writePose(o, "user_frame", w.worldTuser());
            o.endObject();
        }
        o.endArray();
        if (!cell.signals().isEmpty()) {
            o.beginArray("signals");
            for (SignalDescription d : cell.signals()) {
                o.beginObject(null).string("name", d.name()).string("type", d.type().name()).number("value", FileNumbers.formatPlain(d.value()));
                if (!d.script().isEmpty()) {
                    o.beginArray("script");
                    for (SignalDescription.Change c : d.script())
                        o.beginObject(null).number("t_s", FileNumbers.formatPlain(c.timeS())).number("value", FileNumbers.formatPlain(c.value())).endObject();
                    o.endArray();
                }
                if (!d.follows().isEmpty()) o.string("follows", d.follows()).number("delay_s", FileNumbers.formatPlain(d.delayS()));
                o.endObject();
            }
            o.endArray();
        }
        return o.endObject().toString();
    }

    private static void writePose(JsonOut o, String key, PoseDescription p) {
        o.beginObject(key).numbers("position", RobotFile.mm(p.position()))
                .numbers("quaternion", FileNumbers.formatPlain(p.qw()), FileNumbers.formatPlain(p.qx()),
                        FileNumbers.formatPlain(p.qy()), FileNumbers.formatPlain(p.qz()))
                .endObject();
    }

    /** Writes a cell file atomically; refuses to replace an existing file unless {@code overwrite}. */
    public static void write(CellDescription cell, Path file, boolean overwrite) throws IOException {
        AtomicFiles.writeString(file, format(cell), overwrite);
    }
}
