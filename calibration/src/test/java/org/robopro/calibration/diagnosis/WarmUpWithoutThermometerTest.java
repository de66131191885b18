package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
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
 * A campaign with reading times but no thermometer, during which the robot stood twice: the arm,
 * warmed by its drives while it works, cools toward the air while it stands. The truth is written
 * here: the structure's temperature from a heat balance integrated in small steps, two bodies with
 * their own time constants (neither on the diagnosis' grid of time constants), through the
 * independent world simulator's link-by-link growth; the file has time_s only.
 */
class WarmUpWithoutThermometerTest {
    private final RobotDescription robot = RobotLibrary.shipped("irb2000");
    private final KinematicModel model = KinematicModel.build(robot);

    /** Each reading's time (s): 20 s a pose, the robot standing 1500 s after pose 90 and 1200 s after pose 170. */
    private static double[] times(int n) {
        double[] t = new double[n];
        double now = 0;
        for (int i = 0; i < n; i++) {
            now += 20;
            if (i == 90) now += 1500;
            if (i == 170) now += 1200;
            t[i] = now;
        }
        return t;
    }

    /**
     * The structure's rise above the air (K) at the reading times: two lumped bodies heated by the
     * drives only while the robot works between readings (the heat balance C dT/dt = P u − (T − T_air)/R,
     * u = 1 moving, 0 standing; F. P. Incropera, D. P. DeWitt, Fundamentals of Heat and Mass Transfer,
     * §5.2), integrated with explicit Euler steps of 1 s.
     */
    private static double[] rise(double[] times) {
        double[] tau = {700, 3000}, full = {9.0, 7.0}; // s, K warmed through
        double[] temp = new double[2], out = new double[times.length];
        double now = 0;
        for (int i = 0; i < times.length; i++) {
            boolean standing = i > 0 && times[i] - times[i - 1] > 100; // the two pauses: the robot stands until it moves to the next pose
            double moveFrom = standing ? times[i] - 20 : now;
            for (; now < times[i]; now += 1) {
                double u = now >= moveFrom ? 1 : 0;
                for (int b = 0; b < 2; b++) temp[b] += (full[b] * u - temp[b]) / tau[b];
            }
            out[i] = temp[0] + temp[1];
        }
        return out;
    }

    @Test
    void armWarmedByItsDrives_coolsInThePauses_namedFromTimeAlone() {
        Random rng = new Random(41);
        double sigma = 2e-5;
        // steel pedestal and column, cast-aluminium arms (CRC Handbook: 11.5e-6 and 23e-6 per K), a steel flange
        double[] alpha = {11.5e-6, 11.5e-6, 23e-6, 23e-6, 23e-6, 11.5e-6, 11.5e-6};
        org.robopro.world.WorldRobot real = org.robopro.world.Scenario.baseRobot(robot, new Random(7), 1e-3, Math.toRadians(0.1),
                        new double[] {0.03, -0.02, 0.11}).withInstrument(org.robopro.world.Rigid.IDENTITY)
                .withThermal(new org.robopro.world.WorldRobot.Thermal(20.0, alpha, new double[6], new double[6]));
        int n = 240;
        double[] t = times(n), dT = rise(t);
        int[] still = new int[robot.dof()];
        Arrays.fill(still, 1);
        List<double[]> qs = new PoseSampler(model).sample(n, rng);
        List<Measurement> train = new ArrayList<>(), val = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            double[] q = qs.get(i);
            double[] p = real.target(q, still, 20.0 + dT[i], t[i], 0).p();
            Vec3 m = new Vec3(p[0] + sigma * rng.nextGaussian(), p[1] + sigma * rng.nextGaussian(), p[2] + sigma * rng.nextGaussian());
            boolean v = i % 4 == 3;
            (v ? val : train).add(new Measurement("p" + i, q, m, null, null, t[i], Double.NaN, Double.NaN,
                    v ? Measurement.Split.VALIDATE : Measurement.Split.TRAIN, i + 2));
        }
        Diagnosis d = Diagnoser.diagnose(robot, new MeasurementSet("warm.csv", Map.of(), "base", train),
                new MeasurementSet("warm.csv", Map.of(), "base", val));
        List<String> named = d.effects().stream().map(f -> f.effect().label()).toList();
        double floor = Math.sqrt(3) * sigma;
        assertTrue(d.geometricValidateRmsM() > 2 * floor, "the growth matters: " + d.geometricValidateRmsM() / floor);
        // one uniform strain with one time constant for two bodies and links of steel and aluminium: near the floor, not at it
        assertTrue(d.finalValidateRmsM() < 1.3 * floor, "validation " + d.finalValidateRmsM() / floor + " x floor; " + named + "; notes " + d.notes());
        assertEquals(1, named.size(), "named " + named + "; notes " + d.notes());
        assertTrue(named.get(0).startsWith("thermal-expansion (time proxy") && named.get(0).endsWith("cooling in pauses)"), "named " + named);
        String words = d.effects().get(0).words();
        assertTrue(words.contains("while the robot stood from"), words);
    }
}
