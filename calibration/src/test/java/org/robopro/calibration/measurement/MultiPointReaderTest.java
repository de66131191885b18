package org.robopro.calibration.measurement;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Collections;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.models.InputException;
import org.robopro.models.JointType;
import org.robopro.models.Vec3;

/** Several measured points per pose (long and wide form) and distance-only rows. */
class MultiPointReaderTest {
    static final List<JointType> SIX = Collections.nCopies(6, JointType.REVOLUTE);

    static final String HEAD = """
            # robopro-measurements 1
            # length-unit: mm
            # angle-unit: deg
            # frame: tracker
            """;

    /** Long form: pose 2's rows in another point order, a set column, directions. */
    static final String LONG = HEAD + """
            pose,point,q1,q2,q3,q4,q5,q6,x,y,z,dir1,dir2,dir3,dir4,dir5,dir6,set
            1,A,12.5,-20.1,15,40.2,-35.7,10,2315.4,-204.1,1260.5,1,1,1,1,1,1,train
            1,B,12.5,-20.1,15,40.2,-35.7,10,2395.4,-204.1,1260.5,1,1,1,1,1,1,train
            1,C,12.5,-20.1,15,40.2,-35.7,10,2355.4,-164.1,1260.5,1,1,1,1,1,1,train
            2,C,0,0,0,0,90,0,1040,40,1615,0,0,0,0,0,0,validate
            2,A,0,0,0,0,90,0,1000,0,1615,0,0,0,0,0,0,validate
            2,B,0,0,0,0,90,0,1080,0,1615,0,0,0,0,0,0,validate
            """;

    static final String WIDE = HEAD + """
            pose,q1,q2,q3,q4,q5,q6,x1,y1,z1,x2,y2,z2,x3,y3,z3
            1,12.5,-20.1,15,40.2,-35.7,10,2315.4,-204.1,1260.5,2395.4,-204.1,1260.5,2355.4,-164.1,1260.5
            2,0,0,0,0,90,0,1000,0,1615,1080,0,1615,1040,40,1615
            """;

    static final String DISTANCE = """
            # robopro-measurements 1
            # length-unit: mm
            # angle-unit: deg
            # anchor: 1500, -200, 0
            pose,q1,q2,q3,q4,q5,q6,distance
            1,12.5,-20.1,15,40.2,-35.7,10,1523.118
            2,0,0,0,0,90,0,1702.5
            """;

    static InputException fails(String text) {
        return assertThrows(InputException.class, () -> MeasurementReader.parse("m.csv", text, SIX));
    }

    @Test
    void longForm_groupsRowsByPose_inTheFirstPosesPointOrder() {
        MeasurementSet s = MeasurementReader.parse("m.csv", LONG, SIX);
        assertEquals(2, s.size());
        assertEquals(List.of("A", "B", "C"), s.pointNames());
        assertEquals(3, s.pointCount());
        Measurement p2 = s.rows().get(1);
        assertEquals(new Vec3(1.0, 0, 1.615), p2.point(0)); // A, though written second
        assertEquals(new Vec3(1.08, 0, 1.615), p2.point(1));
        assertEquals(new Vec3(1.04, 0.04, 1.615), p2.point(2));
        assertEquals(p2.point(0), p2.position());
        assertEquals(Measurement.Split.VALIDATE, p2.set());
        assertEquals(9, p2.line()); // its first row
        assertEquals(1, s.split(Measurement.Split.VALIDATE).size());
    }

    @Test
    void wideForm_readsNumberedPoints() {
        MeasurementSet s = MeasurementReader.parse("m.csv", WIDE, SIX);
        assertEquals(List.of("1", "2", "3"), s.pointNames());
        assertEquals(new Vec3(2.3554, -0.1641, 1.2605), s.rows().get(0).point(2));
        // The same points as the long form.
        MeasurementSet l = MeasurementReader.parse("m.csv", LONG, SIX);
        for (int i = 0; i < 2; i++) assertEquals(l.rows().get(i).points(), s.rows().get(i).points());
    }

    @Test
    void pointColumnWithOneName_isAnOrdinarySinglePointFile() {
        String one = HEAD + "pose,point,q1,q2,q3,q4,q5,q6,x,y,z\n1,smr,1,2,3,4,5,6,1000,0,1000\n2,smr,0,0,0,0,90,0,1000,0,1615\n";
        MeasurementSet s = MeasurementReader.parse("m.csv", one, SIX);
        assertEquals(1, s.pointCount());
        assertTrue(s.pointNames().isEmpty());
    }

    @Test
    void distance_readsLengthsAndTheAnchor() {
        MeasurementSet s = MeasurementReader.parse("m.csv", DISTANCE, SIX);
        assertTrue(s.isDistance());
        assertEquals(1.523118, s.rows().get(0).distance(), 1e-12);
        assertNull(s.rows().get(0).position());
        assertEquals(new Vec3(1.5, -0.2, 0), s.anchor());
        MeasurementSet d = MeasurementReader.parse("m.csv", DISTANCE.replace("# anchor: 1500, -200, 0\n", "").replace(",distance", ",d"), SIX);
        assertNull(d.anchor());
        assertEquals(1.7025, d.rows().get(1).distance(), 1e-12);
    }

    private static void located(InputException e, int line, String field, String words) {
        assertEquals(line, e.line(), e.getMessage());
        assertEquals(field, e.field(), e.getMessage());
        assertTrue(e.getMessage().contains(words), e.getMessage());
        assertTrue(e.getMessage().startsWith("m.csv:" + line + ":"), e.getMessage());
    }

    @Test
    void longForm_badInput_isLocated() {
        // a pose without one of the points: named at its first row
        located(fails(LONG.replace("2,B,0,0,0,0,90,0,1080,0,1615,0,0,0,0,0,0,validate\n", "")), 9, "point", "has no point 'B'");
        // the same point twice
        located(fails(LONG.replace("2,A,0,0", "2,C,0,0")), 10, "point", "given twice (first on line 9)");
        // a point the first pose does not have
        located(fails(LONG.replace("2,A,0,0", "2,D,0,0")), 10, "point", "not measured at the first pose");
        // a pose whose rows disagree on the joints
        located(fails(LONG.replace("1,B,12.5,-20.1,15,", "1,B,12.5,-20.1,15.01,")), 7, "q3", "other joint values than on line 6");
        // a pose split between training and validation
        located(fails(LONG.replace("1,1,1,1,1,1,train\n1,C", "1,1,1,1,1,1,validate\n1,C")), 7, "set", "belong to one set");
        // an empty point name
        located(fails(LONG.replace("1,C,12.5", "1,,12.5")), 8, "point", "empty point name");
        // orientations with several points
        located(fails(LONG.replace(",set\n", ",set,qw,qx,qy,qz\n").replace("train\n", "train,1,0,0,0\n").replace("validate\n", "validate,1,0,0,0\n")),
                5, "qw", "orientations with several points per pose are not supported");
    }

    @Test
    void wideForm_badInput_isLocated() {
        // mixed forms
        located(fails(WIDE.replace(",x3,y3,z3", ",x,y,z")), 5, "x", "mixes the one-point form");
        located(fails(WIDE.replace("pose,q1", "pose,point,q1").replace("\n1,12.5", "\n1,a,12.5").replace("\n2,0", "\n2,a,0")), 5, "point", "use one");
        // a point without all three coordinates
        located(fails(WIDE.replace(",z3", ",w3")), 5, "z3", "coordinate column 'z3' is missing");
        // a single numbered point
        located(fails(HEAD + "pose,q1,q2,q3,q4,q5,q6,x1,y1,z1\n1,1,2,3,4,5,6,7,8,9\n"), 5, "x1", "at least two points");
        // a bad number in point 3
        located(fails(WIDE.replace("1040,40,1615", "1040,4O,1615")), 7, "y3", "is not a number");
        // a gross value in point 2
        located(fails(WIDE.replace("1080,0,1615", "1080,0,1615000000")), 7, "z2", "outside any robot's reach");
    }

    @Test
    void distance_badInput_isLocated() {
        located(fails(DISTANCE.replace(",distance\n", ",distance,x\n").replace("1523.118\n", "1523.118,5\n").replace("1702.5\n", "1702.5,5\n")),
                5, "x", "has no coordinates");
        // 'd' next to coordinates is an extra column, as in files written before distances were read
        String withD = HEAD + "pose,q1,q2,q3,q4,q5,q6,x,y,z,d\n1,1,2,3,4,5,6,1000,0,1000,7\n";
        assertEquals(new Vec3(1, 0, 1), MeasurementReader.parse("m.csv", withD, SIX).rows().get(0).position());
        located(fails(DISTANCE.replace(",distance\n", ",distance,d\n").replace("1523.118\n", "1523.118,5\n").replace("1702.5\n", "1702.5,5\n")),
                5, "d", "name the same value");
        located(fails(DISTANCE.replace(",distance\n", ",point,distance\n").replace("10,1523", "10,a,1523").replace("90,0,1702", "90,0,a,1702")),
                5, "point", "has no coordinates");
        located(fails(DISTANCE.replace("1702.5", "-3")), 7, "distance", "must not be negative");
        located(fails(DISTANCE.replace("1702.5", "")), 7, "distance", "missing value");
        located(fails(DISTANCE.replace("1500, -200, 0", "1500, -200")), 4, "anchor", "three coordinates");
        located(fails(DISTANCE.replace("1500, -200, 0", "1500, abc, 0")), 4, "anchor", "is not a number");
        // an anchor in a file of positions
        InputException e = fails(WIDE.replace("# frame: tracker\n", "# frame: tracker\n# anchor: 1,2,3\n"));
        located(e, 5, "anchor", "belongs to distance measurements");
    }

    /**
     * Random damage to the three new forms (a line dropped or repeated, a field emptied, changed
     * or moved, a row's point renamed): every result is a set or an InputException naming the file,
     * never another exception. A cheap complement to the Jazzer fuzz test, run in every build.
     */
    @Test
    void damagedFiles_parseOrFailWithALocatedError() {
        java.util.Random rng = new java.util.Random(11);
        String[] seeds = {LONG, WIDE, DISTANCE};
        String[] junk = {"", "x", "-1", "1e400", "NaN", "A", "B", "C", "D", "0", "validate", "train", "2", "1,2", ";", " "};
        for (int n = 0; n < 4000; n++) {
            String[] lines = seeds[n % 3].split("\n", -1);
            java.util.List<String> ls = new java.util.ArrayList<>(List.of(lines));
            int edits = 1 + rng.nextInt(3);
            for (int e = 0; e < edits; e++) {
                int li = rng.nextInt(ls.size());
                switch (rng.nextInt(4)) {
                    case 0 -> ls.remove(li);
                    case 1 -> ls.add(li, ls.get(li));
                    default -> {
                        String[] f = ls.get(li).split(",", -1);
                        int k = rng.nextInt(f.length);
                        f[k] = rng.nextBoolean() ? junk[rng.nextInt(junk.length)] : f[rng.nextInt(f.length)];
                        ls.set(li, String.join(",", f));
                    }
                }
                if (ls.isEmpty()) ls.add("");
            }
            String text = String.join("\n", ls);
            try {
                MeasurementSet s = MeasurementReader.parse("m.csv", text, SIX);
                assertTrue(s.size() > 0);
            } catch (InputException ok) {
                assertTrue(ok.getMessage().startsWith("m.csv:"), ok.getMessage());
            } catch (RuntimeException bad) {
                throw new AssertionError("not an InputException for:\n" + text, bad);
            }
        }
    }
}
