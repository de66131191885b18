package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.function.UnaryOperator;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.PoseConditions;
import org.robopro.calibration.WorldCampaigns;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.models.RobotFile;
import org.robopro.models.RobotLibrary;
import org.robopro.world.Campaign;
import org.robopro.world.Expected;
import org.robopro.world.JointError;
import org.robopro.world.Scenario;
import org.robopro.world.WorldRobot;

/**
 * Forms an independent held-out simulator concealed and the diagnosis once named as the wrong
 * physics, drawn here by the world simulator (org.robopro.world: its own kinematics and error
 * forms, nothing shared with {@link Effect}): each must be located and not named as a family,
 * while the family it was taken for is still named where it is the truth.
 */
class HeldOutFormsTest {

    /** A world scenario on a shipped robot with the given drive errors, measured with the default plan adjusted. */
    static WorldCampaigns.Sim world(String robot, Expected expected, List<JointError> errors, UnaryOperator<Campaign.Plan> plan, long seed) {
        return WorldCampaigns.of(scenario("held-out form", robot, expected, withErrors(errors), plan).trial(seed));
    }

    /**
     * A world scenario on a shipped robot with {@code conceal} applied to its drawn robot (the target
     * on the flange's axis); its name seeds its draws.
     */
    static Scenario scenario(String name, String robot, Expected expected, UnaryOperator<WorldRobot> conceal, UnaryOperator<Campaign.Plan> plan) {
        return new Scenario(name, "outside", robot, expected, (n, r) -> conceal, plan);
    }

    /** Adds drive errors to a drawn robot. */
    static UnaryOperator<WorldRobot> withErrors(List<JointError> errors) {
        return w -> {
            List<JointError> all = new ArrayList<>(w.errors());
            all.addAll(errors);
            return w.withErrors(all);
        };
    }

    /**
     * Nothing named, the structure modelled by {@code fallback}, which mattered (the geometric fit left
     * more than {@code mattersAbove} x the floor on the validation poses) and is followed to within 1.15 x
     * the floor.
     */
    static void modelledByFallbackAlone(Diagnosis d, WorldCampaigns.Sim c, long seed, String fallback, double mattersAbove) {
        assertEquals(List.of(), families(d), "seed " + seed + ": notes " + d.notes());
        assertTrue(d.effects().stream().anyMatch(f -> f.effect().label().equals(fallback)),
                "seed " + seed + ": " + d.effects().stream().map(f -> f.effect().label()).toList());
        assertTrue(d.geometricValidateRmsM() > mattersAbove * c.floorM(), "the structure matters: " + d.geometricValidateRmsM() / c.floorM());
        assertTrue(d.finalValidateRmsM() < 1.15 * c.floorM(), "seed " + seed + ": " + d.finalValidateRmsM() / c.floorM() + " x the floor");
    }

    /** The world's IRB 2000 with its tracker knocked at {@code atS} (0.2 mm and 50 µrad), the default plan; the name seeds the draws. */
    static WorldCampaigns.Sim knocked(double atS, long seed) {
        return WorldCampaigns.of(scenario("instrument knocked", "irb2000", Expected.outside(),
                w -> w.withKnock(new WorldRobot.Knock(atS, new double[] {0.15e-3, -0.1e-3, 0.08e-3}, new double[] {20e-6, -40e-6, 20e-6})),
                p -> p).trial(seed));
    }

    /** The diagnosis's step of the base, which must be there. */
    static Diagnosis.Finding baseStep(Diagnosis d, long seed) {
        return d.effects().stream().filter(f -> f.effect().kind() == Effect.Kind.BASE_STEP).findFirst()
                .orElseThrow(() -> new AssertionError("seed " + seed + ": " + d.effects().stream().map(f -> f.effect().label()).toList()));
    }

    static List<String> families(Diagnosis d) {
        return d.effects().stream().filter(f -> !f.effect().isFallback()).map(f -> f.effect().label()).toList();
    }

    /**
     * Joint 3's error following the product of joints 2 and 3 on the IRB 2400's parallel arm: its
     * part linear in q2 looks like a coupling of joint 3 from joint 2, and a coupling was named
     * beside the two-joint fallback that held the rest. The fallback holds the linear terms of both
     * joints, so the coupling is nested in it and not named.
     */
    @Test
    void errorOfJoint3FromTheProductOfJoints2And3_isNotNamedACoupling() {
        for (long seed : new long[] {3, 11}) {
            WorldCampaigns.Sim c = world("irb2400", Expected.outside(),
                    List.of(new JointError.AngleProduct(2, 1, 2, Math.toRadians(0.04))), p -> p, seed);
            Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("irb2400"), c.train(), c.validation());
            assertEquals(List.of(), families(d), "seed " + seed + ": notes " + d.notes());
            assertTrue(d.located().stream().anyMatch(l -> l.variable().equals("joints 3 and 2")), d.located().toString());
            assertTrue(d.geometricValidateRmsM() > 1.5 * c.floorM(), "the structure matters: " + d.geometricValidateRmsM());
        }
    }

    /** A world scenario on the IRB 2400 with one drive error, measured at a target 80 mm off joint 6's axis. */
    static WorldCampaigns.Sim offAxis(JointError e, long seed) {
        Scenario s = new Scenario("held-out form, target off joint 6's axis", "outside", "irb2400", Expected.outside(),
                (n, r) -> withErrors(List.of(e)), p -> p, new double[] {0.08, 0, 0.1});
        return WorldCampaigns.of(s.trial(seed));
    }

    /**
     * A hose twisted by joint 6 and stiffer as joint 5 bends (the world's torsion spring, free 40°
     * from zero, 0.045° at a half turn straight, 2.5 times that at a right-angle bend) was named a
     * gear-ratio error of joint 6, whose linear part it is: no function of joint 6 alone, and no
     * product of the two joints' sines over joint 6's 720°, held the rest. It is located as joint
     * 6's error depending on joints 6 and 5 and modelled to the floor; nothing is named.
     */
    @Test
    void hoseTwistedByJoint6StifferAsJoint5Bends_isNotNamedAGearRatio() {
        for (long seed : new long[] {4, 9}) {
            WorldCampaigns.Sim c = offAxis(new JointError.HoseTwist(5, 4, Math.toRadians(0.045) / Math.PI, Math.toRadians(40), 1.5), seed);
            Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("irb2400"), c.train(), c.validation());
            modelledByFallbackAlone(d, c, seed, "joint-pair-error j6 (with j5)", 2);
        }
    }

    /**
     * Joint 1's bearing running out along its axis (the world's race ground in three lobes, 0.08 mm):
     * no error of a joint's angle moves the point along joint 1's axis and a tilt of the axis moves
     * it in proportion to the reach, so before it was taken for a wobble of the axis or a smooth error
     * of joint 3 and left 1.3-1.4 x the floor. It is located as the axial runout, modelled to the
     * floor, and nothing is named.
     */
    @Test
    void bearingOfJoint1RunningOutAlongItsAxis_isLocatedAsAnAxialRunout() {
        for (long seed : new long[] {3, 8}) {
            WorldCampaigns.Sim c = WorldCampaigns.of(scenario("axial runout", "irb2000", Expected.outside(),
                    w -> w.withWobbles(List.of(WorldRobot.Wobble.axial(0, 0.08e-3, 3, 1.0))), p -> p).trial(seed));
            Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("irb2000"), c.train(), c.validation());
            modelledByFallbackAlone(d, c, seed, "axial-runout j1 (3 times per turn)", 1.3);
        }
    }

    /**
     * The measured target rolling within its nest's clearance toward gravity (the world's ball in a
     * nest, 0.15 mm of clearance, rolling once the tool leans 10°): a holder that bends moves in
     * proportion to the pull, a play by the same amount whichever way the tool leans. On the PUMA
     * 560 such a play of the flange was named a stiffening compliance of joint 3 beside the holder's
     * sag, 2.2 x the floor (clean-room set X). It is located as a play, modelled to the floor, and
     * nothing is named.
     */
    @Test
    void targetRollingWithinItsNestsClearance_isLocatedAsAToolPlay() {
        for (long seed : new long[] {2, 6}) {
            WorldCampaigns.Sim c = WorldCampaigns.of(scenario("tool play", "puma560", Expected.outside(),
                    w -> w.withTargetPlay(new WorldRobot.TargetPlay(0.15e-3, Math.toRadians(10))), p -> p).trial(seed));
            Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("puma560"), c.train(), c.validation());
            modelledByFallbackAlone(d, c, seed, "tool-play", 1.5);
        }
    }

    /**
     * The flange tipping within its worn bearing's clearance toward gravity, measured in 6-D (the
     * world's mount tipping 1.2 mrad about a point 30 mm inside the flange once the tool leans 10°):
     * the play is modelled with the flange's tips, and those tips turn the tool's axis toward
     * gravity by about the drawn angle (the world turns z toward û: Δω_f = t·(−û_y, û_x), so
     * rxy ≈ −t and ryx ≈ +t), however the estimator softens the take-up near vertical.
     */
    @Test
    void flangeTippingWithinItsBearingsClearance_6d_isModelledWithItsTips() {
        double tilt = 1.2e-3;
        for (long seed : new long[] {1, 5}) {
            WorldCampaigns.Sim c = WorldCampaigns.of(scenario("flange tip", "irb2000", Expected.outside(),
                    w -> w.withTargetPlay(new WorldRobot.TargetPlay(0, Math.toRadians(10), tilt, 0.03)), p -> p.withSixD(true)).trial(seed));
            Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("irb2000"), c.train(), c.validation());
            modelledByFallbackAlone(d, c, seed, "tool-play", 1.5);
            Diagnosis.Finding play = d.effects().stream().filter(f -> f.effect().label().equals("tool-play")).findFirst().orElseThrow();
            List<String> names = play.effect().parameterNames();
            double rxy = play.values()[names.indexOf("rxy")], ryx = play.values()[names.indexOf("ryx")];
            assertEquals(-tilt, rxy, 0.1 * tilt, "seed " + seed + ": rxy");
            assertEquals(tilt, ryx, 0.1 * tilt, "seed " + seed + ": ryx");
        }
    }

    /**
     * Validation poses taken beyond the training poses' range of joint 2 (the top tenth of its
     * angles, as a user validating in another part of the cell), on a joint bent by a gas-spring
     * balancer (the world's torque of a spring on a lever, not a shape the estimator has): the
     * fallback that follows the bend is fitted over the training range only, and beyond it
     * extrapolates. The warnings say that the validation error's excess lies at those poses and that
     * the model carries over within the range; with the same poses split at random, the validation
     * poses lie within the range and no such sentence is written.
     */
    @Test
    void validationBeyondTheTrainingRange_isSaidToBeExtrapolated() {
        for (long seed : new long[] {1, 3}) {
            WorldCampaigns.Sim c = WorldCampaigns.of(scenario("gas spring beyond", "irb2000", Expected.outside(),
                    withErrors(List.of(new JointError.GasSpring(1, 0.15, 0.35, Math.toRadians(95), 3000, 0.2 / 3, 1.3, 2e5))), p -> p).trial(seed));
            List<Measurement> all = new ArrayList<>(c.train().rows());
            all.addAll(c.validation().rows());
            double[] q2 = all.stream().mapToDouble(m -> m.q(1)).sorted().toArray();
            double cut = q2[(int) (0.9 * q2.length)];
            for (boolean beyond : new boolean[] {true, false}) {
                List<Measurement> tr = new ArrayList<>(), va = new ArrayList<>();
                for (int i = 0; i < all.size(); i++) {
                    Measurement m = all.get(i);
                    if (i % 4 == 0 || beyond && m.q(1) > cut || !beyond && i % 10 == 1) va.add(m);
                    else tr.add(m);
                }
                Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("irb2000"), c.train().withRows(tr), c.validation().withRows(va));
                String said = String.join(" | ", d.warnings());
                assertTrue(d.effects().stream().anyMatch(f -> f.effect().label().equals("joint-smooth-error j2")), "seed " + seed + ": "
                        + d.effects().stream().map(f -> f.effect().label()).toList());
                if (beyond) {
                    assertTrue(d.finalValidateRmsM() > 1.5 * c.floorM(), "the extrapolation misses: " + d.finalValidateRmsM() / c.floorM());
                    assertTrue(said.contains("validation poses lie beyond the range joint-smooth-error j2 was fitted over")
                            && said.contains("the model carries over to the poses it can predict"), "seed " + seed + ": " + said);
                } else {
                    assertTrue(d.finalValidateRmsM() < 1.15 * c.floorM(), "seed " + seed + ": " + d.finalValidateRmsM() / c.floorM());
                    assertTrue(!said.contains("beyond the range"), "seed " + seed + ": " + said);
                }
            }
        }
    }

    /**
     * The instrument knocked once, 30 minutes into the campaign (the world's tracker turned by 50
     * µrad about its own origin and shifted by 0.2 mm): every point moves by one rigid motion from
     * then on, whatever the arm's pose. A drift of the instrument with time (a family) follows part
     * of it and was named (a clean-room set's knocked tracker, beside a transmission error); it is
     * located as a step of the instrument against the base at that time, modelled to the floor on
     * the training poses, and nothing is named. (A validation pose between the two training poses
     * either side of the knock can lie on either side of it: the validation error is not held to
     * the floor.)
     */
    @Test
    void instrumentKnockedOnce_isLocatedAsAStepOfTheBase() {
        double at = 1800;
        for (long seed : new long[] {1, 2}) {
            WorldCampaigns.Sim c = knocked(at, seed);
            Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("irb2000"), c.train(), c.validation());
            assertEquals(List.of(), families(d), "seed " + seed + ": notes " + d.notes());
            Diagnosis.Finding step = baseStep(d, seed);
            assertEquals(at, step.effect().tauS(), 40, "seed " + seed + ": the knock's time");
            // the evidence: before the knock the partial residual stands at the step's size, after it it scatters about zero
            // (the residual along the way the step would have moved each pose, not a zero drawn for want of a direction)
            Diagnosis.Plot p = step.plot();
            double sizeMm = 1e3 * Math.sqrt(0.15e-3 * 0.15e-3 + 0.1e-3 * 0.1e-3 + 0.08e-3 * 0.08e-3);
            double before = 0, after = 0, afterSq = 0;
            int nb = 0, na = 0;
            for (int i = 0; i < p.x().length; i++) {
                if (p.x()[i] <= step.effect().tauS()) { before += p.y()[i]; nb++; }
                else { after += p.y()[i]; afterSq += p.y()[i] * p.y()[i]; na++; }
            }
            assertEquals(sizeMm, before / nb, 0.5 * sizeMm, "seed " + seed + ": before the knock");
            assertEquals(0, after / na, 0.1 * sizeMm, "seed " + seed + ": after the knock");
            assertTrue(Math.sqrt(afterSq / na) > 0.2 * 1e3 * c.sigmaM(), "seed " + seed + ": the poses after the knock scatter with the noise");
            assertTrue(d.geometricValidateRmsM() > 2 * c.floorM(), "the knock matters: " + d.geometricValidateRmsM() / c.floorM());
            assertTrue(d.finalTrainRmsM() < 1.1 * c.floorM(), "seed " + seed + ": " + d.finalTrainRmsM() / c.floorM() + " x the floor");
            assertTrue(d.finalValidateRmsM() < 0.5 * d.geometricValidateRmsM(), "seed " + seed + ": " + d.finalValidateRmsM() / c.floorM());
        }
    }

    /**
     * A laser tracker's distance meter whose cyclic error repeats at a fine period of 94 mm (a
     * modulation near 1.6 GHz) and at its second and fourth overtones, 15 µm each (the world's
     * tracker), measured at σ 5 µm: a single sine left 1.4-1.9 x the floor (a clean-room set's
     * meter, beside a lost motion that was named right). The periods down to 20 mm are scanned and
     * the cycle is modelled with its overtones, to the floor; nothing is named.
     */
    @Test
    void distanceMetersCyclicErrorWithOvertones_isModelledToTheFloor() {
        for (long seed : new long[] {1, 2}) {
            var tracker = new WorldRobot.Tracker(15e-6, 0.094, 0.7, 0, new int[0], new double[0], new double[0], new int[0], new double[0],
                    new double[0]).withCyclicOvertones(new double[] {15e-6, 0, 15e-6}, new double[] {2.1, 0, 4.4});
            WorldCampaigns.Sim c = WorldCampaigns.of(scenario("meter overtones", "irb2000", Expected.outside(), w -> w.withTracker(tracker),
                    p -> p.withSigma(0.005e-3)).trial(seed));
            Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("irb2000"), c.train(), c.validation());
            assertEquals(List.of(), families(d), "seed " + seed + ": notes " + d.notes());
            // one cycle, at the meter's period, holding its fourth overtone (not the cycle and its overtones as three errors)
            List<Effect> cycles = d.effects().stream().map(Diagnosis.Finding::effect)
                    .filter(e -> e.kind() == Effect.Kind.INSTRUMENT && e.cycleOrders() > 0).toList();
            assertEquals(1, cycles.size(), "seed " + seed + ": " + cycles.stream().map(Effect::label).toList());
            assertEquals(0.094, cycles.get(0).cycle(), 0.002, "seed " + seed + ": " + cycles.get(0).label());
            assertTrue(cycles.get(0).cycleOrders() >= 4, "seed " + seed + ": " + cycles.get(0).label());
            assertTrue(d.geometricValidateRmsM() > 1.5 * c.floorM(), "the error matters: " + d.geometricValidateRmsM() / c.floorM());
            assertTrue(d.finalValidateRmsM() < 1.15 * c.floorM(), "seed " + seed + ": " + d.finalValidateRmsM() / c.floorM() + " x the floor");
        }
    }

    /**
     * The instrument a coordinate measuring machine reporting its scales' readings while its axes are
     * out of square by 120, −90 and 70 µrad, its x and y scales 40 and −30 ppm off z's and its x-way
     * bowed by 40 and −30 µm over ±1.5 m (the world's machine, solved through its own axis chain).
     * Left to the robot, the bow turned up as a gear's error of joint 1 twice per turn; it is located as
     * the instrument's axes, nothing is named, and a lost motion of joint 2 beside it is named.
     */
    @Test
    void measuringMachineOutOfSquare_isTheInstrumentsAxes_andALostMotionBesideItIsNamed() {
        UnaryOperator<WorldRobot> machine = w -> w.withMachine(new WorldRobot.Machine(120e-6, -90e-6, 70e-6, 40e-6, -30e-6, 40e-6, -30e-6,
                w.instrumentFromBase().p()[0], 1.5));
        WorldCampaigns.Sim c = WorldCampaigns.of(scenario("machine out of square", "irb2400", Expected.outside(), machine, p -> p).trial(3));
        Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("irb2400"), c.train(), c.validation());
        assertEquals(List.of(), families(d), "notes " + d.notes());
        assertTrue(d.effects().stream().anyMatch(f -> f.effect().kind() == Effect.Kind.INSTRUMENT_AXES), "located: "
                + d.effects().stream().map(f -> f.effect().label()).toList());
        assertTrue(d.geometricValidateRmsM() > 1.5 * c.floorM(), "the error matters: " + d.geometricValidateRmsM() / c.floorM());
        assertTrue(d.finalValidateRmsM() < 1.15 * c.floorM(), d.finalValidateRmsM() / c.floorM() + " x the floor");

        WorldCampaigns.Sim withPlay = WorldCampaigns.of(scenario("machine out of square", "irb2000", Expected.outside(), w -> withErrors(
                List.of(new JointError.LostMotion(1, Math.toRadians(0.03)))).apply(machine.apply(w)), p -> p).trial(4));
        Diagnosis dp = Diagnoser.diagnose(RobotLibrary.shipped("irb2000"), withPlay.train(), withPlay.validation());
        assertEquals(List.of("backlash j2"), families(dp), "notes " + dp.notes());
        assertTrue(dp.finalValidateRmsM() < 1.15 * withPlay.floorM(), dp.finalValidateRmsM() / withPlay.floorM() + " x the floor");
    }

    /**
     * The arm read a second after each stop, before it settled (the world's acceleration-limited moves
     * ringing at 8 Hz, ζ 0.04, on drives 1-3): every joint's error follows the move just made, its
     * sign the move's, its size the joint's share of it. A lost motion of fixed size is not it, nor a
     * gear ratio: nothing is named, the settling is located and modelled by the joints' speeds in
     * the move before the reading (computed from the robot file's top speeds, not the world's
     * acceleration limits), and the validation error falls by more than half.
     */
    @Test
    void armReadBeforeItSettled_isModelledAsSettlingNotBacklash() {
        double[] accel = {2.0, 1.6, 2.4, 6, 6, 8};
        for (long seed : new long[] {1, 2}) {
            List<JointError> ringing = new ArrayList<>();
            for (int j = 0; j < 3; j++) ringing.add(new JointError.Settling(j, 8, 0.04, 1.0, 0, accel));
            WorldCampaigns.Sim c = world("irb2000", Expected.outside(), ringing, p -> p, seed);
            Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("irb2000"), c.train(), c.validation());
            assertEquals(List.of(), families(d), "seed " + seed + ": notes " + d.notes());
            assertTrue(d.effects().stream().anyMatch(f -> f.effect().kind() == Effect.Kind.SETTLING),
                    "seed " + seed + ": " + d.effects().stream().map(f -> f.effect().label()).toList());
            assertTrue(d.geometricValidateRmsM() > 2 * c.floorM(), "the settling matters: " + d.geometricValidateRmsM() / c.floorM());
            System.out.printf("settling seed %d: %.2f -> %.2f x the floor %s%n", seed, d.geometricValidateRmsM() / c.floorM(),
                    d.finalValidateRmsM() / c.floorM(), d.effects().stream().map(f -> f.effect().label()).toList());
            assertTrue(d.finalValidateRmsM() < 0.5 * d.geometricValidateRmsM(), "seed " + seed + ": " + d.finalValidateRmsM() / c.floorM());
        }
    }

    /**
     * A transmission error of joint 2 whose cycle grows with the torque on the joint (the world's
     * loaded mesh, its own masses 30 % off the robot file's), measured with two payloads (without
     * them the torque on joint 2 follows joint 2's angle nearly alone, and the growing cycle is
     * a periodic error of that angle with sidebands): a transmission error of fixed size
     * would be named for the part that does not change, and predicts left-out poses worse than the
     * same cycle growing with the load. Nothing is named, the validation error comes within 1.15 x
     * the floor, and on one seed at least the load-periodic error models it (on another a smooth
     * curve of joint 2 may be located first: no family was named that it must stand against).
     */
    @Test
    void transmissionErrorGrowingWithTheLoad_isLocatedNotNamed() {
        var n = RobotLibrary.shipped("irb2000");
        int loaded = 0;
        for (long seed : new long[] {1, 3}) {
            Scenario s = scenario("loaded mesh", "irb2000", Expected.outside(), w -> {
                var m = WorldRobot.Compliance.fromFile(n.massModel().orElseThrow(), n.dof(), 0.3, new java.util.Random(seed));
                var te = new JointError.LoadedHarmonic(1, 7, Math.toRadians(0.006), Math.toRadians(0.012), 200, 0.7 * seed);
                return withErrors(List.of(te)).apply(w.withCompliance(m));
            }, p -> p.withPayloads(0, 10));
            WorldCampaigns.Sim c = WorldCampaigns.of(s.trial(seed));
            Diagnosis d = Diagnoser.diagnose(n, c.train(), c.validation());
            System.out.printf("loaded mesh seed %d: %.2f -> %.2f x the floor %s%n", seed, d.geometricValidateRmsM() / c.floorM(),
                    d.finalValidateRmsM() / c.floorM(), d.effects().stream().map(f -> f.effect().label()).toList());
            assertEquals(List.of(), families(d), "seed " + seed + ": notes " + d.notes());
            assertTrue(d.geometricValidateRmsM() > 2 * c.floorM(), "the structure matters: " + d.geometricValidateRmsM() / c.floorM());
            assertTrue(d.finalValidateRmsM() < 1.15 * c.floorM(), "seed " + seed + ": " + d.finalValidateRmsM() / c.floorM() + " x the floor");
            loaded += d.effects().stream().filter(f -> f.effect().kind() == Effect.Kind.LOAD_PERIODIC).count();
        }
        // where a transmission error of fixed size was named first, the claim check puts the growing cycle in its place
        assertTrue(loaded > 0, "no seed modelled by the load-periodic error");
    }

    /**
     * A play of joint 2 that the arm's weight always takes up (the world's lost motion held by
     * gravity with no free zone, its own masses 30 % off the robot file's): no motion's direction
     * shows it, so nothing is named; it is modelled as a play taken up by gravity, of the world's
     * width to 10 %, and on the side the torque pushes the output to (the world's flank: the output
     * ahead of the motor where the torque is positive, Nordin &amp; Gutman 2002), so the validation
     * error comes within 1.15 x the floor.
     */
    @Test
    void playTakenUpByGravity_isLocatedWithTheTorquesSide() {
        var n = RobotLibrary.shipped("irb2000");
        double width = Math.toRadians(0.03);
        for (long seed : new long[] {1, 2}) {
            Scenario s = scenario("gravity play", "irb2000", Expected.outside(), w -> {
                var m = WorldRobot.Compliance.fromFile(n.massModel().orElseThrow(), n.dof(), 0.3, new java.util.Random(seed));
                return withErrors(List.of(new JointError.GravityHeldLostMotion(1, width, 0))).apply(w.withCompliance(m));
            }, p -> p);
            WorldCampaigns.Sim c = WorldCampaigns.of(s.trial(seed));
            Diagnosis d = Diagnoser.diagnose(n, c.train(), c.validation());
            System.out.printf("gravity play seed %d: %.2f -> %.2f x the floor %s%n", seed, d.geometricValidateRmsM() / c.floorM(),
                    d.finalValidateRmsM() / c.floorM(), d.effects().stream().map(f -> f.effect().label() + " " + java.util.Arrays.toString(f.values())).toList());
            assertEquals(List.of(), families(d), "seed " + seed + ": notes " + d.notes());
            Diagnosis.Finding play = d.effects().stream().filter(f -> f.effect().kind() == Effect.Kind.GRAVITY_PLAY).findFirst()
                    .orElseThrow(() -> new AssertionError("seed " + seed + ": " + d.effects().stream().map(f -> f.effect().label()).toList()));
            assertEquals(width, play.values()[0], 0.1 * width, "seed " + seed + ": the play, with the torque's side");
            assertTrue(withoutHandedOver(d) < 1.15 * c.floorM(), "seed " + seed + ": " + withoutHandedOver(d) / c.floorM() + " x the floor");
        }
    }

    /**
     * The validation error without the poses the notes say lie where gravity hands a play from one side
     * to the other (which side they sit on the model cannot tell; they stay in the reported error), m.
     */
    static double withoutHandedOver(Diagnosis d) {
        var m = java.util.regex.Pattern.compile("hands the gear .*\\(([0-9.]+) mm; ([0-9.]+) mm without").matcher(String.join("\n", d.notes()));
        return m.find() ? Double.parseDouble(m.group(2)) * 1e-3 : d.finalValidateRmsM();
    }

    /**
     * The benchmark's play of joint 2 taken up by gravity, its masses 30 % off the robot file's, on
     * the draw where one validation pose's torque lies close to the torque's zero: by the file's
     * masses on one side, by the world's on the other. It misses by about the play (0.5 mm, some 20
     * robust sigmas); which side it sits on the model cannot tell there, so it is no bad reading: the
     * notes say so and it stays in the validation error. Away from the side change a pose keeps its
     * verdict (the benchmark's gross readings elsewhere are still reported).
     */
    @Test
    void poseWhereAGravityPlaysSideChanges_isNoBadReading() {
        Scenario s = Scenario.catalogue().stream().filter(x -> x.name().startsWith("outside: joint 2's play taken up by gravity"))
                .findFirst().orElseThrow();
        WorldCampaigns.Sim c = WorldCampaigns.of(s.trial(20261125));
        Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("irb2000"), c.train(), c.validation());
        assertEquals(List.of(), families(d), "notes " + d.notes());
        assertTrue(d.effects().stream().anyMatch(f -> f.effect().kind() == Effect.Kind.GRAVITY_PLAY),
                d.effects().stream().map(f -> f.effect().label()).toList().toString());
        assertEquals(List.of(), d.outliers(), "notes " + d.notes());
        assertTrue(d.notes().stream().anyMatch(n -> n.startsWith("validation pose") && n.contains("hands the gear")), "notes " + d.notes());
    }

    /**
     * A tool that grows along its axis as its spindle runs in blocks and rests between them (the
     * world's first-order heating, 0.15 mm when warmed through, never recorded in the file): the
     * measured point drifts on the flange with time. Nothing is named; a drift of the target on the
     * flange with time models it: the validation error falls below 0.6 x the geometric fit's and
     * within 1.2 x the floor (a spline of the time follows a growth that turns every 20 minutes only
     * so closely).
     */
    @Test
    void toolGrowingWithItsSpindle_isATargetDrift() {
        var sp = new WorldRobot.Spindle(new double[] {300, 2700, 5100, 7500}, new double[] {1500, 3900, 6300, 8700}, 0.15e-3, 800);
        for (long seed : new long[] {1, 2}) {
            WorldCampaigns.Sim c = WorldCampaigns.of(scenario("spindle", "irb2000", Expected.outside(),
                    w -> w.withToolBump(WorldRobot.ToolBump.growing(sp)), p -> p.withSigma(0.01e-3)).trial(seed));
            Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("irb2000"), c.train(), c.validation());
            System.out.printf("spindle seed %d: %.2f -> %.2f x the floor %s%n", seed, d.geometricValidateRmsM() / c.floorM(),
                    d.finalValidateRmsM() / c.floorM(), d.effects().stream().map(f -> f.effect().label()).toList());
            assertEquals(List.of(), families(d), "seed " + seed + ": notes " + d.notes());
            assertTrue(d.effects().stream().anyMatch(f -> f.effect().kind() == Effect.Kind.TARGET_DRIFT),
                    "seed " + seed + ": " + d.effects().stream().map(f -> f.effect().label()).toList());
            assertTrue(d.geometricValidateRmsM() > 1.4 * c.floorM(), "the growth matters: " + d.geometricValidateRmsM() / c.floorM());
            assertTrue(d.finalValidateRmsM() < 0.6 * d.geometricValidateRmsM() && d.finalValidateRmsM() < 1.2 * c.floorM(),
                    "seed " + seed + ": " + d.finalValidateRmsM() / c.floorM() + " x the floor");
        }
    }

    /**
     * Two validation readings gone grossly wrong (a beam broken and caught again on the wrong
     * reflector, 2 mm) beside a backlash of joint 2: they are reported as outliers, said with their
     * miss, and left out of the validation error and of every decision taken on the validation
     * poses, so the diagnosis is the one of the campaign without them (the same claim, the same
     * validation error to a thousandth).
     */
    @Test
    void grossValidationReadings_areReportedAndTheDiagnosisIsTheOneWithoutThem() {
        long seed = 5;
        WorldCampaigns.Sim c = world("irb2000", Expected.named(Expected.claim(Expected.Family.LOST_MOTION, 2)),
                List.of(new JointError.LostMotion(1, Math.toRadians(0.02))), p -> p, seed);
        List<String> bad = List.of(c.validation().rows().get(7).poseId(), c.validation().rows().get(40).poseId());
        var corrupted = c.validation().map(m -> bad.contains(m.poseId())
                ? m.withPosition(m.position().plus(new org.robopro.models.Vec3(1.2e-3, -1.5e-3, 0.4e-3))) : m);
        Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("irb2000"), c.train(), corrupted);
        Diagnosis without = Diagnoser.diagnose(RobotLibrary.shipped("irb2000"), c.train(),
                c.validation().filter(m -> !bad.contains(m.poseId())));
        assertEquals(List.of("backlash j2"), families(d), "notes " + d.notes());
        assertEquals(families(without), families(d));
        assertTrue(d.outliers().containsAll(bad), d.outliers().toString());
        for (String id : bad)
            assertTrue(d.notes().stream().anyMatch(n -> n.startsWith("validation pose " + id + " misses by 1.9")), d.notes().toString());
        assertEquals(without.finalValidateRmsM(), d.finalValidateRmsM(), 1e-3 * without.finalValidateRmsM());
        assertEquals(without.geometricValidateRmsM(), d.geometricValidateRmsM(), 1e-3 * without.geometricValidateRmsM());
    }

    /**
     * The instrument knocked near the campaign's end (the world's tracker at 3350 s of about 3500):
     * the dozen poses after it are few enough to be taken for bad readings, and they were reported
     * as such. Measured one after another, they are a change at one time: kept in, the step is
     * located at the knock and no pose is reported. Four readings gone bad one after another, each
     * its own way (a beam re-locked on the wrong reflector, 1.5 mm), no step explains: they are
     * reported as bad readings all the same, and nothing is named.
     */
    @Test
    void runOfPosesInTime_isAStepWhenOneExplainsIt_elseBadReadings() {
        for (long seed : new long[] {1, 2}) {
            WorldCampaigns.Sim c = knocked(3350, seed);
            Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("irb2000"), c.train(), c.validation());
            assertEquals(List.of(), families(d), "seed " + seed + ": notes " + d.notes());
            assertEquals(List.of(), d.outliers(), "seed " + seed + ": notes " + d.notes());
            Diagnosis.Finding step = baseStep(d, seed);
            assertEquals(3350, step.effect().tauS(), 15, "seed " + seed + ": the knock's time");
            assertTrue(d.finalTrainRmsM() < 1.1 * c.floorM(), "seed " + seed + ": " + d.finalTrainRmsM() / c.floorM() + " x the floor");

            WorldCampaigns.Sim clean = WorldCampaigns.of(scenario("readings gone bad", "irb2000", Expected.none(), w -> w, p -> p).trial(seed));
            List<Measurement> byTime = clean.train().rows().stream().sorted(java.util.Comparator.comparingDouble(Measurement::timeS)).toList();
            java.util.Map<String, Measurement> bad = new java.util.HashMap<>();
            double[][] off = {{1.5e-3, 0, 0}, {0, -1.5e-3, 0}, {0, 0, 1.5e-3}, {-1.1e-3, 1.1e-3, 0}};
            for (int k = 0; k < off.length; k++) {
                Measurement m = byTime.get(120 + k);
                bad.put(m.poseId(), m.withPosition(m.position().plus(new org.robopro.models.Vec3(off[k][0], off[k][1], off[k][2]))));
            }
            var train = clean.train().map(m -> bad.getOrDefault(m.poseId(), m));
            Diagnosis g = Diagnoser.diagnose(RobotLibrary.shipped("irb2000"), train, clean.validation());
            assertEquals(List.of(), g.effects().stream().map(f -> f.effect().label()).toList(), "seed " + seed + ": notes " + g.notes());
            assertEquals(new java.util.TreeSet<>(bad.keySet()), new java.util.TreeSet<>(g.outliers()), "seed " + seed + ": notes " + g.notes());
        }
    }

    /** A true gear-ratio error of joint 6, measured the same way, is still named (the two-joint fallback nests it). */
    @Test
    void gearRatioOfJoint6_offAxisTarget_isStillNamed() {
        WorldCampaigns.Sim c = offAxis(new JointError.Scale(5, 2e-4), 4);
        Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("irb2400"), c.train(), c.validation());
        assertEquals(List.of("joint-scale j6"), families(d), "notes " + d.notes());
        assertTrue(d.finalValidateRmsM() < 1.15 * c.floorM(), d.finalValidateRmsM() / c.floorM() + " x the floor");
    }

    /** A true coupling of joint 3 from joint 2 on the same arm is still named (the nested fallback does not take it). */
    @Test
    void couplingOfJoint3FromJoint2_isStillNamed() {
        WorldCampaigns.Sim c = world("irb2400", Expected.outside(),
                List.of(new JointError.Coupling(2, 1, 8e-4)), p -> p, 5);
        Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("irb2400"), c.train(), c.validation());
        assertEquals(List.of("joint-coupling j3<-j2"), families(d), "notes " + d.notes());
        assertTrue(d.finalValidateRmsM() < 1.15 * c.floorM(), d.finalValidateRmsM() + " vs floor " + c.floorM());
    }

    /**
     * The IRB 2400's true masses, chosen here (its robot file has none): upper arm 40 kg half-way
     * between axes 2 and 3, forearm with wrist motors 25 kg 320 mm in front of axis 3, wrist 5 kg
     * at the wrist centre (zero position, base coordinates, m); the payload 100 mm out on the flange.
     */
    static WorldRobot.Compliance irb2400Compliance(double k2, double k3) {
        double inf = Double.POSITIVE_INFINITY;
        return new WorldRobot.Compliance(new double[] {inf, k2, k3, inf, inf, inf},
                List.of(new WorldRobot.Mass(1, 40, new double[] {0.1, 0, 0.9675}), new WorldRobot.Mass(2, 25, new double[] {0.42, 0, 1.42}),
                        new WorldRobot.Mass(4, 5, new double[] {0.855, 0, 1.455})),
                new double[] {0, 0, 0.1}, new double[] {0, 0, -9.80665});
    }

    static WorldCampaigns.Sim compliant(WorldRobot.Compliance cmp, UnaryOperator<Campaign.Plan> plan, long seed) {
        Scenario s = new Scenario("held-out compliance", "gravity-elasticity", "irb2400", Expected.outside(), (n, r) -> w -> w.withCompliance(cmp), plan);
        return WorldCampaigns.of(s.trial(seed));
    }

    /**
     * Drive 2 of the IRB 2400 giving way under gravity, measured with payload steps: the robot file
     * has no mass model, so the compliance is found through the payload's torque with the arm's
     * masses estimated, and named (a transmission error of one cycle per turn was named before).
     */
    @Test
    void complianceOfJoint2WithPayloadSteps_isNamedWithoutAMassModel() {
        WorldCampaigns.Sim c = compliant(irb2400Compliance(5e5, Double.POSITIVE_INFINITY), p -> p.withPayloads(0, 7.5, 15), 7);
        Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("irb2400"), c.train(), c.validation());
        assertEquals(List.of("joint-compliance j2 (masses estimated)"), families(d), "notes " + d.notes());
        assertTrue(d.finalValidateRmsM() < 1.15 * c.floorM(), d.finalValidateRmsM() + " vs floor " + c.floorM());
        assertEquals(List.of(), d.outliers());
        // the stiffness from the payload's torque, against the world's 5e5 N·m/rad
        Diagnosis.Finding f = d.effects().get(0);
        double k = 1 / f.values()[f.effect().gravity().payloadIndex()];
        assertTrue(k > 4e5 && k < 6.25e5, "stiffness " + k);
        // the extended robot file, read back without a mass model, predicts the same to a few µm (the unknown masses
        // ride on the link frames, which the file's identified geometry places a little differently from the nominal; how
        // much follows the estimate of the masses' least determined moment, 6.6e9 here, whose last digits move with rounding)
        ExtendedModel ext = d.model();
        ExtendedModel back = ExtendedModel.of(RobotFile.parse("extended.robot.json", RobotFile.format(ext.toDescription())), "extended.robot.json");
        ExtendedModel rigid = new ExtendedModel(ext.geometry(), List.of());
        double largest = 0;
        for (var m : c.validation().rows()) {
            PoseConditions pc = PoseConditions.of(m);
            assertEquals(0, ext.flange(m.q(), pc).distanceTo(back.flange(m.q(), pc)), 1e-5);
            largest = Math.max(largest, ext.flange(m.q(), pc).distanceTo(rigid.flange(m.q(), pc)));
        }
        assertTrue(largest > 2e-5, "the compliance moves the flange: " + largest);
    }

    /**
     * Joints 2 and 3 of the IRB 2400 each giving in its own angle by the torque about its axis (a
     * serial chain's joint stiffness, the world's springs in the joints): on the parallel arm joint
     * 2's give turns the forearm with it, which drive 2's gear, feeling τ2 − τ3, cannot. Both are
     * named, joint 2 in its own angle, and the extended robot file, read back, predicts the same.
     */
    @Test
    void complianceInTheJointsOwnAngles_parallelArm_isNamedAtTheJoint() {
        WorldCampaigns.Sim c = compliant(irb2400Compliance(4e5, 3e5).inJoints(), p -> p.withPayloads(0, 7.5, 15), 9);
        Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("irb2400"), c.train(), c.validation());
        assertEquals(java.util.Set.of("joint-compliance j2 (at the joint) (masses estimated)", "joint-compliance j3 (masses estimated)"),
                java.util.Set.copyOf(families(d)), "notes " + d.notes());
        assertTrue(d.finalValidateRmsM() < 1.15 * c.floorM(), d.finalValidateRmsM() / c.floorM() + " x the floor");
        // read back, to a few hundredths of what the springs move (the estimated masses ride on the identified link frames, as above)
        ExtendedModel ext = d.model();
        ExtendedModel back = ExtendedModel.of(RobotFile.parse("extended.robot.json", RobotFile.format(ext.toDescription())), "extended.robot.json");
        ExtendedModel rigid = new ExtendedModel(ext.geometry(), List.of());
        double largest = 0, apart = 0;
        for (var m : c.validation().rows()) {
            PoseConditions pc = PoseConditions.of(m);
            apart = Math.max(apart, ext.flange(m.q(), pc).distanceTo(back.flange(m.q(), pc)));
            largest = Math.max(largest, ext.flange(m.q(), pc).distanceTo(rigid.flange(m.q(), pc)));
        }
        assertTrue(apart < 0.05 * largest, "read back " + apart + " m apart, the springs move the flange " + largest + " m");
    }

    /**
     * Drives 2 and 3 giving way under the arm's own weight with one payload throughout: on the
     * parallel arm that is a one-cycle-per-turn shape of each drive's angle, the same as a
     * transmission error's. Neither may be named; the report says to measure with payload steps.
     */
    @Test
    void complianceWithoutPayloadSteps_isNotNamedAsATransmissionError() {
        WorldCampaigns.Sim c = compliant(irb2400Compliance(5e5, 4e5), p -> p, 8);
        Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("irb2400"), c.train(), c.validation());
        assertEquals(List.of(), families(d), "notes " + d.notes());
        assertTrue(d.recommendations().stream().anyMatch(r -> r.contains("payload")), d.recommendations().toString());
        assertTrue(d.geometricValidateRmsM() > 1.5 * c.floorM(), "the structure matters: " + d.geometricValidateRmsM());
    }

    /**
     * A real transmission error of joint 2 on the same arm without payload steps: one that repeats
     * within joint 2's sampled 210° (a reducer's stage at 6 cycles a turn beside the first) is
     * named, and so is one of harmonics 1-3 whose curve turns three times within the range (no
     * torque of a weight, a spring or a cable turns that often over a joint's range). Harmonic 1
     * alone is one smooth arc over that range, which a balancer's spring or the arm's weight gives
     * too: it is located with the words that the data cannot tell.
     */
    @Test
    void transmissionErrorOfJoint2WithoutPayloadSteps_isNamedWhereItRepeatsOrTurnsWithinTheRange() {
        WorldCampaigns.Sim staged = world("irb2400", Expected.outside(), List.of(new JointError.Harmonics(1, new int[] {1, 6},
                new double[] {Math.toRadians(0.008), Math.toRadians(0.006)}, new double[] {0.3, 1.9})), p -> p, 9);
        Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("irb2400"), staged.train(), staged.validation());
        assertEquals(1, families(d).size(), "notes " + d.notes());
        assertTrue(families(d).get(0).startsWith("gear-periodic j2"), families(d) + ", notes " + d.notes());

        JointError.Harmonics three = new JointError.Harmonics(1, new int[] {1, 2, 3},
                new double[] {Math.toRadians(0.008), Math.toRadians(0.006), Math.toRadians(0.007)}, new double[] {0.3, 1.9, 4.0});
        WorldCampaigns.Sim low = world("irb2400", Expected.outside(), List.of(three), p -> p, 9);
        assertTrue(extrema(three, low) >= 3, "the world's curve turns " + extrema(three, low) + " times");
        d = Diagnoser.diagnose(RobotLibrary.shipped("irb2400"), low.train(), low.validation());
        assertEquals(List.of("gear-periodic j2"), families(d), "notes " + d.notes());
        assertTrue(d.notes().stream().anyMatch(n -> n.startsWith("gear-periodic j2 is named though joint 2 was sampled over")), d.notes().toString());

        JointError.Harmonics one = new JointError.Harmonics(1, new int[] {1}, new double[] {Math.toRadians(0.012)}, new double[] {0.3});
        WorldCampaigns.Sim arc = world("irb2400", Expected.outside(), List.of(one), p -> p, 9);
        assertTrue(extrema(one, arc) <= 2, "the world's curve turns " + extrema(one, arc) + " times");
        d = Diagnoser.diagnose(RobotLibrary.shipped("irb2400"), arc.train(), arc.validation());
        assertEquals(List.of(), families(d), "notes " + d.notes());
        assertTrue(d.notes().stream().anyMatch(n -> n.contains("gear-periodic j2 is not claimed")
                && (n.contains("cannot tell") || n.contains("cannot be told"))), d.notes().toString());
        assertTrue(d.located().stream().anyMatch(l -> l.variable().equals("joint 2 angle")), d.located().toString());
    }

    /**
     * The turning points counted on a fitted curve over -135..135°: cos 2q turns three times (at -90,
     * 0 and 90°), cos q once, a ripple of a twentieth of the curve's size on cos q adds none, and
     * sin q none (its extrema at ±90° are only 0.29 of its size above the ends of the range).
     */
    @Test
    void turningPoints_countTheCurvesMaximaAndMinimaAboveARipple() {
        List<org.robopro.calibration.measurement.Measurement> rows = new ArrayList<>();
        for (double deg : new double[] {-135, 0, 135})
            rows.add(org.robopro.calibration.measurement.Measurement.of("p" + deg, new double[] {0, Math.toRadians(deg), 0, 0, 0, 0},
                    new org.robopro.models.Vec3(0, 0, 0)));
        assertEquals(3, Diagnoser.turningPoints(Effect.periodic(1, new int[] {2}), new double[] {0, 1e-4}, rows));
        assertEquals(1, Diagnoser.turningPoints(Effect.periodic(1, new int[] {1}), new double[] {0, 1e-4}, rows));
        assertEquals(1, Diagnoser.turningPoints(Effect.periodic(1, new int[] {1, 9}), new double[] {0, 1e-4, 0, 5e-6}, rows));
        assertEquals(0, Diagnoser.turningPoints(Effect.periodic(1, new int[] {1}), new double[] {1e-4, 0}, rows));
    }

    /** The local extrema of the world's error of joint 2 over the angles its training poses sample. */
    private static int extrema(JointError.Harmonics h, WorldCampaigns.Sim c) {
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
        for (var m : c.train().rows()) { lo = Math.min(lo, m.q(1)); hi = Math.max(hi, m.q(1)); }
        int n = 4000, count = 0;
        double[] q = new double[6];
        double prev = Double.NaN, slope = 0;
        for (int i = 0; i <= n; i++) {
            q[1] = lo + (hi - lo) * i / n;
            double y = h.delta(q, (JointError.Moment) null);
            if (i > 0) {
                double s = Math.signum(y - prev);
                if (s != 0 && slope != 0 && s != slope) count++;
                if (s != 0) slope = s;
            }
            prev = y;
        }
        return count;
    }

    /**
     * Joint 1's absolute encoder reads 0.05° off beyond one angle (a code-track defect): a Fourier
     * series of the step (harmonics 1-8) was named a transmission error and clean poses were
     * flagged. It is located as a jump of the reading at that angle and not named.
     */
    @Test
    void encoderStepAtOneAngleOfJoint1_isLocatedAsAJumpAndNotNamed() {
        for (long seed : new long[] {2, 5}) {
            WorldCampaigns.Sim c = world("irb2000", Expected.outside(), List.of(new JointError.AngleStep(0, Math.toRadians(38), Math.toRadians(-0.05))),
                    p -> p.withPoses(120, 0), seed);
            Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("irb2000"), c.train(), c.validation());
            assertEquals(List.of(), families(d), "seed " + seed + ": notes " + d.notes());
            assertTrue(d.located().stream().anyMatch(l -> l.shape().startsWith("joint 1's reading jumps where it passes")), d.located().toString());
            assertEquals(List.of(), d.outliers(), "seed " + seed + ": the campaign has no bad measurement; effects " + d.effects().stream()
                    .map(f -> f.effect().label()).toList() + ", notes " + d.notes());
        }
    }

    /**
     * The measured target knocked on the flange half-way through the campaign (0.3 mm, 0.05°): it was
     * missed (nothing located at 4.5 x the floor). It is located as the point moving on the flange at
     * about that time, and not named.
     */
    @Test
    void targetKnockedOnTheFlangeMidCampaign_isLocatedInTimeAndNotNamed() {
        Scenario s = new Scenario("knocked target", "outside", "puma560", Expected.outside(),
                (n, r) -> w -> w.withToolBump(new WorldRobot.ToolBump(1500, new double[] {0.25e-3, -0.13e-3, 0.1e-3},
                        new double[] {0, Math.toRadians(0.05), 0})), p -> p);
        WorldCampaigns.Sim c = WorldCampaigns.of(s.trial(4));
        double end = c.train().rows().stream().mapToDouble(m -> m.timeS()).max().orElse(0);
        assertTrue(end > 2500, "the knock falls inside the campaign: it lasts " + end + " s");
        Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("puma560"), c.train(), c.validation());
        assertEquals(List.of(), families(d), "notes " + d.notes());
        Diagnosis.Located l = d.located().stream().filter(x -> x.shape().startsWith("the measured point moved on the flange")).findFirst()
                .orElseThrow(() -> new AssertionError(d.located().toString()));
        double at = Double.parseDouble(l.shape().replaceAll(".*about (\\d+) s.*", "$1"));
        assertEquals(1500, at, 150, l.shape());
        assertEquals(List.of(), d.outliers(), "the campaign has no bad measurement");
    }

    /**
     * A gross error on a validation pose (2 mm, as on a training pose): it was not reported, and the
     * validation error it dominated stayed at 4.8 x the floor. It is reported as an outlier and left
     * out of the validation error, with a note; no clean pose is reported.
     */
    @Test
    void grossErrorOnAValidationPose_isReportedAndLeftOutOfTheValidationError() {
        WorldCampaigns.Sim c = world("irb2400", Expected.outside(), List.of(new JointError.Scale(0, 2e-4)), p -> p, 12);
        List<org.robopro.calibration.measurement.Measurement> rows = new ArrayList<>(c.validation().rows());
        var bad = rows.get(17);
        rows.set(17, bad.withPosition(bad.position().plus(new org.robopro.models.Vec3(1.2e-3, -1.0e-3, 1.3e-3))));
        var validation = new org.robopro.calibration.measurement.MeasurementSet(c.validation().source(), c.validation().metadata(),
                c.validation().frame(), rows);
        Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("irb2400"), c.train(), validation);
        assertEquals(List.of("joint-scale j1"), families(d), "notes " + d.notes());
        assertEquals(List.of(bad.poseId()), d.outliers());
        assertTrue(d.notes().stream().anyMatch(n -> n.startsWith("validation pose " + bad.poseId())), d.notes().toString());
        assertTrue(d.finalValidateRmsM() < 1.15 * c.floorM(), d.finalValidateRmsM() + " vs floor " + c.floorM());
    }

    /**
     * A narrow bump in joint 2's angle on the PUMA 560 (0.045°, 13° wide): more than 5 % of the poses
     * lie beyond 5 robust sigmas of the geometric fit, so the calibration only reports them, and
     * those poses were still left out and flagged as outliers (11 clean poses). None is flagged.
     */
    @Test
    void narrowBumpInJoint2_flagsNoCleanPose() {
        WorldCampaigns.Sim c = world("puma560", Expected.outside(), List.of(new JointError.Bump(1, Math.toRadians(53), Math.toRadians(13),
                Math.toRadians(0.045))), p -> p.withPoses(160, 90), 6);
        Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("puma560"), c.train(), c.validation());
        assertEquals(List.of(), families(d), "notes " + d.notes());
        assertTrue(d.located().stream().anyMatch(l -> l.variable().equals("joint 2 angle")), d.located().toString());
        assertEquals(List.of(), d.outliers(), "the campaign has no bad measurement");
    }

    /**
     * One bump of joint 2's angle on the IRB 2000 (0.05°, 8° wide, about 40°), 300 poses and 100
     * validation poses: two harmonic series of joint 2 (one of ten harmonics up to 21 cycles a turn)
     * add up to it and predict the validation poses well. A gear's error repeats over the turn; this
     * one lies in one place, so no gear is named, and the notes say where it lies.
     */
    @Test
    void bumpAtOneAngleOfJoint2_isNotNamedAGearsPeriodicError() {
        WorldCampaigns.Sim c = world("irb2000", Expected.outside(), List.of(new JointError.Bump(1, Math.toRadians(40), Math.toRadians(8),
                Math.toRadians(0.05))), p -> p.withPoses(300, 100), 4);
        Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("irb2000"), c.train(), c.validation());
        assertEquals(List.of(), families(d), "notes " + d.notes());
        assertTrue(d.notes().stream().anyMatch(n -> n.contains("adds up to one local error about 39")), d.notes().toString());
        assertTrue(d.located().stream().anyMatch(l -> l.variable().equals("joint 2 angle")), d.located().toString());
    }

    /**
     * A gas-spring balancer on joint 2 (its torque a non-linear function of the joint's own angle,
     * not the arm's weight) bends the drive: over joint 2's sampled 200 degrees, harmonics 1-3 of its
     * angle follow that curve as closely as a smooth curve does, and nothing in the data shows them
     * repeat. Before the claim check asked a transmission error of a few harmonics on a joint sampled
     * over less than a turn to beat the smooth curve clearly, the world's balancer was named
     * `gear-periodic j2` on four of five draws.
     */
    @Test
    void balancerOnJoint2_isNotNamedAGearsPeriodicError() {
        for (long seed : new long[] {2, 6}) {
            WorldCampaigns.Sim c = world("irb2000", Expected.outside(), List.of(new JointError.GasSpring(1, 0.15, 0.35, Math.toRadians(100),
                    3000, 0.2 / 3, 1.3, 1.2e6)), p -> p.withPoses(300, 100), seed);
            Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("irb2000"), c.train(), c.validation());
            assertEquals(List.of(), families(d), "seed " + seed + ": notes " + d.notes());
            assertTrue(d.located().stream().anyMatch(l -> l.variable().equals("joint 2 angle")), "seed " + seed + ": " + d.located());
        }
    }

    /**
     * The floor under the robot tilts as it warms, turning the robot about a floor point beside its
     * base while the instrument stands still. A drift of the instrument in proportion to the
     * temperature holds the move of the base's origin but not the turn; before the base's turn stood
     * against a named drift, the world's tilting floor was named `instrument-drift` on five draws of
     * five and left 1.2-1.4 times the noise floor on the validation poses (the world's scenario, five draws).
     */
    @Test
    void floorTilting_isNotNamedAnInstrumentDrift() {
        var tilt = new WorldRobot.FloorTilt(Math.toRadians(30), new double[] {0.5, 0.2, 0}, 150e-6, 2000);
        Scenario s = new Scenario("floor tilt", "outside", "irb2000", Expected.outside(), (n, r) -> w -> w.withFloorTilt(tilt),
                p -> p.withPoses(300, 100));
        WorldCampaigns.Sim c = WorldCampaigns.of(s.trial(3));
        Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("irb2000"), c.train(), c.validation());
        assertEquals(List.of(), families(d), "notes " + d.notes());
        assertTrue(d.effects().stream().anyMatch(f -> f.effect().kind() == Effect.Kind.BASE_TURN), d.effects().toString());
        assertTrue(d.finalValidateRmsM() < 1.15 * Math.sqrt(3) * 0.02e-3 && d.finalValidateRmsM() < d.geometricValidateRmsM(),
                "validation RMS " + d.geometricValidateRmsM() + " -> " + d.finalValidateRmsM());
        // the evidence plot shows the floor's turn growing: the world's angle between the coolest and the warmest pose
        Diagnosis.Plot p = d.effects().stream().filter(f -> f.effect().kind() == Effect.Kind.BASE_TURN).findFirst().orElseThrow().plot();
        double[] cx = p.curveX(), cy = p.curveY();
        List<org.robopro.calibration.measurement.Measurement> all = new ArrayList<>(c.train().rows());
        all.addAll(c.validation().rows());
        all.sort(java.util.Comparator.comparingDouble(org.robopro.calibration.measurement.Measurement::tempC));
        double t0 = all.get(0).timeS(), t1 = all.get(all.size() - 1).timeS();
        double grown = Math.toDegrees(tilt.maxRad() * (Math.exp(-t0 / tilt.tauS()) - Math.exp(-t1 / tilt.tauS()))) * 1e3;
        assertEquals(0, cy[0], 1e-12);
        assertEquals(grown, cy[cy.length - 1], 0.25 * grown, p.yLabel() + " against " + p.xLabel() + " " + cx[0] + ".." + cx[cx.length - 1]);
        // about the world's axis, 30 degrees from the base's x axis (the label gives the axis in base coordinates)
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("\\(([-0-9.]+), ([-0-9.]+), ([-0-9.]+)\\)").matcher(p.yLabel());
        assertTrue(m.find(), p.yLabel());
        double along = Double.parseDouble(m.group(1)) * Math.cos(tilt.azimuth()) + Double.parseDouble(m.group(2)) * Math.sin(tilt.azimuth());
        assertTrue(along > 0.9, p.yLabel());
    }

    /**
     * A coupling of joint 6 from joint 4 and a lost motion of joint 5 in 6-D: both turn the tool many
     * times more than they move it: the geometric fit's ratio of the rotations' σ to the positions' is
     * 17 rad/m on this draw, the noise's 1.75 (0.002° against 0.02 mm). Weighted by them, the rotation rows carried almost
     * nothing once the two were modelled, and the F tests, counting those rows as noise, made 39
     * cycles per turn of joint 4 a located structure on this draw (held-out sets showed a coupling of
     * joint 3 from joint 1 named the same way). Weighted by the ratio the model leaves, nothing is
     * left, and the model predicts the validation poses as well as the twin without the two effects.
     */
    @Test
    void wristPairIn6D_leavesNoStructureOnceTheRotationsAreWeightedByTheirNoise() {
        WorldCampaigns.Sim c = WorldCampaigns.of(Scenario.named("cross-coupling j6<-j4 + lost motion j5, 6-D").trial(20261135));
        Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("irb2000"), c.train(), c.validation());
        assertEquals(java.util.Set.of("joint-coupling j6<-j4", "backlash j5"), java.util.Set.copyOf(families(d)), "notes " + d.notes());
        assertEquals(List.of(), d.located().stream().filter(l -> l.explainedBy() == null).map(Diagnosis.Located::shape).toList(),
                "structure no named effect explains");
        assertTrue(d.finalValidateRmsM() < 1.15 * c.floorM(), d.finalValidateRmsM() + " vs floor " + c.floorM());
    }

    /**
     * The air the tracker's beam crosses warms against its weather station's reading, so every
     * distance comes out short by 0.93 ppm per kelvin, more as the hall warms: the positions scale
     * about the instrument with time. A robot growing uniformly and the instrument drifting toward
     * it hold that only together, and before the instrument's scale was a candidate the world's
     * draw was named `instrument-drift` (as were all of the scenario's first five draws). It is
     * located as the instrument's, and its evidence plot changes by the world's scale over the readings.
     */
    @Test
    void trackersAirCompensationDrifting_isTheInstrumentsScaleNotADriftOrAGrowth() {
        WorldCampaigns.Sim c = WorldCampaigns.of(Scenario.named("outside: the tracker's air compensation drifts as the hall warms").trial(20261126));
        Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("irb2000"), c.train(), c.validation());
        assertEquals(List.of(), families(d), "notes " + d.notes());
        Diagnosis.Finding f = d.effects().stream().filter(x -> x.effect().kind() == Effect.Kind.INSTRUMENT_SCALE).findFirst()
                .orElseThrow(() -> new AssertionError(d.effects().toString()));
        // the world's scale between the poses at the two ends of the effect's reading (time, or temperature: the poses' times)
        List<org.robopro.calibration.measurement.Measurement> all = new ArrayList<>(c.train().rows());
        all.addAll(c.validation().rows());
        boolean time = f.effect().along() == Effect.Along.TIME;
        all.sort(java.util.Comparator.comparingDouble(m -> time ? m.timeS() : m.tempC()));
        WorldRobot.Tracker t = c.world().tracker();
        java.util.function.DoubleUnaryOperator scale = ts -> WorldRobot.Tracker.INDEX_PER_K * t.airWarmK() * (1 - Math.exp(-ts / t.airTauS()));
        double grown = 1e6 * (scale.applyAsDouble(all.get(all.size() - 1).timeS()) - scale.applyAsDouble(all.get(0).timeS()));
        double[] cy = f.plot().curveY();
        assertTrue(grown < 0, "the distances come out shorter as the beam's air warms: " + grown);
        assertEquals(grown, cy[cy.length - 1] - cy[0], 0.3 * Math.abs(grown), f.plot().yLabel());
        assertTrue(d.finalValidateRmsM() < d.geometricValidateRmsM(),
                "validation RMS " + d.geometricValidateRmsM() + " -> " + d.finalValidateRmsM());
    }

    /**
     * Joint 2's zero moving with its drive's temperature, without payload steps: a transmission
     * error of joint 2 passed the tests first and was withdrawn because a deflection under the arm's
     * weight predicted as well; nothing then modelled the structure, and the validation poses stayed
     * at 2.8 × the noise floor (the twin at 1.06) with advice to measure payload steps. What a
     * withdrawn family held is now looked for among the located structures of its drive: the zero's
     * drift with temperature models it, and no advice about a deflection is given.
     */
    @Test
    void zeroMovingWithTemperature_isModelledWhereAWithdrawnGearErrorStood() {
        WorldCampaigns.Sim c = WorldCampaigns.of(Scenario.named("outside: j2 zero moving with drive temperature").trial(20261124));
        Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("irb2000"), c.train(), c.validation());
        assertEquals(List.of(), families(d), "notes " + d.notes());
        assertTrue(d.effects().stream().anyMatch(f -> f.effect().kind() == Effect.Kind.ZERO_DRIFT && f.effect().joint() == 1), d.effects().toString());
        assertTrue(d.finalValidateRmsM() < 1.15 * c.floorM(), d.finalValidateRmsM() + " vs floor " + c.floorM());
        assertTrue(d.recommendations().stream().noneMatch(r -> r.contains("deflection under the arm's weight")), d.recommendations().toString());
    }

    /**
     * Joint 2's error depending on joints 2 and 4 together, 6-D: the two-joint fallback was
     * significant at the first step but had no physical bound, so it was listed among the
     * implausible findings; no family was named for it to take the place of, and nothing modelled
     * the structure (1.9 × the floor left, the twin at 0.99). Where nothing is modelled though the
     * geometric fit left located structure, the located structures' fallbacks are now tried.
     */
    @Test
    void errorOfTwoJointsAlone_isModelledNotListedAsImplausible() {
        WorldCampaigns.Sim c = WorldCampaigns.of(Scenario.named("outside: j2 error depending on j2 and j4, 6-D").trial(20261124));
        Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("irb2000"), c.train(), c.validation());
        assertEquals(List.of(), families(d), "notes " + d.notes());
        assertEquals(List.of(), d.implausible().stream().filter(f -> f.effect().isFallback()).map(f -> f.effect().label()).toList());
        assertTrue(d.effects().stream().anyMatch(f -> f.effect().kind() == Effect.Kind.PAIR && f.effect().joint() == 1), d.effects().toString());
        assertTrue(d.finalValidateRmsM() < 1.15 * c.floorM(), d.finalValidateRmsM() + " vs floor " + c.floorM());
    }

    /**
     * The same bump with 92 poses and no validation poses: the poses on its peak lie 5 to 33 robust
     * sigmas off the fallback that models the rest of it (a smooth curve or a window of joint 2's
     * reading, coarser than the bump), all of them within a band of joint 2's angle a few degrees
     * wide. Bad readings fall on poses at random, so none of them is reported as one.
     */
    @Test
    void bumpAtOneAngleOfJoint2_posesOnItsPeakAreNoBadReadings() {
        for (long seed : new long[] {3, 5}) {
            WorldCampaigns.Sim c = world("irb2000", Expected.outside(), List.of(new JointError.Bump(1, Math.toRadians(40), Math.toRadians(8),
                    Math.toRadians(0.05))), p -> p.withPoses(92, 0), seed);
            Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("irb2000"), c.train(), null);
            assertEquals(List.of(), families(d), "seed " + seed + ": notes " + d.notes());
            assertEquals(List.of(), d.outliers(), "seed " + seed + ": the campaign has no bad measurement; notes " + d.notes());
            assertTrue(d.notes().stream().anyMatch(n -> n.contains("within one band of q2")), "seed " + seed + ": " + d.notes());
        }
    }

    /**
     * The PUMA's drive 2 giving way under gravity (world masses off by up to 30 %, one payload): on
     * this campaign its own angle's smooth curve predicts left-out poses as well as the compliance,
     * so the compliance is not claimed; the notes say why and what to measure (payload steps).
     */
    @Test
    void complianceNotToldFromAnAngleErrorWithOnePayload_saysToVaryThePayload() {
        WorldCampaigns.Sim c = WorldCampaigns.of(Scenario.named("joint elasticity j2 puma560, masses off 30 %").trial(20261125));
        Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("puma560"), c.train(), c.validation());
        assertEquals(List.of(), families(d), "notes " + d.notes());
        assertTrue(d.notes().stream().anyMatch(n -> n.startsWith("joint-compliance j2") && n.contains("is not claimed")
                && n.contains("measure with two or three payloads")), d.notes().toString());
    }

    /** The effects of {@code kind} the diagnosis modelled, as labels. */
    static List<String> modelled(Diagnosis d, Effect.Kind kind) {
        return d.effects().stream().filter(f -> f.effect().kind() == kind).map(f -> f.effect().label()).toList();
    }

    /**
     * Joint 2 of the IRB 2000 softening as it warms (the world's spring of 300 kN·m/rad on masses
     * 30 % off the file's, 5 % softer per kelvin of the campaign's warm-up, the temperature the
     * campaign reads): the catalogue's compliance has one stiffness, so none is named; a compliance
     * that changes through the campaign models it, and the validation error comes within 1.15 x the
     * floor.
     */
    @Test
    void jointSofteningAsItWarms_isAVaryingCompliance() {
        var n = RobotLibrary.shipped("irb2000");
        double k = 3e5;
        for (long seed : new long[] {1, 2}) {
            Scenario s = scenario("softening joint", "irb2000", Expected.outside(), w -> {
                var m = WorldRobot.Compliance.fromFile(n.massModel().orElseThrow(), n.dof(), 0.3, new java.util.Random(seed)).withStiffness(1, k);
                return withErrors(List.of(new JointError.WarmSoftening(1, k, 0.05, 20))).apply(w.withCompliance(m));
            }, p -> p);
            WorldCampaigns.Sim c = WorldCampaigns.of(s.trial(seed));
            Diagnosis d = Diagnoser.diagnose(n, c.train(), c.validation());
            System.out.printf("softening seed %d: %.2f -> %.2f x the floor %s%n", seed, d.geometricValidateRmsM() / c.floorM(),
                    d.finalValidateRmsM() / c.floorM(), d.effects().stream().map(f -> f.effect().label()).toList());
            assertEquals(List.of(), families(d), "seed " + seed + ": notes " + d.notes());
            assertTrue(modelled(d, Effect.Kind.COMPLIANCE_VARYING).stream().anyMatch(l -> l.contains(" j2 ")),
                    "seed " + seed + ": " + d.effects().stream().map(f -> f.effect().label()).toList());
            assertTrue(d.geometricValidateRmsM() > 3 * c.floorM(), "the softening matters: " + d.geometricValidateRmsM() / c.floorM());
            assertTrue(d.finalValidateRmsM() < 1.15 * c.floorM(), "seed " + seed + ": " + d.finalValidateRmsM() / c.floorM() + " x the floor");
        }
    }

    /**
     * A dispensing tool on the IRB 2400 (the world's springs of joints 2 and 3 under the payload alone,
     * the arm's own weight balanced, the payload's centre where the robot file puts it): it carries 10 kg
     * at the start and 2 kg after an hour, while the file records 10 kg throughout. The payload's torque changes with time, which no stiffness does:
     * nothing is named, a compliance under the payload that changes with time models it.
     */
    @Test
    void dispensingTool_isAPayloadComplianceChangingWithTime() {
        double inf = Double.POSITIVE_INFINITY;
        // the payload's centre where the robot file puts it (the flange, for a file without masses): the tool's data gives it
        var cmp = new WorldRobot.Compliance(new double[] {inf, 2e5, 1e5, inf, inf, inf}, List.of(), new double[] {0, 0, 0},
                new double[] {0, 0, -9.80665});
        for (long seed : new long[] {1, 2}) {
            Scenario s = scenario("dispensing tool", "irb2400", Expected.outside(),
                    w -> w.withCompliance(cmp).withDispensing(new WorldRobot.Dispensing(new double[] {0, 3600}, new double[] {10, 2})),
                    p -> p.withPayloads(10));
            WorldCampaigns.Sim c = WorldCampaigns.of(s.trial(seed));
            Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("irb2400"), c.train(), c.validation());
            System.out.printf("dispensing seed %d: %.2f -> %.2f x the floor %s%n", seed, d.geometricValidateRmsM() / c.floorM(),
                    d.finalValidateRmsM() / c.floorM(), d.effects().stream().map(f -> f.effect().label()).toList());
            assertEquals(List.of(), families(d), "seed " + seed + ": notes " + d.notes());
            assertTrue(modelled(d, Effect.Kind.COMPLIANCE_VARYING).stream().anyMatch(l -> l.contains("payload")),
                    "seed " + seed + ": " + d.effects().stream().map(f -> f.effect().label()).toList());
            assertTrue(d.geometricValidateRmsM() > 2 * c.floorM(), "the dispensing matters: " + d.geometricValidateRmsM() / c.floorM());
            assertTrue(d.finalValidateRmsM() < 1.15 * c.floorM(), "seed " + seed + ": " + d.finalValidateRmsM() / c.floorM() + " x the floor");
        }
    }

    /**
     * The dispensing tool with its reservoir off the flange (its centre 30 mm across and 70 mm along the
     * tool, where the file puts it at the flange): the payload's torque has another phase in joint 5's
     * angle, which the file's centre cannot follow. Nothing is named; the payload's compliance with the
     * centre estimated models it, and the validation error ends within 1.25 x the floor (from 5 x).
     */
    @Test
    void dispensingToolOffTheFlange_estimatesThePayloadsCentre() {
        double inf = Double.POSITIVE_INFINITY;
        var cmp = new WorldRobot.Compliance(new double[] {inf, 2e5, 1e5, inf, inf, inf}, List.of(), new double[] {0.0, 0.03, 0.07},
                new double[] {0, 0, -9.80665});
        for (long seed : new long[] {1, 2, 3}) {
            Scenario s = scenario("dispensing tool off the flange", "irb2400", Expected.outside(),
                    w -> w.withCompliance(cmp).withDispensing(new WorldRobot.Dispensing(new double[] {0, 3600}, new double[] {10, 2})),
                    p -> p.withPayloads(10));
            WorldCampaigns.Sim c = WorldCampaigns.of(s.trial(seed));
            Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("irb2400"), c.train(), c.validation());
            List<String> labels = d.effects().stream().map(f -> f.effect().label()).toList();
            System.out.printf("dispensing off the flange seed %d: %.2f -> %.2f x the floor %s%n", seed, d.geometricValidateRmsM() / c.floorM(),
                    d.finalValidateRmsM() / c.floorM(), labels);
            assertEquals(List.of(), families(d), "seed " + seed + ": notes " + d.notes());
            assertTrue(d.effects().stream().anyMatch(f -> f.effect().kind() == Effect.Kind.COMPLIANCE_VARYING && f.effect().payloadCentreFree()),
                    "seed " + seed + ": " + labels);
            assertTrue(d.geometricValidateRmsM() > 3 * c.floorM(), "the dispensing matters: " + d.geometricValidateRmsM() / c.floorM());
            assertTrue(d.finalValidateRmsM() < 1.25 * c.floorM(), "seed " + seed + ": " + d.finalValidateRmsM() / c.floorM() + " x the floor");
        }
    }

    /**
     * The same tool emptied in two shots (10 kg, then 5 kg from 1100 s, then 2 kg from 2300 s) while the
     * file records 10 kg: a spline of the time follows a step only so sharply; the payload's compliance
     * stepping near the world's moments models it, nothing is named, and no clean pose is reported as
     * a bad reading.
     */
    @Test
    void dispensingToolInShots_isAPayloadComplianceSteppingAtTheShots() {
        double inf = Double.POSITIVE_INFINITY;
        var cmp = new WorldRobot.Compliance(new double[] {inf, 2e5, 1e5, inf, inf, inf}, List.of(), new double[] {0, 0, 0},
                new double[] {0, 0, -9.80665});
        var shots = new WorldRobot.Dispensing(new double[] {1100, 1101, 2300, 2301}, new double[] {10, 5, 5, 2});
        for (long seed : new long[] {1, 2}) {
            Scenario s = scenario("dispensing tool in shots", "irb2400", Expected.outside(), w -> w.withCompliance(cmp).withDispensing(shots),
                    p -> p.withPayloads(10));
            WorldCampaigns.Sim c = WorldCampaigns.of(s.trial(seed));
            Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("irb2400"), c.train(), c.validation());
            List<String> labels = d.effects().stream().map(f -> f.effect().label()).toList();
            System.out.printf("dispensing in shots seed %d: %.2f -> %.2f x the floor %s%n", seed, d.geometricValidateRmsM() / c.floorM(),
                    d.finalValidateRmsM() / c.floorM(), labels);
            assertEquals(List.of(), families(d), "seed " + seed + ": notes " + d.notes());
            List<double[]> steps = d.effects().stream().map(f -> f.effect())
                    .filter(e -> e.kind() == Effect.Kind.COMPLIANCE_VARYING && e.stepTimes() != null).map(Effect::stepTimes).toList();
            assertFalse(steps.isEmpty(), "seed " + seed + ": " + labels);
            // a joint's steps within 60 s of both shots (poses are 10-20 s apart; a joint that the payload loads little over the
            // poses near a shot may put its step some poses off)
            assertTrue(steps.stream().anyMatch(t -> Arrays.stream(new double[] {1100, 2300})
                            .allMatch(shot -> Arrays.stream(t).anyMatch(x -> Math.abs(x - shot) < 60))),
                    "seed " + seed + ": steps " + steps.stream().map(Arrays::toString).toList());
            assertEquals(List.of(), d.outliers(), "seed " + seed);
            assertTrue(d.geometricValidateRmsM() > 2 * c.floorM(), "the dispensing matters: " + d.geometricValidateRmsM() / c.floorM());
            assertTrue(d.finalValidateRmsM() < 1.15 * c.floorM(), "seed " + seed + ": " + d.finalValidateRmsM() / c.floorM() + " x the floor");
        }
    }

    /**
     * Joint 1 of the IRB 2000 and joint 2 of the PUMA 560 read by an encoder whose sine channel's gain
     * drifts from the cosine's by 4·10⁻⁵ per kelvin (1.2·10⁻⁴ on the PUMA's shorter arm), matched at 22 °C (the world inverts q = atan2((1 + g)
     * sin θ, cos θ) exactly): an error twice a turn whose size follows the warm-up. No transmission
     * error keeps that size, so nothing is named; the second order growing with the temperature models
     * it.
     */
    @Test
    void encoderChannelsDriftingApart_isAPeriodicErrorGrowingWithTemperature() {
        record Case(String robot, int joint, double perK) { }
        for (Case cs : List.of(new Case("irb2000", 0, 4e-5), new Case("puma560", 1, 1.2e-4))) {
            WorldCampaigns.Sim c = world(cs.robot(), Expected.outside(), List.of(new JointError.QuadratureGain(cs.joint(), cs.perK(), 22)), p -> p, 3);
            Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped(cs.robot()), c.train(), c.validation());
            System.out.printf("encoder gains %s: %.2f -> %.2f x the floor %s%n", cs.robot(), d.geometricValidateRmsM() / c.floorM(),
                    d.finalValidateRmsM() / c.floorM(), d.effects().stream().map(f -> f.effect().label()).toList());
            assertEquals(List.of(), families(d), cs.robot() + ": notes " + d.notes());
            assertTrue(modelled(d, Effect.Kind.WARM_PERIODIC).contains("joint-periodic-warming j" + (cs.joint() + 1) + " (h 2)"),
                    d.effects().stream().map(f -> f.effect().label()).toList().toString());
            assertTrue(d.geometricValidateRmsM() > 2 * c.floorM(), "the error matters: " + d.geometricValidateRmsM() / c.floorM());
            assertTrue(d.finalValidateRmsM() < 1.15 * c.floorM(), cs.robot() + ": " + d.finalValidateRmsM() / c.floorM() + " x the floor");
        }
    }

    /**
     * Joint 5's drive through a bearing seat in joint 4's housing out of round (the world's gear mesh:
     * e cos 2(q4 − β) tan 20° / 25 mm; 35 µm, about 0.03°, on the IRB 2400, 90 µm on the PUMA 560,
     * whose short wrist shows less of it at the target): the error repeats twice per turn of the housing's joint, not with the drive's
     * own angle, so nothing is named; the housing angle's second harmonic models it. (Joint 6 turns the
     * world's target about its own axis, where an error of joint 6 does not move it.)
     */
    @Test
    void driveThroughAnOvalSeat_repeatsWithTheHousingsAngle() {
        record Case(String robot, int joint, int housing, double ovality) { }
        for (Case cs : List.of(new Case("irb2400", 4, 3, 35e-6), new Case("puma560", 4, 3, 90e-6))) {
            WorldCampaigns.Sim c = world(cs.robot(), Expected.outside(),
                    List.of(new JointError.OvalSeat(cs.joint(), cs.housing(), cs.ovality(), Math.toRadians(20), 0.025, 0.4)), p -> p, 3);
            Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped(cs.robot()), c.train(), c.validation());
            System.out.printf("oval seat %s: %.2f -> %.2f x the floor %s%n", cs.robot(), d.geometricValidateRmsM() / c.floorM(),
                    d.finalValidateRmsM() / c.floorM(), d.effects().stream().map(f -> f.effect().label()).toList());
            assertEquals(List.of(), families(d), cs.robot() + ": notes " + d.notes());
            assertEquals(List.of("link-angle-periodic j" + (cs.joint() + 1) + " (q" + (cs.housing() + 1) + ", h 2)"),
                    modelled(d, Effect.Kind.LINK_PERIODIC), d.effects().stream().map(f -> f.effect().label()).toList().toString());
            assertTrue(d.geometricValidateRmsM() > 2 * c.floorM(), "the error matters: " + d.geometricValidateRmsM() / c.floorM());
            assertTrue(d.finalValidateRmsM() < 1.15 * c.floorM(), cs.robot() + ": " + d.finalValidateRmsM() / c.floorM() + " x the floor");
        }
    }

    /**
     * Joint 3's error repeating five times per turn of the forearm's angle to the upper arm (q3 − q2
     * on the IRB 2400's parallel arm, 0.015°) and four times per turn of its angle to the ground on the
     * PUMA 560 (q2 + q3, 0.02°): no function of joint 3's own angle holds it, and a transmission error
     * repeats with its drive's turn, so nothing is named; the link angle's harmonic models it at the
     * world's order.
     */
    @Test
    void errorRepeatingWithALinkAngle_isLocatedAtItsOrder() {
        record Case(String robot, double sign, int k, double deg) { }
        for (Case cs : List.of(new Case("irb2400", -1, 5, 0.015), new Case("puma560", 1, 4, 0.02))) {
            WorldCampaigns.Sim c = world(cs.robot(), Expected.outside(),
                    List.of(new JointError.LinkHarmonic(2, 1, cs.sign(), cs.k(), Math.toRadians(cs.deg()), 0.7)), p -> p, 3);
            Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped(cs.robot()), c.train(), c.validation());
            System.out.printf("link harmonic %s: %.2f -> %.2f x the floor %s%n", cs.robot(), d.geometricValidateRmsM() / c.floorM(),
                    d.finalValidateRmsM() / c.floorM(), d.effects().stream().map(f -> f.effect().label()).toList());
            assertEquals(List.of(), families(d), cs.robot() + ": notes " + d.notes());
            String angle = cs.sign() < 0 ? "−q2 + q3" : "q2 + q3";
            assertEquals(List.of("link-angle-periodic j3 (" + angle + ", h " + cs.k() + ")"), modelled(d, Effect.Kind.LINK_PERIODIC),
                    d.effects().stream().map(f -> f.effect().label()).toList().toString());
            assertTrue(d.geometricValidateRmsM() > 2 * c.floorM(), "the error matters: " + d.geometricValidateRmsM() / c.floorM());
            assertTrue(d.finalValidateRmsM() < 1.15 * c.floorM(), cs.robot() + ": " + d.finalValidateRmsM() / c.floorM() + " x the floor");
        }
    }

    /**
     * The IRB 2000 measured from 10 m through air whose vertical temperature gradient grows from 0.3
     * to 2.5 K/m over the campaign (the world bends the line of sight in its vertical plane): no
     * error of the robot, and no drift of the instrument, is named; the beam's refraction changing
     * with time models it, and the validation error comes within 1.15 x the floor.
     */
    @Test
    void beamBentByTheAirsGradient_isRefractionNotADrift() {
        for (long seed : new long[] {1, 2}) {
            Scenario s = scenario("refraction", "irb2000", Expected.outside(), w -> {
                org.robopro.world.Rigid far = org.robopro.world.Rigid.translation(10, 2, 0.5)
                        .times(org.robopro.world.Rigid.rotation(new double[] {0, 0, 1}, 0.4, new double[3]));
                return w.withInstrument(far.inverse()).withRefraction(new WorldRobot.Refraction(new double[] {0, 3600}, new double[] {0.3, 2.5}));
            }, p -> p.withSigma(0.005e-3));
            WorldCampaigns.Sim c = WorldCampaigns.of(s.trial(seed));
            Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("irb2000"), c.train(), c.validation());
            System.out.printf("refraction seed %d: %.2f -> %.2f x the floor %s%n", seed, d.geometricValidateRmsM() / c.floorM(),
                    d.finalValidateRmsM() / c.floorM(), d.effects().stream().map(f -> f.effect().label()).toList());
            assertEquals(List.of(), families(d), "seed " + seed + ": notes " + d.notes());
            assertTrue(!modelled(d, Effect.Kind.REFRACTION).isEmpty(), "seed " + seed + ": " + d.effects().stream().map(f -> f.effect().label()).toList());
            assertTrue(d.geometricValidateRmsM() > 2 * c.floorM(), "the refraction matters: " + d.geometricValidateRmsM() / c.floorM());
            assertTrue(d.finalValidateRmsM() < 1.15 * c.floorM(), "seed " + seed + ": " + d.finalValidateRmsM() / c.floorM() + " x the floor");
        }
    }

    /**
     * A cable retractor on a boom beside the cell pulling the tool with 40 N toward its anchor, every
     * drive yielding through its own stiffness (the world's moments of the pull about its own joint
     * axes): no family is named (a joint's spring under the arm's weight pulls straight down), the
     * pull is modelled with its anchor found within a few decimetres, and the validation poses come
     * to the floor. On the PUMA 560 too.
     */
    @Test
    void cableRetractorPullingTheTool_isAPullTowardItsAnchor() {
        double[] anchor = {1.6, -1.4, 1.7};
        var x = new WorldRobot.Retractor(anchor, 40, new double[] {4e5, 3e5, 3e5, 3e4, 3e4, 3e4});
        for (String robot : List.of("irb2400", "puma560")) {
            WorldCampaigns.Sim c = WorldCampaigns.of(scenario("cable retractor", robot, Expected.outside(), w -> w.withRetractor(x), p -> p).trial(5));
            Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped(robot), c.train(), c.validation());
            List<String> pulls = modelled(d, Effect.Kind.TOOL_PULL);
            System.out.printf("retractor %s: %.2f -> %.2f x the floor %s%n", robot, d.geometricValidateRmsM() / c.floorM(),
                    d.finalValidateRmsM() / c.floorM(), d.effects().stream().map(f -> f.effect().label()).toList());
            assertEquals(List.of(), families(d), robot + ": notes " + d.notes());
            assertEquals(1, pulls.size(), robot + ": " + d.effects().stream().map(f -> f.effect().label()).toList());
            double[] found = d.effects().stream().filter(f -> f.effect().kind() == Effect.Kind.TOOL_PULL).findFirst().orElseThrow().effect().pullAnchor();
            // the anchor seen from the tool: its direction within 10 deg
            double[] toTrue = {anchor[0] - 0.8, anchor[1], anchor[2] - 0.8}, toFound = {found[0] - 0.8, found[1], found[2] - 0.8};
            double cos = (toTrue[0] * toFound[0] + toTrue[1] * toFound[1] + toTrue[2] * toFound[2])
                    / Math.sqrt((toTrue[0] * toTrue[0] + toTrue[1] * toTrue[1] + toTrue[2] * toTrue[2]) * (toFound[0] * toFound[0] + toFound[1] * toFound[1] + toFound[2] * toFound[2]));
            assertTrue(cos > Math.cos(Math.toRadians(10)), robot + ": anchor " + Arrays.toString(found));
            assertTrue(d.geometricValidateRmsM() > 1.3 * c.floorM(), "the pull matters: " + d.geometricValidateRmsM() / c.floorM());
            assertTrue(d.finalValidateRmsM() < 1.15 * c.floorM(), robot + ": " + d.finalValidateRmsM() / c.floorM() + " x the floor");
        }
    }

    /**
     * The PUMA 560's joint 3 shaft tilting under its gear mesh's forces (the world's turn of the distal
     * chain about its bearing's centre by its own gravity torque, masses 30 % off the file's; 1.2·10⁻⁵
     * rad per N·m, about 0.4 mrad at the largest torque), measured finely (σ 5 µm): the coupling of joint
     * 3 from joint 2 that such a campaign of set AD was named is not named, nor anything else, and the axis's
     * tilt with the torque models it to the floor.
     */
    @Test
    void shaftTiltingUnderItsMeshForces_isNotACoupling() {
        Scenario s = new Scenario("shaft tilt", "outside", "puma560", Expected.outside(), (n, r) -> {
            var m = WorldRobot.Compliance.fromFile(n.massModel().orElseThrow(), n.dof(), 0.3, r);
            var t = new WorldRobot.ShaftTilt(2, 1.2e-5, Math.toRadians(20), 1.1, 0.02);
            return w -> w.withCompliance(m).withShaftTilt(t);
        }, p -> p.withSigma(0.005e-3));
        WorldCampaigns.Sim c = WorldCampaigns.of(s.trial(7));
        Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("puma560"), c.train(), c.validation());
        System.out.printf("shaft tilt puma560 j3: %.2f -> %.2f x the floor %s%n", d.geometricValidateRmsM() / c.floorM(),
                d.finalValidateRmsM() / c.floorM(), d.effects().stream().map(f -> f.effect().label()).toList());
        assertEquals(List.of(), families(d), "notes " + d.notes());
        assertTrue(d.geometricValidateRmsM() > 2 * c.floorM(), "the tilt matters: " + d.geometricValidateRmsM() / c.floorM());
        assertTrue(d.finalValidateRmsM() < 1.15 * c.floorM(), d.finalValidateRmsM() / c.floorM() + " x the floor");
    }

    /**
     * Two laser trackers in one network, each pose read by the one its target faces better, the second's
     * registration off by 80 µrad and 50 µm: nothing is named, the second station's split is modelled with
     * the second station placed within half a metre of where it stands, and the validation poses come to
     * the floor.
     */
    @Test
    void secondTrackerReadingThePosesFacingIt_isTheStationsRegistration() {
        double[] second = {-0.4, 2.5, 0.6};
        var x = new WorldRobot.Network(second, new double[] {50e-6, -60e-6, 20e-6}, new double[] {30e-6, -40e-6, 10e-6});
        WorldCampaigns.Sim c = WorldCampaigns.of(scenario("two trackers", "irb2000", Expected.outside(), w -> w.withNetwork(x), p -> p).trial(3));
        Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("irb2000"), c.train(), c.validation());
        System.out.printf("two trackers irb2000: %.2f -> %.2f x the floor %s%n", d.geometricValidateRmsM() / c.floorM(),
                d.finalValidateRmsM() / c.floorM(), d.effects().stream().map(f -> f.effect().label()).toList());
        assertEquals(List.of(), families(d), "notes " + d.notes());
        Effect station = d.effects().stream().filter(f -> f.effect().kind() == Effect.Kind.SECOND_STATION).findFirst().orElseThrow().effect();
        double[] at = station.stations();
        assertTrue(at != null && Math.hypot(Math.hypot(at[3] - second[0], at[4] - second[1]), at[5] - second[2]) < 0.5,
                "the second station placed " + (at == null ? "by its side only" : Arrays.toString(Arrays.copyOfRange(at, 3, 6))));
        assertTrue(d.geometricValidateRmsM() > 2 * c.floorM(), "the registration matters: " + d.geometricValidateRmsM() / c.floorM());
        assertTrue(d.finalValidateRmsM() < 1.15 * c.floorM(), d.finalValidateRmsM() / c.floorM() + " x the floor");
    }
}
