package org.robopro.calibration.diagnosis;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import java.util.Set;
import java.util.function.Consumer;
import org.robopro.calibration.JointEffect;
import org.robopro.calibration.PoseConditions;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.calibration.simulation.Campaign;
import org.robopro.calibration.simulation.CampaignSimulator;
import org.robopro.calibration.simulation.SimulationSettings;
import org.robopro.kinematics.KinematicModel;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
import org.robopro.models.Vec3;

/**
 * The concealed-effect benchmark of issue 4: simulated IRB-2000 campaigns with random geometric
 * errors, one or two injected effects of realistic size (or none, or outliers), realistic extra
 * columns (approach directions from the pose sequence, a warm-up temperature curve with time,
 * payload changes when compliance is tested), random noise σ 0.01–0.05 mm and 100–300 poses;
 * each is diagnosed blind and scored: effects named right (and on the right joints), false
 * effects, validation RMS over the noise floor √3 σ on 100 further poses.
 */
public final class ConcealedEffectBenchmark {
    /** Seconds between poses of a campaign (time_s). */
    static final double SECONDS_PER_POSE = 20;

    /** One injected effect: how to draw its size. */
    @FunctionalInterface
    interface Injector {
        Effect.Term draw(KinematicModel model, GravityTorques g, Random rng);
    }

    /** A benchmark case. */
    record Case(String name, List<Injector> effects, boolean payloadVaries, boolean outliers) { }

    /** Scores of one case over its seeds. */
    public record Row(String name, int runs, int namedRight, int jointsRight, int runsWithFalse, double meanValRatio,
                      double maxValRatio, int outliersFound, int outliersInjected, int falseOutliers, double meanMs) { }

    /** Result of a benchmark run: rows per case and totals. */
    public record Result(List<Row> rows, int seedsPerCase, double namedRightPct, double jointsRightPct, int nullFalse,
                         int nullRuns, double worstCaseMeanValRatio, double meanValRatio, double maxMs300) {
        /** The bar of issue 4: ≥ 95 % named (and joints) right, no false effect on null cases, RMS ≤ 1.15 floor. */
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

    // ------------------------------------------------------------------ effect sizes (issue 4)

    static double uniform(Random r, double lo, double hi) { return lo + (hi - lo) * r.nextDouble(); }

    static double signed(Random r, double lo, double hi) { return (r.nextBoolean() ? 1 : -1) * uniform(r, lo, hi); }

    static Injector compliance(int joint) {
        return (m, g, r) -> new Effect.Term(Effect.compliance(joint, g), new double[] {1 / uniform(r, 0.5e6, 2e6)});
    }

    static Injector periodic(int joint) {
        boolean wrist = joint >= 3;
        return (m, g, r) -> {
            double[] v = new double[2 * Effect.HARMONICS];
            for (int h = 0; h < Effect.HARMONICS; h++) {
                double a = Math.toRadians(wrist ? uniform(r, 0.02, 0.05) : uniform(r, 0.004, 0.01));
                double ph = 2 * Math.PI * r.nextDouble();
                v[2 * h] = a * Math.cos(ph);
                v[2 * h + 1] = a * Math.sin(ph);
            }
            return new Effect.Term(Effect.periodic(joint), v);
        };
    }

    static Injector backlash(int joint) {
        return (m, g, r) -> new Effect.Term(Effect.backlash(joint), new double[] {Math.toRadians(uniform(r, 0.02, 0.05))});
    }

    static Injector thermal() {
        return (m, g, r) -> new Effect.Term(Effect.thermal(AMBIENT_C), new double[] {uniform(r, 12e-6, 23e-6)});
    }

    static Injector scale(int joint) {
        return (m, g, r) -> new Effect.Term(Effect.scale(joint), new double[] {signed(r, 1e-4, 3e-4)});
    }

    static Injector coupling(int target, int source) {
        return (m, g, r) -> new Effect.Term(Effect.coupling(target, source), new double[] {signed(r, 3e-4, 10e-4)});
    }

    static final double AMBIENT_C = 20;

    /** The cases of the benchmark (joints 0-based here, 1-based in names). */
    static List<Case> cases() {
        List<Case> c = new ArrayList<>();
        c.add(new Case("null (geometric errors only)", List.of(), false, false));
        c.add(new Case("null with outliers", List.of(), false, true));
        c.add(new Case("joint-compliance j2", List.of(compliance(1)), true, false));
        c.add(new Case("joint-compliance j3", List.of(compliance(2)), true, false));
        c.add(new Case("gear-periodic j1", List.of(periodic(0)), false, false));
        c.add(new Case("gear-periodic j2", List.of(periodic(1)), false, false));
        c.add(new Case("gear-periodic j3", List.of(periodic(2)), false, false));
        c.add(new Case("gear-periodic j5 (wrist)", List.of(periodic(4)), false, false));
        c.add(new Case("backlash j1", List.of(backlash(0)), false, false));
        c.add(new Case("backlash j2", List.of(backlash(1)), false, false));
        c.add(new Case("backlash j3", List.of(backlash(2)), false, false));
        c.add(new Case("thermal-expansion", List.of(thermal()), false, false));
        c.add(new Case("joint-scale j1", List.of(scale(0)), false, false));
        c.add(new Case("joint-scale j2", List.of(scale(1)), false, false));
        c.add(new Case("joint-coupling j3<-j2", List.of(coupling(2, 1)), false, false));
        c.add(new Case("joint-compliance j2 + j3", List.of(compliance(1), compliance(2)), true, false));
        c.add(new Case("backlash j2 + thermal-expansion", List.of(backlash(1), thermal()), false, false));
        c.add(new Case("gear-periodic j1 + joint-scale j3", List.of(periodic(0), scale(2)), false, false));
        c.add(new Case("joint-coupling j3<-j2 + backlash j1", List.of(coupling(2, 1), backlash(0)), false, false));
        c.add(new Case("backlash j2 with outliers", List.of(backlash(1)), false, true));
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
        KinematicModel nominal = KinematicModel.build(robot);
        GravityTorques g = new GravityTorques(nominal, robot.massModel().orElseThrow());
        Random r = new Random(seed * 7919 + 17);
        int drawn = 100 + r.nextInt(201);
        int poses = fixedPoses > 0 ? fixedPoses : drawn;
        double sigma = uniform(r, 0.01e-3, 0.05e-3);
        double error = uniform(r, 2e-3, 10e-3);
        List<Effect.Term> truth = new ArrayList<>();
        for (Injector in : c.effects()) truth.add(in.draw(nominal, g, r));
        List<JointEffect> effects = new ArrayList<>();
        for (Effect.Term t : truth) effects.add(t.effect().truth(t.values()));
        double warm = uniform(r, 10, 15), tau = uniform(r, 900, 2400);
        double rated = robot.massModel().get().ratedPayloadKg();
        boolean payload = c.payloadVaries();
        double[] prev = new double[1];
        double[][] prevQ = {null};
        Random cr = new Random(seed * 31 + 5);
        CampaignSimulator.ConditionsSource src = (rng, q, i) -> {
            // Approach directions: the sign of each joint's move from the previous pose (the sequence as measured).
            int[] dir = new int[q.length];
            for (int j = 0; j < q.length; j++)
                dir[j] = prevQ[0] == null ? (cr.nextBoolean() ? 1 : -1) : (q[j] >= prevQ[0][j] ? 1 : -1);
            prevQ[0] = q.clone();
            double t = i * SECONDS_PER_POSE + uniform(cr, 0, 2);
            double temp = AMBIENT_C + warm * (1 - Math.exp(-t / tau)) + 0.05 * cr.nextGaussian();
            double pl = payload ? rated * ((i / 15) % 3) / 2.0 : Double.NaN;
            return new PoseConditions(dir, t, temp, pl);
        };
        SimulationSettings s = SimulationSettings.defaults().withPoses(poses).withValidatePoses(100).withSigma(sigma)
                .withError(error).withSeed(seed);
        Campaign camp = CampaignSimulator.simulate(nominal, s, effects, src);
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
