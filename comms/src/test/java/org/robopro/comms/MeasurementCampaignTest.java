package org.robopro.comms;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robopro.comms.sim.ModelSimulatedRobot;
import org.robopro.comms.sim.SimulatedController;
import org.robopro.kinematics.Pose;
import org.robopro.models.RobotLibrary;
import org.robopro.models.Vec3;

class MeasurementCampaignTest {
    @TempDir Path dir;

    @Test
    void run_irb2000WithErrors_fileFollowsFormatAndRowsDeviateFromNominalByErrorSize() throws Exception {
        ModelSimulatedRobot robot = ModelSimulatedRobot.create(RobotLibrary.load("irb2000"), 4, 0.5e-3, List.of());
        SimulatedController sim = new SimulatedController(robot, SimulatedController.Settings.defaults(4).withNoise(0));
        Pose tool = Pose.translation(0.05, 0, 0.1);
        List<double[]> poses = new ArrayList<>();
        Random rnd = new Random(8);
        for (int k = 0; k < 25; k++) {
            double[] q = new double[6];
            for (int i = 0; i < 6; i++) q[i] = robot.lowerLimits()[i] * 0.5 + rnd.nextDouble() * (robot.upperLimits()[i] - robot.lowerLimits()[i]) * 0.5;
            poses.add(q);
        }
        try (CommandInvoker inv = new CommandInvoker(sim)) {
            inv.execute(Commands.setTool(tool));
            List<MeasurementCampaign.Row> rows = MeasurementCampaign.run(inv, poses);
            assertEquals(25, rows.size());
            double maxDev = 0, sumDev = 0;
            for (MeasurementCampaign.Row r : rows) {
                Vec3 nominal = sim.settings().trackerTbase().times(robot.nominalModel().flange(r.q())).times(tool).position();
                Vec3 truth = sim.settings().trackerTbase().times(robot.trueModel().flange(r.q())).times(tool).position();
                assertEquals(0, r.measured().minus(truth).norm(), 1e-12);
                double d = r.measured().minus(nominal).norm();
                maxDev = Math.max(maxDev, d);
                sumDev += d;
            }
            assertTrue(sumDev / rows.size() > 0.2e-3 && maxDev < 20e-3, "deviation from nominal " + sumDev / rows.size());
            Path file = dir.resolve("campaign.csv");
            MeasurementCampaign.write(file, "irb2000", "simulated laser tracker", rows, false);
            List<String> lines = Files.readAllLines(file);
            assertEquals("# robopro-measurements 1", lines.get(0));
            assertTrue(lines.contains("# length-unit: mm") && lines.contains("# angle-unit: deg") && lines.contains("# frame: tracker"));
            String header = lines.stream().filter(l -> l.startsWith("pose,")).findFirst().orElseThrow();
            assertEquals("pose,q1,q2,q3,q4,q5,q6,x,y,z,dir1,dir2,dir3,dir4,dir5,dir6", header);
            String[] first = lines.get(lines.indexOf(header) + 1).split(",");
            assertEquals(16, first.length);
            assertEquals(Math.toDegrees(poses.get(0)[1]), Double.parseDouble(first[2]), 1e-6);
            assertEquals(rows.get(0).measured().x() * 1000, Double.parseDouble(first[7]), 1e-4);
            assertThrows(java.nio.file.FileAlreadyExistsException.class,
                    () -> MeasurementCampaign.write(file, "irb2000", "x", rows, false));
        }
    }
}
