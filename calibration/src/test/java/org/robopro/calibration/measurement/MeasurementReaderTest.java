package org.robopro.calibration.measurement;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Collections;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.models.InputException;
import org.robopro.models.JointType;

class MeasurementReaderTest {
    static final List<JointType> SIX = Collections.nCopies(6, JointType.REVOLUTE);

    static final String GOOD = """
            # robopro-measurements 1
            # robot: irb2000
            # length-unit: mm
            # angle-unit: deg
            # frame: tracker
            # instrument: laser tracker, sigma 0.03 mm
            pose,q1,q2,q3,q4,q5,q6,x,y,z,dir1,dir2,dir3,dir4,dir5,dir6,time_s,temp_c,payload_kg
            1,12.5,-20.1,15.0,40.2,-35.7,10.0,2315.412,-204.118,1260.503,1,-1,1,1,-1,1,0.0,20.1,0.0
            2,0,0,0,0,90,0,1000,0,1615,0,0,0,0,0,0,12.5,20.3,5
            """;

    static InputException fails(String text) {
        return assertThrows(InputException.class, () -> MeasurementReader.parse("m.csv", text, SIX));
    }

    static String replaceLine(String text, int line, String replacement) {
        String[] ls = text.split("\n", -1);
        ls[line - 1] = replacement;
        return String.join("\n", ls);
    }

    @Test
    void parse_specExample_convertsToSi() {
        MeasurementSet s = MeasurementReader.parse("m.csv", GOOD, SIX);
        assertEquals(2, s.size());
        assertEquals("tracker", s.frame());
        assertFalse(s.inBaseFrame());
        assertEquals("irb2000", s.robot());
        assertEquals("laser tracker, sigma 0.03 mm", s.metadata().get("instrument"));
        Measurement m = s.rows().get(0);
        assertEquals("1", m.poseId());
        assertEquals(Math.toRadians(12.5), m.q(0), 1e-15);
        assertEquals(2.315412, m.position().x(), 1e-12);
        assertArrayEquals(new int[] {1, -1, 1, 1, -1, 1}, m.directions());
        assertEquals(20.1, m.tempC(), 0);
        assertEquals(8, m.line());
        assertTrue(s.hasDirections() && s.hasTime() && s.hasTemperature() && s.hasPayload());
        assertFalse(s.hasOrientation());
        assertNull(m.set());
    }

    @Test
    void parse_columnsInOtherOrderUpperCaseAndSemicolons_areAccepted() {
        String t = """
                # robopro-measurements 1
                # length-unit: m
                # angle-unit: rad
                # frame: base
                Z;Y;X;Q2;Q1;POSE;extra;SET
                3;2;1;0.5;0.25;a;whatever;validate
                """;
        MeasurementSet s = MeasurementReader.parse("m.csv", t, null);
        assertTrue(s.inBaseFrame());
        assertEquals(2, s.dof());
        Measurement m = s.rows().get(0);
        assertEquals(1.0, m.position().x());
        assertEquals(3.0, m.position().z());
        assertEquals(0.25, m.q(0));
        assertEquals(Measurement.Split.VALIDATE, m.set());
    }

    @Test
    void parse_orientationColumns_areNormalisedQuaternions() {
        String t = """
                # robopro-measurements 1
                # length-unit: mm
                # angle-unit: deg
                pose,q1,x,y,z,qw,qx,qy,qz
                p1,10,1,2,3,0.70710678,0,0.70710678,0
                """;
        MeasurementSet s = MeasurementReader.parse("m.csv", t, List.of(JointType.REVOLUTE));
        double[] o = s.rows().get(0).orientation();
        assertEquals(1.0, o[0] * o[0] + o[1] * o[1] + o[2] * o[2] + o[3] * o[3], 1e-15);
        assertTrue(s.hasOrientation());
        assertEquals("instrument", s.frame());
    }

    @Test
    void parse_prismaticJoint_usesLengthUnit() {
        String t = """
                # robopro-measurements 1
                # length-unit: mm
                # angle-unit: deg
                pose,q1,q2,x,y,z
                1,90,250,0,0,0
                """;
        MeasurementSet s = MeasurementReader.parse("m.csv", t, List.of(JointType.REVOLUTE, JointType.PRISMATIC));
        assertEquals(Math.PI / 2, s.rows().get(0).q(0), 1e-15);
        assertEquals(0.25, s.rows().get(0).q(1), 1e-15);
    }

    @Test
    void parse_missingMagicLine_failsOnLine1() {
        InputException e = fails(GOOD.replace("# robopro-measurements 1\n", "# something else\n"));
        assertEquals(1, e.line());
    }

    @Test
    void parse_unknownLengthUnit_namesLineColumnAndField() {
        InputException e = fails(GOOD.replace("length-unit: mm", "length-unit: inch"));
        assertEquals(3, e.line());
        assertEquals(16, e.column());
        assertEquals("length-unit", e.field());
        assertTrue(e.getMessage().contains("inch"), e.getMessage());
    }

    @Test
    void parse_missingAngleUnit_saysWhatToAdd() {
        InputException e = fails(GOOD.replace("# angle-unit: deg\n", ""));
        assertTrue(e.getMessage().contains("# angle-unit: deg"), e.getMessage());
    }

    @Test
    void parse_missingRequiredColumn_failsOnHeader() {
        InputException e = fails(GOOD.replace(",x,y,z,", ",x,z,"));
        assertEquals(7, e.line());
        assertEquals("y", e.field());
    }

    @Test
    void parse_nonNumericValue_namesColumn() {
        InputException e = fails(GOOD.replace("2315.412", "23l5.412"));
        assertEquals(8, e.line());
        assertEquals("x", e.field());
        assertEquals(GOOD.split("\n")[7].indexOf("2315.412") + 1, e.column());
    }

    @Test
    void parse_nonFiniteValues_areRefused() {
        assertEquals("q2", fails(GOOD.replace("-20.1", "NaN")).field());
        assertEquals("q2", fails(GOOD.replace("-20.1", "Infinity")).field());
        assertEquals("q2", fails(GOOD.replace("-20.1", "1e400")).field());
        assertEquals("q2", fails(GOOD.replace("-20.1", "0x10")).field());
    }

    @Test
    void parse_grossValuesBeyondAnyReach_areRefusedPerRowWithLineColumnAndField() {
        // 1e6 mm = 1 km: a misread number, refused before any fit.
        InputException e = fails(GOOD.replace("-204.118", "1e6"));
        assertEquals(8, e.line());
        assertEquals("y", e.field());
        assertEquals(GOOD.replace("-204.118", "1e6").split("\n")[7].indexOf("1e6") + 1, e.column());
        assertTrue(e.getMessage().contains("reach"), e.getMessage());
        assertEquals("z", fails(GOOD.replace("1615", "1e200")).field());
        assertEquals("q5", fails(GOOD.replace("-35.7", "1e300")).field());
        // 99 m is still believable (a tracker far away).
        assertEquals(2, MeasurementReader.parse("m.csv", GOOD.replace("2315.412", "99000"), SIX).size());
    }

    @Test
    void parse_duplicatePoseId_namesBothLines() {
        InputException e = fails(GOOD.replace("\n2,0,0", "\n1,0,0"));
        assertEquals(9, e.line());
        assertEquals("pose", e.field());
        assertTrue(e.getMessage().contains("line 8"), e.getMessage());
    }

    @Test
    void parse_jointCountMismatch_saysBothCounts() {
        InputException e = assertThrows(InputException.class,
                () -> MeasurementReader.parse("m.csv", GOOD, Collections.nCopies(5, JointType.REVOLUTE)));
        assertTrue(e.getMessage().contains("6 joint columns") && e.getMessage().contains("5 joints"), e.getMessage());
    }

    @Test
    void parse_gapInJointColumns_isRefused() {
        assertEquals("q4", fails(GOOD.replace(",q4,", ",q44,")).field());
    }

    @Test
    void parse_rowWithWrongValueCount_isRefused() {
        InputException e = fails(GOOD.replace(",5\n", ",5,7\n"));
        assertEquals(9, e.line());
    }

    @Test
    void parse_badDirectionValue_isRefused() {
        assertEquals("dir2", fails(replaceLine(GOOD, 9, "2,0,0,0,0,90,0,1000,0,1615,0,2,0,0,0,0,12.5,20.3,5")).field());
    }

    @Test
    void parse_partialOrientationColumns_areRefused() {
        String t = """
                # robopro-measurements 1
                # length-unit: mm
                # angle-unit: deg
                pose,q1,x,y,z,qw,qx
                1,0,0,0,0,1,0
                """;
        assertThrows(InputException.class, () -> MeasurementReader.parse("m.csv", t, null));
    }

    @Test
    void parse_noRows_isRefused() {
        fails(GOOD.substring(0, GOOD.indexOf("\n1,") + 1));
    }

    @Test
    void parse_unknownMetadataKeys_areKept() {
        MeasurementSet s = MeasurementReader.parse("m.csv", GOOD.replace("# frame: tracker", "# frame: tracker\n# operator: ana"), SIX);
        assertEquals("ana", s.metadata().get("operator"));
    }
}
