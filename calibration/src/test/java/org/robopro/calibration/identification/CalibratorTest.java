package org.robopro.calibration.identification;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.robopro.calibration.WorldCampaigns;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.kinematics.KinematicModel;
import org.robopro.models.InputException;
import org.robopro.models.RobotLibrary;
import org.robopro.models.Vec3;

/**
 * Campaigns of the independent world simulator (its own kinematics and geometric errors, written
 * as measurement files and read back) are calibrated down to the noise floor, and the calibrated
 * model predicts the world's noise-free truth. The truth is not in this module's
 * parameterisation, so it is compared through predictions, not parameter by parameter.
 */
class CalibratorTest {
    static KinematicModel model(String name) { return KinematicModel.build(RobotLibrary.load(name)); }

    static void report(String label, WorldCampaigns.Sim c, CalibrationResult r) {
        System.out.printf("%s: nominal %.3f mm -> train %.4f validate %.4f mm (floor %.4f), cond %.1f, O1 %.3g, iters %d %s, %.1f ms, fixed %d%n",
                label, r.nominalTrainRmsM() * 1e3, r.trainRmsM() * 1e3, r.validateRmsM() * 1e3,
                c.floorM() * 1e3, r.conditionNumber(), r.observability(),
                r.fit().iterations(), r.fit().reason(), r.elapsedMs(), r.unidentifiable().size());
        for (var d : r.unidentifiable()) System.out.println("  fixed " + d.fixed() + ": " + d.describe());
    }

    @ParameterizedTest
    @CsvSource({"irb2000, 7", "irb2000, 8", "irb2000, 9", "irb2400, 7", "irb2400, 8", "puma560, 7", "puma560, 8"})
    void calibrate_simulatedCampaign_reachesNoiseFloorAndTruth(String robot, long seed) {
        KinematicModel nominal = model(robot);
        WorldCampaigns.Sim c = WorldCampaigns.geometric(nominal.description(), seed, false, p -> p.withPoses(200, 400));
        double nominalError = c.nominalErrorRmsM(nominal);
        assertTrue(nominalError > 1e-3 && nominalError < 30e-3, "nominal error " + nominalError);
        CalibrationResult r = Calibrator.calibrate(nominal, c.train(), c.validation());
        report(robot + "/" + seed, c, r);
        double floor = c.floorM();
        assertTrue(r.fit().converged(), r.fit().reason().toString());
        assertTrue(r.nominalTrainRmsM() > 1e-3, "nominal fit should leave mm errors: " + r.nominalTrainRmsM());
        assertEquals(1.0, r.validateRmsM() / floor, 0.10, "validation RMS / noise floor");
        assertTrue(r.trainRmsM() < floor * 1.05);
        // The calibrated model predicts the world's noise-free truth far better than the noise.
        assertTrue(WorldCampaigns.modelErrorRms(c, r) < 0.5 * floor, "model error " + WorldCampaigns.modelErrorRms(c, r));
    }

    @Test
    void calibrate_sixDInBaseFrame_identifiesToolFrame() {
        KinematicModel nominal = model("irb2000");
        WorldCampaigns.Sim c = WorldCampaigns.geometric(nominal.description(), 3, true, p -> p.withSixD(true).withPoses(200, 300));
        CalibrationResult r = Calibrator.calibrate(nominal, c.train(), c.validation());
        report("irb2000 6-D", c, r);
        assertEquals(1.0, r.validateRmsM() / c.floorM(), 0.10);
        assertTrue(WorldCampaigns.modelErrorRms(c, r) < 0.5 * c.floorM(), "model error " + WorldCampaigns.modelErrorRms(c, r));
        assertTrue(WorldCampaigns.modelAngleRms(c, r) < 0.5 * Math.sqrt(3) * c.sigmaRotRad(), "angle error " + WorldCampaigns.modelAngleRms(c, r));
    }

    @Test
    void calibrate_tooFewPoses_refusesSayingHowMany() {
        KinematicModel nominal = model("irb2000");
        WorldCampaigns.Sim c = WorldCampaigns.geometric(nominal.description(), 1, false, p -> p.withPoses(6, 0));
        InputException e = assertThrows(InputException.class, () -> Calibrator.calibrate(nominal, c.train(), null));
        assertTrue(e.getMessage().contains("measure at least"), e.getMessage());
    }

    @Test
    void calibrate_collinearPoints_saysInstrumentFrameCannotBeDetermined() {
        KinematicModel nominal = model("irb2000");
        WorldCampaigns.Sim c = WorldCampaigns.geometric(nominal.description(), 1, false, p -> p.withPoses(40, 0));
        // Put every measured point on a line.
        List<Measurement> rows = new ArrayList<>();
        int i = 0;
        for (Measurement m : c.train().rows()) rows.add(m.withPosition(new Vec3(0.01 * i++, 0, 0)));
        InputException e = assertThrows(InputException.class,
                () -> Calibrator.calibrate(nominal, c.train().withRows(rows), null));
        assertTrue(e.getMessage().contains("frame: base"), e.getMessage());
    }

    @Test
    void calibrate_grossOutliers_areFlaggedByIdAndDoNotSpoilTheFit() {
        KinematicModel nominal = model("irb2000");
        WorldCampaigns.Sim c = WorldCampaigns.geometric(nominal.description(), 21, false, p -> p.withPoses(200, 300));
        List<Measurement> rows = new ArrayList<>(c.train().rows());
        List<String> moved = new ArrayList<>();
        for (int k : new int[] {5, 77, 150}) {
            Measurement m = rows.get(k);
            moved.add(m.poseId());
            rows.set(k, m.withPosition(m.position().plus(new Vec3(0.5e-3, -0.3e-3, 0.4e-3))));
        }
        CalibrationResult r = Calibrator.calibrate(nominal, c.train().withRows(rows), c.validation());
        List<String> ids = r.outliers().stream().map(CalibrationResult.Outlier::poseId).toList();
        assertTrue(ids.containsAll(moved), ids + " should contain " + moved);
        assertTrue(ids.size() <= 4, ids.toString());
        assertEquals(1.0, r.validateRmsM() / c.floorM(), 0.10);
    }
}
