package org.robopro.calibration.diagnosis;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;
import org.robopro.calibration.JointEffect;
import org.robopro.calibration.simulation.Campaign;
import org.robopro.calibration.simulation.CampaignSimulator;
import org.robopro.calibration.simulation.SimulationSettings;
import org.robopro.kinematics.KinematicModel;
import org.robopro.models.RobotDescription;

/**
 * A simulated calibration campaign with injected non-geometric effects ({@link EffectSpec}s) and
 * realistic conditions columns ({@link SimulatedConditions}): what {@code robopro simulate
 * --effect} writes and the concealed-effect benchmark diagnoses.
 *
 * @param campaign   the campaign (measurements with dir/time_s/temp_c[/payload_kg] columns, truth)
 * @param specs      the effects as asked
 * @param injected   the effects with the values the true robot has (SI), in the order of {@code specs}
 * @param conditions the conditions source used (its warm-up)
 */
public record EffectCampaign(Campaign campaign, List<EffectSpec> specs, List<Effect.Term> injected, SimulatedConditions conditions) {
    public EffectCampaign {
        specs = List.copyOf(specs);
        injected = List.copyOf(injected);
    }

    /**
     * Simulates {@code robot} with settings {@code s} and the effects {@code specs}; sizes without a
     * VALUE and the warm-up are drawn from {@code sizes} (in this order), the conditions' own noise
     * from {@code conditionsSeed}. A payload column is written when a spec is joint-compliance.
     *
     * @throws IllegalArgumentException if a spec does not fit the robot (joint, mass model)
     */
    public static EffectCampaign simulate(RobotDescription robot, SimulationSettings s, List<EffectSpec> specs, Random sizes,
                                          long conditionsSeed) {
        KinematicModel nominal = KinematicModel.build(robot);
        GravityTorques g = robot.massModel().map(m -> new GravityTorques(nominal, m)).orElse(null);
        List<Effect.Term> terms = new ArrayList<>();
        for (EffectSpec spec : specs) terms.add(spec.draw(nominal, g, sizes));
        List<JointEffect> effects = new ArrayList<>();
        for (Effect.Term t : terms) effects.add(t.effect().truth(t.values()));
        boolean compliance = specs.stream().anyMatch(e -> e.kind() == Effect.Kind.COMPLIANCE);
        double rated = compliance ? robot.massModel().orElseThrow().ratedPayloadKg() : Double.NaN;
        SimulatedConditions src = SimulatedConditions.realistic(sizes, conditionsSeed, rated);
        Campaign c = CampaignSimulator.simulate(nominal, s, effects, src);
        return new EffectCampaign(c, specs, terms, src);
    }

    /** Simulates with sizes and conditions from the settings' seed. */
    public static EffectCampaign simulate(RobotDescription robot, SimulationSettings s, List<EffectSpec> specs) {
        return simulate(robot, s, specs, new Random(s.seed() * 7919 + 17), s.seed() * 31 + 5);
    }

    /** The truth file's {@code effects} entries ({@link EffectSpec#truthEntry}) plus the warm-up. */
    public List<Map<String, Object>> truthEntries() {
        List<Map<String, Object>> out = new ArrayList<>();
        for (int i = 0; i < specs.size(); i++) out.add(EffectSpec.truthEntry(specs.get(i), injected.get(i)));
        return out;
    }
}
