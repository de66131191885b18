package org.robopro.models;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.math.BigDecimal;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

class FileNumbersTest {
    @Test
    void formatMm_randomDoubles_readsBackExactly() {
        SplittableRandom rnd = new SplittableRandom(42);
        for (int i = 0; i < 20000; i++) {
            double m = (rnd.nextDouble() - 0.5) * Math.pow(10, rnd.nextInt(-9, 4));
            String s = FileNumbers.formatMm(m);
            assertEquals(m, FileNumbers.mmToM(new BigDecimal(s)), s);
        }
    }

    @Test
    void formatDeg_randomDoubles_readsBackExactly() {
        SplittableRandom rnd = new SplittableRandom(7);
        for (int i = 0; i < 20000; i++) {
            double rad = (rnd.nextDouble() - 0.5) * Math.pow(10, rnd.nextInt(-9, 3));
            String s = FileNumbers.formatDeg(rad);
            assertEquals(rad, FileNumbers.degToRad(new BigDecimal(s)), s);
        }
    }

    @Test
    void formatMm_roundMetres_givesShortMillimetres() {
        assertEquals("780", FileNumbers.formatMm(0.78));
        assertEquals("431.8", FileNumbers.formatMm(0.4318));
        assertEquals("-150.05", FileNumbers.formatMm(-0.15005));
        assertEquals("-0", FileNumbers.formatMm(-0.0));
    }

    @Test
    void formatDeg_roundRadians_givesShortDegrees() {
        assertEquals("90", FileNumbers.formatDeg(Math.PI / 2));
        assertEquals("-100", FileNumbers.formatDeg(FileNumbers.degToRad(new BigDecimal("-100"))));
    }

    @Test
    void degToRad_ordinaryValues_agreesWithMathToRadiansToOneUlp() {
        for (int d = -720; d <= 720; d++) {
            double r = FileNumbers.degToRad(BigDecimal.valueOf(d));
            assertEquals(Math.toRadians(d), r, Math.ulp(r));
        }
    }
}
