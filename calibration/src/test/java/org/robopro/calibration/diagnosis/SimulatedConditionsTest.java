package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.*;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.PoseConditions;

class SimulatedConditionsTest {
    @Test
    void conditions_poseSequence_directionsFollowMovesAndWarmUpRises() {
        SimulatedConditions src = new SimulatedConditions(3, 12, 1200, 10);
        Random r = new Random(4);
        double[] prev = null;
        double firstTemp = Double.NaN, lastTemp = Double.NaN;
        for (int i = 0; i < 200; i++) {
            double[] q = new double[6];
            for (int j = 0; j < 6; j++) q[j] = r.nextGaussian();
            PoseConditions c = src.conditions(r, q, i);
            if (prev != null) for (int j = 0; j < 6; j++) assertEquals(q[j] >= prev[j] ? 1 : -1, c.direction(j), "pose " + i + " joint " + j);
            assertEquals(i * SimulatedConditions.SECONDS_PER_POSE, c.timeS(), 2.0);
            assertEquals(src.temperatureC(c.timeS()), c.tempC(), 0.3, "warm-up curve plus sensor noise");
            assertEquals(10 * ((i / SimulatedConditions.POSES_PER_PAYLOAD) % 3) / 2.0, c.payloadKg(), 0);
            if (i == 0) firstTemp = c.tempC();
            lastTemp = c.tempC();
            prev = q;
        }
        assertEquals(EffectSpec.AMBIENT_C, firstTemp, 0.3);
        assertTrue(lastTemp - firstTemp > 0.9 * 12, "warmed up by about 12 K: " + (lastTemp - firstTemp));
        assertTrue(Double.isNaN(new SimulatedConditions(3, 12, 1200, Double.NaN).conditions(r, new double[6], 0).payloadKg()));
    }
}
