package org.robopro.app.workbench.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;
import org.robopro.kinematics.Pose;

class PathCheckerTest {
    @Test
    void burstOfEdits_oneCheckOffTheCallingThread_reflectsTheLastProgram() throws Exception {
        WorkbenchModel m = ProgramRunTest.modelWithTargets();
        try (PathChecker c = new PathChecker(m, 300)) {
            assertNotNull(c.awaitCurrent(30_000));
            long before = c.checks();
            AtomicReference<Thread> ran = new AtomicReference<>();
            c.addListener(r -> ran.set(Thread.currentThread()));
            List<Instruction> p = new ArrayList<>();
            for (int i = 0; i < 20; i++) {
                p.add(new Instruction(i % 2 == 0 ? Instruction.Type.MOVEJ : Instruction.Type.MOVEL, i % 2 == 0 ? "p10" : "p20", 200, 0));
                m.setProgram(p);
            }
            PathChecker.Result r = c.awaitCurrent(30_000);
            assertNotNull(r);
            assertEquals(20, r.program().size(), "the check saw the last edit");
            assertEquals(20, r.run().steps().size());
            assertTrue(c.checks() - before <= 2, "20 edits within the debounce cost " + (c.checks() - before) + " checks");
            assertNotEquals(Thread.currentThread(), ran.get());
            assertEquals("path-check", ran.get().getName());
        }
    }

    /**
     * A listener (the window hands each result to the Swing thread, which then reads latest())
     * finds the result it was handed as latest(): were the previous one still published, the
     * program table would show the previous program's results beside the new program until the
     * next edit.
     */
    @Test
    void listener_findsTheResultItIsHandedAsLatest() throws Exception {
        WorkbenchModel m = ProgramRunTest.modelWithTargets();
        try (PathChecker c = new PathChecker(m, 20)) {
            c.awaitCurrent(30_000);
            List<String> seen = java.util.Collections.synchronizedList(new ArrayList<>());
            c.addListener(r -> seen.add(c.latest() == r ? "same" : "other: latest is request "
                    + (c.latest() == null ? "none" : c.latest().request()) + ", handed " + r.request()));
            for (int i = 1; i <= 3; i++) {
                List<Instruction> p = new ArrayList<>();
                for (int k = 0; k < i; k++) p.add(new Instruction(Instruction.Type.MOVEJ, k % 2 == 0 ? "p10" : "p20", 200, 0));
                m.setProgram(p);
                PathChecker.Result r = c.awaitCurrent(30_000);
                assertEquals(i, r.program().size());
                assertTrue(r.program() == r.run().program(), "the result's program is the one its run checked");
            }
            assertEquals(List.of("same", "same", "same"), seen);
        }
    }

    @Test
    void jogging_noCheck_butAnUnreachableTargetIsMarked() throws Exception {
        WorkbenchModel m = ProgramRunTest.modelWithTargets();
        try (PathChecker c = new PathChecker(m, 50)) {
            c.awaitCurrent(30_000);
            long n = c.checks();
            double[] q = m.q();
            for (int i = 0; i < 10; i++) { q[0] += 0.01; m.setQ(q); }
            Thread.sleep(300);
            assertEquals(n, c.checks(), "jogging does not start a path check");
            Pose far = Pose.translation(5, 0, 0).times(m.target("p10").orElseThrow().worldTtcp());
            m.putTarget(new Target("far", far, m.q(), m.kinematics().confOf(m.q())));
            PathChecker.Result r = c.awaitCurrent(30_000);
            assertEquals(TargetStatus.UNREACHABLE, r.statuses().get("far"));
            assertEquals(TargetStatus.REACHABLE, r.statuses().get("p10"));
        }
    }
}
