package org.robopro.app.workbench.scene;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.PriorityQueue;
import org.robopro.app.workbench.model.ShippedMeshes;

/**
 * Quadric edge-collapse simplification of a triangle mesh (Garland and Heckbert, "Surface
 * simplification using quadric error metrics", SIGGRAPH 1997): each vertex carries the sum of
 * the squared-distance quadrics of the planes of its triangles (unweighted, so the cost of a
 * contraction is at least the squared distance from its point to any of those planes); the edge
 * whose contraction to the quadric-optimal point costs least is contracted first, until the mesh
 * has the wanted number of triangles or the next contraction would move the point by more than
 * a tolerance from one of the original planes around it. Open borders (where two separately coloured parts meet) are held by extra planes
 * through the border edge perpendicular to its triangle, so seams stay closed; contractions that
 * would flip a triangle or pinch the surface (two sheets sharing an edge) are skipped.
 *
 * <p>The workbench ships meshes simplified this way (a software rasteriser pays for every
 * vertex on every pass); {@link #main} rewrites an STL file.
 */
public final class MeshDecimator {
    private MeshDecimator() { }

    /** Weight of a border edge's plane relative to a triangle's (keeps seams in place). */
    private static final double BORDER_WEIGHT = 100;

    /**
     * A triangle soup (nine floats a triangle) simplified to at most {@code targetTriangles}
     * triangles, stopping earlier when the next contraction's error (root of its quadric cost,
     * a bound on its point's distance from each original plane it answers for, in the mesh's
     * units) would exceed {@code maxError}.
     */
    public static float[] decimate(float[] soup, int targetTriangles, double maxError) {
        // Corners at exactly the same position are one vertex (STL repeats them verbatim).
        int[] corner = StlReader.weld(soup);
        double[][] pos = new double[StlReader.count(corner)][];
        for (int c = 0; c < corner.length; c++)
            if (pos[corner[c]] == null) pos[corner[c]] = new double[] {soup[3 * c], soup[3 * c + 1], soup[3 * c + 2]};
        Mesh m = new Mesh(pos, corner);
        m.run(targetTriangles, maxError * maxError);
        return m.soup();
    }

    /** The working mesh: vertices, triangles, which triangles touch each vertex, quadrics. */
    private static final class Mesh {
        final double[][] p;
        final int[][] tri;
        final boolean[] deadTri;
        final boolean[] deadVert;
        final int[] version;
        final List<List<Integer>> around = new ArrayList<>();
        final double[][] q;
        int live;

        Mesh(double[][] p, int[] corner) {
            this.p = p;
            List<int[]> t = new ArrayList<>();
            for (int i = 0; i + 2 < corner.length; i += 3) {
                int a = corner[i], b = corner[i + 1], c = corner[i + 2];
                if (a != b && b != c && a != c) t.add(new int[] {a, b, c});
            }
            tri = t.toArray(new int[0][]);
            deadTri = new boolean[tri.length];
            deadVert = new boolean[p.length];
            version = new int[p.length];
            live = tri.length;
            for (int i = 0; i < p.length; i++) around.add(new ArrayList<>());
            for (int f = 0; f < tri.length; f++) for (int v : tri[f]) around.get(v).add(f);
            q = new double[p.length][10];
            for (int f = 0; f < tri.length; f++) {
                double[] n = normal(p[tri[f][0]], p[tri[f][1]], p[tri[f][2]]);
                double area = Math.sqrt(dot(n, n)) / 2;
                if (area == 0) continue;
                scale(n, 1 / (2 * area));
                double[] plane = quadric(n, -dot(n, p[tri[f][0]]), 1);
                for (int v : tri[f]) add(q[v], plane);
            }
            // Border edges (one triangle): a plane through the edge, perpendicular to the triangle.
            Map<Long, Integer> count = new HashMap<>();
            for (int[] f : tri) for (int k = 0; k < 3; k++) count.merge(edge(f[k], f[(k + 1) % 3]), 1, Integer::sum);
            for (int[] f : tri) {
                double[] n = normal(p[f[0]], p[f[1]], p[f[2]]);
                if (dot(n, n) == 0) continue;
                for (int k = 0; k < 3; k++) {
                    int a = f[k], b = f[(k + 1) % 3];
                    if (count.get(edge(a, b)) != 1) continue;
                    double[] e = sub(p[b], p[a]);
                    double[] side = cross(e, n);
                    double l = Math.sqrt(dot(side, side));
                    if (l == 0) continue;
                    scale(side, 1 / l);
                    double[] plane = quadric(side, -dot(side, p[a]), BORDER_WEIGHT);
                    add(q[a], plane);
                    add(q[b], plane);
                }
            }
        }

        private record Candidate(double cost, int a, int b, int va, int vb, double[] at) { }

        void run(int target, double maxCost) {
            PriorityQueue<Candidate> heap = new PriorityQueue<>((x, y) -> Double.compare(x.cost, y.cost));
            for (int[] f : tri) for (int k = 0; k < 3; k++) {
                int a = f[k], b = f[(k + 1) % 3];
                if (a < b) heap.add(candidate(a, b));
                else if (!hasEdgeForward(b, a)) heap.add(candidate(b, a)); // border edge seen only this way
            }
            while (live > target && !heap.isEmpty()) {
                Candidate c = heap.poll();
                if (deadVert[c.a] || deadVert[c.b] || version[c.a] != c.va || version[c.b] != c.vb) continue;
                if (c.cost > maxCost) break;
                if (!collapsible(c.a, c.b, c.at)) continue;
                collapse(c.a, c.b, c.at);
                java.util.Set<Integer> nb = new java.util.HashSet<>();
                for (int f : around.get(c.a)) if (!deadTri[f]) for (int v : tri[f]) if (v != c.a) nb.add(v);
                for (int v : nb) heap.add(candidate(Math.min(c.a, v), Math.max(c.a, v)));
            }
        }

        /** Whether some live triangle has the edge a -> b (in that direction). */
        private boolean hasEdgeForward(int a, int b) {
            for (int f : around.get(a)) {
                if (deadTri[f]) continue;
                int[] t = tri[f];
                for (int k = 0; k < 3; k++) if (t[k] == a && t[(k + 1) % 3] == b) return true;
            }
            return false;
        }

        private Candidate candidate(int a, int b) {
            double[] qq = q[a].clone();
            add(qq, q[b]);
            double[] at = optimum(qq);
            double best;
            if (at != null) best = cost(qq, at);
            else {
                double[] mid = {(p[a][0] + p[b][0]) / 2, (p[a][1] + p[b][1]) / 2, (p[a][2] + p[b][2]) / 2};
                at = p[a];
                best = cost(qq, p[a]);
                for (double[] x : new double[][] {p[b], mid}) {
                    double cx = cost(qq, x);
                    if (cx < best) { best = cx; at = x; }
                }
                at = at.clone();
            }
            return new Candidate(Math.max(0, best), a, b, version[a], version[b], at);
        }

        /** Contracting a-b to {@code at} keeps the surface a manifold and flips no triangle. */
        private boolean collapsible(int a, int b, double[] at) {
            // Link condition: the vertices next to both a and b are exactly those of the triangles on a-b.
            java.util.Set<Integer> na = new java.util.HashSet<>(), nbv = new java.util.HashSet<>();
            int shared = 0;
            java.util.Set<Integer> opposite = new java.util.HashSet<>();
            for (int f : around.get(a)) {
                if (deadTri[f]) continue;
                boolean hasB = false;
                for (int v : tri[f]) { if (v != a) na.add(v); if (v == b) hasB = true; }
                if (hasB) { shared++; for (int v : tri[f]) if (v != a && v != b) opposite.add(v); }
            }
            for (int f : around.get(b)) if (!deadTri[f]) for (int v : tri[f]) if (v != b) nbv.add(v);
            na.retainAll(nbv);
            if (!na.equals(opposite) || shared == 0 || shared > 2) return false;
            for (int v : new int[] {a, b}) {
                for (int f : around.get(v)) {
                    if (deadTri[f]) continue;
                    int[] t = tri[f];
                    if ((t[0] == a || t[1] == a || t[2] == a) && (t[0] == b || t[1] == b || t[2] == b)) continue;
                    double[][] now = {p[t[0]], p[t[1]], p[t[2]]};
                    double[][] then = now.clone();
                    for (int k = 0; k < 3; k++) if (t[k] == v) then[k] = at;
                    double[] n0 = normal(now[0], now[1], now[2]), n1 = normal(then[0], then[1], then[2]);
                    double l0 = Math.sqrt(dot(n0, n0)), l1 = Math.sqrt(dot(n1, n1));
                    if (l1 == 0 || l0 == 0) return false;
                    if (dot(n0, n1) < 0.2 * l0 * l1) return false; // turned by more than ~78°
                }
            }
            return true;
        }

        private void collapse(int a, int b, double[] at) {
            p[a] = at;
            add(q[a], q[b]);
            deadVert[b] = true;
            version[a]++;
            for (int f : around.get(b)) {
                if (deadTri[f]) continue;
                int[] t = tri[f];
                boolean hasA = t[0] == a || t[1] == a || t[2] == a;
                if (hasA) {
                    deadTri[f] = true;
                    live--;
                } else {
                    for (int k = 0; k < 3; k++) if (t[k] == b) t[k] = a;
                    around.get(a).add(f);
                }
            }
            around.get(b).clear();
            around.get(a).removeIf(f -> deadTri[f]);
        }

        float[] soup() {
            float[] out = new float[live * 9];
            int o = 0;
            for (int f = 0; f < tri.length; f++) {
                if (deadTri[f]) continue;
                for (int v : tri[f]) for (int k = 0; k < 3; k++) out[o++] = (float) p[v][k];
            }
            return out;
        }
    }

    private static long edge(int a, int b) { return ((long) Math.min(a, b) << 32) | Math.max(a, b); }

    /** The quadric (upper triangle of the 4x4 plane product, weighted) of plane n.x + d = 0. */
    private static double[] quadric(double[] n, double d, double w) {
        double a = n[0], b = n[1], c = n[2];
        return new double[] {w * a * a, w * a * b, w * a * c, w * a * d, w * b * b, w * b * c, w * b * d, w * c * c, w * c * d, w * d * d};
    }

    private static double cost(double[] q, double[] v) {
        double x = v[0], y = v[1], z = v[2];
        return q[0] * x * x + 2 * q[1] * x * y + 2 * q[2] * x * z + 2 * q[3] * x
                + q[4] * y * y + 2 * q[5] * y * z + 2 * q[6] * y + q[7] * z * z + 2 * q[8] * z + q[9];
    }

    /** The point minimising the quadric, or null when its 3x3 part is (nearly) singular. */
    private static double[] optimum(double[] q) {
        double a = q[0], b = q[1], c = q[2], d = q[4], e = q[5], f = q[7];
        double det = a * (d * f - e * e) - b * (b * f - e * c) + c * (b * e - d * c);
        double scale = Math.max(1e-30, Math.abs(a) + Math.abs(d) + Math.abs(f));
        if (Math.abs(det) < 1e-9 * scale * scale * scale) return null;
        double r0 = -q[3], r1 = -q[6], r2 = -q[8];
        double x = (r0 * (d * f - e * e) - b * (r1 * f - e * r2) + c * (r1 * e - d * r2)) / det;
        double y = (a * (r1 * f - e * r2) - r0 * (b * f - e * c) + c * (b * r2 - r1 * c)) / det;
        double z = (a * (d * r2 - r1 * e) - b * (b * r2 - r1 * c) + r0 * (b * e - d * c)) / det;
        return new double[] {x, y, z};
    }

    private static double[] normal(double[] a, double[] b, double[] c) { return cross(sub(b, a), sub(c, a)); }
    private static double[] sub(double[] a, double[] b) { return new double[] {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
    private static double dot(double[] a, double[] b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
    private static void scale(double[] a, double s) { a[0] *= s; a[1] *= s; a[2] *= s; }
    private static void add(double[] a, double[] b) { for (int i = 0; i < a.length; i++) a[i] += b[i]; }
    private static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }

    /** Binary STL bytes of a triangle soup (facet normals left zero: readers compute their own). */
    public static byte[] binaryStl(float[] soup, String header) {
        int n = soup.length / 9;
        ByteBuffer bb = ByteBuffer.allocate(84 + 50 * n).order(ByteOrder.LITTLE_ENDIAN);
        byte[] h = Arrays.copyOf(header.getBytes(java.nio.charset.StandardCharsets.US_ASCII), 80);
        bb.put(h).putInt(n);
        for (int t = 0; t < n; t++) {
            bb.putFloat(0).putFloat(0).putFloat(0);
            for (int k = 0; k < 9; k++) bb.putFloat(soup[9 * t + k]);
            bb.putShort((short) 0);
        }
        return bb.array();
    }

    /**
     * {@code MeshDecimator IN.stl OUT.stl TRIANGLES MAX_ERROR}: writes IN simplified to at most
     * TRIANGLES triangles (or to where the error would pass MAX_ERROR, in the file's units) to
     * OUT as binary STL, whole or not at all.
     */
    public static void main(String[] args) throws IOException {
        if (args.length != 4) {
            System.err.println("usage: MeshDecimator IN.stl OUT.stl TRIANGLES MAX_ERROR");
            System.exit(2);
        }
        Path in = Path.of(args[0]), out = Path.of(args[1]);
        float[] soup = ShippedMeshes.stlTriangles(Files.readAllBytes(in), in);
        float[] d = decimate(soup, Integer.parseInt(args[2]), Double.parseDouble(args[3]));
        byte[] header = Arrays.copyOf(Files.readAllBytes(in), 80);
        String h = new String(header, java.nio.charset.StandardCharsets.US_ASCII).trim();
        if (h.startsWith("solid")) h = "";
        Path tmp = out.resolveSibling(out.getFileName() + ".tmp");
        Files.write(tmp, binaryStl(d, h.isEmpty() ? "robopro: decimated" : h));
        Files.move(tmp, out, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        System.out.println(out + ": " + soup.length / 9 + " -> " + d.length / 9 + " triangles");
    }
}
