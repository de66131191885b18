package org.robopro.comms.sim;

import com.fasterxml.jackson.core.type.TypeReference;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import org.robopro.calibration.JointEffect;
import org.robopro.calibration.PoseConditions;
import org.robopro.calibration.diagnosis.EffectSpec;
import org.robopro.calibration.simulation.Campaign;
import org.robopro.calibration.simulation.CampaignSimulator;
import org.robopro.calibration.simulation.PoseSampler;
import org.robopro.kinematics.Units;
import org.robopro.calibration.simulation.SimulationSettings;
import org.robopro.calibration.diagnosis.Effect;
import org.robopro.calibration.simulation.TrueRobot;
import org.robopro.kinematics.KinematicModel;
import org.robopro.models.RobotDescription;
import org.robopro.models.Vec3;

/**
 * The simulated controller's robot: the controller computes with the nominal
 * {@link KinematicModel}; the physical robot is calibration's {@link TrueRobot}, made exactly as
 * calibration's campaign simulator makes it (docs/calibration.md): seeded Gaussian errors on every
 * identifiable parameter scaled to the requested RMS flange error, a tracker target on the tool
 * (nominally {@code nominalTarget}, off by 2 mm per axis), a tracker 2.5–3.5 m away at an unknown
 * pose, Gaussian noise — plus the {@link SimEffects} chosen (diagnosis' own effects, sizes drawn
 * from the seed unless given). Immutable.
 */
public final class TrueSimulatedRobot extends NominalController {

    /**
     * @param errorM        RMS flange position error of the nominal model against the physical robot, m
     * @param noiseM        tracker noise, one sigma per axis, m
     * @param nominalTarget where the tracker target nominally sits on the flange, m
     * @param effects       effect specs, {@code NAME[:JOINT[<-SOURCE]][=VALUE]} (diagnosis' EffectSpec; {@link SimEffects})
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

    private final TrueRobot truth;
    private final boolean thermal;
    private final List<Effect.Term> effects;
    private final List<String> specs;       // the effect specs as given, or empty
    private final Campaign campaign;        // calibration's construction of the truth, or null (tests' own truth)

    private TrueSimulatedRobot(RobotDescription d, KinematicModel nominal, TrueRobot truth, List<Effect.Term> effects,
                               List<String> specs, Campaign campaign) {
        super(d, nominal);
        this.effects = List.copyOf(effects);
        this.specs = List.copyOf(specs);
        this.campaign = campaign;
        this.truth = truth;
        this.thermal = SimEffects.thermal(truth.effects());
    }

    /** The robot of {@code d} with a physical twin made from {@code seed} and {@code o}. */
    public static TrueSimulatedRobot create(RobotDescription d, long seed, Options o) {
        KinematicModel nominal = KinematicModel.build(d);
        List<Effect.Term> terms = SimEffects.terms(o.effects(), d, nominal, seed);
        List<JointEffect> effects = SimEffects.joint(terms);
        // Calibration's own construction of the truth (one pose is simulated and thrown away).
        SimulationSettings s = SimulationSettings.defaults().withPoses(1).withError(o.errorM()).withSigma(o.noiseM())
                .withNominalTarget(o.nominalTarget()).withSeed(seed);
        Campaign c = CampaignSimulator.simulate(nominal, s);
        return new TrueSimulatedRobot(d, nominal, c.truth().withEffects(effects), terms, o.effects(), c);
    }

    /** A simulated robot around a given truth (tests); its effects are the truth's. */
    public static TrueSimulatedRobot of(RobotDescription d, KinematicModel nominal, TrueRobot truth) {
        return new TrueSimulatedRobot(d, nominal, truth, List.of(), List.of(), null);
    }

    /**
     * What the physical robot really is, as JSON: {@code robopro simulate}'s truth.json (robot,
     * seed, tracker noise {@code sigma_mm}, {@code nominal_flange_rms_mm} (over 200 poses drawn by
     * calibration's pose rule from the seed), tracker pose, target on
     * the flange, every parameter nominal and true) whose {@code effects} are diagnosis' truth
     * entries (spec with the drawn size, effect, joints, SI parameters) each with its diagnosis
     * {@code label} ("backlash j2"). Only for a robot made by {@link #create}.
     */
    public Map<String, Object> truthJson() {
        if (campaign == null) throw new IllegalStateException("no truth record: this robot was not made by TrueSimulatedRobot.create");
        List<Map<String, Object>> entries = new ArrayList<>();
        for (int i = 0; i < effects.size(); i++) {
            Map<String, Object> e = new LinkedHashMap<>();
            e.put("label", effects.get(i).effect().label());
            e.putAll(EffectSpec.truthEntry(EffectSpec.parse(specs.get(i)), effects.get(i)));
            entries.add(e);
        }
        try {
            Map<String, Object> m = new ObjectMapper().readValue(CampaignSimulator.truthJson(campaign, entries),
                    new TypeReference<LinkedHashMap<String, Object>>() { });
            // The campaign that made the truth had one pose: measure the error over the workspace instead.
            List<double[]> poses = new PoseSampler(nominal).sample(200, new Random(campaign.settings().seed()));
            m.put("nominal_flange_rms_mm", Units.mToMm(CampaignSimulator.flangeRms(nominal, truth.model(), poses)));
            return m;
        } catch (IOException e) {
            throw new IllegalStateException(e);
        }
    }

    /** The non-geometric effects injected by {@link #create}, with their values (SI). */
    public List<Effect.Term> effects() { return effects; }

    public KinematicModel nominalModel() { return nominal; }

    /** The physical robot (what calibration should find). */
    public TrueRobot truth() { return truth; }

    public RobotDescription description() { return description; }

    @Override public Vec3 measure(double[] q, PoseConditions c, Random rng) { return truth.measure(q, c, rng); }

    @Override public boolean thermal() { return thermal; }
}
