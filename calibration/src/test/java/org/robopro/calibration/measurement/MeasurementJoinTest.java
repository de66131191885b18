package org.robopro.calibration.measurement;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Collections;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.models.InputException;
import org.robopro.models.JointType;

class MeasurementJoinTest {
    static final List<JointType> SIX = Collections.nCopies(6, JointType.REVOLUTE);
    static final String POINTS = "# frame: tracker\n# instrument: AT960\nname,x,y,z\nP2,1000,20,30\nP1,1100,-20,40.5\n";
    static final String LOG = "# robot: irb2000\nname,q1,q2,q3,q4,q5,q6\nP1,10,0,0,0,30,0\nP2,-10,5,0,0,30,90\nP3,0,0,0,0,0,0\n";

    @Test
    void join_byName_pointsMatchedToTheirJointsInPointOrder() {
        MeasurementSet s = MeasurementJoin.join("pts.csv", POINTS, "log.csv", LOG, SIX, 0.5);
        assertEquals(2, s.size());
        assertEquals("P2", s.rows().get(0).poseId());
        assertEquals(Math.toRadians(-10), s.rows().get(0).q(0), 1e-15);
        assertEquals(Math.toRadians(90), s.rows().get(0).q(5), 1e-15);
        assertEquals(1.1, s.rows().get(1).position().x(), 1e-15);
        assertEquals("tracker", s.frame());
        assertEquals("irb2000", s.robot());
        assertEquals("AT960", s.metadata().get("instrument"));
        // What it writes reads back as an ordinary measurement file.
        MeasurementSet back = MeasurementReader.parse("j.csv", MeasurementWriter.format(s, SIX), SIX);
        assertEquals(2, back.size());
        assertEquals(s.rows().get(1).q(0), back.rows().get(1).q(0), 1e-12);
    }

    @Test
    void join_byTime_nearestLogRowWithinTheTolerance() {
        String pts = "time,x,y,z\n1.02,1000,0,0\n2.96,1100,0,0\n";
        String log = "time_s,q1,q2,q3,q4,q5,q6\n0,0,0,0,0,0,0\n1,10,0,0,0,0,0\n2,20,0,0,0,0,0\n3,30,0,0,0,0,0\n";
        MeasurementSet s = MeasurementJoin.join("p.csv", pts, "l.csv", log, SIX, 0.1);
        assertEquals(Math.toRadians(10), s.rows().get(0).q(0), 1e-15);
        assertEquals(Math.toRadians(30), s.rows().get(1).q(0), 1e-15);
        assertEquals(2.96, s.rows().get(1).timeS(), 0);
        InputException e = assertThrows(InputException.class, () -> MeasurementJoin.join("p.csv", "time,x,y,z\n1.5,0,0,0\n", "l.csv", log, SIX, 0.1));
        assertTrue(e.getMessage().contains("p.csv:2") && e.getMessage().contains("time") && e.getMessage().contains("no joint-log row"), e.getMessage());
    }

    @Test
    void join_badRows_fileLineFieldErrors() {
        InputException missing = assertThrows(InputException.class,
                () -> MeasurementJoin.join("pts.csv", POINTS + "P9,1,2,3\n", "log.csv", LOG, SIX, 0.5));
        assertTrue(missing.getMessage().contains("pts.csv:6") && missing.getMessage().contains("'P9' is not in log.csv"), missing.getMessage());
        InputException notNumber = assertThrows(InputException.class,
                () -> MeasurementJoin.join("pts.csv", POINTS.replace("40.5", "4o.5"), "log.csv", LOG, SIX, 0.5));
        assertTrue(notNumber.getMessage().contains("pts.csv:5") && notNumber.getMessage().contains("'z'"), notNumber.getMessage());
        InputException twice = assertThrows(InputException.class,
                () -> MeasurementJoin.join("pts.csv", POINTS, "log.csv", LOG + "P1,0,0,0,0,0,0\n", SIX, 0.5));
        assertTrue(twice.getMessage().contains("log.csv:6") && twice.getMessage().contains("also on line 3"), twice.getMessage());
        InputException joints = assertThrows(InputException.class,
                () -> MeasurementJoin.join("pts.csv", POINTS, "log.csv", "name,q1,q2\nP1,0,0\n", SIX, 0.5));
        assertTrue(joints.getMessage().contains("q3"), joints.getMessage());
    }

    static final String SMR_POINTS = "# frame: tracker\nname,point,x,y,z\nP1,A,1000,20,30\nP1,B,1060,20,30\nP1,C,1030,72,30\n"
            + "P2,B,1160,-20,40\nP2,A,1100,-20,40\nP2,C,1130,32,40\n";

    @Test
    void join_pointColumn_severalReflectorsPerPose() {
        MeasurementSet s = MeasurementJoin.join("pts.csv", SMR_POINTS, "log.csv", LOG, SIX, 0.5);
        assertEquals(2, s.size());
        assertEquals(List.of("A", "B", "C"), s.pointNames());
        assertEquals(1.1, s.rows().get(1).point(0).x(), 1e-15); // A, written second for P2
        assertEquals(1.16, s.rows().get(1).point(1).x(), 1e-15);
        assertEquals(Math.toRadians(-10), s.rows().get(1).q(0), 1e-15);
        // Written in the long form and read back.
        MeasurementSet back = MeasurementReader.parse("j.csv", MeasurementWriter.format(s, SIX), SIX);
        assertEquals(s.pointNames(), back.pointNames());
        assertEquals(s.rows().get(1).points(), back.rows().get(1).points());
    }

    @Test
    void join_pointColumnByTime_groupsThePointsOfOneLogRow() {
        String pts = "point,time,x,y,z\nA,1.01,1000,0,0\nB,1.03,1060,0,0\nA,2.98,1100,0,0\nB,3.02,1160,0,0\n";
        String log = "time_s,q1,q2,q3,q4,q5,q6\n0,0,0,0,0,0,0\n1,10,0,0,0,0,0\n2,20,0,0,0,0,0\n3,30,0,0,0,0,0\n";
        MeasurementSet s = MeasurementJoin.join("p.csv", pts, "l.csv", log, SIX, 0.1);
        assertEquals(2, s.size());
        assertEquals("2", s.rows().get(0).poseId()); // the log's second row
        assertEquals(Math.toRadians(30), s.rows().get(1).q(0), 1e-15);
        assertEquals(1.01, s.rows().get(0).timeS(), 0);
    }

    @Test
    void join_pointColumn_badRowsAreLocated() {
        InputException missing = assertThrows(InputException.class, () -> MeasurementJoin.join("pts.csv",
                SMR_POINTS.replace("P2,C,1130,32,40\n", ""), "log.csv", LOG, SIX, 0.5));
        assertEquals(6, missing.line());
        assertTrue(missing.getMessage().contains("pose 'P2' has no point 'C'"), missing.getMessage());
        InputException twice = assertThrows(InputException.class, () -> MeasurementJoin.join("pts.csv",
                SMR_POINTS.replace("P2,A,", "P2,B,"), "log.csv", LOG, SIX, 0.5));
        assertEquals(7, twice.line());
        assertEquals("point", twice.field());
        assertTrue(twice.getMessage().contains("given twice (first on line 6)"), twice.getMessage());
        InputException other = assertThrows(InputException.class, () -> MeasurementJoin.join("pts.csv",
                SMR_POINTS.replace("P2,C,", "P2,D,"), "log.csv", LOG, SIX, 0.5));
        assertTrue(other.getMessage().startsWith("pts.csv:8:") && other.getMessage().contains("not measured at the first pose"), other.getMessage());
        InputException empty = assertThrows(InputException.class, () -> MeasurementJoin.join("pts.csv",
                SMR_POINTS.replace("P1,C,", "P1,,"), "log.csv", LOG, SIX, 0.5));
        assertTrue(empty.getMessage().startsWith("pts.csv:5:") && empty.getMessage().contains("empty point name"), empty.getMessage());
    }
}
