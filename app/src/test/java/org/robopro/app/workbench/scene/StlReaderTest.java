package org.robopro.app.workbench.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import com.jme3.bounding.BoundingBox;
import com.jme3.scene.Mesh;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robopro.models.InputException;

class StlReaderTest {
    @TempDir Path dir;

    @Test
    void read_asciiTriangleInMm_scaledToMetres() throws Exception {
        Path f = dir.resolve("t.stl");
        Files.writeString(f, "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 100 0 0\nvertex 0 200 0\nendloop\nendfacet\nendsolid t\n");
        Mesh m = StlReader.read(f, 0.001f);
        assertEquals(1, m.getTriangleCount());
        BoundingBox b = (BoundingBox) m.getBound();
        assertEquals(0.05f, b.getXExtent(), 1e-6);
        assertEquals(0.1f, b.getYExtent(), 1e-6);
    }

    @Test
    void read_binaryTwoTriangles_sameAsAscii() throws Exception {
        ByteBuffer bb = ByteBuffer.allocate(84 + 2 * 50).order(ByteOrder.LITTLE_ENDIAN);
        bb.position(80);
        bb.putInt(2);
        float[][] tris = {{0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 0, 1, 1, 0, 1, 0, 1, 1}};
        for (float[] t : tris) {
            for (int i = 0; i < 3; i++) bb.putFloat(0);
            for (float v : t) bb.putFloat(v);
            bb.putShort((short) 0);
        }
        Path f = dir.resolve("b.stl");
        Files.write(f, bb.array());
        Mesh m = StlReader.read(f, 1f);
        assertEquals(2, m.getTriangleCount());
        assertEquals(0.5f, ((BoundingBox) m.getBound()).getZExtent(), 1e-6);
    }

    @Test
    void read_garbage_namesFileAndLine() throws Exception {
        Path f = dir.resolve("bad.stl");
        Files.writeString(f, "solid x\nvertex 1 2\n");
        InputException e = assertThrows(InputException.class, () -> StlReader.read(f, 1f));
        assertEquals(2, e.line());
    }
}
