package org.robopro.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robopro.calibration.PoseConditions;
import org.robopro.calibration.diagnosis.Effect;
import org.robopro.calibration.measurement.MeasurementWriter;
import org.robopro.calibration.simulation.Campaign;
import org.robopro.calibration.simulation.CampaignSimulator;
import org.robopro.calibration.simulation.SimulationSettings;
import org.robopro.kinematics.KinematicModel;
import org.robopro.models.JointType;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;

/** robopro diagnose end to end: simulated backlash on joint 2, files written, effect named, compensate uses the extended model. */
class DiagnoseCommandTest {
    @TempDir Path dir;
    private final CliHarness cli = new CliHarness();

    private int run(String... args) { return cli.run(args); }

    /** A campaign with backlash on joint 2 (approach directions recorded): {training file, validation file}. */
    private Path[] backlashCampaign() throws Exception {
        RobotDescription robot = RobotLibrary.shipped("irb2000");
        KinematicModel nominal = KinematicModel.build(robot);
        double[][] prev = {null};
        Random cr = new Random(2);
        CampaignSimulator.ConditionsSource src = (rng, q, i) -> {
            int[] d = new int[q.length];
            for (int j = 0; j < q.length; j++) d[j] = prev[0] == null ? (cr.nextBoolean() ? 1 : -1) : (q[j] >= prev[0][j] ? 1 : -1);
            prev[0] = q.clone();
            return new PoseConditions(d, 20.0 * i, 20 + 10 * (1 - Math.exp(-20.0 * i / 1500)), Double.NaN);
        };
        Campaign c = CampaignSimulator.simulate(nominal, SimulationSettings.defaults().withPoses(150).withValidatePoses(60)
                        .withSigma(0.02e-3).withSeed(77),
                List.of(Effect.backlash(1).truth(new double[] {Math.toRadians(0.04)})), src);
        List<JointType> types = robot.joints().stream().map(j -> j.type()).toList();
        Path train = dir.resolve("train.csv"), val = dir.resolve("validate.csv");
        MeasurementWriter.write(c.measurements(), types, train, false);
        MeasurementWriter.write(c.validation(), types, val, false);
        return new Path[] {train, val};
    }

    @Test
    void diagnose_simulatedBacklashJoint2_writesReportJsonAndExtendedModel() throws Exception {
        Path[] files = backlashCampaign();
        Path train = files[0], val = files[1];
        Path outDir = System.getenv("ROBOPRO_KEEP_REPORT") != null ? Path.of(System.getenv("ROBOPRO_KEEP_REPORT")) : dir.resolve("out");
        assertEquals(0, run("diagnose", "--robot", "irb2000", "--measurements", train.toString(), "--validate", val.toString(),
                "--out", outDir.toString(), "--force"), cli.err());
        assertTrue(cli.out().contains("found backlash j2"), cli.out());
        JsonNode j = new ObjectMapper().readTree(Files.readString(outDir.resolve("diagnosis.json")));
        for (String f : new String[] {"geometric", "effects", "final", "outliers", "not_identifiable"}) assertTrue(j.has(f), f);
        assertEquals(1, j.get("effects").size());
        JsonNode e = j.get("effects").get(0);
        assertEquals("backlash", e.get("effect").asText());
        assertEquals(2, e.get("joints").get(0).asInt());
        assertEquals(Math.toRadians(0.04), e.get("parameters").get("b").asDouble(), Math.toRadians(0.004));
        assertTrue(j.get("final").get("validate_rms_mm").asDouble() < 0.5 * j.get("geometric").get("validate_rms_mm").asDouble());
        String html = Files.readString(outDir.resolve("report.html"));
        assertTrue(html.contains("<svg") && html.contains("backlash j2"));
        RobotDescription ext = RobotLibrary.read(outDir.resolve("extended.robot.json"));
        assertEquals("backlash", ext.effects().get(0).effect());

        // compensate reads the extended model's effects
        Path targets = dir.resolve("targets.csv");
        Files.writeString(targets, "# frame: base\nid,x,y,z\n1,1200,100,900\n2,1100,-300,1200\n");
        assertEquals(0, run("compensate", "--nominal", "irb2000", "--calibrated", outDir.resolve("extended.robot.json").toString(),
                "--targets", targets.toString(), "--out", dir.resolve("comp.csv").toString()), cli.err());
    }

    @Test
    void diagnose_missingMeasurementFile_exitCode2() {
        assertEquals(2, run("diagnose", "--robot", "irb2000", "--measurements", dir.resolve("none.csv").toString(), "--out",
                dir.resolve("o").toString()));
    }

    @Test
    void diagnose_folds_effectFoundInEveryFoldAndHeldOutErrorsDrop() throws Exception {
        Path[] files = backlashCampaign();
        Path outDir = dir.resolve("cv");
        assertEquals(0, run("diagnose", "--robot", "irb2000", "--measurements", files[0].toString(), "--folds", "3",
                "--out", outDir.toString()), cli.err());
        JsonNode c = new ObjectMapper().readTree(Files.readString(outDir.resolve("diagnosis.json"))).get("cross_validation");
        assertEquals(3, c.get("per_fold").size());
        int heldOut = 0;
        for (JsonNode f : c.get("per_fold")) heldOut += f.get("poses_held_out").asInt();
        assertEquals(150, heldOut);
        assertEquals(3, c.get("effect_counts").path("backlash j2").asInt(), c.toString());
        assertTrue(c.get("held_out_final_rms_mm").asDouble() < 0.8 * c.get("held_out_geometric_rms_mm").asDouble(), c.toString());
        assertTrue(cli.out().contains("backlash j2 found in 3 of 3 folds"), cli.out());
    }
}
