package org.robopro.app.workbench.scene;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robopro.models.InputException;

/** A mesh path to an endless or special file is refused before anything is read. */
class StlReaderLimitTest {
    @TempDir Path dir;

    @Test
    void devZero_isRefusedAtOnce() {
        Path zero = Path.of("/dev/zero");
        Assumptions.assumeTrue(Files.exists(zero));
        long t0 = System.nanoTime();
        InputException e = assertThrows(InputException.class, () -> StlReader.read(zero, 1e-3f));
        assertTrue(e.getMessage().contains("/dev/zero") && e.getMessage().contains("not a mesh file"), e.getMessage());
        assertTrue(System.nanoTime() - t0 < 2e9);
    }

    @Test
    void fifo_isRefusedWithoutWaitingForAWriter() throws Exception {
        Path fifo = dir.resolve("mesh.stl");
        Process p;
        try {
            p = new ProcessBuilder("mkfifo", fifo.toString()).start();
        } catch (java.io.IOException noMkfifo) {
            Assumptions.abort("no mkfifo");
            return;
        }
        Assumptions.assumeTrue(p.waitFor() == 0 && Files.exists(fifo));
        InputException e = assertThrows(InputException.class, () -> StlReader.read(fifo, 1e-3f));
        assertTrue(e.getMessage().contains("not a regular file"), e.getMessage());
    }
}
