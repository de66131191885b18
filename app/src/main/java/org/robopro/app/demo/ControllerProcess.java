package org.robopro.app.demo;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * The demo's simulated controller as a child process ({@link DemoController#main}), started on
 * the demo's own class path. {@link #close} always ends it; a shutdown hook ends it too should
 * the demo itself be killed (Ctrl-C).
 */
final class ControllerProcess implements AutoCloseable {
    private final Process process;
    private final int port;
    private final Path log, truth;
    private final Thread hook;

    private ControllerProcess(Process process, int port, Path log, Path truth, Thread hook) {
        this.process = process;
        this.port = port;
        this.log = log;
        this.truth = truth;
        this.hook = hook;
    }

    /**
     * Starts the controller and waits (at most {@code timeoutS}) until it writes its port.
     *
     * @param work folder for the port file and the truth file (kept from the demo's output until the reveal)
     * @param log  the process's output
     */
    static ControllerProcess start(Path work, Path log, long seed, String effect, double noiseMm, double timeoutS) throws IOException {
        Path portFile = work.resolve("controller.port"), truth = work.resolve("truth.json");
        Files.deleteIfExists(portFile);
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        List<String> cmd = new ArrayList<>(List.of(java, "-XX:+UseSerialGC", "-Xmx256m", "-cp", System.getProperty("java.class.path"),
                DemoController.class.getName(), "--port-file", portFile.toString(), "--truth", truth.toString(),
                "--seed", Long.toString(seed), "--effect", effect, "--noise-mm", Double.toString(noiseMm)));
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(log.toFile()).start();
        Thread hook = new Thread(p::destroyForcibly, "robopro-demo-controller-kill");
        Runtime.getRuntime().addShutdownHook(hook);
        ControllerProcess cp = null;
        try {
            long deadline = System.nanoTime() + (long) (timeoutS * 1e9);
            while (true) {
                if (Files.exists(portFile)) {
                    String text = Files.readString(portFile).strip();
                    if (!text.isEmpty()) {
                        cp = new ControllerProcess(p, Integer.parseInt(text), log, truth, hook);
                        return cp;
                    }
                }
                if (!p.isAlive())
                    throw new IOException("the controller process exited with status " + p.exitValue() + ": " + tail(log));
                if (System.nanoTime() > deadline)
                    throw new IOException("the controller process did not start within " + timeoutS + " s: " + tail(log));
                Thread.sleep(20);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted while starting the controller", e);
        } finally {
            if (cp == null) stop(p, hook);
        }
    }

    int port() { return port; }

    long pid() { return process.pid(); }

    boolean isAlive() { return process.isAlive(); }

    Path log() { return log; }

    /** The truth file the controller wrote at start. */
    Path truthFile() { return truth; }

    @Override
    public void close() { stop(process, hook); }

    private static void stop(Process p, Thread hook) {
        p.destroy();
        try {
            if (!p.waitFor(5, TimeUnit.SECONDS)) {
                p.destroyForcibly();
                p.waitFor(5, TimeUnit.SECONDS);
            }
        } catch (InterruptedException e) {
            p.destroyForcibly();
            Thread.currentThread().interrupt();
        }
        try {
            Runtime.getRuntime().removeShutdownHook(hook);
        } catch (IllegalStateException shuttingDown) {
            // the JVM is exiting: the hook runs anyway
        }
    }

    static String tail(Path log) {
        try {
            String s = Files.exists(log) ? Files.readString(log) : "";
            return s.length() > 2000 ? "..." + s.substring(s.length() - 2000) : s;
        } catch (IOException e) {
            return "(log unreadable: " + e.getMessage() + ")";
        }
    }
}
