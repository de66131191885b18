package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.PoseConditions;
import org.robopro.calibration.WorldCampaigns;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.kinematics.KinematicModel;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
import org.robopro.models.Vec3;
import org.robopro.world.JointError;
import org.robopro.world.Scenario;

/**
 * Lost motion that builds up over the move (friction wind-up), against the independent world
 * simulator's truth (its own form: the lag (b/2)(1 − exp(−|last move|/x0)) from the real
 * measuring sequence, nothing shared with {@link Effect}): named on its joint with a build-up
 * length near the truth's and brought to the noise floor on the validation poses; where the
 * truth is a constant lost motion, the constant form is named.
 */
class WindUpLostMotionTest {
    private static final String WIND_UP = "lost motion j3 building up over the move (friction wind-up)";
    private final RobotDescription irb2000 = RobotLibrary.shipped("irb2000");

    @Test
    void windUp_isNamedOnJoint3_withTheTruthsBuildUpLength_atTheNoiseFloor() {
        for (long seed : new long[] {20261124, 20261126}) {
            Scenario.Trial t = Scenario.named(WIND_UP).trial(seed, p -> p);
            WorldCampaigns.Sim c = WorldCampaigns.of(t);
            JointError.WindUpLostMotion truth = t.world().errors().stream().filter(e -> e instanceof JointError.WindUpLostMotion)
                    .map(e -> (JointError.WindUpLostMotion) e).findFirst().orElseThrow();
            Diagnosis d = Diagnoser.diagnose(irb2000, c.train(), c.validation());
            assertEquals(1, d.effects().size(), "seed " + seed + ": " + d.effects() + " notes " + d.notes());
            Effect e = d.effects().get(0).effect();
            assertEquals(Effect.Kind.BACKLASH, e.kind());
            assertEquals(2, e.joint());
            assertTrue(e.buildsUp(), "seed " + seed + ": named " + e.label() + " (the constant form) " + d.notes());
            double ratio = e.buildUpRad() / truth.buildUp();
            assertTrue(ratio > 0.7 && ratio < 1.4, "seed " + seed + ": build-up " + Math.toDegrees(e.buildUpRad()) + " deg, truth "
                    + Math.toDegrees(truth.buildUp()));
            assertEquals(truth.width(), d.effects().get(0).values()[0], 0.1 * truth.width(), "lag after a long move");
            assertTrue(d.geometricValidateRmsM() > 3 * c.floorM(), "the lost motion matters");
            assertTrue(d.finalValidateRmsM() <= 1.15 * c.floorM(), "seed " + seed + ": validation " + d.finalValidateRmsM() / c.floorM()
                    + " x floor");
            assertEquals(List.of(), d.outliers(), "the campaign has no bad measurement");
            assertTrue(d.effects().get(0).words().contains("builds up over the move"), d.effects().get(0).words());
            assertTrue(d.effects().get(0).words().contains("mm at the measured point"), d.effects().get(0).words());
        }
    }

    /** Without validation poses (300 poses, the K-fold path): the folds name it again and it reaches the floor on training. */
    @Test
    void windUp_withoutValidationPoses_isNamedByTheFolds() {
        WorldCampaigns.Sim c = WorldCampaigns.of(Scenario.named(WIND_UP).trial(20261126, p -> p.withPoses(300, 0)));
        Diagnosis d = Diagnoser.diagnose(irb2000, c.train(), null);
        assertEquals(1, d.effects().size(), d.effects() + " notes " + d.notes());
        assertTrue(d.effects().get(0).effect().buildsUp(), d.effects().get(0).effect().label());
        assertTrue(d.finalTrainRmsM() <= 1.15 * c.floorM(), d.finalTrainRmsM() / c.floorM() + " x floor");
        assertTrue(d.notes().stream().anyMatch(n -> n.startsWith("backlash j3: named by 5 of 5 folds")), d.notes().toString());
    }

    /** A constant lost motion (world truth) must not be named as one that builds up, nor as a play that changes over the turn. */
    @Test
    void constantLostMotion_staysConstant() {
        for (String s : List.of("lost motion j3, random order, directions recorded", "lost motion j2, directions not recorded")) {
            WorldCampaigns.Sim c = WorldCampaigns.of(Scenario.named(s).trial(20261126, p -> p));
            Diagnosis d = Diagnoser.diagnose(irb2000, c.train(), c.validation());
            assertEquals(1, d.effects().size(), s + ": " + d.effects());
            Effect e = d.effects().get(0).effect();
            assertEquals(Effect.Kind.BACKLASH, e.kind(), s);
            assertFalse(e.buildsUp(), s + ": named " + e.label() + "; notes " + d.notes());
            assertFalse(e.runout(), s + ": named " + e.label() + " (a play changing over the turn); notes " + d.notes());
        }
    }

    @Test
    void moves_areTheLastRealMovesInMeasuringOrder_overTheWholeFile() {
        Measurement a = row("a", 0, Measurement.Split.TRAIN, 0.2, 0), b = row("b", 10, Measurement.Split.VALIDATE, 0.5, 0),
                c = row("c", 20, Measurement.Split.TRAIN, 0.5 + 0.4 * Directions.PLAY_TOLERANCE, -0.1);
        MeasurementSet tr = new MeasurementSet("f", Map.of(), "base", List.of(c, a));
        MeasurementSet va = new MeasurementSet("f", Map.of(), "base", List.of(b));
        Directions.Moves m = Directions.moves(tr, va);
        assertEquals(0.2, m.of(a, 0), 1e-12, "the first pose: from the zero position");
        assertEquals(0.3, m.of(b, 0), 1e-12, "a validation row between two training rows");
        assertEquals(0.3, m.of(c, 0), 1e-12, "a joint that stood still (within the read-back jitter) keeps its last move");
        assertEquals(-0.1, m.of(c, 1), 1e-12);
        assertTrue(Double.isNaN(m.of(row("x", 5, null, 1, 1), 0)), "a row not in the file: unknown");
    }

    @Test
    void windUp_regressorAndRobotFile() {
        Measurement a = row("a", 0, null, 0.2, 0), b = row("b", 10, null, 0.2 + Math.toRadians(2), 0);
        MeasurementSet s = new MeasurementSet("f", Map.of(), "base", List.of(a, b));
        Effect e = Effect.windUp(0, Math.toRadians(4), Directions.moves(s, null));
        PoseConditions up = new PoseConditions(new int[] {1, 1}, 0, Double.NaN, Double.NaN);
        double[] g = new double[1];
        e.regressor(b, up, g);
        assertEquals(-0.5 * (1 - Math.exp(-0.5)), g[0], 1e-12, "half a build-up length: 39 % of the lag");
        e.regressor(b.q(), up, g);
        assertEquals(-0.5, g[0], 1e-12, "move unknown (compensation): the full lag");
        KinematicModel model = KinematicModel.build(irb2000);
        Effect.Term back = Effect.fromDescription(Effect.windUp(2, 0.1, null).describe(new double[] {7e-4}), model, null, "x.json");
        assertTrue(back.effect().buildsUp());
        assertEquals(0.1, back.effect().buildUpRad(), 0);
        assertArrayEquals(new double[] {7e-4}, back.values(), 0);
        assertFalse(Effect.fromDescription(Effect.backlash(2).describe(new double[] {7e-4}), model, null, "x.json").effect().buildsUp());
    }

    /**
     * The travel a drive's friction sees when each pose is taken by an approach move from one side
     * (+1: moving up) of length a, worked by hand from the program: to the approach pose q - a, then
     * up onto q. Coming from below past q - a the drive goes on up: the travel is the whole last move.
     * Coming from above, or from just below q - a's far side (a move up shorter than a), it turns
     * round at q - a: the travel is a. A drive that came up by 10 deg with a 2 deg approach has built
     * up 1 - exp(-10/4) of its lag (build-up length 4 deg); one that came down, 1 - exp(-2/4).
     */
    @Test
    void approachedWindUp_travelSinceTheDriveTurned() {
        double deg = Math.toRadians(1);
        Measurement start = row("s", 0, null, 20 * deg, 0), fromBelow = row("u", 10, null, 30 * deg, 0),
                fromAbove = row("d", 20, null, 25 * deg, 0), shortUp = row("n", 30, null, 26 * deg, 0);
        MeasurementSet s = new MeasurementSet("f", Map.of(), "base", List.of(start, fromBelow, fromAbove, shortUp));
        Effect e = Effect.windUp(0, 4 * deg, 2 * deg, Directions.moves(s, null));
        assertTrue(e.approached());
        assertEquals(10 * deg, e.travel(fromBelow, 1), 1e-12, "came up past the approach pose: the whole move");
        assertEquals(2 * deg, e.travel(fromAbove, 1), 1e-12, "came down, turned round at the approach pose");
        assertEquals(2 * deg, e.travel(shortUp, 1), 1e-12, "came up by 1 deg, less than the approach: turned round below");
        PoseConditions up = new PoseConditions(new int[] {1, 1}, 0, Double.NaN, Double.NaN);
        double[] g = new double[1];
        e.regressor(fromBelow, up, g);
        assertEquals(-0.5 * (1 - Math.exp(-10 / 4.0)), g[0], 1e-12);
        e.regressor(fromAbove, up, g);
        assertEquals(-0.5 * (1 - Math.exp(-2 / 4.0)), g[0], 1e-12, "the output lags behind the side it was taken from");
        Effect plain = Effect.windUp(0, 4 * deg, Directions.moves(s, null));
        assertEquals(-5 * deg, plain.travel(fromAbove, 1), 1e-12, "without an approach: the last move, whatever the recorded side");

        KinematicModel model = KinematicModel.build(irb2000);
        Effect.Term back = Effect.fromDescription(Effect.windUp(2, 0.1, 0.03, null).describe(new double[] {7e-4}), model, null, "x.json");
        assertTrue(back.effect().approached());
        assertEquals(0.03, back.effect().approachRad(), 0);
        assertEquals(0.1, back.effect().buildUpRad(), 0);
    }

    private static Measurement row(String id, double t, Measurement.Split set, double... q) {
        return new Measurement(id, q, Vec3.ZERO, null, null, t, Double.NaN, Double.NaN, set, 0);
    }
}
