package org.robopro.app.demo;

import java.util.List;
import java.util.Locale;
import java.util.Random;
import org.robopro.calibration.JointEffect;
import org.robopro.calibration.diagnosis.Effect;
import org.robopro.calibration.diagnosis.GravityTorques;
import org.robopro.kinematics.KinematicModel;
import org.robopro.models.RobotDescription;

/**
 * The non-geometric effect the demo's true robot hides (issue 8): its kind is chosen with
 * {@code --effect}, its joint and size are drawn from the seed within the realistic ranges of the
 * concealed-effect benchmark (docs/diagnosis.md). The simulator applies exactly the diagnosis's
 * own definition ({@link Effect#truth}), so what the diagnosis names can be compared with it.
 */
public final class ConcealedEffect {
    /** The default concealed effect. */
    public static final String DEFAULT = "gear-periodic";

    /** Effects the demo can conceal ("none": geometric errors only). */
    public static final List<String> NAMES = List.of("gear-periodic", "joint-compliance", "backlash", "joint-scale", "none");

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

    private static double uniform(Random r, double lo, double hi) { return lo + (hi - lo) * r.nextDouble(); }

    /** Draws the effect {@code name} for the robot; null for "none". */
    static Drawn draw(String name, KinematicModel nominal, RobotDescription d, Random rng) {
        String n = name.toLowerCase(Locale.ROOT);
        if (!NAMES.contains(n)) throw new IllegalArgumentException("unknown effect '" + name + "'; choose one of " + String.join(", ", NAMES));
        Effect e;
        double[] v;
        switch (n) {
            case "none" -> { return null; }
            case "gear-periodic" -> {
                // Joints 1-2: a periodic error of 0.004-0.01 deg per harmonic (joint 3's is barely distinct from geometry).
                e = Effect.periodic(rng.nextInt(2));
                v = new double[2 * Effect.HARMONICS];
                for (int h = 0; h < Effect.HARMONICS; h++) {
                    double a = Math.toRadians(uniform(rng, 0.004, 0.01)), ph = 2 * Math.PI * rng.nextDouble();
                    v[2 * h] = a * Math.cos(ph);
                    v[2 * h + 1] = a * Math.sin(ph);
                }
            }
            case "joint-compliance" -> {
                GravityTorques g = new GravityTorques(nominal, d.massModel()
                        .orElseThrow(() -> new IllegalArgumentException(d.name() + " has no mass model: no compliance")));
                e = Effect.compliance(1 + rng.nextInt(2), g); // joints 2-3 carry the arm's weight
                v = new double[] {1 / uniform(rng, 0.5e6, 2e6)};
            }
            case "backlash" -> {
                e = Effect.backlash(rng.nextInt(3));
                v = new double[] {Math.toRadians(uniform(rng, 0.02, 0.05))};
            }
            case "joint-scale" -> {
                e = Effect.scale(rng.nextInt(2));
                v = new double[] {(rng.nextBoolean() ? 1 : -1) * uniform(rng, 1e-4, 3e-4)};
            }
            default -> throw new IllegalStateException(n);
        }
        return new Drawn(e.kind().json, e.label(), e.parameterNames(), v, e.truth(v));
    }
}
