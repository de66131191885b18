package org.robopro.calibration.report;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

class AxisTest {
    @Test
    void linear_1to5point4_roundTicksNot1point0_3point2_5point4() {
        Axis.Ticks t = Axis.linear(1.0, 5.4, 6);
        assertArrayEquals(new String[] {"1", "2", "3", "4", "5", "6"}, t.labels());
        assertEquals(1, t.lo(), 0);
        assertEquals(6, t.hi(), 0);
    }

    @Test
    void linear_smallRange_labelsCarryTheStepsDecimals() {
        Axis.Ticks t = Axis.linear(0, 0.187, 5);
        assertArrayEquals(new String[] {"0.00", "0.05", "0.10", "0.15", "0.20"}, t.labels());
    }

    @Test
    void linear_anyRange_stepIsOneTwoOrFiveTimesAPowerOfTenAndTicksCoverTheData() {
        Random r = new Random(7);
        for (int k = 0; k < 2000; k++) {
            double a = (r.nextDouble() - 0.5) * Math.pow(10, r.nextInt(9) - 4), b = a + r.nextDouble() * Math.pow(10, r.nextInt(9) - 4);
            Axis.Ticks t = Axis.linear(a, b, 6);
            assertTrue(t.lo() <= a + 1e-12 * Math.abs(a) && t.hi() >= b - 1e-12 * Math.abs(b), a + " " + b);
            assertTrue(t.values().length >= 2 && t.values().length <= 8, a + " " + b + ": " + t.values().length);
            double step = t.values()[1] - t.values()[0];
            double m = step / Math.pow(10, Math.floor(Math.log10(step) + 1e-9));
            assertTrue(Math.abs(m - 1) < 1e-4 || Math.abs(m - 2) < 1e-4 || Math.abs(m - 5) < 1e-4 || Math.abs(m - 10) < 1e-4, "step " + step);
            for (double v : t.values())
                assertEquals(0, Math.abs(v / step - Math.round(v / step)), 1e-6 * Math.max(1, Math.abs(v / step)), "tick " + v + " on the step " + step);
        }
    }

    @Test
    void log_fourDecades_decadeTicks() {
        Axis.Ticks t = Axis.log(0.0021, 8.7);
        assertArrayEquals(new String[] {"0.001", "0.01", "0.1", "1", "10"}, t.labels());
        assertEquals(0, t.fraction(0.001), 1e-12);
        assertEquals(1, t.fraction(10), 1e-12);
    }

    @Test
    void log_withinOneDecade_addsTwoAndFive() {
        assertArrayEquals(new String[] {"0.01", "0.02", "0.05", "0.1"}, Axis.log(0.012, 0.09).labels());
    }

    @Test
    void label_tinyAndHuge_asPowersOfTen() {
        assertEquals("1e-5", Axis.label(1e-5, 1e-5));
        assertEquals("2×1e6", Axis.label(2e6, 1e6));
        assertEquals("-3", Axis.label(-3, 1));
    }
}
