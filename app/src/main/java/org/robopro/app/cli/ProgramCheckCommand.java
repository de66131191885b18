package org.robopro.app.cli;

import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import org.robopro.kinematics.KinematicModel;
import org.robopro.models.CellFile;
import org.robopro.models.SignalDescription;
import org.robopro.models.TextFiles;
import org.robopro.programs.check.CheckReport;
import org.robopro.programs.check.PathChecker;
import org.robopro.programs.rapid.ParsedModule;
import org.robopro.programs.rapid.RapidParser;
import org.robopro.programs.sim.MotionInterpreter;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code robopro program check FILE.mod --robot ROBOT}: path checks and cycle time; exit 1 when errors are found. */
@Command(name = "check", mixinStandardHelpOptions = true,
        description = "Check a RAPID module along its path: reachability, limits, configuration, singularities, I/O time line, cycle time.")
public final class ProgramCheckCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "FILE.mod") Path file;

    @Mixin RobotOptions robot;

    @Option(names = "--proc", defaultValue = "main", paramLabel = "PROC", description = "procedure to run (default main)") String proc;

    @Option(names = "--cell", paramLabel = "CELL.json", description = "cell file whose I/O signal table drives inputs (constant, scripted, following an output)")
    Path cell;

    @Spec CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        ParsedModule pm = RapidParser.parseDetailed(TextFiles.readUtf8(file), file.toString());
        KinematicModel model = robot.model();
        List<SignalDescription> signals = cell == null ? List.of() : CellFile.read(cell).signals();
        CheckReport r = new PathChecker(model).check(MotionInterpreter.of(pm).withSignals(signals).simulate(proc), signals);
        spec.commandLine().getOut().print(r.format());
        return r.hasErrors() ? 1 : 0;
    }
}
