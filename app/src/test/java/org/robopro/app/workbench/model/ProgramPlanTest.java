package org.robopro.app.workbench.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.kinematics.Pose;

class ProgramPlanTest {
    static WorkbenchModel modelWithTargets() {
        ProjectData d = DefaultCell.irb2000Welding();
        WorkbenchModel m = new WorkbenchModel(d.robotRef(), d.robot());
        m.load(d);
        double[] q = DefaultCell.readyPose();
        m.setQ(q);
        Pose p = m.worldTtcp();
        m.putTarget(new Target("p10", p, q, m.kinematics().confOf(q)));
        m.putTarget(new Target("p20", Pose.translation(0, 0.2, -0.1).times(p), q, m.kinematics().confOf(q)));
        return m;
    }

    @Test
    void of_reachableMoveL_okAndSamplesFollowTheLine() {
        WorkbenchModel m = modelWithTargets();
        m.setProgram(List.of(new Instruction(Instruction.Type.MOVEJ, "p10", 500, 0), new Instruction(Instruction.Type.MOVEL, "p20", 100, 0)));
        ProgramPlan plan = ProgramPlan.of(m);
        assertTrue(plan.ok(), plan.steps().toString());
        double len = Math.hypot(0.2, 0.1);
        assertEquals(len / 0.1, plan.duration(), 1e-6, "MoveL takes length / speed");
        var a = m.target("p10").orElseThrow().worldTtcp().position();
        var b = m.target("p20").orElseThrow().worldTtcp().position();
        for (int i = 0; i < plan.sampleCount(); i++) {
            var p = plan.tcp(i).minus(a);
            var dir = b.minus(a).normalized();
            double off = p.minus(dir.times(p.dot(dir))).norm();
            assertEquals(0, off, 1e-6, "sample " + i + " leaves the straight line");
        }
        var end = m.worldTtcp(plan.qAtTime(plan.duration()));
        assertEquals(0, end.distanceTo(m.target("p20").orElseThrow().worldTtcp()), 1e-6);
    }

    @Test
    void of_unreachableAndUnknownTargets_reportedPerInstruction() {
        WorkbenchModel m = modelWithTargets();
        Pose p = m.worldTtcp();
        m.putTarget(new Target("far", Pose.translation(3, 0, 0).times(p), m.q(), m.kinematics().confOf(m.q())));
        m.setProgram(List.of(new Instruction(Instruction.Type.MOVEJ, "p10", 500, 0),
                new Instruction(Instruction.Type.MOVEL, "far", 500, 0), new Instruction(Instruction.Type.MOVEL, "nope", 500, 0),
                new Instruction(Instruction.Type.MOVEL, "p20", 500, 0)));
        ProgramPlan plan = ProgramPlan.of(m);
        assertFalse(plan.ok());
        assertTrue(plan.steps().get(0).ok());
        assertFalse(plan.steps().get(1).ok());
        assertTrue(plan.steps().get(1).message().contains("out of reach"), plan.steps().get(1).message());
        assertFalse(plan.steps().get(2).ok());
        assertTrue(plan.steps().get(3).ok());
        assertEquals(TargetStatus.UNREACHABLE, m.status(m.target("far").orElseThrow()));
        assertEquals(TargetStatus.REACHABLE, m.status(m.target("p10").orElseThrow()));
    }

    @Test
    void module_programWithTargets_writesRapid() {
        WorkbenchModel m = modelWithTargets();
        m.setProgram(List.of(new Instruction(Instruction.Type.MOVEJ, "p10", 500, 10), new Instruction(Instruction.Type.MOVEL, "p20", 100, 0)));
        String mod = RapidExport.module("Weld", m);
        assertTrue(mod.startsWith("MODULE Weld\n"));
        assertTrue(mod.contains("MoveJ p10, v500, z10, torch\\WObj:=wobj0;"));
        assertTrue(mod.contains("MoveL p20, v100, fine, torch\\WObj:=wobj0;"));
        Pose p20 = m.target("p20").orElseThrow().worldTtcp();
        assertTrue(mod.contains(String.format(java.util.Locale.ROOT, "CONST robtarget p20:=[[%.2f,%.2f,%.2f]",
                p20.x() * 1000, p20.y() * 1000, p20.z() * 1000)), mod);
        assertTrue(mod.endsWith("ENDMODULE\n"));
    }
}
