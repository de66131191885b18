package org.robopro.calibration.measurement;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedWriter;
import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robopro.models.JointType;

/**
 * A campaign of a million poses (about 75 MB) is read in a separate JVM limited to the heap the
 * issue named (-Xmx1g); the reader's memory must stay proportional to the input.
 */
class LargeCampaignReadTest {
    @TempDir Path dir;

    /** Child JVM entry: reads the file and prints the row count and the heap used. */
    public static void main(String[] args) throws Exception {
        MeasurementSet s = MeasurementReader.read(Path.of(args[0]), Collections.nCopies(6, JointType.REVOLUTE));
        Runtime rt = Runtime.getRuntime();
        System.gc();
        System.out.println(s.size() + " " + (rt.totalMemory() - rt.freeMemory()) / (1 << 20));
    }

    @Test
    void millionPoses_readUnderOneGigabyteOfHeap() throws Exception {
        Path f = dir.resolve("big.csv");
        int n = 1_000_000;
        Random r = new Random(1);
        try (BufferedWriter w = Files.newBufferedWriter(f)) {
            w.write("# robopro-measurements 1\n# robot: irb2000\n# length-unit: mm\n# angle-unit: deg\n# frame: tracker\n");
            w.write("pose,q1,q2,q3,q4,q5,q6,x,y,z\n");
            for (int i = 1; i <= n; i++)
                w.write(String.format(Locale.ROOT, "%d,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f%n", i, r.nextDouble() * 90,
                        r.nextDouble() * 90, r.nextDouble() * 60, r.nextDouble() * 90, r.nextDouble() * 90, r.nextDouble() * 90,
                        1000 + r.nextDouble() * 500, r.nextDouble() * 500, 1000 + r.nextDouble() * 500));
        }
        long mb = Files.size(f) >> 20;
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        // Surefire runs this module's tests on the module path: the child gets both paths as its class path.
        String cp = String.join(File.pathSeparator, System.getProperty("java.class.path", ""),
                System.getProperty("jdk.module.path", ""));
        Process p = new ProcessBuilder(java, "-Xmx1g", "-cp", cp, LargeCampaignReadTest.class.getName(),
                f.toString()).redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes()).strip();
        int code = p.waitFor();
        System.out.println("read " + n + " poses (" + mb + " MB) under -Xmx1g: " + out);
        assertEquals(0, code, out);
        List<String> last = List.of(out.lines().reduce((a, b) -> b).orElse("").split(" "));
        assertEquals(Integer.toString(n), last.get(0), out);
        assertTrue(Integer.parseInt(last.get(1)) < 1024, out);
    }
}
