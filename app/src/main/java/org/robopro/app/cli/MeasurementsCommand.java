package org.robopro.app.cli;

import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/** {@code robopro measurements ...}: parent of the measurement-file subcommands (join). */
@Command(name = "measurements", mixinStandardHelpOptions = true, description = "Build and convert measurement files.",
        subcommands = {MeasurementsJoinCommand.class})
public final class MeasurementsCommand implements Callable<Integer> {
    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Override
    public Integer call() {
        spec.commandLine().usage(spec.commandLine().getErr());
        return 2;
    }
}
