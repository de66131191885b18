package org.robopro.calibration.identification;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class CalibratorOptionsTest {
    @Test
    void outlierThresholdNaN_isRefused_notSilentlyTurningRejectionOff() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> Calibrator.Options.defaults().withOutliers(Double.NaN, true));
        assertTrue(e.getMessage().contains("NaN"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> Calibrator.Options.defaults().withOutliers(0, true));
        Calibrator.Options.defaults().withOutliers(Double.POSITIVE_INFINITY, true); // "never flag" stays possible
    }
}
