package org.robopro.app.demo;

import java.io.IOException;
import java.net.InetAddress;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Random;
import org.robopro.calibration.PoseConditions;
import org.robopro.calibration.simulation.CampaignSimulator;
import org.robopro.calibration.simulation.PoseSampler;
import org.robopro.calibration.simulation.TrueRobot;
import org.robopro.comms.sim.ProtocolHandler;
import org.robopro.comms.sim.SimulatedController;
import org.robopro.comms.sim.SimulatedRobot;
import org.robopro.comms.sim.TcpControllerServer;
import org.robopro.kinematics.IkSolution;
import org.robopro.kinematics.InverseKinematics;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.kinematics.Units;
import org.robopro.models.AtomicFiles;
import org.robopro.models.CellFile;
import org.robopro.models.Vec3;
import org.robopro.models.JointDescription;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;

/**
 * The demo's simulated IRB-2000 controller, run as a process of its own: the comms module's
 * {@link SimulatedController} (open_abb protocol plus robopro's extension on TCP) driving a
 * {@link TrueRobot} with realistic geometric errors (5-15 mm RMS at the flange, drawn from the
 * seed) and one concealed non-geometric effect ({@link ConcealedEffect}). The controller itself
 * knows only the nominal model, like a real one.
 *
 * <p>{@code java ... DemoController --port-file FILE --truth FILE [--seed N] [--effect NAME]
 * [--noise-mm S]}: listens on 127.0.0.1 at a free port, writes the port to the port file once
 * it accepts connections, and writes the truth (error size, effect and its values) to the truth
 * file, which the demo reads only after the diagnosis to reveal what was concealed. Runs until
 * killed.
 */
public final class DemoController {
    private DemoController() { }

    /** What the simulated robot really is, for the reveal at the end. */
    public record Truth(double errorRmsM, ConcealedEffect.Drawn effect, double noiseM) { }

    /** The robot behind the controller: nominal model for the controller, true robot for the tracker. */
    static final class Robot implements SimulatedRobot {
        private final RobotDescription description;
        private final KinematicModel nominal;
        private final TrueRobot truth;
        private final InverseKinematics ik;

        Robot(RobotDescription description, KinematicModel nominal, TrueRobot truth) {
            this.description = description;
            this.nominal = nominal;
            this.truth = truth;
            this.ik = InverseKinematics.of(nominal);
        }

        /** The physical robot (tests compare it with the nominal model). */
        TrueRobot truth() { return truth; }

        @Override public String name() { return description.name(); }
        @Override public int dof() { return nominal.dof(); }
        @Override public double[] lowerLimits() { return description.joints().stream().mapToDouble(JointDescription::min).toArray(); }
        @Override public double[] upperLimits() { return description.joints().stream().mapToDouble(JointDescription::max).toArray(); }
        @Override public double[] maxSpeeds() { return description.joints().stream().mapToDouble(JointDescription::maxSpeed).toArray(); }
        @Override public Pose nominalFlange(double[] q) { return nominal.flange(q); }

        @Override
        public Optional<double[]> inverse(Pose baseTflange, double[] qSeed) {
            return ik.solveNear(baseTflange, qSeed).map(IkSolution::q);
        }

        /** The tracker sees the reflector at the torch tip under the conditions the controller reports (approach directions, payload). */
        @Override
        public Vec3 measure(double[] q, PoseConditions c, Random rng) { return truth.measure(q, c, rng); }
    }

    /** Where the tracker stands: 3 m in front of the robot, turned to face it (unknown to the calibration). */
    static final Pose TRACKER_T_BASE = Pose.rotZ(Math.toRadians(160)).times(Pose.translation(-3.0, 0.4, -0.2));

    /**
     * Builds the true robot of a seed: Gaussian errors on every Table-1 parameter scaled to an
     * RMS flange error drawn uniformly in 5-15 mm, plus the concealed effect; the tracker's
     * reflector sits at {@code flangeTreflector} (the torch tip) and the tracker at {@link #TRACKER_T_BASE}.
     */
    static Robot robot(RobotDescription d, Pose flangeTreflector, long seed, String effect, double noiseM, Truth[] truthOut) {
        KinematicModel nominal = KinematicModel.build(d);
        Random rng = new Random(seed * 1_000_003L + 11);
        double errorM = Units.mmToM(5 + 10 * rng.nextDouble());
        List<double[]> sizing = new PoseSampler(nominal).sample(100, new Random(seed));
        KinematicModel trueModel = CampaignSimulator.perturb(nominal, errorM, sizing, rng);
        ConcealedEffect.Drawn drawn = ConcealedEffect.draw(effect, nominal, d, rng);
        TrueRobot truth = new TrueRobot(trueModel, flangeTreflector, TRACKER_T_BASE, noiseM, 0,
                drawn == null ? List.of() : List.of(drawn.truth()));
        if (truthOut != null) truthOut[0] = new Truth(CampaignSimulator.flangeRms(nominal, trueModel, sizing), drawn, noiseM);
        return new Robot(d, nominal, truth);
    }

    static String truthJson(Truth t) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("format", "robopro-demo-truth 1");
        m.put("geometric_error_rms_mm", Units.mToMm(t.errorRmsM()));
        m.put("concealed_effect", t.effect() == null ? "none" : t.effect().label());
        m.put("effect_kind", t.effect() == null ? "none" : t.effect().kind());
        if (t.effect() != null) {
            m.put("effect_parameters", t.effect().parameterNames());
            m.put("effect_values_si", t.effect().values());
        }
        m.put("tracker_noise_mm", Units.mToMm(t.noiseM()));
        return Json.write(m);
    }

    public static void main(String[] args) throws Exception {
        Path portFile = null, truthFile = null;
        long seed = 1;
        String effect = ConcealedEffect.DEFAULT;
        double noiseMm = 0.02;
        for (int i = 0; i < args.length; i++) {
            if (i + 1 >= args.length) throw new IllegalArgumentException("option " + args[i] + " needs a value");
            String v = args[++i];
            switch (args[i - 1]) {
                case "--port-file" -> portFile = Path.of(v);
                case "--truth" -> truthFile = Path.of(v);
                case "--seed" -> seed = Long.parseLong(v);
                case "--effect" -> effect = v;
                case "--noise-mm" -> noiseMm = Double.parseDouble(v);
                default -> throw new IllegalArgumentException("unknown option " + args[i - 1]);
            }
        }
        if (portFile == null) throw new IllegalArgumentException("--port-file is required");
        start(seed, effect, Units.mmToM(noiseMm), portFile, truthFile);
        Thread.currentThread().join();
    }

    /** Starts the controller on a free loopback port; returns the server (tests run it in process). */
    static TcpControllerServer start(long seed, String effect, double noiseM, Path portFile, Path truthFile) throws IOException {
        RobotDescription d = RobotLibrary.shipped("irb2000");
        Truth[] truth = new Truth[1];
        Robot robot = robot(d, WeldProgram.torch(CellFile.shipped("irb2000-welding")), seed, effect, noiseM, truth);
        SimulatedController controller = new SimulatedController(robot, SimulatedController.Settings.defaults(seed));
        TcpControllerServer server = new TcpControllerServer(new ProtocolHandler(controller), InetAddress.getLoopbackAddress(), 0, null);
        if (truthFile != null) AtomicFiles.writeString(truthFile, truthJson(truth[0]), true);
        // The port file last: its appearance tells the demo the controller is ready.
        AtomicFiles.writeString(portFile, server.port() + "\n", true);
        System.out.printf(Locale.ROOT, "robopro demo controller: irb2000 on 127.0.0.1:%d%n", server.port());
        System.out.flush();
        return server;
    }
}
