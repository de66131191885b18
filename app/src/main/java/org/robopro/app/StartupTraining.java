package org.robopro.app;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.List;
import java.util.stream.Stream;
import org.robopro.app.cli.RoboproCommand;
import picocli.CommandLine;

/**
 * The training run of the class-data-sharing archive the {@code robopro} launcher builds once
 * after each build ({@code java -XX:ArchiveClassesAtExit=app/target/robopro.jsa ... StartupTraining}):
 * runs the common commands in-process on a small simulated campaign in a temporary folder, so
 * the archive holds the classes fk, ik, model show, simulate, calibrate, diagnose and program
 * check load. Later runs map those classes from the archive instead of loading and verifying
 * them from the jars (docs/performance.md, "Command-line start-up"). Prints nothing; exits 0
 * when every command succeeded.
 */
public final class StartupTraining {
    private StartupTraining() { }

    /** A small program, as docs/guide.md's weld.json. */
    static final String PROGRAM = """
            {"format": "robopro-program", "version": 1, "module": "Weld", "robot": "irb2000",
             "tools": {"tTorch": {"robhold": true, "tframe": {"pos_mm": [0, 0, 150], "quat": [1, 0, 0, 0]},
                                  "load": {"mass_kg": 2, "cog_mm": [0, 0, 50]}}},
             "wobjs": {"wTable": {"uframe": {"pos_mm": [900, -200, 500]}, "oframe": {"pos_mm": [0, 0, 0]}}},
             "jointtargets": {"jHome": {"joints_deg": [0, 0, 0, 0, 30, 0]}},
             "targets": {"pStart": {"joints_deg": [-10, 20, 20, 10, 50, 20], "tool": "tTorch", "wobj": "wTable"},
                         "pEnd": {"joints_deg": [10, 20, 20, 10, 50, 20], "tool": "tTorch", "wobj": "wTable"}},
             "procedures": {"main": [
               {"move": "MoveAbsJ", "to": "jHome", "speed": "v1000", "zone": "fine", "tool": "tTorch"},
               {"move": "MoveJ", "to": "pStart", "speed": "v500", "zone": "fine", "tool": "tTorch", "wobj": "wTable"},
               {"move": "MoveL", "to": "pEnd", "speed": "v20", "zone": "fine", "tool": "tTorch", "wobj": "wTable"},
               {"move": "MoveAbsJ", "to": "jHome", "speed": "v1000", "zone": "fine", "tool": "tTorch"}]}}
            """;

    public static void main(String[] args) throws IOException {
        System.exit(run().isEmpty() ? 0 : 1);
    }

    /** Runs the training commands; returns the ones that failed (empty when all succeeded). */
    static List<String> run() throws IOException {
        List<String> failed = new java.util.ArrayList<>();
        Path dir = Files.createTempDirectory("robopro-cds-");
        try {
            String d = dir.toString();
            Files.writeString(dir.resolve("weld.json"), PROGRAM, StandardCharsets.UTF_8);
            List<String[]> runs = List.of(
                    new String[] {"fk", "irb2000", "10", "20", "30", "40", "50", "60"},
                    new String[] {"ik", "irb2000", "1200", "0", "1000", "0", "0", "1", "0"},
                    new String[] {"model", "show", "irb2000"},
                    new String[] {"simulate", "--robot", "irb2000", "--poses", "60", "--seed", "1", "--out", d + "/sim"},
                    new String[] {"calibrate", "--robot", "irb2000", "--measurements", d + "/sim/measurements.csv", "--folds", "2",
                            "--out", d + "/cal"},
                    new String[] {"diagnose", "--robot", "irb2000", "--measurements", d + "/sim/measurements.csv", "--out", d + "/diag"},
                    new String[] {"program", "export", d + "/weld.json", "--out", d + "/Weld.mod"},
                    new String[] {"program", "check", d + "/Weld.mod", "--robot", "irb2000"});
            for (String[] a : runs) {
                CommandLine cl = RoboproCommand.commandLine();
                PrintWriter sink = new PrintWriter(Writer.nullWriter());
                cl.setOut(sink);
                cl.setErr(sink);
                if (cl.execute(a) != 0) failed.add(String.join(" ", a));
            }
        } finally {
            try (Stream<Path> s = Files.walk(dir)) {
                for (Path p : (Iterable<Path>) s.sorted(Comparator.reverseOrder())::iterator) Files.deleteIfExists(p);
            }
        }
        return failed;
    }
}
