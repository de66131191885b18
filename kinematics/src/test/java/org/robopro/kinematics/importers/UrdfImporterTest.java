package org.robopro.kinematics.importers;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.List;
import org.robopro.models.CouplingTerm;
import org.robopro.models.InputException;
import org.robopro.models.JointDescription;
import org.robopro.models.JointType;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotFile;
import org.robopro.models.Vec3;
import org.junit.jupiter.api.Test;

class UrdfImporterTest {
    private static void near(Vec3 expected, Vec3 actual) {
        assertTrue(expected.minus(actual).norm() < 1e-12, "expected " + expected + ", got " + actual);
    }

    @Test
    void parse_smallArm_foldsFixedJointsAndChainsFrames() throws IOException {
        RobotDescription r = UrdfImporter.parse("small-arm.urdf", DhImporterTest.resource("small-arm.urdf"));
        assertEquals("small_arm", r.name());
        assertEquals("small arm", r.displayName());
        assertEquals(List.of("waist_joint", "lift", "wrist_joint", "spin"), r.joints().stream().map(JointDescription::name).toList());
        JointDescription waist = r.joints().get(0), lift = r.joints().get(1), wrist = r.joints().get(2), spin = r.joints().get(3);
        near(new Vec3(0, 0, 0.3), waist.point());
        near(Vec3.Z, waist.axis());
        assertEquals(-3, waist.min());
        assertEquals(2, waist.maxSpeed());
        assertEquals(JointType.PRISMATIC, lift.type());
        near(new Vec3(0.1, 0, 0.5), lift.point());
        assertEquals(0.5, lift.max());
        // the fixed bracket turns the frame 90 deg about z: the wrist's x axis becomes base y
        near(new Vec3(0.3, 0.1, 0.5), wrist.point());
        near(Vec3.Y, wrist.axis());
        // continuous: no limits; roll -90 deg turns local z onto bracket y = base -x
        near(new Vec3(0.25, 0.1, 0.5), spin.point());
        near(new Vec3(-1, 0, 0), spin.axis());
        // the mimic joint's own controller value is held at 0; the coupling drives it
        assertEquals(0, spin.min());
        assertEquals(0, spin.max());
        assertEquals(Double.POSITIVE_INFINITY, spin.maxSpeed());
        // tool0 through the trailing fixed joint; the fixed camera branch is ignored
        near(new Vec3(0.23, 0.1, 0.5), r.flange().origin());
        near(new Vec3(-1, 0, 0), r.flange().zAxis());
        near(Vec3.Y, r.flange().xAxis());
        assertEquals(List.of(new CouplingTerm(4, 4, 1), new CouplingTerm(4, 3, 0.5)), r.coupling());
        assertEquals(r, RobotFile.parse("x", RobotFile.format(r)));
    }

    private static InputException bad(String body) {
        String text = "<robot name=\"t\">\n<link name=\"a\"/>\n<link name=\"b\"/>\n" + body + "\n</robot>\n";
        return assertThrows(InputException.class, () -> UrdfImporter.parse("t.urdf", text));
    }

    private static final String J = "<joint name=\"j\" type=\"%s\"><parent link=\"a\"/><child link=\"%s\"/>%s</joint>";

    @Test
    void parse_unsupportedJointType_namesJointAndLine() {
        InputException e = bad(String.format(J, "floating", "b", ""));
        assertEquals(4, e.line());
        assertEquals("joint.type", e.field());
        assertTrue(e.problem().contains("unsupported type 'floating'"), e.getMessage());
    }

    @Test
    void parse_missingLink_refused() {
        InputException e = bad(String.format(J, "fixed", "c", ""));
        assertEquals("child.link", e.field());
        assertTrue(e.problem().contains("no link named 'c'"));
    }

    @Test
    void parse_zeroAxis_refused() {
        assertEquals("axis.xyz", bad(String.format(J, "continuous", "b", "<axis xyz=\"0 0 0\"/>")).field());
    }

    @Test
    void parse_badNumber_refused() {
        InputException e = bad(String.format(J, "revolute", "b", "<axis xyz=\"0 0 1\"/><limit lower=\"-1\" upper=\"x\" velocity=\"1\"/>"));
        assertEquals("limit.upper", e.field());
    }

    @Test
    void parse_revoluteWithoutLimit_refused() {
        assertEquals("limit", bad(String.format(J, "revolute", "b", "")).field());
    }

    @Test
    void parse_lowerAboveUpper_refused() {
        assertEquals("limit.lower", bad(String.format(J, "prismatic", "b", "<limit lower=\"1\" upper=\"0\" velocity=\"1\"/>")).field());
    }

    @Test
    void parse_branchingChain_refused() {
        InputException e = assertThrows(InputException.class, () -> UrdfImporter.parse("t.urdf",
                "<robot name=\"t\"><link name=\"a\"/><link name=\"b\"/><link name=\"c\"/>"
                        + String.format(J, "continuous", "b", "").replace("name=\"j\"", "name=\"j1\"")
                        + String.format(J, "continuous", "c", "").replace("name=\"j\"", "name=\"j2\"") + "</robot>"));
        assertTrue(e.problem().contains("branches"), e.getMessage());
    }

    @Test
    void parse_onlyFixedJoints_refused() {
        assertTrue(bad(String.format(J, "fixed", "b", "")).problem().contains("no revolute"));
    }

    @Test
    void parse_malformedXml_givesLine() {
        InputException e = bad("<joint name=\"j\" type=\"fixed\">\n<parent link=\"a\">\n</joint>");
        assertEquals(6, e.line());
        assertTrue(e.problem().startsWith("malformed XML"));
    }

    @Test
    void parse_doctype_refusedWithoutFetching() {
        InputException e = assertThrows(InputException.class, () -> UrdfImporter.parse("t.urdf",
                "<?xml version=\"1.0\"?><!DOCTYPE r [<!ENTITY x SYSTEM \"file:///etc/passwd\">]><robot name=\"t\">&x;</robot>"));
        assertTrue(e.problem().contains("DOCTYPE"), e.getMessage());
    }

}
