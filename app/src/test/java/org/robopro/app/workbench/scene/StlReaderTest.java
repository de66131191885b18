package org.robopro.app.workbench.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

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

    @Test
    void normals_cylinderSidesSmoothBoxEdgesSharp() {
        // A 24-sided prism: neighbouring side faces meet at 15 deg (smooth);
        // its caps meet the sides at 90 deg: sharp.
        int n = 24;
        java.util.List<float[]> tris = new java.util.ArrayList<>();
        for (int i = 0; i < n; i++) {
            double a0 = 2 * Math.PI * i / n, a1 = 2 * Math.PI * ((i + 1) % n) / n;
            float x0 = (float) Math.cos(a0), y0 = (float) Math.sin(a0), x1 = (float) Math.cos(a1), y1 = (float) Math.sin(a1);
            tris.add(new float[] {x0, y0, 0, x1, y1, 0, x1, y1, 1});
            tris.add(new float[] {x0, y0, 0, x1, y1, 1, x0, y0, 1});
            tris.add(new float[] {0, 0, 1, x0, y0, 1, x1, y1, 1});
        }
        float[] pos = new float[tris.size() * 9];
        for (int t = 0; t < tris.size(); t++) System.arraycopy(tris.get(t), 0, pos, 9 * t, 9);
        float[] nor = StlReader.normals(pos, StlReader.CREASE_COS);
        // Side corner at angle 0 on the bottom rim: close to radial (1, 0, 0) (within 4 deg; the
        // facet's own normal is 7.5 deg off), level, unit length.
        assertTrue(nor[0] > Math.cos(Math.toRadians(4)), "corner normal " + nor[0] + ", " + nor[1]);
        assertEquals(0, nor[2], 1e-6);
        assertEquals(1, Math.sqrt(nor[0] * nor[0] + nor[1] * nor[1] + nor[2] * nor[2]), 1e-5);
        // Cap corners stay straight up although they share their position with side corners.
        for (int k = 0; k < 3; k++) assertEquals(1, nor[9 * 2 + 3 * k + 2], 1e-6);
    }

    @Test
    void weldingJoinsExactlyEqualPositionsInTheOrderTheyFirstAppear() {
        float nan = Float.NaN;
        float[] pos = {1, 2, 3,   0, 0, 0,   1, 2, 3,   -0f, 0, 0,   nan, 0, 0,   0, 0, 0,   nan, 0, 0,   1, 2, 3.0000005f};
        // +0 and -0 are different points (as Float.equals has them), every NaN one point, and a
        // position one float step away is another point.
        assertEquals(java.util.List.of(0, 1, 0, 2, 3, 1, 3, 4), java.util.Arrays.stream(StlReader.weld(pos)).boxed().toList());
        assertEquals(5, StlReader.count(StlReader.weld(pos)));
        assertEquals(0, StlReader.weld(new float[0]).length);
    }

    @Test
    void indexingKeepsCornersAtOnePointApartWhenTheirNormalsDiffer() {
        // Two triangles sharing an edge, folded at 90 deg (a crease): the shared corners split.
        float[] pos = {0, 0, 0, 1, 0, 0, 0, 1, 0,   1, 0, 0, 0, 0, 0, 0, 0, 1};
        assertEquals(6, StlReader.indexed(pos, StlReader.normals(pos, StlReader.CREASE_COS)).getVertexCount());
        // Two triangles in one plane: the shared corners become one vertex each.
        float[] flat = {0, 0, 0, 1, 0, 0, 0, 1, 0,   1, 0, 0, 1, 1, 0, 0, 1, 0};
        Mesh m = StlReader.indexed(flat, StlReader.normals(flat, StlReader.CREASE_COS));
        assertEquals(4, m.getVertexCount());
        assertEquals(2, m.getTriangleCount());
    }
}
