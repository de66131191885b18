package org.robopro.calibration.identification;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

class IdentifiabilityTest {
    static double[] randomJacobian(long seed, int m, int n) {
        Random r = new Random(seed);
        double[] j = new double[m * n];
        for (int i = 0; i < j.length; i++) j[i] = r.nextGaussian();
        return j;
    }

    static final List<String> NAMES = List.of("a", "b", "c", "d", "e", "f");

    @Test
    void analyze_fullRank_fixesNothing() {
        var res = Identifiability.analyze(randomJacobian(1, 40, 6), 40, 6, NAMES, null, null, 10, 1e-8);
        assertEquals(0, res.fixed().length);
        assertArrayEquals(new int[] {0, 1, 2, 3, 4, 5}, res.free());
        assertTrue(res.conditionNumber() >= 1 && res.conditionNumber() < 100);
    }

    @Test
    void analyze_columnIsCombinationOfOthers_namesTheCombinationAndFixesOne() {
        int m = 40, n = 6;
        double[] j = randomJacobian(2, m, n);
        for (int i = 0; i < m; i++) j[i * n + 3] = 1000 * (j[i * n] + 2 * j[i * n + 1]); // d = 1000 (a + 2 b)
        var res = Identifiability.analyze(j, m, n, NAMES, null, null, 10, 1e-8);
        assertEquals(1, res.fixed().length);
        var combo = res.directions().get(0).combination();
        assertEquals(3, combo.size(), res.directions().get(0).describe());
        assertTrue(combo.keySet().containsAll(List.of("a", "b", "d")));
        assertEquals(5, res.free().length);
    }

    @Test
    void analyze_duplicateColumns_fixesTheHigherPriorityOne() {
        int m = 30, n = 6;
        double[] j = randomJacobian(3, m, n);
        for (int i = 0; i < m; i++) j[i * n + 5] = -0.001 * j[i * n + 2]; // f mirrors c at another scale
        double[] prio = {1, 1, 0.25, 1, 1, 1};
        var res = Identifiability.analyze(j, m, n, NAMES, prio, null, 10, 1e-8);
        assertEquals("f", res.directions().get(0).fixed());
        prio = new double[] {1, 1, 1, 1, 1, 0.25};
        res = Identifiability.analyze(j, m, n, NAMES, prio, null, 10, 1e-8);
        assertEquals("c", res.directions().get(0).fixed());
    }

    @Test
    void analyze_knownSingularValues_reportsConditionAndObservability() {
        // Orthogonal columns of norms 1..4 scale to unit norm: every singular value is 1.
        int m = 4, n = 4;
        double[] j = new double[16];
        for (int k = 0; k < 4; k++) j[k * 4 + k] = k + 1;
        var res = Identifiability.analyze(j, m, n, NAMES.subList(0, 4), null, null, 4, 1e-8);
        assertEquals(1, res.conditionNumber(), 1e-12);
        assertEquals(0.5, res.observability(), 1e-12); // (1)^(1/4) / sqrt(4)
    }

    @Test
    void analyze_moreParametersThanEquations_fixesTheExcess() {
        var res = Identifiability.analyze(randomJacobian(5, 3, 6), 3, 6, NAMES, null, null, 1, 1e-8);
        assertEquals(3, res.fixed().length);
        assertEquals(3, res.free().length);
    }

    @Test
    void analyze_zeroColumn_isFixedFirst() {
        double[] j = randomJacobian(6, 20, 6);
        for (int i = 0; i < 20; i++) j[i * 6 + 4] = 0;
        var res = Identifiability.analyze(j, 20, 6, NAMES, null, null, 5, 1e-8);
        assertEquals("e", res.directions().get(0).fixed());
        assertEquals(1, res.fixed().length);
    }
}
