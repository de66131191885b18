package org.robopro.calibration.identification;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.WorldCampaigns;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.kinematics.KinematicModel;
import org.robopro.models.RobotLibrary;
import org.robopro.world.Rigid;
import org.robopro.world.Scenario;
import org.robopro.world.WorldRobot;

/**
 * The identifiability words on the case of a real campaign: a measured point 1.2 mm from the
 * joint-6 axis leaves the wrist offsets undetermined; 150 mm off the axis determines them. The
 * robot and its campaign come from the independent world simulator.
 */
class TrustTest {
    static final KinematicModel IRB = KinematicModel.build(RobotLibrary.shipped("irb2000"));

    /** A campaign of {@code poses} poses (σ 0.05 mm) on a world IRB 2000 whose measured point is {@code target} (m). */
    static MeasurementSet campaign(WorldRobot w, int poses, long seed) {
        return WorldCampaigns.measure(IRB.description(), w, org.robopro.world.Campaign.Plan.defaults(seed).withPoses(poses, 0)
                .withSigma(0.05e-3).withDirColumns(false).withConditionColumns(false)).train();
    }

    static WorldRobot robot(long seed) {
        return Scenario.baseRobot(IRB.description(), new Random(seed), 1e-3, Math.toRadians(0.1));
    }

    /** A world robot whose measured point sits {@code offAxisM} from its true joint-6 axis, 100 mm out along it. */
    static WorldRobot nearTheAxis(long seed, double offAxisM) {
        WorldRobot w = robot(seed);
        double[] p6 = w.arm().points()[5], a6 = w.arm().axes()[5];
        double[] side = Rigid.unit(Rigid.cross(a6, Math.abs(a6[2]) < 0.9 ? new double[] {0, 0, 1} : new double[] {1, 0, 0}));
        double[] point = Rigid.plus(p6, Rigid.plus(Rigid.scale(a6, 0.1), Rigid.scale(side, offAxisM)));
        double[] onFlange = w.arm().flange().inverse().apply(point);
        return w.withTool(Rigid.translation(onFlange[0], onFlange[1], onFlange[2]));
    }

    static WorldRobot at(long seed, double x, double y, double z) { return robot(seed).withTool(Rigid.translation(x, y, z)); }

    @Test
    void assess_pointNearTheJoint6Axis_wristOffsetsNamedWithAdviceToMoveThePoint() {
        MeasurementSet c = campaign(nearTheAxis(21, 0.0012), 30, 21);
        CalibrationResult r = Calibrator.calibrate(IRB, c, null);
        List<Trust.Concern> cs = Trust.assess(r, c);
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
        MeasurementSet c = campaign(at(22, 0.15, 0.05, 0.1), 150, 22);
        CalibrationResult r = Calibrator.calibrate(IRB, c, null);
        List<Trust.Concern> cs = Trust.assess(r, c);
        assertFalse(cs.stream().anyMatch(k -> k.parameter().startsWith("j5.")), cs.toString());
        for (var p : r.parameters())
            if (!p.fixed() && "m".equals(p.unitSi()) && p.sigma() < 1e-4 && cs.stream().noneMatch(k -> k.parameter().equals(p.name())))
                return;
        throw new AssertionError("expected well-determined parameters");
    }

    @Test
    void span_jointMovedOverLittleOfItsRange_saysWhichRangeToCover() {
        MeasurementSet c = campaign(at(23, 0.1, 0, 0.1), 40, 23);
        var rows = new java.util.ArrayList<org.robopro.calibration.measurement.Measurement>();
        for (var m : c.rows()) {
            double[] q = m.q();
            q[1] = 0.1 * q[1];
            rows.add(new org.robopro.calibration.measurement.Measurement(m.poseId(), q, m.position(), null, null, Double.NaN,
                    Double.NaN, Double.NaN, null, 0));
        }
        var set = c.withRows(rows);
        String s = Trust.span(set, IRB.description().joints().get(1), 1);
        assertTrue(s != null && s.startsWith("add poses with joint 2 over more of its range"), s);
        assertEquals(null, Trust.span(c, IRB.description().joints().get(0), 0), "joint 1 spans its range");
    }
}
