package org.robopro.app.demo;

import java.util.List;
import java.util.Locale;
import java.util.Random;
import org.robopro.calibration.JointEffect;
import org.robopro.calibration.PoseConditions;
import org.robopro.kinematics.KinematicModel;
import org.robopro.models.RobotDescription;

/**
 * The non-geometric effect the demo's true robot hides (issue 8): its kind is chosen with
 * {@code --effect}, its joint and size are drawn from the seed within the realistic ranges of the
 * diagnosis benchmark (docs/diagnosis.md).
 */
public final class ConcealedEffect {
    /** The default concealed effect. */
    public static final String DEFAULT = "gear-periodic";

    /** Effects the demo can conceal ("none": geometric errors only). */
    public static final List<String> NAMES = List.of("gear-periodic", "none");

    /**
     * A drawn effect.
     *
     * @param kind           the diagnosis vocabulary name, e.g. "gear-periodic"
     * @param label          kind and joint, e.g. "gear-periodic j2"
     * @param parameterNames names of its parameters
     * @param values         their values, SI
     * @param truth          the effect as the simulator applies it
     */
    public record Drawn(String kind, String label, List<String> parameterNames, double[] values, JointEffect truth) { }

    private ConcealedEffect() { }

    /** Draws the effect {@code name} for the robot; null for "none". */
    static Drawn draw(String name, KinematicModel nominal, RobotDescription d, Random rng) {
        String n = name.toLowerCase(Locale.ROOT);
        if (!NAMES.contains(n)) throw new IllegalArgumentException("unknown effect '" + name + "'; choose one of " + String.join(", ", NAMES));
        return switch (n) {
            case "none" -> null;
            default -> periodic(rng.nextInt(2), rng);
        };
    }

    // TODO(diagnosis merge): replace by org.robopro.calibration.diagnosis.Effect once it is on main.
    private static Drawn periodic(int joint, Random rng) {
        double[] v = new double[6];
        for (int h = 0; h < 3; h++) {
            double a = Math.toRadians(0.004 + 0.006 * rng.nextDouble()), ph = 2 * Math.PI * rng.nextDouble();
            v[2 * h] = a * Math.cos(ph);
            v[2 * h + 1] = a * Math.sin(ph);
        }
        JointEffect e = new JointEffect() {
            @Override public String name() { return "gear-periodic"; }

            @Override public void addDeltaTheta(KinematicModel model, double[] q, PoseConditions c, double[] dThetaOut) {
                for (int h = 1; h <= 3; h++) dThetaOut[joint] += v[2 * h - 2] * Math.sin(h * q[joint]) + v[2 * h - 1] * Math.cos(h * q[joint]);
            }
        };
        return new Drawn("gear-periodic", "gear-periodic j" + (joint + 1), List.of("a1", "b1", "a2", "b2", "a3", "b3"), v, e);
    }
}
