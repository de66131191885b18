package org.robopro.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The shipped URDF with a mimic joint works with every command that takes a robot (it used to import and then be refused). */
class UrdfMimicCliTest {
    @TempDir Path dir;

    @Test
    void smallArmWithMimic_importsAndWorksWithEveryRobotCommand() throws Exception {
        Path urdf = dir.resolve("small-arm.urdf");
        try (var in = getClass().getResourceAsStream("/org/robopro/kinematics/importers/small-arm.urdf")) {
            if (in != null) Files.copy(in, urdf);
        }
        if (!Files.exists(urdf))
            Files.copy(Path.of("../kinematics/src/test/resources/org/robopro/kinematics/importers/small-arm.urdf"), urdf);
        Path robot = dir.resolve("arm.robot.json");
        CliHarness h = new CliHarness(true);
        assertEquals(0, h.run("model", "import", "--urdf", urdf.toString(), "--out", robot.toString()), h.err());
        String[][] commands = {
                {"model", "show", robot.toString()},
                {"model", "check", robot.toString()},
                {"fk", robot.toString(), "10", "100", "20", "0"},
                {"fk", "--json", robot.toString(), "-30", "250", "45", "0"},
        };
        for (String[] c : commands) {
            int code = h.run(c);
            assertEquals(0, code, String.join(" ", c) + ": " + h.err() + h.out());
            assertFalse((h.err() + h.out()).contains("coupling matrix"), String.join(" ", c) + ": " + h.err() + h.out());
        }
        assertEquals(0, h.run("simulate", "--robot", robot.toString(), "--poses", "60", "--out", dir.resolve("sim").toString()),
                h.err());
        assertEquals(0, h.run("calibrate", "--robot", robot.toString(), "--measurements", dir.resolve("sim/measurements.csv").toString(),
                "--out", dir.resolve("cal").toString()), h.err());
    }
}
