package org.robopro.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robopro.calibration.measurement.MeasurementReader;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;

/** robopro simulate --effect: condition columns, truth with the injected values, and diagnose finds the effect. */
class SimulateCommandTest {
    @TempDir Path dir;
    private final CliHarness cli = new CliHarness();

    private int run(String... args) { return cli.run(args); }

    @Test
    void simulateWithGearPeriodicJoint1_thenDiagnose_namesGearPeriodicOnJoint1() throws Exception {
        Path sim = dir.resolve("sim"), diag = dir.resolve("diag");
        assertEquals(0, run("simulate", "--robot", "irb2000", "--effect", "gear-periodic:1", "--validate-poses", "100",
                "--seed", "3", "--out", sim.toString()), cli.err());
        RobotDescription irb = RobotLibrary.shipped("irb2000");
        MeasurementSet m = MeasurementReader.read(sim.resolve("measurements.csv"), irb);
        assertTrue(m.hasDirections() && m.hasTime() && m.hasTemperature(), "condition columns written");
        assertFalse(m.hasPayload(), "payload only varies with compliance");
        JsonNode truth = new ObjectMapper().readTree(sim.resolve("truth.json").toFile());
        JsonNode e = truth.get("effects").get(0);
        assertEquals("gear-periodic", e.get("effect").asText());
        assertEquals(1, e.get("joints").get(0).asInt());
        double a1 = Math.toDegrees(Math.hypot(e.get("parameters_si").get("a1").asDouble(), e.get("parameters_si").get("b1").asDouble()));
        assertTrue(a1 >= 0.004 && a1 <= 0.01, "harmonic-1 amplitude in EffectSpec's range: " + a1);
        assertEquals("gear-periodic", RobotLibrary.read(sim.resolve("true.robot.json")).effects().get(0).effect());

        assertEquals(0, run("diagnose", "--robot", "irb2000", "--measurements", sim.resolve("measurements.csv").toString(),
                "--validate", sim.resolve("validate.csv").toString(), "--out", diag.toString()), cli.err());
        JsonNode d = new ObjectMapper().readTree(diag.resolve("diagnosis.json").toFile());
        assertEquals(1, d.get("effects").size(), d.get("effects").toString());
        assertEquals("gear-periodic", d.get("effects").get(0).get("effect").asText());
        assertEquals(1, d.get("effects").get(0).get("joints").get(0).asInt());
        assertTrue(d.get("final").get("validate_rms_mm").asDouble() < 0.5 * d.get("geometric").get("validate_rms_mm").asDouble(),
                "modelling the effect improves validation: " + d.get("final") + " vs " + d.get("geometric"));
    }

    @Test
    void simulate_givenValuesAndCoupling_truthRecordsThem() throws Exception {
        Path sim = dir.resolve("sim");
        assertEquals(0, run("simulate", "--robot", "irb2000", "--poses", "30", "--effect", "backlash:3=0.04", "--effect",
                "joint-coupling:3<-2=5e-4", "--effect", "joint-compliance:2", "--out", sim.toString()), cli.err());
        JsonNode effects = new ObjectMapper().readTree(sim.resolve("truth.json").toFile()).get("effects");
        assertEquals(3, effects.size());
        assertEquals(Math.toRadians(0.04), effects.get(0).get("parameters_si").get("b").asDouble(), 1e-15);
        assertEquals("[3,2]", effects.get(1).get("joints").toString());
        assertEquals(5e-4, effects.get(1).get("parameters_si").get("kappa").asDouble(), 0);
        double stiffness = effects.get(2).get("value").get(0).asDouble();
        assertTrue(stiffness >= 0.5e6 && stiffness <= 2e6, "drawn stiffness " + stiffness);
        assertTrue(MeasurementReader.read(sim.resolve("measurements.csv"), RobotLibrary.shipped("irb2000")).hasPayload(),
                "compliance: payload column");
        assertTrue(cli.out().contains("effect joint-coupling:3<-2=5.0E-4"), cli.out());
    }

    @Test
    void simulate_unknownEffect_exitsWithMessageAndWritesNothing() {
        Path sim = dir.resolve("sim");
        assertEquals(2, run("simulate", "--robot", "irb2000", "--effect", "backlish:2", "--out", sim.toString()));
        assertTrue(cli.err().contains("backlish"), cli.err());
        assertFalse(Files.exists(sim.resolve("measurements.csv")));
    }
}
