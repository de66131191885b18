package org.robopro.app.workbench.scene;

import com.jme3.scene.Mesh;
import com.jme3.scene.VertexBuffer;
import com.jme3.util.BufferUtils;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.robopro.app.workbench.model.ShippedMeshes;
import org.robopro.models.InputException;

/**
 * Reads STL meshes (binary and ASCII) into an indexed jME mesh, scaled to metres, with normals
 * smoothed across edges flatter than 30° (crisp where the CAD model has a real edge).
 * jME's plugins load OBJ and glTF but not STL, which is what most robot CAD exports are.
 */
public final class StlReader {
    private StlReader() { }

    /** Largest mesh file read (about 5 million triangles binary); an endless file stops here. */
    static final long MAX_BYTES = 256L << 20;

    public static Mesh read(Path file, float scale) throws IOException {
        if (Files.exists(file) && !Files.isDirectory(file) && !Files.isRegularFile(file))
            throw new InputException(file.toString(), 0, 0, null, "is not a regular file (a device or a pipe?); not a mesh file");
        byte[] b = org.robopro.models.TextFiles.readBytes(file, MAX_BYTES, "mesh file");
        return read(b, file, scale);
    }

    /** A mesh from an STL file's bytes (binary or ASCII); {@code file} names it in error messages. */
    public static Mesh read(byte[] b, Path file, float scale) {
        float[] tri = ShippedMeshes.stlTriangles(b, file);
        float[] pos = new float[tri.length];
        for (int k = 0; k < pos.length; k++) pos[k] = tri[k] * scale;
        // Smoothing indexes every corner; past SMOOTH_MAX triangles the facets' own normals are used.
        float[] nor = normals(pos, pos.length / 9 <= SMOOTH_MAX ? CREASE_COS : 2f);
        return indexed(pos, nor);
    }

    /**
     * An indexed mesh of a triangle soup's corners: corners with the same position and normal
     * become one vertex, so the vertex stage (a software rasteriser's main cost per triangle)
     * runs once per vertex instead of once per corner.
     */
    static Mesh indexed(float[] pos, float[] nor) {
        int nc = pos.length / 3;
        int[] at = weld(pos);
        // The vertices made so far at each position, chained: a corner joins the one with its normal.
        int[] first = new int[count(at)];
        java.util.Arrays.fill(first, -1);
        int[] sibling = new int[nc];
        int[] idx = new int[nc];
        float[] vp = new float[pos.length];
        float[] vn = new float[pos.length];
        int nv = 0;
        for (int c = 0; c < nc; c++) {
            int id = first[at[c]];
            while (id >= 0 && !(bits(vn[3 * id]) == bits(nor[3 * c]) && bits(vn[3 * id + 1]) == bits(nor[3 * c + 1])
                    && bits(vn[3 * id + 2]) == bits(nor[3 * c + 2]))) id = sibling[id];
            if (id < 0) {
                System.arraycopy(pos, 3 * c, vp, 3 * nv, 3);
                System.arraycopy(nor, 3 * c, vn, 3 * nv, 3);
                sibling[nv] = first[at[c]];
                first[at[c]] = nv;
                id = nv++;
            }
            idx[c] = id;
        }
        Mesh m = new Mesh();
        m.setBuffer(VertexBuffer.Type.Position, 3, BufferUtils.createFloatBuffer(java.util.Arrays.copyOf(vp, 3 * nv)));
        m.setBuffer(VertexBuffer.Type.Normal, 3, BufferUtils.createFloatBuffer(java.util.Arrays.copyOf(vn, 3 * nv)));
        if (nv <= 65535) {
            short[] s = new short[nc];
            for (int c = 0; c < nc; c++) s[c] = (short) idx[c];
            m.setBuffer(VertexBuffer.Type.Index, 3, BufferUtils.createShortBuffer(s));
        } else {
            m.setBuffer(VertexBuffer.Type.Index, 3, BufferUtils.createIntBuffer(idx));
        }
        m.updateBound();
        return m;
    }

    /** A float's bits as {@link Float#equals} compares them (every NaN one value, -0 apart from +0). */
    private static int bits(float f) { return Float.floatToIntBits(f); }

    /**
     * The point each corner of a triangle soup (x, y, z of each corner) stands on: corners at
     * exactly the same position (bit for bit, as {@link Float#equals} compares; STL repeats each
     * shared vertex verbatim) get the same id, numbered 0, 1, ... in the order the points first
     * appear. One open-addressed table of corner numbers; no key objects.
     */
    static int[] weld(float[] pos) {
        int nc = pos.length / 3;
        int[] id = new int[nc];
        int size = Integer.highestOneBit(Math.max(2, 2 * nc - 1)) << 1; // a power of two, at least twice the corners
        int[] table = new int[size]; // 1 + the first corner at a point, 0 where empty
        int mask = size - 1, n = 0;
        for (int c = 0; c < nc; c++) {
            int x = bits(pos[3 * c]), y = bits(pos[3 * c + 1]), z = bits(pos[3 * c + 2]);
            int h = (x * 0x9E3779B1 + y) * 0x9E3779B1 + z;
            h ^= h >>> 15;
            h *= 0x85EBCA6B;
            h ^= h >>> 13;
            for (int s = h & mask; ; s = (s + 1) & mask) {
                int f = table[s] - 1;
                if (f < 0) { table[s] = c + 1; id[c] = n++; break; }
                if (bits(pos[3 * f]) == x && bits(pos[3 * f + 1]) == y && bits(pos[3 * f + 2]) == z) { id[c] = id[f]; break; }
            }
        }
        return id;
    }

    /** How many points the ids of {@link #weld} name. */
    static int count(int[] ids) {
        int n = 0;
        for (int i : ids) n = Math.max(n, i + 1);
        return n;
    }

    /** Largest mesh (triangles) whose normals are smoothed (the corner index costs memory per corner). */
    static final int SMOOTH_MAX = 300_000;

    /** Edges sharper than this (30°) stay sharp; smoother surfaces (cylinders, fillets) shade smoothly. */
    static final float CREASE_COS = (float) Math.cos(Math.toRadians(30));

    /**
     * Per-corner normals of a triangle soup (9 floats a triangle): each corner takes the
     * area-weighted mean of the normals of the triangles meeting at its position whose normal is
     * within the crease angle of its own triangle's, so curved surfaces shade smoothly and real
     * edges stay crisp (flat normals alone make every CAD facet visible).
     */
    static float[] normals(float[] pos, float creaseCos) {
        int nt = pos.length / 9;
        boolean flat = creaseCos > 1; // no two faces within the crease: each corner its facet's normal
        float[] fn = new float[nt * 3]; // unit face normals
        float[] fa = new float[nt * 3]; // area-weighted face normals
        for (int t = 0; t < nt; t++) {
            int o = t * 9;
            float ux = pos[o + 3] - pos[o], uy = pos[o + 4] - pos[o + 1], uz = pos[o + 5] - pos[o + 2];
            float vx = pos[o + 6] - pos[o], vy = pos[o + 7] - pos[o + 1], vz = pos[o + 8] - pos[o + 2];
            float nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
            fa[3 * t] = nx; fa[3 * t + 1] = ny; fa[3 * t + 2] = nz;
            float l = (float) Math.sqrt(nx * nx + ny * ny + nz * nz);
            if (l > 0) { nx /= l; ny /= l; nz /= l; }
            fn[3 * t] = nx; fn[3 * t + 1] = ny; fn[3 * t + 2] = nz;
        }
        if (flat) {
            float[] out = new float[nt * 9];
            for (int c = 0; c < nt * 3; c++) System.arraycopy(fn, 3 * (c / 3), out, 3 * c, 3);
            return out;
        }
        // Corners at the same position (exactly: STL repeats each shared vertex verbatim), chained
        // per position from the last corner there back to the first.
        int[] at = weld(pos);
        int[] head = new int[count(at)];
        java.util.Arrays.fill(head, -1);
        int[] next = new int[nt * 3];
        for (int c = 0; c < nt * 3; c++) {
            next[c] = head[at[c]];
            head[at[c]] = c;
        }
        float[] out = new float[nt * 9];
        for (int h : head) {
            for (int c = h; c >= 0; c = next[c]) {
                int t = c / 3;
                float sx = 0, sy = 0, sz = 0;
                for (int d = h; d >= 0; d = next[d]) {
                    int u = d / 3;
                    float dot = fn[3 * t] * fn[3 * u] + fn[3 * t + 1] * fn[3 * u + 1] + fn[3 * t + 2] * fn[3 * u + 2];
                    if (u != t && dot < creaseCos) continue;
                    sx += fa[3 * u]; sy += fa[3 * u + 1]; sz += fa[3 * u + 2];
                }
                float l = (float) Math.sqrt(sx * sx + sy * sy + sz * sz);
                if (l > 0) { sx /= l; sy /= l; sz /= l; } else { sx = fn[3 * t]; sy = fn[3 * t + 1]; sz = fn[3 * t + 2]; }
                out[3 * c] = sx; out[3 * c + 1] = sy; out[3 * c + 2] = sz;
            }
        }
        return out;
    }
}
