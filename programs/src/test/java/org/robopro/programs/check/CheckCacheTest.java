package org.robopro.programs.check;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.function.UnaryOperator;
import org.junit.jupiter.api.Test;
import org.robopro.kinematics.ConfData;
import org.robopro.kinematics.InverseKinematics;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.RobotLibrary;
import org.robopro.programs.RapidParser;
import org.robopro.programs.sim.MotionInterpreter;
import org.robopro.programs.sim.Simulation;

/**
 * Incremental checks: after an edit, a check with the cache gives exactly the report of a check
 * from scratch, and solves only the motions whose inputs changed.
 */
class CheckCacheTest {
    static final KinematicModel IRB2000 = KinematicModel.build(RobotLibrary.shipped("irb2000"));
    static final InverseKinematics IK = InverseKinematics.of(IRB2000);
    static final int MOVES = 60;

    /**
     * RAPID text: targets p0..p(MOVES-1) and circle points taught along a sweep of axis 1, a
     * MoveAbsJ home, then MoveJ / MoveL / MoveC with z10 and fine; {@code edit} changes the
     * statement lines of main before the module is written.
     */
    static String program(UnaryOperator<List<String>> edit) {
        StringBuilder b = new StringBuilder("MODULE Cache\n  PERS tooldata tTorch := [TRUE,[[0,0,150],[1,0,0,0]],[1,[0,0,1],[1,0,0,0],0,0,0]];\n"
                + "  CONST jointtarget jHome := [[0,0,0,0,28.6479,0],[9E9,9E9,9E9,9E9,9E9,9E9]];\n");
        List<String> body = new ArrayList<>();
        body.add("MoveAbsJ jHome, v1000, fine, tTorch;");
        for (int k = 0; k < MOVES; k++) {
            double s = k / (double) MOVES;
            b.append(target("p" + k, q(s, 0)));
            String zone = k % 5 == 4 ? "fine" : "z10";
            if (k % 10 == 9) {
                b.append(target("c" + k, q((k - 0.5) / MOVES, 0.05)));
                body.add("MoveC c" + k + ", p" + k + ", v200, " + zone + ", tTorch;");
            } else if (k % 3 == 0) body.add("MoveJ p" + k + ", v1000, " + zone + ", tTorch;");
            else body.add("MoveL p" + k + ", v200, " + zone + ", tTorch;");
        }
        b.append("  PROC main()\n");
        for (String line : edit.apply(body)) b.append("    ").append(line).append('\n');
        return b.append("  ENDPROC\nENDMODULE\n").toString();
    }

    /** A robtarget taught at joints q (TCP pose by forward kinematics, confdata of q). */
    static String target(String name, double[] q) {
        Pose p = IRB2000.flange(q).times(Pose.translation(0, 0, 0.15));
        double[] wxyz = p.quaternion();
        ConfData c = IK.confOf(q);
        return String.format(Locale.ROOT, "  CONST robtarget %s := [[%.6f,%.6f,%.6f],[%.9f,%.9f,%.9f,%.9f],[%d,%d,%d,%d],[9E9,9E9,9E9,9E9,9E9,9E9]];%n",
                name, p.x() * 1e3, p.y() * 1e3, p.z() * 1e3, wxyz[0], wxyz[1], wxyz[2], wxyz[3], c.cf1(), c.cf4(), c.cf6(), c.cfx());
    }

    static double[] q(double s, double lift) {
        return new double[] {-0.6 + 1.2 * s, 0.25 + lift + 0.1 * Math.sin(7 * s), 0.05 + 0.05 * Math.cos(5 * s), 0.15, 0.9 + 0.1 * Math.sin(3 * s), 0.25};
    }

    static Simulation run(String text) { return MotionInterpreter.of(RapidParser.parseDetailed(text, "Cache.mod")).simulate("main"); }

    /** Checks the edited program with a cache warmed on the original; returns the motions solved again. */
    static long editedMisses(UnaryOperator<List<String>> edit) {
        PathChecker checker = new PathChecker(IRB2000);
        CheckCache cache = new CheckCache();
        CheckReport first = checker.check(run(program(b -> b)), List.of(), cache);
        assertSame(checker.check(run(program(b -> b)), List.of()), first);
        long before = cache.misses();
        Simulation edited = run(program(edit));
        CheckReport incremental = checker.check(edited, List.of(), cache);
        assertSame(new PathChecker(IRB2000).check(edited, List.of()), incremental);
        return cache.misses() - before;
    }

    /** Same problems, durations, end joints and path samples, bit for bit. */
    static void assertSame(CheckReport full, CheckReport inc) {
        assertEquals(full.problems(), inc.problems());
        assertEquals(full.cycleTimeS(), inc.cycleTimeS());
        assertEquals(full.cycleTimeStopsS(), inc.cycleTimeStopsS());
        assertEquals(full.io(), inc.io());
        assertEquals(full.steps().size(), inc.steps().size());
        for (int i = 0; i < full.steps().size(); i++) {
            CheckReport.StepResult a = full.steps().get(i), b = inc.steps().get(i);
            assertEquals(a.step(), b.step());
            assertEquals(a.target(), b.target());
            assertEquals(a.durationS(), b.durationS(), a.step());
            assertEquals(a.cornerDeviationM(), b.cornerDeviationM(), a.step());
            assertEquals(a.interpolationPoints(), b.interpolationPoints());
            assertArrayEquals(a.qEnd(), b.qEnd(), a.step());
            assertEquals(a.samples().size(), b.samples().size());
            for (int k = 0; k < a.samples().size(); k++) assertArrayEquals(a.samples().get(k), b.samples().get(k));
        }
    }

    @Test
    void unchangedProgram_solvesNothingAgain() {
        PathChecker checker = new PathChecker(IRB2000);
        CheckCache cache = new CheckCache();
        checker.check(run(program(b -> b)), List.of(), cache);
        assertEquals(MOVES + 1, cache.misses());
        checker.check(run(program(b -> b)), List.of(), cache);
        assertEquals(MOVES + 1, cache.misses());
        assertEquals(MOVES + 1, cache.hits());
    }

    @Test
    void speedChanged_onlyThatMotionSolvedAgain() {
        long misses = editedMisses(b -> {
            b.set(32, b.get(32).replace("v200", "v500"));
            return b;
        });
        assertEquals(1, misses);
    }

    @Test
    void zoneChanged_nothingSolvedAgain_blendingRecomputed() {
        long misses = editedMisses(b -> {
            b.set(32, b.get(32).replace("z10", "z50"));
            return b;
        });
        assertEquals(0, misses);
    }

    @Test
    void targetChanged_thatMotionAndTheNextOnly() {
        long misses = editedMisses(b -> {
            b.set(32, "MoveL p33, v200, z10, tTorch;");
            return b;
        });
        // The edited MoveL and the MoveL after it (new start); the MoveJ after that starts where it did.
        assertEquals(2, misses);
    }

    @Test
    void moveInsertedAndDeleted_labelsFollow_fewSolvedAgain() {
        long inserted = editedMisses(b -> {
            b.add(20, "MoveJ p40, v1000, fine, tTorch;");
            return b;
        });
        assertTrue(inserted >= 2 && inserted <= 3, inserted + " motions solved again");
        long deleted = editedMisses(b -> {
            b.remove(45);
            return b;
        });
        assertEquals(1, deleted, "the motion after the deleted one starts elsewhere; the rest are found again");
    }

    @Test
    void otherRobotOrOptions_cacheStartsEmpty() {
        CheckCache cache = new CheckCache();
        Simulation sim = run(program(b -> b));
        new PathChecker(IRB2000).check(sim, List.of(), cache);
        PathChecker.Options finer = new PathChecker.Options(0.002, Math.toRadians(1), 0.02, 0.25, Math.toRadians(20), java.util.Optional.empty());
        long before = cache.misses();
        CheckReport r = new PathChecker(IRB2000, finer).check(sim, List.of(), cache);
        assertEquals(MOVES + 1, cache.misses() - before);
        assertSame(new PathChecker(IRB2000, finer).check(sim, List.of()), r);
    }
}
