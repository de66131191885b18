package org.robopro.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Numeric options: NaN, infinities and values outside their range are refused by name, nothing written. */
class OptionValidationTest {
    @TempDir Path dir;

    int run(CliHarness h, String... args) { return h.run(args); }

    @Test
    void nonFiniteNumbers_areRefusedNamingTheOption() {
        CliHarness h = new CliHarness(true);
        assertEquals(2, h.run("calibrate", "--robot", "irb2000", "--measurements", "m.csv", "--outlier-k", "NaN", "--out",
                dir.resolve("c").toString()));
        assertTrue(h.err().contains("--outlier-k") && h.err().contains("not a finite number"), h.err());
        assertEquals(2, h.run("simulate", "--robot", "irb2000", "--error-mm", "1e400", "--out", dir.resolve("s").toString()));
        assertTrue(h.err().contains("--error-mm"), h.err());
        assertEquals(2, h.run("fk", "irb2000", "0", "NaN", "0", "0", "0", "0"));
        assertFalse(Files.exists(dir.resolve("c")) || Files.exists(dir.resolve("s")));
    }

    @Test
    void valuesOutsideTheirRange_areRefused() throws Exception {
        CliHarness h = new CliHarness(true);
        // A 1e300 mm error gave a robot printed as "0.000 mm" off.
        assertEquals(2, h.run("simulate", "--robot", "irb2000", "--error-mm", "1e300", "--out", dir.resolve("s").toString()));
        assertEquals(1, h.err().lines().count(), h.err());
        assertTrue(h.err().contains("--error-mm must be in 0 .. 1000"), h.err());
        assertFalse(Files.exists(dir.resolve("s")));
        assertEquals(0, h.run("simulate", "--robot", "irb2000", "--poses", "40", "--out", dir.resolve("ok").toString()), h.err());
        for (String k : new String[] {"0", "-3"}) {
            assertEquals(2, h.run("calibrate", "--robot", "irb2000", "--measurements", dir.resolve("ok/measurements.csv").toString(),
                    "--outlier-k", k, "--out", dir.resolve("c" + k).toString()));
            assertTrue(h.err().contains("outlier") && h.err().lines().count() == 1, h.err());
            assertFalse(Files.exists(dir.resolve("c" + k)));
        }
    }
}
