package org.robopro.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.ObjectMapper;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Outputs say what they know and nothing else: no other target's values, no NaN in JSON. */
class HonestOutputTest {
    @TempDir Path dir;

    @Test
    void compensate_unreachableTarget_getsEmptyFieldsAndItsStatus_notThePreviousTargetsValues() throws Exception {
        CliHarness h = new CliHarness(true);
        Path targets = dir.resolve("t.csv"), out = dir.resolve("c.csv");
        Files.writeString(targets, "# frame: base\nx,y,z\n1200,100,900\n9000,0,900\n1100,-200,1000\n");
        assertEquals(1, h.run("compensate", "--nominal", "irb2000", "--calibrated", "irb2000", "--targets", targets.toString(),
                "--out", out.toString()), h.err());
        List<String> lines = Files.readAllLines(out);
        String header = lines.get(1), far = lines.get(3);
        int cols = header.split(",", -1).length;
        String[] f = far.split(",", -1);
        assertEquals(cols, f.length, far);
        assertEquals("unreachable", f[cols - 1], far);
        for (int i = 1; i < cols - 1; i++) assertEquals("", f[i], "field " + header.split(",")[i] + " of " + far);
        // The targets either side are computed as usual.
        assertTrue(lines.get(2).endsWith(",converged") && lines.get(4).endsWith(",converged"), lines.toString());
        assertFalse(String.join("\n", lines).contains("NaN"), lines.toString());
    }

    @Test
    void fkJson_neverPrintsNaN() throws Exception {
        // Two prismatic joints along one axis: their huge travels add up beyond the largest double.
        Path gantry = dir.resolve("gantry.robot.json");
        Files.writeString(gantry, """
                {"format": "robopro-robot 1", "name": "gantry", "joints": [
                  {"name": "x", "type": "prismatic", "point": [0, 0, 0], "axis": [1, 0, 0], "limits": [-1e308, 1e308]},
                  {"name": "y", "type": "prismatic", "point": [0, 0, 0], "axis": [1, 0, 0], "limits": [-1e308, 1e308]}],
                 "flange": {"origin": [0, 0, 0], "z_axis": [0, 0, 1], "x_axis": [1, 0, 0]}}
                """);
        CliHarness g = new CliHarness(true);
        int gc = g.run("fk", "--json", gantry.toString(), "1.7e308", "1.7e308");
        assertFalse(g.out().contains("NaN") || g.out().contains("Infinity"), g.out());
        assertEquals(2, gc, g.err());
        for (String[] q : new String[][] {{"1e308", "0", "0", "0", "0", "0"}, {"0", "1e300", "0", "0", "0", "0"}, {"10", "20", "30", "0", "45", "0"}}) {
            CliHarness h = new CliHarness(true);
            String[] args = new String[3 + q.length];
            args[0] = "fk"; args[1] = "--json"; args[2] = "irb2000";
            System.arraycopy(q, 0, args, 3, q.length);
            int code = h.run(args);
            assertFalse(h.out().contains("NaN") || h.out().contains("Infinity"), h.out());
            if (code == 0) new ObjectMapper().readTree(h.out());
            else assertEquals(1, h.err().lines().count(), h.err());
        }
    }

    @Test
    void programCompensate_calibratedModelOfAnotherRobot_isRefusedAndWritesNothing() throws Exception {
        Path mod = dir.resolve("P.mod"), out = dir.resolve("PC.mod");
        Files.writeString(mod, """
                MODULE P
                  CONST robtarget p1 := [[1200,100,900],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
                  PROC main()
                    MoveL p1, v100, fine, tool0;
                  ENDPROC
                ENDMODULE
                """);
        CliHarness h = new CliHarness(true);
        int code = h.run("program", "compensate", mod.toString(), "--robot", "irb2000", "--calibrated", "puma560", "--out", out.toString());
        assertEquals(2, code, h.out() + h.err());
        assertFalse(h.out().contains("wrote"), h.out());
        assertTrue(h.err().contains("puma560") && h.err().contains("nothing written"), h.err());
        assertFalse(Files.exists(out));
        assertEquals(0, h.run("program", "compensate", mod.toString(), "--robot", "irb2000", "--calibrated", "irb2000", "--out",
                out.toString()), h.err());
        assertTrue(h.out().contains("wrote") && Files.exists(out));
    }
}
