package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.WorldCampaigns;
import org.robopro.kinematics.KinematicModel;
import org.robopro.models.RobotFile;
import org.robopro.models.RobotLibrary;
import org.robopro.models.Vec3;
import org.robopro.world.JointError;
import org.robopro.world.Scenario;

/**
 * A motor's resolver error seen at its joint (the world's {@link JointError.MotorSensor}: the
 * output off by the sensor's error over the gear ratio, repeating N and 2N times per output turn,
 * N not whole). The diagnosis locates the lines at the world's own ratio, models them, and names
 * no gear: the output's measurements cannot tell a motor's sensor from the reducer's input stage.
 */
class MotorSensorTest {

    /** The world's motor sensor on the scenario's drive. */
    private static JointError.MotorSensor sensor(WorldCampaigns.Sim s) {
        return s.world().errors().stream().filter(e -> e instanceof JointError.MotorSensor).map(e -> (JointError.MotorSensor) e)
                .findFirst().orElseThrow();
    }

    /**
     * Whether {@code e} holds a line within half a cycle per turn of {@code order}: over joint 3's
     * sampled half turn two lines a cycle or two apart are told apart only just (the Rayleigh
     * resolution), and the line's place is refined to a fraction of that.
     */
    private static boolean hasOrder(Effect e, double order) {
        return Arrays.stream(e.orders()).anyMatch(f -> Math.abs(f - order) < 0.5);
    }

    @Test
    void resolverAlone_locatedAtTheWorldsGearRatio_nothingNamed() {
        for (long seed : new long[] {20261124, 20261126}) {
            WorldCampaigns.Sim s = WorldCampaigns.of(Scenario.named("outside: motor resolver error of j3 at its gear ratio").trial(seed));
            Diagnosis d = Diagnoser.diagnose(s.nominal(), s.train(), s.validation());
            assertTrue(d.effects().stream().allMatch(f -> f.effect().isFallback()), "seed " + seed + ": nothing may be named: " + d.effects());
            double n = sensor(s).ratio();
            Effect shaft = d.effects().stream().map(Diagnosis.Finding::effect).filter(Effect::shaftOrders).findFirst()
                    .orElseThrow(() -> new AssertionError("seed " + seed + ": " + d.effects() + ", located " + d.located()));
            assertEquals(3, shaft.joint() + 1);
            assertTrue(hasOrder(shaft, n), "seed " + seed + ": " + shaft.label() + " against the world's ratio " + n);
            assertTrue(shaft.label().startsWith("shaft-periodic j3"), shaft.label());
            assertTrue(d.finalValidateRmsM() < 1.15 * d.noiseFloorM() && d.geometricValidateRmsM() > 1.15 * d.noiseFloorM(),
                    "seed " + seed + ": " + d.geometricValidateRmsM() / d.noiseFloorM() + " -> " + d.finalValidateRmsM() / d.noiseFloorM() + " x the floor");
        }
    }

    /**
     * Beside a gear-ratio error of joint 1, whose residual raises the whole spectrum at first, the
     * motor's lines are found once the ratio is modelled: the ratio is named, the lines located.
     */
    @Test
    void resolverBesideAGearRatio_ratioNamed_linesLocatedOnceItIsModelled() throws Exception {
        WorldCampaigns.Sim s = WorldCampaigns.of(
                Scenario.named("motor resolver error of j3 at its gear ratio (outside) + gear-ratio error j1").trial(20261125));
        Diagnosis d = Diagnoser.diagnose(s.nominal(), s.train(), s.validation());
        List<String> named = d.effects().stream().filter(f -> !f.effect().isFallback()).map(f -> f.effect().label()).toList();
        assertEquals(List.of("joint-scale j1"), named, "notes " + d.notes());
        assertTrue(d.effects().stream().anyMatch(f -> f.effect().shaftOrders() && hasOrder(f.effect(), sensor(s).ratio())),
                d.effects() + " against the world's ratio " + sensor(s).ratio());
        assertTrue(d.finalValidateRmsM() < 1.15 * d.noiseFloorM(), d.finalValidateRmsM() / d.noiseFloorM() + " x the floor");
        // the report names the shaft's curve and the orders its periodogram holds, not a gear's harmonics 1-3
        Effect shaft = d.effects().stream().map(Diagnosis.Finding::effect).filter(Effect::shaftOrders).findFirst().orElseThrow();
        String html = DiagnosisReport.html(d, new DiagnosisReport.Context("train.csv", "validate.csv", "now"));
        assertTrue(html.contains(">fitted shaft-periodic<"), "the evidence plot's legend");
        assertTrue(html.contains("Periodogram of the partial residual (modelled: " + String.join(", ",
                Arrays.stream(shaft.orders()).mapToObj(Effect::orderText).toList()) + " cycles per turn)"), "the periodogram's title");
    }

    /** A shaft's orders written to a robot file read back as the same located shape and move the joint alike. */
    @Test
    void robotFile_roundTrip() {
        KinematicModel model = KinematicModel.build(RobotLibrary.shipped("irb2000"));
        Effect e = Effect.periodic(2, new int[0], new double[] {66.387, 132.661});
        assertTrue(e.isFallback() && e.shaftOrders(), e.label());
        double[] v = {2e-5, -7e-6, 8e-6, 1.2e-5};
        String text = RobotFile.format(new ExtendedModel(model, List.of(new Effect.Term(e, v))).toDescription());
        Effect back = ExtendedModel.of(RobotFile.parse("x.robot.json", text), "x.robot.json").terms().get(0).effect();
        assertEquals("shaft-periodic j3 (66.387,132.661 per turn)", back.label());
        assertTrue(back.isFallback());
        // the same turn of joint 3 at an angle of joint 3 as the sinusoids give by hand
        double[] q = {0.1, -0.3, 0.4, 0.2, 0.5, -0.1};
        Measurement row = Measurement.of("p", q, new Vec3(1.1, 0.2, 0.9));
        double[] a = new double[6], b = new double[6];
        e.block(model).jointDelta(v, row, a, null);
        back.block(model).jointDelta(v, row, b, null);
        double byHand = v[0] * Math.sin(66.387 * q[2]) + v[1] * Math.cos(66.387 * q[2]) + v[2] * Math.sin(132.661 * q[2])
                + v[3] * Math.cos(132.661 * q[2]);
        assertEquals(byHand, b[2], 1e-15);
        assertEquals(a[2], b[2], 1e-15);
        // a whole order above the output's own is a shaft's too; one within them, whole or not, a gear's
        assertTrue(Effect.periodic(2, new int[] {81}).isFallback());
        assertTrue(!Effect.periodic(2, new int[0], new double[] {7.1}).isFallback());
        assertTrue(!Effect.periodic(2, new int[] {1, 2, 3, 81}).isFallback());
    }
}
