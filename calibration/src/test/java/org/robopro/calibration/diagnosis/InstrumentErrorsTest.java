package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.function.UnaryOperator;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.WorldCampaigns;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.models.RobotLibrary;
import org.robopro.models.Vec3;

/**
 * Errors of the measuring instrument, not of the robot, against truth written here: a world
 * campaign with geometric errors only (org.robopro.world: its own kinematics, nothing shared with
 * {@link Effect}), measured in the laser tracker's own frame, whose readings are then made to lie
 * the way a tracker's do. A tracker measures a distance (interferometer or absolute distance meter)
 * and two angles (azimuth about its standing axis, elevation above its horizon); each reading has
 * its own error (Muralikrishnan et al., Precision Engineering 44 (2016) 13, §3). Written here in
 * spherical coordinates of the tracker frame: the point at distance r, azimuth a, elevation e is
 * reported at r + δr(r), a + δa(a), e.
 */
class InstrumentErrorsTest {

    /** The set with every measured point (tracker frame, m) reported through a tracker whose readings err by {@code dr} and {@code da}. */
    static MeasurementSet misread(MeasurementSet set, UnaryOperator<double[]> err) {
        List<Measurement> rows = new ArrayList<>();
        for (Measurement m : set.rows()) {
            Vec3 p = m.position();
            double r = p.norm(), a = Math.atan2(p.y(), p.x()), e = Math.asin(p.z() / r);
            double[] d = err.apply(new double[] {r, a});
            double r2 = r + d[0], a2 = a + d[1];
            Vec3 q = new Vec3(r2 * Math.cos(e) * Math.cos(a2), r2 * Math.cos(e) * Math.sin(a2), r2 * Math.sin(e));
            rows.add(new Measurement(m.poseId(), m.q(), q, m.orientation(), m.directions(), m.timeS(), m.tempC(),
                    m.payloadKg(), m.set(), m.line(), m.points().isEmpty() ? m.points() : List.of(q), m.distance(), m.fromQ(), m.fromDirections()));
        }
        return new MeasurementSet(set.source(), set.metadata(), set.frame(), rows, set.pointNames(), set.anchor());
    }

    private static List<String> instrumentFindings(Diagnosis d) {
        List<String> out = new ArrayList<>();
        for (Diagnosis.Finding f : d.effects()) if (f.effect().ofInstrument()) out.add(f.effect().label());
        for (Diagnosis.Located l : d.located()) if (l.variable().startsWith("instrument") && l.explainedBy() == null) out.add(l.shape());
        return out;
    }

    /**
     * A distance meter's cyclic error of 40 µm over a 0.35 m period (several cycles over the
     * workspace's distances) on an IRB 2000 seen from 2.5–3.5 m: no family of the robot is named, the
     * error is located in the instrument's distance reading, and the validation poses come down to
     * the floor with the instrument's error modelled.
     */
    @Test
    void distanceMeterCyclicError_isLocatedInTheInstrumentNotNamedAsTheRobots() {
        var desc = RobotLibrary.shipped("irb2000");
        WorldCampaigns.Sim c = WorldCampaigns.geometric(desc, 3, false, p -> p.withPoses(300, 100).withSigma(1.2e-5));
        UnaryOperator<double[]> adm = ra -> new double[] {40e-6 * Math.sin(2 * Math.PI * ra[0] / 0.35 + 1.1), 0};
        Diagnosis d = Diagnoser.diagnose(desc, misread(c.train(), adm), misread(c.validation(), adm));
        assertEquals(List.of(), HeldOutFormsTest.families(d), "notes " + d.notes());
        assertTrue(instrumentFindings(d).stream().anyMatch(s -> s.contains("distance")), d.located().toString() + d.effects());
        assertTrue(d.finalValidateRmsM() < 1.15 * c.floorM(), d.finalValidateRmsM() + " vs floor " + c.floorM() + ": " + d.effects().stream()
                .map(f -> f.effect().label()).toList() + " located " + d.located().stream().map(Diagnosis.Located::shape).toList());
    }

    /**
     * The tracker's azimuth encoder off by 4 arc-seconds once and 3 twice per turn: no family of the
     * robot is named (joint 1's angle and the azimuth seen from the tracker go together over the
     * workspace, but the point moves about the tracker's axis, not the robot's), and the error is
     * located in the instrument's azimuth reading.
     */
    @Test
    void azimuthEncoderError_isLocatedInTheInstrumentNotNamedAsTheRobots() {
        var desc = RobotLibrary.shipped("irb2000");
        WorldCampaigns.Sim c = WorldCampaigns.geometric(desc, 4, false, p -> p.withPoses(300, 100).withSigma(1e-5));
        double as = Math.toRadians(1 / 3600.0);
        UnaryOperator<double[]> enc = ra -> new double[] {0, 4 * as * Math.sin(ra[1] + 0.4) + 3 * as * Math.sin(2 * ra[1] + 2.0)};
        Diagnosis d = Diagnoser.diagnose(desc, misread(c.train(), enc), misread(c.validation(), enc));
        assertEquals(List.of(), HeldOutFormsTest.families(d), "notes " + d.notes());
        assertTrue(!d.located().isEmpty() || d.effects().stream().anyMatch(f -> f.effect().isFallback()), "located: " + d.located());
        assertTrue(d.finalValidateRmsM() < 1.15 * c.floorM(), d.finalValidateRmsM() + " vs floor " + c.floorM() + ": " + d.effects().stream()
                .map(f -> f.effect().label()).toList() + " located " + d.located().stream().map(Diagnosis.Located::shape).toList());
    }

    /**
     * A real transmission error of joint 1 (harmonics 1–3, written as the readings of a controller
     * behind the gear) is still named as the robot's: the instrument's errors are its rivals, and
     * they do not predict left-out poses as well.
     */
    @Test
    void jointOneTransmissionError_isStillTheRobots() {
        var desc = RobotLibrary.shipped("irb2000");
        WorldCampaigns.Sim c = WorldCampaigns.geometric(desc, 5, false, p -> p.withPoses(300, 100).withSigma(1.2e-5));
        StageScanTest.Stage gear = new StageScanTest.Stage(0, new double[] {1, 2, 3}, new double[] {0.006, 0.008, 0.005},
                new double[] {0.3, 2.1, 4.0});
        Diagnosis d = Diagnoser.diagnose(desc, StageScanTest.readBehind(c.train(), gear), StageScanTest.readBehind(c.validation(), gear));
        assertEquals(List.of("gear-periodic j1"), HeldOutFormsTest.families(d).stream().map(s -> s.replaceAll(" \\(.*", "")).toList(),
                "notes " + d.notes());
        assertEquals(List.of(), instrumentFindings(d), d.located().toString());
    }

    /** The instrument's error is left out of the robot's pose: compensation does not move the tool for it. */
    @Test
    void instrumentErrorIsNotTheRobots() {
        var desc = RobotLibrary.shipped("irb2000");
        var model = org.robopro.kinematics.KinematicModel.build(desc);
        Effect e = Effect.instrumentReading(Effect.Sight.RANGE, org.robopro.kinematics.Pose.translation(-3, 0.2, -0.5), 0, 2, 4.5, 4);
        ExtendedModel ext = new ExtendedModel(model, List.of(new Effect.Term(e, new double[] {1e-4, -2e-4, 3e-4, 1e-4})));
        double[] q = {0.3, 0.2, -0.1, 0.5, 0.4, 0.2};
        var pc = org.robopro.calibration.PoseConditions.NONE;
        assertEquals(0, ext.flange(q, pc).distanceTo(model.flange(q)), 1e-15);
        // its regressor: the point moves along the line of sight from the instrument, by the spline of the distance
        double[] g = new double[3 * e.size()];
        double[] base = {1.0, 0.0, 1.5};
        e.positionRegressor(q, pc, base, g);
        double[] los = {1.0 + -3, 0.2, 1.5 - 0.5};
        double n = Math.sqrt(los[0] * los[0] + los[1] * los[1] + los[2] * los[2]);
        double[] b = new double[4];
        Effect.bspline(n, 2, 4.5, b);
        for (int a = 0; a < 3; a++) for (int i = 0; i < 4; i++) assertEquals(los[a] / n * b[i], g[a * 4 + i], 1e-12);
    }

    /**
     * The instrument's distance scale moves a point along its line of sight in proportion to its
     * distance from the instrument: a point at the instrument does not move, one twice as far moves
     * twice as much the same way, and a scale that grows with time moves a point more later. It is
     * the instrument's, not the robot's pose, and the robot file keeps it.
     */
    @Test
    void instrumentScaleIsAboutTheInstrumentNotTheRobotsAndSurvivesTheRobotFile() {
        var desc = RobotLibrary.shipped("irb2000");
        var model = org.robopro.kinematics.KinematicModel.build(desc);
        // instrument_T_base: the base's origin 3 m in front of the instrument, a little off its axes
        var inst = org.robopro.kinematics.Pose.translation(3, 0.2, -0.5);
        Effect e = Effect.instrumentScale(Effect.Along.TIME, inst, 0, 3600);
        double[] flat = {6e-6, 6e-6, 6e-6, 6e-6}, v = {0, 4e-6, 8e-6, 12e-6};
        ExtendedModel ext = new ExtendedModel(model, List.of(new Effect.Term(e, v)));
        double[] q = {0.3, 0.2, -0.1, 0.5, 0.4, 0.2};
        var late = new org.robopro.calibration.PoseConditions(null, 3600, Double.NaN, Double.NaN);
        var early = new org.robopro.calibration.PoseConditions(null, 0, Double.NaN, Double.NaN);
        assertEquals(0, ext.flange(q, late).distanceTo(model.flange(q)), 1e-15);
        Vec3 atInstrument = new Vec3(-3, -0.2, 0.5), near = new Vec3(-1, 0, 0), far = new Vec3(1, 0.2, -0.5);
        assertEquals(0, e.displacement(flat, q, late, atInstrument).norm(), 1e-18);
        // near is √4.29 m from the instrument along (2, 0.2, -0.5), far twice as far along the same line: a scale of 6 ppm
        Vec3 dNear = e.displacement(flat, q, late, near), dFar = e.displacement(flat, q, late, far);
        assertEquals(6e-6 * Math.sqrt(4.29), dNear.norm(), 1e-15);
        assertEquals(2 * dNear.norm(), dFar.norm(), 1e-15);
        assertEquals(1, dNear.dot(dFar) / (dNear.norm() * dFar.norm()), 1e-12);
        assertEquals(1, dNear.dot(new Vec3(2, 0.2, -0.5)) / (dNear.norm() * Math.sqrt(4.29)), 1e-12);
        Vec3 dLate = e.displacement(v, q, late, far), dEarly = e.displacement(v, q, early, far);
        assertTrue(dLate.norm() > 1.5 * dEarly.norm() && dLate.dot(dEarly) > 0, dEarly + " -> " + dLate);
        ExtendedModel back = ExtendedModel.of(org.robopro.models.RobotFile.parse("extended.robot.json",
                org.robopro.models.RobotFile.format(ext.toDescription())), "extended.robot.json");
        Effect e2 = back.terms().get(0).effect();
        assertEquals(e.label(), e2.label());
        assertEquals(0, e2.displacement(back.terms().get(0).values(), q, late, far).minus(dLate).norm(), 1e-15);
    }

    /**
     * The beam bent by the air moves a point straight up by k·d², d its horizontal distance from the
     * instrument: at the instrument nothing, twice as far four times as much, whatever the point's
     * height; the robot file keeps it, read back through the same reader as the instrument's scale.
     */
    @Test
    void refractionMovesAPointUpByItsHorizontalDistanceSquaredAndSurvivesTheRobotFile() {
        var model = org.robopro.kinematics.KinematicModel.build(RobotLibrary.shipped("irb2000"));
        var inst = org.robopro.kinematics.Pose.translation(3, 0.2, -0.5);   // the instrument's origin at (-3, -0.2, 0.5) in the base
        Effect e = Effect.refraction(Effect.Along.TIME, inst, 0, 3600, 4);
        double[] flat = {1e-6, 1e-6, 1e-6, 1e-6};
        double[] q = {0.3, 0.2, -0.1, 0.5, 0.4, 0.2};
        var late = new org.robopro.calibration.PoseConditions(null, 3600, Double.NaN, Double.NaN);
        assertEquals(0, e.displacement(flat, q, late, new Vec3(-3, -0.2, 2)).norm(), 1e-18);
        Vec3 near = e.displacement(flat, q, late, new Vec3(-1, -0.2, 0)), far = e.displacement(flat, q, late, new Vec3(1, -0.2, 1.5));
        assertEquals(1e-6 * 4, near.z(), 1e-18);
        assertEquals(0, Math.hypot(near.x(), near.y()), 1e-18);
        assertEquals(4 * near.z(), far.z(), 1e-18);
        ExtendedModel ext = new ExtendedModel(model, List.of(new Effect.Term(e, flat)));
        ExtendedModel back = ExtendedModel.of(org.robopro.models.RobotFile.parse("extended.robot.json",
                org.robopro.models.RobotFile.format(ext.toDescription())), "extended.robot.json");
        Effect e2 = back.terms().get(0).effect();
        assertEquals(e.label(), e2.label());
        assertEquals(0, e2.displacement(back.terms().get(0).values(), q, late, new Vec3(1, -0.2, 1.5)).minus(far).norm(), 1e-18);
    }
}
