package org.robopro.kinematics.importers;

import java.io.IOException;
import java.io.StringReader;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.regex.Pattern;
import javax.xml.XMLConstants;
import javax.xml.parsers.ParserConfigurationException;
import javax.xml.parsers.SAXParser;
import javax.xml.parsers.SAXParserFactory;
import org.robopro.kinematics.Pose;
import org.robopro.models.CouplingTerm;
import org.robopro.models.FrameDescription;
import org.robopro.models.InputException;
import org.robopro.models.JointDescription;
import org.robopro.models.JointType;
import org.robopro.models.RobotDescription;
import org.robopro.models.TextFiles;
import org.robopro.models.Vec3;
import org.xml.sax.Attributes;
import org.xml.sax.InputSource;
import org.xml.sax.Locator;
import org.xml.sax.SAXException;
import org.xml.sax.SAXParseException;
import org.xml.sax.helpers.DefaultHandler;

/**
 * Imports the kinematic chain of a URDF file (ROS Unified Robot Description Format) as a
 * {@link RobotDescription}: revolute, continuous (revolute without limits), prismatic and fixed
 * joints. Fixed joints are folded into the neighbouring frames; the chain is followed from the
 * root link to the last movable joint and on through fixed joints to the flange (a child link
 * named {@code tool0} or {@code flange} is preferred where fixed branches split). Joint axes and
 * points are the joint frames at q = 0 seen from the root link. A mimic joint k of joint j
 * (theta_k = multiplier * theta_j + offset in URDF) stays a joint of the model whose own
 * controller value is held at 0 (limits 0..0), coupled as theta_k = q_k + multiplier * q_j, with
 * the offset folded into its frame at q = 0. URDF units are SI already.
 *
 * <p>Branching trees with movable joints on more than one branch, floating and planar joints are
 * refused with an {@link InputException} naming file, line and column. DOCTYPEs are refused
 * (no external entities).
 */
public final class UrdfImporter {
    private static final Pattern NUMBER = Pattern.compile("[-+]?(\\d+\\.?\\d*|\\.\\d+)([eE][-+]?\\d+)?");

    private UrdfImporter() { }

    public static RobotDescription read(Path file) {
        String text = TextFiles.readUtf8(file);
        return parse(file.toString(), text);
    }

    // ------------------------------------------------------------------ located XML tree

    private static final class El {
        final String name;
        final Map<String, String> attrs = new LinkedHashMap<>();
        final List<El> children = new ArrayList<>();
        final int line, column;

        El(String name, int line, int column) {
            this.name = name;
            this.line = line;
            this.column = column;
        }

        List<El> all(String n) {
            List<El> l = new ArrayList<>();
            for (El c : children) if (c.name.equals(n)) l.add(c);
            return l;
        }
    }

    private static El parseXml(String file, String text) {
        try {
            SAXParserFactory f = SAXParserFactory.newInstance();
            f.setNamespaceAware(false);
            f.setValidating(false);
            f.setFeature(XMLConstants.FEATURE_SECURE_PROCESSING, true);
            f.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
            f.setFeature("http://xml.org/sax/features/external-general-entities", false);
            f.setFeature("http://xml.org/sax/features/external-parameter-entities", false);
            SAXParser p = f.newSAXParser();
            El[] root = new El[1];
            p.parse(new InputSource(new StringReader(text)), new DefaultHandler() {
                Locator loc;
                final List<El> stack = new ArrayList<>();

                @Override public void setDocumentLocator(Locator l) { loc = l; }

                @Override public void startElement(String uri, String local, String qName, Attributes a) {
                    El e = new El(qName, loc == null ? 0 : loc.getLineNumber(), loc == null ? 0 : loc.getColumnNumber());
                    for (int i = 0; i < a.getLength(); i++) e.attrs.put(a.getQName(i), a.getValue(i));
                    if (stack.isEmpty()) root[0] = e;
                    else stack.get(stack.size() - 1).children.add(e);
                    stack.add(e);
                }

                @Override public void endElement(String uri, String local, String qName) {
                    stack.remove(stack.size() - 1);
                }
            });
            return root[0];
        } catch (SAXParseException e) {
            throw new InputException(file, Math.max(0, e.getLineNumber()), Math.max(0, e.getColumnNumber()), null,
                    "malformed XML: " + e.getMessage(), e);
        } catch (SAXException e) {
            throw new InputException(file, 0, 0, null, "malformed XML: " + e.getMessage(), e);
        } catch (IOException e) {
            throw new InputException(file, 0, 0, null, "cannot read: " + e.getMessage(), e);
        } catch (ParserConfigurationException e) {
            throw new IllegalStateException("XML parser cannot be configured securely", e);
        }
    }

    // ------------------------------------------------------------------ URDF

    private record UJoint(El el, String name, String type, String parent, String child, Pose origin, Vec3 axis,
                          double lower, double upper, double velocity, String mimic, double multiplier, double offset) { }

    public static RobotDescription parse(String file, String text) {
        El robot = parseXml(file, text);
        if (robot == null) throw new InputException(file, 1, 1, null, "empty document");
        if (!robot.name.equals("robot"))
            throw err(file, robot, robot.name, "root element must be <robot>, got <" + robot.name + ">");
        String robotName = robot.attrs.getOrDefault("name", "");
        if (robotName.isBlank()) throw err(file, robot, "robot.name", "missing attribute 'name'");

        Map<String, El> links = new LinkedHashMap<>();
        for (El l : robot.all("link")) {
            String n = attr(file, l, "name");
            if (links.put(n, l) != null) throw err(file, l, "link.name", "duplicate link name '" + n + "'");
        }
        if (links.isEmpty()) throw err(file, robot, "robot", "no <link> elements");

        Map<String, UJoint> joints = new LinkedHashMap<>();
        Map<String, UJoint> byChild = new HashMap<>();
        Map<String, List<UJoint>> byParent = new HashMap<>();
        for (El j : robot.all("joint")) {
            UJoint u = joint(file, j, links);
            if (joints.put(u.name, u) != null) throw err(file, j, "joint.name", "duplicate joint name '" + u.name + "'");
            if (byChild.put(u.child, u) != null)
                throw err(file, j, "joint.child", "link '" + u.child + "' is the child of two joints");
            byParent.computeIfAbsent(u.parent, k -> new ArrayList<>()).add(u);
        }
        List<String> roots = new ArrayList<>();
        for (String l : links.keySet()) if (!byChild.containsKey(l)) roots.add(l);
        if (roots.size() != 1)
            throw err(file, robot, "robot", roots.isEmpty() ? "no root link (the joints form a loop)"
                    : "more than one root link: " + String.join(", ", roots));

        // Which links lead to a movable joint (memoised depth-first; the tree has no loops below the root).
        Map<String, Boolean> leadsToMovable = new HashMap<>();
        int visited = countAndMark(roots.get(0), byParent, leadsToMovable, 0);
        if (visited != links.size())
            throw err(file, robot, "robot", "some links are not connected to the root link '" + roots.get(0) + "'");

        List<JointDescription> out = new ArrayList<>();
        List<UJoint> movable = new ArrayList<>();
        Pose t = Pose.IDENTITY;
        String link = roots.get(0);
        while (true) {
            List<UJoint> kids = byParent.getOrDefault(link, List.of());
            List<UJoint> onward = new ArrayList<>();
            for (UJoint k : kids) if (!k.type.equals("fixed") || leadsToMovable.get(k.child)) onward.add(k);
            UJoint next;
            if (onward.size() > 1) {
                throw err(file, onward.get(1).el, "joint", "the chain branches at link '" + link + "' (joints '"
                        + onward.get(0).name + "' and '" + onward.get(1).name + "'); robopro imports serial chains");
            } else if (onward.size() == 1) {
                next = onward.get(0);
            } else {
                // Only fixed joints remain: follow them to the flange.
                next = null;
                for (UJoint k : kids) if (k.child.equals("tool0") || k.child.equals("flange")) next = k;
                if (next == null && kids.size() == 1) next = kids.get(0);
                if (next == null) break;
            }
            t = t.times(next.origin);
            if (!next.type.equals("fixed")) {
                JointType type = next.type.equals("prismatic") ? JointType.PRISMATIC : JointType.REVOLUTE;
                // A mimic joint has no controller value of its own: its q is held at 0 (limits 0..0) and the
                // coupling gives theta = q + multiplier * q_source; the offset is its angle (or travel) at q = 0.
                boolean mimic = next.mimic != null;
                out.add(CleanNumbers.joint(next.name, type, t.position(), t.rotate(next.axis), mimic ? 0 : next.lower,
                        mimic ? 0 : next.upper, next.velocity));
                movable.add(next);
                if (mimic && next.offset != 0)
                    t = t.times(type == JointType.PRISMATIC ? Pose.translation(next.axis.times(next.offset))
                            : Pose.rotAxis(next.axis, next.offset));
            }
            link = next.child;
        }
        if (out.isEmpty()) throw err(file, robot, "robot", "no revolute, continuous or prismatic joint");
        if (out.size() > RobotDescription.MAX_JOINTS)
            throw err(file, movable.get(RobotDescription.MAX_JOINTS).el, "joint", "the chain has " + out.size()
                    + " movable joints; a robot may have at most " + RobotDescription.MAX_JOINTS);

        List<CouplingTerm> coupling = new ArrayList<>();
        for (int k = 0; k < movable.size(); k++) {
            UJoint u = movable.get(k);
            if (u.mimic == null) continue;
            int src = -1;
            for (int s = 0; s < movable.size(); s++) if (movable.get(s).name.equals(u.mimic)) src = s;
            if (src < 0) throw err(file, u.el, "mimic.joint", "mimics '" + u.mimic + "', which is not a movable joint of the chain");
            if (src == k) throw err(file, u.el, "mimic.joint", "joint '" + u.name + "' mimics itself");
            coupling.add(new CouplingTerm(k + 1, k + 1, 1));
            coupling.add(new CouplingTerm(k + 1, src + 1, u.multiplier));
        }
        String name = DhImporter.sanitize(robotName);
        FrameDescription flange = CleanNumbers.frame(t.position(), t.xAxis(), t.zAxis());
        return new RobotDescription(name, robotName, out, flange, coupling, Optional.empty(), List.of(), List.of(),
                "imported from " + file + " (URDF)", Map.of("imported-from", file, "importer", "urdf"));
    }

    private static int countAndMark(String link, Map<String, List<UJoint>> byParent, Map<String, Boolean> marks, int depth) {
        if (depth > 10_000) throw new IllegalStateException("URDF tree too deep");
        int n = 1;
        boolean movable = false;
        for (UJoint j : byParent.getOrDefault(link, List.of())) {
            n += countAndMark(j.child, byParent, marks, depth + 1);
            movable |= !j.type.equals("fixed") || marks.get(j.child);
        }
        marks.put(link, movable);
        return n;
    }

    private static UJoint joint(String file, El j, Map<String, El> links) {
        String name = attr(file, j, "name");
        String type = attr(file, j, "type");
        if (!List.of("revolute", "continuous", "prismatic", "fixed").contains(type))
            throw err(file, j, "joint.type", "joint '" + name + "': unsupported type '" + type
                    + "'; robopro imports revolute, continuous, prismatic and fixed joints");
        String parent = linkRef(file, j, "parent", links, name);
        String child = linkRef(file, j, "child", links, name);
        if (parent.equals(child)) throw err(file, j, "joint.child", "joint '" + name + "' connects link '" + parent + "' to itself");
        Pose origin = Pose.IDENTITY;
        El o = single(file, j, "origin", false, name);
        if (o != null) {
            double[] xyz = vector(file, o, "xyz", name, new double[3]);
            double[] rpy = vector(file, o, "rpy", name, new double[3]);
            // URDF: fixed-axis roll, pitch, yaw: R = Rz(yaw) Ry(pitch) Rx(roll).
            origin = Pose.translation(xyz[0], xyz[1], xyz[2])
                    .times(Pose.rotZ(rpy[2])).times(Pose.rotY(rpy[1])).times(Pose.rotX(rpy[0]));
        }
        Vec3 axis = Vec3.X;
        El a = single(file, j, "axis", false, name);
        if (a != null) {
            double[] v = vector(file, a, "xyz", name, null);
            Vec3 av = new Vec3(v[0], v[1], v[2]);
            double n = av.norm();
            if (!(n > 1e-9) || !Double.isFinite(n)) throw err(file, a, "axis.xyz", "joint '" + name + "': axis must not be zero");
            axis = av.times(1 / n);
        }
        double lower = Double.NEGATIVE_INFINITY, upper = Double.POSITIVE_INFINITY, velocity = Double.POSITIVE_INFINITY;
        El lim = single(file, j, "limit", type.equals("revolute") || type.equals("prismatic"), name);
        if (lim != null && !type.equals("fixed")) {
            if (!type.equals("continuous")) {
                lower = scalar(file, lim, "lower", name, 0);
                upper = scalar(file, lim, "upper", name, 0);
                if (lower > upper) throw err(file, lim, "limit.lower", "joint '" + name + "': lower limit greater than upper");
            }
            velocity = scalar(file, lim, "velocity", name, Double.NaN);
            if (Double.isNaN(velocity))
                throw err(file, lim, "limit.velocity", "joint '" + name + "': missing attribute 'velocity'");
            if (velocity < 0) throw err(file, lim, "limit.velocity", "joint '" + name + "': velocity must not be negative");
            if (velocity == 0) velocity = Double.POSITIVE_INFINITY; // 0 is common in generated URDFs: unknown
        }
        String mimic = null;
        double multiplier = 1, offset = 0;
        El m = single(file, j, "mimic", false, name);
        if (m != null && !type.equals("fixed")) {
            mimic = attr(file, m, "joint");
            multiplier = scalar(file, m, "multiplier", name, 1);
            offset = scalar(file, m, "offset", name, 0);
            if (!Double.isFinite(multiplier) || !Double.isFinite(offset))
                throw err(file, m, "mimic", "joint '" + name + "': mimic multiplier and offset must be finite");
        }
        return new UJoint(j, name, type, parent, child, origin, axis, lower, upper, velocity, mimic, multiplier, offset);
    }

    private static String linkRef(String file, El j, String tag, Map<String, El> links, String joint) {
        El e = single(file, j, tag, true, joint);
        String l = attr(file, e, "link");
        if (!links.containsKey(l)) throw err(file, e, tag + ".link", "joint '" + joint + "': no link named '" + l + "'");
        return l;
    }

    private static El single(String file, El parent, String tag, boolean required, String joint) {
        List<El> l = parent.all(tag);
        if (l.size() > 1) throw err(file, l.get(1), tag, "joint '" + joint + "': <" + tag + "> given twice");
        if (l.isEmpty() && required) throw err(file, parent, tag, "joint '" + joint + "': missing <" + tag + ">");
        return l.isEmpty() ? null : l.get(0);
    }

    private static String attr(String file, El e, String name) {
        String v = e.attrs.get(name);
        if (v == null || v.isBlank()) throw err(file, e, e.name + "." + name, "missing attribute '" + name + "'");
        return v.trim();
    }

    private static double scalar(String file, El e, String name, String joint, double dflt) {
        String v = e.attrs.get(name);
        if (v == null) return dflt;
        return number(file, e, name, v.trim(), joint);
    }

    /** A three-number attribute; {@code dflt} null makes it required. */
    private static double[] vector(String file, El e, String name, String joint, double[] dflt) {
        String v = e.attrs.get(name);
        if (v == null) {
            if (dflt == null) throw err(file, e, e.name + "." + name, "joint '" + joint + "': missing attribute '" + name + "'");
            return dflt;
        }
        String[] parts = v.trim().split("\\s+");
        if (parts.length != 3)
            throw err(file, e, e.name + "." + name, "joint '" + joint + "': expected 3 numbers, got '" + v.trim() + "'");
        double[] r = new double[3];
        for (int i = 0; i < 3; i++) r[i] = number(file, e, name, parts[i], joint);
        return r;
    }

    private static double number(String file, El e, String name, String text, String joint) {
        if (!NUMBER.matcher(text).matches())
            throw err(file, e, e.name + "." + name, "joint '" + joint + "': '" + text + "' is not a number");
        double d = Double.parseDouble(text);
        if (!Double.isFinite(d)) throw err(file, e, e.name + "." + name, "joint '" + joint + "': number out of range");
        return d;
    }

    private static InputException err(String file, El e, String field, String problem) {
        return new InputException(file, e.line, e.column, field, problem);
    }
}
