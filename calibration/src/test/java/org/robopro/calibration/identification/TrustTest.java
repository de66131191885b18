package org.robopro.calibration.identification;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.simulation.Campaign;
import org.robopro.calibration.simulation.CampaignSimulator;
import org.robopro.calibration.simulation.SimulationSettings;
import org.robopro.kinematics.KinematicModel;
import org.robopro.models.RobotLibrary;
import org.robopro.models.Vec3;

/**
 * The identifiability words on the case of a real campaign: a measured point 1.2 mm from the
 * joint-6 axis leaves the wrist offsets undetermined; 150 mm off the axis determines them.
 */
class TrustTest {
    static final KinematicModel IRB = KinematicModel.build(RobotLibrary.shipped("irb2000"));

    static Campaign campaign(Vec3 target, int poses, long seed) {
        return CampaignSimulator.simulate(IRB, new SimulationSettings(poses, 0, 0.05e-3, 20e-6, 10e-3, 0, target, false, false, seed));
    }

    @Test
    void assess_pointNearTheJoint6Axis_wristOffsetsNamedWithAdviceToMoveThePoint() {
        Campaign c = campaign(new Vec3(0.0012, 0, 0.1), 30, 21);
        CalibrationResult r = Calibrator.calibrate(IRB, c.measurements(), null);
        List<Trust.Concern> cs = Trust.assess(r, c.measurements());
        cs.forEach(k -> System.out.println(k.sentence()));
        Trust.Concern j5 = cs.stream().filter(k -> k.parameter().startsWith("j5.")).findFirst().orElseThrow(() -> new AssertionError(cs));
        assertTrue(j5.advice().contains("move the measured point off the joint-6 axis"), j5.advice());
        assertTrue(j5.sentence().contains("do not rely on the calibrated file for another tool point"), j5.sentence());
        // Every named parameter has a real reason: a sigma above the limit or a correlation above 0.99.
        for (Trust.Concern k : cs) {
            var p = r.parameter(k.parameter());
            boolean big = "m".equals(p.unitSi()) ? p.sigma() > 1e-3 : Math.toDegrees(p.sigma()) > 0.1;
            boolean corr = r.correlations().stream().anyMatch(x -> Math.abs(x.rho()) > 0.99
                    && (x.a().equals(k.parameter()) || x.b().equals(k.parameter())));
            assertTrue(big || corr, k.toString());
        }
    }

    @Test
    void assess_pointFarFromTheAxisAndManyPoses_wristOffsetsTrusted() {
        Campaign c = campaign(new Vec3(0.15, 0.05, 0.1), 150, 22);
        CalibrationResult r = Calibrator.calibrate(IRB, c.measurements(), null);
        List<Trust.Concern> cs = Trust.assess(r, c.measurements());
        assertFalse(cs.stream().anyMatch(k -> k.parameter().startsWith("j5.")), cs.toString());
        for (var p : r.parameters())
            if (!p.fixed() && "m".equals(p.unitSi()) && p.sigma() < 1e-4 && cs.stream().noneMatch(k -> k.parameter().equals(p.name())))
                return;
        throw new AssertionError("expected well-determined parameters");
    }

    @Test
    void span_jointMovedOverLittleOfItsRange_saysWhichRangeToCover() {
        Campaign c = campaign(new Vec3(0.1, 0, 0.1), 40, 23);
        var rows = new java.util.ArrayList<org.robopro.calibration.measurement.Measurement>();
        for (var m : c.measurements().rows()) {
            double[] q = m.q();
            q[1] = 0.1 * q[1];
            rows.add(new org.robopro.calibration.measurement.Measurement(m.poseId(), q, m.position(), null, null, Double.NaN,
                    Double.NaN, Double.NaN, null, 0));
        }
        var set = c.measurements().withRows(rows);
        String s = Trust.span(set, IRB.description().joints().get(1), 1);
        assertTrue(s != null && s.startsWith("add poses with joint 2 over more of its range"), s);
        assertEquals(null, Trust.span(c.measurements(), IRB.description().joints().get(0), 0), "joint 1 spans its range");
    }
}
