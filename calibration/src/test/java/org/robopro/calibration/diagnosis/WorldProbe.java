package org.robopro.calibration.diagnosis;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.measurement.MeasurementReader;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.models.JointType;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
import org.robopro.world.Expected;
import org.robopro.world.Scenario;

/**
 * Diagnoses the world module's scenarios (independent truth) and scores them: named right, named
 * wrong, located only, missed, false claim. A development tool: {@code main} prints a table
 * (ROBOPRO_PROBE_SEEDS seeds, ROBOPRO_PROBE_FILTER substring of the scenario names).
 */
public final class WorldProbe {
    /** One diagnosed trial. */
    public record Outcome(String scenario, long seed, String verdict, List<String> named, double ratio, double ms, int located) { }

    public static Outcome run(Scenario s, long seed) {
        Scenario.Trial t = s.trial(seed);
        if (System.getenv("ROBOPRO_PROBE_TRUTH") != null) System.out.println(t.truthJson());
        RobotDescription robot = RobotLibrary.shipped(s.robot());
        List<JointType> types = robot.joints().stream().map(j -> j.type()).toList();
        MeasurementSet all = MeasurementReader.parse("world-" + seed + ".csv", t.campaign().text(), types);
        MeasurementSet train = all.split(Measurement.Split.TRAIN), val = all.split(Measurement.Split.VALIDATE);
        Diagnosis d = Diagnoser.diagnose(robot, train, val.size() > 0 ? val : null);
        if (System.getenv("ROBOPRO_PROBE_TRUTH") != null) {
            d.located().forEach(l -> System.out.println("  located " + l.stage() + ": " + l.words()));
            d.warnings().forEach(w -> System.out.println("  warning: " + w));
            d.notes().forEach(w -> System.out.println("  note: " + w));
        }
        double floor = Math.sqrt(3) * t.campaign().plan().sigmaM();
        List<String> named = new ArrayList<>();
        Set<String> got = new HashSet<>();
        boolean wrong = false;
        for (Diagnosis.Finding f : d.effects()) {
            named.add(f.effect().label());
            Expected.Family fam = Expected.Family.ofDiagnosisName(f.effect().kind().json);
            if (fam == null) continue; // a fallback (smooth error) is a location, not a claim
            String key = fam + (fam.jointless() ? "" : " " + f.effect().joints1());
            got.add(key);
        }
        Set<String> want = new HashSet<>();
        for (Expected.Claim c : s.expected().claims()) want.add(c.family() + (c.family().jointless() ? "" : " " + c.joints()));
        for (String g : got) if (!want.contains(g)) wrong = true;
        int located = (int) d.located().stream().filter(l -> l.explainedBy() == null).count();
        String verdict = switch (s.expected().verdict()) {
            case NULL -> got.isEmpty() ? "right" : "false";
            case OUTSIDE -> !got.isEmpty() ? "wrong" : located > 0 ? "located" : "missed";
            case NAMED -> wrong ? "wrong" : got.equals(want) ? "right" : !got.isEmpty() ? "partial" : located > 0 ? "located" : "missed";
        };
        return new Outcome(s.name(), seed, verdict, named, d.finalValidateRmsM() / floor, d.elapsedMs(), located);
    }

    public static void main(String[] args) {
        int seeds = Integer.parseInt(System.getenv().getOrDefault("ROBOPRO_PROBE_SEEDS", "1"));
        String filter = System.getenv().getOrDefault("ROBOPRO_PROBE_FILTER", "");
        for (Scenario s : Scenario.catalogue()) {
            if (!s.name().contains(filter)) continue;
            long seed0 = Long.parseLong(System.getenv().getOrDefault("ROBOPRO_PROBE_SEED0", "1"));
            for (long seed = seed0; seed < seed0 + seeds; seed++) {
                try {
                    Outcome o = run(s, seed);
                    System.out.printf(Locale.ROOT, "%-70s %d %-8s ratio %.2f located %d %5.0f ms %s%n", o.scenario(), seed, o.verdict(),
                            o.ratio(), o.located(), o.ms(), o.named());
                } catch (RuntimeException e) {
                    System.out.printf(Locale.ROOT, "%-70s %d CRASH %s%n", s.name(), seed, e);
                }
            }
        }
    }
}
