package org.robopro.app.workbench.scene;

import com.jme3.app.Application;
import com.jme3.app.state.BaseAppState;
import com.jme3.material.Material;
import com.jme3.math.Vector3f;
import com.jme3.scene.Geometry;
import com.jme3.scene.Node;
import com.jme3.scene.Spatial;
import java.util.List;
import org.robopro.app.workbench.model.DefaultCell;
import org.robopro.app.workbench.model.RobotKinematics;
import org.robopro.app.workbench.model.ShippedMeshes;
import org.robopro.app.workbench.model.Tool;
import org.robopro.app.workbench.model.WorkbenchModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.JointDescription;
import org.robopro.models.RobotDescription;
import org.robopro.models.Vec3;

/**
 * The robot as the seed paper's "graphic tree" (§6: each tree node a transform group for one
 * link): nested nodes base -> link 1 -> ... -> link n -> flange -> tool, each link's local
 * transform the relative displacement of its joint, driven each frame from the model's joint
 * values. Each link is drawn from the robot file's meshes, else robopro's shipped meshes (IRB 2400,
 * PUMA 560), else the IRB 2000's procedural model ({@link Irb2000Model}), else built-in shapes
 * (beams between joint points, joint housings); optional frame axes (Fig. 8 view).
 */
public final class RobotState extends BaseAppState {
    private static final int HOUSING = 0x3A3F47;
    private final WorkbenchModel model;
    private final Node parent;
    private final Node robotRoot = new Node("robot");
    private Shapes shapes;
    private Node[] links = new Node[0];
    private Node toolNode;
    private RobotKinematics builtFor;
    private Tool toolBuiltFor;
    private long jointVersion = -1;
    private java.util.Set<WorkbenchModel.FrameKind> framesShown;
    /** The IRB 2000's parallel-arm linkage, posed each frame; null for other robots. */
    private Irb2000Model linkage;

    /** {@code robotMeshes} resolves a robot file's mesh path (relative to the robot file), or null when it cannot. */
    public RobotState(WorkbenchModel model, Node parent, java.util.function.Function<String, java.nio.file.Path> robotMeshes) {
        this(model, parent, robotMeshes, false);
    }

    /**
     * With {@code ghost}, draws the joints read from the real controller ({@link WorkbenchModel#ghostQ()})
     * as a translucent blue copy, hidden while there are none.
     */
    public RobotState(WorkbenchModel model, Node parent, java.util.function.Function<String, java.nio.file.Path> robotMeshes,
                      boolean ghost) {
        this.model = model;
        this.parent = parent;
        this.robotMeshes = robotMeshes;
        this.ghost = ghost;
        if (ghost) robotRoot.setName("robot-ghost");
    }

    private final boolean ghost;

    private final java.util.function.Function<String, java.nio.file.Path> robotMeshes;

    /** The link nodes (0 = base), for tests and picking. */
    public Node[] links() { return links.clone(); }

    @Override protected void initialize(Application app) { shapes = new Shapes(app.getAssetManager()); }
    @Override protected void cleanup(Application app) { }
    @Override protected void onEnable() { parent.attachChild(robotRoot); }
    @Override protected void onDisable() { robotRoot.removeFromParent(); }

    @Override
    public void update(float tpf) {
        RobotKinematics k = model.kinematics();
        Tool tool = model.tool();
        if (k != builtFor || tool != toolBuiltFor) {
            build(k, tool);
            if (ghost) ghostify(robotRoot, shapes.ghost(0x3D7DFF));
            builtFor = k;
            toolBuiltFor = tool;
            jointVersion = -1;
        }
        Shapes.apply(model.worldTbase(), robotRoot);
        double[] ghostQ = ghost ? model.ghostQ() : null;
        boolean hidden = model.preview() != null || (ghost && (ghostQ == null || ghostQ.length != k.dof()));
        robotRoot.setCullHint(hidden ? Spatial.CullHint.Always : Spatial.CullHint.Inherit);
        if (hidden) return;
        long jv = ghost ? model.ghostVersion() : model.jointVersion();
        if (jv != jointVersion) {
            jointVersion = jv;
            Pose[] d = k.linkDisplacements(ghost ? ghostQ : model.q());
            for (int i = 1; i < links.length; i++) Shapes.apply(d[i - 1].inverse().times(d[i]), links[i]);
            if (linkage != null) linkage.pose(links[3]);
        }
        if (model.shownFrames() != framesShown) {
            framesShown = model.shownFrames();
            setFramesVisible(robotRoot, framesShown);
        }
    }

    private static void ghostify(Spatial s, com.jme3.material.Material m) {
        if (s instanceof com.jme3.scene.Geometry g) {
            g.setMaterial(m);
            g.setQueueBucket(com.jme3.renderer.queue.RenderQueue.Bucket.Transparent);
            g.setUserData("pick", null);
        } else if (s instanceof Node n) {
            if (n.getName() != null && n.getName().startsWith("frame")) n.removeFromParent();
            else for (Spatial c : List.copyOf(n.getChildren())) ghostify(c, m);
        }
    }

    /** Shows each of the robot's frames whose kind is in {@code shown}: frame-base, frame-jN, frame-flange, frame-tcp. */
    private static void setFramesVisible(Node n, java.util.Set<WorkbenchModel.FrameKind> shown) {
        for (Spatial s : n.getChildren()) {
            String name = s.getName();
            if (name != null && name.startsWith("frame-")) {
                WorkbenchModel.FrameKind k = name.equals("frame-base") ? WorkbenchModel.FrameKind.BASE
                        : name.equals("frame-flange") ? WorkbenchModel.FrameKind.FLANGE
                        : name.equals("frame-tcp") ? WorkbenchModel.FrameKind.TCP : WorkbenchModel.FrameKind.JOINTS;
                s.setCullHint(shown.contains(k) ? Spatial.CullHint.Inherit : Spatial.CullHint.Always);
            }
            if (s instanceof Node c) setFramesVisible(c, shown);
        }
    }

    private void build(RobotKinematics k, Tool tool) {
        robotRoot.detachAllChildren();
        linkage = null;
        RobotDescription d = k.description();
        int n = d.dof();
        List<JointDescription> js = d.joints();
        Pose flangeZero = Pose.fromFrame(d.flange());
        double reach = Math.max(0.3, flangeZero.position().norm());
        float r1 = (float) (0.075 * reach);
        Material orange = shapes.lit(DefaultCell.ABB_ORANGE);
        Material housing = shapes.lit(HOUSING);
        links = new Node[n + 1];
        Node prev = robotRoot;
        for (int i = 0; i <= n; i++) {
            links[i] = new Node(i == 0 ? "base" : "link" + i);
            links[i].setUserData("pick", "link:" + i);
            prev.attachChild(links[i]);
            prev = links[i];
        }
        // Base: a plinth and a pedestal around axis 1.
        Vector3f a1 = Shapes.v(js.get(0).point());
        float plinthH = (float) Math.min(0.22, 0.25 * Math.max(0.2, js.size() > 1 ? js.get(1).point().z() : 0.5));
        java.util.Set<Integer> meshed = attachMeshes(d);
        if (!meshed.contains(0)) links[0].attachChild(shapes.box("base-plinth", new Vector3f(a1.x - 2.1f * r1, a1.y - 2.1f * r1, 0),
                new Vector3f(a1.x + 2.1f * r1, a1.y + 2.1f * r1, plinthH * 0.35f), housing));
        if (!meshed.contains(0)) links[0].attachChild(shapes.beam("base-pedestal", new Vector3f(a1.x, a1.y, plinthH * 0.35f),
                new Vector3f(a1.x, a1.y, plinthH), 1.5f * r1, orange));
        for (int i = 1; i <= n; i++) {
            if (meshed.contains(i)) {
                if (i < n) links[i].attachChild(frameAxes("frame-j" + (i + 1), Shapes.v(js.get(i).point()), js.get(i).axis(), r1 * 3.2f));
                continue;
            }
            float r = r1 * (float) Math.max(0.38, 1 - 0.15 * (i - 1));
            Vector3f a = i == 1 ? new Vector3f(a1.x, a1.y, plinthH) : Shapes.v(js.get(i - 1).point());
            Vector3f b = i < n ? Shapes.v(js.get(i).point()) : Shapes.v(flangeZero.position());
            if (i == 1 && n > 1) {
                // The turret stands on axis 1 and reaches up to axis 2.
                b = new Vector3f(a1.x, a1.y, b.z);
            }
            if (b.distance(a) > 0.01f) links[i].attachChild(shapes.beam("link" + i + "-beam", a, b, r, orange));
            if (i == 1 && n > 1) {
                Vector3f p2 = Shapes.v(js.get(1).point());
                if (p2.distance(b) > 0.01f) links[1].attachChild(shapes.beam("link1-arm", b, p2, r * 0.8f, orange));
            }
            if (i < n) {
                // The next joint's housing (motor, gearbox) sits on this link.
                JointDescription next = js.get(i);
                Vector3f c = Shapes.v(next.point());
                links[i].attachChild(shapes.disc("joint" + (i + 1) + "-housing", c, Shapes.v(next.axis()),
                        r * 1.12f, 2.3f * r, i >= 3 ? housing : orange));
                links[i].attachChild(frameAxes("frame-j" + (i + 1), c, next.axis(), r1 * 3.2f));
            }
        }
        links[0].attachChild(frameAxes("frame-j1", a1, js.get(0).axis(), r1 * 3.2f));
        // Flange and tool on the last link, at the flange's zero pose.
        Node flangeNode = new Node("flange");
        Shapes.apply(flangeZero, flangeNode);
        links[n].attachChild(flangeNode);
        float fr = Math.max(0.03f, r1 * 0.45f);
        flangeNode.attachChild(shapes.disc("flange-disc", new Vector3f(0, 0, -0.01f), Vector3f.UNIT_Z, fr, 0.02f, housing));
        Node fa = shapes.axes("frame-flange", r1 * 2.5f);
        flangeNode.attachChild(fa);
        toolNode = new Node("tool");
        toolNode.setUserData("pick", "tool");
        flangeNode.attachChild(toolNode);
        buildTool(tool);
        robotRoot.attachChild(shapes.axes("frame-base", r1 * 4f));
        framesShown = null;
    }

    /**
     * The robot file's meshes (STL/OBJ/glTF), each on its link; meshes in base coordinates at the
     * zero position hang directly on the link node (its transform is the link's displacement).
     * Returns the links that got a mesh (they get no built-in shapes).
     */
    private java.util.Set<Integer> attachMeshes(RobotDescription d) {
        java.util.Set<Integer> done = new java.util.HashSet<>();
        for (org.robopro.models.MeshRef m : d.meshes()) {
            if (m.link() < 0 || m.link() >= links.length || m.inLinkFrame()) continue; // link-frame meshes need the module's link frames
            java.nio.file.Path file = robotMeshes.apply(m.path());
            if (file == null) continue;
            try {
                String name = file.getFileName().toString().toLowerCase(java.util.Locale.ROOT);
                Spatial s;
                if (name.endsWith(".stl")) {
                    s = new Geometry("mesh-" + m.path(), StlReader.read(file, (float) m.scale()));
                } else {
                    var am = getApplication().getAssetManager();
                    String dir = file.toAbsolutePath().getParent().toString();
                    am.registerLocator(dir, com.jme3.asset.plugins.FileLocator.class);
                    try {
                        s = am.loadModel(file.getFileName().toString());
                    } finally {
                        am.unregisterLocator(dir, com.jme3.asset.plugins.FileLocator.class);
                    }
                    s.setLocalScale((float) m.scale());
                }
                if (!name.endsWith(".gltf") && !name.endsWith(".glb")) s.setMaterial(shapes.lit(DefaultCell.ABB_ORANGE));
                links[m.link()].attachChild(s);
                done.add(m.link());
            } catch (java.io.IOException | RuntimeException e) {
                java.util.logging.Logger.getLogger(RobotState.class.getName())
                        .warning("robot mesh " + m.path() + " not drawn (built-in shape instead): " + e.getMessage());
            }
        }
        if (done.isEmpty()) done.addAll(attachShippedMeshes(d));
        return done;
    }

    /**
     * The shipped meshes of a robot whose file names none, in base coordinates at the zero
     * position like a robot file's own meshes; also drawn for its calibrated variants. Returns
     * the links that got one.
     */
    private java.util.Set<Integer> attachShippedMeshes(RobotDescription d) {
        java.util.Set<Integer> done = new java.util.HashSet<>();
        for (String robot : ShippedMeshes.robotOf(d).stream().toList()) {
            for (ShippedMeshes.Part part : ShippedMeshes.BY_ROBOT.get(robot)) {
                String res = ShippedMeshes.resource(robot, part);
                try (java.io.InputStream in = RobotState.class.getResourceAsStream(res)) {
                    if (in == null) continue;
                    Geometry g = new Geometry("mesh-" + part.file(), StlReader.read(in.readAllBytes(), java.nio.file.Path.of(res), 1f));
                    g.setMaterial(shapes.lit(part.rgb()));
                    links[part.link()].attachChild(g);
                    done.add(part.link());
                } catch (java.io.IOException | RuntimeException ex) {
                    java.util.logging.Logger.getLogger(RobotState.class.getName()).warning("shipped mesh " + res + " not drawn: " + ex.getMessage());
                }
            }
        }
        if (done.isEmpty() && Irb2000Model.fits(d)) {
            linkage = Irb2000Model.build(d, links, shapes);
            for (int i = 0; i <= d.dof(); i++) done.add(i);
        }
        return done;
    }

    private Node frameAxes(String name, Vector3f origin, Vec3 zAxis, float len) {
        Node a = shapes.axes(name, len);
        a.setLocalTranslation(origin);
        a.setLocalRotation(Shapes.alignZ(Shapes.v(zAxis)));
        return a;
    }

    private void buildTool(Tool tool) {
        toolNode.detachAllChildren();
        if (tool.bodyLength() <= 0 && tool.flangeTtcp().position().norm() < 1e-6) return;
        Material body = shapes.lit(0x2B2F36);
        Material tip = shapes.lit(0xC9A227);
        float r = (float) tool.bodyRadius();
        float len = (float) tool.bodyLength();
        toolNode.attachChild(shapes.beam("tool-body", Vector3f.ZERO, new Vector3f(0, 0, len), r, body));
        Vector3f tcp = Shapes.v(tool.flangeTtcp().position());
        Vector3f end = new Vector3f(0, 0, len);
        if (tcp.distance(end) > 0.005f) toolNode.attachChild(shapes.beam("tool-tip", end, tcp, r * 0.35f, tip));
        Node tcpAxes = shapes.axes("frame-tcp", 0.12f);
        Shapes.apply(tool.flangeTtcp(), tcpAxes);
        toolNode.attachChild(tcpAxes);
        Geometry dot = shapes.disc("tool-tcp", tcp, Shapes.v(tool.flangeTtcp().zAxis()), r * 0.5f, 0.004f, shapes.lit(0xE53935));
        toolNode.attachChild(dot);
    }
}
