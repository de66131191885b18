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
import org.robopro.app.workbench.model.PathChecker;
import org.robopro.app.workbench.model.ProgramRun;
import org.robopro.app.workbench.model.Target;
import org.robopro.app.workbench.model.TargetStatus;
import org.robopro.app.workbench.model.WorkbenchModel;

/**
 * Taught targets (a sphere and a TCP triad each: green when reachable, red when out of reach or
 * outside the joint limits) and the programmed TCP path as a polyline. The path check runs on the
 * {@link PathChecker}'s background thread; each finished check reaches this state through
 * {@code app.enqueue(() -> show(result))}, so the render thread only builds the geometry.
 */
public final class PathState extends BaseAppState {
    public static final int OK_RGB = 0x2E9E44;
    public static final int BAD_RGB = 0xE0241B;
    private final WorkbenchModel model;
    private final Node parent;
    private final Node node = new Node("path");
    private Shapes shapes;
    private volatile Map<String, TargetStatus> statuses = Map.of();
    private volatile ProgramRun plan;
    private PathChecker.Result result;
    private long shownRequest = -1;

    public PathState(WorkbenchModel model, Node parent) {
        this.model = model;
        this.parent = parent;
    }

    /** Target statuses as last drawn. */
    public Map<String, TargetStatus> statuses() { return statuses; }

    /** The program run last drawn (may be null before the first frame). */
    public ProgramRun plan() { return plan; }

    @Override protected void initialize(Application app) {
        shapes = new Shapes(app.getAssetManager());
        // Targets and paths are annotations, not things in the cell: they cast no shadow.
        node.setShadowMode(com.jme3.renderer.queue.RenderQueue.ShadowMode.Off);
        if (result != null) rebuild(result);
    }

    /** Shows a finished path check (render thread; a check older than the one shown is ignored). */
    public void show(PathChecker.Result r) {
        if (r.request() <= shownRequest) return;
        result = r;
        if (isInitialized()) rebuild(r);
    }

    /** The request number of the check drawn last (-1 before the first). */
    public long shownRequest() { return shownRequest; }
    @Override protected void cleanup(Application app) { }
    @Override protected void onEnable() { parent.attachChild(node); }
    @Override protected void onDisable() { node.removeFromParent(); }

    @Override
    public void update(float tpf) {
        node.setCullHint(model.showPath() ? Spatial.CullHint.Inherit : Spatial.CullHint.Always);
        boolean shown = model.frameShown(org.robopro.app.workbench.model.WorkbenchModel.FrameKind.TARGETS);
        if (shown != triadsShown) {
            triadsShown = shown;
            if (triads != null) triads.setCullHint(shown ? Spatial.CullHint.Inherit : Spatial.CullHint.Always);
        }
    }

    private boolean triadsShown = true;
    private Node triads;
    private static final float TRIAD_LENGTH = 0.07f;

    /** One target ball, shared by every target's (culled) pick geometry. */
    private static final Sphere BALL = new Sphere(8, 10, 0.025f);

    /** Copies of {@link #BALL} at each target frame, merged into one mesh. */
    private Geometry balls(String name, List<com.jme3.math.Transform> frames, int rgb) {
        Geometry g = new Geometry(name, Shapes.copies(BALL, frames));
        g.setMaterial(shapes.lit(rgb));
        return g;
    }

    private void rebuild(PathChecker.Result r) {
        shownRequest = r.request();
        node.detachAllChildren();
        List<Target> targets = r.targets();
        ProgramRun p = r.run();
        plan = p;
        Map<String, TargetStatus> st = r.statuses();
        List<com.jme3.math.Transform> frames = new java.util.ArrayList<>(), okFrames = new java.util.ArrayList<>(),
                badFrames = new java.util.ArrayList<>();
        for (Target t : targets) {
            TargetStatus s = st.getOrDefault(t.name(), TargetStatus.REACHABLE);
            Node tn = new Node("target-" + t.name());
            tn.setUserData("pick", "target:" + t.name());
            Shapes.apply(t.worldTtcp(), tn);
            // The ball stays in the graph for picking and the selection outline; it is drawn as part
            // of one merged mesh per colour below (one draw call instead of one per target).
            Geometry ball = new Geometry("target-" + t.name() + "-ball", BALL);
            ball.setMaterial(shapes.lit(s.ok() ? OK_RGB : BAD_RGB));
            ball.setCullHint(Spatial.CullHint.Always);
            tn.attachChild(ball);
            // Like the ball: kept for the selection outline, drawn by the merged triads below.
            Node axes = shapes.axes("target-" + t.name() + "-axes", TRIAD_LENGTH);
            axes.setCullHint(Spatial.CullHint.Always);
            tn.attachChild(axes);
            frames.add(tn.getLocalTransform().clone());
            (s.ok() ? okFrames : badFrames).add(frames.get(frames.size() - 1));
            node.attachChild(tn);
            // The target's name beside it, facing the camera.
            Node label = shapes.label("label-" + t.name(), t.name(), 0.05f, s.ok() ? 0x1B3A1F : 0x8B1A1A);
            label.setLocalTranslation(Shapes.v(t.worldTtcp().position()).add(0.025f, 0, 0.03f));
            node.attachChild(label);
        }
        if (!okFrames.isEmpty()) node.attachChild(balls("target-balls-ok", okFrames, OK_RGB));
        if (!badFrames.isEmpty()) node.attachChild(balls("target-balls-bad", badFrames, BAD_RGB));
        triads = shapes.mergedAxes("target-triads", frames, TRIAD_LENGTH);
        triads.setCullHint(triadsShown ? Spatial.CullHint.Inherit : Spatial.CullHint.Always);
        node.attachChild(triads);
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
        List<org.robopro.app.workbench.model.Instruction> program = r.program();
        Map<String, Target> byName = new java.util.HashMap<>();
        for (Target t : targets) byName.put(t.name(), t);
        for (ProgramRun.Step s : p.steps()) {
            if (s.ok() || s.index() == 0 || s.index() >= program.size()) continue;
            var from = java.util.Optional.ofNullable(byName.get(program.get(s.index() - 1).target()));
            var to = java.util.Optional.ofNullable(byName.get(s.instruction().target()));
            if (from.isEmpty() || to.isEmpty()) continue;
            node.attachChild(shapes.beam("path-fail", Shapes.v(from.get().worldTtcp().position()),
                    Shapes.v(to.get().worldTtcp().position()), 0.004f, shapes.flat(BAD_RGB, false)));
        }
    }

}
