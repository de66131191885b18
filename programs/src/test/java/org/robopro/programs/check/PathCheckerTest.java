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
}
