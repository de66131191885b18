package org.robopro.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The parallel arm's rod: checked against the linkage's own geometry (the rod's two ends stay a
 * rod's length apart, and a parallelogram turns the forearm with the crank) and against the first
 * order of the closure, derived here: at the parallelogram, moving the lever's angle by δφ changes
 * the squared rod length by −2·ground·crank·sin ψ·δφ, so a rod longer by δc turns the forearm by
 * δφ = −rod·δc / (ground·crank·sin ψ) (Norton, Design of Machinery, §4.5).
 */
class LinkageRodTest {
    static final double GROUND = 0.710, CRANK = 0.29;

    @Test
    void aParallelogramTurnsTheForearmWithTheCrank() {
        JointError.LinkageRod rod = new JointError.LinkageRod(2, 1, GROUND, CRANK, CRANK, GROUND, Math.toRadians(90));
        for (double psi = Math.toRadians(20); psi < Math.toRadians(160); psi += 0.05) assertEquals(psi, rod.leverAngle(psi), 1e-12);
    }

    @Test
    void theRodsEndsStayARodsLengthApart() {
        Random r = new Random(3);
        for (int i = 0; i < 200; i++) {
            double lever = CRANK + 20e-6 * (2 * r.nextDouble() - 1), length = GROUND + 80e-6 * (2 * r.nextDouble() - 1);
            JointError.LinkageRod rod = new JointError.LinkageRod(2, 1, GROUND, CRANK, lever, length, 0);
            double psi = Math.toRadians(20 + 140 * r.nextDouble()), phi = rod.leverAngle(psi);
            double ax = CRANK * Math.cos(psi), ay = CRANK * Math.sin(psi);             // the crank's end, pivot frame
            double bx = GROUND + lever * Math.cos(phi), by = lever * Math.sin(phi);    // the lever's end
            assertEquals(length, Math.hypot(bx - ax, by - ay), 1e-12);
            assertTrue(Math.abs(phi - psi) < Math.toRadians(0.1), "the parallelogram's branch");
        }
    }

    @Test
    void toFirstOrder_aLongerRodTurnsTheForearmBack_mostWhereTheCrankLiesAlongTheArm() {
        double dc = 60e-6;
        JointError.LinkageRod rod = new JointError.LinkageRod(2, 1, GROUND, CRANK, CRANK, GROUND + dc, Math.toRadians(90));
        for (double deg : new double[] {30, 60, 90, 120, 150}) {
            double psi = Math.toRadians(deg);
            double expected = -(GROUND + dc) * dc / (GROUND * CRANK * Math.sin(psi));
            double[] q = new double[6];
            q[2] = psi - Math.toRadians(90);
            assertEquals(expected, rod.delta(q, new JointError.Moment(new int[6], null, 0, 20)), 1e-3 * Math.abs(expected), "psi " + deg);
        }
    }

    @Test
    void theScenarioDrawsTheArmsOwnPivotDistance() {
        String json = Scenario.named("outside: parallel-arm rod off its length, irb2000").trial(20261124, p -> p).truthJson();
        assertTrue(json.contains("\"ground_mm\" : 710.0") || json.contains("\"ground_mm\":710.0"), json);
    }
}
