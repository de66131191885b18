package org.robopro.programs.rapid;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Assumptions;

/**
 * Runs the third-party RAPID checker {@code rapidchecker} (PyPI, installed by .ci/install-deps in
 * .venv-rapid at the repository root; ROBOPRO_RAPIDCHECKER_PYTHON may name another Python with it).
 * Missing checker: the test fails when CI=true, else it is skipped.
 */
public final class RapidChecker {
    private RapidChecker() { }

    static Optional<Path> python() {
        String env = System.getenv("ROBOPRO_RAPIDCHECKER_PYTHON");
        if (env != null && !env.isBlank()) return Optional.of(Paths.get(env)).filter(Files::isExecutable);
        for (Path d = Paths.get("").toAbsolutePath(); d != null; d = d.getParent()) {
            Path py = d.resolve(".venv-rapid/bin/python");
            if (Files.isExecutable(py)) return Optional.of(py);
        }
        return Optional.empty();
    }

    /** Asserts rapidchecker finds no error in any of the files (name -> RAPID text). */
    public static void assertValid(Map<String, String> files) {
        Optional<Path> py = python();
        if (py.isEmpty()) {
            String msg = "rapidchecker not found: run .ci/install-deps (creates .venv-rapid with pip install rapidchecker)";
            if ("true".equalsIgnoreCase(System.getenv("CI"))) fail(msg);
            Assumptions.assumeTrue(false, msg);
        }
        try {
            // Its own folder: rapidchecker reads rapidchecker.toml from the working directory.
            Path dir = Files.createTempDirectory("rapidcheck");
            List<String> cmd = new ArrayList<>(List.of(py.get().toString(), "-m", "rapidchecker"));
            for (Map.Entry<String, String> e : files.entrySet()) {
                Path f = dir.resolve(e.getKey());
                Files.writeString(f, e.getValue(), StandardCharsets.UTF_8);
                cmd.add(f.toString());
            }
            ProcessBuilder pb = new ProcessBuilder(cmd).directory(dir.toFile()).redirectErrorStream(true);
            pb.environment().put("NO_COLOR", "1");
            pb.environment().put("COLUMNS", "400");
            Process p = pb.start();
            String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            assertTrue(p.waitFor(120, TimeUnit.SECONDS), "rapidchecker timed out");
            StringBuilder all = new StringBuilder(out);
            if (p.exitValue() != 0) for (Map.Entry<String, String> e : files.entrySet())
                all.append("\n--- ").append(e.getKey()).append('\n').append(numbered(e.getValue()));
            assertEquals(0, p.exitValue(), () -> "rapidchecker rejects robopro's RAPID:\n" + all);
        } catch (IOException e) {
            fail("cannot run rapidchecker: " + e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            fail("interrupted");
        }
    }

    public static void assertValid(String name, String text) { assertValid(Map.of(name, text)); }

    private static String numbered(String text) {
        StringBuilder b = new StringBuilder();
        String[] lines = text.split("\n", -1);
        for (int i = 0; i < lines.length; i++) b.append(String.format("%4d %s%n", i + 1, lines[i]));
        return b.toString();
    }
}
