package org.robopro.app.cli;

import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/**
 * The root command. Each subcommand is its own small class returning an exit code; register it
 * in {@code subcommands} below. With no subcommand, robopro opens the workbench.
 */
@Command(name = "robopro", mixinStandardHelpOptions = true, version = "robopro 0.1.0",
        description = "Off-line programming and calibration of industrial robots.",
        // In the order a user meets them: the GUI and the whole loop, the model, kinematics, then the
        // calibration chain, programs, the controller link.
        subcommands = {
                WorkbenchCommand.class,
                DemoCommand.class,
                ModelCommand.class,
                FkCommand.class,
                IkCommand.class,
                SimulateCommand.class,
                MeasurementsCommand.class,
                CalibrateCommand.class,
                DiagnoseCommand.class,
                CompensateCommand.class,
                ProgramCommand.class,
                LinkCommand.class,
                ControllerSimCommand.class,
                DiagnoseBenchmarkCommand.class,
                CommandLine.HelpCommand.class,
        })
public final class RoboproCommand implements Callable<Integer> {

    public static CommandLine commandLine() {
        CommandLine cl = new CommandLine(new RoboproCommand());
        cl.setExecutionExceptionHandler((ex, cmd, parsed) -> Failures.report(ex, cmd.getErr()));
        // Every number an option takes must be finite: NaN or an overflow (1e400) is refused by name.
        CommandLine.ITypeConverter<Double> finite = v -> {
            double d;
            try {
                d = Double.parseDouble(v.strip());
            } catch (NumberFormatException e) {
                throw new CommandLine.TypeConversionException("'" + v + "' is not a number");
            }
            if (!Double.isFinite(d)) throw new CommandLine.TypeConversionException("'" + v + "' is not a finite number");
            return d;
        };
        cl.registerConverter(Double.class, finite);
        cl.registerConverter(double.class, finite);
        return cl;
    }

    @Override
    public Integer call() throws Exception {
        return new CommandLine(new WorkbenchCommand()).execute(); // no subcommand: open the workbench
    }
}
