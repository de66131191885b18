package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.measurement.MeasurementReader;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.models.JointDescription;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
import org.robopro.world.Readings;
import org.robopro.world.Scenario;

/**
 * Diagnosis of campaigns with several reflectors per pose and of distance-only campaigns. Truth:
 * the independent world simulator's robots and campaigns (org.robopro.world), read again by other
 * instruments ({@link Readings}) and parsed by the product's reader like a user's file.
 */
class MultiPointDiagnosisTest {
    private static final RobotDescription IRB2000 = RobotLibrary.shipped("irb2000");
    /** Three SMRs on the flange, m: a triangle 60 mm across, 95 mm out. */
    static final double[][] SMR = {{0.060, 0, 0.095}, {-0.030, 0.052, 0.095}, {-0.030, -0.052, 0.095}};

    record Data(MeasurementSet train, MeasurementSet validate) { }

    static Data read(String name, String text) {
        MeasurementSet all = MeasurementReader.parse(name, text, IRB2000.joints().stream().map(JointDescription::type).toList());
        return new Data(all.split(Measurement.Split.TRAIN), all.split(Measurement.Split.VALIDATE));
    }

    static Data smr(String scenario, long seed, int poses) {
        Scenario.Trial t = Scenario.named(scenario).trial(seed, p -> p.withPoses(poses, 100));
        return read("smr.csv", Readings.points(t.world(), IRB2000, t.campaign(), SMR, seed));
    }

    static Data distances(String scenario, long seed, int poses, double[] anchor, boolean given) {
        Scenario.Trial t = Scenario.named(scenario).trial(seed, p -> p.withPoses(poses, 100));
        return read("wire.csv", Readings.distances(t.world(), IRB2000, t.campaign(), anchor, given, seed));
    }

    private static List<String> labels(Diagnosis d) { return d.effects().stream().map(f -> f.effect().label()).toList(); }

    @Test
    void threeSmrs_concealedBacklash_isNamed_andEvidenceSpeaksOfPoints() {
        Data c = smr("lost motion j2, directions recorded", 5, 200);
        assertEquals(3, c.train().pointCount());
        Diagnosis d = Diagnoser.diagnose(IRB2000, c.train(), c.validate());
        assertEquals(List.of("backlash j2"), labels(d), d.notes().toString());
        Diagnosis.Finding f = d.effects().get(0);
        assertTrue(f.values()[0] > 0, "lost motion lags: " + f.values()[0]);
        assertTrue(d.finalValidateRmsM() < 0.5 * d.geometricValidateRmsM(), d.finalValidateRmsM() + " vs " + d.geometricValidateRmsM());
        // the noise per axis is the simulated 0.02 mm, seen through all three points
        assertEquals(0.02e-3, d.sigmaM(), 0.004e-3);
        assertEquals(Math.sqrt(3) * d.sigmaM(), d.noiseFloorM(), 1e-12);
        assertEquals("points", d.measurementWords());
        for (Diagnosis.Located l : d.located()) assertTrue(l.words().contains("at the measured points"), l.words());
    }

    @Test
    void threeSmrs_pointSaggingWithReach_isLocatedAtThePointsAndNoFamilyNamed() {
        Data c = smr("outside: measured point sags with reach", 4, 200);
        Diagnosis d = Diagnoser.diagnose(IRB2000, c.train(), c.validate());
        List<String> families = d.effects().stream().filter(f -> !f.effect().isFallback()).map(f -> f.effect().label()).toList();
        assertEquals(List.of(), families, "named a family for a sag outside every family; notes " + d.notes());
        assertTrue(d.located().stream().anyMatch(l -> l.variable().equals("reach of the measured point")), d.located().toString());
        // the structure's evidence plot has a dot per measured point
        Diagnosis.Located reach = d.located().stream().filter(l -> l.variable().equals("reach of the measured point")).findFirst().orElseThrow();
        assertEquals(3 * c.train().size() - 3 * d.outliers().size(), reach.plot().x().length);
    }

    @Test
    void threeSmrs_nothingConcealed_namesNothing() {
        Data c = smr("null irb2000", 3, 150);
        Diagnosis d = Diagnoser.diagnose(IRB2000, c.train(), c.validate());
        assertEquals(List.of(), labels(d), d.notes().toString());
        assertTrue(d.warnings().isEmpty(), d.warnings().toString());
        assertTrue(d.finalTrainRmsM() < 1.2 * d.noiseFloorM(), d.finalTrainRmsM() + " vs floor " + d.noiseFloorM());
    }

    @Test
    void distancesOnly_concealedBacklash_namedOrNothingWrong_andSaysWhatLengthsCannotTell() {
        Data c = distances("lost motion j2, directions recorded", 5, 250, new double[] {1.3, -0.4, 0.05}, false);
        assertTrue(c.train().isDistance());
        Diagnosis d = Diagnoser.diagnose(IRB2000, c.train(), c.validate());
        // lengths to an unknown anchor still show joint 2's lost motion: each length changes with it at most poses
        assertEquals(List.of("backlash j2"), labels(d), d.notes().toString());
        assertTrue(d.finalValidateRmsM() < 0.5 * d.geometricValidateRmsM(), d.finalValidateRmsM() + " vs " + d.geometricValidateRmsM());
        assertTrue(d.notes().stream().anyMatch(n -> n.contains("distance-only data") && n.contains("across the line to the anchor")),
                d.notes().toString());
        assertEquals(d.sigmaM(), d.noiseFloorM(), 1e-15, "one component per distance");
        assertEquals("distances", d.measurementWords());
    }

    @Test
    void pairsOfPoses_concealedBacklash_testedAtBothPoses_andSaysWhatPairsCannotTell() {
        Scenario.Trial t = Scenario.named("lost motion j2, directions recorded").trial(5, p -> p.withPoses(250, 100));
        Data c = read("bar.csv", Readings.pairs(t.world(), IRB2000, t.campaign(), 5));
        assertTrue(c.train().isPairs());
        Diagnosis d = Diagnoser.diagnose(IRB2000, c.train(), c.validate());
        assertEquals(List.of("backlash j2"), labels(d), d.notes().toString());
        // the lost motion the world concealed, against the one found at both poses of every pair
        double truth = t.world().errors().stream().filter(x -> x instanceof org.robopro.world.JointError.LostMotion)
                .mapToDouble(x -> ((org.robopro.world.JointError.LostMotion) x).width()).findFirst().orElseThrow();
        Diagnosis.Finding f = d.effects().get(0);
        assertEquals(truth, f.values()[0], Math.max(4 * f.sigmas()[0], 0.1 * truth), "found " + f.values()[0] + " ± " + f.sigmas()[0]);
        assertTrue(d.finalValidateRmsM() < 0.5 * d.geometricValidateRmsM(), d.finalValidateRmsM() + " vs " + d.geometricValidateRmsM());
        assertTrue(d.notes().stream().anyMatch(n -> n.startsWith("distances between pairs of poses") && n.contains("locate scan")),
                d.notes().toString());
        assertEquals("distances", d.measurementWords());
    }

    @Test
    void pairsOfPoses_nothingConcealed_namesNothing() {
        Scenario.Trial t = Scenario.named("null irb2000").trial(3, p -> p.withPoses(200, 100));
        Data c = read("bar.csv", Readings.pairs(t.world(), IRB2000, t.campaign(), 3));
        Diagnosis d = Diagnoser.diagnose(IRB2000, c.train(), c.validate());
        assertEquals(List.of(), labels(d), d.notes().toString());
        assertEquals(0.02e-3, d.sigmaM(), 0.005e-3);
    }

    @Test
    void distancesOnly_nothingConcealed_namesNothing() {
        Data c = distances("null irb2000", 3, 200, new double[] {1.3, -0.4, 0.05}, true);
        Diagnosis d = Diagnoser.diagnose(IRB2000, c.train(), c.validate());
        assertEquals(List.of(), labels(d), d.notes().toString());
        assertEquals(0.02e-3, d.sigmaM(), 0.005e-3);
    }
}
