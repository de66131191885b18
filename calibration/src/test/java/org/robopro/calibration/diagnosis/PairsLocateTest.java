package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import org.junit.jupiter.api.Test;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
import org.robopro.world.JointError;
import org.robopro.world.Readings;
import org.robopro.world.Scenario;

/**
 * The locate scan on distances between pairs of poses (a ballbar, a length artefact): a residual
 * row depends on both poses, so each probe is its per-pose signature at the second pose minus
 * that at the first, each at its own joints. Truth: the independent world simulator's campaigns
 * read as lengths between consecutive poses ({@link Readings#pairs}) and parsed by the product's
 * reader like a user's file.
 */
class PairsLocateTest {
    private static final RobotDescription IRB2000 = RobotLibrary.shipped("irb2000");

    record Trial(Scenario.Trial world, Diagnosis diagnosis) { }

    static Trial diagnose(String scenario, long seed, int poses) {
        Scenario.Trial t = Scenario.named(scenario).trial(seed, p -> p.withPoses(poses, 100));
        MultiPointDiagnosisTest.Data c = MultiPointDiagnosisTest.read("bar.csv", Readings.pairs(t.world(), IRB2000, t.campaign(), seed));
        assertTrue(c.train().isPairs());
        return new Trial(t, Diagnoser.diagnose(IRB2000, c.train(), c.validate()));
    }

    private static List<String> families(Diagnosis d) {
        return d.effects().stream().filter(f -> !f.effect().isFallback()).map(f -> f.effect().label()).toList();
    }

    @Test
    void bumpInJoint3_isLocatedOnJoint3_notNamed_andItsPlotPeaksWhereTheBumpIs() {
        Trial t = diagnose("outside: bump in the angle of j3", 5, 250);
        Diagnosis d = t.diagnosis();
        JointError.Bump bump = t.world().world().errors().stream().filter(e -> e instanceof JointError.Bump)
                .map(e -> (JointError.Bump) e).findFirst().orElseThrow();
        assertEquals(List.of(), families(d), "named a family for a bump outside every family; notes " + d.notes());
        Diagnosis.Located l = d.located().stream().filter(x -> x.stage().equals("geometric")).findFirst().orElseThrow(
                () -> new AssertionError("nothing located: " + d.notes()));
        assertEquals("joint 3 angle", l.variable(), d.located().toString());
        assertTrue(l.words().contains("in the measured distances"), l.words());
        assertTrue(l.share() > 0.8, l.words());
        // The plot puts each length at the pose of the pair that carries more of the change: where
        // the fitted change is largest, that pose's joint 3 is on the world's bump.
        Diagnosis.Plot p = l.plot();
        assertEquals(p.x().length, p.y().length);
        assertTrue(p.xLabel().contains("joint 3 angle") && p.xLabel().contains("pair"), p.xLabel());
        Integer[] order = new Integer[p.curveY().length];
        for (int i = 0; i < order.length; i++) order[i] = i;
        Arrays.sort(order, (a, b) -> Double.compare(p.curveY()[b], p.curveY()[a]));
        double centre = Math.toDegrees(bump.centre()), width = Math.toDegrees(bump.width());
        for (int i = 0; i < 10; i++)
            assertEquals(centre, p.curveX()[order[i]], 1.5 * width, "largest fitted changes at q3 " + p.curveX()[order[i]]);
        // and the residuals along the change follow the fitted change (a structure, not noise)
        assertTrue(correlation(p.y(), p.curveY()) > 0.9, "correlation " + correlation(p.y(), p.curveY()));
        assertTrue(d.finalValidateRmsM() < 0.3 * d.geometricValidateRmsM(), d.finalValidateRmsM() + " vs " + d.geometricValidateRmsM());
    }

    @Test
    void cycloidalJoint1_stageHarmonicsLocatedAtTheWorldsHarmonics_andNamed() {
        Trial t = diagnose("transmission error j1, cycloidal k up to 40", 5, 250);
        Diagnosis d = t.diagnosis();
        JointError.Harmonics truth = t.world().world().errors().stream().filter(e -> e instanceof JointError.Harmonics)
                .map(e -> (JointError.Harmonics) e).findFirst().orElseThrow();
        Set<Integer> stages = new TreeSet<>();
        for (int k : truth.k()) if (k > 3) stages.add(k);
        Set<Integer> located = new TreeSet<>();
        for (Diagnosis.Located l : d.located()) {
            assertEquals("joint 1 angle", l.variable(), l.words());
            java.util.regex.Matcher m = java.util.regex.Pattern.compile("^(\\d+) cycles? per turn of joint 1$").matcher(l.shape());
            if (m.find()) located.add(Integer.parseInt(m.group(1)));
        }
        assertTrue(located.containsAll(stages), "world harmonics " + Arrays.toString(truth.k()) + ", located " + located);
        assertEquals(1, d.effects().size(), d.notes().toString());
        assertTrue(d.effects().get(0).effect().label().startsWith("gear-periodic j1"), d.effects().get(0).effect().label());
        assertTrue(d.finalValidateRmsM() < 1.2 * d.noiseFloorM(), d.finalValidateRmsM() + " vs floor " + d.noiseFloorM());
    }

    @Test
    void nothingConcealed_locatesNothing() {
        for (long seed : new long[] {3, 8}) {
            Diagnosis d = diagnose("null irb2000", seed, 200).diagnosis();
            assertEquals(List.of(), d.effects().stream().map(f -> f.effect().label()).toList(), "seed " + seed + ": " + d.notes());
            assertEquals(List.of(), d.located(), "seed " + seed);
            assertTrue(d.warnings().isEmpty(), d.warnings().toString());
        }
    }

    static double correlation(double[] a, double[] b) {
        double ma = Arrays.stream(a).average().orElse(0), mb = Arrays.stream(b).average().orElse(0), sab = 0, saa = 0, sbb = 0;
        for (int i = 0; i < a.length; i++) {
            sab += (a[i] - ma) * (b[i] - mb);
            saa += (a[i] - ma) * (a[i] - ma);
            sbb += (b[i] - mb) * (b[i] - mb);
        }
        return sab / Math.sqrt(saa * sbb);
    }
}
