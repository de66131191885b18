package org.robopro.comms.sim;

import java.io.IOException;
import java.net.InetAddress;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import org.robopro.comms.link.FaultInjector;
import org.robopro.comms.link.FramedLink;
import org.robopro.comms.link.SerialPortByteLink;
import org.robopro.kinematics.Units;
import org.robopro.models.AtomicFiles;
import org.robopro.models.RobotLibrary;
import org.robopro.models.Vec3;

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
     * @param effects    non-geometric effects, NAME[:joint] ({@link SimEffects#NAMES})
     * @param noiseMm    tracker noise (mm, one sigma per axis)
     * @param targetMm   nominal position of the tracker target on the flange (mm), or null for (0, 0, 100)
     * @param payloadKg  payload at the flange (kg)
     * @param portFile   file to write the bound TCP port to, or null
     * @param realtime   sleep for the motion time
     * @param faultRate  probability of a fault per reply/frame (tests and demos), 0 for none
     * @param truthFile  file to write what the real robot is to, once at start (the reveal of a demo), or null
     * @param world      a scenario of the independent world simulator (org.robopro.world.Scenario) whose robot is the
     *                   physical robot instead of the seeded errors and {@code effects}, or null
     */
    public record Config(String tcp, String serial, int baud, String robot, long seed, double errorMm, List<String> effects,
                         double noiseMm, Vec3 targetMm, double payloadKg, Path portFile, boolean realtime, double faultRate,
                         Path truthFile, String world) {
        public Config {
            if ((tcp == null) == (serial == null)) throw new IllegalArgumentException("give exactly one of --tcp HOST:PORT and --serial DEVICE");
            if (!(errorMm >= 0 && errorMm <= 1000 && noiseMm >= 0 && noiseMm <= 100 && faultRate >= 0 && faultRate < 1))
                throw new IllegalArgumentException("--error-mm must be in 0 .. 1000, --noise-mm in 0 .. 100 (mm), --fault-rate in [0, 1)");
            effects = List.copyOf(effects);
            if (targetMm == null) targetMm = new Vec3(0, 0, 100);
            if (!targetMm.isFinite() || !(payloadKg >= 0)) throw new IllegalArgumentException("--target must be finite and --payload-kg >= 0");
            if (world != null && !effects.isEmpty()) throw new IllegalArgumentException("give either --world SCENARIO or --effect, not both");
        }

        /** Without a truth file. */
        public Config(String tcp, String serial, int baud, String robot, long seed, double errorMm, List<String> effects,
                      double noiseMm, Vec3 targetMm, double payloadKg, Path portFile, boolean realtime, double faultRate) {
            this(tcp, serial, baud, robot, seed, errorMm, effects, noiseMm, targetMm, payloadKg, portFile, realtime, faultRate, null, null);
        }

        /** Defaults for a TCP simulator of the IRB-2000 (seed 1, 0.5 mm error, 0.02 mm noise, no effects). */
        public static Config tcp(String hostPort) {
            return new Config(hostPort, null, 115200, "irb2000", 1, 0.5, List.of(), 0.02, null, 0, null, false, 0, null, null);
        }

        public Config withSeed(long s) { return new Config(tcp, serial, baud, robot, s, errorMm, effects, noiseMm, targetMm, payloadKg, portFile, realtime, faultRate, truthFile, world); }
        public Config withRobot(String r) { return new Config(tcp, serial, baud, r, seed, errorMm, effects, noiseMm, targetMm, payloadKg, portFile, realtime, faultRate, truthFile, world); }
        public Config withErrorMm(double e) { return new Config(tcp, serial, baud, robot, seed, e, effects, noiseMm, targetMm, payloadKg, portFile, realtime, faultRate, truthFile, world); }
        public Config withNoiseMm(double n) { return new Config(tcp, serial, baud, robot, seed, errorMm, effects, n, targetMm, payloadKg, portFile, realtime, faultRate, truthFile, world); }
        public Config withEffects(List<String> e) { return new Config(tcp, serial, baud, robot, seed, errorMm, e, noiseMm, targetMm, payloadKg, portFile, realtime, faultRate, truthFile, world); }
        public Config withPortFile(Path f) { return new Config(tcp, serial, baud, robot, seed, errorMm, effects, noiseMm, targetMm, payloadKg, f, realtime, faultRate, truthFile, world); }
        public Config withFaultRate(double r) { return new Config(tcp, serial, baud, robot, seed, errorMm, effects, noiseMm, targetMm, payloadKg, portFile, realtime, r, truthFile, world); }
        public Config withTargetMm(Vec3 t) { return new Config(tcp, serial, baud, robot, seed, errorMm, effects, noiseMm, t, payloadKg, portFile, realtime, faultRate, truthFile, world); }
        public Config withWorld(String scenario) { return new Config(tcp, serial, baud, robot, seed, errorMm, effects, noiseMm, targetMm, payloadKg, portFile, realtime, faultRate, truthFile, scenario); }
        public Config withTruthFile(Path f) { return new Config(tcp, serial, baud, robot, seed, errorMm, effects, noiseMm, targetMm, payloadKg, portFile, realtime, faultRate, f, world); }

        /** The stand-alone command line for these settings (for {@link ControllerSim#main}). */
        public List<String> toArgs() {
            List<String> a = new ArrayList<>();
            if (tcp != null) { a.add("--tcp"); a.add(tcp); } else { a.add("--serial"); a.add(serial); a.add("--baud"); a.add(Integer.toString(baud)); }
            a.addAll(List.of("--robot", robot, "--seed", Long.toString(seed), "--error-mm", Double.toString(errorMm),
                    "--noise-mm", Double.toString(noiseMm), "--target", targetMm.x() + "," + targetMm.y() + "," + targetMm.z(),
                    "--payload-kg", Double.toString(payloadKg), "--fault-rate", Double.toString(faultRate)));
            for (String e : effects) { a.add("--effect"); a.add(e); }
            if (portFile != null) { a.add("--port-file"); a.add(portFile.toString()); }
            if (realtime) a.add("--realtime");
            if (truthFile != null) { a.add("--truth-file"); a.add(truthFile.toString()); }
            if (world != null) { a.add("--world"); a.add(world); }
            return a;
        }
    }

    /** Parses "X,Y,Z" (mm). */
    public static Vec3 parseTargetMm(String s) {
        String[] p = s.split(",");
        if (p.length != 3) throw new IllegalArgumentException("--target '" + s + "' is not X,Y,Z (mm)");
        try {
            return new Vec3(Double.parseDouble(p[0].strip()), Double.parseDouble(p[1].strip()), Double.parseDouble(p[2].strip()));
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("--target '" + s + "': not a number");
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
        SimulatedRobot robot = c.world() != null
                ? WorldSimulatedRobot.create(RobotLibrary.load(c.robot()), c.world(), c.seed(), Units.mmToM(c.noiseMm()), c.targetMm().times(1e-3))
                : TrueSimulatedRobot.create(RobotLibrary.load(c.robot()), c.seed(),
                        new TrueSimulatedRobot.Options(Units.mmToM(c.errorMm()), Units.mmToM(c.noiseMm()), c.targetMm().times(1e-3), c.effects()));
        SimulatedController controller = new SimulatedController(robot,
                SimulatedController.Settings.defaults(c.seed()).withRealtime(c.realtime()).withPayload(c.payloadKg()));
        if (c.truthFile() != null) writeTruth(c, robot);
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

    /**
     * The truth file ({@code --truth-file}): the robot's {@link TrueSimulatedRobot#truthJson()}
     * (simulate's truth.json, effects with their drawn sizes) plus the simulator's settings:
     * {@code error_mm} as asked, {@code noise_mm}, {@code payload_kg}, the warm-up when thermal.
     * Written once, before the simulator listens; an existing file is replaced (it is the simulator's own output).
     */
    private static void writeTruth(Config c, SimulatedRobot robot) throws IOException {
        Map<String, Object> root = new LinkedHashMap<>();
        root.put("format", "robopro-controller-sim-truth 1");
        root.put("error_mm", c.errorMm());
        root.put("noise_mm", c.noiseMm());
        root.put("payload_kg", c.payloadKg());
        root.put("effect_specs", c.effects());
        if (robot.thermal()) root.put("warmup", Map.of("t0_c", SimEffects.T0_C, "rise_k", SimEffects.WARMUP_K, "tau_s", SimEffects.WARMUP_TAU_S));
        if (c.world() != null) root.put("world_scenario", c.world());
        root.putAll(robot instanceof WorldSimulatedRobot w ? w.truthJson() : ((TrueSimulatedRobot) robot).truthJson());
        AtomicFiles.writeString(c.truthFile(), org.robopro.models.JsonMapper.create().writeValueAsString(root) + "\n", true);
    }

    public SimulatedController controller() { return controller; }

    /** The bound TCP motion port, or -1 for a serial simulator. */
    public int port() { return server instanceof TcpControllerServer t ? t.port() : -1; }

    /** Where it listens, for the user. */
    public String where() { return where; }

    @Override
    public void close() throws Exception {
        server.close();
        controller.close();
    }

    /**
     * Stand-alone entry: {@code --tcp HOST:PORT | --serial DEVICE [--baud N] [--robot NAME] [--seed N]
     * [--error-mm X] [--effect NAME[:joint]]... [--noise-mm X] [--target X,Y,Z] [--payload-kg M] [--port-file FILE]
     * [--realtime] [--fault-rate R] [--truth-file FILE] [--world SCENARIO] [--stop-on-stdin-eof]}.
     * Runs until killed; with {@code --stop-on-stdin-eof} also until its standard input ends, so
     * that a simulator started by another JVM ({@code ControllerConnection.startSimulator}) dies
     * with it even when that JVM is killed outright.
     */
    public static void main(String[] args) throws Exception {
        String tcp = null, serial = null, robot = "irb2000";
        int baud = 115200;
        long seed = 1;
        double error = 0.5, noise = 0.02, faultRate = 0, payload = 0;
        Vec3 target = null;
        List<String> effects = new ArrayList<>();
        Path portFile = null, truthFile = null;
        String world = null;
        boolean realtime = false, stopOnEof = false;
        for (int i = 0; i < args.length; i++) {
            String a = args[i];
            switch (a) {
                case "--realtime" -> realtime = true;
                case "--stop-on-stdin-eof" -> stopOnEof = true;
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
                        case "--target" -> target = parseTargetMm(v);
                        case "--payload-kg" -> payload = Double.parseDouble(v);
                        case "--fault-rate" -> faultRate = Double.parseDouble(v);
                        case "--truth-file" -> truthFile = Path.of(v);
                        case "--world" -> world = v;
                        default -> throw new IllegalArgumentException("unknown option " + a);
                    }
                }
            }
        }
        ControllerSim sim = start(new Config(tcp, serial, baud, robot, seed, error, effects, noise, target, payload, portFile, realtime,
                faultRate, truthFile, world));
        System.out.println("robopro controller-sim: " + sim.controller().robot().name() + " on " + sim.where());
        System.out.flush();
        if (stopOnEof) {
            while (System.in.read() >= 0) {
                // input is ignored; its end means the parent is gone
            }
            System.out.println("robopro controller-sim: standard input closed, stopping");
            sim.close();
            System.exit(0);
        }
        Thread.currentThread().join();
    }
}
