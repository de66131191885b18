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
        float[] tri = ShippedMeshes.stlTriangles(b, file);
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
}
