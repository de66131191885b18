package org.robopro.app.cli;

import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.function.Consumer;
import org.robopro.app.benchmark.DiagnosisBenchmark;
import org.robopro.app.benchmark.ScenarioFiles;
import org.robopro.models.AtomicFiles;
import org.robopro.world.Scenario;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code robopro diagnose-benchmark}: the independent diagnosis benchmark
 * (docs/diagnosis-benchmark.md): campaigns of the world simulator (a robot with concealed physics
 * written independently of the diagnosis), read as measurement files and diagnosed blind; prints
 * the confusion table (markdown) and optionally writes it to a file. With {@code --scenarios DIR}
 * the campaigns are files supplied from outside, each with its truth label
 * ({@link org.robopro.app.benchmark.ScenarioFiles}); {@code --write-scenarios DIR} writes the
 * world's campaigns in that form. Exit code 0 when every run gave the right answer, 1 otherwise.
 */
@Command(name = "diagnose-benchmark", mixinStandardHelpOptions = true,
        description = "Run the independent diagnosis benchmark (world simulator scenarios, diagnosed blind) and print its confusion table.")
public final class DiagnoseBenchmarkCommand implements Callable<Integer> {
    @Option(names = "--seeds", defaultValue = "5", paramLabel = "N", description = "seeds per scenario (default ${DEFAULT-VALUE})")
    int seeds;

    @Option(names = "--base-seed", defaultValue = "20261124", paramLabel = "S", description = "first seed (default ${DEFAULT-VALUE})")
    long baseSeed;

    @Option(names = "--family", paramLabel = "GROUP",
            description = "only the scenarios of one group: null, outside, transmission-error, lost-motion, thermal-growth, "
                    + "gravity-elasticity, gear-ratio, cross-coupling, pair, one-sided")
    String family;

    @Option(names = "--scenario", paramLabel = "TEXT", description = "only the scenarios whose name contains TEXT")
    String scenario;

    @Option(names = "--verbose", description = "print one line per run")
    boolean verbose;

    @Option(names = "--scenarios", paramLabel = "DIR",
            description = "diagnose the campaign files of DIR instead (NAME.csv, each with its truth label NAME.truth.json; "
                    + "docs/diagnosis-benchmark.md): a held-out set made outside this project")
    Path scenarios;

    @Option(names = "--write-scenarios", paramLabel = "DIR",
            description = "write the selected world campaigns (scenarios x seeds) to DIR as NAME.csv + NAME.truth.json, and run nothing")
    Path writeScenarios;

    @Option(names = "--out", paramLabel = "FILE", description = "also write the table (markdown) to FILE")
    Path out;

    @Option(names = "--force", description = "replace FILE if it exists")
    boolean force;

    @Spec CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        if (seeds < 1) throw new IllegalArgumentException("--seeds must be >= 1, got " + seeds);
        if (scenarios != null && writeScenarios != null) throw new IllegalArgumentException("--scenarios and --write-scenarios exclude each other");
        var w = spec.commandLine().getOut();
        var err = spec.commandLine().getErr();
        Consumer<String> log = line -> {
            if (verbose) { err.println(line); err.flush(); }
        };
        List<DiagnosisBenchmark.Run> runs;
        if (scenarios != null) {
            List<DiagnosisBenchmark.Case> cases = ScenarioFiles.read(scenarios);
            if (family != null) cases = cases.stream().filter(c -> c.group().equals(family)).toList();
            if (scenario != null) cases = cases.stream().filter(c -> c.name().contains(scenario)).toList();
            if (cases.isEmpty()) throw new IllegalArgumentException("--scenarios " + scenarios + ": no campaign left after --family/--scenario");
            err.println(cases.size() + " campaign(s) from " + scenarios);
            err.flush();
            runs = DiagnosisBenchmark.runCases(cases, log);
        } else {
            List<Scenario> chosen = family == null ? Scenario.catalogue() : Scenario.ofFamily(family);
            if (chosen.isEmpty())
                throw new IllegalArgumentException("--family " + family + ": no such group (" + String.join(", ", Scenario.families()) + ")");
            if (scenario != null) {
                chosen = chosen.stream().filter(s -> s.name().contains(scenario)).toList();
                if (chosen.isEmpty()) throw new IllegalArgumentException("--scenario " + scenario + ": no scenario's name contains it");
            }
            if (writeScenarios != null) {
                int n = ScenarioFiles.write(chosen, seeds, baseSeed, writeScenarios, force);
                w.println("wrote " + n + " campaign(s) with their truth labels to " + writeScenarios);
                return 0;
            }
            runs = DiagnosisBenchmark.run(chosen, seeds, baseSeed, log);
        }
        String table = DiagnosisBenchmark.markdown(runs);
        w.print(table);
        if (out != null) {
            AtomicFiles.writeString(out, table, force);
            w.println("wrote " + out);
        }
        return runs.stream().allMatch(r -> r.correct(DiagnosisBenchmark.BAR)) ? 0 : 1;
    }
}
