package org.robopro.calibration.identification;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robopro.calibration.measurement.MeasurementReader;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.calibration.measurement.MeasurementWriter;
import org.robopro.calibration.WorldCampaigns;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.importers.DhImporter;
import org.robopro.models.JointType;
import org.robopro.models.RobotDescription;

/** A robot given only as a modified-DH table, measured in 6-D by an instrument at an unknown pose, end to end through files. */
class ModifiedDhEndToEndTest {
    @TempDir Path dir;

    /** A six-axis arm in modified (Craig) DH form (α_{i-1}, a_{i-1}, θ_i offset, d_i), with an offset wrist. */
    static final String MDH = """
            # test arm, modified DH
            name: mdh-arm
            units: length=mm, angle=deg
            joint, alpha, a, theta, d, min, max
            j1, 0, 0, 0, 500, -170, 170
            j2, -90, 150, -90, 0, -90, 110
            j3, 0, 600, 0, 0, -120, 70
            j4, -90, 120, 0, 640, -190, 190
            j5, 90, 0, 0, 0, -115, 115
            j6, -90, 0, 180, 90, -350, 350
            """;

    @Test
    void calibrate_sixDMeasurementsOfImportedArm_reachNoiseFloor() throws Exception {
        RobotDescription desc = DhImporter.parse("arm.mdh", MDH, DhImporter.Convention.MODIFIED, "mdh-arm");
        KinematicModel nominal = KinematicModel.build(desc);
        // The true arm and its campaign come from the independent world simulator, which reads the
        // imported arm's axes (not its DH table) and writes the measurement file.
        WorldCampaigns.Sim c = WorldCampaigns.geometric(desc, 31, false, p -> p.withSixD(true).withPoses(200, 300));
        Path train = dir.resolve("m.csv"), val = dir.resolve("v.csv");
        List<JointType> types = new ArrayList<>();
        desc.joints().forEach(j -> types.add(j.type()));
        MeasurementWriter.write(c.train(), types, train, false);
        MeasurementWriter.write(c.validation(), types, val, false);
        MeasurementSet t = MeasurementReader.read(train, desc), v = MeasurementReader.read(val, desc);
        assertTrue(t.hasOrientation());
        CalibrationResult r = Calibrator.calibrate(nominal, t, v);
        CalibratorTest.report("mdh 6-D", c, r);
        double floor = c.floorM();
        assertTrue(r.sixD());
        assertEquals(1.0, r.validateRmsM() / floor, 0.10, "validation RMS / noise floor");
        assertTrue(WorldCampaigns.modelErrorRms(c, r) < 0.5 * floor);
        assertTrue(WorldCampaigns.modelAngleRms(c, r) < 0.5 * Math.sqrt(3) * c.sigmaRotRad());
        assertEquals(c.sigmaRotRad(), r.sigmaRotRad(), 0.15 * c.sigmaRotRad(), "estimated orientation noise");
    }
}
