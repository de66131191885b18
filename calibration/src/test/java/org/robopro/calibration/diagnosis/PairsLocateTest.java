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

    record Trial(Scenario.Trial world, Diagnosis diagnosis) {
        /** The world's concealed joint error of this type. */
        <T extends JointError> T truth(Class<T> type) {
            return world.world().errors().stream().filter(type::isInstance).map(type::cast).findFirst().orElseThrow();
        }
    }

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
        JointError.Bump bump = t.truth(JointError.Bump.class);
        assertEquals(List.of(), families(d), "named a family for a bump outside every family; notes " + d.notes());
        Diagnosis.Located l = d.located().stream().filter(x -> x.stage().equals("geometric")).findFirst().orElseThrow(
                () -> new AssertionError("nothing located: " + d.notes()));
        assertEquals("joint 3 angle", l.variable(), d.located().toString());
        assertTrue(l.words().contains("in the measured distances"), l.words());
        assertTrue(l.share() > 0.8, l.words());
        // The plot is joint 3's error at the pose of each pair that carries more of the change: the
        // dots follow the world's bump, and the fitted curve peaks where the bump is, as high.
        Diagnosis.Plot p = l.plot();
        assertEquals(p.x().length, p.y().length);
        assertTrue(p.x().length > 150, "lengths plotted: " + p.x().length);
        assertTrue(p.xLabel().contains("joint 3 angle") && p.xLabel().contains("pair") && p.yLabel().contains("mdeg"), p.xLabel() + " / " + p.yLabel());
        double[] truth = new double[p.x().length];
        for (int i = 0; i < truth.length; i++) {
            double u = (Math.toRadians(p.x()[i]) - bump.centre()) / bump.width();
            truth[i] = bump.amplitude() * Math.exp(-u * u);
        }
        assertTrue(correlation(p.y(), truth) > 0.9, "partial residuals against the world's bump: " + correlation(p.y(), truth));
        double sign = Math.signum(bump.amplitude());
        int peak = 0;
        for (int i = 0; i < p.curveY().length; i++) if (sign * p.curveY()[i] > sign * p.curveY()[peak]) peak = i;
        assertEquals(Math.toDegrees(bump.centre()), p.curveX()[peak], 0.3 * Math.toDegrees(bump.width()), "curve's peak");
        double lowest = Arrays.stream(p.curveY()).map(v -> sign * v).min().orElseThrow();
        assertEquals(Math.abs(Math.toDegrees(bump.amplitude()) * 1e3), sign * p.curveY()[peak] - lowest,
                0.25 * Math.abs(Math.toDegrees(bump.amplitude()) * 1e3), "bump height, mdeg");
        assertTrue(d.finalValidateRmsM() < 0.3 * d.geometricValidateRmsM(), d.finalValidateRmsM() + " vs " + d.geometricValidateRmsM());
        // the report draws it, titled by its variable (the long shape is in the words above it)
        String html = DiagnosisReport.html(d, new DiagnosisReport.Context("bar.csv", "bar.csv", "test"));
        assertTrue(html.contains("Evidence: joint 3 angle") && html.contains("partial residual"), "report's located plot");
    }

    @Test
    void cycloidalJoint1_stageHarmonicsLocatedAtTheWorldsHarmonics_andNamed() {
        Trial t = diagnose("transmission error j1, cycloidal k up to 40", 5, 250);
        Diagnosis d = t.diagnosis();
        JointError.Harmonics truth = t.truth(JointError.Harmonics.class);
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

    /**
     * A named effect's evidence on pairs: the partial residual of joint 2 at the pose of each pair
     * that carries more of the change, against that pose's approach direction. The world's lost
     * motion lags: the two columns of points sit the world's play apart, the +1 side below.
     */
    @Test
    void lostMotionOnPairs_itsEvidencePlotShowsTheWorldsPlayBetweenTheTwoDirections() {
        Trial t = diagnose("lost motion j2, directions recorded", 5, 250);
        Diagnosis d = t.diagnosis();
        assertEquals(List.of("backlash j2"), d.effects().stream().map(f -> f.effect().label()).toList(), d.notes().toString());
        double truth = t.truth(JointError.LostMotion.class).width();
        Diagnosis.Plot p = d.effects().get(0).plot();
        assertTrue(p != null && p.x().length > 150, "plotted " + (p == null ? "nothing" : p.x().length + " lengths"));
        assertTrue(p.xLabel().contains("pair"), p.xLabel());
        double up = 0, down = 0;
        int nUp = 0, nDown = 0;
        for (int i = 0; i < p.x().length; i++) {
            if (p.x()[i] > 0.5) { up += p.y()[i]; nUp++; } else if (p.x()[i] < -0.5) { down += p.y()[i]; nDown++; }
        }
        assertTrue(nUp > 30 && nDown > 30, nUp + " / " + nDown);
        double gapMdeg = down / nDown - up / nUp, truthMdeg = Math.toDegrees(truth) * 1e3;
        assertEquals(truthMdeg, gapMdeg, 0.15 * truthMdeg, "play between the two directions, mdeg");
    }

    /**
     * A smooth fallback's size (its plausibility and its words) is its angle-dependent part: a
     * constant is the joint's zero, which the geometry holds. On lengths between pairs of poses the
     * spline's constant is only nearly the zero's, came out at 0.24° beside a 0.01° error and made
     * the fallback "implausible" (a cycloidal joint 3 then left 5 x σ unmodelled).
     */
    @Test
    void smoothErrorSize_isItsAngleDependentPart() {
        Effect e = Effect.smooth(2, -0.9, 0.9, 7);
        double[] constant = new double[7], bump = new double[7];
        Arrays.fill(constant, Math.toRadians(0.25));
        bump[3] = Math.toRadians(0.01);
        assertEquals(0, Words.rmsSmooth(e, constant), 1e-12);
        double[] both = new double[7];
        for (int i = 0; i < 7; i++) both[i] = constant[i] + bump[i];
        assertEquals(Words.rmsSmooth(e, bump), Words.rmsSmooth(e, both), 1e-12);
        assertTrue(Words.rmsSmooth(e, bump) > Math.toRadians(0.001), "a bump has a size: " + Words.rmsSmooth(e, bump));
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

    /**
     * The fast signature of an effect on pairs (each pose's sensitivity times the effect's
     * regressor there, summed over the pair) against the identification's own measurement
     * function with the effect's block added (its Jacobian columns at v = 0), at a fit that already
     * carries an effect: the same numbers (effects on the measured point to 1e-3, see below).
     */
    @Test
    void pairSignature_isTheIdentificationsMeasurementFunction() {
        Scenario.Trial tr = Scenario.named("lost motion j2, directions recorded").trial(5, p -> p.withPoses(120, 40));
        MultiPointDiagnosisTest.Data c = MultiPointDiagnosisTest.read("bar.csv", Readings.pairs(tr.world(), IRB2000, tr.campaign(), 5));
        org.robopro.kinematics.KinematicModel model = org.robopro.kinematics.KinematicModel.build(IRB2000);
        org.robopro.calibration.identification.CalibrationResult geo = org.robopro.calibration.identification.Calibrator.calibrate(
                model, c.train(), c.validate(), org.robopro.calibration.identification.Calibrator.Options.defaults());
        GravityTorques gravity = new GravityTorques(model, IRB2000.massModel().orElseThrow());
        Diagnoser.Work w = new Diagnoser.Work(model, gravity, c.train().rows(), geo, c.validate(), Diagnoser.Options.defaults());
        Diagnoser.Fit fit = w.fit(List.of(Effect.backlash(1)), new java.util.IdentityHashMap<>(), w.geoFull, null);
        Diagnoser.Tester t = w.tester(fit);
        for (Effect e : List.of(Effect.backlash(2), Effect.periodic(1, new int[] {1, 7, 26}), Effect.smooth(2, -0.9, 0.9, 13),
                Effect.pair(1, 3), Effect.scale(4), Effect.coupling(2, 1), Effect.compliance(1, gravity), Effect.thermal(20),
                Effect.thermalLinks(model, 20), Effect.pointSmooth(Effect.Along.REACH, 0.5, 2.0))) {
            double[] fast = t.signature(e, w.conditions);
            int k = e.size();
            List<org.robopro.calibration.identification.EffectBlock> bl = new java.util.ArrayList<>(fit.problem.effects());
            bl.add(e.block(model));
            double[] full = Arrays.copyOf(fit.full, fit.full.length + k);
            var p = new org.robopro.calibration.identification.IdentificationProblem(model, w.rows, w.sixD, w.instrument, bl, full);
            p.setSigmas(fit.problem.sigmaPos(), fit.problem.sigmaRot());
            int nFull = p.fullSize();
            double[] jac = new double[t.m * nFull];
            p.evaluateFull(full, new double[t.m], jac);
            double scale = 0, diff = 0;
            for (int i = 0; i < t.m; i++)
                for (int col = 0; col < k; col++) {
                    double oracle = jac[i * nFull + nFull - k + col];
                    scale = Math.max(scale, Math.abs(oracle));
                    diff = Math.max(diff, Math.abs(oracle - fast[i * k + col]));
                }
            assertTrue(scale > 0, e.label() + ": no signature");
            // An effect on the measured point is taken at the point's place without the other effects'
            // small motions (and link growth along the robot file's links), the identification at its
            // exact place (millimetres over metres): the per-pose signature makes the same approximation.
            double tol = e.target() == Effect.Target.POSITION ? 1e-3 : 1e-6;
            assertTrue(diff <= tol * scale, e.label() + ": differs by " + diff + " of " + scale);
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
