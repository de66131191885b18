package org.robopro.models;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class CellFileTest {
    @TempDir Path dir;

    @Test
    void shipped_weldingCell_hasRobotTablePartsTorchAndWorkObject() {
        CellDescription c = CellFile.shipped("irb2000-welding");
        assertEquals("irb2000", c.robot());
        assertEquals(PoseDescription.IDENTITY, c.worldTbase());
        assertTrue(c.objects().stream().anyMatch(o -> o.name().equals("table") && o.kind() == CellObject.Kind.BOX));
        ToolDescription torch = c.tools().get(0);
        assertEquals(0.34, torch.flangeTtcp().position().z(), 1e-12);
        // tilt about y: the quaternion of a 35 deg rotation about y
        assertEquals(Math.cos(Math.toRadians(35) / 2), torch.flangeTtcp().qw(), 1e-12);
        assertEquals(Math.sin(Math.toRadians(35) / 2), torch.flangeTtcp().qy(), 1e-12);
        assertEquals("wobj_table", c.workObjects().get(0).name());
        assertEquals(RobotLibrary.load("irb2000"), CellFile.loadRobot(c, null));
    }

    @Test
    void shipped_weldingCell_partsRestOnTableWithinCrudeReach() {
        CellDescription c = CellFile.shipped("irb2000-welding");
        CellObject table = c.objects().stream().filter(o -> o.name().equals("table")).findFirst().orElseThrow();
        CellObject plate = c.objects().stream().filter(o -> o.name().equals("base_plate")).findFirst().orElseThrow();
        double tableTop = table.worldTobject().position().z() + table.size().z() / 2;
        assertEquals(tableTop, plate.worldTobject().position().z() - plate.size().z() / 2, 1e-12);
        RobotDescription r = CellFile.loadRobot(c, null);
        Vec3 shoulder = r.joints().get(1).point();
        double reach = r.joints().get(2).point().minus(shoulder).norm()
                + r.joints().get(4).point().minus(r.joints().get(2).point()).norm()
                + c.tools().get(0).flangeTtcp().position().norm();
        Vec3 seam = plate.worldTobject().position().plus(new Vec3(0, 0, plate.size().z() / 2));
        assertTrue(seam.minus(shoulder).norm() < 0.85 * reach, "seam " + seam + " vs reach " + reach);
        assertTrue(table.worldTobject().position().x() - table.size().x() / 2 > 0.3, "table clear of the robot foot");
    }

    @Test
    void format_thenParse_shippedAndRandomCells_equal() {
        CellDescription c = CellFile.shipped("irb2000-welding");
        assertEquals(c, CellFile.parse("x", CellFile.format(c)));
        SplittableRandom rnd = new SplittableRandom(5);
        for (int i = 0; i < 100; i++) {
            PoseDescription p = PoseDescription.fromRpy(RobotFileTest.randomVec(rnd, 3), rnd.nextDouble(-3, 3),
                    rnd.nextDouble(-1.5, 1.5), rnd.nextDouble(-3, 3));
            CellDescription r = new CellDescription("c" + i, "robots/my.robot.json", p,
                    List.of(new CellObject("m", CellObject.Kind.MESH, p, Vec3.ZERO, new Rgba(rnd.nextDouble(), 0.5, 0, 0.25),
                            "meshes/fixture.stl", 0.001),
                            new CellObject("cyl", CellObject.Kind.CYLINDER, PoseDescription.IDENTITY, new Vec3(0.1, 0.1, rnd.nextDouble(0.01, 1)),
                                    new Rgba(1, 1, 1, 1), "", 1)),
                    List.of(new ToolDescription("t", p, rnd.nextDouble(0, 10), RobotFileTest.randomVec(rnd, 0.3))),
                    List.of(new WorkObjectDescription("w", p)));
            assertEquals(r, CellFile.parse("x", CellFile.format(r)));
        }
    }

    @Test
    void write_thenRead_cellWithRelativeRobotPath_resolvesAgainstCellFolder() throws Exception {
        RobotLibrary.write(RobotLibrary.load("irb2400"), dir.resolve("r.robot.json"), false);
        CellDescription c = new CellDescription("c", "r.robot.json", PoseDescription.IDENTITY, List.of(), List.of(), List.of());
        Path f = dir.resolve("c.cell.json");
        CellFile.write(c, f, false);
        assertEquals(c, CellFile.read(f));
        assertEquals(RobotLibrary.load("irb2400"), CellFile.loadRobot(CellFile.read(f), f));
    }

    static final String CELL = String.join("\n",
            "{\"format\": \"robopro-cell 1\", \"name\": \"c\", \"robot\": {\"ref\": \"irb2000\"},", // 1
            " \"objects\": [",                                                                         // 2
            "  {\"name\": \"t\", \"kind\": \"box\", \"size\": [1, 2, 3], \"colour\": [0.5, 0.5, 0.5]}", // 3
            " ],",                                                                                     // 4
            " \"tools\": [{\"name\": \"torch\", \"tcp\": {\"position\": [0, 0, 300], \"quaternion\": [1, 0, 0, 0]}}]", // 5
            "}");

    private static InputException bad(String from, String to) {
        assertTrue(CELL.contains(from), from);
        return assertThrows(InputException.class, () -> CellFile.parse("c.json", CELL.replace(from, to)));
    }

    @Test
    void parse_validSmallCell_defaultsPosesAndColours() {
        CellDescription c = CellFile.parse("c.json", CELL);
        assertEquals(new Vec3(0.001, 0.002, 0.003), c.objects().get(0).size());
        assertEquals(PoseDescription.IDENTITY, c.objects().get(0).worldTobject());
    }

    @Test
    void parse_unknownKind_namesField() {
        InputException e = bad("\"box\"", "\"sphere\"");
        assertEquals(3, e.line());
        assertEquals("objects[0].kind", e.field());
    }

    @Test
    void parse_zeroSize_refused() {
        assertEquals("objects[0].size", bad("[1, 2, 3]", "[1, 0, 3]").field());
    }

    @Test
    void parse_colourOutOfRange_refused() {
        assertEquals("objects[0].colour[1]", bad("[0.5, 0.5, 0.5]", "[0.5, 2, 0.5]").field());
    }

    @Test
    void parse_zeroQuaternion_refused() {
        InputException e = bad("[1, 0, 0, 0]", "[0, 0, 0, 0]");
        assertEquals(5, e.line());
        assertEquals("tools[0].tcp.quaternion", e.field());
    }

    @Test
    void parse_nonUnitQuaternion_normalised() {
        CellDescription c = CellFile.parse("c.json", CELL.replace("[1, 0, 0, 0]", "[2, 0, 0, 0]"));
        assertEquals(1, c.tools().get(0).flangeTtcp().qw());
    }

    @Test
    void parse_robotFileFormatTag_refused() {
        assertEquals("format", bad("robopro-cell 1", "robopro-robot 1").field());
    }

    @Test
    void parse_missingRobotRef_refused() {
        assertEquals("robot.ref", bad("{\"ref\": \"irb2000\"}", "{}").field());
    }

    @Test
    void parse_duplicateObjectName_refused() {
        InputException e = bad("\"colour\": [0.5, 0.5, 0.5]}", "\"colour\": [0.5, 0.5, 0.5]}, {\"name\": \"t\", \"kind\": \"mesh\", \"mesh\": \"a.stl\"}");
        assertEquals("objects[1].name", e.field());
    }

    static final String SIGNALS = String.join("\n",
            "{\"format\": \"robopro-cell 1\", \"name\": \"c\", \"robot\": {\"ref\": \"irb2000\"},", // 1
            " \"signals\": [",                                                                        // 2
            "  {\"name\": \"doClamp\", \"type\": \"DO\"},",                                           // 3
            "  {\"name\": \"diClamped\", \"type\": \"DI\", \"follows\": \"doClamp\", \"delay_s\": 0.3},", // 4
            "  {\"name\": \"diPart\", \"type\": \"di\", \"value\": 0, \"script\": [{\"t_s\": 1.5, \"value\": 1}]},", // 5
            "  {\"name\": \"aoWire\", \"type\": \"AO\", \"value\": 2.5}",                           // 6
            " ]}");

    @Test
    void parse_signals_tableWithScriptsAndFollowersRoundTrips() {
        CellDescription c = CellFile.parse("c.json", SIGNALS);
        assertEquals(4, c.signals().size());
        SignalDescription clamped = c.signals().get(1);
        assertEquals(SignalDescription.Type.DI, clamped.type());
        assertEquals("doClamp", clamped.follows());
        assertEquals(0.3, clamped.delayS(), 0);
        assertEquals(new SignalDescription.Change(1.5, 1), c.signals().get(2).script().get(0));
        assertEquals(2.5, c.signals().get(3).value(), 0);
        assertEquals(c, CellFile.parse("x", CellFile.format(c)));
    }

    @Test
    void parse_badSignals_locatedErrors() {
        InputException e = assertThrows(InputException.class, () -> CellFile.parse("c.json", SIGNALS.replace("\"DO\"}", "\"DX\"}")));
        assertEquals(3, e.line(), e.getMessage());
        e = assertThrows(InputException.class, () -> CellFile.parse("c.json", SIGNALS.replace("\"follows\": \"doClamp\"", "\"follows\": \"doNone\"")));
        assertEquals(4, e.line(), e.getMessage());
        e = assertThrows(InputException.class, () -> CellFile.parse("c.json", SIGNALS.replace("\"value\": 1}", "\"value\": 2}")));
        assertEquals(5, e.line(), e.getMessage());
        assertTrue(e.getMessage().contains("digital"), e.getMessage());
        e = assertThrows(InputException.class, () -> CellFile.parse("c.json", SIGNALS.replace("\"type\": \"DO\"}", "\"type\": \"DO\", \"script\": []}")));
        assertEquals(3, e.line(), e.getMessage());
        e = assertThrows(InputException.class, () -> CellFile.parse("c.json", SIGNALS.replace("\"diPart\"", "\"doclamp\"")));
        assertTrue(e.getMessage().contains("duplicate"), e.getMessage());
    }
}
