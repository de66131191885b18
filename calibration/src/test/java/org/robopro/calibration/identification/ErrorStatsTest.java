package org.robopro.calibration.identification;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.models.Vec3;

class ErrorStatsTest {
    @Test
    void of_fourValues_matchesNumpyType7() {
        // numpy: np.percentile([1, 2, 3, 4], [50, 95]) = [2.5, 3.85]
        ErrorStats s = ErrorStats.of(new double[] {4, 1, 3, 2});
        assertEquals(4, s.n());
        assertEquals(2.5, s.mean(), 1e-15);
        assertEquals(2.5, s.median(), 1e-15);
        assertEquals(3.85, s.p95(), 1e-12);
        assertEquals(4, s.max(), 0);
        assertEquals(Math.sqrt(7.5), s.rms(), 1e-15);
    }

    @Test
    void of_oddCountAndNaN_medianIsTheMiddleValueNaNSkipped() {
        ErrorStats s = ErrorStats.of(new double[] {5, Double.NaN, 1, 9});
        assertEquals(3, s.n());
        assertEquals(5, s.median(), 0);
        assertEquals(9 - 0.1 * 4, s.p95(), 1e-12); // h = 2 * 0.95 = 1.9: 5 + 0.9 * (9 - 5)
        assertTrue(Double.isNaN(ErrorStats.of(new double[0]).rms()));
    }

    @Test
    void position_outliersLeftOut() {
        var a = new CalibrationResult.PoseError("a", 2, 1, Double.NaN, Double.NaN, false, Vec3.ZERO);
        var b = new CalibrationResult.PoseError("b", 20, 10, Double.NaN, Double.NaN, true, Vec3.ZERO);
        assertEquals(1, ErrorStats.position(List.of(a, b), true).max(), 0);
        assertEquals(2, ErrorStats.position(List.of(a, b), false).max(), 0);
        assertEquals(0, ErrorStats.rotation(List.of(a, b), true).n());
    }
}
