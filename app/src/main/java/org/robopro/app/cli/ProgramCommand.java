package org.robopro.app.cli;

import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/** {@code robopro program check|export|compensate}: robot programs (docs/programs.md). */
@Command(name = "program", mixinStandardHelpOptions = true, description = "Check, export and compensate robot programs (RAPID).",
        subcommands = {ProgramCheckCommand.class, ProgramExportCommand.class, ProgramCompensateCommand.class})
public final class ProgramCommand implements Callable<Integer> {
    @Override
    public Integer call() {
        CommandLine.usage(this, System.out);
        return 0;
    }
}
