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
 * An upper arm that bends under gravity as a beam is not a spring of joint 2: a spring turns the
 * whole link about its joint (its far end moves by L·θ as it turns by θ), a cantilever's far end
 * moves less than that for its turn (2L/3 under a force at its end, 3L/4 under its own weight).
 * With the robot file's masses, the spring of joint 2 is a candidate the bending must beat.
 */
class LinkSagTest {

    private static final double G = 9.80665;

    /**
     * The IRB 2000's upper arm (joint 2 to joint 3) as an Euler-Bernoulli cantilever held at joint 2
     * (Gere &amp; Goodno, Mechanics of Materials, table G-1): its own 25 kg spread along it and 60 kg
     * carried at its far end, EI = 4·10⁵ N·m², loaded by the part of gravity across it; written here
     * from those formulas. The bending is located, no compliance of joint 2 is named, and the
     * validation error comes within 1.15 × the floor.
     */
    @Test
    void upperArmBeam_isLocatedAsTheLinksSag_notNamedAJointSpring() {
        RobotDescription desc = RobotLibrary.shipped("irb2000");
        WorldCampaigns.Sim c = WorldCampaigns.geometric(desc, 43, true, p -> p.withPoses(100, 40).withSigma(1.5e-5));
        KinematicModel model = KinematicModel.build(desc);
        MeasurementSet train = bent(c.train(), model), val = bent(c.validation(), model);
        Diagnosis d = Diagnoser.diagnose(desc, train, val);
        assertEquals(List.of(), HeldOutFormsTest.families(d), "notes " + d.notes());
        assertTrue(d.effects().stream().anyMatch(f -> f.effect().kind() == Effect.Kind.LINK_SAG && f.effect().joint() == 1),
                "no sag of the upper arm: " + d.effects().stream().map(f -> f.effect().label()).toList());
        assertTrue(d.geometricValidateRmsM() > 2 * c.floorM(), "a visible sag: " + d.geometricValidateRmsM() / c.floorM());
        assertTrue(d.finalValidateRmsM() < 1.15 * c.floorM(), d.finalValidateRmsM() + " vs floor " + c.floorM());
    }

    /** Each measured point moved by the upper arm's bending: its far end's deflection δ across the link and turn θ about joint 2's axis. */
    private static MeasurementSet bent(MeasurementSet set, KinematicModel model) {
        double ei = 4e5, own = 25, carried = 60;
        List<Measurement> rows = new ArrayList<>();
        for (Measurement m : set.rows()) {
            Pose[] f = model.linkFrames(m.q());
            Vec3 root = f[2].position(), end = f[3].position(), z = new Vec3(f[2].rot(0, 2), f[2].rot(1, 2), f[2].rot(2, 2));
            Vec3 along = end.minus(root);
            along = along.minus(z.times(along.dot(z)));
            double len = along.norm();
            Vec3 across = z.cross(along.times(1 / len));
            double share = -across.z(); // gravity (0, 0, −g) across the link
            double w = own * G / len * share, p = carried * G * share;
            double delta = w * Math.pow(len, 4) / (8 * ei) + p * Math.pow(len, 3) / (3 * ei);
            double theta = w * Math.pow(len, 3) / (6 * ei) + p * len * len / (2 * ei);
            rows.add(m.withPosition(m.position().plus(across.times(delta)).plus(z.cross(m.position().minus(end)).times(theta))));
        }
        return set.withRows(rows);
    }

    /** The sag reads back from the robot file as written, with and without the moment's and the payload's columns. */
    @Test
    void linkSag_roundTripsThroughTheRobotFile() {
        RobotDescription desc = RobotLibrary.shipped("irb2400");
        KinematicModel model = KinematicModel.build(desc);
        GravityTorques g = GravityTorques.of(model, desc);
        for (Effect e : List.of(Effect.linkSag(model, 1, true), Effect.linkSag(model, 2, false)))
            EffectTest.assertRoundTrips(e, 1e-5, model, g, new PoseConditions(null, Double.NaN, Double.NaN, 5.0), 1e-15);
    }

    /** A robot file whose sag names a prismatic joint 3 is refused in one line naming the file and the field. */
    @Test
    void linkSag_ofAPrismaticJoint_isRefusedNamingTheField() {
        RobotDescription six = RobotLibrary.shipped("irb2400");
        List<org.robopro.models.JointDescription> joints = new ArrayList<>(six.joints());
        org.robopro.models.JointDescription j3 = joints.get(2);
        joints.set(2, new org.robopro.models.JointDescription(j3.name(), org.robopro.models.JointType.PRISMATIC, j3.point(), j3.axis(),
                0, 0.5, 0.5));
        RobotDescription sliding = new RobotDescription("sliding", "sliding", joints, six.flange(), six.coupling(),
                java.util.Optional.empty(), List.of(), List.of(), six.source(), six.provenance());
        KinematicModel model = KinematicModel.build(six), slidingModel = KinematicModel.build(sliding);
        var d = Effect.linkSag(model, 2, false).describe(new double[Effect.linkSag(model, 2, false).size()]);
        org.robopro.models.InputException x = org.junit.jupiter.api.Assertions.assertThrows(org.robopro.models.InputException.class,
                () -> Effect.fromDescription(d, slidingModel, null, "sliding.robot.json"));
        assertEquals("sliding.robot.json: field 'effects.joints': link-sag needs joint 3 revolute with a joint beyond it; "
                + "this robot's joint 3 is prismatic", x.getMessage());
    }
}
