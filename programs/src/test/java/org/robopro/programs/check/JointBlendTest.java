package org.robopro.programs.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.kinematics.KinematicModel;
import org.robopro.models.Vec3;
import org.robopro.programs.Move;
import org.robopro.programs.RapidModule;
import org.robopro.programs.Ref;
import org.robopro.programs.RobTarget;
import org.robopro.programs.Teach;
import org.robopro.programs.WObjData;
import org.robopro.programs.sim.MotionInterpreter;

/** Fly-by points of MoveJ blended in joint space, as the controller does. */
class JointBlendTest {
    static final KinematicModel IRB2000 = PathCheckerTest.IRB2000;

    static double[] lerp(double[] a, double[] b, double s) {
        double[] q = new double[a.length];
        for (int i = 0; i < q.length; i++) q[i] = a[i] + s * (b[i] - a[i]);
        return q;
    }

    static CheckReport moveJs(double[] qa, double[] qb, double[] qc, String zone) {
        RobTarget a = Teach.taught(IRB2000, qa, PathCheckerTest.TORCH, WObjData.WOBJ0);
        RobTarget b = Teach.taught(IRB2000, qb, PathCheckerTest.TORCH, WObjData.WOBJ0);
        RobTarget c = Teach.taught(IRB2000, qc, PathCheckerTest.TORCH, WObjData.WOBJ0);
        RapidModule m = RapidModule.builder("J").pers("tTorch", PathCheckerTest.TORCH).constant("pA", a).constant("pB", b).constant("pC", c)
                .procedure("main", List.of(
                        Move.moveJ(Ref.to("pA"), Ref.to("v1000"), Ref.to("fine"), "tTorch", null),
                        Move.moveJ(Ref.to("pB"), Ref.to("v1000"), Ref.to(zone), "tTorch", null),
                        Move.moveJ(Ref.to("pC"), Ref.to("v1000"), Ref.to("fine"), "tTorch", null)))
                .build();
        return new PathChecker(IRB2000).check(MotionInterpreter.of(m).run());
    }

    static Vec3 tcp(double[] q) { return IRB2000.flange(q).times(PathCheckerTest.TORCH.tframe().toPose()).position(); }

    @Test
    void moveJThroughAPointOnItsJointLine_blendPassesThroughIt_whereACartesianCornerWouldNot() {
        double[] qa = {-0.4, 0.1, 0.1, 0.2, 0.9, 0.1}, qc = {0.6, 0.4, -0.1, -0.3, 0.6, 0.5};
        double[] qb = lerp(qa, qc, 0.4);
        CheckReport r = moveJs(qa, qb, qc, "z50");
        assertFalse(r.hasErrors(), r::format);
        // In joint space the corner's control point lies on the line through entry and exit: the
        // blend goes through pB's joints, so the TCP passes through pB.
        assertEquals(0, r.steps().get(1).cornerDeviationM(), 1e-6, r::format);
        // The TCP path of a joint-space line is curved: a Cartesian corner between the chords would miss pB.
        Vec3 p0 = tcp(qa), p1 = tcp(qb), p2 = tcp(qc);
        double cartesian = p0.minus(p1).normalized().times(0.05 / 4).plus(p2.minus(p1).normalized().times(0.05 / 4)).norm();
        assertTrue(cartesian > 0.001, "the chords meet at an angle: a Cartesian corner would pass " + cartesian * 1e3 + " mm away");
        double saved = r.cycleTimeStopsS() - r.cycleTimeS();
        assertTrue(saved >= 0.25 - 1e-9, "speed kept through the corner saves at least the two half ramps: " + saved);
    }

    @Test
    void moveJThereAndBack_turnsInsideTheZoneShortOfTheTarget() {
        double[] qa = {-0.3, 0.2, 0.0, 0.1, 0.8, 0.0}, qb = {0.3, 0.3, 0.1, 0.1, 0.8, 0.2};
        CheckReport r = moveJs(qa, qb, qa, "z50");
        double dev = r.steps().get(1).cornerDeviationM();
        // Independently: going back along the same joint line, the blend turns where the TCP entered
        // the zone, halfway between that point and pB in joint space (symmetric legs).
        double lo = 0, hi = 1; // the last point of the incoming line at 50 mm or more from pB
        Vec3 pb = tcp(qb);
        for (int it = 0; it < 60; it++) {
            double mid = (lo + hi) / 2;
            if (tcp(lerp(qa, qb, mid)).minus(pb).norm() >= 0.05) lo = mid; else hi = mid;
        }
        double[] turn = lerp(lerp(qa, qb, lo), qb, 0.5);
        assertEquals(tcp(turn).minus(pb).norm(), dev, 1e-4, r::format);
        assertTrue(dev > 0.005 && dev < 0.05, "turns short of pB, inside the zone: " + dev);
        CheckReport fine = moveJs(qa, qb, qa, "fine");
        assertEquals(0, fine.steps().get(1).cornerDeviationM(), 0);
        assertEquals(fine.cycleTimeS(), r.cycleTimeStopsS(), 1e-9, "stop-to-stop times agree");
        assertTrue(r.cycleTimeS() < fine.cycleTimeS());
    }
}
