package org.robopro.comms.sim;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.robopro.calibration.JointEffect;
import org.robopro.calibration.PoseConditions;
import org.robopro.kinematics.KinematicModel;

/**
 * The simulator's non-geometric effects, selected by {@code --effect NAME[:joint]} (joint
 * 1-based), named as in the diagnosis vocabulary (issue 4, docs/diagnosis.md). Each is a
 * calibration {@link JointEffect} of a fixed, realistic size, added to calibration's TrueRobot:
 * <ul>
 * <li>{@code backlash[:j]} (default j = 2): lost motion 0.02°, Δθ_j = dir_j · 0.01°;</li>
 * <li>{@code joint-compliance[:j]} (default 2): gear elasticity under gravity,
 *     Δθ_j = 0.03° · cos θ_j · (1 + payload / 10 kg) (a stand-in for c · τ_gravity);</li>
 * <li>{@code gear-periodic[:j]} (default 1): Δθ_j = 0.01° sin q_j + 0.005° cos 2q_j;</li>
 * <li>{@code joint-scale[:j]} (default 3): θ_j += 2·10⁻⁴ q_j (gear-ratio error);</li>
 * <li>{@code joint-coupling[:j]} (default 3): θ_j += 2·10⁻⁴ q_(j−1) (coupled from the joint before);</li>
 * <li>{@code thermal-expansion}: every length grows by 11.5·10⁻⁶/K · (T − 20 °C); the controller
 *     then reports a warm-up T(t) = 20 °C + 8 K (1 − e^(−t / 600 s)).</li>
 * </ul>
 */
public final class SimEffects {
    private SimEffects() { }

    public static final List<String> NAMES = List.of("backlash", "joint-compliance", "gear-periodic", "joint-scale",
            "joint-coupling", "thermal-expansion");

    /** Temperature at the start of the warm-up, °C, and the expansion's reference. */
    public static final double T0_C = 20;
    public static final double WARMUP_K = 8, WARMUP_TAU_S = 600, ALPHA_PER_K = 11.5e-6;

    /** The effects named by {@code specs} ("backlash:2", "thermal-expansion", ...) on {@code model}. */
    public static List<JointEffect> parse(List<String> specs, KinematicModel model) {
        List<JointEffect> out = new ArrayList<>();
        for (String spec : specs) out.add(parse(spec, model.dof()));
        return out;
    }

    /** Whether any of these effects depends on temperature. */
    public static boolean thermal(List<JointEffect> effects) {
        return effects.stream().anyMatch(e -> e.name().equals("thermal-expansion"));
    }

    /** The simulator's temperature near the robot at clock time t (s) when thermal expansion is on. */
    public static double warmupC(double tS) {
        return T0_C + WARMUP_K * (1 - Math.exp(-Math.max(0, tS) / WARMUP_TAU_S));
    }

    static JointEffect parse(String spec, int dof) {
        String s = spec.strip().toLowerCase(Locale.ROOT);
        int colon = s.indexOf(':');
        String name = colon < 0 ? s : s.substring(0, colon);
        if (!NAMES.contains(name))
            throw new IllegalArgumentException("unknown effect '" + spec + "'; known: " + String.join(", ", NAMES) + " (NAME[:joint])");
        int joint = switch (name) {
            case "gear-periodic" -> 1;
            case "joint-scale", "joint-coupling" -> Math.min(3, dof);
            default -> Math.min(2, dof);
        };
        if (colon >= 0) {
            if (name.equals("thermal-expansion")) throw new IllegalArgumentException("effect '" + spec + "': thermal-expansion takes no joint");
            try {
                joint = Integer.parseInt(s.substring(colon + 1).strip());
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("effect '" + spec + "': joint '" + s.substring(colon + 1) + "' is not a number");
            }
            if (joint < 1 || joint > dof) throw new IllegalArgumentException("effect '" + spec + "': joint " + joint + " outside 1.." + dof);
        }
        if (name.equals("joint-coupling") && joint < 2)
            throw new IllegalArgumentException("effect '" + spec + "': joint-coupling needs a joint >= 2 (coupled from the joint before)");
        int j = joint - 1;
        String label = name.equals("thermal-expansion") ? name : name + ":" + joint;
        return switch (name) {
            case "backlash" -> effect(label, name, (m, q, c, d) -> d[j] += c.direction(j) * Math.toRadians(0.01));
            case "joint-compliance" -> effect(label, name, (m, q, c, d) -> {
                double payload = Double.isNaN(c.payloadKg()) ? 0 : c.payloadKg();
                d[j] += Math.toRadians(0.03) * Math.cos(m.theta(q)[j]) * (1 + payload / 10);
            });
            case "gear-periodic" -> effect(label, name, (m, q, c, d) -> d[j] += Math.toRadians(0.01) * Math.sin(q[j])
                    + Math.toRadians(0.005) * Math.cos(2 * q[j]));
            case "joint-scale" -> effect(label, name, (m, q, c, d) -> d[j] += 2e-4 * q[j]);
            case "joint-coupling" -> effect(label, name, (m, q, c, d) -> d[j] += 2e-4 * q[j - 1]);
            default -> new JointEffect() {
                @Override public String name() { return "thermal-expansion"; }

                @Override public double lengthStrain(PoseConditions c) {
                    return Double.isNaN(c.tempC()) ? 0 : ALPHA_PER_K * (c.tempC() - T0_C);
                }

                @Override public String toString() { return "thermal-expansion"; }
            };
        };
    }

    private interface DeltaTheta {
        void add(KinematicModel model, double[] q, PoseConditions c, double[] dTheta);
    }

    private static JointEffect effect(String label, String name, DeltaTheta f) {
        return new JointEffect() {
            @Override public String name() { return name; }

            @Override public void addDeltaTheta(KinematicModel model, double[] q, PoseConditions c, double[] dThetaOut) {
                f.add(model, q, c, dThetaOut);
            }

            @Override public String toString() { return label; }
        };
    }
}
