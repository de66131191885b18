package org.robopro.calibration.identification;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.kinematics.KinematicModel;
import org.robopro.models.InputException;
import org.robopro.models.RobotLibrary;
import org.robopro.models.Vec3;

/** A campaign too large for the heap is refused at once with what to do, not after minutes in an OutOfMemoryError. */
class CalibratorMemoryTest {
    @Test
    void campaignBeyondTheHeap_refusedBeforeAnyWork() {
        KinematicModel nominal = KinematicModel.build(RobotLibrary.load("irb2000"));
        long perPose = 3L * 3 * (6L * 6 + 12) * Double.BYTES;
        int n = (int) Math.min(Integer.MAX_VALUE - 8, Runtime.getRuntime().maxMemory() / perPose + 1000);
        double[] q = {0.1, 0.2, 0.1, 0, 0.3, 0};
        List<Measurement> rows = new ArrayList<>(n);
        for (int i = 0; i < n; i++) rows.add(new Measurement(Integer.toString(i), q, new Vec3(1, 0, 1), null, null,
                Double.NaN, Double.NaN, Double.NaN, null, i + 7));
        MeasurementSet set = new MeasurementSet("huge.csv", Map.of(), "tracker", rows);
        long t0 = System.nanoTime();
        InputException e = assertThrows(InputException.class, () -> Calibrator.calibrate(nominal, set, null));
        assertTrue(e.getMessage().contains("fewer poses") && e.getMessage().startsWith("huge.csv"), e.getMessage());
        assertTrue(System.nanoTime() - t0 < 10e9);
    }
}
