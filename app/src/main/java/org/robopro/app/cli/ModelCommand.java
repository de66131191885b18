package org.robopro.app.cli;

import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/** {@code robopro model ...}: parent of the model subcommands (show, check, import). */
@Command(name = "model", mixinStandardHelpOptions = true, description = "Inspect and check robot models.",
        subcommands = {ModelShowCommand.class, ModelCheckCommand.class, ModelImportCommand.class})
public final class ModelCommand implements Callable<Integer> {
    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Override
    public Integer call() {
        spec.commandLine().usage(spec.commandLine().getErr());
        return 2;
    }
}
