package org.robopro.app.cli;

import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import org.robopro.kinematics.KinematicModel;
import org.robopro.models.CellDescription;
import org.robopro.models.CellFile;
import org.robopro.models.SignalDescription;
import org.robopro.models.TextFiles;
import org.robopro.programs.check.CheckReport;
import org.robopro.programs.check.PathChecker;
import org.robopro.programs.check.Problem;
import org.robopro.programs.collision.ClearanceChecker;
import org.robopro.programs.sim.Simulation;
import org.robopro.programs.ParsedModule;
import org.robopro.programs.RapidParser;
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

    @Option(names = "--cell", paramLabel = "CELL.json", description = "cell file: its I/O signal table drives inputs; its objects are checked for collisions and clearance")
    Path cell;

    @Spec CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        ParsedModule pm = RapidParser.parseDetailed(TextFiles.readUtf8(file), file.toString());
        KinematicModel model = robot.model();
        CellDescription c = cell == null ? null : CellFile.read(cell);
        List<SignalDescription> signals = c == null ? List.of() : c.signals();
        Simulation sim = MotionInterpreter.of(pm).withSignals(signals).simulate(proc);
        CheckReport r = new PathChecker(model).check(sim, signals);
        var out = spec.commandLine().getOut();
        out.print(r.format());
        boolean errors = r.hasErrors();
        if (c != null) {
            // Collisions and clearance against the cell's objects, and objects placed through one another.
            for (String w : ClearanceChecker.placement(c.objects(), 0.001)) out.println("WARNING cell: " + w);
            ClearanceChecker.Options shapes = org.robopro.app.workbench.model.ShippedMeshes.collisionOptions(model.description(), model);
            out.println("collision shapes: " + shapes.linkShapes());
            ClearanceChecker.Result cr = new ClearanceChecker(model, ClearanceChecker.pose(c.worldTbase()), c.objects(), shapes)
                    .check(sim.steps(), r, java.util.Optional.empty());
            for (ClearanceChecker.MoveClearance m : cr.moves())
                out.printf(java.util.Locale.ROOT, "clearance %-40s %8.1f mm  (%s)%n", m.step(), m.minClearanceM() * 1e3, m.closestPair());
            for (Problem p : cr.problems()) out.println(p);
            errors |= cr.problems().stream().anyMatch(p -> p.severity() == Problem.Severity.ERROR);
        }
        return errors ? 1 : 0;
    }
}
