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

    /**
     * Springs of joints 2 and 3 (the world's own flexible-joint model, masses off by up to 30 % link by
     * link), measured with payload steps, diagnosed with a robot file without masses: on these draws
     * a link's bending predicts left-out poses as well as the spring of its joint. Wherever the
     * diagnosis models a bending, it says that the joint's spring predicts as well and claims neither;
     * it never calls the bending the one explanation.
     */
    @Test
    void jointSprings_whereABendingPredictsAsWell_theReportSaysTheSpringIsAlike() {
        RobotDescription desc = RobotLibrary.shipped("irb2000");
        RobotDescription noMasses = new RobotDescription(desc.name(), desc.displayName(), desc.joints(), desc.flange(), desc.coupling(),
                java.util.Optional.empty(), desc.meshes(), desc.effects(), desc.source(), desc.provenance());
        int bendings = 0;
        for (long seed : new long[] {5, 8}) {
            java.util.Random r = new java.util.Random(seed);
            org.robopro.world.WorldRobot w = org.robopro.world.Scenario.baseRobot(desc, r, 1e-3, Math.toRadians(0.1));
            org.robopro.world.WorldRobot.Compliance c = org.robopro.world.WorldRobot.Compliance.fromFile(desc.massModel().orElseThrow(),
                    desc.dof(), 0.3, r);
            c = c.withStiffness(1, 0.5e6 + r.nextDouble() * 1.5e6).withStiffness(2, 0.5e6 + r.nextDouble() * 1.5e6);
            double rated = desc.massModel().orElseThrow().ratedPayloadKg();
            WorldCampaigns.Sim sim = WorldCampaigns.measure(desc, w.withCompliance(c), org.robopro.world.Campaign.Plan.defaults(seed)
                    .withPoses(150, 50).withSigma(3e-5).withPayloads(0, rated / 2, rated));
            Diagnosis d = Diagnoser.diagnose(noMasses, sim.train(), sim.validation());
            for (Diagnosis.Finding f : d.effects()) {
                if (f.effect().kind() != Effect.Kind.LINK_SAG) continue;
                bendings++;
                int joint = f.effect().joint() + 1;
                assertTrue(f.words().contains("or joint " + joint + " gives way under it") && f.words().contains("neither is claimed"),
                        "seed " + seed + ": " + f.words());
                assertTrue(d.notes().stream().anyMatch(n -> n.startsWith(f.effect().label() + " and joint-compliance j" + joint)),
                        "seed " + seed + ": " + d.notes());
            }
        }
        assertTrue(bendings > 0, "no bending on these draws: the test no longer asks anything");
    }

    /**
     * The forearm bending under its own weight and the payload at its far end (Gere &amp; Goodno, as
     * above; written here), measured with payload steps: the bending and joint 3's spring predict the
     * poses alike, and no spring is named.
     */
    @Test
    void forearmBeam_withPayloadSteps_namesNoSpring() {
        RobotDescription desc = RobotLibrary.shipped("irb2000");
        double rated = desc.massModel().orElseThrow().ratedPayloadKg();
        WorldCampaigns.Sim c = WorldCampaigns.geometric(desc, 2, true, p -> p.withPoses(150, 50).withSigma(2e-5).withPayloads(0, rated / 2, rated));
        KinematicModel model = KinematicModel.build(desc);
        Diagnosis d = Diagnoser.diagnose(desc, forearmBent(c.train(), model), forearmBent(c.validation(), model));
        assertEquals(List.of(), HeldOutFormsTest.families(d), "notes " + d.notes());
        assertTrue(d.effects().stream().anyMatch(f -> f.effect().kind() == Effect.Kind.LINK_SAG && f.effect().joint() == 2),
                "no bending of the forearm: " + d.effects().stream().map(f -> f.effect().label()).toList());
    }

    /** Each measured point moved by the upper arm's bending: its far end's deflection δ across the link and turn θ about joint 2's axis. */
    private static MeasurementSet bent(MeasurementSet set, KinematicModel model) { return bent(set, model, 2, 3, 4e5, 25, 60); }

    /** The forearm (joint 3's axis to the wrist's centre) under 20 kg of its own and 30 kg plus the payload at its far end, EI = 3·10⁵ N·m². */
    private static MeasurementSet forearmBent(MeasurementSet set, KinematicModel model) { return bent(set, model, 3, 5, 3e5, 20, 30); }

    /**
     * Each measured point moved by a link's bending as a cantilever from link frame {@code root}'s
     * origin (on its joint's axis) to frame {@code end}'s: its own {@code own} kg spread along it and
     * {@code carried} kg plus the payload at its far end, stiffness {@code ei} N·m², loaded by the
     * part of gravity across it; the far end deflects by δ across the link and turns by θ.
     */
    private static MeasurementSet bent(MeasurementSet set, KinematicModel model, int root, int end, double ei, double own, double carried) {
        List<Measurement> rows = new ArrayList<>();
        for (Measurement m : set.rows()) {
            Pose[] f = model.linkFrames(m.q());
            Vec3 o = f[root].position(), e = f[end].position(), z = new Vec3(f[root].rot(0, 2), f[root].rot(1, 2), f[root].rot(2, 2));
            Vec3 along = e.minus(o);
            along = along.minus(z.times(along.dot(z)));
            double len = along.norm();
            Vec3 across = z.cross(along.times(1 / len));
            double share = -across.z(); // gravity (0, 0, −g) across the link
            double payload = Double.isFinite(m.payloadKg()) ? m.payloadKg() : 0;
            double w = own * G / len * share, p = (carried + payload) * G * share;
            double delta = w * Math.pow(len, 4) / (8 * ei) + p * Math.pow(len, 3) / (3 * ei);
            double theta = w * Math.pow(len, 3) / (6 * ei) + p * len * len / (2 * ei);
            rows.add(m.withPosition(m.position().plus(across.times(delta)).plus(z.cross(m.position().minus(e)).times(theta))));
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
