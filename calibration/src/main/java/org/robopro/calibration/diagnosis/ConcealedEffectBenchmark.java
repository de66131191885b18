package org.robopro.calibration.diagnosis;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import java.util.Set;
import java.util.function.Consumer;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.calibration.simulation.Campaign;
import org.robopro.calibration.simulation.SimulationSettings;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
import org.robopro.models.Vec3;

/**
 * The concealed-effect benchmark (docs/diagnosis-benchmark.md): simulated IRB-2000 campaigns with random geometric
 * errors, one or two injected effects of realistic size (or none, or outliers), realistic extra
 * columns (approach directions from the pose sequence, a warm-up temperature curve with time,
 * payload changes when compliance is tested), random noise σ 0.01–0.05 mm and 100–300 poses;
 * each is diagnosed blind and scored: effects named right (and on the right joints), false
 * effects, validation RMS over the noise floor √3 σ on 100 further poses.
 */
public final class ConcealedEffectBenchmark {
    /** A benchmark case: the effects injected (sizes drawn, {@link EffectSpec#draw}) and whether outliers are added. */
    record Case(String name, List<EffectSpec> effects, boolean outliers) {
        /** Compliance cases vary the payload (the campaign writes payload_kg). */
        boolean payloadVaries() { return effects.stream().anyMatch(e -> e.kind() == Effect.Kind.COMPLIANCE); }
    }

    /** Scores of one case over its seeds. */
    public record Row(String name, int runs, int namedRight, int jointsRight, int runsWithFalse, double meanValRatio,
                      double maxValRatio, int outliersFound, int outliersInjected, int falseOutliers, double meanMs) { }

    /** Result of a benchmark run: rows per case and totals. */
    public record Result(List<Row> rows, int seedsPerCase, double namedRightPct, double jointsRightPct, int nullFalse,
                         int nullRuns, double worstCaseMeanValRatio, double meanValRatio, double maxMs300) {
        /** The bar the diagnosis must clear: ≥ 95 % named (and joints) right, no false effect on null cases, RMS ≤ 1.15 floor. */
        public boolean meetsBar() {
            return jointsRightPct >= 95 && nullFalse == 0 && worstCaseMeanValRatio <= 1.15;
        }

        public String markdown() {
            StringBuilder sb = new StringBuilder();
            sb.append("| case | runs | named right | joints right | runs with a false effect | val RMS / floor (mean) | (max) | outliers found | clean poses flagged | mean time (ms) |\n");
            sb.append("|---|---|---|---|---|---|---|---|---|---|\n");
            for (Row r : rows)
                sb.append(String.format(Locale.ROOT, "| %s | %d | %d | %d | %d | %.3f | %.3f | %s | %d | %.0f |%n", r.name(), r.runs(),
                        r.namedRight(), r.jointsRight(), r.runsWithFalse(), r.meanValRatio(), r.maxValRatio(),
                        r.outliersInjected() == 0 ? "-" : r.outliersFound() + "/" + r.outliersInjected(), r.falseOutliers(), r.meanMs()));
            sb.append(String.format(Locale.ROOT, "%nNamed right: %.1f %%; named and on the right joints: %.1f %%; "
                            + "false effects on null cases: %d of %d runs; validation RMS / noise floor: %.3f over all runs, "
                            + "%.3f in the worst case (mean over its seeds); slowest diagnosis of 250-300 poses: %.0f ms. Bar met: %s.%n",
                    namedRightPct, jointsRightPct, nullFalse, nullRuns, meanValRatio, worstCaseMeanValRatio, maxMs300,
                    meetsBar() ? "yes" : "NO"));
            return sb.toString();
        }
    }

    private ConcealedEffectBenchmark() { }

    static double uniform(Random r, double lo, double hi) { return EffectSpec.uniform(r, lo, hi); }

    // Effects with sizes drawn from EffectSpec's realistic ranges, joints 0-based here as in the case list.
    private static EffectSpec compliance(int joint) { return EffectSpec.of(Effect.Kind.COMPLIANCE, joint + 1); }
    private static EffectSpec periodic(int joint) { return EffectSpec.of(Effect.Kind.PERIODIC, joint + 1); }
    private static EffectSpec backlash(int joint) { return EffectSpec.of(Effect.Kind.BACKLASH, joint + 1); }
    private static EffectSpec thermal() { return EffectSpec.thermal(); }
    private static EffectSpec scale(int joint) { return EffectSpec.of(Effect.Kind.SCALE, joint + 1); }
    private static EffectSpec coupling(int target, int source) { return EffectSpec.coupling(target + 1, source + 1); }

    /** The cases of the benchmark (joints 0-based here, 1-based in names). */
    static List<Case> cases() {
        List<Case> c = new ArrayList<>();
        c.add(new Case("null (geometric errors only)", List.of(), false));
        c.add(new Case("null with outliers", List.of(), true));
        c.add(new Case("joint-compliance j2", List.of(compliance(1)), false));
        c.add(new Case("joint-compliance j3", List.of(compliance(2)), false));
        c.add(new Case("gear-periodic j1", List.of(periodic(0)), false));
        c.add(new Case("gear-periodic j2", List.of(periodic(1)), false));
        c.add(new Case("gear-periodic j3", List.of(periodic(2)), false));
        c.add(new Case("gear-periodic j5 (wrist)", List.of(periodic(4)), false));
        c.add(new Case("backlash j1", List.of(backlash(0)), false));
        c.add(new Case("backlash j2", List.of(backlash(1)), false));
        c.add(new Case("backlash j3", List.of(backlash(2)), false));
        c.add(new Case("thermal-expansion", List.of(thermal()), false));
        c.add(new Case("joint-scale j1", List.of(scale(0)), false));
        c.add(new Case("joint-scale j2", List.of(scale(1)), false));
        c.add(new Case("joint-coupling j3<-j2", List.of(coupling(2, 1)), false));
        c.add(new Case("joint-compliance j2 + j3", List.of(compliance(1), compliance(2)), false));
        c.add(new Case("backlash j2 + thermal-expansion", List.of(backlash(1), thermal()), false));
        c.add(new Case("gear-periodic j1 + joint-scale j3", List.of(periodic(0), scale(2)), false));
        c.add(new Case("joint-coupling j3<-j2 + backlash j1", List.of(coupling(2, 1), backlash(0)), false));
        c.add(new Case("backlash j2 with outliers", List.of(backlash(1)), true));
        return c;
    }

    /** One simulated campaign of a case, with what was injected. */
    record Trial(Campaign campaign, List<Effect.Term> truth, Set<String> outlierIds, double sigmaM) { }

    /** Builds the campaign of case {@code c} for a seed. */
    static Trial trial(RobotDescription robot, Case c, long seed) { return trial(robot, c, seed, 0); }

    /**
     * A simulated IRB-2000 campaign of the named benchmark case (e.g. "null (geometric errors only)",
     * "backlash j2 + thermal-expansion") with a fixed number of training poses, for speed measurements.
     */
    public static Campaign campaign(String caseName, long seed, int poses) {
        for (Case c : cases()) if (c.name().equals(caseName)) return trial(RobotLibrary.shipped("irb2000"), c, seed, poses).campaign();
        throw new IllegalArgumentException("no benchmark case '" + caseName + "'");
    }

    static Trial trial(RobotDescription robot, Case c, long seed, int fixedPoses) {
        Random r = new Random(seed * 7919 + 17);
        int drawn = 100 + r.nextInt(201);
        int poses = fixedPoses > 0 ? fixedPoses : drawn;
        double sigma = uniform(r, 0.01e-3, 0.05e-3);
        double error = uniform(r, 2e-3, 10e-3);
        SimulationSettings s = SimulationSettings.defaults().withPoses(poses).withValidatePoses(100).withSigma(sigma)
                .withError(error).withSeed(seed);
        // Effect sizes, then the warm-up, from r; the conditions' own noise from a second seed.
        EffectCampaign ec = EffectCampaign.simulate(robot, s, c.effects(), r, seed * 31 + 5);
        Campaign camp = ec.campaign();
        List<Effect.Term> truth = ec.injected();
        Set<String> outlierIds = new LinkedHashSet<>();
        if (c.outliers()) {
            List<Measurement> rows = new ArrayList<>(camp.measurements().rows());
            int n = 3 + r.nextInt(3);
            while (outlierIds.size() < n) {
                int i = r.nextInt(rows.size());
                if (!outlierIds.add(rows.get(i).poseId())) continue;
                Vec3 d = new Vec3(r.nextGaussian(), r.nextGaussian(), r.nextGaussian()).normalized().times(uniform(r, 0.5e-3, 3e-3));
                rows.set(i, rows.get(i).withPosition(rows.get(i).position().plus(d)));
            }
            MeasurementSet m = camp.measurements().withRows(rows);
            camp = new Campaign(camp.nominal(), camp.truth(), camp.settings(), m, camp.validation(), camp.nominalErrorRmsM());
        }
        return new Trial(camp, truth, outlierIds, sigma);
    }

    /** Key of an effect for scoring: name, or name with joints. */
    static String key(Effect e, boolean joints) { return joints ? e.kind().json + e.joints1() : e.kind().json; }

    /** Runs every case with {@code seeds} seeds; {@code log} receives a line per run. */
    public static Result run(int seeds, long baseSeed, Consumer<String> log) {
        return run(cases(), seeds, baseSeed, log);
    }

    static Result run(List<Case> cases, int seeds, long baseSeed, Consumer<String> log) {
        RobotDescription robot = RobotLibrary.shipped("irb2000");
        List<Row> rows = new ArrayList<>();
        int runs = 0, named = 0, joints = 0, nullFalse = 0, nullRuns = 0;
        double worst = 0, maxMs300 = 0, allRatio = 0;
        for (int ci = 0; ci < cases.size(); ci++) {
            Case c = cases.get(ci);
            int nr = 0, jr = 0, withFalse = 0, olFound = 0, olInj = 0, olFalse = 0;
            double sumRatio = 0, maxRatio = 0, sumMs = 0;
            for (int s = 0; s < seeds; s++) {
                long seed = baseSeed + 1000L * ci + s;
                Trial t = trial(robot, c, seed);
                Diagnosis d = Diagnoser.diagnose(robot, t.campaign().measurements(), t.campaign().validation());
                Set<String> want = new HashSet<>(), wantJ = new HashSet<>(), got = new HashSet<>(), gotJ = new HashSet<>();
                for (Effect.Term e : t.truth()) { want.add(key(e.effect(), false)); wantJ.add(key(e.effect(), true)); }
                for (Diagnosis.Finding f : d.effects()) { got.add(key(f.effect(), false)); gotJ.add(key(f.effect(), true)); }
                boolean okN = want.equals(got), okJ = wantJ.equals(gotJ);
                boolean falseEffect = !wantJ.containsAll(gotJ);
                if (okN) nr++;
                if (okJ) jr++;
                if (falseEffect) withFalse++;
                double ratio = d.finalValidateRmsM() / (Math.sqrt(3) * t.sigmaM());
                sumRatio += ratio;
                maxRatio = Math.max(maxRatio, ratio);
                sumMs += d.elapsedMs();
                if (t.campaign().measurements().size() >= 250) maxMs300 = Math.max(maxMs300, d.elapsedMs());
                olInj += t.outlierIds().size();
                for (String id : t.outlierIds()) if (d.outliers().contains(id)) olFound++;
                for (String id : d.outliers()) if (!t.outlierIds().contains(id)) olFalse++;
                if (c.effects().isEmpty()) { nullRuns++; if (!d.effects().isEmpty()) nullFalse++; }
                if (log != null)
                    log.accept(String.format(Locale.ROOT, "%-36s seed %d: %d poses, sigma %.3f mm: found %s, injected %s%s, "
                                    + "val/floor %.3f, %.0f ms", c.name(), seed, t.campaign().measurements().size(), t.sigmaM() * 1e3,
                            gotJ, wantJ, okJ ? "" : "  <-- WRONG", ratio, d.elapsedMs()));
            }
            runs += seeds;
            named += nr;
            joints += jr;
            double mean = sumRatio / seeds;
            allRatio += sumRatio;
            worst = Math.max(worst, mean);
            rows.add(new Row(c.name(), seeds, nr, jr, withFalse, mean, maxRatio, olFound, olInj, olFalse, sumMs / seeds));
        }
        return new Result(rows, seeds, 100.0 * named / runs, 100.0 * joints / runs, nullFalse, nullRuns, worst, allRatio / runs,
                maxMs300);
    }
}
