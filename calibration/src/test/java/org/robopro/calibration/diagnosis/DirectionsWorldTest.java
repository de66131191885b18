package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.UnaryOperator;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.measurement.MeasurementReader;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.models.JointDescription;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
import org.robopro.world.Campaign;
import org.robopro.world.Scenario;

/**
 * Inferred directions against the truth of the independent world simulator: the world knows, per
 * pose and per drive, the sign of the last real motion (from the real measuring sequence, starting
 * at the home position, on the motor side of a parallel-arm linkage; in a joint-by-joint campaign
 * the joints that stand still show only read-back jitter). These campaigns have no play, so that
 * sign is also the flank each output rests on. The
 * campaign is written without dir columns, read back by the product's reader (training and
 * validation rows interleaved in one file), and every pose's inferred direction must equal the truth.
 */
class DirectionsWorldTest {
    @ParameterizedTest(name = "{0}, {1} order, {2} joints moved per pose (0: all), seed {3}")
    @CsvSource({"irb2000,NEAREST,0,1", "irb2000,AS_DRAWN,0,2", "irb2400,NEAREST,0,3", "puma560,NEAREST,0,4", "puma560,AS_DRAWN,0,5",
            "irb2000,NEAREST,2,6", "irb2000,NEAREST,1,7", "puma560,NEAREST,3,8"})
    void inferredDirections_equalTheWorldsTrueDirections_onEveryPoseAndDrive(String robot, Campaign.Order order, int moved, long seed) {
        // moved > 0: a joint-by-joint campaign, the still joints showing only the controller's read-back jitter
        // the campaign drawn from the plan seeded with the case's seed
        check(robot, seed, p -> p.withSeed(seed).withDirColumns(false).withOrder(order).withMovedJoints(moved));
    }

    /**
     * Joint-by-joint campaigns on the world's own draws (each scenario's stream): long runs of a
     * still joint, whose read-back jitter must never add up to a reversal.
     */
    @ParameterizedTest(name = "irb2000, one joint moved per pose, seed {0}")
    @org.junit.jupiter.params.provider.ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20,
            21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40})
    void stillJointsJitter_neverTurnTheirFlank(long seed) {
        check("irb2000", seed, p -> p.withDirColumns(false).withMovedJoints(1));
    }

    /**
     * A controller that logs, for a still joint, the sign of its read-back jitter: the recorded
     * direction then turns with every jitter, though no play was taken up. Recorded directions
     * against the joint's last real move after a move within the jitter are read as that move's, and
     * every pose's direction equals the world's true flank again.
     */
    @ParameterizedTest(name = "irb2000, one joint moved per pose, seed {0}")
    @org.junit.jupiter.params.provider.ValueSource(longs = {3, 4})
    void recordedJitterSigns_areReadAsTheLastRealMove(long seed) {
        Scenario s = Scenario.ofFamily("null").stream().filter(x -> x.robot().equals("irb2000")).findFirst().orElseThrow();
        Campaign.Result c = s.trial(seed, p -> p.withMovedJoints(1)).campaign();
        RobotDescription r = RobotLibrary.shipped("irb2000");
        MeasurementSet all = MeasurementReader.parse("world.csv", c.text(), r.joints().stream().map(JointDescription::type).toList());
        assertTrue(all.hasDirections(), "dir columns written");
        List<Measurement> inOrder = Directions.ordered(all.rows()), logged = new ArrayList<>();
        int flipped = 0;
        double[] prev = null;
        for (Measurement m : inOrder) {
            int[] d = m.directions().clone();
            for (int j = 0; prev != null && j < r.dof(); j++) {
                double jitter = m.q(j) - prev[j];
                int sign = jitter > 0 ? 1 : -1;
                if (jitter != 0 && Math.abs(jitter) <= Directions.PLAY_TOLERANCE && d[j] != sign) { d[j] = sign; flipped++; }
            }
            prev = m.q();
            logged.add(m.withConditions(d, m.timeS(), m.tempC(), m.payloadKg()));
        }
        assertTrue(flipped > 20, "jitter signs against the flank: " + flipped);
        MeasurementSet withJitterSigns = all.withRows(logged);
        Directions.Prepared p = Directions.prepare(withJitterSigns.split(Measurement.Split.TRAIN), withJitterSigns.split(Measurement.Split.VALIDATE));
        assertSame(Directions.Source.RECORDED, p.source());
        Map<String, int[]> read = new HashMap<>();
        for (Measurement m : p.train().rows()) read.put(m.poseId(), m.directions());
        for (Measurement m : p.validate().rows()) read.put(m.poseId(), m.directions());
        List<String> wrong = new ArrayList<>();
        for (Campaign.Row row : c.rows())
            for (int j = 0; j < r.dof(); j++)
                if (read.get(row.id())[j] != row.dir()[j]) wrong.add("pose " + row.id() + " drive " + (j + 1));
        assertEquals(List.of(), wrong, "poses whose direction differs from the world's");
        assertEquals(1, p.notes().size(), p.notes().toString());
    }

    private static void check(String robot, long seed, UnaryOperator<Campaign.Plan> plan) {
        Scenario s = Scenario.ofFamily("null").stream().filter(x -> x.robot().equals(robot)).findFirst().orElseThrow();
        Campaign.Result c = s.trial(seed, plan).campaign();
        RobotDescription r = RobotLibrary.shipped(robot);
        MeasurementSet all = MeasurementReader.parse("world.csv", c.text(), r.joints().stream().map(JointDescription::type).toList());
        assertTrue(all.hasSplit() && !all.hasDirections(), "validation rows interleaved, no dir columns");
        Directions.Prepared p = Directions.prepare(all.split(Measurement.Split.TRAIN), all.split(Measurement.Split.VALIDATE));
        assertSame(Directions.Source.TIME_ORDER, p.source());
        assertEquals(List.of(), differing(c, p, r.dof()), "poses whose inferred direction differs from the world's");
        assertEquals(c.rows().size(), p.train().size() + p.validate().size());
    }

    /** The poses and drives whose prepared direction is not the world's true flank. */
    private static List<String> differing(Campaign.Result c, Directions.Prepared p, int dof) {
        Map<String, int[]> read = new HashMap<>();
        for (Measurement m : p.train().rows()) read.put(m.poseId(), m.directions());
        for (Measurement m : p.validate().rows()) read.put(m.poseId(), m.directions());
        List<String> wrong = new ArrayList<>();
        for (Campaign.Row row : c.rows())
            for (int j = 0; j < dof; j++)
                if (read.get(row.id())[j] != row.dir()[j]) wrong.add("pose " + row.id() + " drive " + (j + 1));
        return wrong;
    }
}
