package org.robopro.app.workbench.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/**
 * The quadric simplifier against shapes whose surface is known exactly (not from the simplifier):
 * a finely tessellated cube must come down to few triangles with its corners exact; a fine
 * sphere keeps every vertex near the true radius and stays closed; open borders stay put.
 */
class MeshDecimatorTest {

    @Test
    void finelyTessellatedCube_collapsesToFewTrianglesWithExactCorners() {
        float[] cube = cube(12);
        assertEquals(6 * 12 * 12 * 2, cube.length / 9);
        float[] d = MeshDecimator.decimate(cube, 12, 1e-5);
        assertTrue(d.length / 9 <= 24, "a flat-faced cube needs very few triangles, got " + d.length / 9);
        // Every vertex still lies on the cube's surface (on a face plane within the box).
        for (int i = 0; i < d.length; i += 3) {
            float x = d[i], y = d[i + 1], z = d[i + 2];
            float onFace = Math.min(Math.min(Math.abs(Math.abs(x) - 1), Math.abs(Math.abs(y) - 1)), Math.abs(Math.abs(z) - 1));
            assertTrue(onFace < 1e-4 && Math.abs(x) <= 1 + 1e-4 && Math.abs(y) <= 1 + 1e-4 && Math.abs(z) <= 1 + 1e-4,
                    "vertex off the cube: " + x + ", " + y + ", " + z);
        }
        assertClosed(d);
        assertEquals(8, volumeTimes6(d) / 6, 1e-3, "the cube's volume (side 2)");
    }

    @Test
    void sphere_staysNearItsRadiusAndClosed() {
        float[] s = sphere(64, 32, 1f);
        int n = s.length / 9;
        float[] d = MeshDecimator.decimate(s, n / 8, 1);
        assertTrue(d.length / 9 <= n / 8 && d.length / 9 > n / 10, "target honoured: " + d.length / 9 + " of " + n);
        for (int i = 0; i < d.length; i += 3) {
            double r = Math.sqrt(d[i] * d[i] + d[i + 1] * d[i + 1] + d[i + 2] * d[i + 2]);
            assertEquals(1, r, 0.02, "vertex radius");
        }
        assertClosed(d);
        assertEquals(4 * Math.PI / 3, volumeTimes6(d) / 6, 0.05 * 4 * Math.PI / 3, "volume kept within 5 %");
    }

    @Test
    void maxError_stopsBeforeTheShapeIsLost() {
        float[] s = sphere(32, 16, 1f);
        float[] d = MeshDecimator.decimate(s, 4, 0.002);
        assertTrue(d.length / 9 > 100, "a 2 mm tolerance on a 1 m sphere keeps it round: " + d.length / 9 + " triangles");
    }

    @Test
    void openBorder_staysInPlace() {
        // A flat square sheet: its border must not move in or shrink.
        float[] sheet = grid(10);
        float[] d = MeshDecimator.decimate(sheet, 2, 1e-4);
        float lo = Float.MAX_VALUE, hi = -Float.MAX_VALUE;
        for (int i = 0; i < d.length; i += 3) {
            lo = Math.min(lo, d[i]);
            hi = Math.max(hi, d[i]);
            assertEquals(0, d[i + 2], 1e-6);
        }
        assertEquals(0, lo, 1e-5);
        assertEquals(1, hi, 1e-5);
        double area = 0;
        for (int t = 0; t < d.length; t += 9)
            area += 0.5 * ((d[t + 3] - d[t]) * (d[t + 7] - d[t + 1]) - (d[t + 6] - d[t]) * (d[t + 4] - d[t + 1]));
        assertEquals(1, area, 1e-4, "the sheet keeps its area");
    }

    /** Every edge of the mesh is shared by exactly two triangles, in opposite directions. */
    private static void assertClosed(float[] d) {
        Map<List<List<Float>>, Integer> directed = new HashMap<>();
        for (int t = 0; t < d.length; t += 9)
            for (int k = 0; k < 3; k++) {
                int a = t + 3 * k, b = t + 3 * ((k + 1) % 3);
                directed.merge(List.of(List.of(d[a], d[a + 1], d[a + 2]), List.of(d[b], d[b + 1], d[b + 2])), 1, Integer::sum);
            }
        for (var e : directed.entrySet()) {
            assertEquals(1, e.getValue(), "edge used twice in one direction");
            assertTrue(directed.containsKey(List.of(e.getKey().get(1), e.getKey().get(0))), "open edge " + e.getKey());
        }
    }

    private static double volumeTimes6(float[] d) {
        double v = 0;
        for (int t = 0; t < d.length; t += 9) {
            double ax = d[t], ay = d[t + 1], az = d[t + 2], bx = d[t + 3], by = d[t + 4], bz = d[t + 5], cx = d[t + 6], cy = d[t + 7], cz = d[t + 8];
            v += ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
        }
        return v;
    }

    /** A cube from -1 to 1, each face an n x n grid of quads, outward triangles. */
    static float[] cube(int n) {
        float[] out = new float[6 * n * n * 2 * 9];
        int o = 0;
        for (int axis = 0; axis < 3; axis++)
            for (int sign = -1; sign <= 1; sign += 2)
                for (int i = 0; i < n; i++)
                    for (int j = 0; j < n; j++) {
                        float u0 = -1 + 2f * i / n, u1 = -1 + 2f * (i + 1) / n, v0 = -1 + 2f * j / n, v1 = -1 + 2f * (j + 1) / n;
                        float[][] q = {pt(axis, sign, u0, v0), pt(axis, sign, u1, v0), pt(axis, sign, u1, v1), pt(axis, sign, u0, v1)};
                        int[][] tris = sign > 0 ? new int[][] {{0, 1, 2}, {0, 2, 3}} : new int[][] {{0, 2, 1}, {0, 3, 2}};
                        for (int[] t : tris) for (int k : t) { System.arraycopy(q[k], 0, out, o, 3); o += 3; }
                    }
        return out;
    }

    /** Point (u, v) on the face of the cube normal to {@code axis} at {@code sign}; (u, v, n) right-handed. */
    private static float[] pt(int axis, int sign, float u, float v) {
        float[] p = new float[3];
        p[axis] = sign;
        p[(axis + 1) % 3] = u;
        p[(axis + 2) % 3] = v;
        return p;
    }

    /** A UV sphere of radius r, outward triangles. */
    static float[] sphere(int slices, int stacks, float r) {
        List<float[]> t = new java.util.ArrayList<>();
        for (int i = 0; i < stacks; i++)
            for (int j = 0; j < slices; j++) {
                float[] a = sp(i, j, slices, stacks, r), b = sp(i + 1, j, slices, stacks, r), c = sp(i + 1, j + 1, slices, stacks, r), e = sp(i, j + 1, slices, stacks, r);
                if (i > 0) t.add(new float[] {a[0], a[1], a[2], c[0], c[1], c[2], e[0], e[1], e[2]});
                if (i < stacks - 1) t.add(new float[] {a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2]});
            }
        float[] out = new float[t.size() * 9];
        for (int i = 0; i < t.size(); i++) System.arraycopy(t.get(i), 0, out, 9 * i, 9);
        return out;
    }

    private static float[] sp(int i, int j, int slices, int stacks, float r) {
        if (i == 0) return new float[] {0, 0, r};
        if (i == stacks) return new float[] {0, 0, -r};
        double th = Math.PI * i / stacks, ph = 2 * Math.PI * (j % slices) / slices;
        return new float[] {(float) (r * Math.sin(th) * Math.cos(ph)), (float) (r * Math.sin(th) * Math.sin(ph)), (float) (r * Math.cos(th))};
    }

    /** A unit square sheet in z = 0 as an n x n grid. */
    static float[] grid(int n) {
        float[] out = new float[n * n * 18];
        int o = 0;
        for (int i = 0; i < n; i++)
            for (int j = 0; j < n; j++) {
                float x0 = (float) i / n, x1 = (float) (i + 1) / n, y0 = (float) j / n, y1 = (float) (j + 1) / n;
                float[] t = {x0, y0, 0, x1, y0, 0, x1, y1, 0, x0, y0, 0, x1, y1, 0, x0, y1, 0};
                System.arraycopy(t, 0, out, o, 18);
                o += 18;
            }
        return out;
    }
}
