package org.robopro.calibration.measurement;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Collections;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.models.InputException;
import org.robopro.models.JointType;

/** Distances between pairs of poses (a length artefact or ballbar probed by the robot): the format, its errors, the writer. */
public class PairDistanceTest {
    private static final List<JointType> SIX = Collections.nCopies(6, JointType.REVOLUTE);
    /** Metadata and the header of a pairs file with directions (the fuzz test mutates the rows after it). */
    static final String HEADER = "# robopro-measurements 1\n# length-unit: mm\n# angle-unit: deg\n"
            + "pose,q1,q2,q3,q4,q5,q6,from_q1,from_q2,from_q3,from_q4,from_q5,from_q6,distance,dir1,dir2,dir3,dir4,dir5,dir6,"
            + "from_dir1,from_dir2,from_dir3,from_dir4,from_dir5,from_dir6\n";
    static final String GOOD = HEADER
            + "2,12.5,-20.1,15,40.2,-35.7,10,0,0,0,0,90,0,812.5,1,-1,1,1,-1,1,1,1,1,1,1,1\n"
            + "3,5,5,5,5,5,5,12.5,-20.1,15,40.2,-35.7,10,420.25,1,1,1,1,1,1,1,-1,1,1,-1,1\n";

    static InputException fails(String text) {
        return assertThrows(InputException.class, () -> MeasurementReader.parse("bar.csv", text, SIX));
    }

    @Test
    void read_pairs_givesBothPosesAndTheLength() {
        MeasurementSet s = MeasurementReader.parse("bar.csv", GOOD, SIX);
        assertTrue(s.isPairs() && s.isDistance());
        assertNull(s.anchor());
        Measurement m = s.rows().get(1);
        assertEquals(0.42025, m.distance(), 1e-12);
        assertEquals(Math.toRadians(5), m.q(0), 1e-15);
        assertEquals(Math.toRadians(12.5), m.fromQ()[0], 1e-15);
        assertArrayEquals(new int[] {1, -1, 1, 1, -1, 1}, m.fromDirections());
        assertArrayEquals(new int[] {1, 1, 1, 1, 1, 1}, m.directions());
        assertArrayEquals(m.fromQ(), m.firstPose().q());
    }

    @Test
    void writer_roundTripsPairs() {
        MeasurementSet s = MeasurementReader.parse("bar.csv", GOOD, SIX);
        String text = MeasurementWriter.format(s, SIX);
        MeasurementSet back = MeasurementReader.parse("again.csv", text, SIX);
        assertEquals(s.rows(), back.rows());
    }

    @Test
    void errors_nameFileLineAndField() {
        String noDist = GOOD.replace(",distance,", ",x,").replace("812.5", "1,2,812.5").replace("420.25", "1,2,420.25")
                .replace(",x,", ",x,y,z,");
        InputException e = fails(noDist);
        assertTrue(e.getMessage().startsWith("bar.csv:4:") && e.getMessage().contains("field 'from_q6'")
                && e.getMessage().contains("no 'distance' column"), e.getMessage());

        e = fails(GOOD.replace("from_q3,", "from_qx,"));
        assertTrue(e.getMessage().startsWith("bar.csv:4:1: field 'from_q3'") && e.getMessage().contains("is missing"), e.getMessage());

        e = fails(GOOD.replace("3,5,5,5,5,5,5,12.5,-20.1", "3,5,5,5,5,5,5,12.5,abc"));
        assertTrue(e.getMessage().startsWith("bar.csv:6:") && e.getMessage().contains("field 'from_q2'"), e.getMessage());

        e = fails(GOOD.replace("3,5,5,5,5,5,5,12.5,-20.1", "3,5,5,5,5,5,5,12.5,1e9"));
        assertTrue(e.getMessage().startsWith("bar.csv:6:") && e.getMessage().contains("field 'from_q2'")
                && e.getMessage().contains("not a joint position"), e.getMessage());

        e = fails(GOOD.replace("# angle-unit: deg\n", "# angle-unit: deg\n# anchor: 1, 2, 3\n"));
        assertTrue(e.getMessage().startsWith("bar.csv:4:") && e.getMessage().contains("field 'anchor'")
                && e.getMessage().contains("has no anchor"), e.getMessage());

        String noFromDirs = GOOD.replace(",from_dir1,from_dir2,from_dir3,from_dir4,from_dir5,from_dir6", "")
                .replace(",1,1,1,1,1,1\n3,", "\n3,").replace(",1,-1,1,1,-1,1\n", "\n");
        e = fails(noFromDirs);
        assertTrue(e.getMessage().startsWith("bar.csv:4:") && e.getMessage().contains("field 'dir1'")
                && e.getMessage().contains("of both poses"), e.getMessage());

        e = fails(GOOD.replace("2,12.5,-20.1,15,40.2,-35.7,10,0,0,0,0,90,0,812.5,1,-1,1,1,-1,1,1,1,1,1,1,1",
                "2,12.5,-20.1,15,40.2,-35.7,10,0,0,0,0,90,0,812.5,1,-1,1,1,-1,1,1,1,1,2,1,1"));
        assertTrue(e.getMessage().startsWith("bar.csv:5:") && e.getMessage().contains("field 'from_dir4'"), e.getMessage());
    }
}
