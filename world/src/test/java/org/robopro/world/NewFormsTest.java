package org.robopro.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;

/** The differently formed truths: each checked against its physics by hand, and the campaigns they need. */
class NewFormsTest {
    static final RobotDescription IRB2000 = RobotLibrary.shipped("irb2000");
    static final int[] UP = {1, 1, 1, 1, 1, 1};

    static double[] deg(double... d) { return Arrays.stream(d).map(Math::toRadians).toArray(); }

    static JointError.Moment at(int[] dir, double[] lastMove, double t, double temp) { return new JointError.Moment(dir, lastMove, t, temp); }

    /**
     * An encoder whose sine channel reads 1 + g of the cosine's: the controller's q satisfies
     * tan q = (1 + g) tan θ, so at q = 0° and 90° the output is where it is read, and at 45° it lags the
     * reading by about (g/2)·sin 90°; at the matching temperature nothing.
     */
    /**
     * Joint 5's drive through a seat 40 µm out of round in joint 4's housing, a 25 mm pitch radius at 20°:
     * with the housing at the bore's long axis the mesh is 40 µm deeper and the output turns by
     * 40 µm·tan 20°/25 mm; a quarter turn of the housing later (the short axis) as much the other way;
     * an eighth of a turn off, nothing; joint 5's own angle does not change it.
     */
    /**
     * A shaft tilting under its mesh's forces turns everything beyond about a line across the joint's
     * axis through the bearing's centre (that centre stays put), by κ·√(τ² + (|τ| tan α)²); the tooth
     * force's part changes side with the torque's sign, the separating force's does not; no torque, no turn.
     */
    @Test
    void shaftTilt_turnsAboutTheBearingsCentre_byTheMeshForces() {
        double[] axis = {0, 1, 0}, point = {0.1, 0, 0.7};
        var t = new WorldRobot.ShaftTilt(1, 3e-6, Math.toRadians(20), 0.4, 0.03);
        double[] centre = Rigid.plus(point, Rigid.scale(axis, 0.03));
        for (double tau : new double[] {80, -80}) {
            Rigid r = t.tilt(axis, point, tau);
            assertEquals(0, Rigid.norm(Rigid.minus(r.apply(centre), centre)), 1e-15);
            // a point 0.5 m out along x moves by the turn times its lever, across it
            double[] far = {0.6, 0.03, 0.7};
            double moved = Rigid.norm(Rigid.minus(r.apply(far), far));
            double angle = 3e-6 * Math.hypot(80, 80 * Math.tan(Math.toRadians(20)));
            assertTrue(moved <= 0.5 * angle * (1 + 1e-9) && moved > 0, "moved " + moved);
            // the turn's axis lies across the joint's axis
            double[] w = {r.r()[7] - r.r()[5], r.r()[2] - r.r()[6], r.r()[3] - r.r()[1]};
            assertEquals(0, Rigid.dot(w, axis), 1e-12);
            assertEquals(2 * Math.sin(angle), Rigid.norm(w), 1e-12);
        }
        // the tooth force's part changes side with the torque, the separating force's does not
        Rigid up = t.tilt(axis, point, 80), down = t.tilt(axis, point, -80);
        double[] wu = {up.r()[7] - up.r()[5], up.r()[2] - up.r()[6], up.r()[3] - up.r()[1]};
        double[] wd = {down.r()[7] - down.r()[5], down.r()[2] - down.r()[6], down.r()[3] - down.r()[1]};
        double[] sum = Rigid.plus(wu, wd), diff = Rigid.minus(wu, wd);
        assertEquals(Math.tan(Math.toRadians(20)), Rigid.norm(sum) / Rigid.norm(diff), 1e-6);
        assertEquals(0, Rigid.norm(Rigid.minus(t.tilt(axis, point, 0).apply(new double[] {1, 2, 3}), new double[] {1, 2, 3})), 0);
    }

    /**
     * A cable retractor's pull loads each joint by the work it does through the joint's turn
     * (virtual work: τ_i = F·∂p/∂θ_i, here by finite differences of the arm's own chain, not by the
     * moment the retractor computes), and the arm yields toward the anchor: the target moves with the
     * force (F·Δp > 0), by about Σ τ_i² / k_i / |F| along it.
     */
    @Test
    void retractorLoadsEachJointByTheWorkOfItsPull_andTheArmYieldsTowardIt() {
        // the PUMA 560: no linkage between drives and joints, so q = θ
        WorldRobot w = WorldRobot.nominal(org.robopro.models.RobotLibrary.shipped("puma560"), new double[] {0, 0, 0.15});
        Arm a = w.arm();
        double[] theta = {0.4, -0.3, 0.5, 0.7, 0.8, -0.2}, anchor = {1.5, -1.4, 1.8};
        var x = new WorldRobot.Retractor(anchor, 40, new double[] {4e5, 3e5, 2e5, 3e4, 3e4, 3e4});
        double[] at = a.flange(theta).apply(new double[] {0, 0, 0.15});
        double[] d = Rigid.minus(anchor, at), f = Rigid.scale(d, 40 / Rigid.norm(d));
        double[] tau = x.torques(a, a.bodies(theta), at);
        for (int i = 0; i < 6; i++) {
            double h = 1e-7;
            double[] up = theta.clone(), dn = theta.clone();
            up[i] += h;
            dn[i] -= h;
            double[] dp = Rigid.scale(Rigid.minus(a.flange(up).apply(new double[] {0, 0, 0.15}), a.flange(dn).apply(new double[] {0, 0, 0.15})), 0.5 / h);
            assertEquals(Rigid.dot(f, dp), tau[i], 1e-6 * 40, "joint " + (i + 1));
        }
        double[] q = theta;
        double[] still = w.target(q, new int[6], 20, 0, 0).p(), pulled = w.withRetractor(x).target(q, new int[6], 20, 0, 0).p();
        double[] moved = Rigid.minus(pulled, still);
        double work = 0;
        for (int i = 0; i < 6; i++) work += tau[i] * tau[i] / x.stiffness()[i];
        assertTrue(Rigid.dot(moved, f) > 0, "the target moves toward the anchor");
        assertEquals(work / 40, Rigid.dot(moved, f) / 40, 0.02 * work / 40, "the pull's work");
    }

    @Test
    void ovalSeatTurnsTheDriveTwiceAPerTurnOfItsHousing() {
        double major = Math.toRadians(30), full = 40e-6 * Math.tan(Math.toRadians(20)) / 0.025;
        var e = new JointError.OvalSeat(4, 3, 40e-6, Math.toRadians(20), 0.025, major);
        var m = at(new int[6], null, 0, 20);
        assertEquals(full, e.delta(new double[] {0, 0, 0, major, 0.3, 0}, m), 1e-15);
        assertEquals(full, e.delta(new double[] {0, 0, 0, major + Math.PI, -1.1, 0}, m), 1e-15);
        assertEquals(-full, e.delta(new double[] {0, 0, 0, major + Math.PI / 2, 0.3, 0}, m), 1e-15);
        assertEquals(0, e.delta(new double[] {0, 0, 0, major + Math.PI / 4, 0.3, 0}, m), 1e-15);
    }

    @Test
    void encoderChannelsOutOfBalanceReadTwiceATurnWrong() {
        var e = new JointError.QuadratureGain(0, 1e-4, 20);
        double g = 1e-4 * (30 - 20);
        var warm = at(new int[6], null, 0, 30);
        for (double deg : new double[] {0, 90, 180, -90}) assertEquals(0, e.delta(new double[] {Math.toRadians(deg), 0, 0, 0, 0, 0}, warm), 1e-15);
        double q = Math.toRadians(45), theta = q + e.delta(new double[] {q, 0, 0, 0, 0, 0}, warm);
        assertEquals(Math.tan(q), (1 + g) * Math.tan(theta), 1e-12);
        assertEquals(-g / 2, theta - q, 1e-6);
        assertEquals(0, e.delta(new double[] {q, 0, 0, 0, 0, 0}, at(new int[6], null, 0, 20)), 1e-15);
    }

    @Test
    void unequalFlanks_lagFullyOneWayAndLessTheOther() {
        var e = new JointError.AsymmetricLostMotion(1, Math.toRadians(0.04), Math.toRadians(0.02));
        double[] q = deg(0, 10, 0, 0, 0, 0);
        assertEquals(-Math.toRadians(0.02), e.delta(q, UP), 1e-15);
        assertEquals(Math.toRadians(0.01), e.delta(q, new int[] {1, -1, 1, 1, 1, 1}), 1e-15);
    }

    @Test
    void windUp_growsWithTheMove_andSaturatesAtHalfThePlay() {
        double b = Math.toRadians(0.04), x0 = Math.toRadians(5);
        var e = new JointError.WindUpLostMotion(2, b, x0);
        double[] q = new double[6];
        double[] move = new double[6];
        move[2] = x0; // one build-up length: 1 - 1/e of the full lag
        assertEquals(-0.5 * b * (1 - Math.exp(-1)), e.delta(q, at(UP, move, 0, 20)), 1e-15);
        move[2] = -x0 / 10; // a short move down: a tenth-ish of the lag, on the other side
        assertEquals(0.5 * b * (1 - Math.exp(-0.1)), e.delta(q, at(new int[] {1, 1, -1, 1, 1, 1}, move, 0, 20)), 1e-15);
        assertEquals(-0.5 * b, e.delta(q, at(UP, null, 0, 20)), 1e-15, "long moves: plain lost motion");
    }

    @Test
    void slipCreepAndDriveThermal_followTimeAndTemperature() {
        double[] q = new double[6];
        var slip = new JointError.Slip(1, 1000, Math.toRadians(0.02));
        assertEquals(0, slip.delta(q, at(UP, null, 999, 20)));
        assertEquals(Math.toRadians(0.02), slip.delta(q, at(UP, null, 1000, 20)));
        var creep = new JointError.Creep(2, Math.toRadians(0.03) / 3600);
        assertEquals(Math.toRadians(0.03), creep.delta(q, at(UP, null, 3600, 20)), 1e-15);
        var th = new JointError.DriveThermal(1, Math.toRadians(0.003), 20);
        assertEquals(Math.toRadians(0.03), th.delta(q, at(UP, null, 0, 30)), 1e-15);
        assertEquals(0, th.delta(q, at(UP, null, 0, Double.NaN)));
    }

    @Test
    void bendingUnderPayload_cubicInReach_proportionalToPayload() {
        var sag = new WorldRobot.Sag(0, 1.5, 1e-5);
        assertEquals(1e-4, sag.at(1.5, 10), 1e-18);
        assertEquals(8e-4, sag.at(3.0, 10), 1e-15);
        assertEquals(0, sag.at(1.5, 0));
        WorldRobot w = WorldRobot.nominal(IRB2000, new double[] {0, 0, 0.1}).withSag(sag);
        double[] q = deg(0, 20, 10, 0, 30, 0);
        double dz = w.target(q, UP, Double.NaN, 0, 10).p()[2] - w.target(q, UP, Double.NaN, 0, 0).p()[2];
        assertTrue(dz < -1e-5 && dz > -1e-3, "dz " + dz);
    }

    @Test
    void knockedTarget_movesOnTheFlangeFromItsMomentOn() {
        var bump = new WorldRobot.ToolBump(100, new double[] {0.2e-3, 0, 0}, new double[3]);
        WorldRobot w = WorldRobot.nominal(IRB2000, new double[] {0, 0, 0.1}).withToolBump(bump);
        double[] q = deg(10, 20, 10, 0, 30, 40);
        double[] before = w.target(q, UP, 20, 99, 0).p(), after = w.target(q, UP, 20, 100, 0).p();
        assertEquals(0.2e-3, Rigid.norm(Rigid.minus(after, before)), 1e-12);
        // The shift is along the flange's x axis (the flange at the model angles theta = C q).
        Rigid flange = w.arm().flange(WorldRobot.times(w.coupling(), q));
        double[] x = flange.rotate(new double[] {1, 0, 0});
        assertEquals(0.2e-3, Rigid.dot(Rigid.minus(after, before), x), 1e-12);
    }

    @Test
    void campaignStartedElsewhere_firstDirectionsFollowTheUnknownStart_andLastMovesAreRecorded() {
        Scenario s = Scenario.named("lost motion j2, directions not recorded, started away from home");
        Campaign.Result c = s.trial(3).campaign();
        assertEquals("ELSEWHERE", c.plan().start().name());
        Campaign.Row first = c.rows().get(0);
        double[] home = Campaign.home(IRB2000);
        int differ = 0;
        for (int j = 0; j < 6; j++) if (first.dir()[j] != (first.q()[j] > home[j] ? 1 : -1)) differ++;
        assertTrue(differ > 0, "some first directions are not those of a move from home");
        assertNotEquals(c.text(), Scenario.named("lost motion j2, directions not recorded").trial(3).campaign().text());
        assertTrue(s.trial(3).truthJson().contains("\"start\" : \"elsewhere\""));
    }

    @Test
    void everyNewScenario_drawsAndMeasures() {
        for (String name : List.of("lost motion j2, unequal flanks (gravity preload)", "lost motion j3 building up over the move (friction wind-up)",
                "transmission error j1 and j3 at once, amplitudes 0.002-0.02 deg", "outside: encoder slip on j2 mid-campaign",
                "outside: j3 zero creeping with time", "outside: j2 zero moving with drive temperature", "outside: arm bends with payload and reach",
                "outside: measured target knocked mid-campaign", "outside: bump in the angle of j3, 6-D", "outside: bump in the angle of j3, 50 poses",
                "outside: j2 error depending on j2 and j4, 6-D", "outside: measured point sags with reach, 50 poses")) {
            Scenario.Trial t = Scenario.named(name).trial(1);
            assertTrue(t.campaign().rows().size() >= 100, name);
            assertTrue(t.truthJson().contains(name.replace("\"", "")), name);
        }
        // The mid-campaign events leave a fifth of the campaign or more on either side.
        for (long seed = 1; seed <= 5; seed++) {
            Scenario.Trial t = Scenario.named("outside: encoder slip on j2 mid-campaign").trial(seed);
            double at = ((JointError.Slip) t.world().errors().get(0)).atS();
            long before = t.campaign().rows().stream().filter(r -> r.timeS() < at).count();
            assertTrue(before > 0.2 * 300 && before < 0.8 * 300, "slip at " + at + " s: " + before + " poses before it");
            Scenario.Trial k = Scenario.named("outside: measured target knocked mid-campaign").trial(seed);
            double kat = k.world().toolBump().atS();
            long kb = k.campaign().rows().stream().filter(r -> r.timeS() < kat).count();
            assertTrue(kb > 0.2 * 300 && kb < 0.8 * 300, "knock at " + kat + " s: " + kb + " poses before it");
        }
    }

    /**
     * The measuring machine's readings, put back through its own axis chain written out here (the
     * scales along x̂, ŷ' and ẑ' tilted by the squareness angles, the x carriage's bow as a parabola),
     * reach the point read, and a machine without errors reads the point itself.
     */
    @Test
    void machineReadings_reachThePointThroughTheMachinesAxisChain() {
        WorldRobot.Machine m = new WorldRobot.Machine(150e-6, -90e-6, 120e-6, 60e-6, -40e-6, 50e-6, -60e-6, 2.1, 1.5);
        double[] p = {2.9, -0.7, 0.45};
        double[] r = m.read(p);
        double ny = Math.sqrt(150e-6 * 150e-6 + 1), nz = Math.sqrt(90e-6 * 90e-6 + 120e-6 * 120e-6 + 1);
        double xi = (r[0] - 2.1) / 1.5;
        double[] back = {
                (1 + 60e-6) * r[0] + (1 - 40e-6) * r[1] * (-150e-6 / ny) + r[2] * (90e-6 / nz),
                (1 - 40e-6) * r[1] / ny + r[2] * (-120e-6 / nz) + 50e-6 * xi * xi,
                r[2] / nz - 60e-6 * xi * xi};
        for (int a = 0; a < 3; a++) assertEquals(p[a], back[a], 1e-12, "axis " + a);
        double off = Math.sqrt(Math.pow(r[0] - p[0], 2) + Math.pow(r[1] - p[1], 2) + Math.pow(r[2] - p[2], 2));
        assertTrue(off > 1e-5, "the machine reads the point elsewhere: " + off + " m");
        double[] clean = new WorldRobot.Machine(0, 0, 0, 0, 0, 0, 0, 2.1, 1.5).read(p);
        for (int a = 0; a < 3; a++) assertEquals(p[a], clean[a], 1e-15);
    }
}
