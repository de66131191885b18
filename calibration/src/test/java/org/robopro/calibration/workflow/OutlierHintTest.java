package org.robopro.calibration.workflow;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.models.Vec3;

class OutlierHintTest {
    private static List<Measurement> poses(int n, long seed) {
        Random r = new Random(seed);
        List<Measurement> out = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            double[] q = new double[6];
            for (int j = 0; j < 6; j++) q[j] = Math.toRadians(-90 + 180 * r.nextDouble());
            out.add(Measurement.of("P" + i, q, Vec3.ZERO));
        }
        return out;
    }

    @Test
    void noOutliers_nothingToSay() {
        assertTrue(OutlierHint.sentence(List.of(), poses(50, 1)).isEmpty());
    }

    @Test
    void twoScatteredOutliersOf200_countedWithoutDiagnoseAdvice() {
        List<Measurement> p = poses(200, 2);
        String s = OutlierHint.sentence(List.of("P3", "P150"), p).orElseThrow();
        assertTrue(s.startsWith("2 of 200 training poses"), s);
        assertFalse(s.contains("diagnos"), s);
    }

    @Test
    void outliersInOneBandOfJoint2_clusterAndAdviseDiagnosis() {
        List<Measurement> p = poses(200, 3);
        List<String> ids = new ArrayList<>();
        // The poses whose joint 2 lies between 40 and 60 deg: what a backlash or gear error near there would flag.
        for (Measurement m : p) if (Math.toDegrees(m.q()[1]) > 40 && Math.toDegrees(m.q()[1]) < 60 && ids.size() < 6) ids.add(m.poseId());
        String s = OutlierHint.sentence(ids, p).orElseThrow();
        assertTrue(s.contains("joint 2 between"), s);
        assertTrue(s.contains("run the diagnosis"), s);
    }

    @Test
    void manyScatteredOutliers_elevenOf64_adviseDiagnosis() {
        List<Measurement> p = poses(64, 4);
        List<String> ids = new ArrayList<>();
        for (int i = 0; i < 64; i += 6) ids.add("P" + i);
        String s = OutlierHint.sentence(ids, p).orElseThrow();
        assertTrue(s.startsWith("11 of 64"), s);
        assertTrue(s.contains("run the diagnosis"), s);
    }
}
