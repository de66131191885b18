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
 * pose and per drive, the side of the play each gear really rests on (from the real measuring
 * sequence, starting at the home position, on the motor side of a parallel-arm linkage; in a
 * joint-by-joint campaign the joints that stand still show only read-back jitter). The
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
