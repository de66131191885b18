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
import org.robopro.app.workbench.model.WorkObject;
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

    /** A project with every field set away from its default: each object kind, tool, work objects, each instruction type. */
    static ProjectData everyField() {
        ProjectData d = DefaultCell.irb2000Welding();
        var objects = new java.util.ArrayList<>(d.objects());
        objects.add(new org.robopro.app.workbench.model.CellObject("fixture7", "Clamp 7", org.robopro.app.workbench.model.CellObject.Kind.FIXTURE,
                Pose.translation(0.9, -0.4, 0.7).times(Pose.rotZ(0.3)), new org.robopro.models.Vec3(0.3, 0.1, 0.12), null, 0x2F7D3A));
        objects.add(new org.robopro.app.workbench.model.CellObject("cylinder2", "Drum", org.robopro.app.workbench.model.CellObject.Kind.CYLINDER,
                Pose.translation(-0.5, 1.1, 0), new org.robopro.models.Vec3(0.4, 0.4, 0.9), null, 0x123456));
        objects.add(new org.robopro.app.workbench.model.CellObject("mesh3", "bracket.stl", org.robopro.app.workbench.model.CellObject.Kind.MESH,
                Pose.translation(1, 1, 0.2).times(Pose.rotZ(-1.1)), new org.robopro.models.Vec3(0.001, 0.001, 0.001), "meshes/bracket.stl", 0x9AA5B1));
        var wobjs = new java.util.ArrayList<>(d.workObjects());
        wobjs.add(new WorkObject("wobj_fixture", Pose.translation(1.1, -0.3, 0.75).times(Pose.rotZ(0.5))));
        var tool = new org.robopro.app.workbench.model.Tool(d.tool().name(), Pose.translation(0.01, 0, 0.32).times(Pose.rotY(0.4)), 0.025, 0.28, 2.5);
        List<Target> targets = List.of(
                new Target("p10", Pose.translation(1.2, 0.1, 0.9).times(Pose.rotY(Math.PI)), new double[] {0, 0.4, 0.1, 0, 1.2, 0},
                        new ConfData(0, 0, 0, 1)),
                new Target("p20", Pose.translation(1.25, 0.0, 0.85).times(Pose.rotY(2.9)), new double[] {0.1, 0.45, 0.05, 0.1, 1.1, -0.2},
                        new ConfData(0, -1, 1, 0), "wobj_fixture"),
                new Target("p30", Pose.translation(1.3, -0.1, 0.85).times(Pose.rotY(3.0)), new double[] {-0.1, 0.5, 0.0, 0, 1.0, 0.3},
                        new ConfData(-1, 0, 0, 1), "wobj_fixture"),
                new Target("jHome", Pose.translation(1.0, 0, 1.2).times(Pose.rotY(Math.PI)), new double[] {0, 0.35, 0.17, 0, 0.87, 0},
                        new ConfData(0, 0, 0, 0)));
        // Imported from a module: the MoveJ linked to its statement, a WaitTime kept as written.
        var module = org.robopro.programs.RapidParser.parse("MODULE Cell\n  PROC main()\n    MoveJ p10, v500, z50, tool0;\n"
                + "    WaitTime 0.5;\n  ENDPROC\nENDMODULE\n", "Cell.mod");
        var body = ((org.robopro.programs.rapid.RapidAst.Routine) module.tree().items().get(0)).body();
        List<Instruction> program = List.of(new Instruction(Instruction.Type.MOVEABSJ, "jHome", 1000, 0),
                new Instruction(Instruction.Type.MOVEJ, "p10", 500, 50).readFrom(body.get(0)), Instruction.kept(body.get(1)),
                new Instruction(Instruction.Type.MOVEL, "p20", 123.5, 0),
                new Instruction(Instruction.Type.MOVEC, "p30", 20, 1.5, "p20"), new Instruction(Instruction.Type.MOVEABSJ, "jHome", 1000, 0));
        return new ProjectData(d.robotRef(), d.robot(), Pose.translation(0.1, -0.05, 0.02).times(Pose.rotZ(0.2)), tool, objects, wobjs,
                targets, program, "calib/irb2000-cal.robot.json", "wobj_fixture", new double[] {0.1, 0.2, 0.3, -0.4, 0.5, -0.6},
                new org.robopro.app.workbench.model.ProgramModule.Source(module, "main"));
    }

    @Test
    void writeRead_everyField_reopensExactlyAsSaved() throws Exception {
        ProjectData d = everyField();
        assertTrue(d.activeWorkObject().equals("wobj_fixture") && d.q() != null && d.calibrationReference() != null);
        java.util.Set<org.robopro.app.workbench.model.CellObject.Kind> kinds = java.util.EnumSet.noneOf(org.robopro.app.workbench.model.CellObject.Kind.class);
        d.objects().forEach(o -> kinds.add(o.kind()));
        assertEquals(java.util.EnumSet.allOf(org.robopro.app.workbench.model.CellObject.Kind.class), kinds, "every object kind in the sample");
        java.util.Set<Instruction.Type> types = java.util.EnumSet.noneOf(Instruction.Type.class);
        d.program().forEach(i -> types.add(i.type()));
        assertEquals(java.util.EnumSet.allOf(Instruction.Type.class), types, "every instruction type in the sample");
        Path f = dir.resolve("every.robopro.json");
        ProjectStore.write(d, f, false);
        ProjectRoundTrip.assertSame(d, ProjectStore.read(f));
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
    void read_formerProgramFile_opensMigratedAsProject() throws Exception {
        // A file of the programs module's former format: taught targets (joints through FK) and typed ones.
        Path f = dir.resolve("demo.json");
        Files.writeString(f, org.robopro.app.cli.ProgramCommandTest.PROJECT);
        ProjectData d = ProjectStore.read(f);
        assertEquals("irb2000", d.robotRef());
        assertEquals("tTorch", d.tool().name());
        assertEquals(List.of("jHome", "pA", "pB"), d.targets().stream().map(Target::name).toList());
        assertEquals(List.of(Instruction.Type.MOVEABSJ, Instruction.Type.MOVEJ, Instruction.Type.MOVEL),
                d.program().stream().map(Instruction::type).toList());
        assertEquals(200, d.program().get(2).speedMmPerS(), 1e-9);
        assertEquals(10, d.program().get(1).zoneMm(), 1e-9);
        // pA was taught at (17, 11, 6, 11, 40, -17) deg: the migrated target stands where FK puts the TCP.
        WorkbenchModel m = new WorkbenchModel(d.robotRef(), d.robot());
        m.load(d);
        double[] qA = java.util.Arrays.stream(new double[] {17, 11, 6, 11, 40, -17}).map(Math::toRadians).toArray();
        Pose tcpA = d.worldTbase().times(m.kinematics().flange(qA)).times(d.tool().flangeTtcp());
        assertEquals(0, d.targets().get(1).worldTtcp().distanceTo(tcpA), 1e-9);
        // Saved, it is a project file of the one format.
        Path saved = dir.resolve("demo.robopro.json");
        ProjectStore.write(d, saved, false);
        assertTrue(Files.readString(saved).contains("\"format\" : \"robopro-project\""));
        assertEquals(d.program(), ProjectStore.read(saved).program());
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
