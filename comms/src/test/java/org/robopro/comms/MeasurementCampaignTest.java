package org.robopro.comms;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.measurement.MeasurementReader;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.comms.sim.SimEffects;
import org.robopro.comms.sim.SimulatedController;
import org.robopro.comms.sim.WorldSimulatedRobot;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
import org.robopro.models.Vec3;

/**
 * A measuring campaign through the simulated controller, whose physical robot comes from the
 * independent world simulator: each row is what the world's robot measured under the conditions
 * the row records.
 */
class MeasurementCampaignTest {
    @TempDir Path dir;

    @Test
    void run_irb2000ThermalNoNoise_rowsAreTruthWithConditionsAndFileRoundTrips() throws Exception {
        RobotDescription d = RobotLibrary.load("irb2000");
        WorldSimulatedRobot robot = WorldSimulatedRobot.create(d, "lost motion j2 + thermal growth per link", 4, 0, new Vec3(0, 0, 0.1));
        SimulatedController sim = new SimulatedController(robot, SimulatedController.Settings.defaults(4).withPayload(2.5));
        List<double[]> poses = MeasurementCampaign.samplePoses(org.robopro.kinematics.KinematicModel.build(d), 25, 8);
        try (CommandInvoker inv = new CommandInvoker(sim)) {
            MeasurementSet set = MeasurementCampaign.run(inv, poses, "irb2000", "simulated laser tracker");
            assertEquals(25, set.size());
            double[] prev = new double[6];
            double prevTime = 0, prevTemp = SimEffects.T0_C;
            for (int k = 0; k < set.size(); k++) {
                Measurement m = set.rows().get(k);
                for (int i = 0; i < 6; i++)
                    if (poses.get(k)[i] != prev[i]) assertEquals(poses.get(k)[i] > prev[i] ? 1 : -1, m.directions()[i], "dir" + (i + 1) + " of pose " + (k + 1));
                assertTrue(m.timeS() > prevTime, "time advances with the motions");
                assertTrue(m.tempC() > prevTemp && m.tempC() < SimEffects.T0_C + SimEffects.WARMUP_K, "warm-up curve: " + m.tempC());
                assertEquals(2.5, m.payloadKg(), 0);
                double[] truth = robot.world().target(m.q(), m.directions(), m.tempC(), m.timeS(), m.payloadKg()).p();
                assertEquals(0, m.position().minus(new Vec3(truth[0], truth[1], truth[2])).norm(), 1e-12);
                prev = m.q();
                prevTime = m.timeS();
                prevTemp = m.tempC();
            }
            Path file = dir.resolve("campaign.csv");
            MeasurementCampaign.write(set, d.joints().stream().map(j -> j.type()).toList(), file, false);
            List<String> lines = Files.readAllLines(file);
            assertEquals("# robopro-measurements 1", lines.get(0));
            assertTrue(lines.contains("# length-unit: mm") && lines.contains("# angle-unit: deg") && lines.contains("# frame: tracker"));
            assertTrue(lines.contains("pose,q1,q2,q3,q4,q5,q6,x,y,z,dir1,dir2,dir3,dir4,dir5,dir6,time_s,temp_c,payload_kg"), lines.toString());
            MeasurementSet back = MeasurementReader.read(file, d);
            assertEquals(25, back.size());
            for (int k = 0; k < 25; k++) {
                Measurement a = set.rows().get(k), b = back.rows().get(k);
                assertEquals(0, a.position().minus(b.position()).norm(), 1e-8);
                assertArrayEquals(a.directions(), b.directions());
                assertEquals(a.timeS(), b.timeS(), 1e-3);
                assertEquals(a.tempC(), b.tempC(), 1e-3);
            }
            assertThrows(FileAlreadyExistsException.class, () -> MeasurementCampaign.write(set, null, file, false));
        }
    }

    @Test
    void run_withoutThermalEffect_fileHasNoTemperatureColumn() throws Exception {
        RobotDescription d = RobotLibrary.load("irb2000");
        WorldSimulatedRobot robot = WorldSimulatedRobot.create(d, "null irb2000", 5, 20e-6, new Vec3(0, 0, 0.1));
        SimulatedController sim = new SimulatedController(robot, SimulatedController.Settings.defaults(5));
        try (CommandInvoker inv = new CommandInvoker(sim)) {
            MeasurementSet set = MeasurementCampaign.run(inv, MeasurementCampaign.samplePoses(org.robopro.kinematics.KinematicModel.build(d), 5, 1), "irb2000", "t");
            Path file = dir.resolve("c.csv");
            MeasurementCampaign.write(set, null, file, false);
            assertTrue(Files.readAllLines(file).contains("pose,q1,q2,q3,q4,q5,q6,x,y,z,dir1,dir2,dir3,dir4,dir5,dir6,time_s,payload_kg"));
        }
    }
}
