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
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
import org.robopro.world.Campaign;
import org.robopro.world.JointError;
import org.robopro.world.Scenario;
import org.robopro.world.WorldRobot;

/**
 * robopro diagnose end to end: a real IRB 2000 drawn by the independent world simulator with
 * 0.04° of lost motion on joint 1 (the output lagging its motor), measured in the nearest-next
 * order with directions recorded, a validation campaign on the same robot; files written, effect
 * named with its size, compensate uses the extended model; cross-validated folds.
 */
class DiagnoseCommandTest {
    @TempDir Path dir;
    private final CliHarness cli = new CliHarness();

    private int run(String... args) { return cli.run(args); }

    /**
     * A real IRB 2000 of the world simulator with 0.04° of lost motion on joint 1, measured in the
     * nearest-next order with directions recorded: {training file (150 poses), validation file
     * (60 poses, a second campaign on the same robot)}.
     */
    private Path[] lostMotionCampaign() throws Exception {
        RobotDescription robot = RobotLibrary.shipped("irb2000");
        WorldRobot w = Scenario.baseRobot(robot, new Random(77), 1e-3, Math.toRadians(0.1))
                .withErrors(List.of(new JointError.LostMotion(0, Math.toRadians(0.04))));
        Path train = dir.resolve("train.csv"), val = dir.resolve("validate.csv");
        Files.writeString(train, Campaign.run(w, robot, Campaign.Plan.defaults(77).withPoses(150, 0)).text());
        Files.writeString(val, Campaign.run(w, robot, Campaign.Plan.defaults(78).withPoses(60, 0)).text());
        return new Path[] {train, val};
    }

    /**
     * A structure modelled by a fallback is printed as located, with no physics named: the world's
     * tracker whose air compensation drifts, which the diagnosis models as the instrument's scale.
     */
    @Test
    void diagnose_aFallback_isPrintedAsLocatedNotFound() throws Exception {
        var t = Scenario.named("outside: the tracker's air compensation drifts as the hall warms").trial(20261126);
        Path train = dir.resolve("air.csv");
        Files.writeString(train, t.campaign().text());
        assertEquals(0, run("diagnose", "--robot", "irb2000", "--measurements", train.toString(), "--out", dir.resolve("air").toString()),
                cli.err());
        assertTrue(cli.out().contains("  located instrument-scale (") && cli.out().contains("(modelled, no known family)"), cli.out());
        assertTrue(!cli.out().contains("  found "), cli.out());
    }

    @Test
    void diagnose_worldLostMotionJoint1_writesReportJsonAndExtendedModel() throws Exception {
        Path[] files = lostMotionCampaign();
        Path train = files[0], val = files[1];
        Path outDir = System.getenv("ROBOPRO_KEEP_REPORT") != null ? Path.of(System.getenv("ROBOPRO_KEEP_REPORT")) : dir.resolve("out");
        assertEquals(0, run("diagnose", "--robot", "irb2000", "--measurements", train.toString(), "--validate", val.toString(),
                "--out", outDir.toString(), "--force"), cli.err());
        assertTrue(cli.out().contains("found backlash j1"), cli.out());
        JsonNode j = new ObjectMapper().readTree(Files.readString(outDir.resolve("diagnosis.json")));
        for (String f : new String[] {"geometric", "effects", "final", "outliers", "not_identifiable"}) assertTrue(j.has(f), f);
        assertEquals(1, j.get("effects").size());
        JsonNode e = j.get("effects").get(0);
        assertEquals("backlash", e.get("effect").asText());
        assertEquals(1, e.get("joints").get(0).asInt());
        assertEquals(Math.toRadians(0.04), e.get("parameters").get("b").asDouble(), Math.toRadians(0.004));
        assertTrue(j.get("final").get("validate_rms_mm").asDouble() < 0.5 * j.get("geometric").get("validate_rms_mm").asDouble());
        String html = Files.readString(outDir.resolve("report.html"));
        assertTrue(html.contains("<svg") && html.contains("backlash j1"));
        RobotDescription ext = RobotLibrary.read(outDir.resolve("extended.robot.json"));
        assertEquals("backlash", ext.effects().get(0).effect());

        // compensate reads the extended model's effects
        Path targets = dir.resolve("targets.csv");
        Files.writeString(targets, "# frame: base\nid,x,y,z\n1,1200,100,900\n2,1100,-300,1200\n");
        assertEquals(0, run("compensate", "--nominal", "irb2000", "--calibrated", outDir.resolve("extended.robot.json").toString(),
                "--targets", targets.toString(), "--out", dir.resolve("comp.csv").toString()), cli.err());
    }

    /** A file whose header names another robot is diagnosed, and the mismatch is said on stderr and first in the report. */
    @Test
    void diagnose_fileMeasuredOnAnotherRobot_warnsFirst() throws Exception {
        String text = lostMotionCampaignText();
        assertTrue(text.contains("# robot: irb2000\n"), text.substring(0, 200));
        Path train = dir.resolve("other.csv");
        Files.writeString(train, text.replace("# robot: irb2000\n", "# robot: irb2400\n"));
        Path outDir = dir.resolve("other");
        assertEquals(0, run("diagnose", "--robot", "irb2000", "--measurements", train.toString(), "--out", outDir.toString()), cli.err());
        String said = "other.csv was measured on 'irb2400', but the robot given is 'irb2000'";
        assertTrue(cli.err().contains("robopro: warning: " + said), cli.err());
        JsonNode j = new ObjectMapper().readTree(Files.readString(outDir.resolve("diagnosis.json")));
        assertEquals(said, j.get("warnings").get(0).asText());
    }

    private String lostMotionCampaignText() throws Exception { return Files.readString(lostMotionCampaign()[0]); }

    @Test
    void diagnose_missingMeasurementFile_exitCode2() {
        assertEquals(2, run("diagnose", "--robot", "irb2000", "--measurements", dir.resolve("none.csv").toString(), "--out",
                dir.resolve("o").toString()));
    }

    @Test
    void diagnose_folds_effectFoundInEveryFoldAndHeldOutErrorsDrop() throws Exception {
        Path[] files = lostMotionCampaign();
        Path outDir = dir.resolve("cv");
        assertEquals(0, run("diagnose", "--robot", "irb2000", "--measurements", files[0].toString(), "--folds", "3",
                "--out", outDir.toString()), cli.err());
        JsonNode c = new ObjectMapper().readTree(Files.readString(outDir.resolve("diagnosis.json"))).get("cross_validation");
        assertEquals(3, c.get("per_fold").size());
        int heldOut = 0;
        for (JsonNode f : c.get("per_fold")) heldOut += f.get("poses_held_out").asInt();
        assertEquals(150, heldOut);
        assertEquals(3, c.get("effect_counts").path("backlash j1").asInt(), c.toString());
        assertTrue(c.get("held_out_final_rms_mm").asDouble() < 0.8 * c.get("held_out_geometric_rms_mm").asDouble(), c.toString());
        assertTrue(cli.out().contains("backlash j1 found in 3 of 3 folds"), cli.out());
    }
}
