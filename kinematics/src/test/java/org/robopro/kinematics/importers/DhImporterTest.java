package org.robopro.kinematics.importers;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.robopro.kinematics.importers.DhImporter.Convention;
import org.robopro.models.InputException;
import org.robopro.models.JointDescription;
import org.robopro.models.JointType;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotFile;
import org.robopro.models.RobotLibrary;
import org.robopro.models.Vec3;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class DhImporterTest {
    static String resource(String name) throws IOException {
        try (InputStream in = DhImporterTest.class.getResourceAsStream(name)) {
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
    }

    /** Same axis line and direction: directions equal, each point on the other's line. */
    static void assertSameAxes(RobotDescription expected, RobotDescription actual, double tol) {
        assertEquals(expected.dof(), actual.dof());
        for (int i = 0; i < expected.dof(); i++) {
            JointDescription e = expected.joints().get(i), a = actual.joints().get(i);
            assertEquals(e.type(), a.type());
            assertTrue(e.axis().minus(a.axis()).norm() < tol, "axis " + (i + 1) + ": " + e.axis() + " vs " + a.axis());
            double off = a.point().minus(e.point()).cross(e.axis()).norm();
            assertTrue(off < tol, "joint " + (i + 1) + " point " + a.point() + " is " + off + " m off the axis through " + e.point());
            assertEquals(e.min(), a.min(), tol);
            assertEquals(e.max(), a.max(), tol);
        }
        assertTrue(expected.flange().origin().minus(actual.flange().origin()).norm() < tol, "flange origin " + actual.flange().origin());
        assertTrue(expected.flange().zAxis().minus(actual.flange().zAxis()).norm() < tol, "flange z " + actual.flange().zAxis());
        assertTrue(expected.flange().xAxis().minus(actual.flange().xAxis()).norm() < tol, "flange x " + actual.flange().xAxis());
    }

    @Test
    void parse_pumaStandardTable_givesShippedPumaAxes() throws IOException {
        RobotDescription imported = DhImporter.parse("puma560.dh", resource("puma560.dh"), Convention.STANDARD, "x");
        RobotDescription shipped = RobotLibrary.load("puma560");
        assertSameAxes(shipped, imported, 1e-9);
        for (int i = 0; i < 6; i++) // standard DH: the joint point is frame i-1's origin, as in the shipped file
            assertTrue(shipped.joints().get(i).point().minus(imported.joints().get(i).point()).norm() < 1e-9);
        assertEquals("puma560", imported.name());
        assertEquals("Unimation PUMA 560", imported.displayName());
    }

    @Test
    void parse_irb2400ModifiedTable_givesShippedIrb2400Axes() throws IOException {
        RobotDescription imported = DhImporter.parse("irb2400.mdh", resource("irb2400.mdh"), Convention.MODIFIED, "x");
        assertSameAxes(RobotLibrary.load("irb2400"), imported, 1e-9);
        assertEquals(Math.toRadians(450), imported.joints().get(5).maxSpeed(), 1e-12);
    }

    @Test
    void parse_importedRobot_roundTripsThroughRobotFile() throws IOException {
        RobotDescription imported = DhImporter.parse("irb2400.mdh", resource("irb2400.mdh"), Convention.MODIFIED, "x");
        assertEquals(imported, RobotFile.parse("x", RobotFile.format(imported)));
    }

    @Test
    void parse_prismaticRow_movesAlongPreviousZ() {
        String t = "units: length=mm, angle=deg\njoint, type, d, a, alpha, theta, min, max\n"
                + "slide, prismatic, 100, 0, -90, 0, 0, 400\nturn, revolute, 0, 50, 0, 0, ,\n";
        RobotDescription r = DhImporter.parse("t.dh", t, Convention.STANDARD, "t");
        assertEquals(JointType.PRISMATIC, r.joints().get(0).type());
        assertEquals(0.4, r.joints().get(0).max(), 1e-15);
        assertTrue(r.joints().get(1).point().minus(new Vec3(0, 0, 0.1)).norm() < 1e-15);
        assertTrue(r.joints().get(1).axis().minus(new Vec3(0, 1, 0)).norm() < 1e-15);
        assertEquals(Double.NEGATIVE_INFINITY, r.joints().get(1).min());
        assertEquals("t", r.name());
    }

    private static InputException bad(String text, Convention c) {
        return assertThrows(InputException.class, () -> DhImporter.parse("t.dh", text, c, "t"));
    }

    private static final String HEAD = "units: length=mm, angle=deg\njoint, d, a, alpha, min, max\n";

    @Test
    void parse_nonNumericCell_namesLineColumnAndField() {
        InputException e = bad(HEAD + "j1, 0, 0, 90, -10, 10\nj2, 0, abc, 0, -10, 10\n", Convention.STANDARD);
        assertEquals(4, e.line());
        assertEquals(8, e.column());
        assertEquals("a", e.field());
        assertTrue(e.problem().contains("'abc' is not a number"), e.getMessage());
    }

    @Test
    void parse_wrongCellCount_namesLine() {
        InputException e = bad(HEAD + "j1, 0, 0, 90, -10\n", Convention.STANDARD);
        assertEquals(3, e.line());
        assertTrue(e.problem().contains("expected 6 cells"), e.getMessage());
    }

    @Test
    void parse_minAboveMax_refused() {
        assertEquals("min", bad(HEAD + "j1, 0, 0, 90, 10, -10\n", Convention.STANDARD).field());
    }

    @Test
    void parse_missingUnits_refused() {
        assertEquals("units", bad("joint, d, a, alpha\nj1, 0, 0, 0\n", Convention.STANDARD).field());
    }

    @Test
    void parse_conventionMismatch_refusedNamingFlags() {
        InputException e = bad("convention: modified\n" + HEAD + "j1, 0, 0, 90, -10, 10\n", Convention.STANDARD);
        assertEquals(1, e.line());
        assertTrue(e.problem().contains("--mdh"), e.getMessage());
    }

    @Test
    void parse_unknownColumn_refused() {
        InputException e = bad("units: length=m, angle=rad\njoint, d, a, alpha, beta\nj1, 0, 0, 0, 0\n", Convention.MODIFIED);
        assertEquals(2, e.line());
        assertEquals("beta", e.field());
    }

    @Test
    void parse_missingRequiredColumn_refused() {
        assertEquals("alpha", bad("units: length=m, angle=rad\nd, a\n0, 0\n", Convention.MODIFIED).field());
    }

    @Test
    void parse_noRows_refused() {
        assertThrows(InputException.class, () -> DhImporter.parse("t.dh", HEAD, Convention.STANDARD, "t"));
    }

    @Test
    void parse_unknownJointType_refused() {
        InputException e = bad("units: length=m, angle=rad\ntype, d, a, alpha\nrotary, 0, 0, 0\n", Convention.STANDARD);
        assertEquals("type", e.field());
        assertEquals(3, e.line());
    }

    @Test
    void parse_nanOrHugeNumber_refused() {
        assertEquals("d", bad(HEAD + "j1, NaN, 0, 90, -10, 10\n", Convention.STANDARD).field());
        assertEquals("d", bad(HEAD + "j1, 1e999, 0, 90, -10, 10\n", Convention.STANDARD).field());
    }

    @Test
    void read_missingOrNonUtf8File_inputExceptionNamingTheFile(@TempDir Path dir) throws Exception {
        Path missing = dir.resolve("none.dh");
        InputException e = assertThrows(InputException.class,
                () -> DhImporter.read(missing, Convention.STANDARD));
        assertEquals(missing.toString(), e.file());
        Path latin1 = Files.write(dir.resolve("bad.urdf"), new byte[] {'<', (byte) 0xE9, '>'});
        e = assertThrows(InputException.class, () -> UrdfImporter.read(latin1));
        assertTrue(e.problem().contains("not UTF-8"), e.getMessage());
    }
}
