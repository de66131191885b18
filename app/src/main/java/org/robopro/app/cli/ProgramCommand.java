package org.robopro.app.cli;

import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

/** {@code robopro program check|export|compensate}: robot programs (docs/programs.md). */
@Command(name = "program", mixinStandardHelpOptions = true, description = "Check, export and compensate robot programs (RAPID).",
        subcommands = {ProgramCheckCommand.class, ProgramExportCommand.class, ProgramCompensateCommand.class})
public final class ProgramCommand implements Callable<Integer> {
    @Spec CommandSpec spec;

    @Override
    public Integer call() {
        spec.commandLine().usage(spec.commandLine().getOut());
        return 0;
    }
}
