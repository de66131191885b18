package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.JointEffect;
import org.robopro.calibration.PoseConditions;
import org.robopro.calibration.compensation.Compensator;
import org.robopro.calibration.simulation.TrueRobot;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.LinkMass;
import org.robopro.models.MassModel;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotFile;
import org.robopro.models.RobotLibrary;
import org.robopro.models.Vec3;
import org.robopro.world.JointError;
import org.robopro.world.WorldRobot;

class ExtendedModelTest {
    private final RobotDescription robot = RobotLibrary.shipped("irb2000");
    private final KinematicModel model = KinematicModel.build(robot);
    private final GravityTorques g = new GravityTorques(model, robot.massModel().orElseThrow());
    private final List<Effect.Term> terms = List.of(
            new Effect.Term(Effect.compliance(1, g), new double[] {1e-6}),
            new Effect.Term(Effect.backlash(1), new double[] {8e-4}),
            new Effect.Term(Effect.thermal(20), new double[] {20e-6}),
            new Effect.Term(Effect.coupling(2, 1), new double[] {5e-4}));
    private final PoseConditions c = new PoseConditions(new int[] {1, -1, 1, 1, -1, 1}, 300, 31, 7);
    private final Pose tool = Pose.translation(0, 0, 0.1);

    private TrueRobot truth() {
        List<JointEffect> es = new ArrayList<>();
        for (Effect.Term t : terms) es.add(t.effect().truth(t.values()));
        return new TrueRobot(model, tool, Pose.IDENTITY, 0, 0, es);
    }

    @Test
    void tool_sameEffectsAsSimulatedTruth_samePose() {
        ExtendedModel ext = new ExtendedModel(model, terms);
        TrueRobot t = truth();
        for (double[] q : model.randomConfigurations(20, 4)) {
            Pose a = ext.tool(q, tool, c), b = t.tool(q, c);
            assertEquals(0, a.distanceTo(b), 1e-12);
            assertEquals(0, a.angleTo(b), 1e-12);
        }
    }

    /** A compliance given as a stiffness on the file's masses, in a robot file that has no masses, is refused, not evaluated on stand-ins. */
    @Test
    void robotFile_complianceOnMassesTheFileDoesNotHave_refusedNamingTheMassModel() {
        RobotDescription noMasses = RobotLibrary.shipped("irb2400");
        assertTrue(noMasses.massModel().isEmpty(), "the IRB 2400 file has no mass model");
        RobotDescription withCompliance = noMasses.withEffects(List.of(
                new org.robopro.models.EffectDescription("joint-compliance", List.of(2), java.util.Map.of("c", 1e-6))));
        var e = org.junit.jupiter.api.Assertions.assertThrows(org.robopro.models.InputException.class,
                () -> ExtendedModel.of(withCompliance, "x.robot.json"));
        assertTrue(e.getMessage().contains("x.robot.json") && e.getMessage().contains("mass_model"), e.getMessage());

        // read from a file, the error points at the effect that needs the masses (the missing field has no line)
        String text = RobotFile.format(withCompliance);
        var fromFile = org.junit.jupiter.api.Assertions.assertThrows(org.robopro.models.InputException.class,
                () -> ExtendedModel.of(RobotFile.parse("x.robot.json", text), "x.robot.json"));
        assertEquals(lineAt(text, text.lastIndexOf('{', text.indexOf("\"joint-compliance\""))), fromFile.line(), fromFile.getMessage());
        assertEquals("effects[0]", fromFile.field(), fromFile.getMessage());
        assertTrue(fromFile.getMessage().contains("mass_model"), fromFile.getMessage());
    }

    @Test
    void robotFile_roundTrip_predictsTheSame() {
        ExtendedModel ext = new ExtendedModel(model, terms);
        String text = RobotFile.format(ext.toDescription());
        assertTrue(text.contains("\"effects\""), text);
        ExtendedModel back = ExtendedModel.of(RobotFile.parse("extended.robot.json", text), "extended.robot.json");
        assertEquals(terms.size(), back.terms().size());
        for (double[] q : model.randomConfigurations(10, 8))
            assertEquals(0, ext.tool(q, tool, c).distanceTo(back.tool(q, tool, c)), 1e-9);
    }

    /**
     * A robot file edited by hand with a bad effect is refused with the file, the line and the
     * field of the bad value: a backlash's build-up length made negative points at that key's line,
     * a parameter left out at its effect's parameters' line, two joints for a backlash at the
     * joints' line (each line found here by searching the file's text, not from the reader).
     */
    @Test
    void robotFile_badEffect_namesItsLineAndField() {
        ExtendedModel ext = new ExtendedModel(model, List.of(
                new Effect.Term(Effect.compliance(1, g), new double[] {1e-6}),
                new Effect.Term(Effect.backlash(1), new double[] {8e-4})));
        String text = RobotFile.format(ext.toDescription());
        String b = "(\"b\"\\s*:\\s*[-0-9.eE]+)";

        String negative = text.replaceFirst(b, "$1,\n      \"build_up_rad\" : -0.1");
        assertTrue(!negative.equals(text), "the build-up length was added: " + negative);
        var e = org.junit.jupiter.api.Assertions.assertThrows(org.robopro.models.InputException.class,
                () -> ExtendedModel.of(RobotFile.parse("x.robot.json", negative), "x.robot.json"));
        assertEquals(lineOf(negative, "\"build_up_rad\""), e.line(), e.getMessage());
        assertTrue(e.getMessage().startsWith("x.robot.json:" + e.line() + ":"), e.getMessage());
        assertTrue(e.field().startsWith("effects[") && e.field().endsWith(".parameters_si.build_up_rad"), e.getMessage());

        String missing = text.replaceFirst("\"b\"(\\s*:)", "\"b_typo\"$1");
        e = org.junit.jupiter.api.Assertions.assertThrows(org.robopro.models.InputException.class,
                () -> ExtendedModel.of(RobotFile.parse("x.robot.json", missing), "x.robot.json"));
        // the backlash's parameters, the object the missing key belongs in
        assertEquals(lineAt(missing, missing.lastIndexOf("\"parameters_si\"", missing.indexOf("\"b_typo\""))), e.line(), e.getMessage());
        assertTrue(e.field().endsWith(".parameters_si.b"), e.getMessage());

        String outside = text.replaceFirst("(\"backlash\",\\s*\"joints\"\\s*:\\s*\\[\\s*\"j2\")", "$1, \"j3\"");
        assertTrue(!outside.equals(text), "a second joint was given to the backlash: " + text);
        e = org.junit.jupiter.api.Assertions.assertThrows(org.robopro.models.InputException.class,
                () -> ExtendedModel.of(RobotFile.parse("x.robot.json", outside), "x.robot.json"));
        assertEquals(lineOf(outside, "\"joints\"", "\"effect\": \"backlash\""), e.line(), e.getMessage());
        assertTrue(e.field().endsWith(".joints"), e.getMessage());
    }

    /** The 1-based line of the first occurrence of {@code s} in {@code text} (after the first of {@code after}, when given). */
    private static int lineOf(String text, String s, String... after) {
        int from = 0;
        for (String a : after) from = text.indexOf(a, from);
        return lineAt(text, text.indexOf(s, from));
    }

    /** The 1-based line of character {@code at} of {@code text}. */
    private static int lineAt(String text, int at) {
        assertTrue(at >= 0, "found in the text");
        return (int) text.substring(0, at).chars().filter(c -> c == '\n').count() + 1;
    }

    /**
     * The same physics written independently by the world simulator (its own kinematics and
     * forms, nothing shared with this package): the robot file's geometry with the measured point
     * at the flange, and each of {@link #terms} in the world's words.
     */
    private WorldRobot world(boolean backlash, boolean thermal, boolean compliance, boolean coupling) {
        WorldRobot w = WorldRobot.nominal(robot, new double[3]);
        List<JointError> errors = new ArrayList<>();
        if (backlash) errors.add(new JointError.LostMotion(1, 8e-4));
        if (coupling) errors.add(new JointError.Coupling(2, 1, 5e-4));
        w = w.withErrors(errors);
        if (thermal) {
            double[] alpha = new double[robot.dof() + 1];
            java.util.Arrays.fill(alpha, 20e-6); // every link alike: a uniform strain
            w = w.withThermal(new WorldRobot.Thermal(20, alpha, new double[3], new double[3]));
        }
        if (compliance) {
            MassModel mm = robot.massModel().orElseThrow();
            List<WorldRobot.Mass> masses = new ArrayList<>();
            for (LinkMass l : mm.links()) masses.add(new WorldRobot.Mass(l.joint() - 1, l.massKg(), l.centreOfMass().toArray()));
            double[] k = new double[robot.dof()];
            java.util.Arrays.fill(k, Double.POSITIVE_INFINITY);
            k[1] = 1 / 1e-6;
            w = w.withCompliance(new WorldRobot.Compliance(k, masses, mm.payloadCentreOfMass().toArray(), mm.gravity().toArray()));
        }
        return w;
    }

    private static Vec3 at(WorldRobot w, double[] q, PoseConditions c) {
        double[] p = w.target(q, c.directions(), c.tempC(), c.timeS(), c.payloadKg()).p();
        return new Vec3(p[0], p[1], p[2]);
    }

    /**
     * Each effect's form against the independent world physics: the extended model and the world
     * robot carrying the same physical sizes put the flange at the same place, for both approach
     * directions. (The measured point is the flange origin: the world's target holder does not
     * grow with temperature, the uniform stretch of the extended model grows the whole arm.) Alone,
     * each agrees to rounding. Together, the forms leave second-order cross terms: the world
     * evaluates gravity at the output angle after the lost motion, the extended model at the
     * angle before it (0.14 µm here: a deflection of 0.35 mm turned by 0.02°), so combinations are
     * held to 1 µm, a twentieth of the noise of a tracker.
     */
    @Test
    void tool_eachEffect_agreesWithTheIndependentWorldPhysics() {
        int[] down = {-1, 1, -1, 1, -1, 1};
        PoseConditions c2 = new PoseConditions(down, 900, 26, 3);
        // Which of terms (compliance j2, backlash j2, thermal, coupling j3<-j2) each case carries.
        String[] names = {"rigid", "elastic drive 2", "backlash j2", "uniform thermal growth", "coupling j3<-j2", "all four",
                "elastic + backlash", "elastic + thermal", "elastic + coupling", "backlash + thermal + coupling"};
        boolean[][] on = {{false, false, false, false}, {true, false, false, false}, {false, true, false, false},
                {false, false, true, false}, {false, false, false, true}, {true, true, true, true},
                {true, true, false, false}, {true, false, true, false}, {true, false, false, true}, {false, true, true, true}};
        for (int e = 0; e < names.length; e++) {
            List<Effect.Term> ts = new ArrayList<>();
            for (int i = 0; i < 4; i++) if (on[e][i]) ts.add(terms.get(i));
            ExtendedModel ext = new ExtendedModel(model, ts);
            WorldRobot w = world(on[e][1], on[e][2], on[e][0], on[e][3]);
            double worst = 0, size = 0;
            for (double[] q : model.randomConfigurations(20, 4))
                for (PoseConditions pc : List.of(c, c2)) {
                    Vec3 a = ext.tool(q, Pose.IDENTITY, pc).position(), b = at(w, q, pc);
                    worst = Math.max(worst, a.minus(b).norm());
                    size = Math.max(size, a.minus(model.flange(q).position()).norm());
                }
            System.out.printf("%s: extended model vs world %.3g m, effect size %.3g m%n", names[e], worst, size);
            assertTrue(worst < (e < 5 ? 1e-9 : 1e-6), names[e] + ": extended model and world differ by " + worst + " m");
            if (e > 0) assertTrue(size > 2e-5, names[e] + ": the effect should move the flange, moved " + size + " m");
        }
    }

    @Test
    void compensator_extendedModel_worldRobotLandsOnTarget() {
        ExtendedModel ext = new ExtendedModel(model, terms);
        Compensator withEffects = new Compensator(model, ext, Pose.IDENTITY, Pose.IDENTITY, c);
        Compensator geometryOnly = new Compensator(model, model, Pose.IDENTITY, Pose.IDENTITY);
        WorldRobot t = world(true, true, true, true);
        double worstWith = 0, worstWithout = 0;
        int n = 0;
        for (double[] q0 : model.randomConfigurations(10, 21)) {
            if (!new org.robopro.calibration.simulation.PoseSampler(model).acceptable(q0)) continue;
            Pose target = model.flange(q0);
            Compensator.Result r = withEffects.compensate(target, q0);
            assertEquals(Compensator.Status.CONVERGED, r.status());
            worstWith = Math.max(worstWith, at(t, r.q(), c).minus(target.position()).norm());
            Compensator.Result r0 = geometryOnly.compensate(target, q0);
            worstWithout = Math.max(worstWithout, at(t, r0.q(), c).minus(target.position()).norm());
            n++;
        }
        assertTrue(n >= 3, "too few acceptable poses: " + n);
        // Within the forms' second-order cross terms (tool_eachEffect_agreesWithTheIndependentWorldPhysics).
        assertTrue(worstWith < 1e-6, "with effects the world's robot misses by " + worstWith);
        assertTrue(worstWithout > 1e-4, "the effects should matter: " + worstWithout);
    }

    /**
     * To reach a target the command must lead the lagging output: with backlash b on joint 2 and
     * approach direction dir, the compensated controller value of drive 2 is the target's plus
     * (b/2)·dir, every other drive unchanged (computed here by hand, not with the effect's code).
     */
    @Test
    void compensator_backlash_commandLeadsByHalfThePlay() {
        double b = Math.toRadians(0.05);
        ExtendedModel ext = new ExtendedModel(model, List.of(new Effect.Term(Effect.backlash(1), new double[] {b})));
        for (int dir : new int[] {1, -1}) {
            PoseConditions cond = new PoseConditions(new int[] {dir, dir, dir, dir, dir, dir}, 0, 20, 0);
            Compensator comp = new Compensator(model, ext, tool, tool, cond);
            double[] q0 = {0.3, 0.2, -0.1, 0.4, 0.5, 0.6};
            Pose target = model.tool(q0, tool);
            Compensator.Result r = comp.compensate(target, q0);
            assertEquals(Compensator.Status.CONVERGED, r.status());
            double[] q = r.q();
            assertEquals(b / 2 * dir, q[1] - q0[1], 1e-9, "drive 2 leads by half the play, dir " + dir);
            for (int j : new int[] {0, 2, 3, 4, 5}) assertEquals(q0[j], q[j], 1e-9, "drive " + (j + 1));
        }
    }
}
