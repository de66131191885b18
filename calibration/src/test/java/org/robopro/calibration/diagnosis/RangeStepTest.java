package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.robopro.calibration.PoseConditions;
import org.robopro.calibration.WorldCampaigns;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.RobotFile;
import org.robopro.models.RobotLibrary;
import org.robopro.models.Vec3;
import org.robopro.world.Scenario;

/**
 * A laser tracker takes its distance again from the absolute distance meter whenever the beam is
 * broken, and that meter's error stays until the next break. The world's campaign with such
 * breaks (a form outside every family): the diagnosis locates jumps of the instrument's distances
 * at the world's own break times, names nothing, and the model reaches its twin's error. A smooth
 * change of the distances (the air) is not taken for jumps.
 */
class RangeStepTest {
    @Test
    void beamBreaks_locatedAtTheWorldsBreaks_nothingNamed() {
        WorldCampaigns.Sim s = WorldCampaigns.of(
                Scenario.named("outside: the tracker's distance taken again at every beam break, sigma 0.005 mm").trial(20261126));
        Diagnosis d = Diagnoser.diagnose(s.nominal(), s.train(), s.validation());
        assertTrue(d.effects().stream().allMatch(f -> f.effect().isFallback()), "nothing may be named: " + d.effects());
        List<Effect> steps = d.effects().stream().map(f -> f.effect()).filter(e -> e.kind() == Effect.Kind.RANGE_STEP).toList();
        assertFalse(steps.isEmpty(), d.effects().toString());
        // each step between the training poses either side of one of the world's breaks (the world's own record)
        double[] breaks = s.world().tracker().resetS();
        double[] times = s.train().rows().stream().mapToDouble(Measurement::timeS).sorted().toArray();
        for (Effect e : steps) {
            int i = 0;
            while (i < times.length && times[i] <= e.tauS()) i++;
            double before = i > 1 ? times[i - 2] : 0, after = i + 1 < times.length ? times[i + 1] : Double.MAX_VALUE;
            assertTrue(Arrays.stream(breaks).anyMatch(b -> b > before && b <= after),
                    e.label() + " is not next to a break of the world's " + Arrays.toString(breaks));
        }
        assertTrue(d.finalValidateRmsM() < 1.15 * d.noiseFloorM(), d.finalValidateRmsM() / d.noiseFloorM() + " x the floor");
    }

    /**
     * The air along the beam warming against the tracker's weather station scales every distance
     * smoothly with time: a jump fitted to such a change predicts left-out poses no better than a
     * smooth scale, and no jump is reported (the world's draw where one did).
     */
    @Test
    void airWarming_isNoJump() {
        WorldCampaigns.Sim s = WorldCampaigns.of(Scenario.named("outside: the tracker's air compensation drifts as the hall warms").trial(20261125));
        Diagnosis d = Diagnoser.diagnose(s.nominal(), s.train(), s.validation());
        assertTrue(d.effects().stream().noneMatch(f -> f.effect().kind() == Effect.Kind.RANGE_STEP), d.effects() + " " + d.notes());
        assertTrue(d.effects().stream().anyMatch(f -> f.effect().kind() == Effect.Kind.INSTRUMENT_SCALE), d.effects().toString());
        assertTrue(d.effects().stream().allMatch(f -> f.effect().isFallback()), d.effects().toString());
    }

    /** A scale of the distances with seven functions of time reads back with seven. */
    @Test
    void robotFile_roundTrip_instrumentScaleResolution() {
        KinematicModel model = KinematicModel.build(RobotLibrary.shipped("irb2400"));
        Pose inst = Pose.translation(0.4, -2.1, 0.3);
        Effect e = Effect.instrumentScale(Effect.Along.TIME, inst, 0, 5000, 7);
        double[] v = {1e-6, -2e-6, 3e-6, 0, 2e-6, -1e-6, 4e-6};
        String text = RobotFile.format(new ExtendedModel(model, List.of(new Effect.Term(e, v))).toDescription());
        Effect back = ExtendedModel.of(RobotFile.parse("x.robot.json", text), "x.robot.json").terms().get(0).effect();
        assertEquals("instrument-scale (time, 7 functions)", back.label());
        assertEquals(7, back.basisCount());
        PoseConditions c = new PoseConditions(null, 1800, Double.NaN, Double.NaN);
        Vec3 p = new Vec3(1.1, 0.2, 0.9);
        assertEquals(0, e.displacement(v, new double[6], c, p).minus(back.displacement(v, new double[6], c, p)).norm(), 1e-15);
    }

    /** A jump of the distances, written to a robot file and read back, moves the same point by the same amount. */
    @Test
    void robotFile_roundTrip() {
        KinematicModel model = KinematicModel.build(RobotLibrary.shipped("irb2400"));
        Pose inst = Pose.translation(0.4, -2.1, 0.3).times(Pose.rotAxis(new Vec3(0, 0, 1), 0.7));
        Effect e = Effect.rangeStep(inst, 1234.5);
        double[] v = {12e-6};
        ExtendedModel ext = new ExtendedModel(model, List.of(new Effect.Term(e, v)));
        String text = RobotFile.format(ext.toDescription());
        Effect back = ExtendedModel.of(RobotFile.parse("x.robot.json", text), "x.robot.json").terms().get(0).effect();
        assertEquals(e.label(), back.label());
        double[] q = new double[6];
        Vec3 p = new Vec3(1.1, 0.2, 0.9);
        for (double time : new double[] {100, 1234.5, 2000}) {
            PoseConditions c = new PoseConditions(null, time, Double.NaN, Double.NaN);
            Vec3 a = e.displacement(v, q, c, p), b = back.displacement(v, q, c, p);
            assertEquals(0, a.minus(b).norm(), 1e-15);
            // before the jump: −d along the line of sight from the instrument, after it nothing
            Vec3 sight = inst.inverse().position().minus(p).times(-1);
            double along = a.dot(sight.times(1 / sight.norm()));
            assertEquals(time <= 1234.5 ? -12e-6 : 0, along, 1e-12);
            assertEquals(Math.abs(along), a.norm(), 1e-12);
        }
    }
}
