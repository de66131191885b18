package org.robopro.app.workbench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robopro.app.workbench.model.DefaultCell;
import org.robopro.app.workbench.model.Instruction;
import org.robopro.app.workbench.model.ProjectData;
import org.robopro.app.workbench.model.Target;
import org.robopro.app.workbench.model.WorkbenchModel;
import org.robopro.kinematics.ConfData;
import org.robopro.kinematics.Pose;
import org.robopro.models.InputException;

class ProjectStoreTest {
    @TempDir Path dir;

    static ProjectData sample() {
        ProjectData d = DefaultCell.irb2000Welding();
        Target t = new Target("p10", Pose.translation(1.2, 0.1, 0.9).times(Pose.rotY(Math.PI)), new double[] {0, 0.4, 0.1, 0, 1.2, 0},
                new ConfData(0, 0, 0, 1));
        return new ProjectData(d.robotRef(), d.robot(), Pose.translation(0.1, 0, 0), d.tool(), d.objects(), d.workObjects(),
                List.of(t), List.of(new Instruction(Instruction.Type.MOVEL, "p10", 200, 0)), "calib/irb2000-cal.robot.json");
    }

    @Test
    void writeRead_sampleProject_roundTrips() throws Exception {
        ProjectData d = sample();
        Path f = dir.resolve("cell.robopro.json");
        ProjectStore.write(d, f, false);
        ProjectData back = ProjectStore.read(f);
        assertEquals(d.robotRef(), back.robotRef());
        assertEquals(0, back.worldTbase().distanceTo(d.worldTbase()), 1e-9);
        assertEquals(d.tool().name(), back.tool().name());
        assertEquals(d.tool().bodyLength(), back.tool().bodyLength(), 1e-9);
        assertEquals(d.objects().size(), back.objects().size());
        for (int i = 0; i < d.objects().size(); i++) {
            assertEquals(d.objects().get(i).id(), back.objects().get(i).id());
            assertEquals(0, d.objects().get(i).worldTobject().distanceTo(back.objects().get(i).worldTobject()), 1e-9);
            assertEquals(0, d.objects().get(i).worldTobject().angleTo(back.objects().get(i).worldTobject()), 1e-9);
            assertEquals(d.objects().get(i).rgb(), back.objects().get(i).rgb());
        }
        assertEquals(0, back.targets().get(0).worldTtcp().angleTo(d.targets().get(0).worldTtcp()), 1e-9);
        assertEquals(d.targets().get(0).conf(), back.targets().get(0).conf());
        assertEquals(d.program(), back.program());
        assertEquals("calib/irb2000-cal.robot.json", back.calibrationReference());
        assertEquals(ProjectStore.toJson(d), ProjectStore.toJson(back), "write(read(write(x))) is stable");
    }

    @Test
    void read_version1Project_stillOpens() throws Exception {
        // A version-1 project as the first workbench wrote it (own robot/tool/objects sections).
        String v1 = String.join("\n", "{", "\"format\" : \"robopro-project\", \"version\" : 1,",
                "\"robot\" : { \"ref\" : \"irb2000\" },",
                "\"tool\" : { \"name\" : \"torch\", \"tcp\" : { \"position_mm\" : [ 110, 0, 340 ], \"quaternion\" : [ 1, 0, 0, 0 ] },",
                "  \"body_radius_mm\" : 30, \"body_length_mm\" : 187, \"mass_kg\" : 2.5 },",
                "\"objects\" : [ { \"id\" : \"t\", \"kind\" : \"table\", \"pose\" : { \"position_mm\" : [ 1200, 0, 0 ], \"quaternion\" : [ 1, 0, 0, 0 ] },",
                "  \"size_mm\" : [ 800, 1200, 700 ] } ],",
                "\"targets\" : [ { \"name\" : \"p10\", \"pose\" : { \"position_mm\" : [ 1200, 0, 900 ], \"quaternion\" : [ 0, 0, 1, 0 ] },",
                "  \"joints_deg\" : [ 0, 20, 5, 0, 60, 0 ], \"conf\" : [ 0, 0, 0, 0 ] } ],",
                "\"programs\" : [ { \"name\" : \"main\", \"instructions\" : [ { \"type\" : \"MoveJ\", \"target\" : \"p10\", \"speed_mm_s\" : 500, \"zone_mm\" : 10 } ] } ]",
                "}");
        ProjectData d = ProjectStore.parse(v1, "old.robopro.json", dir);
        assertEquals(1, d.objects().size());
        assertEquals(0.187, d.tool().bodyLength(), 1e-12);
        assertEquals(1, d.program().size());
        // Saved again it is a version-2 file whose cell part is a valid cell file.
        String v2 = ProjectStore.toJson(d);
        assertTrue(v2.contains("\"version\" : 2"), v2);
        var cell = org.robopro.models.CellFile.fromTree(org.robopro.models.LocatedJson.parse("x", v2).get("cell"));
        assertEquals(1, cell.objects().size());
        assertEquals(0.35, cell.objects().get(0).worldTobject().position().z(), 1e-12, "cell files place boxes by their centre");
    }

    @Test
    void write_existingFileWithoutOverwrite_refuses() throws Exception {
        Path f = dir.resolve("cell.robopro.json");
        Files.writeString(f, "user data");
        assertThrows(java.nio.file.FileAlreadyExistsException.class, () -> ProjectStore.write(sample(), f, false));
        assertEquals("user data", Files.readString(f));
    }

    @Test
    void parse_badNumber_namesLineColumnAndField() {
        String json = ProjectStore.toJson(sample()).replace("\"mass_kg\" : 2.5", "\"mass_kg\" : -1");
        InputException e = assertThrows(InputException.class, () -> ProjectStore.parse(json, "x.json", dir));
        assertEquals("cell.tools[0].mass_kg", e.field(), "the embedded cell is read by the cell-file reader");
        String[] lines = json.split("\n");
        assertTrue(lines[e.line() - 1].contains("\"mass_kg\""), "line " + e.line() + " is " + lines[e.line() - 1]);
        assertTrue(e.column() > 1);
        assertTrue(e.getMessage().startsWith("x.json:" + e.line() + ":"), e.getMessage());
    }

    @Test
    void parse_truncatedJson_reportsSyntaxErrorWithLine() {
        String json = ProjectStore.toJson(sample());
        String cut = json.substring(0, json.length() / 2);
        InputException e = assertThrows(InputException.class, () -> ProjectStore.parse(cut, "cut.json", dir));
        assertTrue(e.line() > 10, e.getMessage());
        assertTrue(e.problem().startsWith("not valid JSON"), e.getMessage());
    }

    @Test
    void parse_programNamesUnknownTarget_rejected() {
        String json = ProjectStore.toJson(sample()).replace("\"target\" : \"p10\"", "\"target\" : \"p77\"");
        InputException e = assertThrows(InputException.class, () -> ProjectStore.parse(json, "x.json", dir));
        assertEquals("programs.0.instructions.0.target", e.field());
    }

    @Test
    void parse_wrongFormat_rejected() {
        InputException e = assertThrows(InputException.class, () -> ProjectStore.parse("{\"format\": \"other\"}", "x.json", dir));
        assertEquals("format", e.field());
        assertEquals(1, e.line());
    }

    @Test
    void autosave_dirtyModel_writesAndRecoverableUntilSaved() throws Exception {
        ProjectData d = sample();
        Path f = dir.resolve("cell.robopro.json");
        ProjectStore.write(d, f, false);
        Files.setLastModifiedTime(f, java.nio.file.attribute.FileTime.fromMillis(System.currentTimeMillis() - 10_000));
        WorkbenchModel m = new WorkbenchModel(d.robotRef(), d.robot());
        m.load(d);
        ProjectStore.Autosave a = new ProjectStore.Autosave(() -> ProjectStore.autosavePath(f), m, 60_000);
        assertTrue(!a.saveNow(), "nothing to save right after loading");
        m.removeTarget("p10");
        assertTrue(a.saveNow());
        assertEquals(f.resolveSibling("cell.robopro.json.autosave"), ProjectStore.recoverable(f).orElseThrow());
        ProjectData saved = ProjectStore.read(ProjectStore.autosavePath(f));
        assertEquals(0, saved.targets().size(), "the autosave holds the unsaved change");
        assertEquals(0, saved.program().size(), "instructions to a removed target go with it");
        assertEquals(1, ProjectStore.read(f).targets().size(), "the project itself is untouched");
        ProjectStore.deleteAutosave(f);
        assertTrue(ProjectStore.recoverable(f).isEmpty());
    }
}
