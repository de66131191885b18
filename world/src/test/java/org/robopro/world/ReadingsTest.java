package org.robopro.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;

/** Other instruments' readings of a campaign: checked against the campaign's own noise-free truth. */
class ReadingsTest {
    static final RobotDescription IRB2000 = RobotLibrary.shipped("irb2000");

    private static Scenario.Trial noiseFree(String scenario) {
        return Scenario.named(scenario).trial(4, p -> p.withPoses(30, 10).withSigma(0));
    }

    private static List<String[]> dataRows(String text) {
        return text.lines().filter(l -> !l.startsWith("#")).skip(1).map(l -> l.split(",")).toList();
    }

    @Test
    void points_theCampaignsOwnTarget_readsItsTruePoint_andOtherPointsSitWhereTheFlangePutsThem() {
        Scenario.Trial t = noiseFree("lost motion j2, directions recorded");
        double[] target = t.world().flangeToTool().p();
        double[][] pts = {target, {0.05, 0, 0.1}};
        String text = Readings.points(t.world(), IRB2000, t.campaign(), pts, 1);
        assertTrue(text.contains("pose,point,q1,q2,q3,q4,q5,q6,x,y,z,dir1"), text.substring(0, 300));
        List<String[]> rows = dataRows(text);
        List<Campaign.Row> truth = t.campaign().rows();
        assertEquals(2 * truth.size(), rows.size());
        for (int i = 0; i < truth.size(); i++) {
            String[] a = rows.get(2 * i), b = rows.get(2 * i + 1);
            assertEquals(truth.get(i).id(), a[0]);
            assertEquals("P1", a[1]);
            assertEquals("P2", b[1]);
            for (int k = 0; k < 3; k++) assertEquals(truth.get(i).truePoint()[k] * 1e3, Double.parseDouble(a[8 + k]), 1e-4);
            // the second point: the first one's flange frame (the true target's rotation is the tool tilt) moved by the offset
            double sep = 0;
            for (int k = 0; k < 3; k++) sep += Math.pow(Double.parseDouble(a[8 + k]) - Double.parseDouble(b[8 + k]), 2);
            double[] d = Rigid.minus(pts[1], target);
            assertEquals(Rigid.norm(d) * 1e3, Math.sqrt(sep), 1e-4, "a rigid flange keeps the points' separation");
        }
    }

    @Test
    void distances_areTheLengthsFromTheAnchorToTheTruePointInTheBaseFrame() {
        Scenario.Trial t = noiseFree("lost motion j2, directions recorded");
        double[] anchor = {1.2, -0.4, 0.05};
        String text = Readings.distances(t.world(), IRB2000, t.campaign(), anchor, true, 1);
        assertTrue(text.contains("# anchor: 1200.0000, -400.0000, 50.0000"), text.substring(0, 300));
        List<String[]> rows = dataRows(text);
        Rigid baseFromInstrument = t.world().instrumentFromBase().inverse();
        for (int i = 0; i < rows.size(); i++) {
            double[] p = baseFromInstrument.apply(t.campaign().rows().get(i).truePoint());
            assertEquals(Rigid.norm(Rigid.minus(p, anchor)) * 1e3, Double.parseDouble(rows.get(i)[7]), 1e-4);
        }
    }

    @Test
    void pairs_areTheLengthsBetweenTheTruePointsOfConsecutivePoses_withTheFirstPoseInFromColumns() {
        Scenario.Trial t = noiseFree("lost motion j2, directions recorded");
        String text = Readings.pairs(t.world(), IRB2000, t.campaign(), 1);
        String header = text.lines().filter(l -> !l.startsWith("#")).findFirst().orElseThrow();
        assertTrue(header.startsWith("pose,q1,q2,q3,q4,q5,q6,distance,dir1") && header.endsWith("from_q6,from_dir1,from_dir2,from_dir3,from_dir4,from_dir5,from_dir6"), header);
        List<String[]> rows = dataRows(text);
        List<Campaign.Row> truth = t.campaign().rows();
        assertEquals(truth.size() - 1, rows.size());
        for (int i = 1; i < truth.size(); i++) {
            String[] r = rows.get(i - 1);
            assertEquals(truth.get(i).id(), r[0]);
            // a length is the same seen from any frame: the campaign's instrument-frame truth
            double len = Rigid.norm(Rigid.minus(truth.get(i).truePoint(), truth.get(i - 1).truePoint()));
            assertEquals(len * 1e3, Double.parseDouble(r[7]), 1e-4);
            int from = r.length - 12;
            for (int j = 0; j < 6; j++) assertEquals(Math.toDegrees(truth.get(i - 1).q()[j]), Double.parseDouble(r[from + j]), 1e-6);
        }
    }

    @Test
    void aJointByJointCampaign_isRefused() {
        Scenario.Trial t = Scenario.named("null irb2000").trial(4, p -> p.withPoses(20, 0).withMovedJoints(2));
        assertThrows(IllegalArgumentException.class, () -> Readings.points(t.world(), IRB2000, t.campaign(), new double[][] {{0, 0, 0.1}}, 1));
    }
}
