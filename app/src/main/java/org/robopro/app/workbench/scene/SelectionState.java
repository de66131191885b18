package org.robopro.app.workbench.scene;

import com.jme3.app.Application;
import com.jme3.app.state.BaseAppState;
import com.jme3.bounding.BoundingBox;
import com.jme3.bounding.BoundingVolume;
import com.jme3.scene.Geometry;
import com.jme3.scene.Node;
import com.jme3.scene.Spatial;
import com.jme3.scene.debug.WireBox;
import org.robopro.app.workbench.model.WorkbenchModel;

/** Outlines the selected object, link, target or tool with a yellow box around its world bounds. */
public final class SelectionState extends BaseAppState {
    private final WorkbenchModel model;
    private final Node searchRoot;
    private final Node overlayParent;
    private Geometry outline;

    /** {@code searchRoot}: where pickable nodes live; {@code overlayParent}: a y-up node for the outline (world bounds are in jME coordinates). */
    public SelectionState(WorkbenchModel model, Node searchRoot, Node overlayParent) {
        this.model = model;
        this.searchRoot = searchRoot;
        this.overlayParent = overlayParent;
    }

    @Override
    protected void initialize(Application app) {
        outline = new Geometry("selection", new WireBox(1, 1, 1));
        outline.setMaterial(new Shapes(app.getAssetManager()).flat(0xFFD400, true));
        outline.setQueueBucket(com.jme3.renderer.queue.RenderQueue.Bucket.Transparent);
    }

    @Override protected void cleanup(Application app) { }
    @Override protected void onEnable() { overlayParent.attachChild(outline); }
    @Override protected void onDisable() { outline.removeFromParent(); }

    /** The node tagged with {@code pick} = key under root, or null. */
    public static Spatial find(Spatial s, String key) {
        if (key == null) return null;
        if (key.equals(s.getUserData("pick"))) return s;
        if (s instanceof Node n)
            for (Spatial c : n.getChildren()) {
                Spatial f = find(c, key);
                if (f != null) return f;
            }
        return null;
    }

    @Override
    public void update(float tpf) {
        Spatial sel = find(searchRoot, model.selection());
        if (sel == null) {
            outline.setCullHint(Spatial.CullHint.Always);
            return;
        }
        BoundingVolume bv = ownBound(sel);
        if (!(bv instanceof BoundingBox bb)) {
            outline.setCullHint(Spatial.CullHint.Always);
            return;
        }
        outline.setCullHint(Spatial.CullHint.Inherit);
        ((WireBox) outline.getMesh()).updatePositions(bb.getXExtent() * 1.03f + 0.005f, bb.getYExtent() * 1.03f + 0.005f,
                bb.getZExtent() * 1.03f + 0.005f);
        outline.setLocalTranslation(bb.getCenter());
    }

    /** World bound of a link without its child links (which hang below it in the graphic tree). */
    private static BoundingVolume ownBound(Spatial s) {
        if (!(s instanceof Node n)) return s.getWorldBound();
        BoundingVolume acc = null;
        for (Spatial c : n.getChildren()) {
            if (c.getUserData("pick") != null && c != s) continue;
            if (c.getName() != null && (c.getName().startsWith("frame-") || c.getName().equals("flange"))) continue;
            BoundingVolume b = c.getWorldBound();
            if (b == null) continue;
            acc = acc == null ? b.clone() : acc.merge(b);
        }
        return acc;
    }
}
