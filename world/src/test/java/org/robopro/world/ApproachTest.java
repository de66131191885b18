package org.robopro.world;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.robopro.models.JointDescription;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;

/**
 * One-sided approach campaigns: every ruled drive takes each pose by a short move from its side,
 * through an approach pose the file does not hold. Checked row by row from the file's own joint
 * values, with the rule restated here: a drive that travelled towards the pose from the wrong
 * side (or by less than the approach) turns round at the approach pose, and its last motion is
 * the approach alone; one that travelled from the right side by more keeps going through the
 * stop, and its last motion is the whole travel.
 */
class ApproachTest {
    static final RobotDescription IRB2000 = RobotLibrary.shipped("irb2000");
    static final double TWO_DEG = Math.toRadians(2);

    static Campaign.Result run(Campaign.Approach a, WorldRobot w, long seed) {
        return Campaign.run(w, IRB2000, Campaign.Plan.defaults(seed).withPoses(150, 50).withApproach(a));
    }

    static WorldRobot robot(long seed) { return Scenario.baseRobot(IRB2000, new Random(seed), 1e-3, Math.toRadians(0.1)); }

    @Test
    void everyDriveFromAbove_dirAlwaysUp_lastMoveTheApproachOrTheWholeTravel() {
        Campaign.Result c = run(Campaign.Approach.all(6, 1, TWO_DEG, TWO_DEG, 0), robot(3), 3);
        double[] prev = Campaign.home(IRB2000);
        int turned = 0, through = 0;
        for (Campaign.Row r : c.rows()) {
            for (int j = 0; j < 6; j++) {
                assertEquals(1, r.dir()[j], "row " + r.id() + " drive " + (j + 1));
                double travel = r.q()[j] - prev[j];
                JointDescription d = IRB2000.joints().get(j);
                double approach = Math.min(TWO_DEG, r.q()[j] - d.min());
                if (travel > approach) {
                    assertEquals(travel, r.lastMove()[j], 1e-12, "travelled up by more than the approach: one motion");
                    through++;
                } else {
                    assertEquals(approach, r.lastMove()[j], 1e-12, "turned round at the approach pose");
                    turned++;
                }
            }
            prev = r.q();
        }
        assertTrue(turned > 300 && through > 300, turned + " turned, " + through + " through");
        // the file: every dir column 1
        assertTrue(c.text().lines().filter(l -> l.matches("\\d+,.*")).allMatch(l -> l.contains(",1,1,1,1,1,1,")));
        // the approach takes time: the same poses without it are measured sooner
        Campaign.Result plain = Campaign.run(robot(3), IRB2000, Campaign.Plan.defaults(3).withPoses(150, 50));
        for (int i = 0; i < c.rows().size(); i++) assertArrayEquals(plain.rows().get(i).q(), c.rows().get(i).q(), 0.0);
        assertTrue(c.rows().get(199).timeS() > plain.rows().get(199).timeS() + 200, "one more second of travel per pose at least");
    }

    @Test
    void oneDriveRuled_aShareFromTheOtherSide_theOthersFollowTheirTravel() {
        Campaign.Approach a = new Campaign.Approach(new int[] {0, -1, 0, 0, 0, 0}, Math.toRadians(0.5), Math.toRadians(10), 0.2);
        Campaign.Result c = run(a, robot(4), 4);
        double[] prev = Campaign.home(IRB2000);
        int other = 0;
        double shortest = Double.MAX_VALUE, longest = 0;
        for (Campaign.Row r : c.rows()) {
            int side = r.dir()[1];
            if (side == 1) other++;
            double travel = r.q()[1] - prev[1];
            if (travel * side <= 0) { // came from the wrong side: turned round at the approach pose
                assertEquals(side, Math.signum(r.lastMove()[1]), 0.0);
                shortest = Math.min(shortest, Math.abs(r.lastMove()[1]));
                longest = Math.max(longest, Math.abs(r.lastMove()[1]));
            }
            for (int j : new int[] {0, 2, 3, 4, 5}) {
                assertEquals(r.q()[j] > prev[j] ? 1 : -1, r.dir()[j], "an unruled drive: the sign of its travel");
                assertEquals(r.q()[j] - prev[j], r.lastMove()[j], 1e-15);
            }
            prev = r.q();
        }
        assertTrue(other > 0.12 * 200 && other < 0.28 * 200, other + " of 200 poses from the other side");
        assertTrue(shortest >= Math.toRadians(0.5) - 1e-12 && shortest < Math.toRadians(1), "shortest approach " + Math.toDegrees(shortest));
        assertTrue(longest <= Math.toRadians(10) + 1e-12 && longest > Math.toRadians(7), "longest approach " + Math.toDegrees(longest));
    }

    @Test
    void approachPose_staysWithinTheLimits() {
        JointDescription j2 = IRB2000.joints().get(1);
        double[] q = new double[6];
        q[1] = j2.min() + Math.toRadians(0.5);
        double[] via = Campaign.approachPose(IRB2000, Campaign.Approach.all(6, 1, TWO_DEG, TWO_DEG, 0), q, new Random(1));
        assertEquals(j2.min(), via[1], 0.0, "short of the limit: the approach starts at the limit");
        assertEquals(-TWO_DEG, via[0], 1e-15);
    }

    @Test
    void physics_aConstantLostMotionIsTheSameAtEveryPose_aWindUpFollowsTheApproach() {
        double b = Math.toRadians(0.04), x0 = Math.toRadians(5);
        WorldRobot base = robot(5);
        Campaign.Approach up = Campaign.Approach.all(6, 1, TWO_DEG, TWO_DEG, 0);
        Campaign.Result none = run(up, base, 5);
        Campaign.Result play = run(up, base.withErrors(List.of(new JointError.LostMotion(1, b))), 5);
        Campaign.Result wind = run(up, base.withErrors(List.of(new JointError.WindUpLostMotion(1, b, x0))), 5);
        WorldRobot shifted = offsetJ2(base, -b / 2);
        for (int i = 0; i < none.rows().size(); i++) {
            Campaign.Row r = play.rows().get(i), w = wind.rows().get(i);
            // the play is a constant -b/2 on drive 2: the robot with its zero moved by that much
            double[] p = shifted.target(r.q(), r.dir(), r.lastMove(), r.tempC(), r.timeS(), 0).p();
            assertArrayEquals(p, r.truePoint(), 1e-12);
            // the wind-up: -b/2 (1 - exp(-|last motion|/x0)), by the row's own last motion
            double lag = -0.5 * b * (1 - Math.exp(-Math.abs(w.lastMove()[1]) / x0));
            double[] pw = offsetJ2(base, lag).target(w.q(), w.dir(), w.lastMove(), w.tempC(), w.timeS(), 0).p();
            assertArrayEquals(pw, w.truePoint(), 1e-12);
        }
        assertTrue(wind.rows().stream().mapToDouble(r -> r.lastMove()[1]).distinct().count() > 50, "the wind-up's lag varies with the motion");
    }

    /** The robot with drive 2's zero moved by {@code by} (the zero offsets act on the drive, before the coupling). */
    private static WorldRobot offsetJ2(WorldRobot w, double by) {
        double[] z = w.zeroOffsets();
        z[1] += by;
        return new WorldRobot(w.robotName(), w.arm(), w.coupling(), z, w.errors(), w.flangeToTool(), w.instrumentFromBase(), w.thermal(),
                w.compliance(), w.sag(), w.toolBump());
    }

    @Test
    void oneSidedScenarios_formTheirOwnGroup_theirAnswerBelongsToTheirCampaign() {
        List<Scenario> one = Scenario.ofFamily(Scenario.ONE_SIDED);
        assertEquals(4, one.size());
        List<String> names = one.stream().map(Scenario::name).toList();
        for (Scenario s : Scenario.catalogue()) assertEquals(names.contains(s.name()), s.answerNeedsItsCampaign(), s.name());
        for (Scenario s : one) {
            Scenario.Trial t = s.trial(1, p -> p.withPoses(5, 0));
            assertTrue(t.campaign().plan().approach() != null, s.name());
            assertTrue(t.truthJson().contains("\"approach\""), "the truth record says how the poses were approached: " + s.name());
        }
        assertTrue(!Scenario.named("null irb2000").trial(1, p -> p.withPoses(5, 0)).truthJson().contains("\"approach\""));
    }

    @Test
    void badRules_refused() {
        assertThrows(IllegalArgumentException.class, () -> new Campaign.Approach(new int[] {2, 0, 0, 0, 0, 0}, 0.01, 0.01, 0));
        assertThrows(IllegalArgumentException.class, () -> Campaign.Approach.all(6, 1, 0, 0.01, 0));
        assertThrows(IllegalArgumentException.class, () -> Campaign.Approach.all(6, 1, 0.02, 0.01, 0));
        assertThrows(IllegalArgumentException.class, () -> Campaign.Approach.all(6, 1, 0.01, 0.01, 1));
    }
}
