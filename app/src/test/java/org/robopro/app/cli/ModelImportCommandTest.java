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
}
