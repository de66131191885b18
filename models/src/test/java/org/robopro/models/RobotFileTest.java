package org.robopro.models;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class RobotFileTest {
    @TempDir Path dir;

    /** A small valid file; the error tests change one thing in it. Line numbers matter. */
    static final String VALID = String.join("\n",
            "// two-joint test robot",                                                              // 1
            "{",                                                                                     // 2
            "  \"format\": \"robopro-robot 1\",",                                                    // 3
            "  \"name\": \"two\",",                                                                  // 4
            "  \"joints\": [",                                                                       // 5
            "    {\"name\": \"a\", \"type\": \"revolute\", \"point\": [0, 0, 100], \"axis\": [0, 0, 1], \"limits\": [-90, 90], \"max_speed\": 100},", // 6
            "    {\"name\": \"b\", \"type\": \"prismatic\", \"point\": [10, 0, 100], \"axis\": [1, 0, 0], \"limits\": [0, 500], \"max_speed\": 250}", // 7
            "  ],",                                                                                  // 8
            "  \"flange\": {\"origin\": [510, 0, 100], \"z_axis\": [1, 0, 0], \"x_axis\": [0, 0, -1]},", // 9
            "  \"coupling\": [{\"joint\": \"b\", \"terms\": [{\"q\": \"b\", \"factor\": 1}, {\"q\": \"a\", \"factor\": 0.5}]}],", // 10
            "  \"source\": \"test\"",                                                                // 11
            "}");

    @Test
    void parse_validFile_convertsMmAndDegToSi() {
        RobotDescription r = RobotFile.parse("t.json", VALID);
        assertEquals(2, r.dof());
        assertEquals(new Vec3(0, 0, 0.1), r.joints().get(0).point());
        assertEquals(Math.PI / 2, r.joints().get(0).max());
        assertEquals(0.5, r.joints().get(1).max());
        assertEquals(0.25, r.joints().get(1).maxSpeed());
        assertEquals(List.of(new CouplingTerm(2, 2, 1), new CouplingTerm(2, 1, 0.5)), r.coupling());
        assertEquals("two", r.displayName());
    }

    private static InputException bad(String from, String to) {
        assertTrue(VALID.contains(from), "test text must contain " + from);
        return assertThrows(InputException.class, () -> RobotFile.parse("t.json", VALID.replace(from, to)));
    }

    private static void assertError(InputException e, int line, String field, String problemPart) {
        assertEquals("t.json", e.file());
        assertEquals(line, e.line(), e.getMessage());
        assertTrue(e.column() > 0, e.getMessage());
        assertEquals(field, e.field(), e.getMessage());
        assertTrue(e.problem().contains(problemPart), e.getMessage());
    }

    @Test
    void parse_unknownJointType_namesTypeField() {
        assertError(bad("\"prismatic\"", "\"rotary\""), 7, "joints[1].type", "unknown joint type 'rotary'");
    }

    @Test
    void parse_zeroAxis_namesAxisField() {
        assertError(bad("\"axis\": [1, 0, 0]", "\"axis\": [0, 0, 0]"), 7, "joints[1].axis", "must not be zero");
    }

    @Test
    void parse_hugeAxisComponent_refusedAsOutOfRange() {
        assertError(bad("\"axis\": [1, 0, 0]", "\"axis\": [1e400, 0, 0]"), 7, "joints[1].axis[0]", "out of range");
    }

    @Test
    void parse_couplingNamingMissingJoint_namesTerm() {
        assertError(bad("{\"q\": \"a\"", "{\"q\": \"c\""), 10, "coupling[0].terms[1].q", "no joint named 'c'");
    }

    @Test
    void parse_limitsMinAboveMax_namesLimits() {
        assertError(bad("[-90, 90]", "[90, -90]"), 6, "joints[0].limits", "greater than maximum");
    }

    @Test
    void parse_missingField_namesIt() {
        assertError(bad("\"point\": [0, 0, 100], ", ""), 6, "joints[0].point", "missing required field");
    }

    @Test
    void parse_wrongType_namesFieldAndTypes() {
        assertError(bad("\"max_speed\": 100", "\"max_speed\": \"fast\""), 6, "joints[0].max_speed", "expected a number, got a string");
    }

    @Test
    void parse_unknownVersion_namesFormat() {
        assertError(bad("robopro-robot 1", "robopro-robot 2"), 3, "format", "unknown format version '2'");
    }

    @Test
    void parse_otherFormatTag_saysNotARobotFile() {
        assertError(bad("robopro-robot 1", "robopro-cell 1"), 3, "format", "not a robopro-robot file");
    }

    @Test
    void parse_duplicateJointNames_namesSecond() {
        assertError(bad("{\"name\": \"b\"", "{\"name\": \"a\""), 7, "joints[1].name", "duplicate joint name 'a'");
    }

    @Test
    void parse_nonOrthogonalFlange_namesXAxis() {
        assertError(bad("\"x_axis\": [0, 0, -1]", "\"x_axis\": [0.1, 0, -1]"), 9, "flange.x_axis", "not orthogonal");
    }

    @Test
    void parse_misspeltField_namesIt() {
        assertError(bad("\"max_speed\": 250", "\"max_sped\": 250"), 7, "joints[1].max_sped", "unknown field");
    }

    @Test
    void parse_duplicateKey_namesIt() {
        assertError(bad("\"source\": \"test\"", "\"source\": \"test\", \"source\": \"x\""), 11, "source", "duplicate field");
    }

    @Test
    void parse_wrongArity_namesField() {
        assertError(bad("\"point\": [10, 0, 100]", "\"point\": [10, 0]"), 7, "joints[1].point", "expected 3 values, got 2");
    }

    @Test
    void parse_malformedJson_givesLineAndColumn() {
        InputException e = bad("\"source\": \"test\"", "\"source\": test");
        assertEquals(11, e.line());
        assertTrue(e.column() > 0);
        assertTrue(e.problem().startsWith("malformed JSON"), e.getMessage());
    }

    @Test
    void parse_trailingContent_refused() {
        InputException e = assertThrows(InputException.class, () -> RobotFile.parse("t.json", VALID + " {}"));
        assertEquals(12, e.line());
    }

    @Test
    void parse_emptyText_refused() {
        assertThrows(InputException.class, () -> RobotFile.parse("t.json", "  // nothing\n"));
    }

    @Test
    void read_missingFile_throwsInputException() {
        InputException e = assertThrows(InputException.class, () -> RobotFile.read(dir.resolve("none.json")));
        assertTrue(e.problem().contains("no such file"));
    }

    @Test
    void read_notUtf8_throwsInputException() throws Exception {
        Path f = dir.resolve("latin1.json");
        Files.write(f, new byte[] {'{', (byte) 0xe9, '}'});
        assertThrows(InputException.class, () -> RobotFile.read(f));
    }

    @Test
    void format_thenParse_shippedRobots_equal() {
        for (String n : RobotLibrary.shippedNames()) {
            RobotDescription r = RobotLibrary.load(n);
            assertEquals(r, RobotFile.parse("x", RobotFile.format(r)), n);
        }
    }

    @Test
    void format_thenParse_randomRobots_equalExactly() {
        SplittableRandom rnd = new SplittableRandom(2024);
        for (int k = 0; k < 200; k++) {
            RobotDescription r = randomRobot(rnd);
            String text = RobotFile.format(r);
            assertEquals(r, RobotFile.parse("x", text), text);
        }
    }

    @Test
    void write_existingFile_refusedUnlessOverwrite() throws Exception {
        Path f = dir.resolve("r.robot.json");
        RobotDescription r = RobotFile.parse("t", VALID);
        RobotFile.write(r, f, false);
        assertThrows(FileAlreadyExistsException.class, () -> RobotFile.write(r, f, false));
        RobotFile.write(r, f, true);
        assertEquals(r, RobotFile.read(f));
    }

    static RobotDescription randomRobot(SplittableRandom rnd) {
        int n = 1 + rnd.nextInt(7);
        List<JointDescription> joints = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            JointType t = rnd.nextInt(4) == 0 ? JointType.PRISMATIC : JointType.REVOLUTE;
            double a = rnd.nextDouble(-3, 3), b = rnd.nextDouble(-3, 3);
            double min = rnd.nextInt(5) == 0 ? Double.NEGATIVE_INFINITY : Math.min(a, b);
            double max = rnd.nextInt(5) == 0 ? Double.POSITIVE_INFINITY : Math.max(a, b);
            double speed = rnd.nextInt(5) == 0 ? Double.POSITIVE_INFINITY : rnd.nextDouble(0.01, 10);
            joints.add(new JointDescription("j" + (i + 1) + (rnd.nextBoolean() ? "" : " \"q\u00e9\""), t,
                    randomVec(rnd, 2), randomUnit(rnd), min, max, speed));
        }
        Vec3 z = randomUnit(rnd);
        Vec3 x = z.cross(randomUnit(rnd)).normalized();
        FrameDescription flange = new FrameDescription(randomVec(rnd, 2), x, z);
        List<CouplingTerm> coupling = new ArrayList<>();
        if (n >= 2 && rnd.nextBoolean()) {
            coupling.add(new CouplingTerm(2, 2, 1));
            coupling.add(new CouplingTerm(2, 1, rnd.nextDouble(-2, 2)));
        }
        Optional<MassModel> mass = Optional.empty();
        if (rnd.nextBoolean())
            mass = Optional.of(new MassModel(List.of(new LinkMass(n, "link", rnd.nextDouble(0, 50), randomVec(rnd, 2))),
                    rnd.nextDouble(0, 20), randomVec(rnd, 0.2), new Vec3(0, 0, -9.81)));
        List<MeshRef> meshes = rnd.nextBoolean() ? List.of(new MeshRef(0, "meshes/base.stl", 0.001, false),
                new MeshRef(n, "meshes/l.obj", 1, true)) : List.of();
        List<EffectDescription> effects = rnd.nextBoolean()
                ? List.of(new EffectDescription("joint-compliance", List.of(1, n), Map.of("k1", rnd.nextDouble(), "k2", 1e-7)))
                : List.of();
        Map<String, String> prov = rnd.nextBoolean() ? Map.of("calibrated-from", "m.csv", "date", "2025-01-01") : Map.of();
        return new RobotDescription("r" + rnd.nextInt(100), "Robot \u00e4 \\ / \n", joints, flange, coupling, mass, meshes,
                effects, "src", prov);
    }

    static Vec3 randomVec(SplittableRandom rnd, double s) {
        return new Vec3(rnd.nextDouble(-s, s), rnd.nextDouble(-s, s), rnd.nextDouble(-s, s));
    }

    static Vec3 randomUnit(SplittableRandom rnd) {
        Vec3 v;
        do v = randomVec(rnd, 1); while (v.norm() < 0.1);
        Vec3 u = v.normalized();
        // Only vectors that are unit to 1e-12 are kept as written; normalised ones always are.
        return u;
    }
}
