package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.WorldCampaigns;
import org.robopro.calibration.identification.CalibrationResult;
import org.robopro.calibration.identification.Calibrator;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.kinematics.KinematicModel;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
import org.robopro.world.Readings;
import org.robopro.world.Scenario;

/**
 * The locate scan tells most probes apart from their Gram matrices: XᵀX = SᵀS − (UᵀS)ᵀ(UᵀS) −
 * (BᵀS)ᵀ(BᵀS) for the raw columns S, the model's span U and a structure found B. Its p must be
 * the p of the F test on the columns projected out explicitly (Gram–Schmidt), probe by probe,
 * alone and beside a structure, on single poses and on distances between pairs of poses.
 */
class ScanGramTest {

    private static final RobotDescription IRB2000 = RobotLibrary.shipped("irb2000");

    @Test
    void gramP_isTheProjectedTestsP_singlePoses() {
        WorldCampaigns.Sim c = WorldCampaigns.of(Scenario.named("lost motion j2 + thermal growth per link").trial(11, p -> p.withPoses(120, 40)));
        check(c.train(), c.validation());
    }

    @Test
    void gramP_isTheProjectedTestsP_pairsOfPoses() {
        Scenario.Trial tr = Scenario.named("lost motion j2, directions recorded").trial(5, p -> p.withPoses(120, 40));
        MultiPointDiagnosisTest.Data c = MultiPointDiagnosisTest.read("bar.csv", Readings.pairs(tr.world(), IRB2000, tr.campaign(), 5));
        check(c.train(), c.validate());
    }

    private static void check(MeasurementSet train, MeasurementSet validate) {
        KinematicModel model = KinematicModel.build(IRB2000);
        CalibrationResult geo = Calibrator.calibrate(model, train, validate, Calibrator.Options.defaults());
        GravityTorques gravity = new GravityTorques(model, IRB2000.massModel().orElseThrow());
        Diagnoser.Work w = new Diagnoser.Work(model, gravity, train.rows(), geo, validate, Diagnoser.Options.defaults());
        Diagnoser.Fit fit = w.fit(List.of(), new IdentityHashMap<>(), w.geoFull, null);
        Diagnoser.Tester t = w.tester(fit);
        List<Locator.Probe> probes = Locator.probes(t, Directions.Source.RECORDED);
        // the structure beside: the kept columns of the probe that explains most
        Diagnoser.Candidate strongest = null;
        for (Locator.Probe p : probes) {
            Diagnoser.Candidate cand = Locator.test(t, p, new double[0], 0, 0);
            if (cand != null && (strongest == null || cand.drss > strongest.drss)) strongest = cand;
        }
        assertTrue(strongest != null && strongest.p < 1e-6, "the campaign has a structure to stand beside");
        double[] block = strongest.basis;
        int nb = strongest.df1, m = t.m;
        double[] resBeside = Diagnoser.projectOut(block, nb, m, t.rPerp);
        double rssAlone = sumSq(t.rPerp), rssBeside = sumSq(resBeside);
        int compared = 0, significant = 0, absorbed = 0;
        for (Locator.Probe p : probes) {
            if (p.raw == null) continue;
            List<String> names = new ArrayList<>();
            for (int col = 0; col < p.k; col++) names.add("c" + col);
            for (boolean beside : new boolean[] {false, true}) {
                Locator.Gram g = new Locator.Gram(p);
                Diagnoser.Candidate exact;
                double gp;
                if (beside) {
                    double[] left = Diagnoser.projectOut(block, nb, m, p.s(), p.k);
                    exact = t.testProjected(left, p.n0, p.k, names, block, nb, 0, true);
                    g.remove(block, nb);
                    gp = g.p(t, resBeside, rssBeside, nb);
                } else {
                    exact = t.testProjected(p.s(), p.n0, p.k, names, new double[0], 0, 0);
                    gp = g.p(t, t.rPerp, rssAlone, 0);
                }
                String what = p.shape + (beside ? ", beside the structure" : "");
                if (gp == 0 && exact.p > 0) continue; // a column's share left at the bound: the scan tests it exactly
                if (exact.keptColumns == 0) {
                    assertTrue(Double.isNaN(gp), what + ": no column kept, yet p " + gp);
                    absorbed++;
                    continue;
                }
                compared++;
                if (exact.p < 1e-3) significant++;
                if (exact.p == 0) { assertEquals(0, gp, what); continue; }
                double le = Math.log(exact.p), lg = Math.log(gp);
                assertTrue(Math.abs(le - lg) <= 1e-6 * Math.max(1, Math.abs(le)), what + ": p " + gp + " from the Gram matrix, " + exact.p + " exactly");
            }
        }
        assertTrue(compared > 100, "probes compared: " + compared);
        assertTrue(significant > 5, "significant ones among them: " + significant);
        assertTrue(compared > absorbed, "absorbed: " + absorbed);
    }

    private static double sumSq(double[] x) {
        double s = 0;
        for (double v : x) s += v * v;
        return s;
    }
}
