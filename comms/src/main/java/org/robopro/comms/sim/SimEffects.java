package org.robopro.comms.sim;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.robopro.calibration.JointEffect;
import org.robopro.calibration.diagnosis.Effect;
import org.robopro.calibration.diagnosis.EffectSpec;
import org.robopro.calibration.diagnosis.GravityTorques;
import org.robopro.kinematics.KinematicModel;
import org.robopro.models.RobotDescription;

/**
 * The simulator's non-geometric effects, selected by {@code --effect SPEC}: diagnosis'
 * {@link EffectSpec} ({@code NAME[:JOINT[<-SOURCE]][=VALUE]}, joint 1-based; without a joint
 * gear-periodic 1, joint-scale and joint-coupling 3 (from 2), backlash and joint-compliance 2),
 * made into diagnosis' own {@link Effect}s, so the controller's real robot and the diagnosis share
 * one definition of every effect (docs/diagnosis.md): joint-compliance deflects by the real gravity
 * torque of the robot's mass model ({@link GravityTorques}, with the controller's payload), and so on.
 * Sizes without a VALUE are drawn from {@link EffectSpec}'s realistic ranges with the simulator's seed.
 * Thermal expansion is referred to {@link EffectSpec#AMBIENT_C}; the controller then reports the
 * warm-up {@link #warmupC} on its clock.
 */
public final class SimEffects {
    private SimEffects() { }

    public static final List<String> NAMES = List.of("backlash", "joint-compliance", "gear-periodic", "joint-scale",
            "joint-coupling", "thermal-expansion");

    /** Temperature at the start of the warm-up, °C, and the expansion's reference. */
    public static final double T0_C = EffectSpec.AMBIENT_C;
    /** The controller's warm-up: rise (K) and time constant (s). */
    public static final double WARMUP_K = 8, WARMUP_TAU_S = 600;

    /**
     * The effects named by {@code specs} on robot {@code d} ({@code model} its nominal model), with
     * sizes drawn from {@code seed} unless given: what the simulated real robot has.
     *
     * @throws IllegalArgumentException naming a spec that is malformed or does not fit the robot
     */
    public static List<Effect.Term> terms(List<String> specs, RobotDescription d, KinematicModel model, long seed) {
        GravityTorques g = d.massModel().map(m -> new GravityTorques(model, m)).orElse(null);
        Random sizes = new Random(seed * 7919 + 17);
        List<Effect.Term> out = new ArrayList<>();
        for (String s : specs) out.add(EffectSpec.parse(s).draw(model, g, sizes));
        return out;
    }

    /** The terms as calibration's {@link JointEffect}s for its TrueRobot. */
    public static List<JointEffect> joint(List<Effect.Term> terms) {
        return terms.stream().map(t -> t.effect().truth(t.values())).toList();
    }

    /** Whether any of these effects depends on temperature. */
    public static boolean thermal(List<JointEffect> effects) {
        return effects.stream().anyMatch(e -> e.name().equals(Effect.Kind.THERMAL.json));
    }

    /** The simulator's temperature near the robot at clock time t (s) when thermal expansion is on. */
    public static double warmupC(double tS) {
        return T0_C + WARMUP_K * (1 - Math.exp(-Math.max(0, tS) / WARMUP_TAU_S));
    }
}
