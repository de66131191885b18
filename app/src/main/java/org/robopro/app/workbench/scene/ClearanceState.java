package org.robopro.app.workbench.scene;

import com.jme3.app.Application;
import com.jme3.app.state.BaseAppState;
import com.jme3.material.Material;
import com.jme3.material.RenderState;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import com.jme3.renderer.queue.RenderQueue;
import com.jme3.scene.Geometry;
import com.jme3.scene.Node;
import com.jme3.scene.shape.Sphere;
import java.util.Map;
import java.util.Optional;
import org.robopro.app.workbench.LiveClearance;
import org.robopro.app.workbench.model.CellObject;
import org.robopro.app.workbench.model.WorkbenchModel;
import org.robopro.kinematics.Pose;
import org.robopro.programs.collision.Convex;

/**
 * The live collision view while jogging or scrubbing: the collision shapes of every robot part
 * and cell object in contact (translucent red) or closer than {@link LiveClearance#NEAR_M}
 * (amber) are drawn over the scene: the link or tool capsule the checker uses, the object's box
 * or cylinder slightly enlarged. The reading is taken at most every {@link #PERIOD_S} and only
 * when the joints or the cell changed, so the per-frame cost is nil while nothing moves and a
 * fraction of a millisecond while jogging.
 */
public final class ClearanceState extends BaseAppState {
    public static final int COLLIDING_RGB = 0xE0241B;
    public static final int NEAR_RGB = 0xF2A516;
    /** Shortest time between two readings, s. */
    public static final float PERIOD_S = 1 / 30f;
    private final WorkbenchModel model;
    private final LiveClearance clearance;
    private final Node parent;
    private final Node node = new Node("clearance");
    private Material red, amber;
    private Shapes shapes;
    private long shownJoints = -1;
    private Object shownCell;
    private float sinceRead;
    private volatile Optional<LiveClearance.Reading> shown = Optional.empty();

    public ClearanceState(WorkbenchModel model, LiveClearance clearance, Node parent) {
        this.model = model;
        this.clearance = clearance;
        this.parent = parent;
    }

    /** The reading drawn last (empty before the first, or without a kinematic model). */
    public Optional<LiveClearance.Reading> shown() { return shown; }

    @Override protected void initialize(Application app) {
        shapes = new Shapes(app.getAssetManager());
        node.setShadowMode(com.jme3.renderer.queue.RenderQueue.ShadowMode.Off); // highlights, not bodies
        red = translucent(app, COLLIDING_RGB);
        amber = translucent(app, NEAR_RGB);
    }

    private static Material translucent(Application app, int rgb) {
        Material m = new Material(app.getAssetManager(), "Common/MatDefs/Misc/Unshaded.j3md");
        ColorRGBA c = Shapes.color(rgb);
        c.a = 0.45f;
        m.setColor("Color", c);
        m.getAdditionalRenderState().setBlendMode(RenderState.BlendMode.Alpha);
        m.getAdditionalRenderState().setDepthWrite(false);
        return m;
    }

    @Override protected void cleanup(Application app) { }
    @Override protected void onEnable() { parent.attachChild(node); }
    @Override protected void onDisable() { node.removeFromParent(); }

    @Override
    public void update(float tpf) {
        sinceRead += tpf;
        long joints = model.jointVersion();
        Object cell = model.objects();
        if ((joints == shownJoints && cell == shownCell) || sinceRead < PERIOD_S) return;
        sinceRead = 0;
        shownJoints = joints;
        shownCell = cell;
        Optional<LiveClearance.Reading> r = clearance.current();
        shown = r;
        node.detachAllChildren();
        if (r.isEmpty()) return;
        Map<String, LiveClearance.Level> hl = r.get().highlights();
        if (hl.isEmpty()) return;
        Pose worldTbase = model.worldTbase();
        Map<String, Convex.Capsule> robot = clearance.robotShapes(r.get().q());
        for (Map.Entry<String, LiveClearance.Level> e : hl.entrySet()) {
            Material m = e.getValue() == LiveClearance.Level.COLLIDING ? red : amber;
            String part = e.getKey();
            Convex.Capsule c = robot.get(part);
            if (c != null) {
                Vector3f a = Shapes.v(worldTbase.apply(c.a())), b = Shapes.v(worldTbase.apply(c.b()));
                float rad = (float) c.radius();
                node.attachChild(shapes.beam("clearance-" + part, a, b, rad, m));
                for (Vector3f end : new Vector3f[] {a, b}) {
                    Geometry s = new Geometry("clearance-" + part + "-end", new Sphere(10, 16, rad));
                    s.setMaterial(m);
                    s.setLocalTranslation(end);
                    node.attachChild(s);
                }
            } else if (part.startsWith("object:")) {
                model.object(part.substring(7)).ifPresent(o -> node.attachChild(object(o, m)));
            }
        }
        for (var ch : node.getChildren()) ch.setQueueBucket(RenderQueue.Bucket.Transparent);
    }

    /** The object's collision shape, 5 mm larger all round so it shows over the object itself. */
    private Node object(CellObject o, Material m) {
        Node n = new Node("clearance-object-" + o.id());
        Shapes.apply(o.worldTobject().times(Pose.translation(0, 0, -0.005)), n);
        if (o.kind() == CellObject.Kind.CYLINDER)
            n.attachChild(shapes.beam("clearance-" + o.id(), Vector3f.ZERO, new Vector3f(0, 0, (float) o.size().z() + 0.01f),
                    (float) (Math.max(o.size().x(), o.size().y()) / 2 + 0.005), m));
        else n.attachChild(shapes.standingBox("clearance-" + o.id(), o.size().plus(new org.robopro.models.Vec3(0.01, 0.01, 0.01)), m));
        return n;
    }
}
