package org.robopro.app.workbench.scene;

import com.jme3.math.Vector3f;
import com.jme3.scene.Mesh;
import com.jme3.scene.VertexBuffer;
import com.jme3.util.BufferUtils;

/**
 * Casting-like solids for procedural robot models: a closed convex 2-D profile (rounded
 * rectangle, circle) swept along a straight line, scaled from one end to the other (a taper),
 * with flat caps. Side normals come from the profile, so rounded edges shade smoothly while
 * the caps stay flat.
 */
public final class Loft {
    private Loft() { }

    /** A circle of radius r as n points, counter-clockwise. */
    public static float[][] circle(float r, int n) {
        float[][] p = new float[n][];
        for (int i = 0; i < n; i++) {
            double a = 2 * Math.PI * i / n;
            p[i] = new float[] {(float) (r * Math.cos(a)), (float) (r * Math.sin(a))};
        }
        return p;
    }

    /** A w x h rectangle (u along w, v along h) with corners rounded by r, counter-clockwise. */
    public static float[][] roundedRect(float w, float h, float r, int perCorner) {
        r = Math.min(r, Math.min(w, h) / 2 * 0.999f);
        float[][] centres = {{w / 2 - r, h / 2 - r}, {-w / 2 + r, h / 2 - r}, {-w / 2 + r, -h / 2 + r}, {w / 2 - r, -h / 2 + r}};
        float[][] p = new float[4 * (perCorner + 1)][];
        int k = 0;
        for (int c = 0; c < 4; c++)
            for (int i = 0; i <= perCorner; i++) {
                double a = Math.PI / 2 * (c + (double) i / perCorner);
                p[k++] = new float[] {(float) (centres[c][0] + r * Math.cos(a)), (float) (centres[c][1] + r * Math.sin(a))};
            }
        return p;
    }

    /**
     * The profile swept from a to b. The profile's u axis is {@code across} (made perpendicular
     * to the sweep), v the remaining direction; the profile is scaled by {@code scaleB} at b.
     */
    public static Mesh sweep(float[][] profile, Vector3f a, Vector3f b, Vector3f across, float scaleB) {
        Vector3f axis = b.subtract(a);
        float len = axis.length();
        Vector3f w = len > 1e-9f ? axis.divide(len) : Vector3f.UNIT_Z.clone();
        Vector3f u = across.subtract(w.mult(across.dot(w)));
        if (u.lengthSquared() < 1e-12f) u = Math.abs(w.x) < 0.9f ? Vector3f.UNIT_X.cross(w) : Vector3f.UNIT_Y.cross(w);
        u.normalizeLocal();
        Vector3f v = w.cross(u).normalizeLocal();
        int n = profile.length;
        // 2-D outward normals per profile point (average of the two adjacent edges), tilted by the taper.
        float[][] pn = new float[n][];
        for (int i = 0; i < n; i++) {
            float[] p0 = profile[(i + n - 1) % n], p1 = profile[i], p2 = profile[(i + 1) % n];
            float ex = p2[0] - p0[0], ey = p2[1] - p0[1];
            float l = (float) Math.hypot(ex, ey);
            pn[i] = l > 0 ? new float[] {ey / l, -ex / l} : new float[] {0, 0};
        }
        int sideVerts = 2 * n, capVerts = 2 * n;
        float[] pos = new float[(sideVerts + capVerts) * 3];
        float[] nor = new float[(sideVerts + capVerts) * 3];
        int[] idx = new int[n * 6 + 2 * (n - 2) * 3];
        int vi = 0;
        for (int end = 0; end < 2; end++) {
            Vector3f o = end == 0 ? a : b;
            float s = end == 0 ? 1 : scaleB;
            for (int i = 0; i < n; i++) {
                Vector3f p = o.add(u.mult(profile[i][0] * s)).addLocal(v.mult(profile[i][1] * s));
                float radial = (float) Math.hypot(profile[i][0], profile[i][1]);
                float slope = len > 1e-9f ? (1 - scaleB) * radial / len : 0;
                Vector3f nn = u.mult(pn[i][0]).addLocal(v.mult(pn[i][1])).addLocal(w.mult(slope)).normalizeLocal();
                put(pos, nor, vi++, p, nn);
            }
        }
        for (int end = 0; end < 2; end++) {
            Vector3f o = end == 0 ? a : b;
            float s = end == 0 ? 1 : scaleB;
            Vector3f nn = end == 0 ? w.negate() : w;
            for (int i = 0; i < n; i++) put(pos, nor, vi++, o.add(u.mult(profile[i][0] * s)).addLocal(v.mult(profile[i][1] * s)), nn);
        }
        int k = 0;
        for (int i = 0; i < n; i++) {
            int i2 = (i + 1) % n;
            int a0 = i, a1 = i2, b0 = n + i, b1 = n + i2;
            idx[k++] = a0; idx[k++] = a1; idx[k++] = b1;
            idx[k++] = a0; idx[k++] = b1; idx[k++] = b0;
        }
        int c0 = 2 * n, c1 = 3 * n;
        for (int i = 1; i < n - 1; i++) {
            idx[k++] = c0; idx[k++] = c0 + i + 1; idx[k++] = c0 + i;
            idx[k++] = c1; idx[k++] = c1 + i; idx[k++] = c1 + i + 1;
        }
        Mesh m = new Mesh();
        m.setBuffer(VertexBuffer.Type.Position, 3, BufferUtils.createFloatBuffer(pos));
        m.setBuffer(VertexBuffer.Type.Normal, 3, BufferUtils.createFloatBuffer(nor));
        m.setBuffer(VertexBuffer.Type.Index, 3, BufferUtils.createIntBuffer(idx));
        m.updateBound();
        return m;
    }

    private static void put(float[] pos, float[] nor, int i, Vector3f p, Vector3f n) {
        pos[3 * i] = p.x; pos[3 * i + 1] = p.y; pos[3 * i + 2] = p.z;
        nor[3 * i] = n.x; nor[3 * i + 1] = n.y; nor[3 * i + 2] = n.z;
    }
}
