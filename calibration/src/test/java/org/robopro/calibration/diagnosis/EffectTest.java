package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.JointEffect;
import org.robopro.calibration.PoseConditions;
import org.robopro.calibration.identification.EffectBlock;
import org.robopro.calibration.identification.IdentificationProblem;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.simulation.TrueRobot;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.EffectDescription;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
import org.robopro.models.Vec3;

class EffectTest {
    /**
     * An effect on the measured point written to the robot file with values (i + 1)·scale and read
     * back: the same label and size, the same values, and the same columns at one pose (within tol).
     */
    static void assertRoundTrips(Effect e, double scale, KinematicModel model, GravityTorques g, PoseConditions cond, double tol) {
        double[] v = new double[e.size()];
        for (int i = 0; i < v.length; i++) v[i] = (i + 1) * scale;
        Effect.Term back = Effect.fromDescription(e.describe(v), model, g, "x.robot.json");
        assertEquals(e.label(), back.effect().label());
        assertEquals(e.size(), back.effect().size());
        double[] q = {0.3, 0.4, -0.2, 0.1, 0.5, 0.2}, p = {1.2, 0.3, 0.9}, a = new double[3 * e.size()], b = new double[3 * e.size()];
        e.positionRegressor(q, cond, p, a);
        back.effect().positionRegressor(q, cond, p, b);
        for (int i = 0; i < a.length; i++) assertEquals(a[i], b[i], tol, e.label() + " column " + i);
        for (int i = 0; i < v.length; i++) assertEquals(v[i], back.values()[i], 0, e.parameterNames().get(i));
    }

    private final RobotDescription robot = RobotLibrary.shipped("irb2000");
    private final KinematicModel model = KinematicModel.build(robot);
    private final GravityTorques g = new GravityTorques(model, robot.massModel().orElseThrow());

    private List<Effect.Term> terms() {
        return List.of(new Effect.Term(Effect.compliance(1, g), new double[] {8e-7}),
                new Effect.Term(Effect.periodic(2), new double[] {1e-4, -5e-5, 3e-5, 7e-5, -2e-5, 4e-5}),
                new Effect.Term(Effect.backlash(0), new double[] {6e-4}),
                new Effect.Term(Effect.thermal(20), new double[] {17e-6}),
                new Effect.Term(Effect.scale(3), new double[] {2e-4}),
                new Effect.Term(Effect.coupling(2, 1), new double[] {-6e-4}));
    }

    private List<Measurement> rows(TrueRobot truth, int n, long seed) {
        Random r = new Random(seed);
        List<Measurement> out = new ArrayList<>();
        double[][] qs = model.randomConfigurations(n, seed);
        for (int i = 0; i < n; i++) {
            int[] dir = new int[6];
            for (int j = 0; j < 6; j++) dir[j] = r.nextBoolean() ? 1 : -1;
            PoseConditions c = new PoseConditions(dir, 20.0 * i, 20 + 12 * r.nextDouble(), 10 * r.nextDouble());
            Vec3 p = truth.point(qs[i], c);
            out.add(new Measurement("p" + i, qs[i], p, null, dir, c.timeS(), c.tempC(), c.payloadKg(), null, 0));
        }
        return out;
    }

    /**
     * A payload's compliance in steps: before the first step its first coefficient times the payload's
     * own torque (the whole torque less the arm's, worked out here from the masses at that pose), between
     * the steps the second, after them the last; the arm's own weight no part of it; the robot file keeps
     * it.
     */
    @Test
    void payloadComplianceInStepsTakesThePayloadsTorqueByInterval() {
        Effect e = Effect.complianceInSteps(2, g, new double[] {1000, 2000});
        assertEquals(3, e.size());
        double[] q = {0.3, 0.4, -0.2, 0.1, 0.5, 0.2};
        double payloadTorque = g.driveTorques(q, 10)[2] - g.driveTorques(q, 0)[2];
        assertTrue(Math.abs(payloadTorque) > 1, "the payload loads joint 3 here: " + payloadTorque);
        double[] times = {0, 999, 1000, 1500, 2000, 3000}, g1 = new double[3];
        int[] interval = {0, 0, 1, 1, 2, 2};
        for (int k = 0; k < times.length; k++) {
            e.regressor(q, new PoseConditions(null, times[k], Double.NaN, 10), g1);
            for (int i = 0; i < 3; i++) assertEquals(i == interval[k] ? payloadTorque : 0, g1[i], 1e-9, "t " + times[k] + " column " + i);
        }
        e.regressor(q, new PoseConditions(null, 1500, Double.NaN, 0), g1);
        assertArrayEquals(new double[3], g1, 1e-12);
        double[] v = {1e-7, 2e-7, 3e-7};
        Effect.Term back = Effect.fromDescription(e.describe(v), model, g, "x.robot.json");
        assertEquals(e.label(), back.effect().label());
        assertArrayEquals(v, back.values(), 0);
        double[] g2 = new double[3];
        for (double t : times) {
            var c = new PoseConditions(null, t, Double.NaN, 10);
            e.regressor(q, c, g1);
            back.effect().regressor(q, c, g2);
            assertArrayEquals(g1, g2, 1e-15, "t " + t);
        }
        // with the payload's centre estimated: four columns an interval, the first the file's centre, and the file keeps it
        Effect free = Effect.withPayloadCentreFree(e);
        assertEquals(12, free.size());
        double[] g4 = new double[12], t4 = new double[4];
        g.payloadDriveTorques(q, 10, 2, t4);
        free.regressor(q, new PoseConditions(null, 1500, Double.NaN, 10), g4);
        for (int i = 0; i < 12; i++) assertEquals(i / 4 == 1 ? t4[i % 4] : 0, g4[i], 1e-12, "column " + i);
        double[] v4 = new double[12];
        for (int i = 0; i < 12; i++) v4[i] = (i + 1) * 1e-8;
        Effect.Term back4 = Effect.fromDescription(free.describe(v4), model, g, "x.robot.json");
        assertEquals(free.label(), back4.effect().label());
        assertArrayEquals(v4, back4.values(), 0);
    }

    @Test
    void block_simulatedTruthWithSameValues_zeroResidual() {
        Pose tool = Pose.translation(0.01, -0.02, 0.1);
        Pose inst = Pose.translation(2, 1, 0.3).times(Pose.rotZ(0.7));
        List<JointEffect> truthEffects = new ArrayList<>();
        List<EffectBlock> blocks = new ArrayList<>();
        for (Effect.Term t : terms()) { truthEffects.add(t.effect().truth(t.values())); blocks.add(t.effect().block(model)); }
        TrueRobot truth = new TrueRobot(model, tool, inst, 0, 0, truthEffects);
        List<Measurement> rows = rows(truth, 12, 5);
        double[] start = IdentificationProblem.startVector(model, tool, false, inst, blocks);
        int off = start.length;
        for (Effect.Term t : terms()) off -= t.values().length;
        for (Effect.Term t : terms()) for (double v : t.values()) start[off++] = v;
        IdentificationProblem p = new IdentificationProblem(model, rows, false, true, blocks, start);
        p.setSigmas(1, 1);
        double[] r = new double[p.residualCount()];
        p.evaluateFull(start, r, null);
        for (double v : r) assertEquals(0, v, 1e-9);
        // and the effects matter: without them the residual is far from zero
        double[] zero = start.clone();
        for (int i = p.effectOffset(0); i < zero.length; i++) zero[i] = 0;
        p.evaluateFull(zero, r, null);
        double max = 0;
        for (double v : r) max = Math.max(max, Math.abs(v));
        assertEquals(true, max > 1e-4, "effects change the prediction by " + max);
    }

    @Test
    void block_effectColumns_matchCentralDifferences() {
        Pose tool = Pose.translation(0.0, 0.0, 0.1);
        Pose inst = Pose.translation(2, 1, 0.3).times(Pose.rotZ(0.7));
        List<EffectBlock> blocks = new ArrayList<>();
        for (Effect.Term t : terms()) blocks.add(t.effect().block(model));
        TrueRobot truth = new TrueRobot(model, tool, inst, 0, 0, List.of());
        List<Measurement> rows = rows(truth, 6, 9);
        double[] x = IdentificationProblem.startVector(model, tool, false, inst, blocks);
        int e0 = x.length;
        for (Effect.Term t : terms()) e0 -= t.values().length;
        int k = e0;
        for (Effect.Term t : terms()) for (double v : t.values()) x[k++] = v;
        assertColumnsMatchCentralDifferences(rows, blocks, x, e0, 1e-6, "");
    }

    /**
     * Asserts that the analytic Jacobian columns e0.. of the problem at x match central differences
     * within tol·(1 + |fd|); returns the largest |fd| seen (how much those parameters move the prediction).
     */
    private double assertColumnsMatchCentralDifferences(List<Measurement> rows, List<EffectBlock> blocks, double[] x, int e0,
                                                        double tol, String label) {
        return assertColumnsMatchCentralDifferences(rows, false, blocks, x, e0, tol, label);
    }

    /** As above, with the orientation rows too when {@code sixD} (the rows then carry orientations). */
    private double assertColumnsMatchCentralDifferences(List<Measurement> rows, boolean sixD, List<EffectBlock> blocks, double[] x, int e0,
                                                        double tol, String label) {
        IdentificationProblem p = new IdentificationProblem(model, rows, sixD, true, blocks, x);
        p.setSigmas(1, 1);
        int m = p.residualCount(), n = p.fullSize();
        double[] jac = new double[m * n], r = new double[m], rp = new double[m], rm = new double[m];
        p.evaluateFull(x, r, jac);
        double moved = 0;
        for (int c = e0; c < n; c++) {
            double h = 1e-3 * Math.max(Math.abs(x[c]), 1e-6);
            double[] xp = x.clone(), xm = x.clone();
            xp[c] += h;
            xm[c] -= h;
            p.evaluateFull(xp, rp, null);
            p.evaluateFull(xm, rm, null);
            for (int i = 0; i < m; i++) {
                double fd = (rp[i] - rm[i]) / (2 * h);
                moved = Math.max(moved, Math.abs(fd));
                assertEquals(fd, jac[i * n + c], tol * (1 + Math.abs(fd)), label + p.names().get(c) + " row " + i);
            }
        }
        return moved;
    }

    /** The fallbacks of located structures (no physical family), with values of their size. */
    /** n mass scales of 1 but mass k's, {@code f}. */
    private static double[] scaled(int n, int k, double f) {
        double[] s = new double[n];
        Arrays.fill(s, 1);
        s[k] = f;
        return s;
    }

    private List<Effect.Term> fallbacks() {
        double[] s13 = new double[13];
        for (int i = 0; i < s13.length; i++) s13[i] = 1e-4 * Math.sin(i);
        double[] p12 = new double[12];
        for (int i = 0; i < p12.length; i++) p12[i] = 1e-5 * Math.cos(i);
        return List.of(new Effect.Term(Effect.smooth(2, -0.9, 0.9, 13), s13),
                new Effect.Term(Effect.pair(1, 3), new double[] {2e-4, -1e-4, 5e-5, 3e-5, 4e-5, -6e-5, 2e-5, -3e-5, 1e-5, 7e-5, -4e-5}),
                new Effect.Term(Effect.pointSmooth(Effect.Along.REACH, 0.3, 1.8), p12),
                new Effect.Term(Effect.pointSmooth(Effect.Along.TIME, 0, 4000), p12),
                new Effect.Term(Effect.pointSmooth(Effect.Along.PAYLOAD_REACH, 0.3, 1.8), p12),
                new Effect.Term(Effect.zeroDrift(2, Effect.Along.TEMPERATURE, 20, 32), new double[] {1e-4, -2e-4, 3e-4, 1e-4}),
                new Effect.Term(Effect.zeroStep(1, 1500), new double[] {3e-4}),
                new Effect.Term(Effect.axialRunout(model, 0, new int[] {2, 3}), new double[] {5e-5, -3e-5, 2e-5, 4e-5}),
                new Effect.Term(Effect.toolPlay(model, Effect.DOWN, false), new double[] {1e-4, -5e-5, 3e-5, 8e-5, -2e-5, 1e-5}),
                new Effect.Term(Effect.toolPull(model, new Vec3(0, 0, 0.1), new double[] {1.8, -1.2, 2.1}),
                        new double[] {1e-4, 2e-4, 1.5e-4, 2e-3, 1e-3, 3e-3}),
                new Effect.Term(Effect.loadTilt(model, 1, g, 400, scaled(g.massCount(), 1, 1.2)),
                        new double[] {2e-4, -1e-4, 5e-5, 1.5e-4, 3e-5, -2e-5, 1e-5, 4e-5}),
                new Effect.Term(Effect.secondStation(model, new Vec3(0.3, 0.8, 0.1)), new double[] {5e-5, -3e-5, 2e-5, 8e-5, -6e-5, 4e-5}),
                new Effect.Term(Effect.secondStation(model, new Vec3(2.5, 0.4, 1.2), new Vec3(-0.2, 2.6, 0.5), new Vec3(0, 0, 0.1)),
                        new double[] {5e-5, -3e-5, 2e-5, 8e-5, -6e-5, 4e-5}));
    }

    /**
     * A rigid motion of the measured points (a base step before its time, a second station's poses):
     * its turn columns against a point turned by a small angle about each base axis (Rodrigues'
     * rotation, not the cross product the columns are written with), its shifts the unit moves; every
     * column moves the point by minus that (the instrument's pose holds the state after).
     */
    @Test
    void rigidMotionColumns_turnThePointAboutEachAxis() {
        double[] p = {0.7, -1.3, 0.45};
        double[] g3 = new double[18];
        Effect.baseStepRegressor(p, g3, null);
        double eps = 1e-7;
        for (int c = 0; c < 3; c++) {
            double[] axis = new double[3];
            axis[c] = 1;
            Pose turn = Pose.rotAxis(new Vec3(axis[0], axis[1], axis[2]), eps);
            Vec3 moved = turn.apply(new Vec3(p[0], p[1], p[2]));
            double[] d = {(moved.x() - p[0]) / eps, (moved.y() - p[1]) / eps, (moved.z() - p[2]) / eps};
            for (int a = 0; a < 3; a++) {
                assertEquals(-d[a], g3[a * 6 + 3 + c], 1e-6, "turn about axis " + c + ", row " + a);
                assertEquals(a == c ? -1 : 0, g3[a * 6 + c], 0, "shift along axis " + c + ", row " + a);
            }
        }
    }

    /**
     * A joint's own give on a parallel arm (IRB 2000, θ3 = q3 − q2), checked against rigid-body
     * motion and the potential energy, not the model's Jacobian: the torque about joint 2's axis is
     * −∂V/∂θ2 (virtual work) by central differences of the arm's potential energy, and joint 2's own
     * angle giving by φ = c·τ turns the whole arm beyond it about that axis, the forearm with it, so
     * the flange moves as the rotation by φ about joint 2's axis line (Rodrigues). The drive's form
     * moves drive 2 alone, which the parallel rod keeps from turning the forearm: not that rotation.
     */
    @Test
    void complianceAtTheJoint_turnsTheWholeArmBeyondItAboutItsAxis() {
        RobotDescription r2000 = RobotLibrary.shipped("irb2000");
        KinematicModel m = KinematicModel.build(r2000);
        GravityTorques g = new GravityTorques(m, r2000.massModel().orElseThrow());
        assertTrue(Effect.atJointDiffers(m, 1), "joint 2 of a parallel arm");
        assertTrue(!Effect.atJointDiffers(m, 2), "joint 3's own angle is drive 3's");
        Effect atJoint = Effect.complianceAtJoint(1, g, false), drive = Effect.compliance(1, g);
        double c = 4e-6, payload = 6, h = 1e-6;
        PoseConditions cond = new PoseConditions(null, Double.NaN, Double.NaN, payload);
        for (double[] q : m.randomConfigurations(5, 17)) {
            double[] th = m.theta(q), up = th.clone(), dn = th.clone();
            up[1] += h;
            dn[1] -= h;
            double tau = -(g.potentialEnergy(m.q(up), payload) - g.potentialEnergy(m.q(dn), payload)) / (2 * h);
            double phi = atJoint.value(new double[] {c}, q, cond);
            assertEquals(c * tau, phi, 1e-6 * Math.abs(c * tau) + 1e-15, "c times the torque about joint 2's own axis");
            Pose axis = m.linkFrames(q)[2];
            Pose turn = Pose.rotAxis(axis.zAxis(), phi);
            Vec3 p = m.flange(q).position(), o = axis.position();
            Vec3 expected = o.plus(turn.apply(p.minus(o)));
            double[] given = q.clone();
            atJoint.addToDrives(phi, given);
            Vec3 moved = m.flange(given).position();
            assertEquals(0, moved.minus(expected).norm(), 1e-12, "the flange turned about joint 2's axis");
            double[] byDrive = q.clone();
            drive.addToDrives(phi, byDrive);
            assertTrue(m.flange(byDrive).position().minus(expected).norm() > 0.1 * p.minus(o).norm() * Math.abs(phi),
                    "drive 2 alone leaves the forearm's angle to the ground");
        }
        // the robot file keeps which form it is
        Effect back = Effect.fromDescription(atJoint.describe(new double[] {c}), m, g, "x.robot.json").effect();
        assertTrue(back.atJoint());
        assertEquals(atJoint.label(), back.label());
    }

    /**
     * The instrument's axes out of square, seen in the base's frame: a shear of the instrument's x
     * and y moves a point on its x axis along its y axis by the shear times its x (turned into the
     * base's axes by the registration), and a bowed x-way moves it along y by the bow times x²; the
     * robot file keeps the bowed form.
     */
    @Test
    void instrumentAxes_shearAndBowInTheInstrumentsFrame_andBackFromTheRobotFile() {
        Pose inst = Pose.translation(-2.5, 0.4, -0.3).times(Pose.rotAxis(new Vec3(0, 0, 1), 0.7));
        Effect bowed = Effect.instrumentAxesBowed(inst);
        assertEquals(11, bowed.size());
        double xi = 1.8;
        Vec3 pb = inst.inverse().apply(new Vec3(xi, 0, 0)); // on the instrument's x axis
        double[] g3 = new double[3 * 11];
        bowed.positionRegressor(null, new PoseConditions(null, Double.NaN, Double.NaN, Double.NaN), pb.toArray(), g3);
        Vec3 yBase = inst.inverse().apply(new Vec3(0, 1, 0)).minus(inst.inverse().apply(Vec3.ZERO));
        for (int a = 0; a < 3; a++) {
            double ya = a == 0 ? yBase.x() : a == 1 ? yBase.y() : yBase.z();
            assertEquals(xi * ya, g3[a * 11 + 2], 1e-12, "square_xy, axis " + a);
            assertEquals(xi * xi * ya, g3[a * 11 + 5], 1e-12, "bow_x_y, axis " + a);
            assertEquals(0, g3[a * 11 + 1], 1e-12, "scale_y: nothing on the x axis");
        }
        double[] v = new double[11];
        v[5] = 2e-5;
        Effect back = Effect.fromDescription(bowed.describe(v), KinematicModel.build(RobotLibrary.shipped("irb2000")), null, "x.robot.json").effect();
        assertEquals(bowed.label(), back.label());
        assertTrue(back.bowed());
    }

    /**
     * A pull on the tool, checked against the forward kinematics alone (not the model's Jacobian): each
     * drive's torque is the work the pull does through that drive's turn, F·∂p/∂q_j by central
     * differences of the attach point (virtual work), and the measured point's move is the forward
     * kinematics at q + Δq, Δq_j = c_j τ_j, less that at q; the pull toward the anchor turns the measured
     * frame about the yielding joints' axes by as much.
     */
    @Test
    void toolPull_isTheJointsYieldingToTheWorkOfTheForce() {
        RobotDescription r2400 = RobotLibrary.shipped("irb2400");
        KinematicModel m = KinematicModel.build(r2400);
        Vec3 attach = new Vec3(0.02, -0.01, 0.15);
        double[] anchor = {1.8, -1.2, 2.1}, q = {0.3, 0.4, -0.2, 0.6, 0.7, -0.4}, c = {2e-6, 3e-6, 4e-6, 3e-5, 2e-5, 4e-5};
        double f = 40;
        Effect pull = Effect.toolPull(m, attach, anchor);
        assertEquals(6, pull.size());
        Vec3 a = m.flange(q).apply(attach);
        Vec3 dir = new Vec3(anchor[0] - a.x(), anchor[1] - a.y(), anchor[2] - a.z());
        dir = dir.times(1 / dir.norm());
        double[] v = new double[6], dq = new double[6];
        for (int j = 0; j < 6; j++) {
            double h = 1e-6;
            double[] up = q.clone(), dn = q.clone();
            up[j] += h;
            dn[j] -= h;
            Vec3 dp = m.flange(up).apply(attach).minus(m.flange(dn).apply(attach)).times(0.5 / h);
            double tau = f * dir.dot(dp);
            v[j] = c[j] * f;
            dq[j] = c[j] * tau;
        }
        assertArrayEquals(dq, pull.pullDeflections(q, v), 1e-12);
        double[] q2 = q.clone();
        for (int j = 0; j < 6; j++) q2[j] += dq[j];
        Vec3 point = new Vec3(0.0, 0.05, 0.2), p0 = m.flange(q).apply(point), p1 = m.flange(q2).apply(point);
        double[] g3 = new double[18];
        pull.positionRegressor(q, PoseConditions.NONE, p0.toArray(), g3);
        for (int r = 0; r < 3; r++) {
            double moved = 0;
            for (int col = 0; col < 6; col++) moved += g3[r * 6 + col] * v[col];
            assertEquals(p1.toArray()[r] - p0.toArray()[r], moved, 1e-3 * p1.minus(p0).norm(), "axis " + r);
        }
        assertTrue(p1.minus(p0).norm() > 1e-5, "the pull moves the point: " + p1.minus(p0).norm());
        // a robot file holds the pull and reads it back
        Effect.Term back = Effect.fromDescription(pull.describe(v), m, null, "test");
        assertEquals(pull.label(), back.effect().label());
        assertArrayEquals(v, back.values(), 0);
        assertArrayEquals(pull.pullDeflections(q, v), back.effect().pullDeflections(q, v), 1e-15);
    }

    /**
     * A tool play with the flange's tips, measured in 6-D: it reads back with its tips, and its
     * columns (the point's shifts and the frame's turns) match central differences; the tips turn
     * the frame and do not move the point.
     */
    @Test
    void toolPlayWithTips_6d_roundTripsAndColumnsMatchCentralDifferences() {
        Pose tool = Pose.translation(0.0, 0.0, 0.1);
        Pose inst = Pose.translation(2, 1, 0.3).times(Pose.rotZ(0.7));
        List<Measurement> rows = new ArrayList<>();
        // each measured frame as the geometry predicts it
        for (Measurement m : rows(new TrueRobot(model, tool, inst, 0, 0, List.of()), 8, 13))
            rows.add(m.withOrientation(inst.times(model.flange(m.q())).times(tool).quaternion()));
        Effect play = Effect.toolPlay(model, Effect.DOWN, true);
        double[] v = {1e-4, -5e-5, 3e-5, 8e-5, -2e-5, 1e-5, 4e-4, -1e-3, 9e-4, -3e-4};
        assertEquals(v.length, play.size());
        assertEquals(true, play.turnsFrame());
        Effect.Term back = Effect.fromDescription(play.describe(v), model, g, "test");
        assertEquals(play.size(), back.effect().size());
        assertEquals(true, back.effect().turnsFrame());
        assertArrayEquals(v, back.values(), 0);
        // the orientation residual's columns are first order in the turn left: compared where the tips are zero
        Arrays.fill(v, Effect.PLAY_SHIFTS, v.length, 0);
        List<EffectBlock> blocks = List.of(play.block(model));
        double[] x = IdentificationProblem.startVector(model, tool, true, inst, blocks);
        int e0 = x.length - v.length;
        System.arraycopy(v, 0, x, e0, v.length);
        assertEquals(true, assertColumnsMatchCentralDifferences(rows, true, blocks, x, e0, 1e-6, "tool-play tips ") > 0);
        double[] q = rows.get(0).q(), gp = new double[3 * v.length], gr = new double[3 * v.length];
        play.positionRegressor(q, PoseConditions.of(rows.get(0)), new double[] {1, 0, 1}, gp);
        play.rotationRegressor(q, PoseConditions.of(rows.get(0)), gr);
        for (int a = 0; a < 3; a++)
            for (int c = 0; c < v.length; c++) {
                if (c >= Effect.PLAY_SHIFTS) assertEquals(0, gp[a * v.length + c], 0, "a tip moves no point, column " + c);
                else assertEquals(0, gr[a * v.length + c], 0, "a shift turns no frame, column " + c);
            }
    }

    @Test
    void fallbacks_roundTripAndColumnsMatchCentralDifferences() {
        Pose tool = Pose.translation(0.0, 0.0, 0.1);
        Pose inst = Pose.translation(2, 1, 0.3).times(Pose.rotZ(0.7));
        List<Measurement> rows = rows(new TrueRobot(model, tool, inst, 0, 0, List.of()), 8, 11);
        for (Effect.Term t : fallbacks()) {
            assertEquals(true, t.effect().isFallback(), t.effect().label());
            Effect.Term back = Effect.fromDescription(t.effect().describe(t.values()), model, g, "test");
            assertEquals(t.effect().label(), back.effect().label());
            assertArrayEquals(t.values(), back.values(), 0);
            List<EffectBlock> blocks = List.of(t.effect().block(model));
            double[] x = IdentificationProblem.startVector(model, tool, false, inst, blocks);
            int e0 = x.length - t.values().length;
            System.arraycopy(t.values(), 0, x, e0, t.values().length);
            // a point displacement with reach also moves with the point the geometry predicts: a loose tolerance there
            double tol = t.effect().kind() == Effect.Kind.POINT_SMOOTH ? 1e-3 : 1e-6;
            double moved = assertColumnsMatchCentralDifferences(rows, blocks, x, e0, tol, t.effect().label() + " ");
            assertEquals(true, moved > 0, t.effect().label() + " moves the prediction");
        }
    }

    @Test
    void zeroStep_beforeTheJumpTheZeroWasLower_afterItAndAtAnUnknownTimeNothing() {
        Effect e = Effect.zeroStep(1, 1500);
        double[] q = new double[6];
        assertEquals(-3e-4, e.value(new double[] {3e-4}, q, new PoseConditions(null, 1000, Double.NaN, Double.NaN)), 0);
        assertEquals(0, e.value(new double[] {3e-4}, q, new PoseConditions(null, 2000, Double.NaN, Double.NaN)), 0);
        assertEquals(0, e.value(new double[] {3e-4}, q, new PoseConditions(null, Double.NaN, Double.NaN, Double.NaN)), 0);
    }

    @Test
    void describe_roundTrip_sameEffectAndValues() {
        for (Effect.Term t : terms()) {
            EffectDescription d = t.effect().describe(t.values());
            Effect.Term back = Effect.fromDescription(d, model, g, "test");
            assertEquals(t.effect().label(), back.effect().label());
            assertArrayEquals(t.values(), back.values(), 0);
        }
    }

    /**
     * Physics, not this code: a driven output lags its motor-side encoder. After a motion in
     * direction +1 the output stands b/2 behind q, after −1 b/2 ahead (dead-band model). The error
     * is the drive's, before the coupling θ = C q (the IRB-2000's parallel arm passes joint 2's
     * error on to θ3): truth and block must both move θ by C·(−(b/2)·dir·e_2).
     */
    @Test
    void backlash_outputLagsTheEncoder() {
        double b = Math.toRadians(0.04);
        JointEffect truth = Effect.backlash(1).truth(new double[] {b});
        double[] q = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6};
        for (int dir : new int[] {1, -1, 0}) {
            PoseConditions c = new PoseConditions(new int[] {0, dir, 0, 0, 0, 0}, 0, 20, 0);
            double[] dTheta = new double[6];
            truth.addDeltaTheta(model, q, c, dTheta);
            double[][] cm = model.couplingMatrix();
            for (int i = 0; i < 6; i++) assertEquals(cm[i][1] * -0.5 * b * dir, dTheta[i], 1e-15, "dir " + dir + " theta " + (i + 1));
            double[] dv = new double[6];
            double[] dt = new double[6];
            Measurement row = new Measurement("p", q, Vec3.ZERO, null, c.directions(), 0, 20, 0, null, 0);
            Effect.backlash(1).block(model).jointDelta(new double[] {b}, row, dt, dv);
            for (int i = 0; i < 6; i++) {
                assertEquals(cm[i][1] * -0.5 * b * dir, dt[i], 1e-15);
                assertEquals(cm[i][1] * -0.5 * dir, dv[i], 1e-15, "derivative of theta " + (i + 1) + " by b");
            }
        }
        // The extended model's tool point is the geometry's at the lagging angle, computed here by hand.
        ExtendedModel ext = new ExtendedModel(model, List.of(new Effect.Term(Effect.backlash(1), new double[] {b})));
        PoseConditions up = new PoseConditions(new int[] {1, 1, 1, 1, 1, 1}, 0, 20, 0);
        double[] lag = q.clone();
        lag[1] -= b / 2;
        assertEquals(0, ext.flange(q, up).distanceTo(model.flange(lag)), 1e-12);
    }
}
