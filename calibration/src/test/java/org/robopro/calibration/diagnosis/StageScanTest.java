package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.WorldCampaigns;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.models.RobotLibrary;

/**
 * Reducer stages at orders the harmonic scan does not reach, against truth written here: a world
 * campaign with geometric errors only (org.robopro.world: its own kinematics, nothing shared with
 * {@link Effect}) whose joint readings are then made to lie by a stage error. The output angle is
 * what the world measured, q_out; the controller reads r with r + δ(r) = q_out (solved by
 * fixed-point iteration), written with the file's four decimals of a degree. δ is a sum of sines
 * of the joint angle at the stage orders, whole or not.
 */
class StageScanTest {

    /** δ(r) = Σ a_i sin(n_i r + φ_i) on one joint. */
    record Stage(int joint, double[] n, double[] aDeg, double[] phase) {
        double delta(double r) {
            double s = 0;
            for (int i = 0; i < n.length; i++) s += Math.toRadians(aDeg[i]) * Math.sin(n[i] * r + phase[i]);
            return s;
        }
    }

    /** The set with each row's reading of the stage's joint replaced by what a controller behind that stage reads. */
    static MeasurementSet readBehind(MeasurementSet set, Stage st) {
        List<Measurement> rows = new ArrayList<>();
        for (Measurement m : set.rows()) {
            double[] q = m.q().clone();
            double out = q[st.joint()], r = out;
            for (int it = 0; it < 50; it++) r = out - st.delta(r);
            q[st.joint()] = Math.toRadians(Math.rint(Math.toDegrees(r) * 1e4) / 1e4);
            rows.add(m.withQ(q));
        }
        return new MeasurementSet(set.source(), set.metadata(), set.frame(), rows, set.pointNames(), set.anchor());
    }

    /**
     * An RV reducer on joint 2 of the IRB 2400, total ratio 81: its input stage repeats 81 times per
     * output turn, beside the once and twice per turn of the output stage. 300 poses resolve harmonics
     * up to 60 only; the stage scan places 81, and the line is modelled as a shaft's turn, not named a
     * gear's: at the total ratio the input stage turns with the motor, whose angle sensor's error
     * repeats there alike. No gear is named with an order above 40, and the validation poses come
     * down to the floor.
     */
    @Test
    void rvReducerInputStage_isLocatedAt81CyclesPerTurnAsAShaftsTurn() {
        Stage truth = new Stage(1, new double[] {1, 2, 81}, new double[] {0.006, 0.007, 0.0075}, new double[] {0.6, 5.0, 4.4});
        var desc = RobotLibrary.shipped("irb2400");
        WorldCampaigns.Sim c = WorldCampaigns.geometric(desc, 5, false, p -> p.withPoses(300, 100).withSigma(1.2e-5));
        Diagnosis d = Diagnoser.diagnose(desc, readBehind(c.train(), truth), readBehind(c.validation(), truth));
        Effect shaft = d.effects().stream().map(Diagnosis.Finding::effect).filter(Effect::shaftOrders).findFirst()
                .orElseThrow(() -> new AssertionError(d.effects().toString()));
        assertEquals(1, shaft.joint(), "joint 2");
        assertTrue(Arrays.stream(shaft.orders()).anyMatch(x -> x == 81), shaft.label());
        assertTrue(shaft.isFallback(), shaft.label());
        assertTrue(d.effects().stream().filter(f -> !f.effect().isFallback())
                .allMatch(f -> Arrays.stream(f.effect().orders()).allMatch(x -> x <= Effect.SHAFT_ORDER)), d.effects().toString());
        assertTrue(d.finalValidateRmsM() < 1.15 * c.floorM(), d.finalValidateRmsM() + " vs floor " + c.floorM());
        assertTrue(d.located().stream().anyMatch(l -> l.words().contains("81 cycles per turn of joint 2 (a stage turning 81 times per output turn)")),
                d.located().stream().map(Diagnosis.Located::words).toList().toString());
    }

    /** Geometry and noise only, readings to four decimals: the stage scan finds no stage. */
    @Test
    void geometryAndNoise_noStage() {
        for (String robot : new String[] {"irb2400", "puma560"}) {
            var desc = RobotLibrary.shipped(robot);
            WorldCampaigns.Sim c = WorldCampaigns.geometric(desc, 11, false, p -> p.withPoses(300, 0).withSigma(1e-5));
            Stage none = new Stage(0, new double[0], new double[0], new double[0]);
            Diagnosis d = Diagnoser.diagnose(desc, readBehind(c.train(), none), null);
            assertEquals(List.of(), HeldOutFormsTest.families(d), robot + ": " + d.notes());
            assertTrue(d.located().stream().noneMatch(l -> l.words().contains("a stage turning")), robot + ": " + d.located());
        }
    }

    /** The reading's rounding step is read from the decimals, and the highest order follows from it. */
    @Test
    void readingStepAndHighestOrder() {
        assertEquals(1e-4, StageScan.readingStep(new double[] {12.3456, -0.0001, 90}), 1e-12);
        assertEquals(0.01, StageScan.readingStep(new double[] {12.34, -0.05}), 1e-12);
        // 0.01 deg readings: the phase of order f moves by f·0.01°/√12 rms; 0.1 rad allows about 1985 cycles per turn, capped at 1000
        assertEquals(StageScan.MAX_ORDER, StageScan.maxOrder(new double[] {12.34, -0.05}), 1e-9);
        // 0.1 deg readings: about 198 cycles per turn
        assertEquals(0.1 * Math.sqrt(12) / Math.toRadians(0.1), StageScan.maxOrder(new double[] {12.3, -0.5}), 1e-6);
        assertEquals("7.1", Effect.orderText(7.1));
        assertEquals("81", Effect.orderText(81));
    }

    /** A gear-periodic effect holding an order that is not whole: its columns, names and label. */
    @Test
    void periodicWithAnOrderThatIsNotWhole() {
        Effect e = Effect.periodic(0, new int[] {1, 2, 3}, new double[] {7.1, 81});
        assertEquals(List.of("a1", "b1", "a2", "b2", "a3", "b3", "a81", "b81", "a7.1", "b7.1"), e.parameterNames());
        assertEquals("gear-periodic j1 (h 1,2,3,81,7.1)", e.label());
        double[] g = new double[e.size()], q = {0.37, 0, 0, 0, 0, 0};
        e.regressor(q, org.robopro.calibration.PoseConditions.NONE, g);
        assertEquals(Math.sin(7.1 * 0.37), g[8], 1e-15);
        assertEquals(Math.cos(81 * 0.37), g[7], 1e-15);
    }
}
