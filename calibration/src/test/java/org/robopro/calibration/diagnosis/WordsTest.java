package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class WordsTest {
    /** A smooth error on a joint sampled over less than a turn: the words say stage harmonics cannot be resolved there. */
    @Test
    void smoothErrorOverAShortRange_saysWhatTheRangeCannotTell() {
        String s = Words.shortRange(Effect.smooth(2, Math.toRadians(-54), Math.toRadians(54), 25));
        assertTrue(s.contains("Over a range of 108 deg, harmonics of the joint closer than 3.3 cycles per turn cannot be told apart"), s);
        assertTrue(s.contains("joint 3"), s);
        assertEquals("", Words.shortRange(Effect.smooth(0, Math.toRadians(-170), Math.toRadians(170), 25)), "most of a turn sampled");
    }

    /**
     * A bar along the flange's unit axis b that sags by k across gravity and not along it, the map
     * A = k (I − b bᵀ) (written here), drops the point k more held across gravity than along it;
     * an isotropic part (a constant shift) adds nothing.
     */
    @Test
    void toolSagSpan_isTheBarsSagAcrossGravity() {
        double k = 1.5e-4;
        double[] b = {0.3, -0.2, Math.sqrt(1 - 0.13)}, a = new double[9];
        for (int r = 0; r < 3; r++) for (int c = 0; c < 3; c++) a[3 * r + c] = k * ((r == c ? 1 : 0) - b[r] * b[c]) + (r == c ? 4e-5 : 0);
        assertEquals(k, Words.sagSpan(a), 1e-12);
    }
}
