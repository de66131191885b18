package org.robopro.app.workbench.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.kinematics.Pose;
import org.robopro.models.Vec3;
import org.robopro.programs.check.Problem;

class ProgramRunTest {
    static WorkbenchModel modelWithTargets() {
        ProjectData d = DefaultCell.irb2000Welding();
        WorkbenchModel m = new WorkbenchModel(d.robotRef(), d.robot());
        m.load(d);
        double[] q = DefaultCell.readyPose();
        m.setQ(q);
        Pose p = m.worldTtcp();
        m.putTarget(new Target("p10", p, q, m.kinematics().confOf(q)));
        m.putTarget(new Target("p20", Pose.translation(0, 0.2, -0.1).times(p), q, m.kinematics().confOf(q)));
        m.putTarget(new Target("p15", Pose.translation(0, 0.1, -0.02).times(p), q, m.kinematics().confOf(q)));
        return m;
    }

    @Test
    void of_reachableMoveL_okAndSamplesFollowTheLine() {
        WorkbenchModel m = modelWithTargets();
        m.setProgram(List.of(new Instruction(Instruction.Type.MOVEJ, "p10", 500, 0), new Instruction(Instruction.Type.MOVEL, "p20", 100, 0)));
        ProgramRun run = m.programRun();
        assertTrue(run.ok(), run.problemLines().toString());
        assertNotNull(run.report(), "the kinematics module answers, so the path checker runs");
        double len = Math.hypot(0.2, 0.1);
        assertTrue(run.duration() >= len / 0.1, "MoveL takes at least length / speed: " + run.duration());
        assertEquals(run.report().cycleTimeS(), run.duration(), 1e-9, "the timeline uses the checker's durations");
        var a = m.target("p10").orElseThrow().worldTtcp().position();
        var b = m.target("p20").orElseThrow().worldTtcp().position();
        var dir = b.minus(a).normalized();
        for (int i = 0; i < run.sampleCount(); i++) {
            var p = run.tcp(i).minus(a);
            assertEquals(0, p.minus(dir.times(p.dot(dir))).norm(), 1e-6, "sample " + i + " leaves the straight line");
        }
        var end = m.worldTtcp(run.qAtTime(run.duration()));
        assertEquals(0, end.distanceTo(m.target("p20").orElseThrow().worldTtcp()), 1e-6);
    }

    @Test
    void of_moveC_samplesLieOnTheCircleThroughTheThreeTargets() {
        WorkbenchModel m = modelWithTargets();
        m.setProgram(List.of(new Instruction(Instruction.Type.MOVEJ, "p10", 500, 0),
                new Instruction(Instruction.Type.MOVEC, "p20", 100, 0, "p15")));
        ProgramRun run = m.programRun();
        assertTrue(run.ok(), run.problemLines().toString());
        Vec3 a = m.target("p10").orElseThrow().worldTtcp().position();
        Vec3 v = m.target("p15").orElseThrow().worldTtcp().position();
        Vec3 c = m.target("p20").orElseThrow().worldTtcp().position();
        org.robopro.programs.check.PathChecker.Circle circle = org.robopro.programs.check.PathChecker.Circle.through(a, v, c);
        for (Vec3 p : new Vec3[] {a, v, c}) assertEquals(circle.radius(), p.minus(circle.center()).norm(), 1e-9);
        for (int i = 0; i < run.sampleCount(); i++)
            assertEquals(circle.radius(), run.tcp(i).minus(circle.center()).norm(), 1e-6, "sample " + i + " is off the circle");
    }

    @Test
    void of_unreachableAndUnknownTargets_reportedPerInstructionAndTarget() {
        WorkbenchModel m = modelWithTargets();
        Pose p = m.worldTtcp();
        m.putTarget(new Target("far", Pose.translation(3, 0, 0).times(p), m.q(), m.kinematics().confOf(m.q())));
        m.setProgram(List.of(new Instruction(Instruction.Type.MOVEJ, "p10", 500, 0),
                new Instruction(Instruction.Type.MOVEL, "far", 500, 0), new Instruction(Instruction.Type.MOVEL, "nope", 500, 0),
                new Instruction(Instruction.Type.MOVEL, "p20", 500, 0)));
        ProgramRun run = m.programRun();
        assertFalse(run.ok());
        assertEquals(4, run.steps().size());
        for (int i = 0; i < 4; i++) assertEquals(i, run.steps().get(i).index());
        assertTrue(run.steps().get(0).ok());
        assertFalse(run.steps().get(1).ok());
        Problem firstError = run.steps().get(1).problems().stream().filter(x -> x.severity() == Problem.Severity.ERROR).findFirst().orElseThrow();
        assertEquals(Problem.Kind.UNREACHABLE, firstError.kind());
        assertEquals("far", firstError.target());
        assertFalse(run.steps().get(2).ok());
        assertTrue(run.steps().get(2).message().contains("no target named nope"), run.steps().get(2).message());
        assertTrue(run.steps().get(3).ok(), run.steps().get(3).message());
        assertTrue(run.badTargets().contains("far") && run.badTargets().contains("nope"), run.badTargets().toString());
        assertFalse(run.badTargets().contains("p20"));
        assertEquals(TargetStatus.UNREACHABLE, m.statuses().get("far"));
        assertEquals(TargetStatus.REACHABLE, m.statuses().get("p10"));
        assertTrue(run.problemLines().get(0).startsWith("instruction 2 (MoveL far"), run.problemLines().toString());
    }

    @Test
    void programRun_unchangedModel_cachedAndInvalidatedByChanges() {
        WorkbenchModel m = modelWithTargets();
        m.setProgram(List.of(new Instruction(Instruction.Type.MOVEJ, "p10", 500, 0)));
        ProgramRun a = m.programRun();
        m.select("target:p10");
        m.setQ(DefaultCell.readyPose());
        assertTrue(a == m.programRun(), "selection and jogging keep the run");
        m.addInstruction(new Instruction(Instruction.Type.MOVEL, "p20", 100, 0));
        assertFalse(a == m.programRun(), "a program change recomputes it");
        assertEquals(2, m.programRun().steps().size());
    }
}
