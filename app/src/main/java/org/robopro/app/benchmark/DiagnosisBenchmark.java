package org.robopro.app.benchmark;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.EnumMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.function.Consumer;
import org.robopro.calibration.diagnosis.Diagnoser;
import org.robopro.calibration.diagnosis.Diagnosis;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.measurement.MeasurementReader;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.models.JointDescription;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
import org.robopro.world.Expected;
import org.robopro.world.Scenario;

/**
 * The independent diagnosis benchmark (docs/diagnosis-benchmark.md): each scenario of the world
 * simulator ({@link Scenario#catalogue()}: a real robot drawn with geometric errors and a concealed
 * effect written in the world's own physics, or none, or one outside every family) is measured,
 * written as a measurement file, read back by the product's reader and diagnosed blind by
 * {@link Diagnoser} as a user's file would be. Each run is scored against the scenario's expected
 * answer:
 * <ul>
 * <li><b>named right</b>: the physical families named (on their joints) are exactly the concealed ones;</li>
 * <li><b>named wrong</b>: a family was named that is not there (wrong family or wrong joint);</li>
 * <li><b>located only</b>: nothing wrong named, a structure located (for an outside case this is the right answer);</li>
 * <li><b>missed</b>: nothing wrong named, the concealed effect neither named nor located;</li>
 * <li><b>false claim</b>: on a null campaign, anything named or located;</li>
 * <li><b>clean</b>: on a null campaign, nothing claimed (the right answer).</li>
 * </ul>
 * and by its validation RMS after the diagnosis over the noise floor √3 σ, and over what the same
 * diagnosis leaves on the run's geometry-only twin ({@link Scenario#twin}: the same robot, poses
 * and noise draws without the concealed effects), the floor that campaign's size allows.
 */
public final class DiagnosisBenchmark {
    private DiagnosisBenchmark() { }

    /** Outcome of one run. */
    public enum Outcome {
        NAMED_RIGHT("named right"), NAMED_WRONG("named wrong"), LOCATED_ONLY("located only"), MISSED("missed"),
        FALSE_CLAIM("false claim on null"), CLEAN("clean null");

        public final String words;

        Outcome(String words) { this.words = words; }
    }

    /**
     * One campaign to diagnose blind, with the answer it must give: a trial of a world scenario,
     * or a measurement file and its truth label supplied from outside ({@link ScenarioFiles}).
     *
     * @param name       the scenario's name (runs of one name share a table row)
     * @param group      the scenario's group (null, outside, a family, pair, or the label's own)
     * @param robot      the nominal robot file the campaign was measured on
     * @param fileName   the measurement file's name (for messages)
     * @param text       the measurement file's text (shared/formats/measurements.md)
     * @param expected   the answer
     * @param sigmaM     the instrument's noise per axis, m (the floor is √3 σ)
     * @param outlierIds the poses whose readings were made grossly wrong on purpose
     * @param seed       the seed it was drawn with (0 when unknown)
     * @param twinText   the measurement text of the campaign's geometry-only twin (same poses, order and noise
     *                   draws, no concealed effect, no outlier), or null when there is none
     * @param twinFileName the twin's measurement file name (for messages), or null when there is none
     */
    public record Case(String name, String group, RobotDescription robot, String fileName, String text, Expected expected,
                       double sigmaM, Set<String> outlierIds, long seed, String twinText, String twinFileName) {
        public Case { outlierIds = Set.copyOf(outlierIds); }

        /** A world trial as a case: its campaign text and the scenario's expected answer, without a twin. */
        public static Case of(Scenario.Trial t) { return of(t, null); }

        /** A world trial and its geometry-only twin ({@link Scenario#twin}, or null) as a case. */
        public static Case of(Scenario.Trial t, Scenario.Trial twin) {
            Set<String> outliers = new LinkedHashSet<>();
            for (var r : t.campaign().rows()) if (r.outlier()) outliers.add(r.id());
            return new Case(t.scenario().name(), t.scenario().family(), RobotLibrary.shipped(t.scenario().robot()),
                    t.scenario().name() + ".csv", t.campaign().text(), t.scenario().expected(), t.campaign().plan().sigmaM(), outliers, t.seed(),
                    twin == null ? null : twin.campaign().text(), twin == null ? null : t.scenario().name() + ScenarioFiles.TWIN);
        }

        /** The twin's campaign as a case of its own: nothing concealed, nothing to find. */
        Case twin() {
            return new Case(name + " (twin)", group, robot, twinFileName, twinText, Expected.none(), sigmaM, Set.of(), seed, null, null);
        }
    }

    /** When a run's geometry-only twin is diagnosed too. */
    public enum Twins {
        /** Every run that has a twin (the published benchmark: every run's ratio to its twin is reported). */
        ALWAYS,
        /** Only when the run misses the bar on the floor, so that the twin can decide (CI: same verdicts, less time). */
        WHEN_NEEDED,
        /** Never. */
        NEVER
    }

    /**
     * One diagnosed run.
     *
     * @param name        the scenario's name
     * @param expected    the answer it had to give
     * @param named       what the diagnosis named, as "family-name jN"
     * @param located     what it located without naming
     * @param geoRatio    validation RMS of the geometric calibration over the floor
     * @param finalRatio  validation RMS after the diagnosis over the floor
     * @param twinRatio   validation RMS the same diagnosis leaves on the geometry-only twin, over the floor (NaN: not run)
     * @param outliersInjected gross outliers in the campaign
     * @param outliersFound    of those, reported as outliers
     * @param cleanFlagged     clean poses reported as outliers
     */
    public record Run(String name, Expected expected, long seed, Outcome outcome, List<String> named, List<String> located, double geoRatio,
                      double finalRatio, double twinRatio, double ms, int outliersInjected, int outliersFound, int cleanFlagged) {
        /**
         * The right answer for the scenario's kind, with the validation RMS brought to the bar where
         * it applies ({@link #rmsRoute}), every injected outlier reported and no clean pose reported as one.
         */
        public boolean correct(double bar) {
            if (outliersFound < outliersInjected || cleanFlagged > 0) return false;
            return switch (expected.verdict()) {
                case NAMED -> outcome == Outcome.NAMED_RIGHT && rmsRoute(bar) != null;
                case NULL -> outcome == Outcome.CLEAN && rmsRoute(bar) != null;
                case OUTSIDE -> outcome == Outcome.LOCATED_ONLY;
            };
        }

        /**
         * How the run meets the validation-RMS bar: "floor" when it is within {@code bar} × the noise
         * floor; "twin" when it is not, but its geometry-only twin itself ends above
         * {@link #TWIN_ABOVE} × the floor (the campaign is too small for the bar, whatever is
         * concealed) and the run is within {@link #TWIN_MARGIN} × the twin; {@link #UNMEASURED} when
         * the file has no validation poses (the diagnosis judged its claims by K-fold
         * cross-validation; the verdict alone is scored and the summary counts these apart); null
         * when it fails.
         */
        public String rmsRoute(double bar) {
            if (Double.isNaN(finalRatio) && Double.isNaN(geoRatio)) return UNMEASURED;
            if (finalRatio <= bar) return "floor";
            if (twinRatio > TWIN_ABOVE && finalRatio <= TWIN_MARGIN * twinRatio) return "twin";
            return null;
        }

        /** This run with its twin's validation RMS over the floor set. */
        public Run withTwinRatio(double ratio) {
            return new Run(name, expected, seed, outcome, named, located, geoRatio, finalRatio, ratio, ms, outliersInjected, outliersFound,
                    cleanFlagged);
        }

        /** Validation RMS over the twin's (NaN without a twin). */
        public double toTwin() { return finalRatio / twinRatio; }

        public String line() {
            return String.format(Locale.ROOT, "%-62s seed %d: %-19s named %s located %s, val/floor %.3f -> %.3f (twin %.3f), outliers %d/%d "
                            + "(+%d clean flagged), %.0f ms", name, seed, outcome.words, named, located, geoRatio, finalRatio, twinRatio,
                    outliersFound, outliersInjected, cleanFlagged, ms);
        }
    }

    /** {@link Run#rmsRoute}'s answer for a campaign file without validation poses. */
    public static final String UNMEASURED = "no validation poses";

    /** The validation RMS a named (or null) run must reach, times the noise floor. */
    public static final double BAR = 1.15;

    /**
     * A twin above this many times the floor shows a campaign too small for {@link #BAR}: a null
     * campaign of 50 poses fitted with the right model ends at 1.11–1.18 × (about 30 geometric
     * parameters estimated from 150 numbers).
     */
    public static final double TWIN_ABOVE = 1.10;

    /** What a run may cost beyond its twin when the twin is above {@link #TWIN_ABOVE}: 5 %. */
    public static final double TWIN_MARGIN = 1.05;

    /** Runs the scenarios with {@code seeds} seeds each (seed = baseSeed + k), each with its twin diagnosed. */
    public static List<Run> run(List<Scenario> scenarios, int seeds, long baseSeed, Consumer<String> log) {
        return run(scenarios, seeds, baseSeed, Twins.ALWAYS, log);
    }

    /** Runs the scenarios with {@code seeds} seeds each (seed = baseSeed + k), their twins diagnosed as {@code twins} says. */
    public static List<Run> run(List<Scenario> scenarios, int seeds, long baseSeed, Twins twins, Consumer<String> log) {
        List<Run> out = new ArrayList<>();
        for (Scenario s : scenarios)
            for (int k = 0; k < seeds; k++) {
                Run r = run(s, baseSeed + k, twins);
                if (log != null) log.accept(r.line());
                out.add(r);
            }
        return out;
    }

    /** Runs the given cases (e.g. campaign files supplied from outside, {@link ScenarioFiles#read}), each twin diagnosed. */
    public static List<Run> runCases(List<Case> cases, Consumer<String> log) {
        List<Run> out = new ArrayList<>();
        for (Case c : cases) {
            Run r = run(c, Twins.ALWAYS);
            if (log != null) log.accept(r.line());
            out.add(r);
        }
        return out;
    }

    /** A world campaign as the product reads it: training rows, and validation rows or null. */
    public record Sets(MeasurementSet train, MeasurementSet validate) { }

    /** Reads a trial's measurement text with the product's reader and splits it by its set column. */
    public static Sets read(Scenario.Trial t) { return read(Case.of(t)); }

    /** Reads a case's measurement text with the product's reader and splits it by its set column. */
    public static Sets read(Case c) {
        MeasurementSet all = MeasurementReader.parse(c.fileName(), c.text(), c.robot().joints().stream().map(JointDescription::type).toList());
        MeasurementSet validate = all.hasSplit() && all.split(Measurement.Split.VALIDATE).size() > 0
                ? all.split(Measurement.Split.VALIDATE) : null;
        return new Sets(all.hasSplit() ? all.split(Measurement.Split.TRAIN) : all, validate);
    }

    /** One run: measure, write, read, diagnose, score; the twin diagnosed too. */
    public static Run run(Scenario s, long seed) { return run(s, seed, Twins.ALWAYS); }

    /** One run: measure, write, read, diagnose, score; the twin diagnosed as {@code twins} says. */
    public static Run run(Scenario s, long seed, Twins twins) {
        return run(Case.of(s.trial(seed), twins == Twins.NEVER ? null : s.twin(seed)), twins);
    }

    /** One run of a campaign text: read, diagnose blind, score against the case's answer; its twin, if any, diagnosed too. */
    public static Run run(Case c) { return run(c, Twins.ALWAYS); }

    /** One run of a campaign text, its twin diagnosed as {@code twins} says. */
    public static Run run(Case c, Twins twins) {
        Run r = diagnose(c);
        boolean twin = c.twinText() != null && (twins == Twins.ALWAYS || twins == Twins.WHEN_NEEDED && r.finalRatio() > BAR);
        if (!twin) return r;
        // A twin identical to its campaign (a null scenario without outliers) ends where the campaign did: the diagnosis is deterministic.
        return r.withTwinRatio(c.twinText().equals(c.text()) ? r.finalRatio() : diagnose(c.twin()).finalRatio());
    }

    private static Run diagnose(Case c) {
        Sets sets = read(c);
        Diagnosis d = Diagnoser.diagnose(c.robot(), sets.train(), sets.validate());
        double floor = Math.sqrt(3) * c.sigmaM();
        List<String> named = new ArrayList<>(), located = new ArrayList<>();
        Set<String> claims = new LinkedHashSet<>();
        for (Diagnosis.Finding f : d.effects()) {
            String name = f.effect().json();
            Expected.Family fam = Expected.Family.ofDiagnosisName(name);
            if (fam == null) { located.add(f.effect().label()); continue; }
            named.add(f.effect().label());
            claims.add(key(fam, f.effect().joints1()));
        }
        // Structures the locate scan found that no named effect explains.
        for (Diagnosis.Located l : d.located()) if (l.explainedBy() == null && !located.contains(l.shape())) located.add(l.shape());
        Set<String> want = new LinkedHashSet<>();
        for (Expected.Claim cl : c.expected().claims()) want.addAll(keys(cl));
        Outcome o = score(c.expected().verdict(), want, claims, !located.isEmpty());
        int found = 0, clean = 0;
        for (String id : d.outliers()) if (c.outlierIds().contains(id)) found++; else clean++;
        return new Run(c.name(), c.expected(), c.seed(), o, named, located, d.geometricValidateRmsM() / floor, d.finalValidateRmsM() / floor, Double.NaN,
                d.elapsedMs(), c.outlierIds().size(), found, clean);
    }

    /**
     * What a label's claim asks to be named: a cross-coupling is one claim on its driven and source
     * joints; any other family on several joints ("gravity-elasticity on 2 and 3") is that family
     * named on each of them, as the diagnosis names one effect per joint.
     */
    static List<String> keys(Expected.Claim cl) {
        if (cl.family().jointless() || cl.family() == Expected.Family.CROSS_COUPLING || cl.joints().size() < 2)
            return List.of(key(cl.family(), cl.joints()));
        List<String> out = new ArrayList<>();
        for (int j : cl.joints()) out.add(key(cl.family(), List.of(j)));
        return out;
    }

    static String key(Expected.Family f, List<Integer> joints) {
        return f.name() + (f.jointless() ? "" : joints.toString());
    }

    static Outcome score(Expected.Verdict v, Set<String> want, Set<String> got, boolean located) {
        if (v == Expected.Verdict.NULL) return got.isEmpty() && !located ? Outcome.CLEAN : Outcome.FALSE_CLAIM;
        if (!want.containsAll(got)) return Outcome.NAMED_WRONG;
        if (v == Expected.Verdict.NAMED && got.equals(want)) return Outcome.NAMED_RIGHT;
        return located || !got.isEmpty() ? Outcome.LOCATED_ONLY : Outcome.MISSED;
    }

    /**
     * The confusion table (rows: scenarios; columns: outcomes), the validation ratios to the floor
     * and to the twin, and how the runs meet the RMS bar, as markdown.
     */
    public static String markdown(List<Run> runs) {
        StringBuilder sb = new StringBuilder();
        sb.append("| scenario | runs | named right | named wrong | located only | missed | false claim (null) | clean (null) "
                + "| val RMS / floor before | after (median) | after (max) | twin / floor (median) | after / twin (median) | after / twin (max) "
                + "| outliers found | clean flagged | ms (mean) |\n");
        sb.append("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
        Map<String, List<Run>> byScenario = new java.util.LinkedHashMap<>();
        for (Run r : runs) byScenario.computeIfAbsent(r.name(), k -> new ArrayList<>()).add(r);
        for (var e : byScenario.entrySet()) sb.append(row(e.getKey(), e.getValue()));
        sb.append(row("**all**", runs));
        sb.append('\n');
        sb.append("Validation RMS after the diagnosis over the noise floor (named and null scenarios): ")
                .append(distribution(runs.stream().filter(r -> r.expected().verdict() != Expected.Verdict.OUTSIDE)
                        .mapToDouble(Run::finalRatio).toArray())).append('\n');
        double[] toTwin = runs.stream().filter(r -> r.expected().verdict() != Expected.Verdict.OUTSIDE && !Double.isNaN(r.twinRatio()))
                .mapToDouble(Run::toTwin).toArray();
        if (toTwin.length > 0)
            sb.append("\nValidation RMS after the diagnosis over its geometry-only twin's (named and null scenarios): ")
                    .append(distribution(toTwin)).append('\n');
        List<Run> barred = runs.stream().filter(r -> r.expected().verdict() != Expected.Verdict.OUTSIDE).toList();
        long byFloor = barred.stream().filter(r -> "floor".equals(r.rmsRoute(BAR))).count();
        long byTwin = barred.stream().filter(r -> "twin".equals(r.rmsRoute(BAR))).count();
        long unmeasured = barred.stream().filter(r -> UNMEASURED.equals(r.rmsRoute(BAR))).count();
        sb.append(String.format(Locale.ROOT, "%nValidation RMS bar (named and null scenarios): %d of %d runs within %.2f × the floor, %d more within "
                        + "%.2f × their twin where the twin itself is above %.2f × the floor, %d meet neither%s.%n", byFloor, barred.size(), BAR, byTwin,
                TWIN_MARGIN, TWIN_ABOVE, barred.size() - byFloor - byTwin - unmeasured,
                unmeasured == 0 ? "" : String.format(Locale.ROOT, "; files without validation poses, verdict scored alone: %d", unmeasured)));
        List<Run> namedRight = runs.stream().filter(r -> r.outcome() == Outcome.NAMED_RIGHT).toList();
        List<String> besides = namedRight.stream().filter(r -> !r.located().isEmpty())
                .map(r -> r.name() + " (seed " + r.seed() + "): " + String.join("; ", r.located())).toList();
        if (!namedRight.isEmpty())
            sb.append(String.format(Locale.ROOT, "%nNamed right, with a structure located beside that no named effect explains: %d of %d runs%s%n",
                    besides.size(), namedRight.size(), besides.isEmpty() ? "." : ":"));
        for (String b : besides) sb.append("- ").append(b).append('\n');
        long correct = runs.stream().filter(r -> r.correct(BAR)).count();
        sb.append(String.format(Locale.ROOT, "%nRight answers (named right or clean with validation RMS ≤ %.2f × floor, or ≤ %.2f × a twin "
                + "above %.2f × floor; outside: located and not named; every injected outlier reported, no clean pose reported): %d of %d runs.%n",
                BAR, TWIN_MARGIN, TWIN_ABOVE, correct, runs.size()));
        return sb.toString();
    }

    static String row(String name, List<Run> rs) {
        Map<Outcome, Integer> n = new EnumMap<>(Outcome.class);
        for (Outcome o : Outcome.values()) n.put(o, 0);
        for (Run r : rs) n.merge(r.outcome(), 1, Integer::sum);
        // runs without validation poses have no validation ratios: the columns are over the runs that have them
        double[] after = rs.stream().mapToDouble(Run::finalRatio).filter(v -> !Double.isNaN(v)).sorted().toArray();
        double[] geo = rs.stream().mapToDouble(Run::geoRatio).filter(v -> !Double.isNaN(v)).toArray();
        String before = geo.length == 0 ? "-" : String.format(Locale.ROOT, "%.2f", Arrays.stream(geo).average().orElse(Double.NaN));
        int inj = rs.stream().mapToInt(Run::outliersInjected).sum(), found = rs.stream().mapToInt(Run::outliersFound).sum();
        double[] twin = rs.stream().mapToDouble(Run::twinRatio).filter(v -> !Double.isNaN(v)).sorted().toArray();
        double[] toTwin = rs.stream().mapToDouble(Run::toTwin).filter(v -> !Double.isNaN(v)).sorted().toArray();
        return String.format(Locale.ROOT, "| %s | %d | %d | %d | %d | %d | %d | %d | %s | %s | %s | %s | %s | %s | %s | %d | %.0f |%n", name,
                rs.size(), n.get(Outcome.NAMED_RIGHT), n.get(Outcome.NAMED_WRONG), n.get(Outcome.LOCATED_ONLY), n.get(Outcome.MISSED),
                n.get(Outcome.FALSE_CLAIM), n.get(Outcome.CLEAN), before, median(after),
                after.length == 0 ? "-" : String.format(Locale.ROOT, "%.2f", after[after.length - 1]),
                median(twin), median(toTwin), toTwin.length == 0 ? "-" : String.format(Locale.ROOT, "%.2f", toTwin[toTwin.length - 1]),
                inj == 0 ? "-" : found + "/" + inj, rs.stream().mapToInt(Run::cleanFlagged).sum(),
                rs.stream().mapToDouble(Run::ms).average().orElse(0));
    }

    /** The median of sorted values to two decimals, "-" when there are none. */
    static String median(double[] sorted) { return sorted.length == 0 ? "-" : String.format(Locale.ROOT, "%.2f", sorted[sorted.length / 2]); }

    /** How many runs fall in each bin: up to 1.05, 1.05–1.10, 1.10–1.15, 1.15–1.5, 1.5–2, above 2. */
    static String distribution(double[] ratios) {
        double[] edges = {1.05, 1.10, 1.15, 1.5, 2, Double.POSITIVE_INFINITY};
        String[] names = {"≤ 1.05", "1.05–1.10", "1.10–1.15", "1.15–1.5", "1.5–2", "> 2"};
        StringBuilder sb = new StringBuilder();
        double lo = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < edges.length; i++) {
            int c = 0;
            for (double v : ratios) if (v > lo && v <= edges[i]) c++;
            sb.append(names[i]).append(": ").append(c).append(i < edges.length - 1 ? ", " : "");
            lo = edges[i];
        }
        return sb.append(" (of ").append(ratios.length).append(" runs)").toString();
    }
}
