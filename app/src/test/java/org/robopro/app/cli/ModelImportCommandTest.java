package org.robopro.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import org.robopro.models.InputException;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

class ModelImportCommandTest {
    @TempDir Path dir;
    final StringWriter err = new StringWriter();

    private int run(String... args) {
        CommandLine cl = new CommandLine(new ModelImportCommand());
        cl.setOut(new PrintWriter(new StringWriter()));
        cl.setErr(new PrintWriter(err, true));
        cl.setExecutionExceptionHandler((ex, cmd, parsed) -> {
            if (ex instanceof InputException) {
                cmd.getErr().println("robopro: " + ex.getMessage());
                return 2;
            }
            throw ex;
        });
        return cl.execute(args);
    }

    @Test
    void call_dhTable_writesReadableRobotFile() throws Exception {
        Path dh = dir.resolve("two.dh");
        Files.writeString(dh, "units: length=mm, angle=deg\njoint, d, a, alpha, min, max\nj1, 400, 0, 90, -90, 90\nj2, 0, 300, 0, -45, 45\n");
        Path out = dir.resolve("two.robot.json");
        assertEquals(0, run("--dh", dh.toString(), "--out", out.toString()));
        RobotDescription r = RobotLibrary.load(out.toString());
        assertEquals("two", r.name());
        assertEquals(2, r.dof());
        // second run refuses to overwrite without --force
        assertEquals(2, run("--dh", dh.toString(), "--out", out.toString()));
        assertTrue(err.toString().contains("refusing to overwrite"), err.toString());
        assertEquals(0, run("--dh", dh.toString(), "--out", out.toString(), "--force"));
    }

    @Test
    void call_badTable_exitsTwoWithLocatedMessage() throws Exception {
        Path dh = dir.resolve("bad.mdh");
        Files.writeString(dh, "units: length=mm, angle=deg\njoint, d, a, alpha\nj1, 4x0, 0, 90\n");
        assertEquals(2, run("--mdh", dh.toString(), "--out", dir.resolve("o.json").toString()));
        assertTrue(err.toString().contains("bad.mdh:3:5: field 'd'"), err.toString());
    }

    @Test
    void call_twoInputs_isAUsageError() {
        assertEquals(2, run("--dh", "a", "--urdf", "b", "--out", "c"));
    }

    /** A realistic modified-DH table in degrees with 30-degree steps: values that pick up float noise through radians. */
    static final String MDH = "name: six\nunits: length=mm, angle=deg\njoint, alpha, a, theta, d, min, max\n"
            + "j1, 0, 0, 0, 615, -180, 180\nj2, -90, 100, -90, 0, -100, 110\nj3, 0, 705, 0, 0, -60, 65\n"
            + "j4, -90, 135, 0, 755, -200, 200\nj5, 90, 0, 0, 0, -120, 120\nj6, -90, 0, 180, 85, -400, 400\n";

    @Test
    void call_mdhTable_cleanNumbersInTheRobotFile() throws Exception {
        Path mdh = dir.resolve("six.mdh");
        Files.writeString(mdh, MDH);
        Path out = dir.resolve("six.robot.json");
        assertEquals(0, run("--mdh", mdh.toString(), "--out", out.toString()), err.toString());
        String text = Files.readString(out);
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("-?\\d+\\.\\d*(999999|000000\\d)\\d*|\\d[eE]-\\d+").matcher(text);
        assertTrue(!m.find(), () -> "float noise in the imported file: " + m.group() + "\n" + text);
        assertTrue(text.contains("\"limits\": [-60, 65]") || text.contains("[-60, 65]"), text);
        // And the numbers still describe the table: the cleaned file gives the same flange pose as the table within 1e-9 mm.
        RobotDescription clean = RobotLibrary.load(out.toString());
        RobotDescription raw = org.robopro.kinematics.importers.DhImporter.read(mdh, org.robopro.kinematics.importers.DhImporter.Convention.MODIFIED);
        double[] q = {0.3, -0.2, 0.4, 1.0, -0.7, 0.5};
        var a = org.robopro.kinematics.KinematicModel.build(clean).flange(q);
        var b = org.robopro.kinematics.KinematicModel.build(raw).flange(q);
        assertTrue(a.distanceTo(b) < 1e-11, a + " vs " + b);
    }

    @Test
    void robotOption_dhMdhUrdfReadDirectly_otherTextGetsAHintToModelImport() throws Exception {
        Path mdh = dir.resolve("six.mdh");
        Files.writeString(mdh, MDH);
        CliHarness cli = new CliHarness(true);
        assertEquals(0, cli.run("fk", mdh.toString(), "0", "0", "0", "0", "0", "0"), cli.err());
        Path txt = dir.resolve("six.txt");
        Files.writeString(txt, MDH);
        assertEquals(2, cli.run("fk", txt.toString(), "0", "0", "0", "0", "0", "0"));
        assertTrue(cli.err().contains("robopro model import --dh|--mdh|--urdf") && cli.err().contains("six.txt"), cli.err());
    }
}
