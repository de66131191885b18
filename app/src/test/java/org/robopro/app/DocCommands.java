package org.robopro.app;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.DynamicTest;

/**
 * Runs every {@code sh} block of a document in docs/, in order, in one temporary folder, as bash
 * scripts (so the document's own heredocs, variables and background jobs work as a reader's
 * shell would run them). {@code ./robopro} there is a small script running {@link Main} on the
 * test class path. Each block must exit with 0 and print every {@code <!-- expect: TEXT -->} that
 * follows it. Needs bash: fails when CI=true and bash is missing, skipped otherwise. Used by
 * {@link GuideCommandsTest} (docs/guide.md) and {@link RealCampaignCommandsTest}
 * (docs/real-campaign.md).
 */
final class DocCommands {
    private DocCommands() { }

    private static final Pattern EXPECT = Pattern.compile("^<!--\\s*expect:\\s*(.*?)\\s*-->\\s*$");
    static final long BLOCK_TIMEOUT_S = 180;

    /** A runnable block: where it starts in the guide, its text and what its output must contain. */
    record Block(String doc, int line, String script, List<String> expect) {
        String title() {
            String first = script.lines().filter(l -> !l.isBlank()).findFirst().orElse("");
            return doc + ":" + line + ": " + (first.length() > 70 ? first.substring(0, 70) + "..." : first);
        }
    }

    static Path doc(String name) {
        for (Path d = Path.of("").toAbsolutePath(); d != null; d = d.getParent()) {
            Path g = d.resolve("docs").resolve(name);
            if (Files.isRegularFile(g)) return g;
        }
        throw new IllegalStateException("docs/" + name + " not found above " + Path.of("").toAbsolutePath());
    }

    /** A document's sh blocks with their expectations. */
    static List<Block> blocks(String doc, List<String> lines) {
        List<Block> out = new ArrayList<>();
        for (int i = 0; i < lines.size(); i++) {
            if (!lines.get(i).strip().equals("```sh")) continue;
            int start = i + 1;
            StringBuilder sb = new StringBuilder();
            for (i = start; i < lines.size() && !lines.get(i).strip().equals("```"); i++) sb.append(lines.get(i)).append('\n');
            assertTrue(i < lines.size(), "unclosed ```sh block at " + doc + ":" + start);
            List<String> expect = new ArrayList<>();
            for (int k = i + 1; k < lines.size(); k++) {
                Matcher m = EXPECT.matcher(lines.get(k).strip());
                if (!m.matches()) break;
                expect.add(m.group(1));
            }
            out.add(new Block(doc, start, sb.toString(), expect));
        }
        return out;
    }

    private static boolean hasBash() {
        try {
            return new ProcessBuilder("bash", "-c", "true").start().waitFor(10, TimeUnit.SECONDS);
        } catch (IOException | InterruptedException e) {
            return false;
        }
    }

    /** {@code ./robopro}: runs the command line on this test's class path (the real launcher would rebuild). */
    private static void writeLauncher(Path dir) throws IOException {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        String cp = System.getProperty("java.class.path").replace("'", "'\\''");
        Path launcher = dir.resolve("robopro");
        Files.writeString(launcher, "#!/usr/bin/env bash\nexec '" + java.replace("'", "'\\''")
                + "' -XX:TieredStopAtLevel=1 -XX:+UseSerialGC -cp '" + cp + "' " + Main.class.getName() + " \"$@\"\n");
        Files.setPosixFilePermissions(launcher, PosixFilePermissions.fromString("rwxr-xr-x"));
    }

    /** One dynamic test per sh block of docs/{@code name}, run in order in {@code work}; at least {@code minBlocks} blocks. */
    static Stream<DynamicTest> tests(String name, Path work, int minBlocks) throws IOException {
        if (!hasBash()) {
            assertNotEquals("true", System.getenv("CI"), "bash is needed to run the commands of docs/" + name);
            Assumptions.abort("bash not available");
        }
        List<Block> blocks = blocks(name, Files.readAllLines(doc(name), StandardCharsets.UTF_8));
        assertTrue(blocks.size() >= minBlocks, name + " has its runnable blocks: " + blocks.size());
        writeLauncher(work);
        return blocks.stream().map(b -> DynamicTest.dynamicTest(b.title(), () -> run(b, work)));
    }

    private static void run(Block b, Path work) throws Exception {
        Path script = work.resolve("block-" + b.line() + ".sh"), log = work.resolve("block-" + b.line() + ".log");
        // Background jobs a block starts (the controller) end with it even when a command fails.
        Files.writeString(script, "set -euo pipefail\ntrap 'kill $(jobs -p) 2>/dev/null || true' EXIT\n" + b.script());
        Process p = new ProcessBuilder("bash", script.toString()).directory(work.toFile())
                .redirectErrorStream(true).redirectOutput(log.toFile()).start();
        boolean done = p.waitFor(BLOCK_TIMEOUT_S, TimeUnit.SECONDS);
        if (!done) {
            p.descendants().forEach(ProcessHandle::destroyForcibly);
            p.destroyForcibly();
        }
        String out = Files.readString(log);
        assertTrue(done, () -> b.title() + " did not finish within " + BLOCK_TIMEOUT_S + " s:\n" + out);
        assertEquals(0, p.exitValue(), () -> b.title() + " failed:\n" + out);
        for (String e : b.expect()) assertTrue(out.contains(e), () -> b.title() + ": output lacks '" + e + "':\n" + out);
    }
}
