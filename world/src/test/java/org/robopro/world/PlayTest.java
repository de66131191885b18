package org.robopro.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;

/**
 * A drive's play as the dead zone it is: the output stays where it stood until the motor has
 * crossed the play, then follows on the far flank. Checked against the output's own position,
 * tracked here as a clamp of the output between the motor's two flank positions (Nordin &amp;
 * Gutman, "Controlling mechanical systems with backlash: a survey", Automatica 38 (2002) 1633, §2),
 * not against the side the campaign keeps.
 */
class PlayTest {
    static final RobotDescription IRB2000 = RobotLibrary.shipped("irb2000");
    static final double B = Math.toRadians(0.04);

    static WorldRobot withPlay() {
        return Scenario.baseRobot(IRB2000, new Random(4), 1e-3, Math.toRadians(0.1)).withErrors(List.of(new JointError.LostMotion(1, B)));
    }

    @Test
    void aReversalShorterThanThePlayLeavesTheOutputWhereItStood() {
        WorldRobot w = withPlay();
        double[] side = {1, 1, 1, 1, 1, 1};
        double[] a = new double[6], b = new double[6];
        b[1] = Math.toRadians(10);
        Campaign.moveWithinPlay(w, side, a, b);
        assertEquals(1, side[1], 0, "after a long rise the output lags on its flank");
        double[] c = b.clone();
        c[1] -= 1.4e-6;                                      // 0.00008 deg back: jitter, far inside the play
        Campaign.moveWithinPlay(w, side, b, c);
        double lag = -0.5 * B * side[1];
        assertEquals(-0.5 * B + 1.4e-6, lag, 1e-12, "the output stood still while the motor went back");
        assertTrue(side[1] > 0.99, "still on the rising flank: " + side[1]);
        double[] d = c.clone();
        d[1] -= 2 * B;
        Campaign.moveWithinPlay(w, side, c, d);
        assertEquals(-1, side[1], 0, "a reversal longer than the play puts it on the other flank");
    }

    @Test
    void overARandomSequenceTheOutputIsTheClampOfItsLastPlace() {
        WorldRobot w = withPlay();
        Random r = new Random(11);
        double[] side = {1, 1, 1, 1, 1, 1};
        double[] q = new double[6];
        double out = q[1] - B / 2;                           // resting after a rise
        int inside = 0;
        for (int k = 0; k < 2000; k++) {
            double[] next = q.clone();
            next[1] += (r.nextBoolean() ? 1 : -1) * B * (r.nextDouble() < 0.5 ? 0.3 * r.nextDouble() : 3 * r.nextDouble());
            Campaign.moveWithinPlay(w, side, q, next);
            out = Math.max(next[1] - B / 2, Math.min(next[1] + B / 2, out));
            double modelled = next[1] + w.errors().get(0).delta(next, new JointError.Moment(new int[6], null, 0, 20, null, side));
            assertEquals(out, modelled, 1e-12, "step " + k);
            if (Math.abs(side[1]) < 0.999) inside++;
            q = next;
        }
        assertTrue(inside > 100, "short reversals leave the output inside the play: " + inside);
    }

    @Test
    void theCampaignLogsTheCommandedSignButTheTruthFollowsThePlay() {
        WorldRobot w = withPlay();
        Campaign.Result c = Campaign.run(w, IRB2000, Campaign.Plan.defaults(7).withPoses(150, 0));
        for (Campaign.Row row : c.rows()) {
            double[] p = w.target(row.q(), row.dir(), row.side(), row.lastMove(), row.tempC(), row.timeS(), row.payloadKg()).p();
            for (int i = 0; i < 3; i++) assertEquals(row.truePoint()[i], p[i], 1e-12);
            if (Math.abs(row.side()[1]) == 1) assertEquals(row.dir()[1], row.side()[1], 0.0, "on a flank: the flank of the last move");
        }
    }
}
