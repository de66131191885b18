package org.robopro.models;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeMap;

/**
 * Reader and writer of robot files, format "robopro-robot 1" (docs/robot-file.md): JSON with
 * comments, millimetres and degrees in the file, SI in {@link RobotDescription}. The reader checks
 * everything before building anything and refuses bad input with an {@link InputException} naming
 * file, line, column and field. The writer round-trips exactly: {@code parse(format(r)) equals r}
 * for any robot whose axes are unit vectors.
 */
public final class RobotFile {
    public static final String FORMAT = "robopro-robot";
    public static final int VERSION = 1;
    /** Standard gravity, m/s^2, base -z, used when a mass model gives none. */
    public static final Vec3 STANDARD_GRAVITY = new Vec3(0, 0, -9.80665);

    private static final double UNIT_TOLERANCE = 1e-12;
    /** Flange axes closer than this to orthogonal (|cos|) are accepted as given. */
    static final double ORTHOGONAL_TOLERANCE = 1e-6;

    private RobotFile() { }

    // ------------------------------------------------------------------ reading

    /** Reads a robot file from disk. */
    public static RobotDescription read(Path file) {
        return parse(file.toString(), TextFiles.readUtf8(file));
    }

    /** Parses robot-file text; {@code fileName} names it in errors. */
    public static RobotDescription parse(String fileName, String text) {
        LocatedJson.Node root = LocatedJson.parse(fileName, text);
        return fromTree(root);
    }

    /** Builds a robot from an already parsed tree (e.g. a robot embedded in a cell file). */
    public static RobotDescription fromTree(LocatedJson.Node root) {
        root.onlyFields(Set.of("format", "name", "display_name", "joints", "flange", "coupling",
                "mass_model", "meshes", "effects", "source", "provenance"));
        checkFormat(root.get("format"), FORMAT, VERSION);
        String name = identifier(root.get("name"));
        String displayName = root.has("display_name") ? root.get("display_name").asNonEmptyString() : name;

        LocatedJson.Node jointsNode = root.get("joints");
        if (jointsNode.items().isEmpty()) throw jointsNode.error("a robot needs at least one joint");
        if (jointsNode.items().size() > RobotDescription.MAX_JOINTS)
            throw jointsNode.error(jointsNode.items().size() + " joints; a robot may have at most " + RobotDescription.MAX_JOINTS);
        List<JointDescription> joints = new ArrayList<>();
        Map<String, Integer> index = new HashMap<>();
        for (LocatedJson.Node j : jointsNode.items()) {
            JointDescription jd = joint(j);
            if (jd.name().equals("base")) throw j.get("name").error("'base' is reserved for the robot base");
            Integer prev = index.putIfAbsent(jd.name(), joints.size() + 1);
            if (prev != null) throw j.get("name").error("duplicate joint name '" + jd.name() + "' (also joint " + prev + ")");
            joints.add(jd);
        }

        FrameDescription flange = frame(root.get("flange"), "origin");
        List<CouplingTerm> coupling = root.has("coupling") ? coupling(root.get("coupling"), index) : List.of();
        Optional<MassModel> mass = root.has("mass_model") ? Optional.of(massModel(root.get("mass_model"), index))
                : Optional.empty();
        List<MeshRef> meshes = new ArrayList<>();
        if (root.has("meshes")) for (LocatedJson.Node m : root.get("meshes").items()) meshes.add(mesh(m, index));
        List<EffectDescription> effects = new ArrayList<>();
        if (root.has("effects")) for (LocatedJson.Node e : root.get("effects").items()) effects.add(effect(e, index));
        String source = root.has("source") ? root.get("source").asString() : "";
        Map<String, String> provenance = new LinkedHashMap<>();
        if (root.has("provenance"))
            for (Map.Entry<String, LocatedJson.Node> e : root.get("provenance").members().entrySet())
                provenance.put(e.getKey(), e.getValue().asString());
        return new RobotDescription(name, displayName, joints, flange, coupling, mass, meshes, effects, source,
                provenance);
    }

    static void checkFormat(LocatedJson.Node n, String format, int version) {
        String tag = n.asString().trim();
        String prefix = format + " ";
        if (!tag.startsWith(prefix))
            throw n.error("not a " + format + " file: format tag is '" + tag + "', expected '" + format + " " + version + "'");
        String v = tag.substring(prefix.length()).trim();
        if (!v.equals(Integer.toString(version)))
            throw n.error("unknown format version '" + v + "'; this robopro reads " + format + " version " + version);
    }

    static String identifier(LocatedJson.Node n) {
        String s = n.asNonEmptyString();
        if (!s.matches("[A-Za-z0-9_.\\-]+"))
            throw n.error("'" + s + "' is not a valid name (letters, digits, '_', '.', '-')");
        return s;
    }

    private static JointDescription joint(LocatedJson.Node j) {
        j.onlyFields(Set.of("name", "type", "point", "axis", "limits", "max_speed"));
        String name = j.get("name").asNonEmptyString();
        LocatedJson.Node typeNode = j.get("type");
        JointType type = JointType.parse(typeNode.asString());
        if (type == null)
            throw typeNode.error("unknown joint type '" + typeNode.asString() + "'; expected revolute or prismatic");
        Vec3 point = pointMm(j.get("point"));
        Vec3 axis = direction(j.get("axis"));
        double min = Double.NEGATIVE_INFINITY, max = Double.POSITIVE_INFINITY;
        if (j.has("limits")) {
            List<LocatedJson.Node> l = j.get("limits").items(2);
            if (l.get(0).kind() != LocatedJson.Kind.NULL) min = jointValue(l.get(0), type);
            if (l.get(1).kind() != LocatedJson.Kind.NULL) max = jointValue(l.get(1), type);
            if (min > max)
                throw j.get("limits").error("minimum " + l.get(0).numberText() + " is greater than maximum "
                        + l.get(1).numberText());
        }
        double speed = Double.POSITIVE_INFINITY;
        if (j.has("max_speed")) {
            LocatedJson.Node s = j.get("max_speed");
            speed = jointValue(s, type);
            if (!(speed > 0)) throw s.error("must be greater than zero");
        }
        return new JointDescription(name, type, point, axis, min, max, speed);
    }

    private static double jointValue(LocatedJson.Node n, JointType type) {
        return type == JointType.REVOLUTE ? FileNumbers.degToRad(n) : FileNumbers.mmToM(n);
    }

    /** A point [x, y, z] in millimetres, returned in metres. */
    static Vec3 pointMm(LocatedJson.Node n) {
        List<LocatedJson.Node> c = n.items(3);
        double[] v = new double[3];
        for (int k = 0; k < 3; k++) {
            v[k] = FileNumbers.mmToM(c.get(k));
            if (!(Math.abs(v[k]) <= RobotDescription.MAX_COORDINATE_M))
                throw c.get(k).error("coordinate " + c.get(k).numberText() + " mm is beyond "
                        + (long) (RobotDescription.MAX_COORDINATE_M * 1000) + " mm: not a dimension of a robot or its cell");
        }
        return new Vec3(v[0], v[1], v[2]);
    }

    /** A plain 3-vector (no unit conversion). */
    static Vec3 plainVec(LocatedJson.Node n) {
        List<LocatedJson.Node> c = n.items(3);
        return new Vec3(c.get(0).asDouble(), c.get(1).asDouble(), c.get(2).asDouble());
    }

    /** A direction: non-zero, returned as a unit vector (unchanged if already unit to 1e-12). */
    static Vec3 direction(LocatedJson.Node n) {
        Vec3 v = plainVec(n);
        double norm = v.norm();
        if (!Double.isFinite(norm)) throw n.error("direction is too long to normalise");
        if (norm < 1e-9) throw n.error("direction must not be zero");
        return Math.abs(norm - 1) <= UNIT_TOLERANCE ? v : v.times(1 / norm);
    }

    static FrameDescription frame(LocatedJson.Node f, String originField) {
        f.onlyFields(Set.of(originField, "z_axis", "x_axis"));
        Vec3 origin = pointMm(f.get(originField));
        Vec3 z = direction(f.get("z_axis"));
        Vec3 x = direction(f.get("x_axis"));
        double cos = z.dot(x);
        if (Math.abs(cos) > ORTHOGONAL_TOLERANCE)
            throw f.get("x_axis").error(String.format(java.util.Locale.ROOT,
                    "x_axis is not orthogonal to z_axis (angle %.6f deg)", Math.toDegrees(Math.acos(Math.max(-1, Math.min(1, cos))))));
        return new FrameDescription(origin, x, z);
    }

    private static int jointRef(LocatedJson.Node n, Map<String, Integer> index) {
        String s = n.asString();
        Integer i = index.get(s);
        if (i == null) throw n.error("no joint named '" + s + "' (joints: " + String.join(", ", names(index)) + ")");
        return i;
    }

    private static List<String> names(Map<String, Integer> index) {
        String[] a = new String[index.size()];
        index.forEach((k, v) -> a[v - 1] = k);
        return List.of(a);
    }

    private static List<CouplingTerm> coupling(LocatedJson.Node c, Map<String, Integer> index) {
        List<CouplingTerm> terms = new ArrayList<>();
        Set<Long> seen = new HashSet<>();
        for (LocatedJson.Node row : c.items()) {
            row.onlyFields(Set.of("joint", "terms"));
            int joint = jointRef(row.get("joint"), index);
            LocatedJson.Node termsNode = row.get("terms");
            if (termsNode.items().isEmpty()) throw termsNode.error("a coupling needs at least one term");
            for (LocatedJson.Node t : termsNode.items()) {
                t.onlyFields(Set.of("q", "factor"));
                int source = jointRef(t.get("q"), index);
                double factor = t.get("factor").asDouble();
                if (!seen.add((long) joint << 32 | source))
                    throw t.get("q").error("term for this joint and q given twice");
                terms.add(new CouplingTerm(joint, source, factor));
            }
        }
        return terms;
    }

    private static MassModel massModel(LocatedJson.Node m, Map<String, Integer> index) {
        m.onlyFields(Set.of("links", "rated_payload_kg", "payload_centre_of_mass", "gravity_m_s2"));
        List<LinkMass> links = new ArrayList<>();
        for (LocatedJson.Node l : m.get("links").items()) {
            l.onlyFields(Set.of("joint", "name", "mass_kg", "centre_of_mass"));
            int joint = jointRef(l.get("joint"), index);
            String name = l.has("name") ? l.get("name").asString() : "";
            double mass = nonNegative(l.get("mass_kg"));
            links.add(new LinkMass(joint, name, mass, pointMm(l.get("centre_of_mass"))));
        }
        double payload = m.has("rated_payload_kg") ? nonNegative(m.get("rated_payload_kg")) : 0;
        Vec3 payloadCom = m.has("payload_centre_of_mass") ? pointMm(m.get("payload_centre_of_mass")) : Vec3.ZERO;
        Vec3 gravity = m.has("gravity_m_s2") ? plainVec(m.get("gravity_m_s2")) : STANDARD_GRAVITY;
        return new MassModel(links, payload, payloadCom, gravity);
    }

    private static double nonNegative(LocatedJson.Node n) {
        double v = n.asDouble();
        if (v < 0) throw n.error("must not be negative");
        return v;
    }

    private static MeshRef mesh(LocatedJson.Node m, Map<String, Integer> index) {
        m.onlyFields(Set.of("link", "path", "scale", "frame"));
        LocatedJson.Node linkNode = m.get("link");
        int link = "base".equals(linkNode.asString()) ? 0 : jointRef(linkNode, index);
        String path = m.get("path").asNonEmptyString();
        double scale = 0.001;
        if (m.has("scale")) {
            scale = m.get("scale").asDouble();
            if (!(scale > 0)) throw m.get("scale").error("must be greater than zero");
        }
        boolean inLinkFrame = false;
        if (m.has("frame")) {
            String f = m.get("frame").asString();
            if (f.equals("link")) inLinkFrame = true;
            else if (!f.equals("base")) throw m.get("frame").error("expected \"base\" or \"link\", got '" + f + "'");
        }
        return new MeshRef(link, path, scale, inLinkFrame);
    }

    private static EffectDescription effect(LocatedJson.Node e, Map<String, Integer> index) {
        e.onlyFields(Set.of("effect", "joints", "parameters_si"));
        String name = e.get("effect").asNonEmptyString();
        List<Integer> joints = new ArrayList<>();
        if (e.has("joints")) for (LocatedJson.Node j : e.get("joints").items()) joints.add(jointRef(j, index));
        Map<String, Double> params = new LinkedHashMap<>();
        if (e.has("parameters_si"))
            for (Map.Entry<String, LocatedJson.Node> p : e.get("parameters_si").members().entrySet())
                params.put(p.getKey(), p.getValue().asDouble());
        return new EffectDescription(name, joints, params, e);
    }


    // ------------------------------------------------------------------ writing

    /** The robot-file text of {@code robot}. */
    public static String format(RobotDescription robot) {
        List<JointDescription> joints = robot.joints();
        JsonOut o = new JsonOut().beginObject(null);
        o.string("format", FORMAT + " " + VERSION);
        o.string("name", robot.name());
        o.string("display_name", robot.displayName());
        o.beginArray("joints");
        for (JointDescription j : joints) {
            o.beginObject(null).string("name", j.name()).string("type", j.type().fileName());
            o.numbers("point", mm(j.point()));
            o.numbers("axis", plain(j.axis()));
            boolean rev = j.type() == JointType.REVOLUTE;
            if (Double.isFinite(j.min()) || Double.isFinite(j.max()))
                o.numbers("limits", limit(j.min(), rev), limit(j.max(), rev));
            if (Double.isFinite(j.maxSpeed()))
                o.number("max_speed", rev ? FileNumbers.formatDeg(j.maxSpeed()) : FileNumbers.formatMm(j.maxSpeed()));
            o.endObject();
        }
        o.endArray();
        writeFrame(o, "flange", "origin", robot.flange());
        if (!robot.coupling().isEmpty()) {
            o.beginArray("coupling");
            List<CouplingTerm> c = robot.coupling();
            for (int i = 0; i < c.size(); ) {
                int joint = c.get(i).joint();
                o.beginObject(null).string("joint", joints.get(joint - 1).name()).beginArray("terms");
                for (; i < c.size() && c.get(i).joint() == joint; i++)
                    o.beginObject(null).string("q", joints.get(c.get(i).source() - 1).name())
                            .number("factor", FileNumbers.formatPlain(c.get(i).factor())).endObject();
                o.endArray().endObject();
            }
            o.endArray();
        }
        robot.massModel().ifPresent(m -> {
            o.beginObject("mass_model").beginArray("links");
            for (LinkMass l : m.links()) {
                o.beginObject(null).string("joint", joints.get(l.joint() - 1).name());
                if (!l.name().isEmpty()) o.string("name", l.name());
                o.number("mass_kg", FileNumbers.formatPlain(l.massKg())).numbers("centre_of_mass", mm(l.centreOfMass()));
                o.endObject();
            }
            o.endArray();
            o.number("rated_payload_kg", FileNumbers.formatPlain(m.ratedPayloadKg()));
            o.numbers("payload_centre_of_mass", mm(m.payloadCentreOfMass()));
            o.numbers("gravity_m_s2", plain(m.gravity()));
            o.endObject();
        });
        if (!robot.meshes().isEmpty()) {
            o.beginArray("meshes");
            for (MeshRef m : robot.meshes())
                o.beginObject(null).string("link", m.link() == 0 ? "base" : joints.get(m.link() - 1).name())
                        .string("path", m.path()).number("scale", FileNumbers.formatPlain(m.scale()))
                        .string("frame", m.inLinkFrame() ? "link" : "base").endObject();
            o.endArray();
        }
        if (!robot.effects().isEmpty()) {
            o.beginArray("effects");
            for (EffectDescription e : robot.effects()) {
                o.beginObject(null).string("effect", e.effect());
                o.strings("joints", e.joints().stream().map(i -> joints.get(i - 1).name()).toList());
                o.beginObject("parameters_si");
                new TreeMap<>(e.parameters()).forEach((k, v) -> o.number(k, FileNumbers.formatPlain(v)));
                o.endObject().endObject();
            }
            o.endArray();
        }
        o.string("source", robot.source());
        if (!robot.provenance().isEmpty()) {
            o.beginObject("provenance");
            new TreeMap<>(robot.provenance()).forEach(o::string);
            o.endObject();
        }
        return o.endObject().toString();
    }

    static void writeFrame(JsonOut o, String key, String originField, FrameDescription f) {
        o.beginObject(key).numbers(originField, mm(f.origin())).numbers("z_axis", plain(f.zAxis()))
                .numbers("x_axis", plain(f.xAxis())).endObject();
    }

    static String[] mm(Vec3 v) {
        return new String[] {FileNumbers.formatMm(v.x()), FileNumbers.formatMm(v.y()), FileNumbers.formatMm(v.z())};
    }

    static String[] plain(Vec3 v) {
        return new String[] {FileNumbers.formatPlain(v.x()), FileNumbers.formatPlain(v.y()), FileNumbers.formatPlain(v.z())};
    }

    private static String limit(double v, boolean revolute) {
        if (!Double.isFinite(v)) return "null";
        return revolute ? FileNumbers.formatDeg(v) : FileNumbers.formatMm(v);
    }

    /** Writes a robot file atomically; refuses to replace an existing file unless {@code overwrite}. */
    public static void write(RobotDescription robot, Path file, boolean overwrite) throws IOException {
        AtomicFiles.writeString(file, format(robot), overwrite);
    }
}
