package org.robopro.app.workbench.scene;

import com.jme3.scene.Mesh;
import com.jme3.scene.VertexBuffer;
import com.jme3.util.BufferUtils;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.robopro.models.InputException;

/**
 * Reads STL meshes (binary and ASCII) into a jME mesh with flat normals, scaled to metres.
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
        float[] tri = isBinary(b) ? binary(b, file) : ascii(new String(b, StandardCharsets.US_ASCII), file);
        int nv = tri.length / 3;
        float[] pos = new float[nv * 3];
        float[] nor = new float[nv * 3];
        for (int t = 0; t < nv / 3; t++) {
            int o = t * 9;
            float ax = tri[o], ay = tri[o + 1], az = tri[o + 2];
            float ux = tri[o + 3] - ax, uy = tri[o + 4] - ay, uz = tri[o + 5] - az;
            float vx = tri[o + 6] - ax, vy = tri[o + 7] - ay, vz = tri[o + 8] - az;
            float nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
            float l = (float) Math.sqrt(nx * nx + ny * ny + nz * nz);
            if (l > 0) { nx /= l; ny /= l; nz /= l; }
            for (int k = 0; k < 9; k++) pos[o + k] = tri[o + k] * scale;
            for (int k = 0; k < 3; k++) { nor[o + 3 * k] = nx; nor[o + 3 * k + 1] = ny; nor[o + 3 * k + 2] = nz; }
        }
        Mesh m = new Mesh();
        m.setBuffer(VertexBuffer.Type.Position, 3, BufferUtils.createFloatBuffer(pos));
        m.setBuffer(VertexBuffer.Type.Normal, 3, BufferUtils.createFloatBuffer(nor));
        m.updateBound();
        return m;
    }

    private static boolean isBinary(byte[] b) {
        if (b.length < 84) return false;
        long n = ByteBuffer.wrap(b, 80, 4).order(ByteOrder.LITTLE_ENDIAN).getInt() & 0xffffffffL;
        return 84 + 50 * n == b.length;
    }

    private static float[] binary(byte[] b, Path file) {
        ByteBuffer bb = ByteBuffer.wrap(b).order(ByteOrder.LITTLE_ENDIAN);
        int n = bb.getInt(80);
        float[] out = new float[n * 9];
        for (int t = 0; t < n; t++) {
            int o = 84 + 50 * t + 12;
            for (int k = 0; k < 9; k++) out[t * 9 + k] = bb.getFloat(o + 4 * k);
        }
        return out;
    }

    private static float[] ascii(String s, Path file) {
        List<Float> v = new ArrayList<>();
        String[] lines = s.split("\n");
        for (int i = 0; i < lines.length; i++) {
            String l = lines[i].trim();
            if (!l.toLowerCase(Locale.ROOT).startsWith("vertex")) continue;
            String[] p = l.split("\\s+");
            if (p.length != 4) throw new InputException(file.toString(), i + 1, 1, "vertex", "expected 'vertex x y z'");
            try {
                for (int k = 1; k <= 3; k++) v.add(Float.parseFloat(p[k]));
            } catch (NumberFormatException e) {
                throw new InputException(file.toString(), i + 1, 1, "vertex", "not a number: " + l);
            }
        }
        if (v.isEmpty() || v.size() % 9 != 0)
            throw new InputException(file.toString(), 0, 0, "facet", "no complete triangles (is this an STL file?)");
        float[] out = new float[v.size()];
        for (int i = 0; i < out.length; i++) out[i] = v.get(i);
        return out;
    }
}
