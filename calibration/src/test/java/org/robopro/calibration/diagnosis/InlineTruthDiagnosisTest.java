package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.calibration.simulation.PoseSampler;
import org.robopro.kinematics.KinematicModel;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
import org.robopro.models.Vec3;

/**
 * Diagnoses campaigns whose truth is written here, by hand, without the diagnosis' own effect
 * classes: the joint angles are perturbed with the physical formula before forward kinematics,
 * which is the independent world simulator's (its own product of exponentials, on a robot drawn
 * with geometric errors, measured in its base frame).
 * Backlash: a driven output lags its motor-side encoder, q_out = q − (b/2)·dir with dir the sign
 * of the joint's last move in the measuring sequence, before the coupling θ = C q_out. The files carry no dir columns, so the
 * diagnosis must infer the directions from the measuring order (time_s).
 */
class InlineTruthDiagnosisTest {
    private final RobotDescription robot = RobotLibrary.shipped("irb2000");
    private final KinematicModel model = KinematicModel.build(robot);
    /** The real robot: the file's robot with geometric errors (world defaults), the measured point about (30, -20, 110) mm on the flange. */
    private org.robopro.world.WorldRobot world(long seed) {
        return org.robopro.world.Scenario.baseRobot(robot, new Random(seed * 7 + 1), 1e-3, Math.toRadians(0.1), new double[] {0.03, -0.02, 0.11})
                .withInstrument(org.robopro.world.Rigid.IDENTITY);
    }

    /**
     * One measuring sequence of {@code n} poses with lost motion {@code b} (rad) on joint
     * {@code joint}, position noise {@code sigma} per axis; every {@code every}-th pose is a
     * validation pose of the same file (set column) when {@code every > 0}.
     */
    private MeasurementSet[] campaign(int n, int joint, double b, double sigma, int every, long seed) {
        return campaign(n, joint, b, sigma, every, seed, q -> 0);
    }

    /** As above, plus an error of drive 1 (rad) written by {@code drive1} as a function of the controller values. */
    private MeasurementSet[] campaign(int n, int joint, double b, double sigma, int every, long seed,
                                      java.util.function.ToDoubleFunction<double[]> drive1) {
        Random rng = new Random(seed);
        org.robopro.world.WorldRobot real = world(seed);
        int[] still = new int[robot.dof()];
        java.util.Arrays.fill(still, 1);
        List<double[]> qs = new PoseSampler(model).sample(n, rng);
        List<Measurement> train = new ArrayList<>(), val = new ArrayList<>();
        double[] prev = null;
        int lastDir = 0;
        for (int i = 0; i < n; i++) {
            double[] q = qs.get(i);
            if (prev != null && q[joint] != prev[joint]) lastDir = q[joint] > prev[joint] ? 1 : -1;
            double[] out = q.clone();
            out[joint] -= 0.5 * b * lastDir;                 // the drive's output lags its encoder (before the coupling)
            out[0] += drive1.applyAsDouble(q);
            double[] t = real.target(out, still, Double.NaN, Double.NaN, 0).p(); // the world robot carries no drive error of its own
            Vec3 p = new Vec3(t[0], t[1], t[2]);
            p = new Vec3(p.x() + sigma * rng.nextGaussian(), p.y() + sigma * rng.nextGaussian(), p.z() + sigma * rng.nextGaussian());
            boolean v = every > 0 && i % every == every - 1;
            Measurement m = new Measurement("p" + i, q, p, null, null, 20.0 * i, Double.NaN, Double.NaN,
                    every > 0 ? (v ? Measurement.Split.VALIDATE : Measurement.Split.TRAIN) : null, i + 2);
            (v ? val : train).add(m);
            prev = q;
        }
        return new MeasurementSet[] {new MeasurementSet("inline.csv", Map.of(), "base", train),
                every > 0 ? new MeasurementSet("inline.csv", Map.of(), "base", val) : null};
    }

    @Test
    void backlashJoint2_noDirColumns_namedFromInferredDirectionsWithLaggingSign() {
        double b = Math.toRadians(0.04), sigma = 2e-5;
        MeasurementSet[] c = campaign(260, 1, b, sigma, 4, 11);
        Diagnosis d = Diagnoser.diagnose(robot, c[0], c[1]);
        assertTrue(d.directions().inferred(), d.directions().words);
        List<String> named = d.effects().stream().map(f -> f.effect().label()).toList();
        assertEquals(List.of("backlash j2"), named, "named " + named);
        double est = d.effects().get(0).values()[0];
        assertEquals(b, est, 0.15 * b, "lost motion " + Math.toDegrees(est) + " deg");
        double floor = Math.sqrt(3) * sigma;
        assertTrue(d.finalValidateRmsM() < 1.15 * floor, "validation " + d.finalValidateRmsM() / floor + " x floor");
        assertTrue(d.geometricValidateRmsM() > 1.5 * floor, "the effect matters: " + d.geometricValidateRmsM() / floor);
    }

    /**
     * A small real-like campaign: 30 poses, lost motion of 0.007° on joint 1, 0.03 mm noise, no
     * dir columns (a laser-tracker campaign of that size found it with F ≈ 48). Named, positive.
     */
    @Test
    void smallCampaign_smallLostMotionOnJoint1_accepted() {
        double b = Math.toRadians(0.007);
        int found = 0;
        for (long seed = 1; seed <= 3; seed++) {
            MeasurementSet[] c = campaign(30, 0, b, 3e-5, 0, seed);
            Diagnosis d = Diagnoser.diagnose(robot, c[0], null);
            for (Diagnosis.Finding f : d.effects()) {
                assertEquals("backlash j1", f.effect().label(), "nothing else is named: " + d.effects());
                assertTrue(f.values()[0] > 0.4 * b && f.values()[0] < 2 * b, "lost motion " + Math.toDegrees(f.values()[0]));
                found++;
            }
        }
        assertTrue(found >= 2, "found in " + found + " of 3 campaigns");
    }

    @Test
    void nullCampaign_noDirColumns_claimsNothing() {
        for (long seed = 5; seed <= 6; seed++) {
            MeasurementSet[] c = campaign(200, 0, 0, 2e-5, 4, seed);
            Diagnosis d = Diagnoser.diagnose(robot, c[0], c[1]);
            assertTrue(d.effects().isEmpty(), "seed " + seed + ": " + d.effects());
        }
    }

    /**
     * A two-stage reducer on joint 1: once per turn plus 17 cycles per turn (0.008°), outside the
     * default harmonics 1-3. The scan must locate "17 cycles per turn of joint 1" and the
     * diagnosis name a periodic error with that harmonic, down to the noise on validation.
     */
    @Test
    void highHarmonicOnJoint1_locatedAndNamedWithItsHarmonic() {
        double a1 = Math.toRadians(0.004), a17 = Math.toRadians(0.008), sigma = 2e-5;
        MeasurementSet[] c = campaign(300, 0, 0, sigma, 4, 21, q -> a1 * Math.sin(q[0] + 0.3) + a17 * Math.sin(17 * q[0] + 1.1));
        Diagnosis d = Diagnoser.diagnose(robot, c[0], c[1]);
        assertTrue(d.located().stream().anyMatch(l -> l.shape().equals("17 cycles per turn of joint 1") && l.explainedBy() != null),
                d.located().stream().map(Diagnosis.Located::words).toList().toString());
        assertEquals(1, d.effects().size(), d.effects().toString());
        Effect e = d.effects().get(0).effect();
        assertEquals(Effect.Kind.PERIODIC, e.kind());
        assertEquals(0, e.joint());
        assertTrue(java.util.Arrays.stream(e.harmonics()).anyMatch(h -> h == 17), e.label());
        double floor = Math.sqrt(3) * sigma;
        assertTrue(d.finalValidateRmsM() < 1.15 * floor, "validation " + d.finalValidateRmsM() / floor + " x floor");
        assertTrue(d.warnings().isEmpty(), d.warnings().toString());
        String json = DiagnosisReport.json(d, new DiagnosisReport.Context("m.csv", null, "now"));
        assertTrue(json.contains("\"located\"") && json.contains("17 cycles per turn of joint 1"), json);
    }

    @Test
    void nullCampaign_locatesNothingAndWarnsOfNothing() {
        MeasurementSet[] c = campaign(200, 0, 0, 2e-5, 4, 33);
        Diagnosis d = Diagnoser.diagnose(robot, c[0], c[1]);
        assertTrue(d.effects().isEmpty(), d.effects().toString());
        assertTrue(d.located().isEmpty(), d.located().stream().map(Diagnosis.Located::words).toList().toString());
        assertTrue(d.warnings().isEmpty(), d.warnings().toString());
    }
}
