package org.robopro.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robopro.app.Main;
import org.robopro.programs.RapidModule;
import org.robopro.programs.RapidParser;

public class ProgramCommandTest {
    /** A program file of the former robopro-program format (taught targets, a jointtarget, three moves). */
    public static final String PROJECT = """
            {"format": "robopro-program", "version": 1, "module": "Demo", "robot": "irb2000",
             "tools": {"tTorch": {"tframe": {"pos_mm": [0, 0, 150]}}},
             "jointtargets": {"jHome": {"joints_deg": [0, 0, 0, 0, 30, 0]}},
             "targets": {"pA": {"joints_deg": [17, 11, 6, 11, 40, -17], "tool": "tTorch"},
                         "pB": {"joints_deg": [6, 17, 0, 6, 34, -6], "tool": "tTorch"}},
             "procedures": {"main": [{"move": "MoveAbsJ", "to": "jHome", "speed": "v1000", "zone": "fine", "tool": "tTorch"},
                                     {"move": "MoveJ", "to": "pA", "speed": "v1000", "zone": "z10", "tool": "tTorch"},
                                     {"move": "MoveL", "to": "pB", "speed": "v200", "zone": "fine", "tool": "tTorch"}]}}
            """;

    @Test
    void exportCheckCompensate_project_writesValidModulesAndExitCodes(@TempDir Path dir) throws Exception {
        Path project = dir.resolve("demo.json");
        Files.writeString(project, PROJECT);
        Path mod = dir.resolve("Demo.mod");
        assertEquals(0, Main.run("program", "export", project.toString(), "--out", mod.toString()));
        RapidModule m = RapidParser.parse(Files.readString(mod), mod.toString());
        assertEquals(2, m.procedures().get(0).body().size() - 1);
        assertEquals(2, Main.run("program", "export", project.toString(), "--out", mod.toString()), "refuses to overwrite");
        assertEquals(0, Main.run("program", "check", mod.toString(), "--robot", "irb2000"));
        Path comp = dir.resolve("Comp.mod");
        assertEquals(0, Main.run("program", "compensate", mod.toString(), "--robot", "irb2000", "--calibrated", "irb2000",
                "--out", comp.toString()));
        assertTrue(Files.readString(comp).contains("CONST robtarget pA:="));
    }

    @Test
    void export_workbenchProject_writesTheWorkbenchsModule(@TempDir Path dir) throws Exception {
        // The one project format: a workbench project (here one migrated from the former format) exports as the workbench does.
        Path old = dir.resolve("demo.json");
        Files.writeString(old, PROJECT);
        Path project = dir.resolve("demo.robopro.json");
        org.robopro.app.workbench.ProjectStore.write(org.robopro.app.workbench.ProjectStore.read(old), project, false);
        Path mod = dir.resolve("Weld.mod");
        assertEquals(0, Main.run("program", "export", project.toString(), "--out", mod.toString()));
        String text = Files.readString(mod);
        try (org.robopro.app.workbench.WorkbenchSession s = org.robopro.app.workbench.WorkbenchSession.open(project)) {
            Path viaWorkbench = dir.resolve("w/Weld.mod");
            Files.createDirectories(viaWorkbench.getParent());
            assertEquals(s.exportRapid(viaWorkbench, false), text);
        }
        RapidModule m = RapidParser.parse(text, mod.toString());
        assertEquals("Weld", m.name());
        assertEquals(3, m.procedure("main").orElseThrow().body().size());
    }

    @Test
    void check_ioProgramWithCellSignals_printsTimeLineAndWarnsOnUnsetInput(@TempDir Path dir) throws Exception {
        Path project = dir.resolve("demo.json");
        Files.writeString(project, PROJECT);
        Path mod = dir.resolve("Demo.mod");
        assertEquals(0, Main.run("program", "export", project.toString(), "--out", mod.toString()));
        String text = Files.readString(mod).replace("  ENDPROC", "    SetDO doClamp, 1;\n    WaitDI diClamped, 1;\n    WaitDI diNever, 1;\n  ENDPROC");
        Files.writeString(mod, text);
        int line = (int) text.lines().takeWhile(l -> !l.contains("WaitDI diNever")).count() + 1;
        Path cell = dir.resolve("c.cell.json");
        Files.writeString(cell, "{\"format\": \"robopro-cell 1\", \"name\": \"c\", \"robot\": {\"ref\": \"irb2000\"}, \"objects\": [{\"name\": \"crate\", \"kind\": \"box\", \"pose\": {\"position\": [0, 1800, 300]}, \"size\": [200, 200, 200]}],\n"
                + " \"signals\": [{\"name\": \"doClamp\", \"type\": \"DO\"},\n"
                + "  {\"name\": \"diClamped\", \"type\": \"DI\", \"follows\": \"doClamp\", \"delay_s\": 0.25},\n"
                + "  {\"name\": \"diNever\", \"type\": \"DI\"}]}");
        CliHarness cli = new CliHarness();
        assertEquals(0, cli.run("program", "check", mod.toString(), "--robot", "irb2000", "--cell", cell.toString()), cli.err());
        assertTrue(cli.out().contains("I/O time line"), cli.out());
        assertTrue(cli.out().matches("(?s).*diClamped +I= 1.*".replace("I", "")), cli.out());
        assertTrue(cli.out().contains("WARNING IO_WAIT") && cli.out().contains("Demo.mod:" + line + ":5"), cli.out());
        assertTrue(cli.out().matches("(?s).*clearance main#3 MoveL pB +[0-9.]+ mm .*"), cli.out());
        Files.writeString(cell, Files.readString(cell).replace("\"DI\", \"follows", "\"DX\", \"follows"));
        CliHarness bad = new CliHarness();
        assertEquals(2, bad.run("program", "check", mod.toString(), "--robot", "irb2000", "--cell", cell.toString()));
        assertTrue(bad.err().contains("c.cell.json:3"), bad.err());
    }
}
