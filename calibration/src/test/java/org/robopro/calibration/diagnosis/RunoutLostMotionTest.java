package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.robopro.calibration.PoseConditions;
import org.robopro.calibration.WorldCampaigns;
import org.robopro.kinematics.KinematicModel;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
import org.robopro.world.JointError;
import org.robopro.world.Scenario;

/**
 * Lost motion whose play changes over the turn of its joint, against the independent world's
 * truth: an output gear that runs off its bearing's centre, the play changing with the centre
 * distance by 2·Δa·tan α (the world's own gear geometry, nothing shared with {@link Effect}).
 * Named on its joint with the play's mean, change and widest angle near the truth's, at the
 * floor; a constant play named constant is in {@link WindUpLostMotionTest}.
 */
class RunoutLostMotionTest {
    private final RobotDescription irb2000 = RobotLibrary.shipped("irb2000");

    @Test
    void playChangingOverTheTurn_namedOnJoint2_withTheTruthsPlay_atTheFloor() {
        Scenario s = Scenario.named("lost motion j2 whose play changes over the turn (output gear runout)");
        for (long seed : new long[] {20261124, 20261126}) {
            Run run = lostMotion(s.trial(seed), 1, "seed " + seed);
            WorldCampaigns.Sim c = run.c();
            JointError.GearPairLostMotion truth = run.truth();
            Diagnosis d = run.d();
            Diagnosis.Finding f = run.f();
            assertTrue(f.effect().runout(), "seed " + seed + ": " + f.effect().label());
            double[] v = f.values();
            // the truth's play over the turn: width + A cos(q - phase), A = 2 e tan(alpha) / r
            double change = truth.gearChange();
            assertEquals(truth.width(), v[0], 0.1 * truth.width(), "seed " + seed + ": mean play");
            assertEquals(change, Math.hypot(v[1], v[2]), 0.2 * change, "seed " + seed + ": change over the turn");
            double widest = Math.atan2(v[2], v[1]);
            assertEquals(0, Math.IEEEremainder(widest - truth.gearPhase(), 2 * Math.PI), Math.toRadians(15), "seed " + seed + ": widest angle");
            assertTrue(d.finalValidateRmsM() <= 1.15 * c.floorM(), "seed " + seed + ": " + d.finalValidateRmsM() / c.floorM());
        }
    }

    @Test
    void playChangingOverTheTurn_directionsFromTheMeasuringOrder() {
        Scenario s = Scenario.named("lost motion j1 irb2400 whose play changes over the turn (output gear runout), directions not recorded");
        Run run = lostMotion(s.trial(20261125), 0, "seed 20261125");
        assertTrue(run.f().effect().runout(), run.f().effect().label());
        assertTrue(run.d().finalValidateRmsM() <= 1.15 * run.c().floorM(), run.d().finalValidateRmsM() / run.c().floorM() + " x floor");
    }

    /**
     * A play changing with the pinion that drives the output gear (the world's tooth counts, its
     * ratio not whole): the order found in the lag's spectrum near z_gear/z_pinion (the fitted
     * cycle drifting from the truth's by no more than a twentieth of a cycle over the joint's
     * measured range, {@link #orderTolerance}), the mean play and its change near the world's gear
     * geometry, at the floor. On seed 20261124 the
     * spectrum's line alone (4.53 against 4.95) left 1.36 times the floor and a smooth error of
     * joint 3 beside it; the order the left-out poses choose near it does not.
     */
    @Test
    void playChangingWithItsPinion_namedWithTheStageOrder() {
        Scenario s = Scenario.named("lost motion j3 whose play changes with its pinion's turn (eccentric pinion)");
        for (long seed : new long[] {20261124, 20261126}) {
            Run run = lostMotion(s.trial(seed), 2, "seed " + seed);
            WorldCampaigns.Sim c = run.c();
            JointError.GearPairLostMotion truth = run.truth();
            Diagnosis d = run.d();
            Diagnosis.Finding f = run.f();
            assertTrue(d.located().stream().allMatch(l -> l.explainedBy() != null), "seed " + seed + ": " + d.located());
            double ratio = (double) truth.gearTeeth() / truth.pinionTeeth();
            assertEquals(1, f.effect().runoutOrders().length, "seed " + seed + ": " + f.effect().label());
            assertEquals(ratio, f.effect().runoutOrders()[0], orderTolerance(c, 2), "seed " + seed + ": " + f.effect().label());
            double[] v = f.values();
            assertEquals(truth.width(), v[0], 0.1 * truth.width(), "seed " + seed + ": mean play");
            assertEquals(truth.pinionChange(), Math.hypot(v[1], v[2]), 0.25 * truth.pinionChange(), "seed " + seed + ": change with the pinion's turn");
            assertTrue(d.finalValidateRmsM() <= 1.15 * c.floorM(), "seed " + seed + ": " + d.finalValidateRmsM() / c.floorM());
        }
    }

    @Test
    void playChangingWithItsPinion_directionsFromTheMeasuringOrder() {
        Run run = lostMotion(Scenario.named("lost motion j1 puma560 whose play changes with its pinion's turn (eccentric pinion), "
                + "directions not recorded").trial(20261125), 0, "seed 20261125");
        WorldCampaigns.Sim c = run.c();
        JointError.GearPairLostMotion truth = run.truth();
        Diagnosis d = run.d();
        Effect e = run.f().effect();
        double ratio = (double) truth.gearTeeth() / truth.pinionTeeth();
        assertEquals(1, e.runoutOrders().length, e.label());
        assertEquals(ratio, e.runoutOrders()[0], orderTolerance(c, 0), e.label());
        assertTrue(d.finalValidateRmsM() <= 1.15 * c.floorM(), d.finalValidateRmsM() / c.floorM() + " x floor");
    }

    /**
     * Both gears of the last pair running off their centres: the play changes once per turn and at
     * the pinion's rate, both named, each change near the world's.
     */
    @Test
    void playChangingWithBothGears_namedWithBothOrders() {
        bothGears(new long[] {20261124, 20261126}, 1);
    }

    /**
     * Both gears again, on a draw whose pinion turns 3.57 times per output turn, below the least
     * order the play's scan searches (4): its line shows in the lag's spectrum only once the output
     * gear's larger once-per-turn change is modelled, at the scan's edge, and the left-out poses
     * choose the order below it. Before, the play was named changing once per turn, at 1.35 times
     * the floor, with a jump of joint 2's reading located beside it. The left-out error changes
     * little with the order here (within 0.4 % between 3.2 and 3.6 times per turn), so the order
     * is held to three twentieths of a cycle over the range, not one, and below the scan's least.
     */
    @Test
    void playChangingWithBothGears_pinionBelowTheScansLeastOrder() {
        bothGears(new long[] {20261125}, 3);
    }

    /** The both-gears scenario on {@code seeds}: both orders named, the pinion's within {@code cycles}/20 of a cycle over the range. */
    private static void bothGears(long[] seeds, double cycles) {
        Scenario s = Scenario.named("lost motion j2 whose play changes with its output gear's and its pinion's turn (both eccentric)");
        for (long seed : seeds) {
            Run run = lostMotion(s.trial(seed), 1, "seed " + seed);
            WorldCampaigns.Sim c = run.c();
            JointError.GearPairLostMotion truth = run.truth();
            Diagnosis d = run.d();
            Diagnosis.Finding f = run.f();
            double[] orders = f.effect().runoutOrders(), v = f.values();
            assertEquals(2, orders.length, "seed " + seed + ": " + f.effect().label());
            assertEquals(1, orders[0]);
            double ratio = (double) truth.gearTeeth() / truth.pinionTeeth();
            assertEquals(ratio, orders[1], cycles * orderTolerance(c, 1), "seed " + seed + ": " + f.effect().label());
            assertEquals(truth.gearChange(), Math.hypot(v[1], v[2]), 0.3 * truth.gearChange(), "seed " + seed + ": once per turn");
            assertEquals(truth.pinionChange(), Math.hypot(v[3], v[4]), 0.3 * truth.pinionChange(), "seed " + seed + ": the pinion's");
            assertTrue(d.finalValidateRmsM() <= 1.15 * c.floorM(), "seed " + seed + ": " + d.finalValidateRmsM() / c.floorM());
        }
    }

    /** A world trial diagnosed blind: its campaign, the truth's last gear pair, the diagnosis and the one effect it names. */
    private record Run(WorldCampaigns.Sim c, JointError.GearPairLostMotion truth, Diagnosis d, Diagnosis.Finding f) { }

    /** Diagnoses trial {@code t} on its robot; exactly one effect must be named, lost motion of {@code joint} (0-based). */
    private static Run lostMotion(Scenario.Trial t, int joint, String where) {
        WorldCampaigns.Sim c = WorldCampaigns.of(t);
        Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped(t.scenario().robot()), c.train(), c.validation());
        assertEquals(1, d.effects().size(), where + ": " + d.effects() + " " + d.notes());
        Diagnosis.Finding f = d.effects().get(0);
        assertEquals(Effect.Kind.BACKLASH, f.effect().kind(), where + ": " + f.effect().label());
        assertEquals(joint, f.effect().joint(), where + ": " + f.effect().label());
        return new Run(c, gearPair(t), d, f);
    }

    /** The world's last gear pair in a trial. */
    private static JointError.GearPairLostMotion gearPair(Scenario.Trial t) {
        return t.world().errors().stream().filter(e -> e instanceof JointError.GearPairLostMotion)
                .map(e -> (JointError.GearPairLostMotion) e).findFirst().orElseThrow();
    }

    /** Cycles per turn by which an order may miss: a twentieth of a cycle over joint j's measured range. */
    private static double orderTolerance(WorldCampaigns.Sim c, int j) {
        double lo = c.train().rows().stream().mapToDouble(m -> m.q(j)).min().orElseThrow();
        double hi = c.train().rows().stream().mapToDouble(m -> m.q(j)).max().orElseThrow();
        return 0.05 / ((hi - lo) / (2 * Math.PI));
    }

    /** The regressor at an order that is not whole beside once per turn, by hand, and the robot file keeping the orders. */
    @Test
    void pinionOrderRegressorAndRobotFile() {
        Effect e = Effect.withRunout(Effect.backlash(2), 4.947, 1);
        double q3 = Math.toRadians(-35);
        double[] g = new double[5];
        e.regressor(new double[] {0, 0, q3, 0, 0, 0}, new PoseConditions(new int[] {0, 0, 1, 0, 0, 0}, 0, Double.NaN, Double.NaN), g);
        assertArrayEquals(new double[] {-0.5, -0.5 * Math.cos(q3), -0.5 * Math.sin(q3), -0.5 * Math.cos(4.947 * q3),
                -0.5 * Math.sin(4.947 * q3)}, g, 1e-15, "moved up: the output sits half the play below; orders in rising order");
        assertEquals(List.of("b", "b_cos", "b_sin", "b_cos_4.947", "b_sin_4.947"), e.parameterNames());
        Effect.Term back = Effect.fromDescription(e.describe(new double[] {5e-4, 1e-4, 1e-4, -1e-4, 2e-5}), KinematicModel.build(irb2000),
                null, "x.json");
        assertArrayEquals(new double[] {1, 4.947}, back.effect().runoutOrders(), 0);
        assertEquals(e.label(), back.effect().label());
    }

    /**
     * The regressor by hand: the output lags by half the play, b(q) = b + b_cos cos q + b_sin sin q,
     * behind the direction it last moved in; the robot file keeps the form.
     */
    @Test
    void regressorAndRobotFile() {
        Effect e = Effect.withRunout(Effect.backlash(1));
        assertEquals(3, e.size());
        double q2 = Math.toRadians(60);
        double[] g = new double[3];
        e.regressor(new double[] {0, q2, 0, 0, 0, 0}, new PoseConditions(new int[] {0, -1, 0, 0, 0, 0}, 0, Double.NaN, Double.NaN), g);
        assertArrayEquals(new double[] {0.5, 0.5 * Math.cos(q2), 0.5 * Math.sin(q2)}, g, 1e-15, "moved down: the output sits half the play above");
        KinematicModel model = KinematicModel.build(irb2000);
        double[] v = {7e-4, 1e-4, -2e-4};
        Effect.Term back = Effect.fromDescription(e.describe(v), model, null, "x.json");
        assertTrue(back.effect().runout());
        assertArrayEquals(v, back.values(), 0);
        assertEquals(Effect.Kind.BACKLASH, Effect.withoutRunout(back.effect()).kind());
        assertTrue(!Effect.withoutRunout(back.effect()).runout());
    }
}
