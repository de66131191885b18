package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.robopro.calibration.WorldCampaigns;
import org.robopro.world.Scenario;

/**
 * A family whose own fallback holds its shape (a drift of the instrument with time inside a turn
 * of the base with time) stays claimed when it explains nearly all the fallback does in its
 * place; what the fallback finds beside it is another structure. The world's tracker drifting as
 * it settles, with its distance taken again from the absolute distance meter at every beam break
 * (an error along the line of sight that a turn with time follows in part): the drift is named,
 * not the turn. A floor that tilts as the hall warms is a turn: there the share is far from it
 * and no drift is named.
 */
class FamilyShareTest {
    private static Diagnosis diagnose(String scenario, long seed) {
        WorldCampaigns.Sim s = WorldCampaigns.of(Scenario.named(scenario).trial(seed));
        return Diagnoser.diagnose(s.nominal(), s.train(), s.validation());
    }

    private static List<Effect> claimed(Diagnosis d) {
        return d.effects().stream().map(f -> f.effect()).filter(e -> !e.isFallback()).toList();
    }

    @Test
    void driftBesideRangeResets_isNamed() {
        Diagnosis d = diagnose("instrument drift with time + the tracker's distance taken again at beam breaks, sigma 0.005 mm", 20261127);
        List<Effect> named = claimed(d);
        assertEquals(1, named.size(), d.effects() + " " + d.notes());
        assertEquals(Effect.Kind.DRIFT, named.get(0).kind(), named.toString());
        assertTrue(named.get(0).usesTimeProxy(), named.toString());
        assertTrue(d.effects().stream().noneMatch(f -> f.effect().kind() == Effect.Kind.BASE_TURN), d.effects().toString());
        // what the turn followed beside the drift is the instrument's distances: jumps at the beam breaks or, as well on these
        // poses, a smooth scale of them with time
        assertTrue(d.effects().stream().anyMatch(f -> f.effect().kind() == Effect.Kind.RANGE_STEP
                || f.effect().kind() == Effect.Kind.INSTRUMENT_SCALE), d.effects().toString());
    }

    @Test
    void floorTiltingAsItWarms_namesNoDrift() {
        Diagnosis d = diagnose("outside: the floor tilts as it warms", 20261124);
        assertTrue(claimed(d).isEmpty(), d.effects() + " " + d.notes());
    }
}
