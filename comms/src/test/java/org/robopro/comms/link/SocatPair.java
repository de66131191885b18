package org.robopro.comms.link;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Assertions;
import org.junit.jupiter.api.Assumptions;

/**
 * A pseudo-terminal pair made by socat, linked as {@code dir/ttyA} and {@code dir/ttyB}. Without
 * socat the test fails with a clear message under CI=true and is skipped otherwise.
 */
public final class SocatPair implements AutoCloseable {
    private final Path a, b;
    private Process process;

    public SocatPair(Path dir) throws IOException, InterruptedException {
        this.a = dir.resolve("ttyA");
        this.b = dir.resolve("ttyB");
        requireSocat();
        start();
    }

    public static void requireSocat() {
        boolean found = false;
        for (String d : System.getenv().getOrDefault("PATH", "/usr/bin:/bin").split(":"))
            if (Files.isExecutable(Path.of(d, "socat"))) found = true;
        if (!found) {
            String msg = "socat is not installed: the serial-link tests need it for a pseudo-terminal pair (apt-get install socat; .ci/install-deps does)";
            if ("true".equalsIgnoreCase(System.getenv("CI"))) Assertions.fail(msg);
            Assumptions.abort(msg);
        }
    }

    /** (Re)starts socat; the links point at fresh ptys. */
    public void start() throws IOException, InterruptedException {
        Files.deleteIfExists(a);
        Files.deleteIfExists(b);
        process = new ProcessBuilder("socat", "-d", "-d", "pty,raw,echo=0,link=" + a, "pty,raw,echo=0,link=" + b)
                .redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (!(Files.exists(a) && Files.exists(b))) {
            if (!process.isAlive()) throw new IOException("socat exited with " + process.exitValue());
            if (System.nanoTime() > deadline) throw new IOException("socat made no ptys within 10 s");
            Thread.sleep(20);
        }
    }

    /** Kills socat: both ends see the line go away (a dropped link). */
    public void kill() throws InterruptedException {
        if (process != null) {
            process.destroy();
            if (!process.waitFor(5, TimeUnit.SECONDS)) process.destroyForcibly().waitFor();
        }
    }

    public String a() { return a.toString(); }

    public String b() { return b.toString(); }

    @Override
    public void close() throws InterruptedException { kill(); }
}
