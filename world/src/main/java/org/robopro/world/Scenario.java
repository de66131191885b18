package org.robopro.world;

import static org.robopro.world.Expected.Family.CROSS_COUPLING;
import static org.robopro.world.Expected.Family.GEAR_RATIO;
import static org.robopro.world.Expected.Family.GRAVITY_ELASTICITY;
import static org.robopro.world.Expected.Family.LOST_MOTION;
import static org.robopro.world.Expected.Family.THERMAL_GROWTH;
import static org.robopro.world.Expected.Family.TRANSMISSION_ERROR;
import static org.robopro.world.Expected.claim;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import java.util.function.BiFunction;
import java.util.function.UnaryOperator;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;

/**
 * A named situation of the real robot with the answer a diagnosis must give. Each seed draws a
 * new robot: geometric errors (axis points ~1 mm, axis directions ~0.1°, zero offsets ~0.1°,
 * flange frame, measured target ~100 mm off the flange), an unknown instrument 2.5–3.5 m away, and
 * the scenario's own effects with sizes drawn from realistic ranges.
 *
 * @param name     short name, e.g. "lost motion j2, directions not recorded"
 * @param family   the group it is scored in ("null", "outside", or a family's name)
 * @param robot    shipped robot name
 * @param expected the answer
 * @param effects  adds the concealed effects to the base robot (nominal file, random numbers)
 * @param plan     adjusts the default campaign plan
 */
public record Scenario(String name, String family, String robot, Expected expected,
                       BiFunction<RobotDescription, Random, UnaryOperator<WorldRobot>> effects, UnaryOperator<Campaign.Plan> plan,
                       double[] targetInFlangeM) {

    /** A scenario measuring the target at {@link #TARGET_IN_FLANGE_M}, on the flange's axis. */
    public Scenario(String name, String family, String robot, Expected expected,
                    BiFunction<RobotDescription, Random, UnaryOperator<WorldRobot>> effects, UnaryOperator<Campaign.Plan> plan) {
        this(name, family, robot, expected, effects, plan, TARGET_IN_FLANGE_M);
    }

    public Scenario {
        targetInFlangeM = targetInFlangeM.clone();
    }

    /** Where the measured target sits nominally on the flange, m (off by ~2 mm in each drawn robot). */
    @Override public double[] targetInFlangeM() { return targetInFlangeM.clone(); }

    /** One drawn robot and its campaign. */
    public record Trial(Scenario scenario, long seed, WorldRobot world, Campaign.Result campaign) {
        /** What was concealed, as JSON (mm, deg, SI where named). */
        public String truthJson() { return Truth.json(scenario, seed, world, campaign); }
    }

    /**
     * The group of campaigns approached from one side ({@link Campaign.Approach}): their answer
     * belongs to their own campaign ({@link #answerNeedsItsCampaign()}).
     */
    public static final String ONE_SIDED = "one-sided";

    /**
     * Whether the expected answer holds only for the scenario's own campaign: a one-sided approach
     * hides a lost motion that another campaign of the same robot (the demo's, a controller
     * simulator's) shows. Such a scenario is scored on its own campaign only.
     */
    public boolean answerNeedsItsCampaign() { return family.equals(ONE_SIDED); }

    /** Where the measured target sits nominally on the flange unless a scenario says otherwise, m: 100 mm along its z axis. */
    static final double[] TARGET_IN_FLANGE_M = {0, 0, 0.1};

    /** Draws the robot and measures it. */
    public Trial trial(long seed) { return trial(seed, p -> p); }

    /** Draws the robot and measures it with the scenario's plan changed by {@code adjust} (e.g. more poses). */
    public Trial trial(long seed, UnaryOperator<Campaign.Plan> adjust) {
        WorldRobot world = robot(seed, targetInFlangeM);
        return new Trial(this, seed, world, Campaign.run(world, RobotLibrary.shipped(robot), campaignPlan(seed, adjust)));
    }

    /**
     * The trial's geometry-only twin: the same robot (geometric errors, target, instrument), the
     * same poses in the same measuring order, the same times, temperatures, payloads and noise
     * draws, but none of the scenario's concealed effects and no gross outliers. Diagnosed like the
     * trial, it shows what the campaign's size and noise allow when nothing but geometry is there:
     * the achievable floor of that very run. For a scenario that conceals nothing and injects no
     * outliers the twin is the trial itself.
     */
    public Trial twin(long seed) { return twin(seed, p -> p); }

    /** {@link #twin(long)} of the trial {@link #trial(long, UnaryOperator)} gives with {@code adjust}. */
    public Trial twin(long seed, UnaryOperator<Campaign.Plan> adjust) {
        RobotDescription nominal = RobotLibrary.shipped(robot);
        WorldRobot world = baseRobot(nominal, robotStream(seed), 1e-3, Math.toRadians(0.1), targetInFlangeM);
        return new Trial(this, seed, world, Campaign.run(world, nominal, campaignPlan(seed, adjust).withOutliers(0)));
    }

    private Campaign.Plan campaignPlan(long seed, UnaryOperator<Campaign.Plan> adjust) {
        return adjust.apply(plan.apply(Campaign.Plan.defaults(campaignSeed(seed))));
    }

    /**
     * The seed of the scenario's campaign (poses, order, validation split, warm-up, noise) for a
     * trial seed: drawn from the seed and the scenario's name, so that two scenarios of one seed
     * measure different poses with different noise (their runs are independent), while a scenario
     * and a seed always give the same campaign and its twin shares it.
     */
    public long campaignSeed(long seed) { return mix(seed, name); }

    /** A 64-bit mix of a seed and a name (the finaliser of SplitMix64: nearby seeds give unrelated results). */
    static long mix(long seed, String name) {
        long z = seed * 0x9E3779B97F4A7C15L + name.hashCode();
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }

    /** The random stream the scenario's robot of a seed is drawn from: geometric errors first, then the concealed effects. */
    private Random robotStream(long seed) { return new Random(seed * 31 + name.hashCode()); }

    /**
     * The scenario's real robot of a seed, without a campaign (e.g. for a simulated controller),
     * its measured target nominally at {@code targetInFlangeM} on the flange (off by ~2 mm).
     */
    public WorldRobot robot(long seed, double[] targetInFlangeM) {
        RobotDescription nominal = RobotLibrary.shipped(robot);
        Random rng = robotStream(seed);
        WorldRobot base = baseRobot(nominal, rng, 1e-3, Math.toRadians(0.1), targetInFlangeM);
        return effects.apply(nominal, rng).apply(base);
    }

    /** What a robot of this scenario conceals, as JSON (the truth record without a campaign). */
    public String truthJson(long seed, WorldRobot world) { return Truth.json(this, seed, world, null); }

    /**
     * The robot file with random geometric errors and an unknown instrument pose: axis points by
     * N(0, pointM) per component, axis directions and flange by N(0, angleRad), zero offsets
     * N(0, angleRad), the measured target at (0, 0, 100) mm on the flange ± 2 mm (and turned a
     * little for 6-D), the instrument 2.5–3.5 m away at any heading, tilted up to 5°.
     */
    public static WorldRobot baseRobot(RobotDescription nominal, Random rng, double pointM, double angleRad) {
        return baseRobot(nominal, rng, pointM, angleRad, new double[] {0, 0, 0.1});
    }

    /** {@link #baseRobot(RobotDescription, Random, double, double)} with the measured target nominally elsewhere on the flange. */
    public static WorldRobot baseRobot(RobotDescription nominal, Random rng, double pointM, double angleRad, double[] targetInFlangeM) {
        int n = nominal.dof();
        Arm arm = Arm.of(nominal).perturbed(rng, pointM, angleRad);
        double[] offsets = new double[n];
        for (int i = 0; i < n; i++) offsets[i] = angleRad * rng.nextGaussian();
        double[] target = Rigid.plus(targetInFlangeM, Arm.gauss(rng, 2e-3));
        double[] tilt = Arm.gauss(rng, Math.toRadians(0.5));
        Rigid tool = new Rigid(Rigid.rotation(Rigid.unit(tilt), Rigid.norm(tilt), new double[3]).r(), target);
        double heading = 2 * Math.PI * rng.nextDouble(), dist = 2.5 + rng.nextDouble();
        Rigid baseFromInstrument = Rigid.translation(dist * Math.cos(heading), dist * Math.sin(heading), rng.nextDouble())
                .times(Rigid.rotation(new double[] {0, 0, 1}, 2 * Math.PI * rng.nextDouble(), new double[3]))
                .times(Rigid.rotation(new double[] {1, 0, 0}, Math.toRadians(5) * (2 * rng.nextDouble() - 1), new double[3]))
                .times(Rigid.rotation(new double[] {0, 1, 0}, Math.toRadians(5) * (2 * rng.nextDouble() - 1), new double[3]));
        return new WorldRobot(nominal.name(), arm, nominal.couplingMatrix(), offsets, List.of(), tool,
                baseFromInstrument.inverse(), null, null, null, null);
    }

    // ---- effects with realistic sizes (joints 0-based here, 1-based in names) ----

    static double uniform(Random r, double lo, double hi) { return lo + (hi - lo) * r.nextDouble(); }

    /** A second tracker beside the cell ({@link WorldRobot.Network}): its place and its registration's error drawn. */
    static WorldRobot.Network network(Random r) {
        double az = 2 * Math.PI * r.nextDouble(), d = uniform(r, 2, 3), w = uniform(r, 40e-6, 90e-6), s = uniform(r, 30e-6, 60e-6);
        double[] u = Arm.gauss(r, 1), v = Arm.gauss(r, 1);
        double nu = Math.sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]), nv = Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        return new WorldRobot.Network(new double[] {d * Math.cos(az), d * Math.sin(az), uniform(r, 0, 1)},
                new double[] {w * u[0] / nu, w * u[1] / nu, w * u[2] / nu}, new double[] {s * v[0] / nv, s * v[1] / nv, s * v[2] / nv});
    }

    /** Drive {@code joint}'s shaft tilting under its mesh's forces ({@link WorldRobot.ShaftTilt}, 20° pressure angle) on masses 30 % off the file's. */
    static UnaryOperator<WorldRobot> shaftTilt(RobotDescription n, Random r, int joint, double radPerNm) {
        var m = WorldRobot.Compliance.fromFile(n.massModel().orElseThrow(), n.dof(), 0.3, r);
        var t = new WorldRobot.ShaftTilt(joint, radPerNm, Math.toRadians(20), 2 * Math.PI * r.nextDouble(), uniform(r, -0.05, 0.05));
        return w -> w.withCompliance(m).withShaftTilt(t);
    }

    /** A cable retractor on a boom beside the cell ({@link WorldRobot.Retractor}): its anchor, pull and the drives' stiffnesses drawn. */
    static WorldRobot.Retractor retractor(Random r, int dof) {
        double az = 2 * Math.PI * r.nextDouble(), d = uniform(r, 1.9, 2.5);
        double[] k = new double[dof];
        for (int j = 0; j < dof; j++) k[j] = j < 3 ? uniform(r, 2e5, 6e5) : uniform(r, 2e4, 6e4);
        return new WorldRobot.Retractor(new double[] {d * Math.cos(az), d * Math.sin(az), uniform(r, 1, 2)}, uniform(r, 30, 50), k);
    }

    static double signed(Random r, double lo, double hi) { return (r.nextBoolean() ? 1 : -1) * uniform(r, lo, hi); }

    /** Adds drive errors to a robot. */
    static UnaryOperator<WorldRobot> add(JointError... e) {
        return w -> {
            List<JointError> all = new ArrayList<>(w.errors());
            all.addAll(List.of(e));
            return w.withErrors(all);
        };
    }

    /**
     * A hose twisted by joint 6 ({@link JointError.HoseTwist}): 0.03–0.06° at a half turn from where
     * it hangs free (within 90° of zero), straight; its stiffness one to two times higher again at a
     * right-angle bend of joint 5.
     */
    static JointError.HoseTwist hoseTwist(Random r) {
        return new JointError.HoseTwist(5, 4, Math.toRadians(uniform(r, 0.03, 0.06)) / Math.PI, Math.toRadians(signed(r, 0, 90)), uniform(r, 1, 2));
    }

    /** Transmission error of a single-stage gear train: harmonics 1..3, 0.004–0.01° each (0.02–0.05° on the wrist), random phases. */
    public static JointError.Harmonics lowHarmonics(int joint, Random r) {
        double lo = joint >= 3 ? 0.02 : 0.004, hi = joint >= 3 ? 0.05 : 0.01;
        return new JointError.Harmonics(joint, new int[] {1, 2, 3},
                new double[] {Math.toRadians(uniform(r, lo, hi)), Math.toRadians(uniform(r, lo, hi)), Math.toRadians(uniform(r, lo, hi))},
                new double[] {2 * Math.PI * r.nextDouble(), 2 * Math.PI * r.nextDouble(), 2 * Math.PI * r.nextDouble()});
    }

    /**
     * Transmission error of a multi-stage or cycloidal reducer: the output's once-per-turn term
     * plus two stage harmonics drawn from 4..40 per output turn, 0.004–0.01° each.
     */
    public static JointError.Harmonics highHarmonics(int joint, Random r) {
        int k1 = 4 + r.nextInt(37);
        int k2;
        do { k2 = 4 + r.nextInt(37); } while (k2 == k1);
        return new JointError.Harmonics(joint, new int[] {1, k1, k2},
                new double[] {Math.toRadians(uniform(r, 0.002, 0.005)), Math.toRadians(uniform(r, 0.004, 0.01)), Math.toRadians(uniform(r, 0.004, 0.01))},
                new double[] {2 * Math.PI * r.nextDouble(), 2 * Math.PI * r.nextDouble(), 2 * Math.PI * r.nextDouble()});
    }

    /** Transmission error at harmonics {@code k}, amplitudes spread over a decade (0.002–0.02° each), random phases. */
    static JointError.Harmonics spreadHarmonics(int joint, int[] k, Random r) {
        double[] a = new double[k.length], ph = new double[k.length];
        for (int i = 0; i < k.length; i++) {
            a[i] = Math.toRadians(0.002 * Math.pow(10, r.nextDouble()));
            ph[i] = 2 * Math.PI * r.nextDouble();
        }
        return new JointError.Harmonics(joint, k, a, ph);
    }

    /**
     * The tracker's stand knocked once, 0.1–0.3 mm and 20–100 µrad about its own origin in random
     * directions, 900–2600 s into the campaign (a quarter to three quarters of the hour 300 poses take).
     */
    static WorldRobot.Knock knock(Random r) {
        return new WorldRobot.Knock(uniform(r, 900, 2600), Rigid.scale(Rigid.unit(Arm.gauss(r, 1)), uniform(r, 0.1e-3, 0.3e-3)),
                Rigid.scale(Rigid.unit(Arm.gauss(r, 1)), uniform(r, 20e-6, 100e-6)));
    }

    /** Lost motion 0.02–0.05°. */
    public static JointError.LostMotion lostMotion(int joint, Random r) {
        return new JointError.LostMotion(joint, Math.toRadians(uniform(r, 0.02, 0.05)));
    }

    /**
     * Lost motion 0.02–0.05° whose output gear (pitch radius 60–120 mm, pressure angle 20°) runs out
     * by enough to change the play by 30–80 % of its width over a turn; its pinion runs true.
     */
    public static JointError.GearPairLostMotion runoutLostMotion(int joint, Random r) {
        double width = Math.toRadians(uniform(r, 0.02, 0.05)), radius = uniform(r, 0.06, 0.12), alpha = Math.toRadians(20);
        double runout = uniform(r, 0.3, 0.8) * width * radius / (2 * Math.tan(alpha));
        double phase = 2 * Math.PI * r.nextDouble();
        int[] z = teeth(r);
        return new JointError.GearPairLostMotion(joint, width, runout, phase, 0, 0, z[0], z[1], radius, alpha);
    }

    /**
     * Tooth counts of a last gear pair, {output gear, pinion}: a pinion of 13–23 teeth driving 3.2–6.8
     * times as many, never a whole ratio (a whole ratio would bring the same teeth into mesh every
     * turn and wear them unevenly).
     */
    private static int[] teeth(Random r) {
        int zp = 13 + r.nextInt(11), zg = (int) Math.round(uniform(r, 3.2, 6.8) * zp);
        return new int[] {zg % zp == 0 ? zg + 1 : zg, zp};
    }

    /**
     * Lost motion 0.02–0.05° of a last gear pair whose pinion (13–23 teeth, driving an output gear
     * 3.2–6.8 times its size, pitch radius 60–120 mm, pressure angle 20°) runs off its centre by
     * enough to change the play by 30–80 % of its width, and, with {@code gearToo}, whose output gear
     * runs off its centre by as much again as the pinion (0.5–1 times); tooth counts of {@link #teeth}.
     */
    public static JointError.GearPairLostMotion gearPairLostMotion(int joint, boolean gearToo, Random r) {
        double width = Math.toRadians(uniform(r, 0.02, 0.05)), radius = uniform(r, 0.06, 0.12), alpha = Math.toRadians(20);
        int[] z = teeth(r);
        double change = uniform(r, 0.3, 0.8) * width;
        double pinion = change, gear = gearToo ? uniform(r, 0.5, 1) * change : 0;
        double scale = gearToo ? 1 / (1 + gear / pinion) : 1; // the two together still change the play by 30–80 %
        double toM = radius / (2 * Math.tan(alpha));
        return new JointError.GearPairLostMotion(joint, width, gear * scale * toM, 2 * Math.PI * r.nextDouble(), pinion * scale * toM,
                2 * Math.PI * r.nextDouble(), z[0], z[1], radius, alpha);
    }

    /** Gear-ratio error ±(1–3)·10⁻⁴. */
    public static JointError.Scale gearRatio(int joint, Random r) { return new JointError.Scale(joint, signed(r, 1e-4, 3e-4)); }

    /** The upper arm's twist: the file's masses ±30 %, a payload centre 0.15-0.25 m off the flange's axis, a stiffness in lo..hi N·m/rad. */
    static WorldRobot.Twist twist(RobotDescription n, double lo, double hi, Random r) {
        var m = WorldRobot.Compliance.fromFile(n.massModel().orElseThrow(), n.dof(), 0.3, r);
        double[] pc = {uniform(r, 0.15, 0.25), signed(r, 0, 0.05), uniform(r, 0.05, 0.1)};
        return new WorldRobot.Twist(uniform(r, lo, hi), m.masses(), pc, m.gravity());
    }

    /** Cross-coupling ±(3–10)·10⁻⁴. */
    public static JointError.Coupling crossCoupling(int joint, int source, Random r) {
        return new JointError.Coupling(joint, source, signed(r, 3e-4, 10e-4));
    }

    /**
     * Thermal growth: each link's own coefficient, 10–24·10⁻⁶/K (steel to cast aluminium), the
     * aluminium target holder at 23·10⁻⁶/K, and, if asked, an instrument drift of 1–3 µm/K in a
     * random direction.
     */
    public static WorldRobot.Thermal thermal(RobotDescription nominal, Random r, boolean drift) {
        double[] a = new double[nominal.dof() + 1];
        for (int i = 0; i < a.length; i++) a[i] = uniform(r, 10e-6, 24e-6);
        double[] d = drift ? Rigid.scale(Rigid.unit(Arm.gauss(r, 1)), uniform(r, 1e-6, 3e-6)) : new double[3];
        return new WorldRobot.Thermal(20, a, d, new double[3], WorldRobot.Thermal.ALUMINIUM_HOLDER_ALPHA);
    }

    /** Joint elasticity on one drive, stiffness 0.5–2·10⁶ N·m/rad, with the file's masses off by up to ±30 % link by link. */
    static UnaryOperator<WorldRobot> elastic(RobotDescription nominal, Random r, int... joints) {
        WorldRobot.Compliance c = WorldRobot.Compliance.fromFile(nominal.massModel().orElseThrow(), nominal.dof(), 0.3, r);
        for (int j : joints) c = c.withStiffness(j, uniform(r, 0.5e6, 2e6));
        WorldRobot.Compliance cc = c;
        return w -> w.withCompliance(cc);
    }

    /** The same elasticity with its springs in the joints' own angles ({@link WorldRobot.Compliance#inJoints}). */
    static UnaryOperator<WorldRobot> inJoints(UnaryOperator<WorldRobot> elastic) {
        return w -> { WorldRobot e = elastic.apply(w); return e.withCompliance(e.compliance().inJoints()); };
    }

    /**
     * A measuring machine out of square ({@link WorldRobot.Machine}): each squareness 50-150 µrad and
     * the x and y scales 20-60 ppm off z's, random signs, the x-way bowed 20-60 µm in y and z over a
     * travel of ±1.5 m about the robot's base.
     */
    static UnaryOperator<WorldRobot> machine(Random r) {
        double gxy = signed(r, 50e-6, 150e-6), gxz = signed(r, 50e-6, 150e-6), gyz = signed(r, 50e-6, 150e-6);
        double sx = signed(r, 20e-6, 60e-6), sy = signed(r, 20e-6, 60e-6), by = signed(r, 20e-6, 60e-6), bz = signed(r, 20e-6, 60e-6);
        return w -> w.withMachine(new WorldRobot.Machine(gxy, gxz, gyz, sx, sy, by, bz, w.instrumentFromBase().p()[0], 1.5));
    }

    private static UnaryOperator<Campaign.Plan> same() { return p -> p; }

    private static Scenario s(String name, String family, String robot, Expected e,
                              BiFunction<RobotDescription, Random, UnaryOperator<WorldRobot>> effects, UnaryOperator<Campaign.Plan> plan) {
        return new Scenario(name, family, robot, e, effects, plan);
    }

    /** Rated payload steps of a robot (0, half, full; 10 kg when the file gives none). */
    static UnaryOperator<Campaign.Plan> payloads(String robot) {
        double rated = RobotLibrary.shipped(robot).massModel().map(m -> m.ratedPayloadKg()).filter(v -> v > 0).orElse(5.0);
        return p -> p.withPayloads(0, rated / 2, rated);
    }

    /** The catalogue: every family alone and in pairs, outside cases, nulls, on every shipped robot, sparse, noisy and 6-D campaigns. */
    public static List<Scenario> catalogue() {
        List<Scenario> c = new ArrayList<>();
        // nothing to find
        c.add(s("null irb2000", "null", "irb2000", Expected.none(), (n, r) -> w -> w, same()));
        c.add(s("null irb2000, sigma 0.05 mm", "null", "irb2000", Expected.none(), (n, r) -> w -> w, p -> p.withSigma(0.05e-3)));
        c.add(s("null irb2000, 50 poses", "null", "irb2000", Expected.none(), (n, r) -> w -> w, p -> p.withPoses(50, 50)));
        c.add(s("null irb2000, 6-D", "null", "irb2000", Expected.none(), (n, r) -> w -> w, p -> p.withSixD(true)));
        c.add(s("null irb2000, payload steps", "null", "irb2000", Expected.none(), (n, r) -> w -> w, payloads("irb2000")));
        c.add(s("null irb2000, 5 gross outliers", "null", "irb2000", Expected.none(), (n, r) -> w -> w, p -> p.withOutliers(5)));
        c.add(s("null irb2400", "null", "irb2400", Expected.none(), (n, r) -> w -> w, same()));
        c.add(s("null puma560", "null", "puma560", Expected.none(), (n, r) -> w -> w, same()));
        // transmission error
        c.add(s("transmission error j1, k 1-3", "transmission-error", "irb2000", Expected.named(claim(TRANSMISSION_ERROR, 1)),
                (n, r) -> add(lowHarmonics(0, r)), same()));
        c.add(s("transmission error j2, k 1-3", "transmission-error", "irb2000", Expected.named(claim(TRANSMISSION_ERROR, 2)),
                (n, r) -> add(lowHarmonics(1, r)), same()));
        c.add(s("transmission error j5 (wrist), k 1-3", "transmission-error", "irb2000", Expected.named(claim(TRANSMISSION_ERROR, 5)),
                (n, r) -> add(lowHarmonics(4, r)), same()));
        c.add(s("transmission error j1, cycloidal k up to 40", "transmission-error", "irb2000", Expected.named(claim(TRANSMISSION_ERROR, 1)),
                (n, r) -> add(highHarmonics(0, r)), same()));
        c.add(s("transmission error j3, cycloidal k up to 40", "transmission-error", "irb2000", Expected.named(claim(TRANSMISSION_ERROR, 3)),
                (n, r) -> add(highHarmonics(2, r)), same()));
        c.add(s("transmission error j2 puma560, k 1-3", "transmission-error", "puma560", Expected.named(claim(TRANSMISSION_ERROR, 2)),
                (n, r) -> add(lowHarmonics(1, r)), same()));
        // lost motion
        c.add(s("lost motion j1, directions recorded", "lost-motion", "irb2000", Expected.named(claim(LOST_MOTION, 1)),
                (n, r) -> add(lostMotion(0, r)), same()));
        c.add(s("lost motion j2, directions recorded", "lost-motion", "irb2000", Expected.named(claim(LOST_MOTION, 2)),
                (n, r) -> add(lostMotion(1, r)), same()));
        c.add(s("lost motion j2, directions not recorded", "lost-motion", "irb2000", Expected.named(claim(LOST_MOTION, 2)),
                (n, r) -> add(lostMotion(1, r)), p -> p.withDirColumns(false)));
        c.add(s("lost motion j3, random order, directions recorded", "lost-motion", "irb2000", Expected.named(claim(LOST_MOTION, 3)),
                (n, r) -> add(lostMotion(2, r)), p -> p.withOrder(Campaign.Order.AS_DRAWN)));
        c.add(s("lost motion j1 irb2400, directions recorded", "lost-motion", "irb2400", Expected.named(claim(LOST_MOTION, 1)),
                (n, r) -> add(lostMotion(0, r)), same()));
        // thermal growth
        c.add(s("thermal growth per link", "thermal-growth", "irb2000", Expected.named(claim(THERMAL_GROWTH)),
                (n, r) -> { var t = thermal(n, r, false); return w -> w.withThermal(t); }, same()));
        c.add(s("thermal growth per link + instrument drift", "thermal-growth", "irb2000", Expected.named(claim(THERMAL_GROWTH)),
                (n, r) -> { var t = thermal(n, r, true); return w -> w.withThermal(t); }, same()));
        c.add(s("instrument drift with time", "thermal-growth", "irb2000", Expected.named(claim(THERMAL_GROWTH)),
                (n, r) -> {
                    var t = driftPerMinute(n, r, 0.5e-6, 1e-6);
                    return w -> w.withThermal(t);
                }, same()));
        // gravity elasticity
        c.add(s("joint elasticity j2, masses off 30 %", "gravity-elasticity", "irb2000", Expected.named(claim(GRAVITY_ELASTICITY, 2)),
                (n, r) -> elastic(n, r, 1), payloads("irb2000")));
        c.add(s("joint elasticity j3, masses off 30 %", "gravity-elasticity", "irb2000", Expected.named(claim(GRAVITY_ELASTICITY, 3)),
                (n, r) -> elastic(n, r, 2), payloads("irb2000")));
        c.add(s("joint elasticity j2 puma560, masses off 30 %", "gravity-elasticity", "puma560", Expected.named(claim(GRAVITY_ELASTICITY, 2)),
                (n, r) -> elastic(n, r, 1), same()));
        c.add(s("joint elasticity j2 in the joint's own angle, masses off 30 %", "gravity-elasticity", "irb2000",
                Expected.named(claim(GRAVITY_ELASTICITY, 2)), (n, r) -> inJoints(elastic(n, r, 1)), payloads("irb2000")));
        c.add(s("joint elasticity j2 + j3 in the joints' own angles, masses off 30 %", "pair", "irb2000",
                Expected.named(claim(GRAVITY_ELASTICITY, 2), claim(GRAVITY_ELASTICITY, 3)), (n, r) -> inJoints(elastic(n, r, 1, 2)), payloads("irb2000")));
        c.add(s("joint elasticity j2 + j3, masses off 30 %", "pair", "irb2000",
                Expected.named(claim(GRAVITY_ELASTICITY, 2), claim(GRAVITY_ELASTICITY, 3)), (n, r) -> elastic(n, r, 1, 2), payloads("irb2000")));
        // gear ratio, coupling
        c.add(s("gear-ratio error j1", "gear-ratio", "irb2000", Expected.named(claim(GEAR_RATIO, 1)), (n, r) -> add(gearRatio(0, r)), same()));
        c.add(s("gear-ratio error j2", "gear-ratio", "irb2000", Expected.named(claim(GEAR_RATIO, 2)), (n, r) -> add(gearRatio(1, r)), same()));
        c.add(s("cross-coupling j3<-j2", "cross-coupling", "irb2000", Expected.named(claim(CROSS_COUPLING, 3, 2)),
                (n, r) -> add(crossCoupling(2, 1, r)), same()));
        // pairs
        c.add(s("lost motion j2 + thermal growth per link", "pair", "irb2000", Expected.named(claim(LOST_MOTION, 2), claim(THERMAL_GROWTH)),
                (n, r) -> { var t = thermal(n, r, false); var b = lostMotion(1, r); return w -> add(b).apply(w.withThermal(t)); }, same()));
        c.add(s("transmission error j1 + gear-ratio j3", "pair", "irb2000",
                Expected.named(claim(TRANSMISSION_ERROR, 1), claim(GEAR_RATIO, 3)),
                (n, r) -> add(lowHarmonics(0, r), gearRatio(2, r)), same()));
        c.add(s("lost motion j1 + cross-coupling j3<-j2, directions not recorded", "pair", "irb2000",
                Expected.named(claim(LOST_MOTION, 1), claim(CROSS_COUPLING, 3, 2)),
                (n, r) -> add(lostMotion(0, r), crossCoupling(2, 1, r)), p -> p.withDirColumns(false)));
        c.add(s("joint elasticity j2 + transmission error j1, masses off 30 %", "pair", "irb2000",
                Expected.named(claim(GRAVITY_ELASTICITY, 2), claim(TRANSMISSION_ERROR, 1)),
                (n, r) -> { var e = elastic(n, r, 1); var h = lowHarmonics(0, r); return w -> add(h).apply(e.apply(w)); }, payloads("irb2000")));
        // sparse, noisy and 6-D campaigns with an effect
        c.add(s("lost motion j1, 4 gross outliers", "lost-motion", "irb2000", Expected.named(claim(LOST_MOTION, 1)),
                (n, r) -> add(lostMotion(0, r)), p -> p.withOutliers(4)));
        c.add(s("lost motion j2, 50 poses", "lost-motion", "irb2000", Expected.named(claim(LOST_MOTION, 2)),
                (n, r) -> add(lostMotion(1, r)), p -> p.withPoses(50, 50)));
        c.add(s("transmission error j1, sigma 0.05 mm", "transmission-error", "irb2000", Expected.named(claim(TRANSMISSION_ERROR, 1)),
                (n, r) -> add(lowHarmonics(0, r)), p -> p.withSigma(0.05e-3)));
        c.add(s("gear-ratio error j2, 6-D", "gear-ratio", "irb2000", Expected.named(claim(GEAR_RATIO, 2)),
                (n, r) -> add(gearRatio(1, r)), p -> p.withSixD(true)));
        // outside every family: must be located, never named
        c.add(s("outside: bump in the angle of j3", "outside", "irb2000", Expected.outside(), Scenario::bumpJ3, same()));
        c.add(s("outside: j2 error depending on j2 and j4", "outside", "irb2000", Expected.outside(),
                (n, r) -> add(new JointError.TwoJoint(1, 3, Math.toRadians(signed(r, 0.01, 0.02)))), same()));
        c.add(s("outside: bump in the angle of j2 puma560", "outside", "puma560", Expected.outside(),
                (n, r) -> add(new JointError.Bump(1, Math.toRadians(uniform(r, 20, 160)), Math.toRadians(uniform(r, 10, 20)),
                        Math.toRadians(signed(r, 0.02, 0.04)))), same()));
        // a parallel arm's rod 40-80 µm longer or shorter than the upper arm's pivot distance (crank 250-320 mm, the crank at
        // 85-95 deg to the upper arm where θ3 = 0, the lever within 20 µm of the crank); the poses keep θ3 = q3 − q2 within
        // joint 3's limits, as the linkage does (the crank then stays 25-35 deg or more away from the upper arm)
        for (String robot : List.of("irb2000", "irb2400"))
            c.add(s("outside: parallel-arm rod off its length, " + robot, "outside", robot, Expected.outside(), (n, r) -> {
                double ground = Math.abs(n.joints().get(2).point().z() - n.joints().get(1).point().z()), crank = uniform(r, 0.25, 0.32);
                return add(new JointError.LinkageRod(2, 1, ground, crank, crank + signed(r, 0, 20e-6), ground + signed(r, 40e-6, 80e-6),
                        Math.toRadians(uniform(r, 85, 95))));
            }, p -> p.withLinkageRange(true)));
        // a motor's resolver 8-20 arc-minutes off once per motor turn, 0.3-0.7 of that twice, behind a gear ratio of 60-110
        // (whole or not); alone, and beside a gear-ratio error of another joint, whose residual hides the motor's lines at first
        c.add(s("outside: motor resolver error of j3 at its gear ratio", "outside", "irb2000", Expected.outside(),
                (n, r) -> add(motorSensor(2, r)), same()));
        c.add(s("motor resolver error of j3 at its gear ratio (outside) + gear-ratio error j1", "pair", "irb2000",
                Expected.named(claim(GEAR_RATIO, 1)), (n, r) -> add(motorSensor(2, r), gearRatio(0, r)), same()));
        // joints read as whole counts: the PUMA 560's 1000-count motor encoders behind its published gear ratios (Armstrong,
        // Khatib & Burdick 1986: 62.61, 107.36, 53.69, 76.01, 71.91, 76.73), and an arm's 10-bit resolver converters behind
        // ratios of 60-130
        c.add(s("outside: joint angles read as whole counts of 1000-count motor encoders, puma560, sigma 0.01 mm", "outside", "puma560",
                Expected.outside(), (n, r) -> counts(1000, new double[] {62.61, 107.36, 53.69, 76.01, 71.91, 76.73}), p -> p.withSigma(0.01e-3)));
        c.add(s("outside: joint angles read as whole counts of 10-bit resolver converters, sigma 0.01 mm", "outside", "irb2400",
                Expected.outside(), (n, r) -> {
                    double[] ratio = new double[6];
                    for (int j = 0; j < 6; j++) ratio[j] = uniform(r, 60, 130);
                    return counts(1024, ratio);
                }, p -> p.withSigma(0.01e-3)));
        c.add(s("outside: measured point sags with reach", "outside", "irb2000", Expected.outside(),
                (n, r) -> { var sag = new WorldRobot.Sag(uniform(r, 0.1e-3, 0.2e-3), 1.5); return w -> w.withSag(sag); }, same()));
        heldOutStyle(c);
        oneSided(c);
        openWorldForms(c);
        return c;
    }

    /**
     * Campaigns a careful calibration engineer measures: every pose approached from one side (an
     * approach pose short of it, then a short move onto it), so that the play is always taken up
     * the same way. A constant lost motion is then the same at every pose and the zero offsets take
     * it whole: nothing about it can be told, and nothing may be claimed. Where a minority of the
     * poses is approached from the other side the lost motion shows again. A friction wind-up's lag
     * follows the drive's motion since it last turned: the approach move where the drive turned
     * round at the approach pose (its length is in the program, not in the file), the whole travel
     * where it came from the approach's side. So even a fixed approach length does not take a
     * wind-up out of the data.
     */
    private static void oneSided(List<Scenario> c) {
        double two = Math.toRadians(2);
        c.add(s("lost motion j2, every pose approached from above (cannot be told)", ONE_SIDED, "irb2000", Expected.none(),
                (n, r) -> add(lostMotion(1, r)), p -> p.withApproach(Campaign.Approach.all(6, 1, two, two, 0))));
        c.add(s("lost motion j2, j2 approached from above, a fifth of the poses from below", ONE_SIDED, "irb2000",
                Expected.named(claim(LOST_MOTION, 2)), (n, r) -> add(lostMotion(1, r)),
                p -> p.withApproach(new Campaign.Approach(new int[] {0, 1, 0, 0, 0, 0}, two, two, 0.2))));
        c.add(s("lost motion j3 building up over the move, approached by 0.5-10 deg from above, a fifth from below", ONE_SIDED,
                "irb2000", Expected.named(claim(LOST_MOTION, 3)),
                (n, r) -> add(new JointError.WindUpLostMotion(2, Math.toRadians(uniform(r, 0.03, 0.06)), Math.toRadians(uniform(r, 3, 10)))),
                p -> p.withApproach(Campaign.Approach.all(6, 1, Math.toRadians(0.5), Math.toRadians(10), 0.2))));
        c.add(s("lost motion j3 building up over the move, every pose approached by 2 deg from above", ONE_SIDED,
                "irb2000", Expected.named(claim(LOST_MOTION, 3)),
                (n, r) -> add(new JointError.WindUpLostMotion(2, Math.toRadians(uniform(r, 0.03, 0.06)), Math.toRadians(uniform(r, 3, 10)))),
                p -> p.withApproach(Campaign.Approach.all(6, 1, Math.toRadians(2), Math.toRadians(2), 0))));
    }

    /**
     * Truths formed differently from the catalogue's, and more structures outside every family, so
     * that the benchmark can prove the estimator wrong in ways its first scenarios did not try:
     * lost motion that is asymmetric or builds up with the move, a campaign that starts away from
     * home, harmonics of spread amplitudes on two joints, a joint zero that slips, creeps or moves
     * with temperature, link bending under payload, a target knocked mid-campaign, and 6-D and
     * 50-pose versions of outside cases.
     */
    private static void heldOutStyle(List<Scenario> c) {
        c.add(s("lost motion j2, unequal flanks (gravity preload)", "lost-motion", "irb2000", Expected.named(claim(LOST_MOTION, 2)),
                (n, r) -> {
                    double up = Math.toRadians(uniform(r, 0.02, 0.05));
                    return add(new JointError.AsymmetricLostMotion(1, up, up * uniform(r, 0.3, 0.7)));
                }, same()));
        c.add(s("lost motion j2 whose play changes over the turn (output gear runout)", "lost-motion", "irb2000",
                Expected.named(claim(LOST_MOTION, 2)), (n, r) -> add(runoutLostMotion(1, r)), same()));
        c.add(s("lost motion j1 irb2400 whose play changes over the turn (output gear runout), directions not recorded",
                "lost-motion", "irb2400", Expected.named(claim(LOST_MOTION, 1)), (n, r) -> add(runoutLostMotion(0, r)),
                p -> p.withDirColumns(false)));
        c.add(s("lost motion j3 whose play changes with its pinion's turn (eccentric pinion)", "lost-motion", "irb2000",
                Expected.named(claim(LOST_MOTION, 3)), (n, r) -> add(gearPairLostMotion(2, false, r)), same()));
        c.add(s("lost motion j1 puma560 whose play changes with its pinion's turn (eccentric pinion), directions not recorded",
                "lost-motion", "puma560", Expected.named(claim(LOST_MOTION, 1)), (n, r) -> add(gearPairLostMotion(0, false, r)),
                p -> p.withDirColumns(false)));
        c.add(s("lost motion j2 whose play changes with its output gear's and its pinion's turn (both eccentric)", "lost-motion",
                "irb2000", Expected.named(claim(LOST_MOTION, 2)), (n, r) -> add(gearPairLostMotion(1, true, r)), same()));
        c.add(s("lost motion j3 building up over the move (friction wind-up)", "lost-motion", "irb2000", Expected.named(claim(LOST_MOTION, 3)),
                (n, r) -> add(new JointError.WindUpLostMotion(2, Math.toRadians(uniform(r, 0.03, 0.06)), Math.toRadians(uniform(r, 3, 10)))),
                same()));
        c.add(s("lost motion j2, directions not recorded, started away from home", "lost-motion", "irb2000",
                Expected.named(claim(LOST_MOTION, 2)), (n, r) -> add(lostMotion(1, r)),
                p -> p.withDirColumns(false).withStart(Campaign.Start.ELSEWHERE)));
        c.add(s("lost motion j1, directions not recorded, two joints moved per pose", "lost-motion", "irb2000",
                Expected.named(claim(LOST_MOTION, 1)), (n, r) -> add(lostMotion(0, r)), p -> p.withDirColumns(false).withMovedJoints(2)));
        c.add(s("lost motion j3, directions not recorded (drive 3 behind the parallel linkage)", "lost-motion", "irb2000",
                Expected.named(claim(LOST_MOTION, 3)), (n, r) -> add(lostMotion(2, r)), p -> p.withDirColumns(false)));
        c.add(s("lost motion j2 irb2400, directions not recorded", "lost-motion", "irb2400",
                Expected.named(claim(LOST_MOTION, 2)), (n, r) -> add(lostMotion(1, r)), p -> p.withDirColumns(false)));
        c.add(s("transmission error j1 and j3 at once, amplitudes 0.002-0.02 deg", "pair", "irb2000",
                Expected.named(claim(TRANSMISSION_ERROR, 1), claim(TRANSMISSION_ERROR, 3)),
                (n, r) -> {
                    var h1 = spreadHarmonics(0, new int[] {1, 2, 3}, r);
                    var h3 = spreadHarmonics(2, new int[] {1, 4 + r.nextInt(37)}, r);
                    return add(h1, h3);
                }, same()));
        c.add(s("outside: encoder slip on j2 mid-campaign", "outside", "irb2000", Expected.outside(),
                (n, r) -> add(new JointError.Slip(1, uniform(r, 1000, 2500), Math.toRadians(signed(r, 0.01, 0.03)))), same()));
        c.add(s("outside: j3 zero creeping with time", "outside", "irb2000", Expected.outside(),
                (n, r) -> add(new JointError.Creep(2, Math.toRadians(signed(r, 0.02, 0.04)) / 3600)), same()));
        c.add(s("outside: j2 zero moving with drive temperature", "outside", "irb2000", Expected.outside(),
                (n, r) -> add(new JointError.DriveThermal(1, Math.toRadians(signed(r, 0.002, 0.004)), 20)), same()));
        c.add(s("outside: zeros of drives 1-3 drift as their motors warm, 6-D", "outside", "irb2000", Expected.outside(),
                (n, r) -> add(new JointError.MotorWarm(0, Math.toRadians(signed(r, 0.008, 0.02)), uniform(r, 600, 3000)),
                        new JointError.MotorWarm(1, Math.toRadians(signed(r, 0.008, 0.02)), uniform(r, 600, 3000)),
                        new JointError.MotorWarm(2, Math.toRadians(signed(r, 0.008, 0.02)), uniform(r, 600, 3000))),
                p -> p.withSixD(true)));
        c.add(s("outside: gas-spring balancer bends joint 2", "outside", "irb2000", Expected.outside(),
                (n, r) -> {
                    double arm = uniform(r, 0.12, 0.18), anchor = uniform(r, 0.30, 0.40), phi0 = Math.toRadians(90 + signed(r, 0, 20));
                    double l0 = Math.sqrt(arm * arm + anchor * anchor - 2 * arm * anchor * Math.cos(phi0));
                    // a force of 2-4 kN at q = 0, the dead length a third of the spring's shortest
                    double dead = (anchor - arm) / 3;
                    return add(new JointError.GasSpring(1, arm, anchor, phi0, uniform(r, 2000, 4000), dead, 1.3, uniform(r, 0.8e6, 2e6)));
                }, same()));
        c.add(s("outside: the floor tilts as it warms", "outside", "irb2000", Expected.outside(),
                (n, r) -> {
                    double psi = uniform(r, 0, 2 * Math.PI), d = uniform(r, 0.3, 0.8), at = uniform(r, 0, 2 * Math.PI);
                    var tilt = new WorldRobot.FloorTilt(psi, new double[] {d * Math.cos(at), d * Math.sin(at), 0},
                            signed(r, 100e-6, 200e-6), uniform(r, 1200, 3000));
                    return w -> w.withFloorTilt(tilt);
                }, same()));
        c.add(s("outside: arm bends with payload and reach", "outside", "irb2000", Expected.outside(),
                (n, r) -> {
                    double rated = RobotLibrary.shipped("irb2000").massModel().map(m -> m.ratedPayloadKg()).filter(v -> v > 0).orElse(5.0);
                    var sag = new WorldRobot.Sag(0, 1.5, uniform(r, 0.1e-3, 0.2e-3) / rated);
                    return w -> w.withSag(sag);
                }, payloads("irb2000")));
        c.add(s("outside: measured target knocked mid-campaign", "outside", "irb2000", Expected.outside(),
                (n, r) -> {
                    var b = new WorldRobot.ToolBump(uniform(r, 1000, 2500), Rigid.scale(Rigid.unit(Arm.gauss(r, 1)), uniform(r, 0.1e-3, 0.3e-3)),
                            Arm.gauss(r, Math.toRadians(0.05)));
                    return w -> w.withToolBump(b);
                }, same()));
        c.add(s("outside: bump in the angle of j3, 6-D", "outside", "irb2000", Expected.outside(), Scenario::bumpJ3, p -> p.withSixD(true)));
        c.add(s("outside: bump in the angle of j3, 50 poses", "outside", "irb2000", Expected.outside(), Scenario::bumpJ3,
                p -> p.withPoses(50, 50)));
        c.add(s("outside: j2 error depending on j2 and j4, 6-D", "outside", "irb2000", Expected.outside(),
                (n, r) -> add(new JointError.TwoJoint(1, 3, Math.toRadians(signed(r, 0.01, 0.02)))), p -> p.withSixD(true)));
        c.add(s("outside: measured point sags with reach, 50 poses", "outside", "irb2000", Expected.outside(),
                (n, r) -> { var sag = new WorldRobot.Sag(uniform(r, 0.1e-3, 0.2e-3), 1.5); return w -> w.withSag(sag); },
                p -> p.withPoses(50, 50)));
        // a hose twisted by joint 6 of the IRB 2400 (±400 deg), stiffer as joint 5 bends: 0.03-0.06 deg at a half turn from
        // where it hangs free, straight; measured at a target 80 mm off joint 6's axis (a torch's tip), or on the axis in 6-D
        c.add(new Scenario("outside: hose twisted by j6, stiffer as the wrist bends, target off joint 6's axis", "outside", "irb2400",
                Expected.outside(), (n, r) -> add(hoseTwist(r)), same(), new double[] {0.08, 0, 0.1}));
        c.add(s("outside: hose twisted by j6, stiffer as the wrist bends, 6-D", "outside", "irb2400", Expected.outside(),
                (n, r) -> add(hoseTwist(r)), p -> p.withSixD(true)));
        // the arm read about a second after each stop, still ringing at 7-9 Hz (ζ 0.03-0.05) from the braking of its
        // acceleration-limited moves; on the PUMA, whose file gives no joint speeds
        c.add(s("outside: arm read before it settled", "outside", "irb2000", Expected.outside(), (n, r) -> add(settling(r)), same()));
        c.add(s("outside: arm read before it settled, no joint speeds in the robot file", "outside", "puma560", Expected.outside(),
                (n, r) -> add(settling(r)), same()));
    }

    /** One structural mode ringing on drives 1-3 after acceleration-limited moves (rad/s²: 1.5-3 for the arm, 5-9 for the wrist). */
    private static JointError[] settling(Random r) {
        double hz = uniform(r, 7, 9), zeta = uniform(r, 0.03, 0.05), dwell = uniform(r, 0.9, 1.1);
        double[] accel = new double[6];
        for (int k = 0; k < 6; k++) accel[k] = k < 3 ? uniform(r, 1.5, 3) : uniform(r, 5, 9);
        JointError[] out = new JointError[3];
        for (int j = 0; j < 3; j++) out[j] = new JointError.Settling(j, hz, zeta, dwell, 0, accel);
        return out;
    }

    /**
     * Forms a clean-room simulator written outside the project measured and this world did not
     * have: the laser tracker's own errors (its distance meter's cyclic error, its azimuth
     * encoder's once- and twice-per-turn error), the base rocking on its foundation above an
     * overturning moment, a dress pack pulling on the wrist, a bearing whose axis wobbles at a
     * ratio of the joint's angle, a target slipping once in a sparse campaign; and, named, a
     * stiffening joint spring and lost motion held on one flank by gravity beside a wrist coupling.
     * Sizes: visible after a geometric calibration at σ 0.02 mm, not gross.
     */
    private static void openWorldForms(List<Scenario> c) {
        c.add(s("outside: tracker distance-meter cyclic error", "outside", "irb2000", Expected.outside(),
                (n, r) -> { var t = tracker(r, true, false, false); return w -> w.withTracker(t); }, same()));
        // a meter resolving its phase on 1-3 GHz modulations: a fine period of 0.1-0.3 m (half the wavelength) with its second and
        // fourth overtones, 10-20 µm each, measured at 5 µm
        c.add(s("outside: tracker distance-meter cyclic error with overtones, sigma 0.005", "outside", "irb2000", Expected.outside(),
                (n, r) -> {
                    var t = new WorldRobot.Tracker(uniform(r, 10e-6, 20e-6), uniform(r, 0.1, 0.3), 2 * Math.PI * r.nextDouble(), 0,
                            new int[0], new double[0], new double[0], new int[0], new double[0], new double[0])
                            .withCyclicOvertones(new double[] {uniform(r, 10e-6, 20e-6), 0, uniform(r, 10e-6, 20e-6)},
                                    new double[] {2 * Math.PI * r.nextDouble(), 0, 2 * Math.PI * r.nextDouble()});
                    return w -> w.withTracker(t);
                }, p -> p.withSigma(0.005e-3)));
        c.add(s("outside: tracker azimuth encoder error", "outside", "irb2000", Expected.outside(),
                (n, r) -> { var t = tracker(r, false, false, true); return w -> w.withTracker(t); }, same()));
        c.add(s("outside: tracker distance and azimuth errors", "outside", "irb2000", Expected.outside(),
                (n, r) -> { var t = tracker(r, true, true, true); return w -> w.withTracker(t); }, same()));
        // the air the beam crosses warms 12-20 K against the reading of the tracker's weather station (a station shaded or in a draft
        // while lamps, the sun or a furnace warm the hall)
        c.add(s("outside: the tracker's air compensation drifts as the hall warms", "outside", "irb2000", Expected.outside(),
                (n, r) -> {
                    var t = tracker(r, false, false, false).withAirWarming(uniform(r, 12, 20), uniform(r, 1200, 2400));
                    return w -> w.withTracker(t);
                }, same()));
        c.add(s("outside: the tracker's distance taken again at every beam break, sigma 0.005 mm", "outside", "irb2400", Expected.outside(),
                (n, r) -> {
                    var t = beamBreaks(tracker(r, false, false, false), 300, 900, r);
                    return w -> w.withTracker(t);
                }, p -> p.withSigma(0.005e-3)));
        c.add(s("instrument drift with time + the tracker's distance taken again at beam breaks, sigma 0.005 mm", "thermal-growth", "irb2400",
                Expected.named(claim(THERMAL_GROWTH)),
                (n, r) -> {
                    // a tracker settling on its stand as it warms: 1-2 µm per minute; the arm crossing the beam now and then
                    var th = driftPerMinute(n, r, 1e-6, 2e-6);
                    var t = beamBreaks(tracker(r, false, false, false), 600, 1500, r);
                    return w -> w.withThermal(th).withTracker(t);
                }, p -> p.withSigma(0.005e-3)));
        c.add(s("outside: base rocks on its foundation above an overturning moment", "outside", "irb2000", Expected.outside(),
                (n, r) -> {
                    // The file's arm weighs 86 kg (±30 %) and tips a 0.25-0.35 m foot edge by at most about 500 N·m with 10 kg:
                    // anchors loosened to a hold of 50-150 N·m, and a rotational stiffness of 2-5·10⁶ N·m/rad above it (a base on a
                    // levelling pad with slack bolts), tilt the base by up to about 2·10⁻⁴ rad, a few tenths of a mm at 2 m.
                    var m = WorldRobot.Compliance.fromFile(n.massModel().orElseThrow(), n.dof(), 0.3, r);
                    var rock = new WorldRobot.Rocking(uniform(r, 0.25, 0.35), uniform(r, 50, 150), uniform(r, 2e6, 5e6), m.masses(),
                            m.payloadCentre(), m.gravity());
                    return w -> w.withRocking(rock);
                }, payloads("irb2000")));
        c.add(s("outside: base rocks on its foundation above an overturning moment, puma560, payload steps", "outside", "puma560",
                Expected.outside(), (n, r) -> {
                    // The PUMA 560's arm (±30 %) and up to 5 kg on a 0.1-0.15 m foot: a hold of 2-10 N·m and 1.5-3·10⁵ N·m/rad
                    // above it (a light arm on a small plate with its bolts slack) tilt the base by up to about 10⁻⁴ rad.
                    var m = WorldRobot.Compliance.fromFile(n.massModel().orElseThrow(), n.dof(), 0.3, r);
                    var rock = new WorldRobot.Rocking(uniform(r, 0.1, 0.15), uniform(r, 2, 10), uniform(r, 1.5e5, 3e5), m.masses(),
                            m.payloadCentre(), m.gravity());
                    return w -> w.withRocking(rock);
                }, payloads("puma560")));
        c.add(s("outside: a pedestal's foot rocks on the floor above an overturning moment", "outside", "irb2000", Expected.outside(),
                (n, r) -> {
                    // The robot bolted on a rigid steel pedestal 0.4-0.8 m tall whose foot plate (0.3-0.4 m half-width) sits on
                    // slack anchors: the same hold and stiffness as a rocking base plate, but the robot turns about the foot's edge
                    // on the floor, so its base also slides toward the lean by the tilt times the pedestal's height.
                    var m = WorldRobot.Compliance.fromFile(n.massModel().orElseThrow(), n.dof(), 0.3, r);
                    var rock = new WorldRobot.Rocking(uniform(r, 0.3, 0.4), uniform(r, 50, 150), uniform(r, 2e6, 5e6), m.masses(),
                            m.payloadCentre(), m.gravity(), uniform(r, 0.4, 0.8));
                    return w -> w.withRocking(rock);
                }, payloads("irb2000")));
        c.add(s("outside: dress-pack drag on the wrist", "outside", "irb2000", Expected.outside(),
                (n, r) -> {
                    var d = new WorldRobot.DressPack(uniform(r, 0.08, 0.12), Math.toRadians(uniform(r, 60, 120)), uniform(r, 0.5, 1.0), 0,
                            uniform(r, 150, 300), new double[] {uniform(r, 1e4, 3e4), uniform(r, 1e4, 3e4), uniform(r, 1e4, 3e4)});
                    return w -> w.withDressPack(d);
                }, same()));
        c.add(s("outside: bearing wobble of j3 at twice its angle", "outside", "irb2000", Expected.outside(),
                (n, r) -> { var wb = wobble(2, 2, r); return w -> w.withWobbles(List.of(wb)); }, same()));
        c.add(s("outside: bearing wobble of j1 at 0.38 times its angle, 3 gross outliers", "outside", "irb2000", Expected.outside(),
                (n, r) -> { var wb = wobble(0, 0.38, r); return w -> w.withWobbles(List.of(wb)); }, p -> p.withOutliers(3)));
        // a race's face ground in two or three lobes, 0.05-0.1 mm: the arm beyond joint 1 (the IRB 2000) or joint 2 (the PUMA
        // 560, beside a lost motion of joint 3) rides up and down along the axis as the joint turns
        c.add(s("outside: joint 1's bearing runs out along its axis", "outside", "irb2000", Expected.outside(),
                (n, r) -> { var wb = axialRunout(0, r); return w -> w.withWobbles(List.of(wb)); }, same()));
        // a reflector's ball in a nest with 0.1-0.2 mm of radial clearance, rolling once the tool leans 5-15 deg
        c.add(s("outside: the target rolls within its nest's clearance toward gravity", "outside", "irb2000", Expected.outside(),
                (n, r) -> { var tp = new WorldRobot.TargetPlay(uniform(r, 0.1e-3, 0.2e-3), Math.toRadians(uniform(r, 5, 15)));
                    return w -> w.withTargetPlay(tp); }, same()));
        c.add(s("outside: the instrument is knocked once during the campaign", "outside", "irb2000", Expected.outside(), (n, r) -> {
                    var k = knock(r);
                    return w -> w.withKnock(k);
                }, same()));
        c.add(s("the instrument is knocked once (outside) + transmission error j1 puma560", "pair", "puma560",
                Expected.named(claim(TRANSMISSION_ERROR, 1)), (n, r) -> {
                    var k = knock(r);
                    var te = lowHarmonics(0, r);
                    return w -> add(te).apply(w).withKnock(k);
                }, same()));
        // a flange on a worn bearing pair (some 30-60 µm of radial clearance over a 30-40 mm span) tipping by 0.5-1.5 mrad
        // toward gravity about a point 20-45 mm inside it, measured in 6-D: the target's position and the flange's turn
        c.add(s("outside: the flange tips within its worn bearing's clearance toward gravity, 6-D", "outside", "irb2000",
                Expected.outside(), (n, r) -> { var tp = new WorldRobot.TargetPlay(0, Math.toRadians(uniform(r, 5, 15)), uniform(r, 0.5e-3, 1.5e-3),
                        uniform(r, 0.02, 0.045));
                    return w -> w.withTargetPlay(tp); }, p -> p.withSixD(true)));
        c.add(s("joint 2's bearing runs out along its axis (outside) + lost motion j3 puma560", "pair", "puma560",
                Expected.named(claim(LOST_MOTION, 3)),
                (n, r) -> { var wb = axialRunout(1, r); var lm = lostMotion(2, r); return w -> add(lm).apply(w).withWobbles(List.of(wb)); },
                same()));
        c.add(s("outside: measured target slips mid-campaign, 60 poses", "outside", "irb2000", Expected.outside(),
                (n, r) -> {
                    // 120 poses take about 30 minutes: the slip comes between 9 and 21 minutes in
                    var b = new WorldRobot.ToolBump(uniform(r, 540, 1260), Rigid.scale(Rigid.unit(Arm.gauss(r, 1)), uniform(r, 0.1e-3, 0.3e-3)),
                            Arm.gauss(r, Math.toRadians(0.05)));
                    return w -> w.withToolBump(b);
                }, p -> p.withPoses(60, 60)));
        // a bump narrower than the smooth curves' finest features, on a small campaign without validation poses
        c.add(s("outside: narrow bump in the angle of j2, 100 poses", "outside", "irb2000", Expected.outside(),
                (n, r) -> add(new JointError.Bump(1, Math.toRadians(uniform(r, 25, 55)), Math.toRadians(uniform(r, 6, 9)),
                        Math.toRadians(signed(r, 0.03, 0.06)))), p -> p.withPoses(100, 0)));
        // The upper arm twisting under a payload whose centre sits 0.15-0.25 m off the flange's axis: the file's masses
        // (±30 %) and 10 kg give up to some 30 N·m about the arm's axis as the wrist swings the payload from side to side; a
        // torsional stiffness of 1.5-3·10⁵ N·m/rad (a cast arm's box section) turns the hand by up to about 10⁻⁴ rad. The PUMA
        // 560's smaller arm, carrying 0-5 kg in steps, twists as much at 3-6·10⁴ N·m/rad.
        c.add(s("outside: the upper arm twists under an off-axis payload", "outside", "irb2000", Expected.outside(),
                (n, r) -> { var t = twist(n, 1.5e5, 3e5, r); return w -> w.withTwist(t); },
                p -> p.withPayloads(RobotLibrary.shipped("irb2000").massModel().orElseThrow().ratedPayloadKg())));
        c.add(s("outside: the upper arm twists under an off-axis payload, payload steps, 6-D", "outside", "puma560", Expected.outside(),
                (n, r) -> { var t = twist(n, 3e4, 6e4, r); return w -> w.withTwist(t); },
                p -> payloads("puma560").apply(p).withSixD(true)));
        c.add(s("joint elasticity j2 with a stiffening spring, masses off 30 %", "gravity-elasticity", "irb2000",
                Expected.named(claim(GRAVITY_ELASTICITY, 2)),
                (n, r) -> {
                    var m = WorldRobot.Compliance.fromFile(n.massModel().orElseThrow(), n.dof(), 0.3, r);
                    double k = uniform(r, 0.5e6, 2e6);
                    // the tangent stiffness at about 500 N·m (drive 2's largest gravity torque with the rated load) is 2.2-4 times k
                    var cc = m.withStiffness(1, k).withHardening(1, uniform(r, 0.6, 1.0) * 500 / k);
                    return w -> w.withCompliance(cc);
                }, payloads("irb2000")));
        // both turn the tool far more than they move it: the geometric fit's σ of the rotations is many times the noise's
        c.add(s("cross-coupling j6<-j4 + lost motion j5, 6-D", "pair", "irb2000",
                Expected.named(claim(CROSS_COUPLING, 6, 4), claim(LOST_MOTION, 5)),
                (n, r) -> add(crossCoupling(5, 3, r), lostMotion(4, r)), p -> p.withSixD(true)));
        // a gear whose mesh deflects more under load: the part that repeats with the angle grows with the torque on it
        c.add(s("outside: transmission error j2 growing with the load, masses off 30 %", "outside", "irb2000", Expected.outside(),
                (n, r) -> {
                    var m = WorldRobot.Compliance.fromFile(n.massModel().orElseThrow(), n.dof(), 0.3, r);
                    var te = new JointError.LoadedHarmonic(1, 2 + r.nextInt(5), Math.toRadians(uniform(r, 0.002, 0.004)),
                            Math.toRadians(signed(r, 0.01, 0.02)), 200, 2 * Math.PI * r.nextDouble());
                    return w -> add(te).apply(w.withCompliance(m));
                }, same()));
        // a play the arm's weight always takes up: no free zone, so no motion's direction shows it
        c.add(s("outside: joint 2's play taken up by gravity whatever the last motion, masses off 30 %", "outside", "irb2000", Expected.outside(),
                (n, r) -> {
                    var m = WorldRobot.Compliance.fromFile(n.massModel().orElseThrow(), n.dof(), 0.3, r);
                    var b = new JointError.GravityHeldLostMotion(1, Math.toRadians(uniform(r, 0.02, 0.04)), 0);
                    return w -> add(b).apply(w.withCompliance(m));
                }, same()));
        // a spindle run in blocks of 10-25 minutes with rests as long: the tool grows 100-200 µm along its axis and shrinks back,
        // measured at 10 µm
        c.add(s("outside: the tool grows along its axis as its spindle runs and rests", "outside", "irb2000", Expected.outside(),
                (n, r) -> {
                    List<Double> on = new ArrayList<>(), off = new ArrayList<>();
                    for (double t = uniform(r, 0, 900); t < 30000; ) {
                        on.add(t);
                        t += uniform(r, 600, 1500);
                        off.add(t);
                        t += uniform(r, 600, 1500);
                    }
                    var sp = new WorldRobot.Spindle(on.stream().mapToDouble(Double::doubleValue).toArray(),
                            off.stream().mapToDouble(Double::doubleValue).toArray(), uniform(r, 0.1e-3, 0.2e-3), uniform(r, 500, 1200));
                    return w -> w.withToolBump(WorldRobot.ToolBump.growing(sp));
                }, p -> p.withSigma(0.01e-3)));
        // a joint whose reducer softens as the robot warms up: 3-8 % per kelvin of the campaign's warm-up
        c.add(s("outside: joint 2 softening as it warms, masses off 30 %", "outside", "irb2000", Expected.outside(),
                (n, r) -> {
                    double k = uniform(r, 2e5, 4e5);
                    var m = WorldRobot.Compliance.fromFile(n.massModel().orElseThrow(), n.dof(), 0.3, r).withStiffness(1, k);
                    var soft = new JointError.WarmSoftening(1, k, uniform(r, 0.03, 0.08), 20);
                    return w -> add(soft).apply(w.withCompliance(m));
                }, same()));
        // a dispensing tool recorded at its full 10 kg that empties to 1-3 kg over the campaign, steadily or in two steps; the
        // arm's own weight balanced, the payload's centre at the flange as the file (without masses) puts it
        c.add(s("outside: a dispensing tool empties while the file records it full", "outside", "irb2400", Expected.outside(),
                (n, r) -> {
                    double inf = Double.POSITIVE_INFINITY, end = uniform(r, 1, 3);
                    var cmp = new WorldRobot.Compliance(new double[] {inf, uniform(r, 1.5e5, 3e5), uniform(r, 0.8e5, 1.5e5), inf, inf, inf},
                            List.of(), new double[3], new double[] {0, 0, -9.80665});
                    double t1 = uniform(r, 800, 1400), t2 = uniform(r, 1800, 2600), mid = uniform(r, end + 2, 8);
                    var d = r.nextBoolean() ? new WorldRobot.Dispensing(new double[] {0, 3000}, new double[] {10, end})
                            : new WorldRobot.Dispensing(new double[] {t1, t1 + 1, t2, t2 + 1}, new double[] {10, mid, mid, end});
                    return w -> w.withCompliance(cmp).withDispensing(d);
                }, p -> p.withPayloads(10)));
        // the same tool with its reservoir hanging off the flange (its centre 40-100 mm out along the tool and up to 40 mm across
        // it, where the file without masses puts it at the flange), emptying steadily
        c.add(s("outside: a dispensing tool off the flange empties while the file records it full", "outside", "irb2400", Expected.outside(),
                (n, r) -> {
                    double inf = Double.POSITIVE_INFINITY, across = uniform(r, 0, 0.04), turn = 2 * Math.PI * r.nextDouble();
                    var cmp = new WorldRobot.Compliance(new double[] {inf, uniform(r, 1.5e5, 3e5), uniform(r, 0.8e5, 1.5e5), inf, inf, inf},
                            List.of(), new double[] {across * Math.cos(turn), across * Math.sin(turn), uniform(r, 0.04, 0.1)},
                            new double[] {0, 0, -9.80665});
                    var d = new WorldRobot.Dispensing(new double[] {0, 3000}, new double[] {10, uniform(r, 1, 3)});
                    return w -> w.withCompliance(cmp).withDispensing(d);
                }, p -> p.withPayloads(10)));
        // a cable retractor on a boom 1.9-2.5 m from axis 1, 1-2 m above the base, pulling the tool with 30-50 N; each drive
        // yields through its own stiffness (N·m/rad: the main axes' reducers 2-6e5, the wrist's 2-6e4)
        c.add(s("outside: a cable retractor on a side boom pulls the tool", "outside", "irb2400", Expected.outside(),
                (n, r) -> { var x = retractor(r, n.dof()); return w -> w.withRetractor(x); }, same()));
        c.add(s("outside: a cable retractor on a side boom pulls the tool, puma560", "outside", "puma560", Expected.outside(),
                (n, r) -> { var x = retractor(r, n.dof()); return w -> w.withRetractor(x); }, same()));
        c.add(s("lost motion j2 beside a cable retractor pulling the tool", "lost-motion", "irb2000", Expected.named(claim(LOST_MOTION, 2)),
                (n, r) -> { var x = retractor(r, n.dof()); var lm = lostMotion(1, r); return w -> add(lm).apply(w.withRetractor(x)); }, same()));
        // two laser trackers in one network, each pose read by the one its target faces better: the second 2-3 m from axis 1,
        // registered into the first's frame within 40-90 µrad and 30-60 µm
        c.add(s("outside: a second tracker reads the poses facing it, its registration off", "outside", "irb2000", Expected.outside(),
                (n, r) -> { var x = network(r); return w -> w.withNetwork(x); }, same()));
        c.add(s("outside: a second tracker reads the poses facing it, its registration off, irb2400", "outside", "irb2400", Expected.outside(),
                (n, r) -> { var x = network(r); return w -> w.withNetwork(x); }, same()));
        // a measuring machine's axes out of square by 50-150 µrad, its x and y scales 20-60 ppm off z's, its x-way bowed 20-60 µm
        c.add(s("outside: the instrument a measuring machine out of square, its x-way bowed", "outside", "irb2400", Expected.outside(),
                (n, r) -> machine(r), same()));
        c.add(s("lost motion j2 measured by a machine out of square", "lost-motion", "irb2000", Expected.named(claim(LOST_MOTION, 2)),
                (n, r) -> { var m = machine(r); var lm = lostMotion(1, r); return w -> add(lm).apply(m.apply(w)); }, same()));
        // the PUMA 560's light gear shafts: joint 2's or 3's output shaft tilting under its mesh's forces, 2.5-4e-6 rad per N·m on
        // joint 2 (0.3-0.45 mrad at its largest gravity torque, about 110 N·m), 0.8-1.4e-5 on joint 3 (about 30 N·m), the masses 30 %
        // off the file's
        c.add(s("outside: j2's output shaft tilting under its gear mesh's forces, puma560", "outside", "puma560", Expected.outside(),
                (n, r) -> shaftTilt(n, r, 1, uniform(r, 2.5e-6, 4e-6)), same()));
        c.add(s("outside: j3's output shaft tilting under its gear mesh's forces, puma560", "outside", "puma560", Expected.outside(),
                (n, r) -> shaftTilt(n, r, 2, uniform(r, 8e-6, 1.4e-5)), same()));
        c.add(s("lost motion j1 beside j2's shaft tilting under its gear mesh's forces, puma560", "lost-motion", "puma560",
                Expected.named(claim(LOST_MOTION, 1)), (n, r) -> {
                    var lm = lostMotion(0, r);
                    var tilt = shaftTilt(n, r, 1, uniform(r, 2.5e-6, 4e-6));
                    return w -> add(lm).apply(tilt.apply(w));
                }, same()));
        // joint 1 (and joint 2 of the PUMA 560, 6-15e-5) read by an encoder whose channels' gains drift apart by 2-5e-5 per kelvin, matched
        // at 20-24 °C: an error twice a turn growing through the warm-up (up to 0.005-0.02 deg)
        c.add(s("outside: j1's encoder channels drifting apart as it warms", "outside", "irb2000", Expected.outside(),
                (n, r) -> add(new JointError.QuadratureGain(0, uniform(r, 2e-5, 5e-5), uniform(r, 20, 24))), same()));
        c.add(s("outside: j2's encoder channels drifting apart as it warms, puma560", "outside", "puma560", Expected.outside(),
                (n, r) -> add(new JointError.QuadratureGain(1, uniform(r, 6e-5, 1.5e-4), uniform(r, 20, 24))), same()));
        // joint 5's drive through an oval bearing seat in joint 4's housing (20-50 um radial, a 25 mm pitch radius, 20 deg
        // pressure angle: 0.017-0.042 deg twice per turn of joint 4), on the IRB 2400 and the PUMA 560
        c.add(s("outside: j5's drive through an oval seat in joint 4's housing", "outside", "irb2400", Expected.outside(),
                (n, r) -> add(new JointError.OvalSeat(4, 3, uniform(r, 20e-6, 50e-6), Math.toRadians(20), 0.025, 2 * Math.PI * r.nextDouble())),
                same()));
        c.add(s("outside: j5's drive through an oval seat in joint 4's housing, puma560", "outside", "puma560", Expected.outside(),
                (n, r) -> add(new JointError.OvalSeat(4, 3, uniform(r, 20e-6, 50e-6), Math.toRadians(20), 0.025, 2 * Math.PI * r.nextDouble())),
                same()));
        // joint 3's error repeating 3-9 times per turn of the forearm's angle to the upper arm (a parallel arm's rod and lever), and
        // on the PUMA 560 with the forearm's angle to the ground (a serial arm's counterweight)
        c.add(s("outside: j3 error repeating with the forearm's angle to the upper arm", "outside", "irb2400", Expected.outside(),
                (n, r) -> add(new JointError.LinkHarmonic(2, 1, -1, 3 + r.nextInt(7), Math.toRadians(uniform(r, 0.01, 0.02)),
                        2 * Math.PI * r.nextDouble())), same()));
        c.add(s("outside: j3 error repeating with the forearm's angle to the ground, puma560", "outside", "puma560", Expected.outside(),
                (n, r) -> add(new JointError.LinkHarmonic(2, 1, 1, 3 + r.nextInt(7), Math.toRadians(uniform(r, 0.015, 0.025)),
                        2 * Math.PI * r.nextDouble())), same()));
        // the tracker 9-12 m away in a hall whose air stratifies as it warms: the vertical gradient grows from 0.2-0.5 to 1.5-3 K/m
        c.add(s("outside: the tracker's beam bent by the hall's stratifying air, 10 m away", "outside", "irb2000", Expected.outside(),
                (n, r) -> {
                    double heading = 2 * Math.PI * r.nextDouble(), dist = uniform(r, 9, 12);
                    Rigid far = Rigid.translation(dist * Math.cos(heading), dist * Math.sin(heading), uniform(r, 0, 1))
                            .times(Rigid.rotation(new double[] {0, 0, 1}, 2 * Math.PI * r.nextDouble(), new double[3]));
                    var air = new WorldRobot.Refraction(new double[] {0, uniform(r, 2000, 4000)}, new double[] {uniform(r, 0.2, 0.5), uniform(r, 1.5, 3)});
                    return w -> w.withInstrument(far.inverse()).withRefraction(air);
                }, p -> p.withSigma(0.005e-3)));
        c.add(s("lost motion j2 held on one flank by gravity + cross-coupling j5<-j4", "pair", "irb2000",
                Expected.named(claim(LOST_MOTION, 2), claim(CROSS_COUPLING, 5, 4)),
                (n, r) -> {
                    // the masses only give the torque that holds the play: every drive rigid
                    var m = WorldRobot.Compliance.fromFile(n.massModel().orElseThrow(), n.dof(), 0.3, r);
                    var b = new JointError.GravityHeldLostMotion(1, Math.toRadians(uniform(r, 0.02, 0.05)), uniform(r, 30, 80));
                    var k = crossCoupling(4, 3, r);
                    return w -> add(b, k).apply(w.withCompliance(m));
                }, same()));
    }

    /**
     * A laser tracker's reading errors: its distance meter's cyclic error, 20–30 µm with a period of
     * 150–600 mm, and if asked a range scale error of ±(1–3)·10⁻⁶; its azimuth encoder's once- and
     * twice-per-turn errors, 2–5 arc-seconds each.
     */
    static WorldRobot.Tracker tracker(Random r, boolean distance, boolean scale, boolean azimuth) {
        double arcsec = Math.toRadians(1.0 / 3600);
        double a = distance ? uniform(r, 20e-6, 30e-6) : 0, period = uniform(r, 0.15, 0.6), ph = 2 * Math.PI * r.nextDouble();
        double sc = scale ? signed(r, 1e-6, 3e-6) : 0;
        int[] k = azimuth ? new int[] {1, 2} : new int[0];
        double[] amp = azimuth ? new double[] {uniform(r, 2, 5) * arcsec, uniform(r, 2, 5) * arcsec} : new double[0];
        double[] aph = azimuth ? new double[] {2 * Math.PI * r.nextDouble(), 2 * Math.PI * r.nextDouble()} : new double[0];
        return new WorldRobot.Tracker(a, period, ph, sc, k, amp, aph, new int[0], new double[0], new double[0]);
    }

    /** The instrument drifting in a random direction by {@code lo}–{@code hi} m per minute, nothing else warming. */
    static WorldRobot.Thermal driftPerMinute(RobotDescription n, Random r, double lo, double hi) {
        double[] d = Rigid.scale(Rigid.unit(Arm.gauss(r, 1)), uniform(r, lo, hi) / 60);
        return new WorldRobot.Thermal(20, new double[n.dof() + 1], new double[3], d);
    }

    /**
     * {@code t} with its distance taken again from the absolute distance meter at the campaign's
     * start and at beam breaks every {@code minS}–{@code maxS} on average (a Poisson process over
     * the first 10 000 s): each time the meter's offset is drawn anew, normal with a sigma of
     * 8–15 µm (a tracker's ADM states ±10 µm or so; the upper end is a warm or worn meter).
     */
    static WorldRobot.Tracker beamBreaks(WorldRobot.Tracker t, double minS, double maxS, Random r) {
        double mean = uniform(r, minS, maxS), sigma = uniform(r, 8e-6, 15e-6);
        List<Double> at = new ArrayList<>(List.of(0.0));
        for (double s = -mean * Math.log(1 - r.nextDouble()); s < 10_000; s += -mean * Math.log(1 - r.nextDouble())) at.add(s);
        double[] times = new double[at.size()], offsets = new double[at.size()];
        for (int i = 0; i < times.length; i++) { times[i] = at.get(i); offsets[i] = sigma * r.nextGaussian(); }
        return t.withBeamBreaks(times, offsets);
    }

    /** A bearing wobble of 0.005–0.02° on {@code joint} at {@code ratio} times its angle, random phase. */
    /** A bearing's race ground in two or three lobes on its face, 0.05-0.1 mm ({@link WorldRobot.Wobble#axial}). */
    static WorldRobot.Wobble axialRunout(int joint, Random r) {
        return WorldRobot.Wobble.axial(joint, uniform(r, 0.05e-3, 0.1e-3), r.nextBoolean() ? 2 : 3, 2 * Math.PI * r.nextDouble());
    }

    static WorldRobot.Wobble wobble(int joint, double ratio, Random r) {
        return new WorldRobot.Wobble(joint, Math.toRadians(uniform(r, 0.005, 0.02)), ratio, 2 * Math.PI * r.nextDouble());
    }

    /** A motor's resolver error on drive {@code joint} (see {@link JointError.MotorSensor}), gear ratio 60-110. */
    static JointError.MotorSensor motorSensor(int joint, Random r) {
        double arcmin = Math.toRadians(1.0 / 60), a1 = uniform(r, 8, 20) * arcmin;
        return new JointError.MotorSensor(joint, uniform(r, 60, 110), new double[] {a1, uniform(r, 0.3, 0.7) * a1},
                new double[] {2 * Math.PI * r.nextDouble(), 2 * Math.PI * r.nextDouble()});
    }

    /** Every joint read as whole counts of its motor's sensor: {@code perTurn} counts a motor turn behind gear ratio {@code ratio[j]}. */
    static UnaryOperator<WorldRobot> counts(int perTurn, double[] ratio) {
        JointError[] e = new JointError[ratio.length];
        for (int j = 0; j < ratio.length; j++) e[j] = new JointError.Counts(j, 2 * Math.PI / (perTurn * ratio[j]));
        return add(e);
    }

    /** A smooth local bump of 0.02–0.04° in joint 3's angle, 10–20° wide, centred in the middle 60 % of its range. */
    static UnaryOperator<WorldRobot> bumpJ3(RobotDescription n, Random r) {
        var j = n.joints().get(2);
        double mid = 0.5 * (j.min() + j.max()), half = 0.3 * (j.max() - j.min());
        return add(new JointError.Bump(2, mid + half * (2 * r.nextDouble() - 1), Math.toRadians(uniform(r, 10, 20)),
                Math.toRadians(signed(r, 0.02, 0.04))));
    }

    /** A scenario of the catalogue by name. */
    public static Scenario named(String name) {
        for (Scenario s : catalogue()) if (s.name.equals(name)) return s;
        throw new IllegalArgumentException("no world scenario '" + name + "'");
    }

    /** The catalogue's scenarios of one group ("null", "outside", "lost-motion", ...). */
    public static List<Scenario> ofFamily(String family) {
        return catalogue().stream().filter(s -> s.family.equals(family.toLowerCase(Locale.ROOT))).toList();
    }

    /** The groups of the catalogue, in order. */
    public static List<String> families() {
        return catalogue().stream().map(Scenario::family).distinct().toList();
    }
}
