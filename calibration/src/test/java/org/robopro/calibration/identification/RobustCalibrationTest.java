package org.robopro.calibration.identification;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.WorldCampaigns;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.kinematics.KinematicModel;
import org.robopro.models.InputException;
import org.robopro.models.RobotLibrary;
import org.robopro.models.Vec3;

/**
 * Wild poses (a corrupted digit, a swapped sign, a reading kilometres off) must not shape the
 * final fit: with up to 5 % of them the validation error equals the clean fit's within noise. The
 * robots and campaigns come from the independent world simulator; the fits are also compared with
 * the world's noise-free truth.
 */
class RobustCalibrationTest {
    static KinematicModel model(String name) { return KinematicModel.build(RobotLibrary.load(name)); }

    /** A world robot of {@code nominal}'s file with geometric errors, measured at {@code poses} + {@code validate} poses. */
    static WorldCampaigns.Sim world(KinematicModel nominal, long seed, int poses, int validate) {
        return WorldCampaigns.geometric(nominal.description(), seed, false,
                p -> p.withPoses(poses, validate).withDirColumns(false).withConditionColumns(false));
    }

    /** Replaces {@code count} training rows (chosen at random) by wild values of the given sizes, m. */
    static List<Measurement> spoil(List<Measurement> clean, int count, double[] sizes, long seed) {
        List<Measurement> rows = new ArrayList<>(clean);
        Random rng = new Random(seed);
        List<Integer> idx = new ArrayList<>();
        for (int i = 0; i < rows.size(); i++) idx.add(i);
        java.util.Collections.shuffle(idx, rng);
        for (int k = 0; k < count; k++) {
            int i = idx.get(k);
            Measurement m = rows.get(i);
            double s = sizes[k % sizes.length];
            Vec3 d = new Vec3(rng.nextGaussian(), rng.nextGaussian(), rng.nextGaussian());
            rows.set(i, m.withPosition(m.position().plus(d.times(s / d.norm()))));
        }
        return rows;
    }

    @ParameterizedTest
    @CsvSource({"irb2000, 21, 8", "irb2400, 22, 8", "puma560, 23, 8", "irb2000, 24, 1"})
    void calibrate_withUpTo5PercentWildPoses_equalsTheCleanFitWithinNoise(String robot, long seed, int wild) {
        KinematicModel nominal = model(robot);
        WorldCampaigns.Sim c = world(nominal, seed, 160, 300);
        CalibrationResult clean = Calibrator.calibrate(nominal, c.train(), c.validation());
        // 50 m (a digit in the wrong place), 1 m, 200 mm (one corrupted digit), 20 mm, 2 mm.
        double[] sizes = {50, 1.0, 0.2, 0.02, 0.002, 0.2, 5, 0.05};
        List<Measurement> rows = spoil(c.train().rows(), wild, sizes, seed);
        CalibrationResult r = Calibrator.calibrate(nominal, c.train().withRows(rows), c.validation());
        double trueClean = WorldCampaigns.modelErrorRms(c, clean), trueWild = WorldCampaigns.modelErrorRms(c, r);
        System.out.printf("%s/%d: clean validate %.4f mm, with %d wild %.4f mm, %d flagged; against the world's truth %.4f -> %.4f mm%n",
                robot, seed, clean.validateRmsM() * 1e3, wild, r.validateRmsM() * 1e3, r.outliers().size(), trueClean * 1e3, trueWild * 1e3);
        assertEquals(1.0, r.validateRmsM() / clean.validateRmsM(), 0.05, "validation RMS relative to the clean fit");
        // Against the noise-free truth: the clean fit is within the noise of the truth, and the wild poses add little to that.
        assertTrue(trueClean < 0.5 * c.floorM(), "clean fit off the truth by " + trueClean * 1e3 + " mm");
        assertTrue(trueWild < trueClean + 0.25 * c.floorM(), "with wild poses off the truth by " + trueWild * 1e3 + " mm");
        assertTrue(r.outliers().size() >= wild && r.outliers().size() <= wild + 3, "flagged " + r.outliers().size());
        // Every flagged pose is excluded from the final training RMS; the wild ones are all flagged.
        for (int i = 0; i < rows.size(); i++)
            if (rows.get(i) != c.train().rows().get(i)) {
                String id = rows.get(i).poseId();
                assertTrue(r.outliers().stream().anyMatch(o -> o.poseId().equals(id)), "wild pose " + id + " not flagged");
            }
    }

    @Test
    void calibrate_nonPhysicalCoordinate_isRefusedNamingLineAndField() {
        KinematicModel nominal = model("irb2000");
        MeasurementSet c = world(nominal, 5, 60, 0).train();
        for (double v : new double[] {1e200, 1e100, Double.NaN, 1e6}) {
            List<Measurement> rows = new ArrayList<>(c.rows());
            Measurement m = rows.get(7);
            rows.set(7, new Measurement(m.poseId(), m.q(), new Vec3(m.position().x(), v, m.position().z()), m.orientation(),
                    m.directions(), m.timeS(), m.tempC(), m.payloadKg(), m.set(), 42));
            InputException e = assertThrows(InputException.class,
                    () -> Calibrator.calibrate(nominal, c.withRows(rows), null), "y = " + v);
            assertTrue(e.getMessage().contains(":42") && e.getMessage().contains("y"), e.getMessage());
        }
    }
}
