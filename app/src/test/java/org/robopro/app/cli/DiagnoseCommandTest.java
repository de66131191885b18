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
 * order with directions recorded, written as one measurement file with a set column; files
 * written, effect named with its size, compensate uses the extended model.
 */
class DiagnoseCommandTest {
    @TempDir Path dir;
    private final CliHarness cli = new CliHarness();

    private int run(String... args) { return cli.run(args); }

    @Test
    void diagnose_worldLostMotionJoint1_writesReportJsonAndExtendedModel() throws Exception {
        RobotDescription robot = RobotLibrary.shipped("irb2000");
        WorldRobot w = Scenario.baseRobot(robot, new Random(77), 1e-3, Math.toRadians(0.1))
                .withErrors(List.of(new JointError.LostMotion(0, Math.toRadians(0.04))));
        Campaign.Result c = Campaign.run(w, robot, Campaign.Plan.defaults(77).withPoses(150, 60));
        Path train = dir.resolve("campaign.csv");
        Files.writeString(train, c.text());
        Path outDir = System.getenv("ROBOPRO_KEEP_REPORT") != null ? Path.of(System.getenv("ROBOPRO_KEEP_REPORT")) : dir.resolve("out");
        assertEquals(0, run("diagnose", "--robot", "irb2000", "--measurements", train.toString(),
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

    @Test
    void diagnose_missingMeasurementFile_exitCode2() {
        assertEquals(2, run("diagnose", "--robot", "irb2000", "--measurements", dir.resolve("none.csv").toString(), "--out",
                dir.resolve("o").toString()));
    }
}
