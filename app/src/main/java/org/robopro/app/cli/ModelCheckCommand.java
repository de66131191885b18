package org.robopro.app.cli;

import java.io.PrintWriter;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.ParameterizationCheck;
import org.robopro.models.RobotDescription;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Parameters;
import org.robopro.models.RobotLibrary;

/**
 * {@code robopro model check FILE}: reads a robot file and checks its parameterization for
 * singularities (seed paper §3), comparing with plain DH. Exit 0 when clean, 1 with warnings,
 * 2 for a bad file.
 */
@Command(name = "check", mixinStandardHelpOptions = true,
        description = "Check a robot file: parameterization singularities (rank of dT/dp, det(J^T J)) and identifiability.")
public final class ModelCheckCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "FILE", description = "robot file (or shipped robot name)")
    String file;

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        RobotDescription d = RobotLibrary.load(file);
        ParameterizationCheck.Result r = ParameterizationCheck.check(KinematicModel.build(d));
        out.printf(Locale.ROOT, "%s: %d joints, model read and built.%n%n", d.name(), d.dof());
        print(out, "robopro model (seed paper Table 1)", r);
        ParameterizationCheck.Result dh = ParameterizationCheck.check(KinematicModel.buildPlainDh(d));
        out.println();
        print(out, "for comparison: plain Denavit-Hartenberg", dh);
        out.println();
        if (r.warnings().isEmpty()) out.println("OK: no singular or near-singular parameterization.");
        for (String w : r.warnings()) out.println("WARNING: " + w);
        out.flush();
        return r.warnings().isEmpty() ? 0 : 1;
    }

    private static void print(PrintWriter out, String title, ParameterizationCheck.Result r) {
        out.println(title + ":");
        out.printf(Locale.ROOT, "  %-16s %-8s %-10s %-6s %-12s %s%n", "transformation", "type", "axes(deg)", "rank", "det(JtJ)", "min sv");
        for (ParameterizationCheck.TransformationCheck t : r.transformations())
            out.printf(Locale.ROOT, "  %-16s %-8s %-10s %d/%-4d %-12.3g %.3g%s%n", t.label(), t.convention(),
                    Double.isNaN(t.axisAngle()) ? "-" : String.format(Locale.ROOT, "%.1f", Math.toDegrees(t.axisAngle())),
                    t.rank(), t.parameters().size(), t.detJtJ(), t.smallestSingularValue(), t.singular() ? "  SINGULAR" : "");
        out.printf(Locale.ROOT, "  identification Jacobian: %d parameters (complete minimal: %d), rank %d, condition number %.3g%n",
                r.parameterCount(), r.expectedCount(), r.identificationRank(), r.conditionNumber());
    }
}
