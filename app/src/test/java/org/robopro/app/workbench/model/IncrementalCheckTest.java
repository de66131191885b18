package org.robopro.app.workbench.model;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.junit.jupiter.api.Test;
import org.robopro.kinematics.Pose;
import org.robopro.programs.check.CheckReport;

/** The workbench's background path check after an edit: only the changed motions are solved, the result is a full check's. */
class IncrementalCheckTest {
    @Test
    void speedEdit_solvesOneMotion_sameRunAsAFullCheck() throws Exception {
        WorkbenchModel m = ProgramRunTest.modelWithTargets();
        double[] q = m.q();
        Pose tcp = m.worldTtcp();
        for (int i = 0; i < 30; i++)
            m.putTarget(new Target(String.format(Locale.ROOT, "b%02d", i),
                    Pose.translation(0, -0.1 + 0.04 * (i % 6), -0.15 + 0.06 * (i / 6)).times(tcp), q, m.kinematics().confOf(q)));
        List<Instruction> p = new ArrayList<>();
        for (int i = 0; i < 60; i++) {
            String to = String.format(Locale.ROOT, "b%02d", (i * 7) % 30);
            if (i % 5 == 4) p.add(new Instruction(Instruction.Type.MOVEC, to, 200, 10, String.format(Locale.ROOT, "b%02d", (i * 7 + 11) % 30)));
            else p.add(new Instruction(i == 0 ? Instruction.Type.MOVEJ : Instruction.Type.MOVEL, to, 200, 10));
        }
        m.setProgram(p);
        ProgramRun first = m.programRun();
        long misses = m.checkCache().misses(), hits = m.checkCache().hits();
        // The program goes round its 30 targets twice: the second round repeats the first's motions exactly.
        assertEquals(60, misses + hits);
        assertTrue(misses > 30, "the first check solves each distinct motion: " + misses);

        Instruction i = p.get(25);
        p.set(25, new Instruction(i.type(), i.target(), 350, i.zoneMm(), i.via()));
        m.setProgram(p);
        ProgramRun edited = m.programRun();
        assertEquals(misses + 1, m.checkCache().misses(), "a speed edit solves that motion only");
        assertEquals(hits + 59, m.checkCache().hits());
        assertTrue(edited.duration() < first.duration(), "a faster motion shortens the cycle");

        ProgramRun full = ProgramRun.of(m); // no cache
        CheckReport a = full.report(), b = edited.report();
        assertEquals(a.problems(), b.problems());
        assertEquals(a.cycleTimeS(), b.cycleTimeS());
        assertEquals(full.sampleCount(), edited.sampleCount());
        for (int k = 0; k < full.sampleCount(); k++) assertArrayEquals(full.qAt(k), edited.qAt(k));
    }
}
