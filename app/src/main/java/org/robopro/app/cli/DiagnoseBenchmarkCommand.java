package org.robopro.app.cli;

import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.robopro.calibration.diagnosis.ConcealedEffectBenchmark;
import org.robopro.models.AtomicFiles;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code robopro diagnose-benchmark}: the concealed-effect benchmark
 * (docs/diagnosis-benchmark.md): simulated IRB-2000 campaigns with hidden effects, diagnosed
 * blind; prints the score table (markdown) and optionally writes it to a file. Exit code 0 when
 * the bar is met, 1 otherwise.
 */
@Command(name = "diagnose-benchmark", mixinStandardHelpOptions = true,
        description = "Run the concealed-effect diagnosis benchmark and print its score table.")
public final class DiagnoseBenchmarkCommand implements Callable<Integer> {
    @Option(names = "--seeds", defaultValue = "10", paramLabel = "N", description = "seeds per case (default ${DEFAULT-VALUE})")
    int seeds;

    @Option(names = "--base-seed", defaultValue = "20260401", paramLabel = "S", description = "first seed (default ${DEFAULT-VALUE})")
    long baseSeed;

    @Option(names = "--verbose", description = "print one line per run")
    boolean verbose;

    @Option(names = "--out", paramLabel = "FILE", description = "also write the table (markdown) to FILE")
    Path out;

    @Option(names = "--force", description = "replace FILE if it exists")
    boolean force;

    @Spec CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        if (seeds < 1) throw new IllegalArgumentException("--seeds must be >= 1, got " + seeds);
        var w = spec.commandLine().getOut();
        var err = spec.commandLine().getErr();
        ConcealedEffectBenchmark.Result r = ConcealedEffectBenchmark.run(seeds, baseSeed, line -> {
            if (verbose) { err.println(line); err.flush(); }
        });
        String table = r.markdown();
        w.print(table);
        if (out != null) {
            AtomicFiles.writeString(out, table, force);
            w.println("wrote " + out);
        }
        return r.meetsBar() ? 0 : 1;
    }
}
