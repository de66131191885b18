package org.robopro.world;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;

/**
 * The forms first seen in a clean-room simulator, each checked by hand: the tracker's distance
 * meter and azimuth encoder, the base rocking over a foot edge, the dress pack's pull on the wrist,
 * a bearing's wobble, a stiffening joint spring, lost motion held by gravity.
 */
class OpenWorldFormsTest {
    static final RobotDescription IRB2000 = RobotLibrary.shipped("irb2000");
    static final double G = 9.80665;
    static final int[] UP = {1, 1, 1, 1, 1, 1};
    static final double ARCSEC = Math.toRadians(1.0 / 3600);

    static double[] deg(double... d) { return Arrays.stream(d).map(Math::toRadians).toArray(); }

    /** The file's masses exactly (no perturbation), every drive rigid. */
    static WorldRobot.Compliance exact() {
        return WorldRobot.Compliance.fromFile(IRB2000.massModel().orElseThrow(), 6, 0, new Random(0) {
            @Override public double nextGaussian() { return 0; }
        });
    }

    static WorldRobot nominal() { return WorldRobot.nominal(IRB2000, new double[] {0, 0, 0.1}); }

    static WorldRobot.Tracker distance(double a, double period, double phase, double scale) {
        return new WorldRobot.Tracker(a, period, phase, scale, new int[0], new double[0], new double[0], new int[0], new double[0], new double[0]);
    }

    @Test
    void distanceMeterCyclicError_alongTheLineOfSight_byHand() {
        // period 400 mm, phase pi/2: at 3 m, 2 pi 3 / 0.4 = 15 pi, sin(15 pi + pi/2) = -1; at 5 m, 25 pi: -1 again; at 3.1 m, 15.5 pi: sin(16 pi) = 0
        var t = distance(25e-6, 0.4, Math.PI / 2, 0);
        assertArrayEquals(new double[] {3 - 25e-6, 0, 0}, t.read(new double[] {3, 0, 0}), 1e-12);
        assertArrayEquals(new double[] {0, 4 * (5 - 25e-6) / 5, 3 * (5 - 25e-6) / 5}, t.read(new double[] {0, 4, 3}), 1e-12);
        assertArrayEquals(new double[] {0, 0, 3.1}, t.read(new double[] {0, 0, 3.1}), 1e-12);
        // a range scale of 2e-6 adds 6 µm at 3 m
        assertArrayEquals(new double[] {3 + 6e-6 - 25e-6, 0, 0}, distance(25e-6, 0.4, Math.PI / 2, 2e-6).read(new double[] {3, 0, 0}), 1e-12);
        // On a robot seen by a tilted tracker: the shift is along the tracker's line of sight to the point, a sin(2 pi rho / period + phase)
        Rigid inst = Rigid.rotation(new double[] {1, 0, 0}, Math.toRadians(4), new double[3])
                .times(Rigid.translation(-2.5, 1.0, -0.4));
        WorldRobot plain = nominal().withInstrument(inst), seen = plain.withTracker(distance(25e-6, 0.3, 0.7, 0));
        for (double[] q : List.of(deg(0, 0, 0, 0, 0, 0), deg(30, 20, -10, 40, 50, 60), deg(-60, -30, 20, 0, -70, 10))) {
            double[] p = plain.target(q, UP, 20, 0, 0).p(), m = seen.target(q, UP, 20, 0, 0).p();
            double rho = Rigid.norm(p);
            double[] expect = Rigid.scale(Rigid.unit(p), 25e-6 * Math.sin(2 * Math.PI * rho / 0.3 + 0.7));
            assertArrayEquals(expect, Rigid.minus(m, p), 1e-12);
        }
    }

    @Test
    void beamBreaks_eachOffsetAlongTheLineOfSightUntilTheNextBreak_byHand() {
        var t = distance(0, 1, 0, 0).withBeamBreaks(new double[] {0, 100, 250}, new double[] {4e-6, -11e-6, 7e-6});
        // before any break the start's offset; at and after a break its own; the point stays on its line of sight
        assertArrayEquals(new double[] {3 + 4e-6, 0, 0}, t.read(new double[] {3, 0, 0}, 50), 1e-12);
        assertArrayEquals(new double[] {0, 4 * (5 - 11e-6) / 5, 3 * (5 - 11e-6) / 5}, t.read(new double[] {0, 4, 3}, 100), 1e-12);
        assertArrayEquals(new double[] {0, 0, 2 + 7e-6}, t.read(new double[] {0, 0, 2}, 1e4), 1e-12);
        // an unknown time: the start's
        assertArrayEquals(new double[] {3 + 4e-6, 0, 0}, t.read(new double[] {3, 0, 0}), 1e-12);
        // seen through a tilted tracker: the robot's point moves along the line of sight by the offset of the moment
        Rigid inst = Rigid.rotation(new double[] {1, 0, 0}, Math.toRadians(4), new double[3]).times(Rigid.translation(-2.5, 1.0, -0.4));
        WorldRobot plain = nominal().withInstrument(inst), seen = plain.withTracker(t);
        double[] q = deg(30, 20, -10, 40, 50, 60);
        double[] p = plain.target(q, UP, 20, 180, 0).p(), m = seen.target(q, UP, 20, 180, 0).p();
        assertArrayEquals(Rigid.scale(Rigid.unit(p), -11e-6), Rigid.minus(m, p), 1e-12);
        assertTrue(Scenario.named("outside: the tracker's distance taken again at every beam break, sigma 0.005 mm").trial(3).truthJson()
                .contains("beam_break_offset_um"));
    }

    @Test
    void azimuthEncoderError_turnsThePointAboutTheTrackersOwnVerticalAxis_byHand() {
        double a1 = 4 * ARCSEC, a2 = 3 * ARCSEC;
        var t = new WorldRobot.Tracker(0, 1, 0, 0, new int[] {1, 2}, new double[] {a1, a2}, new double[] {Math.PI / 2, 0},
                new int[0], new double[0], new double[0]);
        // azimuth 0: a1 sin(pi/2) + a2 sin(0) = a1; the point (2, 0, 1) turns by a1 about z, 2 a1 = 39 µm sideways
        double[] p = t.read(new double[] {2, 0, 1});
        assertArrayEquals(new double[] {2 * Math.cos(a1), 2 * Math.sin(a1), 1}, p, 1e-12);
        assertEquals(2 * a1, p[1], 1e-12);
        // azimuth 45°: a1 sin(pi/4 + pi/2) + a2 sin(pi/2) = a1 cos(pi/4) + a2
        double e = a1 * Math.cos(Math.PI / 4) + a2, h = Math.sqrt(2) * 3;
        assertArrayEquals(new double[] {h * Math.cos(Math.PI / 4 + e), h * Math.sin(Math.PI / 4 + e), -0.5}, t.read(new double[] {3, 3, -0.5}), 1e-12);
        // The tracker stands tilted: the shift lies in its own horizontal plane, |shift| = horizontal distance x angle error (to first order)
        Rigid inst = Rigid.rotation(new double[] {0, 1, 0}, Math.toRadians(5), new double[3]).times(Rigid.translation(-3, 0.5, -0.2));
        WorldRobot plain = nominal().withInstrument(inst), seen = plain.withTracker(t);
        double[] q = deg(20, 10, 5, 0, 30, 0);
        double[] x = plain.target(q, UP, 20, 0, 0).p(), y = seen.target(q, UP, 20, 0, 0).p();
        double[] d = Rigid.minus(y, x);
        assertEquals(0, d[2], 1e-12, "no shift along the tracker's own z");
        double az = Math.atan2(x[1], x[0]), err = a1 * Math.sin(az + Math.PI / 2) + a2 * Math.sin(2 * az);
        assertEquals(Math.hypot(x[0], x[1]) * Math.abs(err), Rigid.norm(d), 1e-9);
    }

    /**
     * The upper arm twists about its own axis by T / k, T the moment of the weights beyond it about
     * that axis; gravity then does work on the loads: a weight off the arm's plane moves down.
     */
    @Test
    void upperArmTwist_byHand() {
        var m = exact();
        // 10 kg with their centre 0.2 m along the flange's y
        var twist = new WorldRobot.Twist(2e5, m.masses(), new double[] {0, 0.2, 0}, m.gravity());
        WorldRobot rigid = nominal(), twisted = rigid.withTwist(twist);
        // Zero pose: the upper arm runs straight up from joint 2's point (0, 0, 0.78) to joint 3's (0, 0, 1.49), e = +z, and
        // a weight's moment (c - p) × m g about a vertical axis is 0 whatever its place
        assertEquals(0, twist.torque(rigid.arm(), new double[6], 10), 1e-9, "an upright arm: gravity is along its axis");
        // Joint 2 at 90°: the upper arm lies along +x (joint 2 turns about +y, +90° swings +z to +x); the payload's centre
        // sits off the arm's plane (y = 0), so its weight turns the arm about x
        double[] q = deg(0, 90, 0, 0, 0, 0);
        double[] e = {1, 0, 0};
        double[] p = rigid.arm().bodies(q)[0].apply(rigid.arm().points()[1]);
        double[] c = rigid.arm().bodies(q)[5].apply(rigid.arm().flange().apply(new double[] {0, 0.2, 0}));
        double t = Rigid.dot(e, Rigid.cross(Rigid.minus(c, p), new double[] {0, 0, -10 * G}));
        assertEquals(t, twist.torque(rigid.arm(), q, 10), 1e-9);
        assertTrue(Math.abs(t) > 10, "the payload hangs beside the arm: " + t + " N·m");
        // the payload's centre moves down under the twist (gravity does work on it), by about (T / k) times its lever
        double[] before = c, after = twist.turn(rigid.arm(), q, 10).apply(c);
        double lever = Math.abs(c[1] - p[1]);
        assertTrue(after[2] < before[2], "the weight goes down: " + (after[2] - before[2]));
        assertEquals(lever * Math.abs(t) / 2e5, before[2] - after[2], 1e-3 * lever * Math.abs(t) / 2e5);
        // and the measured target moves with everything beyond the arm
        double[] pt = rigid.target(q, UP, 20, 0, 10).p(), pw = twisted.target(q, UP, 20, 0, 10).p();
        assertArrayEquals(twist.turn(rigid.arm(), q, 10).apply(pt), pw, 1e-12);
    }

    @Test
    void baseRocksOverTheFootEdge_aboveTheHoldMoment_byHand() {
        var m = exact();
        var rock = new WorldRobot.Rocking(0.2, 20, 1e6, m.masses(), m.payloadCentre(), m.gravity());
        WorldRobot rigid = nominal(), rocking = rigid.withRocking(rock);
        // Zero pose, 10 kg: about the +x edge (x = 0.2 m) the weights have lever x - 0.2: upper arm 45 kg at x 0 (-0.2),
        // forearm 35 kg at 0.3 (0.1), wrist 6 kg at 0.85 (0.65), payload 10 kg at the flange, 1.0 (0.8): M = 6.4 g
        double moment = (45 * -0.2 + 35 * 0.1 + 6 * 0.65 + 10 * 0.8) * G;
        assertEquals(moment, rocking.overturningMoments(rigid.arm(), new double[6], 10)[0], 1e-9);
        double phi = (moment - 20) / 1e6;
        // the robot turns about +y (z × x) through (0.2, 0, 0): the target (1.1, 0, 1.615) relative to the edge is (0.9, 0, 1.615)
        double[] p = rocking.target(new double[6], UP, 20, 0, 10).p();
        assertArrayEquals(new double[] {0.2 + 0.9 * Math.cos(phi) + 1.615 * Math.sin(phi), 0, -0.9 * Math.sin(phi) + 1.615 * Math.cos(phi)}, p, 1e-12);
        // without the payload M = -1.6 g < 20 N·m: no tilt at all
        assertArrayEquals(rigid.target(new double[6], UP, 20, 0, 0).p(), rocking.target(new double[6], UP, 20, 0, 0).p(), 0.0);
        // a hold above the moment: rigid
        WorldRobot held = rigid.withRocking(new WorldRobot.Rocking(0.2, 70, 1e6, m.masses(), m.payloadCentre(), m.gravity()));
        assertArrayEquals(rigid.target(new double[6], UP, 20, 0, 10).p(), held.target(new double[6], UP, 20, 0, 10).p(), 0.0);
        // Joint 1 at 90°: the arm reaches over the +y edge; the same moment tips it about z × y = -x through (0, 0.2, 0)
        double[] q1 = deg(90, 0, 0, 0, 0, 0);
        double[] r = rocking.target(q1, UP, 20, 0, 10).p();
        // the target at (0, 1.1, 1.615): relative to the edge (0, 0.9, 1.615), turned by phi about -x
        assertArrayEquals(new double[] {0, 0.2 + 0.9 * Math.cos(phi) + 1.615 * Math.sin(phi), -0.9 * Math.sin(phi) + 1.615 * Math.cos(phi)}, r, 1e-12);
    }

    @Test
    void pedestalFootRocksOnTheFloor_theBaseSlidesTowardTheLean_byHand() {
        var m = exact();
        var rock = new WorldRobot.Rocking(0.2, 20, 1e6, m.masses(), m.payloadCentre(), m.gravity(), 0.6);
        WorldRobot rigid = nominal(), rocking = rigid.withRocking(rock);
        // The same moment as on the base plate (the weights are vertical: the edge's depth gives them no lever)
        double moment = (45 * -0.2 + 35 * 0.1 + 6 * 0.65 + 10 * 0.8) * G, phi = (moment - 20) / 1e6;
        assertEquals(moment, rocking.overturningMoments(rigid.arm(), new double[6], 10)[0], 1e-9);
        // about +y through the foot's edge (0.2, 0, -0.6): the target (1.1, 0, 1.615) is (0.9, 0, 2.215) from it
        double[] p = rocking.target(new double[6], UP, 20, 0, 10).p();
        assertArrayEquals(new double[] {0.2 + 0.9 * Math.cos(phi) + 2.215 * Math.sin(phi), 0, -0.6 - 0.9 * Math.sin(phi) + 2.215 * Math.cos(phi)},
                p, 1e-12);
        // against the plate on the floor of the base itself, the target moves further toward the lean by about phi x 0.6 m
        double[] plate = rigid.withRocking(new WorldRobot.Rocking(0.2, 20, 1e6, m.masses(), m.payloadCentre(), m.gravity())).target(
                new double[6], UP, 20, 0, 10).p();
        assertEquals(0.6 * phi, p[0] - plate[0], 1e-3 * 0.6 * phi);
    }

    @Test
    void dressPackPull_yieldsTheWristDrives_byVirtualWork_byHand() {
        var pack = new WorldRobot.DressPack(0.1, Math.toRadians(90), 0.8, 0, 200, new double[] {2e4, 1.5e4, 1e4});
        WorldRobot rigid = nominal(), pulled = rigid.withDressPack(pack);
        // Wound up: q4 120°, q6 60°, wrist straight: u = pi, s = 0.1 pi, slack 0.1 pi/2: T = 200 · 0.05 pi;
        // ds/dq4 = ds/dq6 = r^2 u / s = r, so tau4 = tau6 = -T r = -pi N·m; joint 5 feels nothing
        double tau = -200 * 0.05 * Math.PI * 0.1;
        assertArrayEquals(new double[] {tau, 0, tau}, pack.torques(Math.toRadians(120), 0, Math.toRadians(60)), 1e-12);
        double[] q = deg(10, 20, -5, 120, 0, 60);
        double[] yielded = q.clone();
        yielded[3] += tau / 2e4;
        yielded[5] += tau / 1e4;
        assertArrayEquals(rigid.target(yielded, UP, 20, 0, 0).p(), pulled.target(q, UP, 20, 0, 0).p(), 1e-12);
        // Bent: q5 90°, no twist: v = 0.8 pi/2, s = 0.1 v, slack 0.1 pi/2 is more than s: loose, nothing moves
        double[] bent = deg(10, 20, -5, 0, 90, 0);
        assertArrayEquals(rigid.target(bent, UP, 20, 0, 0).p(), pulled.target(bent, UP, 20, 0, 0).p(), 0.0);
        // Bent and wound: q4 = 100°, q5 = 90°, q6 = -20° (u = 80° = 1.3963 rad, v = 1.2566 rad): s = 0.1 · hypot(u, v),
        // tau5 = -T r^2 v · 0.8 / s. Joint 5 now yields too, and by a torque that neither joint 5 nor the twist gives alone.
        double u = Math.toRadians(80), v = 0.8 * Math.toRadians(90), s = 0.1 * Math.hypot(u, v), t = 200 * (s - 0.1 * Math.PI / 2);
        double[] expect = {-t * 0.01 * u / s, -t * 0.01 * v * 0.8 / s, -t * 0.01 * u / s};
        assertArrayEquals(expect, pack.torques(Math.toRadians(100), Math.toRadians(90), Math.toRadians(-20)), 1e-12);
        assertTrue(t > 0 && expect[1] < -0.1, "taut, joint 5 pulled back: " + expect[1]);
        double[] q2 = deg(-20, 10, 15, 100, 90, -20), y2 = q2.clone();
        for (int j = 0; j < 3; j++) y2[3 + j] += expect[j] / pack.wristStiffness()[j];
        assertArrayEquals(rigid.target(y2, UP, 20, 0, 0).p(), pulled.target(q2, UP, 20, 0, 0).p(), 1e-12);
    }

    @Test
    void bearingWobble_tiltsTheAxis_andMovesEverythingOutboard_byHand() {
        double alpha = Math.toRadians(0.01);
        WorldRobot rigid = nominal();
        // Joint 1 (axis z through the origin): u = z × x = y, v = z × u = -x. At q1 = 0 and phase 0 the tilt is about +y:
        // the target (1.1, 0, 1.615) turns to (1.1 cos a + 1.615 sin a, 0, -1.1 sin a + 1.615 cos a)
        WorldRobot w1 = rigid.withWobbles(List.of(new WorldRobot.Wobble(0, alpha, 0.38, 0)));
        assertArrayEquals(new double[] {1.1 * Math.cos(alpha) + 1.615 * Math.sin(alpha), 0, -1.1 * Math.sin(alpha) + 1.615 * Math.cos(alpha)},
                w1.target(new double[6], UP, 20, 0, 0).p(), 1e-12);
        // At q1 = 90° the arm points along +y and the tilt's direction has turned by only 0.38 · 90° = 34.2°:
        // d = cos(34.2°) y - sin(34.2°) x; the target (0, 1.1, 1.615) moves by alpha d × p (first order)
        double b = Math.toRadians(0.38 * 90);
        double[] d = {-Math.sin(b), Math.cos(b), 0}, p = {0, 1.1, 1.615};
        double[] shift = Rigid.minus(w1.target(deg(90, 0, 0, 0, 0, 0), UP, 20, 0, 0).p(), rigid.target(deg(90, 0, 0, 0, 0, 0), UP, 20, 0, 0).p());
        assertArrayEquals(Rigid.scale(Rigid.cross(d, p), alpha), shift, 1e-7);
        assertTrue(Rigid.norm(shift) > 3e-4, "0.01° at 2 m: " + Rigid.norm(shift));
        // Joint 3 at twice its angle (axis y through (0, 0, 1.49)): u = y × x = -z, v = y × u = -x. The tilt turns the forearm about
        // d = cos(2 q3) u + sin(2 q3) v through joint 3's point; at q3 = 45° (theta3 = q3 - q2 = 45°), d = -x
        WorldRobot w3 = rigid.withWobbles(List.of(new WorldRobot.Wobble(2, alpha, 2, 0)));
        double[] q = deg(0, 0, 45, 0, 0, 0);
        double[] at = rigid.target(q, UP, 20, 0, 0).p(), moved = w3.target(q, UP, 20, 0, 0).p();
        double[] rel = Rigid.minus(at, new double[] {0, 0, 1.49});
        assertArrayEquals(Rigid.scale(Rigid.cross(new double[] {-1, 0, 0}, rel), alpha), Rigid.minus(moved, at), 1e-7);
        // The tilt is not an angle error of joint 3: that would move the point in the xz plane; this moves it sideways (y)
        assertTrue(Math.abs(moved[1] - at[1]) > 1e-4, "sideways " + (moved[1] - at[1]));
        // Where the direction has come round to the joint's own axis's plane the shift lies in the joint's plane of motion,
        // at q3 = 0: d = -z; everything about the axis point: the points of joint 3's axis do not move
        assertArrayEquals(new double[] {0, 0, 1.49}, w3.arm().points()[2], 0.0);
    }

    @Test
    void stiffeningSpring_deflectsLessThanLinear_byHand() {
        // k dq (1 + (dq/dh)^2) = tau with k 1e6, dh 1e-4, tau 200: in units of dh, y + y^3 = 2, y = 1
        var c = exact().withStiffness(1, 1e6).withHardening(1, 1e-4);
        assertEquals(1e-4, c.deflection(1, 200), 1e-15);
        assertEquals(-1e-4, c.deflection(1, -200), 1e-15);
        assertEquals(2e-4, exact().withStiffness(1, 1e6).deflection(1, 200), 1e-15);
        for (double tau : new double[] {-500, -37, 0, 3, 120, 480}) {
            double dq = c.deflection(1, tau);
            assertEquals(tau, 1e6 * dq * (1 + dq * dq / 1e-8), 1e-9);
        }
        // Drive 3 at the zero pose with 10 kg carries tau = (35 · 0.3 + 6 · 0.85 + 10 · 1.0) g. With dh = tau / 2k, y + y^3 = 2: it yields by
        // dh = half the linear spring's tau / k; the forearm turns about +y at joint 3 (the flange 1.0 m ahead, 0.125 m above it)
        double tau = (35 * 0.3 + 6 * 0.85 + 10 * 1.0) * G, k = 1e6;
        WorldRobot rigid = WorldRobot.nominal(IRB2000, new double[3]);
        WorldRobot soft = rigid.withCompliance(exact().withStiffness(2, k).withHardening(2, tau / (2 * k)));
        double dq = tau / (2 * k);
        double[] a = rigid.target(new double[6], UP, Double.NaN, 0, 10).p(), c3 = soft.target(new double[6], UP, Double.NaN, 0, 10).p();
        assertEquals(-1.000 * Math.sin(dq) + 0.125 * (Math.cos(dq) - 1), c3[2] - a[2], 1e-12);
        assertEquals(1.000 * (Math.cos(dq) - 1) + 0.125 * Math.sin(dq), c3[0] - a[0], 1e-12);
    }

    @Test
    void lostMotionHeldByGravity_showsTheDirectionOnlyWhereTheTorqueIsSmall_byHand() {
        double b = Math.toRadians(0.04);
        WorldRobot rigid = nominal(), held = rigid.withCompliance(exact()).withErrors(List.of(new JointError.GravityHeldLostMotion(1, b, 50)));
        int[] down = {1, -1, 1, 1, 1, 1};
        // Upper arm vertical: drive 2 carries tau_q2 = tau_theta2 - tau_theta3 = 0 (PhysicsTest): the play follows the last motion
        double[] q0 = deg(10, 0, 5, 0, 30, 0);
        assertArrayEquals(rigid.target(shift(q0, -b / 2), UP, 20, 0, 10).p(), held.target(q0, UP, 20, 0, 10).p(), 1e-12);
        assertArrayEquals(rigid.target(shift(q0, b / 2), down, 20, 0, 10).p(), held.target(q0, down, 20, 0, 10).p(), 1e-12);
        // Leaning 30° forward with 10 kg: tau_q2 = ((35 + 6 + 10) 0.710 + 45 · 0.355) g sin 30° = 256 N·m > 50, pushing the output ahead:
        // q_out = q + b/2 whichever way the drive last moved
        double[] q30 = deg(0, 30, 0, 0, 0, 0);
        double tq = ((35 + 6 + 10) * 0.710 + 45 * 0.355) * G * 0.5;
        assertEquals(tq, held.driveSide(held.gravityTorques(held.arm(), WorldRobot.times(held.coupling(), q30), 10))[1], 1e-9);
        assertArrayEquals(rigid.target(shift(q30, b / 2), UP, 20, 0, 10).p(), held.target(q30, UP, 20, 0, 10).p(), 1e-12);
        assertArrayEquals(rigid.target(shift(q30, b / 2), down, 20, 0, 10).p(), held.target(q30, down, 20, 0, 10).p(), 1e-12);
        // Leaning back: the torque turns negative and the output rests b/2 behind
        double[] qm = deg(0, -30, 0, 0, 0, 0);
        assertArrayEquals(rigid.target(shift(qm, -b / 2), down, 20, 0, 10).p(), held.target(qm, down, 20, 0, 10).p(), 1e-12);
    }

    /** q with drive 2 moved by d; drive 3's controller value is the forearm's angle, so the forearm keeps it (theta3 = q3 - q2). */
    static double[] shift(double[] q, double d) {
        double[] s = q.clone();
        s[1] += d;
        return s;
    }

    static final List<String> NAMES = List.of("outside: tracker distance-meter cyclic error", "outside: tracker azimuth encoder error",
            "outside: tracker distance and azimuth errors", "outside: base rocks on its foundation above an overturning moment",
            "outside: dress-pack drag on the wrist", "outside: bearing wobble of j3 at twice its angle",
            "outside: bearing wobble of j1 at 0.38 times its angle, 3 gross outliers", "outside: measured target slips mid-campaign, 60 poses",
            "joint elasticity j2 with a stiffening spring, masses off 30 %", "lost motion j2 held on one flank by gravity + cross-coupling j5<-j4");

    @Test
    void everyOpenWorldScenario_drawsMeasuresAndRecordsItsTruth() {
        for (String name : NAMES) {
            Scenario.Trial t = Scenario.named(name).trial(1);
            assertTrue(t.campaign().rows().size() >= 120, name);
            String json = t.truthJson();
            assertTrue(json.contains(name), name);
            String key = name.contains("tracker") ? "\"tracker\"" : name.contains("rocks") ? "\"rocking\"" : name.contains("dress") ? "\"dress_pack\""
                    : name.contains("wobble") ? "\"bearing_wobbles\"" : name.contains("slips") ? "\"tool_bump\"" : name.contains("stiffening")
                    ? "\"hardening_deg\"" : "held by gravity";
            assertTrue(json.contains(key), name + ": " + key);
            // not gross: no true point more than 1 mm from its twin's
            Scenario.Trial twin = Scenario.named(name).twin(1);
            double worst = 0;
            for (int i = 0; i < t.campaign().rows().size(); i++)
                worst = Math.max(worst, Rigid.norm(Rigid.minus(t.campaign().rows().get(i).truePoint(), twin.campaign().rows().get(i).truePoint())));
            assertTrue(worst < 1e-3 && worst > 2e-5, name + ": largest shift " + worst);
        }
        assertEquals(3, Scenario.named(NAMES.get(6)).trial(2).campaign().rows().stream().filter(Campaign.Row::outlier).count());
        // the slip in the sparse campaign leaves a fifth of its 120 poses or more on either side
        for (long seed = 1; seed <= 5; seed++) {
            Scenario.Trial k = Scenario.named("outside: measured target slips mid-campaign, 60 poses").trial(seed);
            double at = k.world().toolBump().atS();
            long before = k.campaign().rows().stream().filter(r -> r.timeS() < at).count();
            assertTrue(before > 0.2 * 120 && before < 0.8 * 120, "slip at " + at + " s: " + before + " poses before it");
        }
        // the rocking base does rock, at some poses and not at others
        Scenario.Trial rk = Scenario.named(NAMES.get(3)).trial(1);
        long rocked = 0;
        for (Campaign.Row r : rk.campaign().rows()) {
            double[] m = rk.world().overturningMoments(rk.world().arm(), WorldRobot.times(rk.world().coupling(), r.q()), r.payloadKg());
            if (Arrays.stream(m).max().getAsDouble() > rk.world().rocking().holdMomentNm()) rocked++;
        }
        assertTrue(rocked > 30 && rocked < 270, "poses rocked: " + rocked);
        assertNotEquals(Scenario.named(NAMES.get(0)).trial(1).campaign().text(), Scenario.named(NAMES.get(0)).twin(1).campaign().text());
    }
}
