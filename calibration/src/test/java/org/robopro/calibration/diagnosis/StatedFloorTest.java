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
     * A measured target knocked on the flange mid-campaign (outside every family; the world's truth):
     * the error left stays well above the stated floor, and the report says so first.
     */
    @Test
    void errorLeftAboveTheStatedFloor_isSaidFirst() {
        var c = WorldCampaigns.of(Scenario.named("outside: measured target knocked mid-campaign").trial(20261124L, p -> p));
        Diagnosis d = Diagnoser.diagnose(irb2000, c.train(), c.validation());
        assertTrue(d.finalValidateRmsM() > 1.2 * c.floorM(), "error is left: " + d.finalValidateRmsM() / c.floorM());
        assertTrue(!d.warnings().isEmpty() && d.warnings().get(0).startsWith("The final model misses the validation poses"), d.warnings().toString());
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
}
