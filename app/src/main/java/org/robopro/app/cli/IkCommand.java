package org.robopro.app.cli;

import java.io.PrintWriter;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.robopro.kinematics.IkSolution;
import org.robopro.kinematics.InverseKinematics;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.kinematics.Units;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** {@code robopro ik ROBOT x y z qw qx qy qz [--json]}: every joint solution with ABB confdata. */
@Command(name = "ik", mixinStandardHelpOptions = true,
        description = "Inverse kinematics: all joint solutions (deg) reaching a flange pose (mm, quaternion w x y z), with ABB confdata.")
public final class IkCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "ROBOT", description = "shipped robot name or robot file")
    String robot;

    // hideParamSyntax: picocli would otherwise print the label once per value (7 times) in the usage
    @Parameters(index = "1..7", arity = "7", paramLabel = "X Y Z QW QX QY QZ", hideParamSyntax = true,
            description = "flange position (mm) and orientation quaternion")
    double[] pose;

    @Option(names = "--json", description = "print a JSON list of solutions")
    boolean json;

    @Option(names = "--all", description = "also list solutions outside the joint limits")
    boolean all;

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Override
    public Integer call() {
        if (pose == null || pose.length != 7) throw new IllegalArgumentException("ik needs x y z qw qx qy qz");
        for (double v : pose) if (!Double.isFinite(v)) throw new IllegalArgumentException("pose values must be finite");
        KinematicModel m = KinematicModel.build(RobotOptions.load(robot));
        Pose target = Pose.fromQuaternion(pose[3], pose[4], pose[5], pose[6],
                Units.mmToM(pose[0]), Units.mmToM(pose[1]), Units.mmToM(pose[2]));
        List<IkSolution> sols = InverseKinematics.of(m).solveAll(target).stream().filter(s -> all || s.withinLimits()).toList();
        PrintWriter out = spec.commandLine().getOut();
        if (json) {
            StringBuilder sb = new StringBuilder("[");
            for (int i = 0; i < sols.size(); i++) {
                IkSolution s = sols.get(i);
                sb.append(i == 0 ? "" : ", ").append("{\"joints\": [");
                for (int k = 0; k < s.q().length; k++)
                    sb.append(k == 0 ? "" : ", ").append(String.format(Locale.ROOT, "%.6f", edge(m, k, s.q()[k])));
                sb.append(String.format(Locale.ROOT, "], \"conf\": {\"cf1\": %d, \"cf4\": %d, \"cf6\": %d, \"cfx\": %d}, "
                                + "\"within_limits\": %b, \"singularity_measure\": %.6g}",
                        s.conf().cf1(), s.conf().cf4(), s.conf().cf6(), s.conf().cfx(), s.withinLimits(), s.singularityMeasure()));
            }
            out.println(sb.append(']'));
        } else {
            if (sols.isEmpty()) out.println("no solution" + (all ? "" : " inside the joint limits (try --all)"));
            for (IkSolution s : sols) {
                StringBuilder sb = new StringBuilder();
                for (int k = 0; k < s.q().length; k++) sb.append(String.format(Locale.ROOT, "%10.4f", edge(m, k, s.q()[k])));
                out.printf(Locale.ROOT, "%s   conf [%d,%d,%d,%d]  singularity %.3g%s%n", sb, s.conf().cf1(), s.conf().cf4(),
                        s.conf().cf6(), s.conf().cfx(), s.singularityMeasure(), s.withinLimits() ? "" : "  OUTSIDE LIMITS");
            }
        }
        out.flush();
        return sols.isEmpty() ? 1 : 0;
    }

    private static double edge(KinematicModel m, int k, double v) { return m.isPrismatic(k) ? Units.mToMm(v) : Units.radToDeg(v); }
}
