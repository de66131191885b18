package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.models.Vec3;

class DirectionsTest {
    private static Measurement row(String id, double t, int line, Measurement.Split set, double... q) {
        return new Measurement(id, q, Vec3.ZERO, null, null, t, Double.NaN, Double.NaN, set, line);
    }

    @Test
    void infer_jointThatDidNotMove_keepsItsLastDirection() {
        Map<String, int[]> d = Directions.infer(List.of(row("a", 0, 1, null, 0, 0), row("b", 1, 2, null, 1, 0),
                row("c", 2, 3, null, 1, -1), row("d", 3, 4, null, 0.5, -1)));
        assertArrayEquals(new int[] {0, 0}, d.get("a"), "first pose at the zero position: not moved, unknown");
        assertArrayEquals(new int[] {1, 0}, d.get("b"), "joint 2 has not moved yet");
        assertArrayEquals(new int[] {1, -1}, d.get("c"), "joint 1 stood still: still on its + flank");
        assertArrayEquals(new int[] {-1, -1}, d.get("d"));
    }

    @Test
    void infer_firstPose_isTheMoveFromTheZeroPosition_orUnknownWithoutAStart() {
        List<Measurement> rows = List.of(row("a", 0, 1, null, 0.3, -0.2, 0), row("b", 1, 2, null, 0.1, -0.2, 0));
        Map<String, int[]> d = Directions.infer(rows);
        assertArrayEquals(new int[] {1, -1, 0}, d.get("a"), "from q = 0: up, down, not moved");
        assertArrayEquals(new int[] {-1, -1, 0}, d.get("b"));
        Map<String, int[]> u = Directions.infer(rows, null);
        assertArrayEquals(new int[] {0, 0, 0}, u.get("a"), "start unknown");
        assertArrayEquals(new int[] {-1, 0, 0}, u.get("b"));
    }

    @Test
    void infer_reversalWithinThePlayTolerance_keepsTheFlank_andSmallMovesAddUp() {
        double t = Directions.PLAY_TOLERANCE, e = 0.38 * t;
        // joint 1 goes up to 1, then creeps back in steps of e (each within the tolerance, read as
        // jitter about where it stands: the mean of its readings since it moved), then up by 0.5 tolerance.
        Map<String, int[]> d = Directions.infer(List.of(row("a", 0, 1, null, 1), row("b", 1, 2, null, 1 - e),
                row("c", 2, 3, null, 1 - 2 * e), row("d", 3, 4, null, 1 - 3 * e), row("e", 4, 5, null, 1 - 4 * e),
                row("f", 5, 6, null, 1 - 5 * e), row("g", 6, 7, null, 1 - 5 * e + 0.5 * t)));
        assertArrayEquals(new int[] {1}, d.get("a"));
        assertArrayEquals(new int[] {1}, d.get("b"), "0.38 tolerance back: still on the + flank");
        assertArrayEquals(new int[] {1}, d.get("c"), "0.57 tolerance below where it stands (the mean of its two readings): still +");
        assertArrayEquals(new int[] {1}, d.get("d"), "0.76 below the mean of three readings: still +");
        assertArrayEquals(new int[] {1}, d.get("e"), "0.95 below the mean of four: still +");
        assertArrayEquals(new int[] {-1}, d.get("f"), "1.14 below the mean of five: the creep has added up, the play is taken the other way");
        assertArrayEquals(new int[] {-1}, d.get("g"), "0.5 tolerance up again: stays on the - flank");
    }

    @Test
    void prepare_splitFileWithTime_ordersTheWholeFileByTime() {
        // One file, rows written out of time order, validation rows interleaved in time.
        List<Measurement> train = List.of(row("t3", 30, 1, Measurement.Split.TRAIN, 3), row("t1", 10, 2, Measurement.Split.TRAIN, 1),
                row("t5", 50, 3, Measurement.Split.TRAIN, 0));
        List<Measurement> val = List.of(row("v2", 20, 4, Measurement.Split.VALIDATE, 5), row("v4", 40, 5, Measurement.Split.VALIDATE, 2));
        MeasurementSet tr = new MeasurementSet("file.csv", Map.of(), "base", train);
        MeasurementSet va = new MeasurementSet("file.csv", Map.of(), "base", val);
        Directions.Prepared p = Directions.prepare(tr, va);
        assertSame(Directions.Source.TIME_ORDER, p.source());
        // time order: t1 (1), v2 (5), t3 (3), v4 (2), t5 (0)
        assertEquals(1, p.train().rows().get(1).directions()[0], "t1 is the first pose measured: up from the zero position");
        assertEquals(1, p.validate().rows().get(0).directions()[0], "v2 after t1: up");
        assertEquals(-1, p.train().rows().get(0).directions()[0], "t3 after v2: down (the training rows alone would say up)");
        assertEquals(-1, p.validate().rows().get(1).directions()[0], "v4 after t3: down");
        assertEquals(-1, p.train().rows().get(2).directions()[0], "t5 after v4: down");
    }

    @Test
    void prepare_noTime_usesFileLines_andRecordedDirectionsWin() {
        List<Measurement> rows = List.of(row("b", Double.NaN, 2, null, 2), row("a", Double.NaN, 1, null, 1));
        Directions.Prepared p = Directions.prepare(new MeasurementSet("f", Map.of(), "base", rows), null);
        assertSame(Directions.Source.FILE_ORDER, p.source());
        assertEquals(1, p.train().rows().get(0).directions()[0]);
        Measurement rec = row("a", 0, 1, null, 1).withConditions(new int[] {-1}, 0, Double.NaN, Double.NaN);
        Directions.Prepared r = Directions.prepare(new MeasurementSet("f", Map.of(), "base", List.of(rec)), null);
        assertSame(Directions.Source.RECORDED, r.source());
        assertEquals(-1, r.train().rows().get(0).directions()[0]);
    }
}
