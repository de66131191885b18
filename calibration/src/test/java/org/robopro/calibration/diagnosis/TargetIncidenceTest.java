package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.PoseConditions;
import org.robopro.calibration.WorldCampaigns;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
import org.robopro.models.Vec3;

/**
 * A solid glass cube-corner reflector fixed on the tool, seen off its axis: the tracker's reading
 * moves with the direction it sees the reflector from, in the tool's frame, which no error of the
 * robot follows. It is located and modelled as the reflector's error (left out of the robot's
 * pose), not named as a family of the robot.
 */
class TargetIncidenceTest {
    /** Prism depth (vertex to front face) and index of refraction: a 7/8" glass SMR, BK7-like glass. */
    private static final double DEPTH_M = 0.008, INDEX = 1.517;
    /** Poses are kept where the reflector is seen within this angle of its axis (its acceptance). */
    private static final double ACCEPTANCE_RAD = Math.toRadians(30);

    @Test
    void glassPrismSeenOffItsAxis_isLocatedAsTheReflectors_notNamed() {
        RobotDescription desc = RobotLibrary.shipped("irb2400");
        WorldCampaigns.Sim c = WorldCampaigns.geometric(desc, 53, false, p -> p.withPoses(2800, 960).withSigma(2e-5));
        Vec3 axis = facing(c);
        MeasurementSet train = refracted(c, c.train(), axis), val = refracted(c, c.validation(), axis);
        assertTrue(train.size() >= 80 && val.size() >= 25, "poses within the acceptance: " + train.size() + ", " + val.size());
        Diagnosis d = Diagnoser.diagnose(desc, train, val);
        assertEquals(List.of(), HeldOutFormsTest.families(d), "notes " + d.notes());
        assertTrue(d.effects().stream().anyMatch(f -> f.effect().kind() == Effect.Kind.TARGET_INCIDENCE),
                "not modelled: " + d.effects().stream().map(f -> f.effect().label()).toList() + ", located "
                        + d.located().stream().map(Diagnosis.Located::shape).toList());
        assertTrue(d.geometricValidateRmsM() > 2 * c.floorM(), "a visible refraction: " + d.geometricValidateRmsM() / c.floorM());
        assertTrue(d.finalValidateRmsM() < 1.15 * c.floorM(), d.finalValidateRmsM() / c.floorM() + " x the floor, notes " + d.notes());
    }

    /** The reflector's error reads back from the robot file as written, and leaves the robot's pose alone. */
    @Test
    void incidence_roundTripsThroughTheRobotFile_andIsTheMeasurements() {
        RobotDescription desc = RobotLibrary.shipped("irb2400");
        KinematicModel model = KinematicModel.build(desc);
        Pose inst = Pose.translation(0.4, -2.1, 0.3).times(Pose.rotAxis(new Vec3(0.2, 0.3, 0.9).times(1 / Math.sqrt(0.94)), 0.7));
        Effect e = Effect.targetIncidence(model, inst, new Vec3(0.1, -0.2, 0.95));
        assertTrue(e.ofInstrument(), "an error of the measurement, not of the robot");
        EffectTest.assertRoundTrips(e, 1e-6, model, GravityTorques.of(model, desc), PoseConditions.NONE, 1e-12);
    }

    /** The reflector's axis in the target's frame: the mean direction toward the tracker over the training poses. */
    private static Vec3 facing(WorldCampaigns.Sim c) {
        Vec3 sum = new Vec3(0, 0, 0);
        for (Measurement m : c.train().rows()) {
            Pose t = c.truePose(m.q());
            Vec3 toTracker = t.position().times(-1 / t.position().norm()); // the tracker is the instrument frame's origin
            sum = sum.plus(t.inverse().rotate(toTracker));
        }
        return sum.times(1 / sum.norm());
    }

    /**
     * Each reading moved as a tracker reads a solid cube corner seen at incidence θ. Unfolded, the
     * corner is a glass plate twice its depth with the exit inverted through the vertex V, so the
     * return comes back along the beam only when the refracted ray passes through V (the tracker
     * steers its beam so): entering the front face at A = V − (L/cos θr)·u_r, with sin θ = n sin θr
     * (Snell) and u_r in the plane of the beam u and the axis â. The tracker counts the optical path
     * A→V, n·L/cos θr, less its reflector constant set at normal incidence (n·L − L), along its beam
     * from A: the reading is A + (n·L/cos θr − n·L + L)·u, where V is the truth.
     */
    private static MeasurementSet refracted(WorldCampaigns.Sim c, MeasurementSet set, Vec3 axisTarget) {
        List<Measurement> rows = new ArrayList<>();
        for (Measurement m : set.rows()) {
            Pose t = c.truePose(m.q());
            Vec3 a = t.rotate(axisTarget);                 // the axis, out of the prism's face, instrument frame
            Vec3 u = t.position().times(1 / t.position().norm());    // the beam, tracker to reflector
            double cosT = -u.dot(a);
            if (!(Math.acos(Math.max(-1, Math.min(1, cosT))) <= ACCEPTANCE_RAD)) continue;
            Vec3 across = u.plus(a.times(cosT));                     // u = −cosθ â + sinθ ŵ
            double sinT = across.norm();
            Vec3 w = sinT > 1e-12 ? across.times(1 / sinT) : new Vec3(0, 0, 0);
            double sinR = sinT / INDEX, cosR = Math.sqrt(1 - sinR * sinR);
            Vec3 ur = a.times(-cosR).plus(w.times(sinR));
            Vec3 entry = ur.times(-DEPTH_M / cosR);                  // A − V
            Vec3 error = entry.plus(u.times(INDEX * DEPTH_M / cosR - INDEX * DEPTH_M + DEPTH_M));
            rows.add(m.withPosition(m.position().plus(error)));
        }
        return set.withRows(rows);
    }
}
