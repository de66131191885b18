package org.robopro.kinematics;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Random;
import org.junit.jupiter.api.Test;

class FastTrigTest {

    @Test
    void atan2_randomAndSpecialArguments_matchesMathAtan2() {
        Random r = new Random(41);
        double worst = 0;
        for (int i = 0; i < 200_000; i++) {
            double scale = Math.pow(10, r.nextInt(13) - 6);
            double y = scale * (2 * r.nextDouble() - 1), x = Math.pow(10, r.nextInt(13) - 6) * (2 * r.nextDouble() - 1);
            worst = Math.max(worst, Math.abs(FastTrig.atan2(y, x) - Math.atan2(y, x)));
        }
        assertEquals(0, worst, 1e-15, "largest difference over random arguments");
        double[] special = {0.0, -0.0, 1, -1, 1e-300, -1e-300, 1e300, -1e300, 0.0625, 0.5, 15.0 / 16,
            Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY};
        for (double y : special)
            for (double x : special)
                assertEquals(Math.atan2(y, x), FastTrig.atan2(y, x), 1e-15, "atan2(" + y + ", " + x + ")");
        assertEquals(Double.NaN, FastTrig.atan2(Double.NaN, 1));
    }

    @Test
    void acosAsin_wholeDomain_matchMath() {
        Random r = new Random(42);
        for (int i = 0; i < 100_000; i++) {
            double x = 2 * r.nextDouble() - 1;
            assertEquals(Math.acos(x), FastTrig.acos(x), 1e-15, "acos " + x);
            assertEquals(Math.asin(x), FastTrig.asin(x), 1e-15, "asin " + x);
        }
        for (double x : new double[] {-1, -0.0, 0.0, 1, 1 - 1e-16, -1 + 1e-16}) {
            assertEquals(Math.acos(x), FastTrig.acos(x), 1e-15, "acos " + x);
            assertEquals(Math.asin(x), FastTrig.asin(x), 1e-15, "asin " + x);
        }
    }

    @Test
    void sinCos_jointRangeAndBeyond_matchMath() {
        Random r = new Random(43);
        for (int i = 0; i < 200_000; i++) {
            double x = (2 * r.nextDouble() - 1) * (i % 2 == 0 ? 4 * Math.PI : 2e5);
            assertEquals(Math.sin(x), FastTrig.sin(x), 4e-16 * Math.max(1, Math.abs(x) / 100), "sin " + x);
            assertEquals(Math.cos(x), FastTrig.cos(x), 4e-16 * Math.max(1, Math.abs(x) / 100), "cos " + x);
        }
        for (double x : new double[] {0, -0.0, Math.PI / 4, Math.PI / 2, Math.PI, -Math.PI, 1e-300, 3 * Math.PI / 4}) {
            assertEquals(Math.sin(x), FastTrig.sin(x), 4e-16, "sin " + x);
            assertEquals(Math.cos(x), FastTrig.cos(x), 4e-16, "cos " + x);
        }
        assertEquals(Double.NaN, FastTrig.sin(Double.NaN));
        assertEquals(Double.NaN, FastTrig.cos(Double.POSITIVE_INFINITY));
    }
}
