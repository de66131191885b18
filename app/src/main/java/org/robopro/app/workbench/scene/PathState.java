package org.robopro.app.workbench.scene;

import com.jme3.app.Application;
import com.jme3.app.state.BaseAppState;
import com.jme3.scene.Geometry;
import com.jme3.scene.Mesh;
import com.jme3.scene.Node;
import com.jme3.scene.Spatial;
import com.jme3.scene.VertexBuffer;
import com.jme3.scene.shape.Sphere;
import com.jme3.util.BufferUtils;
import java.util.List;
import java.util.Map;
import org.robopro.app.workbench.model.ProgramRun;
import org.robopro.app.workbench.model.Target;
import org.robopro.app.workbench.model.TargetStatus;
import org.robopro.app.workbench.model.WorkbenchModel;

/**
 * Taught targets (a sphere and a TCP triad each: green when reachable, red when out of reach or
 * outside the joint limits) and the programmed TCP path as a polyline, recomputed when the
 * targets, program, robot, tool or placement change.
 */
public final class PathState extends BaseAppState {
    public static final int OK_RGB = 0x2E9E44;
    public static final int BAD_RGB = 0xE0241B;
    private final WorkbenchModel model;
    private final Node parent;
    private final Node node = new Node("path");
    private Shapes shapes;
    private long builtVersion = -1;
    private volatile Map<String, TargetStatus> statuses = Map.of();
    private volatile ProgramRun plan;

    public PathState(WorkbenchModel model, Node parent) {
        this.model = model;
        this.parent = parent;
    }

    /** Target statuses as last drawn. */
    public Map<String, TargetStatus> statuses() { return statuses; }

    /** The program run last drawn (may be null before the first frame). */
    public ProgramRun plan() { return plan; }

    @Override protected void initialize(Application app) { shapes = new Shapes(app.getAssetManager()); }
    @Override protected void cleanup(Application app) { }
    @Override protected void onEnable() { parent.attachChild(node); }
    @Override protected void onDisable() { node.removeFromParent(); }

    @Override
    public void update(float tpf) {
        node.setCullHint(model.showPath() ? Spatial.CullHint.Inherit : Spatial.CullHint.Always);
        long v = model.version();
        if (v == builtVersion) return;
        builtVersion = v;
        node.detachAllChildren();
        List<Target> targets = model.targets();
        ProgramRun p = model.programRun();
        plan = p;
        Map<String, TargetStatus> st = model.statuses();
        for (Target t : targets) {
            TargetStatus s = st.getOrDefault(t.name(), TargetStatus.REACHABLE);
            Node tn = new Node("target-" + t.name());
            tn.setUserData("pick", "target:" + t.name());
            Shapes.apply(t.worldTtcp(), tn);
            Geometry ball = new Geometry("target-" + t.name() + "-ball", new Sphere(12, 16, 0.025f));
            ball.setMaterial(shapes.lit(s.ok() ? OK_RGB : BAD_RGB));
            tn.attachChild(ball);
            tn.attachChild(shapes.axes("target-" + t.name() + "-axes", 0.07f));
            node.attachChild(tn);
        }
        statuses = Map.copyOf(st);
        if (p.sampleCount() >= 2) {
            float[] pts = new float[p.sampleCount() * 3];
            for (int i = 0; i < p.sampleCount(); i++) {
                pts[3 * i] = (float) p.tcp(i).x();
                pts[3 * i + 1] = (float) p.tcp(i).y();
                pts[3 * i + 2] = (float) p.tcp(i).z();
            }
            Mesh m = new Mesh();
            m.setMode(Mesh.Mode.LineStrip);
            m.setBuffer(VertexBuffer.Type.Position, 3, BufferUtils.createFloatBuffer(pts));
            m.setLineWidth(3f);
            m.updateBound();
            Geometry line = new Geometry("path-line", m);
            line.setMaterial(shapes.flat(p.ok() ? 0xF2C12E : BAD_RGB, true));
            line.setQueueBucket(com.jme3.renderer.queue.RenderQueue.Bucket.Transparent);
            node.attachChild(line);
        }
        // Straight dashes between consecutive program targets whose move failed, so the gap is visible.
        List<org.robopro.app.workbench.model.Instruction> program = model.program();
        for (ProgramRun.Step s : p.steps()) {
            if (s.ok() || s.index() == 0 || s.index() >= program.size()) continue;
            var from = model.target(program.get(s.index() - 1).target());
            var to = model.target(s.instruction().target());
            if (from.isEmpty() || to.isEmpty()) continue;
            node.attachChild(shapes.beam("path-fail", Shapes.v(from.get().worldTtcp().position()),
                    Shapes.v(to.get().worldTtcp().position()), 0.004f, shapes.flat(BAD_RGB, false)));
        }
    }

}
