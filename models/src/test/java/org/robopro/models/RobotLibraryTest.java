package org.robopro.models;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class RobotLibraryTest {
    @TempDir Path dir;

    @Test
    void shippedNames_always_listsTheThreeReferenceRobots() {
        assertEquals(List.of("irb2000", "irb2400", "puma560"), RobotLibrary.shippedNames());
    }

    @Test
    void load_everyShippedName_parsesSixJointsAndSource() {
        for (String n : RobotLibrary.shippedNames()) {
            RobotDescription r = RobotLibrary.load(n);
            assertEquals(n, r.name());
            assertEquals(6, r.dof());
            assertTrue(r.source().length() > 20, "source of " + n);
            for (JointDescription j : r.joints()) assertEquals(1.0, j.axis().norm(), 1e-15);
        }
    }

    @Test
    void load_irb2000_matchesReferenceNumbersInSi() {
        RobotDescription r = RobotLibrary.load("irb2000");
        assertEquals(new Vec3(0, 0, 0.78), r.joints().get(1).point());
        assertEquals(new Vec3(0.85, 0, 1.615), r.joints().get(4).point());
        assertEquals(Math.toRadians(-100), r.joints().get(1).min(), 1e-15);
        assertEquals(Math.toRadians(450), r.joints().get(5).maxSpeed(), 1e-12);
        assertEquals(new Vec3(1.0, 0, 1.615), r.flange().origin());
        assertEquals(Vec3.X, r.flange().zAxis());
        assertEquals(new Vec3(0, 0, -1), r.flange().xAxis());
        double[][] c = r.couplingMatrix();
        assertEquals(1, c[2][2]);
        assertEquals(-1, c[2][1]);
        MassModel m = r.massModel().orElseThrow();
        assertEquals(86, m.links().stream().mapToDouble(LinkMass::massKg).sum(), 1e-12);
        assertEquals(10, m.ratedPayloadKg());
    }

    @Test
    void load_puma560_hasNoSpeedsButAMassModel() {
        RobotDescription r = RobotLibrary.load("puma560");
        assertTrue(r.joints().stream().allMatch(j -> j.maxSpeed() == Double.POSITIVE_INFINITY));
        assertEquals(5, r.massModel().orElseThrow().links().size());
        assertTrue(r.coupling().isEmpty());
    }

    @Test
    void load_sameShippedNameTwice_returnsSharedInstance() {
        assertSame(RobotLibrary.load("irb2400"), RobotLibrary.load("irb2400"));
    }

    @Test
    void load_filePath_readsThatFile() throws Exception {
        Path f = dir.resolve("my.robot.json");
        RobotDescription r = RobotLibrary.load("irb2000");
        RobotLibrary.write(r, f, false);
        assertEquals(r, RobotLibrary.load(f.toString()));
    }

    @Test
    void load_unknownName_throwsInputExceptionListingShippedRobots() {
        InputException e = assertThrows(InputException.class, () -> RobotLibrary.load("irb9999"));
        assertTrue(e.getMessage().contains("irb2000"), e.getMessage());
    }

    @Test
    void write_existingFileWithoutOverwrite_refusesAndKeepsContent() throws Exception {
        Path f = dir.resolve("keep.robot.json");
        Files.writeString(f, "precious");
        assertThrows(InputException.class, () -> RobotLibrary.write(RobotLibrary.load("irb2000"), f, false));
        assertEquals("precious", Files.readString(f));
        RobotLibrary.write(RobotLibrary.load("irb2000"), f, true);
        assertEquals(RobotLibrary.load("irb2000"), RobotLibrary.read(f));
    }
}
