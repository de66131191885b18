package org.robopro.comms.sim;

import java.util.List;
import java.util.Optional;
import java.util.Random;
import org.robopro.calibration.JointEffect;
import org.robopro.calibration.PoseConditions;
import org.robopro.calibration.simulation.CampaignSimulator;
import org.robopro.calibration.simulation.SimulationSettings;
import org.robopro.calibration.simulation.TrueRobot;
import org.robopro.kinematics.IkSolution;
import org.robopro.kinematics.InverseKinematics;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.JointDescription;
import org.robopro.models.RobotDescription;
import org.robopro.models.Vec3;

/**
 * The simulated controller's robot: the controller computes with the nominal
 * {@link KinematicModel}; the physical robot is calibration's {@link TrueRobot}, made exactly as
 * calibration's campaign simulator makes it (docs/calibration.md): seeded Gaussian errors on every
 * identifiable parameter scaled to the requested RMS flange error, a tracker target on the tool
 * (nominally {@code nominalTarget}, off by 2 mm per axis), a tracker 2.5–3.5 m away at an unknown
 * pose, Gaussian noise — plus the {@link SimEffects} chosen. Immutable.
 */
public final class TrueSimulatedRobot implements SimulatedRobot {

    /**
     * @param errorM        RMS flange position error of the nominal model against the physical robot, m
     * @param noiseM        tracker noise, one sigma per axis, m
     * @param nominalTarget where the tracker target nominally sits on the flange, m
     * @param effects       effect specs, {@code NAME[:joint]} ({@link SimEffects#NAMES})
     */
    public record Options(double errorM, double noiseM, Vec3 nominalTarget, List<String> effects) {
        public Options {
            if (!(errorM >= 0) || !(noiseM >= 0) || !Double.isFinite(errorM + noiseM))
                throw new IllegalArgumentException("error " + errorM + " m and noise " + noiseM + " m must be finite and >= 0");
            effects = List.copyOf(effects);
        }

        /** 0.5 mm RMS error, 0.02 mm noise, target 100 mm along the flange z axis, no effects. */
        public static Options defaults() { return new Options(0.5e-3, 0.02e-3, new Vec3(0, 0, 0.1), List.of()); }

        public Options withError(double m) { return new Options(m, noiseM, nominalTarget, effects); }
        public Options withNoise(double m) { return new Options(errorM, m, nominalTarget, effects); }
        public Options withEffects(List<String> e) { return new Options(errorM, noiseM, nominalTarget, e); }
    }

    private final RobotDescription description;
    private final KinematicModel nominal;
    private final TrueRobot truth;
    private final InverseKinematics ik;
    private final boolean thermal;

    private TrueSimulatedRobot(RobotDescription d, KinematicModel nominal, TrueRobot truth) {
        this.description = d;
        this.nominal = nominal;
        this.truth = truth;
        this.ik = InverseKinematics.of(nominal);
        this.thermal = SimEffects.thermal(truth.effects());
    }

    /** The robot of {@code d} with a physical twin made from {@code seed} and {@code o}. */
    public static TrueSimulatedRobot create(RobotDescription d, long seed, Options o) {
        KinematicModel nominal = KinematicModel.build(d);
        List<JointEffect> effects = SimEffects.parse(o.effects(), nominal);
        // Calibration's own construction of the truth (one pose is simulated and thrown away).
        SimulationSettings s = SimulationSettings.defaults().withPoses(1).withError(o.errorM()).withSigma(o.noiseM())
                .withNominalTarget(o.nominalTarget()).withSeed(seed);
        TrueRobot truth = CampaignSimulator.simulate(nominal, s).truth().withEffects(effects);
        return new TrueSimulatedRobot(d, nominal, truth);
    }

    /** A simulated robot around a given truth (tests). */
    public static TrueSimulatedRobot of(RobotDescription d, KinematicModel nominal, TrueRobot truth) {
        return new TrueSimulatedRobot(d, nominal, truth);
    }

    public KinematicModel nominalModel() { return nominal; }

    /** The physical robot (what calibration should find). */
    public TrueRobot truth() { return truth; }

    public RobotDescription description() { return description; }

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

    @Override public Vec3 measure(double[] q, PoseConditions c, Random rng) { return truth.measure(q, c, rng); }

    @Override public boolean thermal() { return thermal; }
}
