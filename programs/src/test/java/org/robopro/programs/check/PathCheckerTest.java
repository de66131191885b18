package org.robopro.programs.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.kinematics.ConfData;
import org.robopro.kinematics.InverseKinematics;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.RobotLibrary;
import org.robopro.models.Vec3;
import org.robopro.programs.JointTarget;
import org.robopro.programs.LoadData;
import org.robopro.programs.Move;
import org.robopro.programs.Quaternion;
import org.robopro.programs.RapidModule;
import org.robopro.programs.RapidPose;
import org.robopro.programs.Ref;
import org.robopro.programs.RobTarget;
import org.robopro.programs.Teach;
import org.robopro.programs.ToolData;
import org.robopro.programs.WObjData;
import org.robopro.programs.sim.MotionInterpreter;

class PathCheckerTest {
    static final KinematicModel IRB2000 = KinematicModel.build(RobotLibrary.shipped("irb2000"));
    static final ToolData TORCH = new ToolData(true, new RapidPose(new Vec3(0, 0, 0.15), Quaternion.IDENTITY), LoadData.LOAD0);

    static RapidModule program(RobTarget a, RobTarget b, RobTarget c, double[] qHome) {
        return RapidModule.builder("T")
                .pers("tTorch", TORCH)
                .constant("jHome", JointTarget.of(qHome))
                .constant("pA", a).constant("pB", b).constant("pC", c)
                .procedure("main", List.of(
                        Move.moveAbsJ(Ref.to("jHome"), Ref.to("v1000"), Ref.to("fine"), "tTorch", null),
                        Move.moveJ(Ref.to("pA"), Ref.to("v1000"), Ref.to("z10"), "tTorch", null),
                        Move.moveL(Ref.to("pB"), Ref.to("v200"), Ref.to("z10"), "tTorch", null),
                        Move.moveC(Ref.to("pC"), Ref.to("pA"), Ref.to("v200"), Ref.to("fine"), "tTorch", null)))
                .build();
    }

    @Test
    void check_taughtTargets_noErrorsAndJointValuesReachTargetsByFk() {
        double[] home = {0, 0, 0, 0, 0.5, 0};
        double[] qa = {0.3, 0.2, 0.1, 0.2, 0.7, -0.3}, qb = {0.1, 0.3, 0.0, 0.1, 0.6, -0.1}, qc = {0.2, 0.35, 0.05, 0.15, 0.5, -0.2};
        RobTarget a = Teach.taught(IRB2000, qa, TORCH, WObjData.WOBJ0);
        RobTarget b = Teach.taught(IRB2000, qb, TORCH, WObjData.WOBJ0);
        RobTarget c = Teach.taught(IRB2000, qc, TORCH, WObjData.WOBJ0);
        CheckReport r = new PathChecker(IRB2000).check(MotionInterpreter.of(program(a, b, c, home)).run());
        assertFalse(r.hasErrors(), r::format);
        CheckReport.StepResult moveJ = r.steps().get(1);
        for (int j = 0; j < 6; j++) assertEquals(qa[j], moveJ.qEnd()[j], 1e-9, "MoveJ ends at the taught joints");
        CheckReport.StepResult moveL = r.steps().get(2);
        Pose reached = IRB2000.flange(moveL.qEnd()).times(TORCH.tframe().toPose());
        assertEquals(0, reached.distanceTo(b.pose()), 1e-9);
        assertTrue(moveL.interpolationPoints() > 10, "MoveL is checked along its path");
        // The checked samples (what playback shows) lie on the straight TCP line from pA to pB.
        assertEquals(moveL.interpolationPoints(), moveL.samples().size());
        Vec3 from = a.pose().position(), to = b.pose().position(), dir = to.minus(from).normalized();
        for (double[] qs : moveL.samples()) {
            Vec3 p = IRB2000.flange(qs).times(TORCH.tframe().toPose()).position().minus(from);
            assertEquals(0, p.minus(dir.times(p.dot(dir))).norm(), 1e-9, "sample off the line");
        }
        assertTrue(r.cycleTimeS() > 0);
    }

    @Test
    void check_farTarget_unreachableNamedByInstructionAndTarget() {
        double[] home = {0, 0, 0, 0, 0.5, 0};
        RobTarget far = RobTarget.of(Pose.translation(5, 0, 1), new ConfData(0, 0, 0, 0));
        RobTarget ok = Teach.taught(IRB2000, new double[] {0.1, 0.3, 0.0, 0.1, 0.6, -0.1}, TORCH, WObjData.WOBJ0);
        CheckReport r = new PathChecker(IRB2000).check(MotionInterpreter.of(program(far, ok, ok, home)).run());
        assertTrue(r.problems().stream().anyMatch(p -> p.kind() == Problem.Kind.UNREACHABLE && p.target().equals("pA")
                && p.step().equals("main#2 MoveJ pA")), r::format);
        assertTrue(r.format().contains("pA"));
    }

    @Test
    void check_moveLThroughWristFlip_configurationProblemReported() {
        double[] home = {0, 0, 0, 0, 0.5, 0};
        RobTarget up = Teach.taught(IRB2000, new double[] {0, 0.3, 0.1, 0.4, 0.4, 0}, TORCH, WObjData.WOBJ0);
        RobTarget down = Teach.taught(IRB2000, new double[] {0, 0.3, 0.1, 0.4, -0.4, 0}, TORCH, WObjData.WOBJ0);
        CheckReport r = new PathChecker(IRB2000).check(MotionInterpreter.of(program(up, down, up, home)).run());
        assertTrue(r.problems().stream().anyMatch(p -> p.target().equals("pB") && (p.kind() == Problem.Kind.NEAR_SINGULARITY
                || p.kind() == Problem.Kind.CONFIGURATION_CHANGE || p.kind() == Problem.Kind.CONFIGURATION_MISMATCH)), r::format);
    }

    @Test
    void trapezoid_longAndShortMoves_matchesProfileFormulas() {
        PathChecker c = new PathChecker(IRB2000);
        double v = 2.0, ramp = PathChecker.Options.DEFAULT.rampS(), a = v / ramp;
        double longD = 3.0;
        assertEquals(longD / v + v / a, c.trapezoid(longD, v), 1e-12);
        double shortD = 0.1;
        assertTrue(shortD < v * v / a);
        // Triangle profile: accelerate over half the distance, decelerate over the other half.
        double half = Math.sqrt(2 * (shortD / 2) / a);
        assertEquals(2 * half, c.trapezoid(shortD, v), 1e-12);
    }

    @Test
    void circle_threePoints_passesThroughAllAndSpansTheArc() {
        Vec3 a = new Vec3(1, 0, 0), b = new Vec3(0, 1, 0), cc = new Vec3(-1, 0, 0);
        PathChecker.Circle circle = PathChecker.Circle.through(a, b, cc);
        assertEquals(1, circle.radius, 1e-12);
        assertEquals(Math.PI, circle.angle, 1e-12);
        assertEquals(0, circle.at(0.5).minus(b).norm(), 1e-12);
        assertEquals(0, circle.at(1).minus(cc).norm(), 1e-12);
        assertEquals(null, PathChecker.Circle.through(a, new Vec3(2, 0, 0), new Vec3(3, 0, 0)));
    }

    @Test
    void confOf_taughtTarget_equalsIkConfOfJointsUsed() {
        double[] q = {0.3, 0.2, 0.1, 0.2, 0.7, -0.3};
        RobTarget t = Teach.taught(IRB2000, q, TORCH, WObjData.WOBJ0);
        assertEquals(InverseKinematics.of(IRB2000).confOf(q), t.robconf());
    }

    /** Taught targets at TCP positions (m) with the torch pointing down, each solved next to the previous one. */
    static RobTarget[] down(Vec3... p) {
        InverseKinematics ik = InverseKinematics.of(IRB2000);
        double[] seed = {0, 0.2, 0.1, 0.1, 1.2, 0.1};
        RobTarget[] out = new RobTarget[p.length];
        for (int k = 0; k < p.length; k++) {
            Pose tcp = Pose.of(new double[] {-1, 0, 0, 0, 1, 0, 0, 0, -1}, p[k].x(), p[k].y(), p[k].z());
            double[] q = ik.solveNear(tcp.times(TORCH.tframe().toPose().inverse()), seed).orElseThrow().q();
            out[k] = Teach.taught(IRB2000, q, TORCH, WObjData.WOBJ0);
            seed = q;
        }
        return out;
    }

    static CheckReport corner(String zone, boolean waitAtCorner) {
        RobTarget[] t = down(new Vec3(0.9, -0.15, 0.8), new Vec3(0.9, 0.15, 0.8), new Vec3(0.9, 0.15, 0.5));
        List<org.robopro.programs.Statement> body = new java.util.ArrayList<>(List.of(
                Move.moveJ(Ref.to("pA"), Ref.to("v1000"), Ref.to("fine"), "tTorch", null),
                Move.moveL(Ref.to("pB"), Ref.to("v100"), Ref.to(zone), "tTorch", null),
                Move.moveL(Ref.to("pC"), Ref.to("v100"), Ref.to("fine"), "tTorch", null)));
        if (waitAtCorner) body.add(2, new org.robopro.programs.WaitTime(0));
        RapidModule m = RapidModule.builder("T").pers("tTorch", TORCH).constant("pA", t[0]).constant("pB", t[1]).constant("pC", t[2])
                .procedure("main", body).build();
        return new PathChecker(IRB2000).check(MotionInterpreter.of(m).run());
    }

    @Test
    void check_flyByCorner_passesWithinTheZoneAndSavesTheStop() {
        CheckReport r = corner("z50", false);
        assertFalse(r.hasErrors(), r::format);
        // Right-angle corner, 300 mm legs, z50: the corner path leaves 50 mm before pB and joins 50 mm after.
        // Parabola with pB as control point: nearest to pB at its middle, |(-50 u_in + 50 u_out)/4| = 12.5 sqrt 2 mm.
        double dev = r.steps().get(1).cornerDeviationM();
        assertEquals(0.0125 * Math.sqrt(2), dev, 1e-6, r::format);
        // Sampled independently: the closest point of the corner path to pB.
        Vec3 b = new Vec3(0.9, 0.15, 0.8), entry = new Vec3(0.9, 0.10, 0.8), exit = new Vec3(0.9, 0.15, 0.75);
        double nearest = Double.MAX_VALUE;
        for (int k = 0; k <= 1000; k++) {
            double t = k / 1000.0;
            Vec3 p = entry.times((1 - t) * (1 - t)).plus(b.times(2 * t * (1 - t))).plus(exit.times(t * t));
            nearest = Math.min(nearest, p.minus(b).norm());
        }
        assertEquals(nearest, dev, 1e-6);
        // Speed is kept through the corner: at least the two half ramps (0.25 s) saved, at most that plus
        // the 100 mm of legs minus the 70.7 mm chord at 100 mm/s.
        double saved = r.cycleTimeStopsS() - r.cycleTimeS();
        assertTrue(saved >= 0.25 - 1e-9 && saved <= 0.25 + (0.1 - 0.05 * Math.sqrt(2)) / 0.1, "saved " + saved + "\n" + r.format());
        // z200 on 300 mm legs: the zone shrinks to half of each leg (150 mm).
        assertEquals(0.0375 * Math.sqrt(2), corner("z200", false).steps().get(1).cornerDeviationM(), 1e-6);
        // A wait after the fly-by point: the robot stops there, nothing is blended.
        CheckReport stop = corner("z50", true);
        assertEquals(0, stop.steps().get(1).cornerDeviationM(), 0);
        assertEquals(stop.cycleTimeStopsS(), stop.cycleTimeS(), 1e-12);
        CheckReport fine = corner("fine", false);
        assertEquals(fine.cycleTimeStopsS(), fine.cycleTimeS(), 1e-12);
        assertEquals(r.cycleTimeStopsS(), fine.cycleTimeS(), 1e-9, "without blending, z50 is timed as fine");
    }
}
