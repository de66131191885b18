package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

class StatsTest {
    @Test
    void fUpperTail_twoNumeratorDegrees_matchesClosedForm() {
        // P(F > f; 2, d2) = (1 + 2 f / d2)^(-d2/2)
        for (double d2 : new double[] {3, 17, 250, 900})
            for (double f : new double[] {0.1, 1, 3.5, 12, 40}) {
                double exact = Math.pow(1 + 2 * f / d2, -d2 / 2);
                assertEquals(exact, Stats.fUpperTail(f, 2, d2), 1e-12 + 1e-9 * exact, "d2 " + d2 + " f " + f);
            }
    }

    @Test
    void regularizedBeta_edgeShapes_matchClosedForms() {
        for (double x : new double[] {0.01, 0.3, 0.77, 0.999}) {
            assertEquals(Math.pow(x, 3.5), Stats.regularizedBeta(x, 3.5, 1), 1e-12);
            assertEquals(1 - Math.pow(1 - x, 4.25), Stats.regularizedBeta(x, 1, 4.25), 1e-12);
        }
    }

    @Test
    void logGamma_knownValues_exact() {
        assertEquals(Math.log(24), Stats.logGamma(5), 1e-12);
        assertEquals(0.5 * Math.log(Math.PI), Stats.logGamma(0.5), 1e-12);
        assertEquals(Math.log(362880), Stats.logGamma(10), 1e-10);
    }

    @Test
    void fUpperTail_oneNumeratorDegree_matchesTableCriticalValue() {
        // F(0.95; 1, 120) = 3.9201 (standard tables)
        assertEquals(0.05, Stats.fUpperTail(3.9201, 1, 120), 2e-5);
    }
}
