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
        java.util.Map<Corner, Integer> ids = new java.util.HashMap<>(nc);
        int[] idx = new int[nc];
        float[] vp = new float[pos.length];
        float[] vn = new float[pos.length];
        int nv = 0;
        for (int c = 0; c < nc; c++) {
            Corner k = new Corner(pos[3 * c], pos[3 * c + 1], pos[3 * c + 2], nor[3 * c], nor[3 * c + 1], nor[3 * c + 2]);
            Integer id = ids.putIfAbsent(k, nv);
            if (id == null) {
                System.arraycopy(pos, 3 * c, vp, 3 * nv, 3);
                System.arraycopy(nor, 3 * c, vn, 3 * nv, 3);
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

    private record Corner(float x, float y, float z, float nx, float ny, float nz) { }

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
        // Corners at the same position (exactly: STL repeats each shared vertex verbatim), chained per position.
        java.util.Map<java.util.List<Float>, Integer> head = new java.util.HashMap<>();
        int[] next = new int[nt * 3];
        for (int c = 0; c < nt * 3; c++) {
            Integer h = head.put(java.util.List.of(pos[3 * c], pos[3 * c + 1], pos[3 * c + 2]), c);
            next[c] = h == null ? -1 : h;
        }
        float[] out = new float[nt * 9];
        for (var e : head.entrySet()) {
            for (int c = e.getValue(); c >= 0; c = next[c]) {
                int t = c / 3;
                float sx = 0, sy = 0, sz = 0;
                for (int d = e.getValue(); d >= 0; d = next[d]) {
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
