package org.robopro.app.workbench.scene;

import com.jme3.app.Application;
import com.jme3.app.state.BaseAppState;
import com.jme3.asset.AssetManager;
import com.jme3.asset.plugins.FileLocator;
import com.jme3.material.Material;
import com.jme3.scene.Geometry;
import com.jme3.scene.Node;
import com.jme3.scene.Spatial;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.function.Function;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.robopro.app.workbench.model.CellObject;
import org.robopro.app.workbench.model.WorkbenchModel;

/**
 * Tables, fixtures, parts and imported meshes, rebuilt from the model whenever its object list
 * changes. Meshes: STL by {@link StlReader}, OBJ and glTF by jME's plugins.
 */
public final class CellState extends BaseAppState {
    private static final Logger LOG = Logger.getLogger(CellState.class.getName());
    private final WorkbenchModel model;
    private final Node parent;
    private final Node cell = new Node("cell");
    private final Function<String, Path> resolve;
    private Shapes shapes;
    private List<CellObject> builtFor;

    /** {@code resolve} turns a project-relative mesh path into a file. */
    public CellState(WorkbenchModel model, Node parent, Function<String, Path> resolve) {
        this.model = model;
        this.parent = parent;
        this.resolve = resolve;
    }

    @Override protected void initialize(Application app) { shapes = new Shapes(app.getAssetManager()); }
    @Override protected void cleanup(Application app) { }
    @Override protected void onEnable() { parent.attachChild(cell); }
    @Override protected void onDisable() { cell.removeFromParent(); }

    @Override
    public void update(float tpf) {
        List<CellObject> objs = model.objects();
        if (objs == builtFor) return;
        builtFor = objs;
        cell.detachAllChildren();
        for (CellObject o : objs) cell.attachChild(build(o));
    }

    private Spatial build(CellObject o) {
        Node n = new Node("object-" + o.id());
        n.setUserData("pick", "object:" + o.id());
        Shapes.apply(o.worldTobject(), n);
        Material m = shapes.lit(o.rgb());
        if (o.meshPath() != null) {
            try {
                n.attachChild(loadMesh(resolve.apply(o.meshPath()), (float) o.size().x(), m));
                return n;
            } catch (RuntimeException | java.io.IOException e) {
                LOG.log(Level.WARNING, "cannot load mesh " + o.meshPath() + ": " + e.getMessage());
                // fall through: draw a box so the object stays visible and selectable
            }
        }
        if (o.kind() == CellObject.Kind.TABLE) {
            double t = Math.min(0.05, o.size().z() * 0.08);
            var top = shapes.box(o.id() + "-top", new com.jme3.math.Vector3f(-(float) o.size().x() / 2, -(float) o.size().y() / 2,
                    (float) (o.size().z() - t)), new com.jme3.math.Vector3f((float) o.size().x() / 2, (float) o.size().y() / 2,
                    (float) o.size().z()), m);
            n.attachChild(top);
            float lx = (float) o.size().x() / 2 - 0.05f, ly = (float) o.size().y() / 2 - 0.05f;
            Material legs = shapes.lit(0x3A3F47);
            for (int sx = -1; sx <= 1; sx += 2)
                for (int sy = -1; sy <= 1; sy += 2)
                    n.attachChild(shapes.box(o.id() + "-leg", new com.jme3.math.Vector3f(sx * lx - 0.03f, sy * ly - 0.03f, 0),
                            new com.jme3.math.Vector3f(sx * lx + 0.03f, sy * ly + 0.03f, (float) (o.size().z() - t)), legs));
        } else if (o.kind() == CellObject.Kind.CYLINDER) {
            n.attachChild(shapes.beam(o.id() + "-cylinder", com.jme3.math.Vector3f.ZERO,
                    new com.jme3.math.Vector3f(0, 0, (float) o.size().z()), (float) (Math.max(o.size().x(), o.size().y()) / 2), m));
        } else {
            n.attachChild(shapes.standingBox(o.id() + "-box", o.size(), m));
        }
        return n;
    }

    private Spatial loadMesh(Path file, float scale, Material m) throws java.io.IOException {
        String name = file.getFileName().toString().toLowerCase(Locale.ROOT);
        if (name.endsWith(".stl")) {
            Geometry g = new Geometry("mesh", StlReader.read(file, scale));
            g.setMaterial(m);
            return g;
        }
        AssetManager am = getApplication().getAssetManager();
        String dir = file.toAbsolutePath().getParent().toString();
        am.registerLocator(dir, FileLocator.class);
        try {
            Spatial s = am.loadModel(file.getFileName().toString());
            s.setLocalScale(scale);
            if (name.endsWith(".obj")) s.setMaterial(m);
            return s;
        } finally {
            am.unregisterLocator(dir, FileLocator.class);
        }
    }
}
