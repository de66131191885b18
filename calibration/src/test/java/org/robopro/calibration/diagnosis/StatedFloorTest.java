package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.WorldCampaigns;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
import org.robopro.world.Scenario;

/**
 * When the error left stays above the floor of the instrument's stated noise, the report says so
 * first, with what to measure; a floor estimated from the residuals would grow with the error left.
 */
class StatedFloorTest {
    private final RobotDescription irb2000 = RobotLibrary.shipped("irb2000");

    private static MeasurementSet withInstrument(String words) {
        return new MeasurementSet("f.csv", words == null ? Map.of() : Map.of("instrument", words), "tracker", List.of());
    }

    @Test
    void statedSigma_isReadFromTheInstrumentLine() {
        assertEquals(3e-5, Diagnoser.statedSigmaM(withInstrument("laser tracker, sigma 0.03 mm")), 1e-12);
        assertEquals(2e-5, Diagnoser.statedSigmaM(withInstrument("simulated by robopro world, sigma 0.0200 mm, seed 7")), 1e-12);
        assertEquals(1.5e-5, Diagnoser.statedSigmaM(withInstrument("CMM, Sigma: 15 um")), 1e-12);
        assertTrue(Double.isNaN(Diagnoser.statedSigmaM(withInstrument("laser tracker"))));
        assertTrue(Double.isNaN(Diagnoser.statedSigmaM(withInstrument(null))));
    }

    /**
     * Joint 2's error following the product of joints 1 and 4 (outside every family and every
     * fallback: no function of joint 2's angle, nor of joint 2 with one other; the world's truth):
     * the error left stays well above the stated floor, and the report says so first. (A target
     * knocked mid-campaign was the example until the locate scan could model it.)
     */
    @Test
    void errorLeftAboveTheStatedFloor_isSaidFirst() {
        var c = HeldOutFormsTest.world("irb2000", org.robopro.world.Expected.outside(),
                List.of(new org.robopro.world.JointError.AngleProduct(1, 0, 3, Math.toRadians(0.03))), p -> p, 20261124L);
        Diagnosis d = Diagnoser.diagnose(irb2000, c.train(), c.validation());
        assertTrue(d.finalValidateRmsM() > 1.2 * c.floorM(), "error is left: " + d.finalValidateRmsM() / c.floorM());
        assertTrue(!d.warnings().isEmpty() && d.warnings().get(0).startsWith("The final model misses the validation poses"), d.warnings().toString());
    }

    /**
     * Under a final model that misses the stated floor a pose a few robust sigmas out is no sign of a
     * bad reading (the model's residuals have heavier tails than the noise): the world's lost motion
     * building up over moves of 0.5-10°, a fifth of them from below, is left at about 3.9 × the floor
     * (its twin 1.1 ×) and holds no bad reading, and none is reported (a clean pose was); beside a
     * bearing wobble of joint 1 modelled by its fallback, the three gross readings are all still
     * reported.
     */
    @Test
    void underAModelShortOfTheFloor_onlyFarPosesAreBadReadings() {
        var c = WorldCampaigns.of(Scenario.named("lost motion j3 building up over the move, approached by 0.5-10 deg from above, a fifth "
                + "from below").trial(20261126L));
        Diagnosis d = Diagnoser.diagnose(irb2000, c.train(), c.validation());
        assertTrue(d.finalValidateRmsM() > 1.2 * c.floorM(), "error is left: " + d.finalValidateRmsM() / c.floorM());
        assertTrue(c.campaign().rows().stream().noneMatch(r -> r.outlier()), "a campaign without bad readings");
        assertEquals(List.of(), d.outliers(), d.notes().toString());
        var w = WorldCampaigns.of(Scenario.named("outside: bearing wobble of j1 at 0.38 times its angle, 3 gross outliers").trial(20261124L));
        Diagnosis dw = Diagnoser.diagnose(irb2000, w.train(), w.validation());
        List<String> bad = w.campaign().rows().stream().filter(r -> r.outlier()).map(r -> r.id()).toList();
        assertEquals(3, bad.size());
        assertTrue(dw.outliers().containsAll(bad), "reported " + dw.outliers() + ", bad " + bad);
    }

    /**
     * Lost motion that builds up over the move (the world's friction wind-up): once modelled it
     * reaches the floor and nothing is said of error left; with lost motion named and error left,
     * the advice is to approach from each side after moves of several sizes.
     */
    @Test
    void lostMotionWindingUp_reachesTheFloor_andTheAdviceForLostMotionNamesMovesOfSeveralSizes() {
        var c = WorldCampaigns.of(Scenario.named("lost motion j3 building up over the move (friction wind-up)").trial(20261124L, p -> p));
        Diagnosis d = Diagnoser.diagnose(irb2000, c.train(), c.validation());
        assertTrue(d.finalValidateRmsM() <= 1.15 * c.floorM(), "modelled to the floor: " + d.finalValidateRmsM() / c.floorM());
        assertTrue(d.warnings().stream().noneMatch(w -> w.startsWith("The final model misses")), d.warnings().toString());
        String plain = Diagnoser.aboveStatedFloor(1e-4, true, 2e-5, List.of(Effect.backlash(2)), true);
        assertTrue(plain.contains("approach a few poses of joint 3 from each side after moves of several sizes"), plain);
        String windUp = Diagnoser.aboveStatedFloor(1e-4, true, 2e-5, List.of(Effect.windUp(2, Math.toRadians(5), null)), true);
        assertTrue(windUp.contains("modelled as building up over the move (build-up length 5.0 deg"), windUp);
    }

    @Test
    void nullCampaign_atTheFloor_saysNothingOfIt() {
        var c = WorldCampaigns.of(Scenario.named("null irb2000").trial(7L, p -> p));
        Diagnosis d = Diagnoser.diagnose(irb2000, c.train(), c.validation());
        assertTrue(d.warnings().stream().noneMatch(w -> w.startsWith("The final model misses")), d.warnings().toString());
    }

    /**
     * Lengths (to an anchor, or between pairs of poses): the stated floor is σ itself, one
     * component per length. The world measures its lengths with σ = 0.02 mm; a file that states a
     * smaller sigma than the instrument delivers (0.014 mm: the held-out lengths come out at 1.6-1.7
     * x it, below the 1.2 x √3 of a point's floor) is told so first, with what lengths cannot show;
     * one that states the world's own sigma is not (its held-out lengths come out at 1.1-1.2 x σ,
     * what a model without error leaves on new poses with about 40 parameters fitted to 199 lengths).
     */
    @Test
    void lengthsToAnAnchor_andBetweenPairs_areHeldToTheStatedSigmaOfOneLength() {
        Scenario.Trial t = Scenario.named("null irb2000").trial(3, p -> p.withPoses(200, 100));
        String anchor = org.robopro.world.Readings.distances(t.world(), irb2000, t.campaign(), new double[] {1.3, -0.4, 0.05}, true, 3);
        String pairs = org.robopro.world.Readings.pairs(t.world(), irb2000, t.campaign(), 3);
        for (String[] c : new String[][] {{"anchor", anchor, "in the lengths to the anchor", "along the line to the anchor"},
                {"pairs", pairs, "in the lengths between pairs of poses", "along the line between the two places"}}) {
            assertTrue(c[1].contains("sigma 0.0200 mm"), "the world states its sigma");
            Diagnosis honest = diagnose(c[1]);
            assertTrue(honest.warnings().stream().noneMatch(w -> w.startsWith("The final model misses")), c[0] + ": " + honest.warnings());
            Diagnosis optimistic = diagnose(c[1].replace("sigma 0.0200 mm", "sigma 0.0140 mm"));
            double ratio = optimistic.finalValidateRmsM() / 0.014e-3;
            assertTrue(ratio > 1.3 && ratio < 1.2 * Math.sqrt(3), c[0] + ": held-out " + ratio + " x the stated sigma");
            assertTrue(!optimistic.warnings().isEmpty() && optimistic.warnings().get(0).startsWith("The final model misses the validation poses"),
                    c[0] + ": " + optimistic.warnings());
            String first = optimistic.warnings().get(0);
            assertTrue(first.contains(c[2]) && first.contains("0.0140 mm per length") && first.contains(c[3])
                    && first.contains("measure the positions (x, y, z)"), first);
        }
    }

    /**
     * Lengths between pairs of poses with one structure the two-joint fallback holds (joint 2's error
     * following joints 2 and 4) and one that nothing holds and lengths do not locate (joint 2's error
     * following the product of joints 1 and 4): the error left is said first. The part located is
     * modelled by the fallback and the rest, which lengths do not locate, is said to be nowhere the
     * scan can find, with what to measure. (Joint 2's error following joints 2 and 4 alone was the
     * example, said to live there, until the two-joint fallback modelled it wherever nothing else did.)
     */
    @Test
    void pairsWithStructureLeft_saysFirstThatErrorIsLeftAboveTheStatedSigma() {
        Scenario s = new Scenario("j2 error following j2 and j4, and the product of j1 and j4", "outside", "irb2000",
                org.robopro.world.Expected.outside(), (n, r) -> w -> w.withErrors(List.of(
                        new org.robopro.world.JointError.TwoJoint(1, 3, Math.toRadians(0.015)),
                        new org.robopro.world.JointError.AngleProduct(1, 0, 3, Math.toRadians(0.003)))), p -> p);
        Scenario.Trial t = s.trial(5, p -> p.withPoses(250, 100));
        Diagnosis d = diagnose(org.robopro.world.Readings.pairs(t.world(), irb2000, t.campaign(), 5));
        assertTrue(d.finalValidateRmsM() > 1.2 * 0.02e-3, "error is left: " + d.finalValidateRmsM());
        assertTrue(!d.warnings().isEmpty() && d.warnings().get(0).startsWith("The final model misses the validation poses"), d.warnings().toString());
        assertTrue(d.warnings().get(0).contains("the scan locates no structure in it") && d.warnings().get(0).contains("measure more pairs"),
                d.warnings().get(0));
        assertTrue(d.effects().stream().anyMatch(f -> f.effect().kind() == Effect.Kind.PAIR && f.effect().joint() == 1), d.effects().toString());
        assertTrue(d.located().stream().anyMatch(l -> l.variable().equals("joints 2 and 4")), d.located().toString());
    }

    private Diagnosis diagnose(String text) {
        MultiPointDiagnosisTest.Data c = MultiPointDiagnosisTest.read("lengths.csv", text);
        return Diagnoser.diagnose(irb2000, c.train(), c.validate());
    }
}
