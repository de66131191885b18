package org.robopro.app.workbench;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.function.Consumer;
import org.robopro.comms.CommandInvoker;
import org.robopro.comms.CommandRecord;
import org.robopro.comms.Commands;
import org.robopro.comms.ControllerStatus;
import org.robopro.comms.ProgramInfo;
import org.robopro.comms.client.ProtocolClient;
import org.robopro.comms.client.RequestChannel;
import org.robopro.comms.client.SerialRequestChannel;
import org.robopro.comms.client.TcpRequestChannel;

/**
 * The workbench's link to a robot controller (comms module): a {@link CommandInvoker} over a
 * {@link ProtocolClient} on TCP ("host:port") or a serial device, and, by default, the simulated
 * controller started as a child process ({@code robopro controller-sim --tcp 127.0.0.1:0
 * --port-file ...}, in this JVM's Java with this JVM's class path). Every command runs on the
 * invoker's worker thread; callers get futures, and each command's progress (queued, running,
 * retried, succeeded, failed) goes to the log consumer. Thread-safe.
 */
public final class ControllerSession implements AutoCloseable {
    /** Baud rate for serial devices (the simulator's and the IRB controllers' usual setting). */
    public static final int SERIAL_BAUD = 19200;

    private final String description;
    private final ProtocolClient client;
    private final CommandInvoker invoker;
    private final Process simulator;
    private final Path simulatorDir;

    private ControllerSession(String description, RequestChannel channel, Process simulator, Path simulatorDir, Consumer<String> log) {
        this.description = description;
        this.client = new ProtocolClient(channel);
        this.invoker = new CommandInvoker(client);
        this.simulator = simulator;
        this.simulatorDir = simulatorDir;
        invoker.addListener(r -> {
            if (r.state() == CommandRecord.State.RUNNING) return; // queued/done lines say enough
            log.accept("Controller: " + r.state().name().toLowerCase(java.util.Locale.ROOT) + " " + r.description()
                    + (r.attempt() > 1 ? " (attempt " + r.attempt() + ")" : "") + (r.detail().isEmpty() ? "" : ": " + r.detail()));
        });
    }

    /** Connects to "host:port" (TCP, open_abb protocol) or a serial device path. Blocking: call off the UI thread. */
    public static ControllerSession connect(String address, Consumer<String> log) {
        RequestChannel ch = address.contains(":") && !address.startsWith("/") ? TcpRequestChannel.parse(address)
                : SerialRequestChannel.open(address, SERIAL_BAUD);
        ControllerSession s = new ControllerSession(address, ch, null, null, log);
        s.hello();
        return s;
    }

    /**
     * Starts the simulated controller for {@code robot} (a shipped name or robot file) on a free
     * local port and connects to it. Blocking (up to {@code timeoutMs} for the simulator to
     * start): call off the UI thread.
     */
    public static ControllerSession startSimulator(String robot, long timeoutMs, Consumer<String> log) throws IOException, InterruptedException {
        Path dir = Files.createTempDirectory("robopro-sim");
        Path portFile = dir.resolve("port");
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-Xmx256m",
                "-cp", System.getProperty("java.class.path"), "org.robopro.app.Main", "controller-sim",
                "--tcp", "127.0.0.1:0", "--port-file", portFile.toString(), "--robot", robot));
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(dir.resolve("controller-sim.log").toFile()).start();
        // Never leave a simulator behind when the workbench exits without closing the session.
        Runtime.getRuntime().addShutdownHook(new Thread(p::destroyForcibly, "stop-controller-sim"));
        long end = System.currentTimeMillis() + timeoutMs;
        String port = "";
        while (System.currentTimeMillis() < end) {
            if (!p.isAlive())
                throw new IOException("the simulated controller stopped (status " + p.exitValue() + "): "
                        + Files.readString(dir.resolve("controller-sim.log")).strip());
            if (Files.exists(portFile)) {
                port = Files.readString(portFile, StandardCharsets.UTF_8).trim();
                if (port.matches("\\d+")) break;
            }
            Thread.sleep(50);
        }
        if (!port.matches("\\d+")) {
            p.destroyForcibly();
            throw new IOException("the simulated controller did not report its port within " + timeoutMs + " ms");
        }
        log.accept("Started the simulated controller (" + robot + ") on 127.0.0.1:" + port + ", pid " + p.pid());
        ControllerSession s = new ControllerSession("simulated controller 127.0.0.1:" + port, TcpRequestChannel.parse("127.0.0.1:" + port),
                p, dir, log);
        try {
            s.hello();
        } catch (RuntimeException e) {
            s.close();
            throw e;
        }
        return s;
    }

    private void hello() {
        invoker.execute(Commands.ping());
    }

    public String description() { return description; }

    /** The controller's robot name (robopro controllers), or "" for plain SERVER.mod. */
    public String robotName() { return client.extended() ? client.robotName() : ""; }

    public CompletableFuture<ProgramInfo> download(String name, String rapidText) {
        return invoker.submit(Commands.downloadProgram(name, rapidText.getBytes(StandardCharsets.UTF_8)));
    }

    public CompletableFuture<String> upload(String name) {
        return invoker.submit(Commands.uploadProgram(name)).thenApply(b -> new String(b, StandardCharsets.UTF_8));
    }

    public CompletableFuture<List<ProgramInfo>> programs() { return invoker.submit(Commands.listPrograms()); }

    public CompletableFuture<Void> run(String name) { return invoker.submit(Commands.startProgram(name)); }

    public CompletableFuture<ControllerStatus> status() { return invoker.submit(Commands.readStatus()); }

    /** The controller's joint values (rad). */
    public CompletableFuture<double[]> readJoints() { return invoker.submit(Commands.readJoints()); }

    public List<CommandRecord> history() { return invoker.history(); }

    /** Closes the link and stops a simulator this session started. */
    @Override
    public void close() {
        invoker.close();
        try {
            client.close();
        } catch (RuntimeException ignored) {
            // closing a dead link has nothing left to do
        }
        if (simulator != null) {
            simulator.destroy();
            try {
                if (!simulator.waitFor(3, java.util.concurrent.TimeUnit.SECONDS)) simulator.destroyForcibly();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                simulator.destroyForcibly();
            }
            try {
                Files.deleteIfExists(simulatorDir.resolve("port"));
            } catch (IOException ignored) {
                // a temp file left behind is harmless
            }
        }
    }
}
