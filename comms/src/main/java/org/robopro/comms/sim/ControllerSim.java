package org.robopro.comms.sim;

import java.io.IOException;
import java.net.InetAddress;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.robopro.comms.link.FaultInjector;
import org.robopro.comms.link.FramedLink;
import org.robopro.comms.link.SerialPortByteLink;
import org.robopro.kinematics.Units;
import org.robopro.models.AtomicFiles;
import org.robopro.models.RobotLibrary;

/**
 * Starts the simulated controller from settings: the {@code robopro controller-sim} command and
 * the stand-alone {@link #main} (which tests run as a separate JVM) both come here.
 */
public final class ControllerSim implements AutoCloseable {

    /**
     * @param tcp        "HOST:PORT" (PORT 0: any free pair), or null
     * @param serial     serial device path, or null (exactly one of tcp and serial)
     * @param baud       serial speed
     * @param robot      shipped robot name or robot file
     * @param seed       seed of the geometric errors and of the tracker noise
     * @param errorMm    size of the geometric errors (mm; rad per m for angles)
     * @param effects    non-geometric effects ({@link ModelSimulatedRobot#EFFECTS})
     * @param noiseMm    tracker noise (mm, one sigma per axis)
     * @param portFile   file to write the bound TCP port to, or null
     * @param realtime   sleep for the motion time
     * @param faultRate  probability of a fault per reply/frame (tests and demos), 0 for none
     */
    public record Config(String tcp, String serial, int baud, String robot, long seed, double errorMm, List<String> effects,
                         double noiseMm, Path portFile, boolean realtime, double faultRate) {
        public Config {
            if ((tcp == null) == (serial == null)) throw new IllegalArgumentException("give exactly one of --tcp HOST:PORT and --serial DEVICE");
            if (!(errorMm >= 0 && noiseMm >= 0 && faultRate >= 0 && faultRate < 1))
                throw new IllegalArgumentException("--error-mm and --noise-mm must be >= 0, --fault-rate in [0, 1)");
            effects = List.copyOf(effects);
        }
    }

    private final SimulatedController controller;
    private final AutoCloseable server;
    private final String where;

    private ControllerSim(SimulatedController controller, AutoCloseable server, String where) {
        this.controller = controller;
        this.server = server;
        this.where = where;
    }

    public static ControllerSim start(Config c) throws IOException {
        ModelSimulatedRobot robot = ModelSimulatedRobot.create(RobotLibrary.load(c.robot()), c.seed(), Units.mmToM(c.errorMm()), c.effects());
        SimulatedController controller = new SimulatedController(robot,
                SimulatedController.Settings.defaults(c.seed()).withNoise(Units.mmToM(c.noiseMm())).withRealtime(c.realtime()));
        ProtocolHandler handler = new ProtocolHandler(controller);
        FaultInjector faults = c.faultRate() > 0 ? FaultInjector.uniform(c.seed() + 1, c.faultRate(), 30) : null;
        if (c.tcp() != null) {
            int i = c.tcp().lastIndexOf(':');
            if (i <= 0) throw new IllegalArgumentException("--tcp '" + c.tcp() + "' is not HOST:PORT");
            int port;
            try {
                port = Integer.parseInt(c.tcp().substring(i + 1));
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("--tcp '" + c.tcp() + "': port is not a number");
            }
            if (port < 0 || port > 65534) throw new IllegalArgumentException("--tcp port " + port + " outside 0..65534");
            TcpControllerServer server = new TcpControllerServer(handler, InetAddress.getByName(c.tcp().substring(0, i)), port, faults);
            if (c.portFile() != null) AtomicFiles.writeString(c.portFile(), server.port() + "\n", true);
            return new ControllerSim(controller, server, "tcp " + c.tcp().substring(0, i) + ":" + server.port()
                    + " (logger on " + server.loggerPort() + ")");
        }
        SerialControllerServer server = new SerialControllerServer(handler, () -> new SerialPortByteLink(c.serial(), c.baud()),
                FramedLink.Options.forBaud(c.baud()), faults);
        return new ControllerSim(controller, server, "serial " + c.serial() + " at " + c.baud() + " baud");
    }

    public SimulatedController controller() { return controller; }

    /** Where it listens, for the user. */
    public String where() { return where; }

    @Override
    public void close() throws Exception {
        server.close();
        controller.close();
    }

    /**
     * Stand-alone entry: {@code --tcp HOST:PORT | --serial DEVICE [--baud N] [--robot NAME] [--seed N]
     * [--error-mm X] [--effect NAME]... [--noise-mm X] [--port-file FILE] [--realtime] [--fault-rate R]}.
     * Runs until killed.
     */
    public static void main(String[] args) throws Exception {
        String tcp = null, serial = null, robot = "irb2000";
        int baud = 115200;
        long seed = 1;
        double error = 0.5, noise = 0.02, faultRate = 0;
        List<String> effects = new ArrayList<>();
        Path portFile = null;
        boolean realtime = false;
        for (int i = 0; i < args.length; i++) {
            String a = args[i];
            switch (a) {
                case "--realtime" -> realtime = true;
                default -> {
                    if (i + 1 >= args.length) throw new IllegalArgumentException("option " + a + " needs a value");
                    String v = args[++i];
                    switch (a) {
                        case "--tcp" -> tcp = v;
                        case "--serial" -> serial = v;
                        case "--baud" -> baud = Integer.parseInt(v);
                        case "--robot" -> robot = v;
                        case "--seed" -> seed = Long.parseLong(v);
                        case "--error-mm" -> error = Double.parseDouble(v);
                        case "--effect" -> effects.add(v);
                        case "--noise-mm" -> noise = Double.parseDouble(v);
                        case "--port-file" -> portFile = Path.of(v);
                        case "--fault-rate" -> faultRate = Double.parseDouble(v);
                        default -> throw new IllegalArgumentException("unknown option " + a);
                    }
                }
            }
        }
        ControllerSim sim = start(new Config(tcp, serial, baud, robot, seed, error, effects, noise, portFile, realtime, faultRate));
        System.out.println("robopro controller-sim: " + sim.controller().robot().name() + " on " + sim.where());
        Thread.currentThread().join();
    }
}
