package org.robopro.app.workbench.scene;

import com.jme3.app.Application;
import com.jme3.app.SimpleApplication;
import com.jme3.app.state.BaseAppState;
import com.jme3.light.AmbientLight;
import com.jme3.light.DirectionalLight;
import com.jme3.material.Material;
import com.jme3.math.ColorRGBA;
import com.jme3.math.FastMath;
import com.jme3.math.Vector3f;
import com.jme3.renderer.queue.RenderQueue.ShadowMode;
import com.jme3.scene.Geometry;
import com.jme3.scene.Node;
import com.jme3.scene.Spatial;
import com.jme3.bounding.BoundingBox;
import com.jme3.scene.debug.Grid;
import com.jme3.scene.shape.Quad;
import com.jme3.shadow.DirectionalLightShadowRenderer;
import com.jme3.shadow.EdgeFilteringMode;
import org.robopro.app.workbench.model.WorkbenchModel;

/**
 * Lights, background, floor and floor grid (1 m and 0.25 m lines), all in the jME y-up root;
 * and the key light's shadows (View → Shadows): one 1024² shadow map over the nearest 12 m of
 * the view, bilinear edges, cast by the robot, tool and cell objects (not by targets, paths or
 * frames) onto the floor. A software rasteriser pays per pixel (docs/performance.md), so the
 * floor is drawn unlit in its lit colour, and only a patch of it under where the casters'
 * shadows can fall takes the shadow pass.
 */
public final class EnvironmentState extends BaseAppState {
    private final WorkbenchModel model;
    private final Node env = new Node("environment");
    private final AmbientLight ambient = new AmbientLight(new ColorRGBA(0.45f, 0.46f, 0.5f, 1));
    private final DirectionalLight key = new DirectionalLight(new Vector3f(-0.5f, -1f, -0.35f).normalizeLocal(),
            new ColorRGBA(0.85f, 0.83f, 0.8f, 1));
    private final DirectionalLight fill = new DirectionalLight(new Vector3f(0.6f, -0.4f, 0.7f).normalizeLocal(),
            new ColorRGBA(0.35f, 0.37f, 0.42f, 1));
    /** Shadow map size in pixels (square); -Drobopro.shadowMap to compare. */
    private static final int SHADOW_MAP = Integer.getInteger("robopro.shadowMap", 1024);
    private DirectionalLightShadowRenderer shadows;
    private boolean shadowsOn;
    private static final int FLOOR = 0xA9AEB5;
    /** The part of the floor that receives shadows (the rest takes no shadow pass), floor-coloured. */
    private Geometry patch;

    public EnvironmentState(WorkbenchModel model) { this.model = model; }

    @Override
    protected void initialize(Application app) {
        Shapes s = new Shapes(app.getAssetManager());
        app.getViewPort().setBackgroundColor(new ColorRGBA(0.80f, 0.83f, 0.87f, 1));
        Geometry floor = new Geometry("floor", new Quad(12, 12));
        // The floor is flat and the lights directional, so its lit colour is one colour: drawn
        // unlit in that colour (Shapes.lit's diffuse and ambient terms, no highlight), it costs a
        // software rasteriser a fraction of the per-pixel lighting over most of the view.
        ColorRGBA c = Shapes.color(FLOOR);
        ColorRGBA sum = ambient.getColor().mult(Shapes.AMBIENT);
        for (DirectionalLight l : new DirectionalLight[] {key, fill})
            sum.addLocal(l.getColor().mult(Math.max(0, -l.getDirection().y)));
        Material floorMat = new Material(app.getAssetManager(), "Common/MatDefs/Misc/Unshaded.j3md");
        floorMat.setColor("Color", new ColorRGBA(Math.min(1, c.r * sum.r), Math.min(1, c.g * sum.g), Math.min(1, c.b * sum.b), 1));
        floor.setMaterial(floorMat);
        floor.rotate(-FastMath.HALF_PI, 0, 0);
        floor.setLocalTranslation(-6, -0.002f, 6);
        floor.setShadowMode(ShadowMode.Off);
        env.attachChild(floor);
        patch = new Geometry("floor-shadow", new Quad(1, 1));
        patch.setMaterial(floorMat);
        patch.rotate(-FastMath.HALF_PI, 0, 0);
        patch.setShadowMode(ShadowMode.Receive);
        env.attachChild(patch);
        Geometry fine = new Geometry("grid-fine", new Grid(49, 49, 0.25f));
        fine.setMaterial(s.flat(0x9298A0, false));
        fine.setLocalTranslation(-6, 0, -6);
        fine.setShadowMode(ShadowMode.Off);
        env.attachChild(fine);
        Geometry coarse = new Geometry("grid", new Grid(13, 13, 1f));
        coarse.setMaterial(s.flat(0x6F757D, false));
        coarse.setLocalTranslation(-6, 0.001f, -6);
        coarse.setShadowMode(ShadowMode.Off);
        env.attachChild(coarse);
        shadows = new DirectionalLightShadowRenderer(app.getAssetManager(), SHADOW_MAP, 1);
        shadows.setLight(key);
        shadows.setShadowIntensity(0.45f);
        shadows.setEdgeFilteringMode(EdgeFilteringMode.Bilinear);
        shadows.setShadowZExtend(12f);
        shadows.setShadowZFadeLength(2f);
    }

    @Override protected void cleanup(Application app) { }

    /** After every state has posed its objects: fits the shadow patch to this frame's casters. */
    @Override
    public void render(com.jme3.renderer.RenderManager rm) {
        if (!shadowsOn) {
            if (patch.getCullHint() != Spatial.CullHint.Always) patch.setCullHint(Spatial.CullHint.Always);
            return;
        }
        // The scene's geometric state is brought up to date again only when the patch changed.
        if (fitPatch()) ((SimpleApplication) getApplication()).getRootNode().updateGeometricState();
    }

    /** Floor-plane extent (x0, z0, x1, z1) of the casters' shadows, grown by {@link #sweep}. */
    private final float[] box = new float[4];
    /** The patch's extent (x0, z0, x1, z1) as last set on it; NaN until it is first set. */
    private final float[] shown = {Float.NaN, Float.NaN, Float.NaN, Float.NaN};

    /** Grows {@link #box} by the shadow of every visible caster under {@code s} along {@code d}. */
    private void sweep(Spatial s, Vector3f d) {
        if (s.getShadowMode() == ShadowMode.Off || s.getShadowMode() == ShadowMode.Receive || s.getCullHint() == Spatial.CullHint.Always) return;
        if (s instanceof Node n) {
            for (Spatial c : n.getChildren()) sweep(c, d);
            return;
        }
        if (!(s.getWorldBound() instanceof BoundingBox b)) return;
        Vector3f c = b.getCenter();
        for (int k = 0; k < 8; k++) {
            float x = c.x + ((k & 1) == 0 ? -b.getXExtent() : b.getXExtent());
            float y = Math.max(0, c.y + ((k & 2) == 0 ? -b.getYExtent() : b.getYExtent()));
            float z = c.z + ((k & 4) == 0 ? -b.getZExtent() : b.getZExtent());
            float t = y / -d.y; // to the floor along the light
            box[0] = Math.min(box[0], Math.min(x, x + t * d.x));
            box[2] = Math.max(box[2], Math.max(x, x + t * d.x));
            box[1] = Math.min(box[1], Math.min(z, z + t * d.z));
            box[3] = Math.max(box[3], Math.max(z, z + t * d.z));
        }
    }

    /**
     * Sizes the shadow-receiving floor patch to where the casters' shadows can fall: the
     * casters' bounding box swept along the key light down to the floor, plus a margin, clipped
     * to the floor. The rest of the floor takes no shadow pass. Returns whether the patch changed
     * (shown or hidden, moved or resized); a patch that still fits is left untouched.
     */
    private boolean fitPatch() {
        Node root = ((SimpleApplication) getApplication()).getRootNode();
        box[0] = box[1] = Float.MAX_VALUE;
        box[2] = box[3] = -Float.MAX_VALUE;
        for (Spatial s : root.getChildren()) if (s != env) sweep(s, key.getDirection());
        float x0 = box[0], z0 = box[1], x1 = box[2], z1 = box[3];
        float m = 0.1f;
        x0 = Math.max(-6, x0 - m); z0 = Math.max(-6, z0 - m); x1 = Math.min(6, x1 + m); z1 = Math.min(6, z1 + m);
        boolean empty = x1 <= x0 || z1 <= z0;
        Spatial.CullHint hint = empty ? Spatial.CullHint.Always : Spatial.CullHint.Inherit;
        boolean changed = patch.getCullHint() != hint;
        if (changed) patch.setCullHint(hint);
        if (empty || (x0 == shown[0] && z0 == shown[1] && x1 == shown[2] && z1 == shown[3])) return changed;
        patch.setLocalScale(x1 - x0, z1 - z0, 1);
        patch.setLocalTranslation(x0, -0.002f, z1);
        shown[0] = x0; shown[1] = z0; shown[2] = x1; shown[3] = z1;
        return true;
    }

    @Override
    public void update(float tpf) {
        boolean on = model.shadows();
        if (on == shadowsOn) return;
        shadowsOn = on;
        var vp = getApplication().getViewPort();
        if (on) vp.addProcessor(shadows);
        else vp.removeProcessor(shadows);
    }

    @Override
    protected void onEnable() {
        Node root = ((SimpleApplication) getApplication()).getRootNode();
        root.attachChild(env);
        root.addLight(ambient);
        root.addLight(key);
        root.addLight(fill);
    }

    @Override
    protected void onDisable() {
        Node root = ((SimpleApplication) getApplication()).getRootNode();
        env.removeFromParent();
        root.removeLight(ambient);
        root.removeLight(key);
        root.removeLight(fill);
        if (shadowsOn) getApplication().getViewPort().removeProcessor(shadows);
        shadowsOn = false;
    }
}
