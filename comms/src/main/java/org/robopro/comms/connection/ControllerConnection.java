package org.robopro.comms.connection;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.robopro.comms.CommandInvoker;
import org.robopro.comms.client.ProtocolClient;
import org.robopro.comms.client.SerialRequestChannel;
import org.robopro.comms.client.TcpRequestChannel;
import org.robopro.comms.sim.ControllerSim;
import org.robopro.comms.sim.SimulatedController;

/**
 * A link to a robot controller, for callers that should not know the protocol (the demo, the
 * workbench): a real controller over TCP or RS-232, or robopro's simulated controller started for
 * the purpose — as a process of its own (like a real controller) or inside this JVM. Use
 * {@link #invoker()} to submit {@link Commands}; {@link #close()} ends the link and stops a
 * simulator this connection started.
 *
 * <pre>{@code
 * try (ControllerConnection c = ControllerConnection.startSimulator(ControllerSim.Config.tcp("127.0.0.1:0").withSeed(7))) {
 *     c.invoker().execute(Commands.moveJoints(q));
 *     Vec3 p = c.invoker().execute(Commands.measure());
 * }
 * }</pre>
 */
public final class ControllerConnection implements AutoCloseable {
    private final ProtocolClient client;
    private final CommandInvoker invoker;
    private final String description;
    private final Process process;          // a simulator process this connection started, or null
    private final ControllerSim inProcess;  // an in-process simulator this connection started, or null
    private final Path tempDir;
    private final Thread killHook;          // stops the simulator process should this JVM exit without close (Ctrl-C)

    private ControllerConnection(ProtocolClient client, CommandInvoker.Options options, String description, Process process,
                                 ControllerSim inProcess, Path tempDir) {
        this(client, options, description, process, inProcess, tempDir, null);
    }

    private ControllerConnection(ProtocolClient client, CommandInvoker.Options options, String description, Process process,
                                 ControllerSim inProcess, Path tempDir, Thread killHook) {
        this.killHook = killHook;
        this.client = client;
        this.invoker = new CommandInvoker(client, options);
        this.description = description;
        this.process = process;
        this.inProcess = inProcess;
        this.tempDir = tempDir;
    }

    /** A controller at "HOST:PORT" speaking open_abb's SERVER.mod protocol (robopro's extension used when offered). */
    public static ControllerConnection connectTcp(String hostPort, CommandInvoker.Options options) {
        TcpRequestChannel ch = TcpRequestChannel.parse(hostPort);
        return new ControllerConnection(new ProtocolClient(ch), options, ch.describe(), null, null, null);
    }

    public static ControllerConnection connectTcp(String hostPort) { return connectTcp(hostPort, CommandInvoker.Options.DEFAULT); }

    /** A controller on a serial device (8N1 at {@code baud}) through robopro's framed link. */
    public static ControllerConnection connectSerial(String device, int baud, CommandInvoker.Options options) {
        SerialRequestChannel ch = SerialRequestChannel.open(device, baud);
        return new ControllerConnection(new ProtocolClient(ch), options, ch.describe(), null, null, null);
    }

    public static ControllerConnection connectSerial(String device, int baud) { return connectSerial(device, baud, CommandInvoker.Options.DEFAULT); }

    /**
     * Starts the simulated controller as a separate JVM on loopback TCP (the host and port of
     * {@code options.tcp()}; port 0 picks a free one), waits until it listens (at most
     * {@code startTimeout}), and connects. The process is stopped by {@link #close()}; should
     * this JVM end without it, by a shutdown hook (Ctrl-C), and should it be killed outright, the
     * simulator stops when its standard input (a pipe from this JVM) closes.
     */
    public static ControllerConnection startSimulator(ControllerSim.Config options, Duration startTimeout,
                                                      CommandInvoker.Options invokerOptions) throws IOException {
        if (options.tcp() == null) throw new IllegalArgumentException("startSimulator needs a TCP simulator (Config.tcp(\"127.0.0.1:0\"))");
        Path tmp = Files.createTempDirectory("robopro-sim");
        Path portFile = tmp.resolve("port");
        Path log = tmp.resolve("sim.log");
        List<String> cmd = new ArrayList<>();
        cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        cmd.add("-cp");
        cmd.add(childClassPath());
        cmd.add(ControllerSim.class.getName());
        cmd.addAll(options.withPortFile(portFile).toArgs());
        cmd.add("--stop-on-stdin-eof");
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(log.toFile()).start();
        Thread hook = new Thread(p::destroyForcibly, "robopro-simulator-kill");
        Runtime.getRuntime().addShutdownHook(hook);
        try {
            long deadline = System.nanoTime() + startTimeout.toNanos();
            while (!Files.exists(portFile) || Files.readString(portFile).isBlank()) {
                if (!p.isAlive()) throw new IOException("simulated controller exited (code " + p.exitValue() + "): " + tail(log));
                if (System.nanoTime() > deadline)
                    throw new IOException("simulated controller did not start within " + startTimeout.toSeconds() + " s: " + tail(log));
                Thread.sleep(25);
            }
            String host = options.tcp().substring(0, options.tcp().lastIndexOf(':'));
            int port = Integer.parseInt(Files.readString(portFile).strip());
            TcpRequestChannel ch = new TcpRequestChannel(host, port);
            return new ControllerConnection(new ProtocolClient(ch), invokerOptions,
                    "simulated controller (pid " + p.pid() + ") on " + ch.describe(), p, null, tmp, hook);
        } catch (IOException | RuntimeException | InterruptedException e) {
            p.destroyForcibly();
            removeHook(hook);
            if (e instanceof InterruptedException) {
                Thread.currentThread().interrupt();
                throw new IOException("interrupted while starting the simulated controller", e);
            }
            throw e instanceof IOException io ? io : new IOException(e.getMessage(), e);
        }
    }

    public static ControllerConnection startSimulator(ControllerSim.Config options) throws IOException {
        return startSimulator(options, Duration.ofSeconds(30), CommandInvoker.Options.DEFAULT);
    }

    /**
     * This JVM's module path and class path as one class path for a child JVM (when robopro runs as
     * named modules, e.g. under the module-path test runner, the class path alone lacks them).
     */
    static String childClassPath() {
        String cp = System.getProperty("java.class.path", ""), mp = System.getProperty("jdk.module.path", "");
        if (mp.isEmpty()) return cp;
        return cp.isEmpty() ? mp : mp + java.io.File.pathSeparator + cp;
    }

    /** Starts the simulated controller inside this JVM (its TCP server on loopback) and connects to it. */
    public static ControllerConnection startSimulatorInProcess(ControllerSim.Config options, CommandInvoker.Options invokerOptions)
            throws IOException {
        ControllerSim sim = ControllerSim.start(options);
        try {
            if (options.tcp() == null) {
                SerialRequestChannel ch = SerialRequestChannel.open(options.serial(), options.baud());
                return new ControllerConnection(new ProtocolClient(ch), invokerOptions, "simulated controller on " + ch.describe(), null, sim, null);
            }
            String host = options.tcp().substring(0, options.tcp().lastIndexOf(':'));
            TcpRequestChannel ch = new TcpRequestChannel(host, sim.port());
            return new ControllerConnection(new ProtocolClient(ch), invokerOptions, "simulated controller on " + ch.describe(), null, sim, null);
        } catch (RuntimeException e) {
            closeQuietly(sim);
            throw e;
        }
    }

    /** The invoker: queue, history, listeners, cancellation, timeouts and retries (docs/controller-link.md). */
    public CommandInvoker invoker() { return invoker; }

    /** The protocol client (for what the commands do not cover, e.g. {@link ProtocolClient#robotName()}). */
    public ProtocolClient client() { return client; }

    /** "tcp 127.0.0.1:5000", "serial /dev/ttyUSB0", "simulated controller (pid 1234) on tcp ...". */
    public String description() { return description; }

    /** The in-process simulator's controller, when this connection started one (tests, the workbench's truth view). */
    public Optional<SimulatedController> simulatedController() {
        return Optional.ofNullable(inProcess).map(ControllerSim::controller);
    }

    /** The simulator process, when this connection started one. */
    public Optional<Process> simulatorProcess() { return Optional.ofNullable(process); }

    /** The simulator process's output (a temporary file, deleted by {@link #close()}), when this connection started one. */
    public Optional<Path> simulatorLog() { return Optional.ofNullable(tempDir).map(d -> d.resolve("sim.log")); }

    /** Ends the link (cancelling queued commands) and stops the simulator this connection started. Idempotent. */
    @Override
    public void close() {
        try {
            invoker.close();
        } finally {
            client.close();
            if (inProcess != null) closeQuietly(inProcess);
            if (process != null) {
                process.destroy();
                try {
                    if (!process.waitFor(5, java.util.concurrent.TimeUnit.SECONDS)) process.destroyForcibly();
                } catch (InterruptedException e) {
                    process.destroyForcibly();
                    Thread.currentThread().interrupt();
                }
                removeHook(killHook);
            }
            if (tempDir != null) {
                try (var files = Files.list(tempDir)) {
                    for (Path f : files.toList()) Files.deleteIfExists(f);
                    Files.deleteIfExists(tempDir);
                } catch (IOException ignored) {
                    // a leftover temp file is harmless
                }
            }
        }
    }

    private static void removeHook(Thread hook) {
        if (hook == null) return;
        try {
            Runtime.getRuntime().removeShutdownHook(hook);
        } catch (IllegalStateException shuttingDown) {
            // the JVM is exiting: the hook runs anyway
        }
    }

    private static void closeQuietly(ControllerSim sim) {
        try {
            sim.close();
        } catch (Exception ignored) {
            // closing a simulator we are abandoning anyway
        }
    }

    private static String tail(Path log) {
        try {
            String s = Files.exists(log) ? Files.readString(log) : "";
            return s.length() > 2000 ? "..." + s.substring(s.length() - 2000) : s;
        } catch (IOException e) {
            return "(log unreadable: " + e.getMessage() + ")";
        }
    }
}
