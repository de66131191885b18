package org.robopro.comms.sim;

import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.Random;
import org.robopro.kinematics.IkSolution;
import org.robopro.kinematics.InverseKinematics;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.ModelParameter;
import org.robopro.kinematics.Pose;
import org.robopro.models.JointDescription;
import org.robopro.models.RobotDescription;

/**
 * A {@link SimulatedRobot} from a robot description: the controller uses the nominal
 * {@link KinematicModel}; the "true" robot is the same structure with seeded geometric errors
 * on every identifiable parameter (translations ~ N(0, errorM), rotations ~ N(0, errorM / 1 m)
 * rad), plus optional non-geometric effects:
 * <ul>
 * <li>{@code backlash}: each joint lags by half a 0.02 deg dead band against its last motion;</li>
 * <li>{@code compliance}: joints 2 and 3 sag under gravity by 0.03 deg times the cosine of the
 * link's angle to the horizontal (a stand-in for gear elasticity).</li>
 * </ul>
 * Immutable; the true parameters are available for checking a calibration against them.
 */
public final class ModelSimulatedRobot implements SimulatedRobot {
    public static final List<String> EFFECTS = List.of("backlash", "compliance");

    private final RobotDescription description;
    private final KinematicModel nominal;
    private final KinematicModel truth;
    private final InverseKinematics ik;
    private final boolean backlash;
    private final boolean compliance;

    private ModelSimulatedRobot(RobotDescription d, KinematicModel nominal, KinematicModel truth, List<String> effects) {
        for (String e : effects)
            if (!EFFECTS.contains(e.toLowerCase(Locale.ROOT)))
                throw new IllegalArgumentException("unknown effect '" + e + "'; known: " + String.join(", ", EFFECTS));
        this.description = d;
        this.nominal = nominal;
        this.truth = truth;
        this.ik = InverseKinematics.of(nominal);
        this.backlash = effects.stream().anyMatch(e -> e.equalsIgnoreCase("backlash"));
        this.compliance = effects.stream().anyMatch(e -> e.equalsIgnoreCase("compliance"));
    }

    /** The robot with seeded geometric errors of size {@code errorM} and the named effects. */
    public static ModelSimulatedRobot create(RobotDescription d, long seed, double errorM, List<String> effects) {
        if (!(errorM >= 0) || !Double.isFinite(errorM)) throw new IllegalArgumentException("error size " + errorM + " m must be >= 0");
        KinematicModel nominal = KinematicModel.build(d);
        double[] p = nominal.parameterValues();
        List<ModelParameter> params = nominal.parameters();
        Random rnd = new Random(seed);
        for (int i = 0; i < p.length; i++) {
            double s = params.get(i).kind() == ModelParameter.Kind.TRANSLATION ? errorM : errorM / 1.0;
            p[i] += s * rnd.nextGaussian();
        }
        return new ModelSimulatedRobot(d, nominal, nominal.withParameterValues(p), effects);
    }

    public KinematicModel nominalModel() { return nominal; }

    /** The "true" model (what calibration should find). */
    public KinematicModel trueModel() { return truth; }

    @Override public String name() { return description.name(); }

    @Override public int dof() { return nominal.dof(); }

    @Override public double[] lowerLimits() { return description.joints().stream().mapToDouble(JointDescription::min).toArray(); }

    @Override public double[] upperLimits() { return description.joints().stream().mapToDouble(JointDescription::max).toArray(); }

    @Override public double[] maxSpeeds() { return description.joints().stream().mapToDouble(JointDescription::maxSpeed).toArray(); }

    @Override public Pose nominalFlange(double[] q) { return nominal.flange(q); }

    @Override
    public Pose trueFlange(double[] q, int[] lastDirection) {
        double[] qe = q.clone();
        if (backlash) for (int i = 0; i < qe.length; i++) qe[i] -= lastDirection[i] * Math.toRadians(0.01);
        if (compliance && qe.length >= 3) {
            qe[1] += Math.toRadians(0.03) * Math.cos(q[1]);
            qe[2] += Math.toRadians(0.03) * Math.cos(q[2]);
        }
        return truth.flange(qe);
    }

    @Override
    public Optional<double[]> inverse(Pose baseTflange, double[] qSeed) {
        return ik.solveNear(baseTflange, qSeed).map(IkSolution::q);
    }
}
