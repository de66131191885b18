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
}
