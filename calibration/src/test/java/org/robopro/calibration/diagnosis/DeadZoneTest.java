package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.WorldCampaigns;
import org.robopro.world.Campaign;
import org.robopro.world.Scenario;

/**
 * A joint that reverses by less than its play before a pose leaves its output where it stood: the
 * world simulator moves each output through its play as the motor moves (the play operator), so at
 * such a pose the output rests inside the play or on the flank of the move before. The diagnosis
 * must model that pose, not report it as a bad reading, nor take a friction wind-up (which also
 * lags less after a short move) for it. Which poses those are is read from the
 * world's own record of where each output rests, not from the diagnosis.
 */
class DeadZoneTest {

    @ParameterizedTest(name = "{0}, seed {1}, joint {2}")
    @CsvSource(delimiter = '|', value = {
        "lost motion j1, directions recorded|20261124|1",
        "lost motion j3, directions not recorded (drive 3 behind the parallel linkage)|20261126|3",
        "lost motion j2 whose play changes over the turn (output gear runout)|20261126|2",
        "lost motion j2 whose play changes over the turn (output gear runout)|20261125|2"})
    void aPoseInsideThePlay_isModelled_notReportedAsABadReading(String scenario, long seed, int joint) {
        WorldCampaigns.Sim s = WorldCampaigns.of(Scenario.named(scenario).trial(seed, p -> p));
        List<String> inside = s.campaign().rows().stream()
                .filter(r -> Math.abs(r.side()[joint - 1] - r.dir()[joint - 1]) > 0.1).map(Campaign.Row::id).toList();
        assertFalse(inside.isEmpty(), "the world has a pose whose output is off the flank of its last move");
        Diagnosis d = Diagnoser.diagnose(s.nominal(), s.train(), s.validation());
        assertEquals(List.of(), d.outliers(), "no clean pose reported as a bad reading");
        assertFalse(d.effects().stream().anyMatch(f -> f.effect().buildsUp()), "a play, not a friction wind-up: " + d.effects());
        String note = d.notes().stream().filter(n -> n.contains("less than its play")).findFirst().orElse("");
        assertTrue(note.startsWith("joint " + joint + " "), d.notes().toString());
        for (String id : inside) assertTrue(note.matches(".*pose(s)? ([0-9]+, )*" + id + "\\b.*"), id + ": " + note);
    }

    /**
     * A commanded reversal of 0.00008° (pose 135 of this draw), logged by its sign as dir2 = −1: the
     * world keeps the output on its rising flank, and the diagnosis reads the recorded direction as
     * the last real move's, so the pose is not reported as a bad reading.
     */
    @Test
    void aRecordedReversalWithinJitter_isReadAsTheLastRealMove() {
        WorldCampaigns.Sim s = WorldCampaigns.of(Scenario.named("lost motion j2, directions recorded").trial(7, p -> p));
        Campaign.Row row = s.campaign().rows().stream().filter(r -> r.dir()[1] < 0 && r.side()[1] > 0.99).findFirst().orElseThrow();
        Diagnosis d = Diagnoser.diagnose(s.nominal(), s.train(), s.validation());
        assertEquals(List.of(), d.outliers());
        assertTrue(d.notes().stream().anyMatch(n -> n.startsWith("recorded directions against") && n.contains(row.id() + " j2")),
                d.notes().toString());
    }

    /**
     * Every pose approached from above through a pose the file does not hold: the file's own moves
     * go both ways, so a play operator run over them puts many outputs on the other flank, but the
     * approach crossed the play each time. The residuals keep the recorded flanks.
     */
    @Test
    void approachedFromAbove_theFilesMovesDoNotOverrideTheRecordedFlanks() {
        WorldCampaigns.Sim s = WorldCampaigns.of(Scenario.named("lost motion j2, j2 approached from above, a fifth of the poses from below").trial(20261124, p -> p));
        assertTrue(Directions.inPlay(s.train(), s.validation(), 1, q -> Math.toRadians(0.04)).size() > 5,
                "the file's moves alone would put outputs elsewhere");
        Diagnosis d = Diagnoser.diagnose(s.nominal(), s.train(), s.validation());
        assertFalse(d.notes().stream().anyMatch(n -> n.contains("less than its play")), d.notes().toString());
    }
}
