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
import com.jme3.scene.debug.Grid;
import com.jme3.scene.shape.Quad;
import com.jme3.shadow.DirectionalLightShadowRenderer;
import com.jme3.shadow.EdgeFilteringMode;
import org.robopro.app.workbench.model.WorkbenchModel;

/**
 * Lights, background, floor and floor grid (1 m and 0.25 m lines), all in the jME y-up root;
 * and the key light's shadows (View → Shadows): one 1024² shadow map over the nearest 12 m of
 * the view, filtered with jME's 4-tap PCF, cast by the robot, tool and cell objects onto
 * themselves and the floor. One split and a small map keep the cost low on a software
 * rasteriser (docs/performance.md).
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
    private Geometry floor, patch;

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
        floor.setShadowMode(ShadowMode.Receive);
        env.attachChild(floor);
        this.floor = floor;
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

    /**
     * Sizes the shadow-receiving floor patch to where the casters' shadows can fall: the
     * casters' bounding box swept along the key light down to the floor, plus a margin, clipped
     * to the floor. The rest of the floor takes no shadow pass.
     */
    private void fitPatch() {
        Node root = ((SimpleApplication) getApplication()).getRootNode();
        float x0 = Float.MAX_VALUE, z0 = Float.MAX_VALUE, x1 = -Float.MAX_VALUE, z1 = -Float.MAX_VALUE;
        Vector3f d = key.getDirection();
        for (com.jme3.scene.Spatial s : root.getChildren()) {
            if (s == env || !(s.getWorldBound() instanceof com.jme3.bounding.BoundingBox b)) continue;
            Vector3f c = b.getCenter();
            for (int k = 0; k < 8; k++) {
                float x = c.x + ((k & 1) == 0 ? -b.getXExtent() : b.getXExtent());
                float y = Math.max(0, c.y + ((k & 2) == 0 ? -b.getYExtent() : b.getYExtent()));
                float z = c.z + ((k & 4) == 0 ? -b.getZExtent() : b.getZExtent());
                for (float t : new float[] {0, y / -d.y}) {
                    x0 = Math.min(x0, x + t * d.x); x1 = Math.max(x1, x + t * d.x);
                    z0 = Math.min(z0, z + t * d.z); z1 = Math.max(z1, z + t * d.z);
                }
            }
        }
        float m = 0.1f;
        x0 = Math.max(-6, x0 - m); z0 = Math.max(-6, z0 - m); x1 = Math.min(6, x1 + m); z1 = Math.min(6, z1 + m);
        if (x1 <= x0 || z1 <= z0) { patch.setCullHint(com.jme3.scene.Spatial.CullHint.Always); return; }
        patch.setLocalScale(x1 - x0, z1 - z0, 1);
        patch.setLocalTranslation(x0, -0.002f, z1);
    }

    @Override
    public void update(float tpf) {
        boolean usePatch = !WorkbenchApp.VARIANT.equals("patch") || ((WorkbenchApp) getApplication()).variant();
        floor.setShadowMode(usePatch ? ShadowMode.Off : ShadowMode.Receive);
        patch.setCullHint(usePatch ? com.jme3.scene.Spatial.CullHint.Inherit : com.jme3.scene.Spatial.CullHint.Always);
        if (usePatch) fitPatch();
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
