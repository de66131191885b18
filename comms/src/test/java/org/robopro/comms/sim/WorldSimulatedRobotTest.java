package org.robopro.comms.sim;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.PoseConditions;
import org.robopro.models.RobotLibrary;
import org.robopro.models.Vec3;

class WorldSimulatedRobotTest {
    @Test
    void measuresTheWorldRobotUnderTheControllersConditions() {
        var d = RobotLibrary.shipped("irb2000");
        WorldSimulatedRobot r = WorldSimulatedRobot.create(d, "lost motion j1, directions recorded", 3, 0, new Vec3(0, 0, 0.1));
        assertFalse(r.thermal());
        double[] q = {0.3, 0.2, -0.1, 0.4, 0.5, 0.6};
        int[] up = {1, 1, 1, 1, 1, 1}, down = {-1, 1, 1, 1, 1, 1};
        Vec3 a = r.measure(q, new PoseConditions(up, 0, Double.NaN, Double.NaN), new Random(1));
        assertArrayEquals(r.world().target(q, up, Double.NaN, 0, 0).p(), a.toArray(), 1e-15);
        // The approach direction of joint 1 moves the measured point: the world's lost motion acts.
        Vec3 b = r.measure(q, new PoseConditions(down, 0, Double.NaN, Double.NaN), new Random(1));
        assertTrue(a.minus(b).norm() > 1e-4, "lost motion moved the point by " + a.minus(b).norm());
        assertTrue(WorldSimulatedRobot.create(d, "thermal growth per link", 3, 0, new Vec3(0, 0, 0.1)).thermal());
        assertTrue(WorldSimulatedRobot.create(d, "outside: j2 zero moving with drive temperature", 3, 0, new Vec3(0, 0, 0.1)).thermal(),
                "a drive's thermal error needs the warm-up too");
        assertTrue(r.truthJson().get("effects").toString().contains("lost motion j1"));
        assertThrows(IllegalArgumentException.class, () -> WorldSimulatedRobot.create(d, "null puma560", 3, 0, new Vec3(0, 0, 0.1)));
        assertThrows(IllegalArgumentException.class, () -> WorldSimulatedRobot.create(d, "no such scenario", 3, 0, new Vec3(0, 0, 0.1)));
    }
}
