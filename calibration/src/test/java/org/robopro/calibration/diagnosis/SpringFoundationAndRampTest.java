package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.function.ToDoubleFunction;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.WorldCampaigns;
import org.robopro.models.RobotLibrary;
import org.robopro.world.Scenario;

/**
 * Three forms against truth the diagnosis did not write (org.robopro.world, nothing shared with
 * {@link Effect}): a joint spring that stiffens with its load, the base giving way on its
 * foundation, and a gear-ratio error over a joint's short range, which a few harmonics of its
 * angle follow as closely as the ramp itself.
 */
class SpringFoundationAndRampTest {

    /**
     * The world's cubic-hardening spring on drive 2 (τ = k·dq·(1 + (dq/h)²), its tangent stiffness
     * 2-4 times k at the largest torques, masses off ±30 %) is a compliance that stiffens, not a
     * transmission error of joint 2: harmonics 1-3 of the angle had followed the deflection's
     * curve better than a linear spring.
     */
    @Test
    void stiffeningSpring_isNamedACompliance_thatStiffens() {
        WorldCampaigns.Sim c = WorldCampaigns.of(Scenario.named("joint elasticity j2 with a stiffening spring, masses off 30 %").trial(20261125));
        Diagnosis d = Diagnoser.diagnose(c.nominal(), c.train(), c.validation());
        assertEquals(List.of("joint-compliance j2 (stiffening)"), HeldOutFormsTest.families(d), "notes " + d.notes());
        Diagnosis.Finding f = d.effects().get(0);
        assertTrue(f.values()[1] < 0, "a stiffening spring's cubic term is negative: " + java.util.Arrays.toString(f.values()));
        assertTrue(d.finalValidateRmsM() < 1.15 * c.floorM(), d.finalValidateRmsM() + " vs floor " + c.floorM());
    }

    /** A linear spring (the same scenario family without hardening) stays a linear compliance. */
    @Test
    void linearSpring_staysLinear() {
        WorldCampaigns.Sim c = WorldCampaigns.of(Scenario.named("joint elasticity j2, masses off 30 %").trial(20261125));
        Diagnosis d = Diagnoser.diagnose(c.nominal(), c.train(), c.validation());
        assertEquals(List.of("joint-compliance j2"), HeldOutFormsTest.families(d), "notes " + d.notes());
    }

    /**
     * A richer alias takes a named form's place only for what it finds beside it. Over joint 3's
     * range harmonics 1-3 of q3 follow a gear-ratio ramp δ3 = ε·q3 (ε = −9.3·10⁻⁴, a 62-pose IRB 2400
     * campaign), and on a clean-room campaign of that kind their leave-one-pose-out error came out 2 %
     * lower by their five extra parameters' share of the noise, so the gear was named. With the scale
     * error fitted they find nothing significant on the ramp, and do on a true two-cycle error.
     */
    @Test
    void aRicherAlias_isRefused_whenItFindsNothingBesideTheSimplerForm() {
        var desc = RobotLibrary.shipped("irb2400");
        WorldCampaigns.Sim c = WorldCampaigns.geometric(desc, 31, false, p -> p.withPoses(43, 19).withSigma(1.1e-5));
        ToDoubleFunction<double[]> ramp = q -> -9.3e-4 * q[2];
        ToDoubleFunction<double[]> twoCycles = q -> -9.3e-4 * q[2] + Math.toRadians(0.004) * Math.sin(2 * q[2] + 0.7);
        assertTrue(richerRefused(desc, c, ramp), "harmonics in place of a true ramp");
        assertTrue(!richerRefused(desc, c, twoCycles), "harmonics in place of a ramp with a two-cycle error beside it");
    }

    private static boolean richerRefused(org.robopro.models.RobotDescription desc, WorldCampaigns.Sim c, ToDoubleFunction<double[]> delta) {
        var train = NonlinearPullTest.readOff(c.train(), 2, delta);
        var val = NonlinearPullTest.readOff(c.validation(), 2, delta);
        var model = org.robopro.kinematics.KinematicModel.build(desc);
        var geo = org.robopro.calibration.identification.Calibrator.calibrate(model, train, val,
                org.robopro.calibration.identification.Calibrator.Options.defaults());
        Diagnoser.Work w = new Diagnoser.Work(model, GravityTorques.of(model, desc), train.rows(), geo, val, Diagnoser.Options.defaults());
        Diagnoser.Fit fit = w.fit(List.of(Effect.scale(2)), new java.util.IdentityHashMap<>(), w.geoFull, null);
        return Diagnoser.richerWithoutCause(w.tester(fit), Effect.scale(2), Effect.periodic(2), w);
    }

    /**
     * The world's base rocking on its foundation above an overturning moment, nothing else: the
     * base's tilt under the arm's moment is located (a probe of its own, not only a rival of a
     * named family), and no family of the arm's drives is named for it. The world's foot is a
     * square plate with its edges along the base's x and y axes that tips over whichever edge the
     * moment exceeds the bolts' hold about: the tilt found is a square foot's, its edges' axes within
     * 10° of a multiple of 90°, and it brings the validation error to its twin's.
     */
    @Test
    void baseRockingAlone_isLocatedAsASquareFoot_andNothingNamed() {
        WorldCampaigns.Sim c = WorldCampaigns.of(Scenario.named("outside: base rocks on its foundation above an overturning moment").trial(20261124));
        Diagnosis d = Diagnoser.diagnose(c.nominal(), c.train(), c.validation());
        assertEquals(List.of(), HeldOutFormsTest.families(d), "notes " + d.notes());
        Effect tilt = d.effects().stream().map(Diagnosis.Finding::effect).filter(e -> e.kind() == Effect.Kind.BASE_TILT).findFirst()
                .orElseThrow(() -> new AssertionError("no tilt: " + d.effects().stream().map(f -> f.effect().label()).toList()));
        assertTrue(tilt.squareFoot(), tilt.label());
        double off = Math.abs(Math.IEEEremainder(Math.toDegrees(tilt.tiltAzimuth()), 90));
        assertTrue(off < 10, tilt.label());
        assertTrue(d.finalValidateRmsM() < 1.15 * c.floorM(), d.finalValidateRmsM() + " vs floor " + c.floorM());
    }

    /**
     * The world's pedestal whose foot plate rocks on the floor 0.4-0.8 m below the robot's base: the
     * robot turns about the foot's edge, so its base also slides toward the lean by the tilt times
     * the pedestal's height. It is located as the base's tilt (nothing named for it: a tilt about the
     * base plate alone had left the slide to a drive's scale or gear error), it brings the validation
     * error within 1.15 times the floor, and the report puts the pivot below the base plate (not how
     * far: see {@link Words#pivotWords}).
     */
    @Test
    void pedestalFootRocking_isLocatedAsATilt_withItsDepth_andNothingNamed() {
        Scenario.Trial t = Scenario.named("outside: a pedestal's foot rocks on the floor above an overturning moment").trial(20261129);
        WorldCampaigns.Sim c = WorldCampaigns.of(t);
        Diagnosis d = Diagnoser.diagnose(c.nominal(), c.train(), c.validation());
        assertEquals(List.of(), HeldOutFormsTest.families(d), "notes " + d.notes());
        Diagnosis.Finding tilt = d.effects().stream().filter(f -> f.effect().kind() == Effect.Kind.BASE_TILT).findFirst()
                .orElseThrow(() -> new AssertionError("no tilt: " + d.effects().stream().map(f -> f.effect().label()).toList()));
        assertTrue(d.finalValidateRmsM() < 1.15 * c.floorM(), d.finalValidateRmsM() + " vs floor " + c.floorM());
        assertTrue(tilt.values()[2] > 2 * tilt.sigmas()[2], "a slide toward the lean: " + java.util.Arrays.toString(tilt.values()));
        assertTrue(tilt.words().contains("rocks about a point below its base plate"), tilt.words());
    }

    /**
     * The base's give under the arm's moment is a structure of its own for the locate scan: on the
     * world's rocking base it is found after the geometric fit (with the tilt searched there), on a
     * null campaign of the same robot it is not.
     */
    @Test
    void baseMomentProbe_findsTheRockingBase_andNothingOnANullCampaign() {
        assertTrue(baseMomentFound(Scenario.named("outside: base rocks on its foundation above an overturning moment").trial(20261125)));
        assertTrue(!baseMomentFound(Scenario.named("null irb2000, payload steps").trial(20261125)));
    }

    private static boolean baseMomentFound(Scenario.Trial t) {
        WorldCampaigns.Sim c = WorldCampaigns.of(t);
        var model = org.robopro.kinematics.KinematicModel.build(c.nominal());
        var geo = org.robopro.calibration.identification.Calibrator.calibrate(model, c.train(), c.validation(),
                org.robopro.calibration.identification.Calibrator.Options.defaults());
        Diagnoser.Work w = new Diagnoser.Work(model, GravityTorques.of(model, c.nominal()), c.train().rows(), geo, c.validation(),
                Diagnoser.Options.defaults());
        Diagnoser.Tester geoTester = w.tester(w.fit(List.of(), new java.util.IdentityHashMap<>(), w.geoFull, null));
        List<Locator.Found> found = Locator.scan(geoTester, Locator.probes(geoTester, Directions.Source.NONE), 0.05, Diagnoser.MAX_LOCATED);
        return found.stream().anyMatch(f -> f.probe.var == Locator.Var.BASE_MOMENT && f.probe.tilt != null);
    }

    /**
     * A base that tips about the edge of its foot turns everything it carries as one rigid body: the
     * tool's pose with the tilt is the rotation about that edge (the line through P0 = d·(ẑ × e) − h·ẑ
     * along e, h the foot's depth below the base origin: a pedestal's) of the pose without it, its
     * orientation included (6-D data see the turn). Written here from the rigid motion, not from the
     * effect's regressor; equal to first order in the angle.
     */
    @Test
    void baseTilt_turnsTheToolAsARigidRotationAboutItsEdge() {
        var desc = RobotLibrary.shipped("irb2000");
        var model = org.robopro.kinematics.KinematicModel.build(desc);
        GravityTorques g = GravityTorques.of(model, desc);
        double psi = Math.toRadians(35), d = 0.3, h = 0.6, a = 2e-7; // axis azimuth, edge 0.3 m from axis 1 and 0.6 m down, tilt per N·m
        Effect tilt = Effect.baseTilt(g, psi, Double.NEGATIVE_INFINITY);
        ExtendedModel ext = new ExtendedModel(model, List.of(new Effect.Term(tilt, new double[] {a, -a * d, a * h})));
        double[] q = {0.4, 0.3, -0.2, 0.5, 0.6, -0.3};
        var c = org.robopro.calibration.PoseConditions.NONE;
        org.robopro.kinematics.Pose plain = model.flange(q), tilted = ext.flange(q, c);
        org.robopro.models.Vec3 m = g.baseMoment(q, 0);
        double ex = Math.cos(psi), ey = Math.sin(psi), phi = a * (m.x() * ex + m.y() * ey);
        org.robopro.models.Vec3 axis = new org.robopro.models.Vec3(ex, ey, 0), p0 = new org.robopro.models.Vec3(-d * ey, d * ex, -h);
        org.robopro.kinematics.Pose rigid = org.robopro.kinematics.Pose.translation(p0).times(org.robopro.kinematics.Pose.rotAxis(axis, phi))
                .times(org.robopro.kinematics.Pose.translation(p0.times(-1))).times(plain);
        assertTrue(Math.abs(phi) > 1e-5, "a visible tilt: " + phi);
        assertEquals(0, tilted.position().minus(rigid.position()).norm(), 1e-3 * Math.abs(phi) * 2.0, "position");
        assertTurnedAs(tilted, rigid, plain, 1e-3);
    }

    /** {@code actual}'s orientation is {@code rigid}'s to {@code rel} of the turn from {@code plain} to {@code rigid}. */
    static void assertTurnedAs(org.robopro.kinematics.Pose actual, org.robopro.kinematics.Pose rigid, org.robopro.kinematics.Pose plain, double rel) {
        double[] r1 = actual.rotationRowMajor(), r2 = rigid.rotationRowMajor(), r0 = plain.rotationRowMajor();
        double dev = 0, turn = 0;
        for (int i = 0; i < 9; i++) { dev = Math.max(dev, Math.abs(r1[i] - r2[i])); turn = Math.max(turn, Math.abs(r0[i] - r2[i])); }
        assertTrue(dev < rel * turn, "orientation off the rigid turn by " + dev + " (the turn itself " + turn + ")");
    }

    /** The new forms read back from the robot file as written: the stiffening spring, the square foot, the tilt toward the lean, re-estimated masses. */
    @Test
    void newForms_roundTripThroughTheRobotFile() {
        var desc = RobotLibrary.shipped("irb2000");
        var model = org.robopro.kinematics.KinematicModel.build(desc);
        GravityTorques g = GravityTorques.of(model, desc);
        double[] scales = new double[g.massCount()];
        java.util.Arrays.fill(scales, 1);
        scales[1] = 1.2;
        List<Effect.Term> terms = List.of(new Effect.Term(Effect.complianceStiffening(1, g), new double[] {2e-6, -3e-13}),
                new Effect.Term(Effect.squareFootTilt(g, Math.toRadians(10), 300, scales), new double[] {1e-7, -3e-8, 4e-8}),
                new Effect.Term(Effect.baseTilt(g, Double.NaN, 120, null), new double[] {2e-7, 0, 1e-7}),
                new Effect.Term(Effect.baseTilt(g, Math.toRadians(200), Double.NEGATIVE_INFINITY, null), new double[] {3e-7, 1e-8, 0}));
        double[] q = {0.3, 0.4, -0.2, 0.1, 0.5, 0.2};
        var c = new org.robopro.calibration.PoseConditions(null, Double.NaN, Double.NaN, 5.0);
        for (Effect.Term t : terms) {
            Effect.Term back = Effect.fromDescription(t.effect().describe(t.values()), model, g, "x.robot.json");
            assertEquals(t.effect().label(), back.effect().label());
            assertEquals(t.effect().size(), back.effect().size());
            double[] a = new double[3 * t.effect().size()], b = new double[3 * t.effect().size()], p = {1.2, 0.3, 0.9};
            if (t.effect().target() == Effect.Target.POSITION) {
                t.effect().positionRegressor(q, c, p, a);
                back.effect().positionRegressor(q, c, p, b);
            } else {
                t.effect().regressor(q, c, a);
                back.effect().regressor(q, c, b);
            }
            for (int i = 0; i < a.length; i++) assertEquals(a[i], b[i], 1e-12 * (1 + Math.abs(a[i])), t.effect().label());
        }
        // a tilt written before it had its slide reads back with none
        var written = terms.get(2).effect().describe(terms.get(2).values());
        var params = new java.util.LinkedHashMap<>(written.parameters());
        params.remove("slide");
        Effect.Term old = Effect.fromDescription(new org.robopro.models.EffectDescription(written.effect(), written.joints(), params), model, g,
                "x.robot.json");
        assertEquals(List.of(2e-7, 0.0, 0.0), java.util.Arrays.stream(old.values()).boxed().toList());
    }
}
