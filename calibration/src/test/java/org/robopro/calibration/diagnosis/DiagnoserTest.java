package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.calibration.WorldCampaigns;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
import org.robopro.world.Scenario;

/**
 * What the diagnosis says when a column is missing, and what it claims when it has the data. The
 * campaigns are the independent world simulator's (org.robopro.world), read back as measurement files.
 */
class DiagnoserTest {
    private final RobotDescription robot = RobotLibrary.shipped("irb2000");

    /** A world scenario's campaign with {@code poses} training and 100 validation poses. */
    private static WorldCampaigns.Sim world(String scenario, long seed, int poses) {
        return WorldCampaigns.of(Scenario.named(scenario).trial(seed, p -> p.withPoses(poses, 100)));
    }

    private static MeasurementSet strip(MeasurementSet s, boolean dirs, boolean time, boolean temp) {
        if (s == null) return null;
        List<Measurement> rows = new ArrayList<>();
        for (Measurement m : s.rows())
            rows.add(m.withConditions(dirs ? null : m.directions(), time ? Double.NaN : m.timeS(), temp ? Double.NaN : m.tempC(),
                    m.payloadKg()));
        return s.withRows(rows);
    }

    @Test
    void diagnose_backlashWithDirections_claimsBacklashOnJoint2() {
        WorldCampaigns.Sim c = world("lost motion j2, directions recorded", 5, 200);
        Diagnosis d = Diagnoser.diagnose(robot, c.train(), c.validation());
        assertEquals(1, d.effects().size());
        assertEquals("backlash j2", d.effects().get(0).effect().label());
        assertEquals(Directions.Source.RECORDED, d.directions());
        assertTrue(d.finalValidateRmsM() < 0.5 * d.geometricValidateRmsM());
    }

    @Test
    void diagnose_backlashWithoutDirectionColumns_infersThemFromTheMeasuringOrder() {
        WorldCampaigns.Sim c = world("lost motion j2, directions recorded", 5, 200);
        Diagnosis d = Diagnoser.diagnose(robot, strip(c.train(), true, false, false), strip(c.validation(), true, false, false));
        assertEquals(Directions.Source.TIME_ORDER, d.directions());
        // The lost motion on joint 2 and nothing else.
        assertEquals(List.of("backlash j2"), d.effects().stream().map(f -> f.effect().label()).toList());
        Diagnosis.Finding f = d.effects().stream().filter(x -> x.effect().kind() == Effect.Kind.BACKLASH).findFirst().orElseThrow();
        assertTrue(f.values()[0] > 0, "lost motion is positive (lagging output): " + f.values()[0]);
        assertTrue(f.words().contains("inferred"), f.words());
        assertTrue(d.finalValidateRmsM() < 0.5 * d.geometricValidateRmsM(), d.finalValidateRmsM() + " vs " + d.geometricValidateRmsM());
        assertTrue(d.recommendations().stream().anyMatch(r -> r.contains("dir1..dir6")), d.recommendations().toString());
    }

    @Test
    void diagnose_thermalWithoutTemperatureOrTime_advisesRecordingThem() {
        WorldCampaigns.Sim c = world("thermal growth per link", 8, 250);
        Diagnosis d = Diagnoser.diagnose(robot, strip(c.train(), false, true, true), strip(c.validation(), false, true, true));
        assertTrue(d.recommendations().stream().anyMatch(r -> r.contains("temp_c")), d.recommendations().toString());
        assertTrue(d.effects().stream().noneMatch(f -> f.effect().kind() == Effect.Kind.THERMAL));
    }

    @Test
    void diagnose_thermalWithTimeOnly_claimsExpansionFromTheWarmUpProxy() {
        WorldCampaigns.Sim c = world("thermal growth per link", 8, 250);
        Diagnosis d = Diagnoser.diagnose(robot, strip(c.train(), false, false, true), strip(c.validation(), false, false, true));
        assertEquals(1, d.effects().size(), d.effects().toString());
        assertTrue(d.effects().get(0).effect().usesTimeProxy());
        assertTrue(d.recommendations().stream().anyMatch(r -> r.contains("temp_c")));
    }

    @Test
    void diagnose_robotWithoutMassModel_saysComplianceWasNotTested() {
        RobotDescription noMass = new RobotDescription(robot.name(), robot.displayName(), robot.joints(), robot.flange(),
                robot.coupling(), Optional.empty(), robot.meshes(), robot.effects(), robot.source(), robot.provenance());
        WorldCampaigns.Sim c = world("null irb2000", 3, 120);
        Diagnosis d = Diagnoser.diagnose(noMass, c.train(), null);
        assertTrue(d.effects().isEmpty());
        assertTrue(d.notes().stream().anyMatch(n -> n.contains("mass model")), d.notes().toString());
        assertTrue(Double.isNaN(d.finalValidateRmsM()));
    }
}
