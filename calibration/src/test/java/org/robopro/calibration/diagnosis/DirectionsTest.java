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
        assertArrayEquals(new int[] {0, 0}, d.get("a"), "first pose: unknown");
        assertArrayEquals(new int[] {1, 0}, d.get("b"), "joint 2 has not moved yet");
        assertArrayEquals(new int[] {1, -1}, d.get("c"), "joint 1 stood still: still on its + flank");
        assertArrayEquals(new int[] {-1, -1}, d.get("d"));
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
        assertEquals(0, p.train().rows().get(1).directions()[0], "t1 is the first pose measured");
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
