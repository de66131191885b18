package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.WorldCampaigns;
import org.robopro.world.Campaign;
import org.robopro.world.Scenario;

/**
 * A file without time_s or temp_c cannot locate a drift, but what is left may still change with the
 * order the poses were measured in: the report then says so and asks for the columns. Truth from
 * the world simulator, its files written without the condition columns.
 */
class PoseOrderAdviceTest {

    /** The world's floor slab tilting as the hall warms (a turn of the base with temperature), measured without time or temperature. */
    @Test
    void floorTiltingAsItWarms_withoutConditionColumns_asksForTime() {
        Diagnosis d = diagnosed("outside: the floor tilts as it warms", 20261125);
        assertTrue(d.recommendations().stream().anyMatch(r -> r.contains("change smoothly with the pose order")
                && r.contains("Record time_s")), d.recommendations().toString());
    }

    /**
     * The target knocked on the flange mid-campaign, measured without time or temperature: the
     * report says the residuals jump once along the pose order, between the two poses the world
     * knocked it between (its own record of the moment), and what to check.
     */
    @Test
    void targetKnocked_withoutConditionColumns_saysWhereTheResidualsJump() {
        for (long seed : new long[] {20261124, 20261125}) {
            WorldCampaigns.Sim s = sim("outside: measured target knocked mid-campaign", seed);
            double at = s.world().toolBump().atS();
            List<Campaign.Row> rows = s.campaign().rows().stream().filter(r -> !r.validate()).toList();
            int k = 0;
            while (rows.get(k).timeS() < at) k++;
            String expected = "between poses " + rows.get(k - 1).id() + " and " + rows.get(k).id();
            Diagnosis d = Diagnoser.diagnose(s.nominal(), s.train(), s.validation());
            assertTrue(d.recommendations().stream().anyMatch(r -> r.contains("jump once along the pose order") && r.contains(expected)),
                    expected + ": " + d.recommendations());
        }
    }

    /** The floor tilting as the hall warms changes the residuals smoothly: no step is said. */
    @Test
    void floorTiltingAsItWarms_isNoStep() {
        for (long seed : new long[] {20261125, 20261126}) {
            Diagnosis d = diagnosed("outside: the floor tilts as it warms", seed);
            assertFalse(d.recommendations().stream().anyMatch(r -> r.contains("jump once")), d.recommendations().toString());
        }
    }

    /** Geometry alone, measured without time or temperature: nothing is said about the order. */
    @Test
    void nullCampaign_withoutConditionColumns_saysNothingOfTheOrder() {
        for (long seed : new long[] {20261124, 20261125}) {
            Diagnosis d = diagnosed("null irb2000", seed);
            assertFalse(d.recommendations().stream().anyMatch(r -> r.contains("pose order")), d.recommendations().toString());
        }
    }

    private static Diagnosis diagnosed(String scenario, long seed) {
        WorldCampaigns.Sim s = sim(scenario, seed);
        return Diagnoser.diagnose(s.nominal(), s.train(), s.validation());
    }

    private static WorldCampaigns.Sim sim(String scenario, long seed) {
        WorldCampaigns.Sim s = WorldCampaigns.of(Scenario.named(scenario).trial(seed, p -> p.withConditionColumns(false)));
        assertFalse(s.train().rows().stream().anyMatch(m -> Double.isFinite(m.timeS()) || Double.isFinite(m.tempC())));
        return s;
    }
}
