package org.robopro.app.cli;

import java.util.concurrent.Callable;
import org.robopro.models.InputException;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/**
 * The root command. Each subcommand is its own small class returning an exit code; register it
 * in {@code subcommands} below. With no subcommand, robopro opens the workbench.
 */
@Command(name = "robopro", mixinStandardHelpOptions = true, version = "robopro 0.1.0",
        description = "Off-line programming and calibration of industrial robots.",
        subcommands = {
                CommandLine.HelpCommand.class,
                SimulateCommand.class,
                CalibrateCommand.class,
                CompensateCommand.class,
                DiagnoseCommand.class,
                DiagnoseBenchmarkCommand.class,
                ModelCommand.class,
                FkCommand.class,
                IkCommand.class,
                ProgramCommand.class,
                WorkbenchCommand.class,
                ControllerSimCommand.class,
                LinkCommand.class,
        })
public final class RoboproCommand implements Callable<Integer> {

    public static CommandLine commandLine() {
        CommandLine cl = new CommandLine(new RoboproCommand());
        cl.setExecutionExceptionHandler((ex, cmd, parsed) -> {
            if (ex instanceof InputException || ex instanceof java.io.IOException
                    || ex instanceof IllegalArgumentException) {
                cmd.getErr().println("robopro: " + ex.getMessage());
                return 2;
            }
            throw ex;
        });
        return cl;
    }

    @Override
    public Integer call() throws Exception {
        return new CommandLine(new WorkbenchCommand()).execute(); // no subcommand: open the workbench
    }
}
