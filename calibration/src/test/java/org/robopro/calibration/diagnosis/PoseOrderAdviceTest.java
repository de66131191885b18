package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.robopro.calibration.WorldCampaigns;
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

    /** Geometry alone, measured without time or temperature: nothing is said about the order. */
    @Test
    void nullCampaign_withoutConditionColumns_saysNothingOfTheOrder() {
        for (long seed : new long[] {20261124, 20261125}) {
            Diagnosis d = diagnosed("null irb2000", seed);
            assertFalse(d.recommendations().stream().anyMatch(r -> r.contains("pose order")), d.recommendations().toString());
        }
    }

    private static Diagnosis diagnosed(String scenario, long seed) {
        WorldCampaigns.Sim s = WorldCampaigns.of(Scenario.named(scenario).trial(seed, p -> p.withConditionColumns(false)));
        assertFalse(s.train().rows().stream().anyMatch(m -> Double.isFinite(m.timeS()) || Double.isFinite(m.tempC())));
        return Diagnoser.diagnose(s.nominal(), s.train(), s.validation());
    }
}
