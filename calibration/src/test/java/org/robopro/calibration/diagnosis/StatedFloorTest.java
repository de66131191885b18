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
     * Lost motion that builds up over the move (the world's friction wind-up): the constant play the
     * diagnosis names leaves about 2.5 x the floor, which the residual-based floor cannot see.
     */
    @Test
    void lostMotionWindingUp_isNamedButTheReportSaysFirstThatErrorIsLeftAndWhatToMeasure() {
        var c = WorldCampaigns.of(Scenario.named("lost motion j3 building up over the move (friction wind-up)").trial(20261124L, p -> p));
        Diagnosis d = Diagnoser.diagnose(irb2000, c.train(), c.validation());
        assertTrue(d.finalValidateRmsM() > 1.2 * c.floorM(), "the constant play does not reach the floor: " + d.finalValidateRmsM());
        assertTrue(!d.warnings().isEmpty() && d.warnings().get(0).startsWith("The final model misses the validation poses"), d.warnings().toString());
        assertTrue(d.warnings().get(0).contains("approach a few poses of joint 3 from each side after moves of several sizes"), d.warnings().get(0));
    }

    @Test
    void nullCampaign_atTheFloor_saysNothingOfIt() {
        var c = WorldCampaigns.of(Scenario.named("null irb2000").trial(7L, p -> p));
        Diagnosis d = Diagnoser.diagnose(irb2000, c.train(), c.validation());
        assertTrue(d.warnings().stream().noneMatch(w -> w.startsWith("The final model misses")), d.warnings().toString());
    }
}
