package org.robopro.app.workbench.scene;

import com.jme3.asset.AssetManager;
import com.jme3.material.Material;
import com.jme3.material.RenderState;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Matrix3f;
import com.jme3.math.Quaternion;
import com.jme3.math.Transform;
import com.jme3.math.Vector3f;
import com.jme3.scene.Geometry;
import com.jme3.scene.Node;
import com.jme3.scene.debug.Arrow;
import com.jme3.scene.shape.Box;
import com.jme3.scene.shape.Cylinder;
import java.util.HashMap;
import java.util.Map;
import org.robopro.kinematics.Pose;
import org.robopro.models.Vec3;

/** Geometry helpers shared by the scene states: poses to transforms, beams, boxes, axis triads, cached materials. */
public final class Shapes {
    private final AssetManager assets;
    private final Map<String, Material> materials = new HashMap<>();

    public Shapes(AssetManager assets) { this.assets = assets; }

    public static Vector3f v(Vec3 p) { return new Vector3f((float) p.x(), (float) p.y(), (float) p.z()); }

    /** A robopro pose as a jME transform (same coordinates: the scene's world node is z-up). */
    public static Transform transform(Pose p) {
        Matrix3f m = new Matrix3f(
                (float) p.rot(0, 0), (float) p.rot(0, 1), (float) p.rot(0, 2),
                (float) p.rot(1, 0), (float) p.rot(1, 1), (float) p.rot(1, 2),
                (float) p.rot(2, 0), (float) p.rot(2, 1), (float) p.rot(2, 2));
        Quaternion q = new Quaternion();
        q.fromRotationMatrix(m);
        return new Transform(new Vector3f((float) p.x(), (float) p.y(), (float) p.z()), q);
    }

    public static void apply(Pose p, com.jme3.scene.Spatial s) { s.setLocalTransform(transform(p)); }

    /** Rotation taking +z to {@code dir}. */
    public static Quaternion alignZ(Vector3f dir) {
        Vector3f z = dir.normalize();
        Vector3f helper = Math.abs(z.x) < 0.9f ? Vector3f.UNIT_X : Vector3f.UNIT_Y;
        Vector3f x = helper.cross(z).normalizeLocal();
        Vector3f y = z.cross(x);
        Quaternion q = new Quaternion();
        q.fromAxes(x, y, z);
        return q;
    }

    /** Share of a lit material's colour that the ambient light sees. */
    static final float AMBIENT = 0.55f;

    /** Shaded material of an 0xRRGGBB colour, shared. */
    public Material lit(int rgb) {
        return materials.computeIfAbsent("lit" + rgb, k -> {
            Material m = new Material(assets, "Common/MatDefs/Light/Lighting.j3md");
            ColorRGBA c = color(rgb);
            m.setBoolean("UseMaterialColors", true);
            m.setColor("Diffuse", c);
            m.setColor("Ambient", c.mult(AMBIENT));
            m.setColor("Specular", new ColorRGBA(0.35f, 0.35f, 0.35f, 1));
            m.setFloat("Shininess", 24f);
            return m;
        });
    }

    /** Flat (unlit) material, optionally drawn over everything (selection outlines, frames). */
    public Material flat(int rgb, boolean onTop) {
        return materials.computeIfAbsent("flat" + rgb + onTop, k -> {
            Material m = new Material(assets, "Common/MatDefs/Misc/Unshaded.j3md");
            m.setColor("Color", color(rgb));
            if (onTop) m.getAdditionalRenderState().setDepthTest(false);
            m.getAdditionalRenderState().setFaceCullMode(RenderState.FaceCullMode.Off);
            return m;
        });
    }

    /** Translucent unshaded colour (the real robot's ghost). */
    public Material ghost(int rgb) {
        Material m = new Material(assets, "Common/MatDefs/Misc/Unshaded.j3md");
        ColorRGBA c = color(rgb);
        c.a = 0.35f;
        m.setColor("Color", c);
        m.getAdditionalRenderState().setBlendMode(com.jme3.material.RenderState.BlendMode.Alpha);
        m.getAdditionalRenderState().setDepthWrite(false);
        return m;
    }

    public static ColorRGBA color(int rgb) {
        return new ColorRGBA(((rgb >> 16) & 255) / 255f, ((rgb >> 8) & 255) / 255f, (rgb & 255) / 255f, 1f);
    }

    /** A closed cylinder of radius r from a to b. */
    public Geometry beam(String name, Vector3f a, Vector3f b, float r, Material m) {
        Vector3f d = b.subtract(a);
        float len = d.length();
        Geometry g = new Geometry(name, new Cylinder(2, 28, r, Math.max(len, 1e-4f), true));
        g.setMaterial(m);
        g.setLocalTranslation(a.add(b).multLocal(0.5f));
        if (len > 1e-6f) g.setLocalRotation(alignZ(d));
        return g;
    }

    /** A cylinder of radius r and length len centred at c along axis. */
    public Geometry disc(String name, Vector3f c, Vector3f axis, float r, float len, Material m) {
        Vector3f h = axis.normalize().multLocal(len / 2);
        return beam(name, c.subtract(h), c.add(h), r, m);
    }

    /** A box of full size (sx, sy, sz) standing on its local origin (centre of the underside). */
    public Geometry standingBox(String name, Vec3 size, Material m) {
        Geometry g = new Geometry(name, new Box((float) size.x() / 2, (float) size.y() / 2, (float) size.z() / 2));
        g.setLocalTranslation(0, 0, (float) size.z() / 2);
        g.setMaterial(m);
        return g;
    }

    /** A box from corner lo to corner hi. */
    public Geometry box(String name, Vector3f lo, Vector3f hi, Material m) {
        Vector3f half = hi.subtract(lo).multLocal(0.5f);
        Geometry g = new Geometry(name, new Box(half.x, half.y, half.z));
        g.setLocalTranslation(lo.add(half));
        g.setMaterial(m);
        return g;
    }

    /** Red/green/blue arrows for the x/y/z axes of a frame, {@code len} long (the paper's Fig. 8 view). */
    public Node axes(String name, float len) {
        Node n = new Node(name);
        n.setShadowMode(com.jme3.renderer.queue.RenderQueue.ShadowMode.Off);
        for (int i = 0; i < 3; i++) {
            Arrow a = new Arrow(AXIS_DIRS[i].mult(len));
            a.setLineWidth(2f);
            Geometry g = new Geometry(name + "-" + "xyz".charAt(i), a);
            g.setMaterial(flat(AXIS_RGB[i], true));
            g.setQueueBucket(com.jme3.renderer.queue.RenderQueue.Bucket.Transparent);
            n.attachChild(g);
        }
        return n;
    }

    private static final Vector3f[] AXIS_DIRS = {Vector3f.UNIT_X, Vector3f.UNIT_Y, Vector3f.UNIT_Z};
    private static final int[] AXIS_RGB = {0xE53935, 0x43A047, 0x1E88E5};

    /**
     * The same triads as {@link #axes} at many frames, drawn as one line mesh per axis colour
     * (three draw calls however many frames).
     */
    public Node mergedAxes(String name, java.util.List<Transform> frames, float len) {
        Node n = new Node(name);
        n.setShadowMode(com.jme3.renderer.queue.RenderQueue.ShadowMode.Off);
        for (int i = 0; i < 3; i++) {
            Arrow a = new Arrow(AXIS_DIRS[i].mult(len));
            a.setLineWidth(2f);
            Geometry g = new Geometry(name + "-" + "xyz".charAt(i), copies(a, frames));
            g.setMaterial(flat(AXIS_RGB[i], true));
            g.setQueueBucket(com.jme3.renderer.queue.RenderQueue.Bucket.Transparent);
            n.attachChild(g);
        }
        return n;
    }

    /**
     * One mesh holding a copy of {@code template} at each frame (positions transformed, normals
     * turned), so many equal markers cost one draw call.
     */
    public static com.jme3.scene.Mesh copies(com.jme3.scene.Mesh template, java.util.List<Transform> frames) {
        java.nio.FloatBuffer p = template.getFloatBuffer(com.jme3.scene.VertexBuffer.Type.Position);
        java.nio.FloatBuffer nrm = template.getFloatBuffer(com.jme3.scene.VertexBuffer.Type.Normal);
        com.jme3.scene.mesh.IndexBuffer idx = template.getIndexBuffer();
        int nv = template.getVertexCount(), ni = idx.size(), k = frames.size();
        float[] pos = new float[k * nv * 3];
        float[] nor = nrm == null ? null : new float[k * nv * 3];
        int[] ind = new int[k * ni];
        Vector3f v = new Vector3f(), w = new Vector3f();
        for (int f = 0; f < k; f++) {
            Transform t = frames.get(f);
            for (int j = 0; j < nv; j++) {
                int a = 3 * (f * nv + j);
                v.set(p.get(3 * j), p.get(3 * j + 1), p.get(3 * j + 2));
                t.transformVector(v, w);
                pos[a] = w.x;
                pos[a + 1] = w.y;
                pos[a + 2] = w.z;
                if (nor == null) continue;
                v.set(nrm.get(3 * j), nrm.get(3 * j + 1), nrm.get(3 * j + 2));
                t.getRotation().mult(v, w);
                nor[a] = w.x;
                nor[a + 1] = w.y;
                nor[a + 2] = w.z;
            }
            for (int j = 0; j < ni; j++) ind[f * ni + j] = idx.get(j) + f * nv;
        }
        com.jme3.scene.Mesh m = new com.jme3.scene.Mesh();
        m.setMode(template.getMode());
        m.setLineWidth(template.getLineWidth());
        m.setBuffer(com.jme3.scene.VertexBuffer.Type.Position, 3, com.jme3.util.BufferUtils.createFloatBuffer(pos));
        if (nor != null) m.setBuffer(com.jme3.scene.VertexBuffer.Type.Normal, 3, com.jme3.util.BufferUtils.createFloatBuffer(nor));
        m.setBuffer(com.jme3.scene.VertexBuffer.Type.Index, template.getMode() == com.jme3.scene.Mesh.Mode.Lines ? 2 : 3,
                com.jme3.util.BufferUtils.createIntBuffer(ind));
        m.updateBound();
        return m;
    }

    /**
     * A text label in the 3D scene that always faces the camera, {@code height} metres tall,
     * its bottom-left corner at the node's origin.
     */
    public Node label(String name, String text, float height, int rgb) { return label(name, text, height, rgb, false); }

    /** {@link #label(String, String, float, int)}, optionally drawn over everything (as {@link #flat}'s {@code onTop}). */
    public Node label(String name, String text, float height, int rgb, boolean onTop) {
        com.jme3.font.BitmapFont font = assets.loadFont("Interface/Fonts/Default.fnt");
        com.jme3.font.BitmapText t = new com.jme3.font.BitmapText(font);
        t.setName(name + "-text");
        t.setText(text);
        t.setSize(height);
        t.setColor(new com.jme3.math.ColorRGBA(((rgb >> 16) & 255) / 255f, ((rgb >> 8) & 255) / 255f, (rgb & 255) / 255f, 1));
        t.setQueueBucket(com.jme3.renderer.queue.RenderQueue.Bucket.Transparent);
        Node n = new Node(name);
        n.setShadowMode(com.jme3.renderer.queue.RenderQueue.ShadowMode.Off);
        Node face = new Node(name + "-billboard");
        face.addControl(new com.jme3.scene.control.BillboardControl());
        face.attachChild(t);
        t.setLocalTranslation(0, t.getLineHeight(), 0);
        n.attachChild(face);
        if (onTop) n.depthFirstTraversal(sp -> {
            if (sp instanceof Geometry g) {
                g.setMaterial(g.getMaterial().clone()); // the font's page material is shared with every other label
                g.getMaterial().getAdditionalRenderState().setDepthTest(false);
            }
        });
        return n;
    }
}
