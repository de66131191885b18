package org.robopro.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.io.UncheckedIOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class FailuresTest {
    @TempDir Path dir;

    static String line(Throwable t, int expectCode) {
        StringWriter sw = new StringWriter();
        assertEquals(expectCode, Failures.report(t, new PrintWriter(sw)));
        String s = sw.toString();
        assertEquals(1, s.lines().count(), "one line: " + s);
        assertFalse(s.contains("Exception") && expectCode == Failures.INPUT, s);
        return s;
    }

    @Test
    void unexpectedException_isOneLinePlusALogFileWithTheTrace() throws Exception {
        String s = line(new NullPointerException("Cannot invoke \"Object.x()\" because \"y\" is null"), Failures.INTERNAL);
        assertTrue(s.startsWith("robopro: internal error"), s);
        assertFalse(s.contains("Cannot invoke"), s);
        Path log = Path.of(s.substring(s.indexOf("details are in ") + 15, s.indexOf(" - please")));
        assertTrue(Files.readString(log).contains("at org.robopro.app.cli.FailuresTest"), "trace in " + log);
        Files.delete(log);
        assertTrue(line(new StackOverflowError(), Failures.INTERNAL).contains("stack"));
    }

    @Test
    void fileProblems_nameTheFileInWords() {
        assertEquals("robopro: /x/out: is a directory\n".trim(),
                line(new FileSystemException("/x/out", null, "Is a directory"), Failures.INPUT).trim());
        String s = line(new UncheckedIOException("cannot write /ro/cal.json: /ro/cal.json", new AccessDeniedException("/ro/cal.json")),
                Failures.INPUT);
        assertTrue(s.contains("/ro/cal.json") && s.contains("permission denied"), s);
        assertFalse(s.contains("UncheckedIOException"), s);
    }

    @Test
    void calibrate_outHoldingAnOldSummary_writesNothingNew() throws Exception {
        CliHarness h = new CliHarness(true);
        Path sim = dir.resolve("sim"), cal = Files.createDirectories(dir.resolve("cal"));
        assertEquals(0, h.run("simulate", "--robot", "irb2000", "--poses", "60", "--validate-poses", "0", "--seed", "3",
                "--out", sim.toString()), h.err());
        Files.writeString(cal.resolve("summary.json"), "{\"old\": true}");
        assertEquals(2, h.run("calibrate", "--robot", "irb2000", "--measurements", sim.resolve("measurements.csv").toString(),
                "--out", cal.toString()));
        assertEquals(1, h.err().lines().count(), h.err());
        assertTrue(h.err().contains("summary.json") && h.err().contains("nothing was written"), h.err());
        try (var files = Files.list(cal)) {
            assertEquals(1, files.count(), "only the old summary stays");
        }
        assertEquals(0, h.run("calibrate", "--robot", "irb2000", "--measurements", sim.resolve("measurements.csv").toString(),
                "--out", cal.toString(), "--force"), h.err());
        assertTrue(Files.exists(cal.resolve("calibrated.robot.json")));
        assertFalse(Files.readString(cal.resolve("summary.json")).contains("old"));
    }
}
