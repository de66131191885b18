package org.robopro.app.cli;

import java.io.PrintWriter;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.kinematics.Units;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** {@code robopro fk ROBOT q1 ... qn [--json]}: flange pose for controller joint values (deg / mm). */
@Command(name = "fk", mixinStandardHelpOptions = true,
        description = "Forward kinematics: the flange pose (mm, quaternion w x y z) for joint values as the controller gives them (deg; mm for prismatic).")
public final class FkCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "ROBOT", description = "shipped robot name or robot file")
    String robot;

    @Parameters(index = "1..*", arity = "1..*", paramLabel = "Q", description = "joint values, degrees (mm for prismatic joints)")
    double[] joints;

    @Option(names = "--json", description = "print {\"position_mm\": [x, y, z], \"quaternion\": [qw, qx, qy, qz]}")
    boolean json;

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Override
    public Integer call() {
        KinematicModel m = KinematicModel.build(RobotOptions.load(robot));
        double[] q = toSi(m, joints, robot);
        Pose p = m.flange(q);
        double[] quat = p.quaternion();
        PrintWriter out = spec.commandLine().getOut();
        double x = noNegZero(Units.mToMm(p.x())), y = noNegZero(Units.mToMm(p.y())), z = noNegZero(Units.mToMm(p.z()));
        for (int i = 0; i < 4; i++) quat[i] = noNegZero(quat[i] * 1e3) / 1e3;
        if (!Double.isFinite(x + y + z + quat[0] + quat[1] + quat[2] + quat[3]))
            throw new IllegalArgumentException("the joint values give no finite pose for " + robot
                    + " (a value too large for the robot's joints?); check the joint values");
        if (json)
            out.printf(Locale.ROOT, "{\"position_mm\": [%.6f, %.6f, %.6f], \"quaternion\": [%.9f, %.9f, %.9f, %.9f]}%n",
                    x, y, z, quat[0], quat[1], quat[2], quat[3]);
        else
            out.printf(Locale.ROOT, "position (mm): %.3f %.3f %.3f%nquaternion (w x y z): %.6f %.6f %.6f %.6f%n%s%n",
                    x, y, z, quat[0], quat[1], quat[2], quat[3],
                    m.withinLimits(q) ? "inside the joint limits" : "WARNING: outside the joint limits");
        out.flush();
        return 0;
    }

    /** Rounding noise below the printed precision would print as -0.000000. */
    private static double noNegZero(double v) { return Math.abs(v) < 5e-7 ? 0.0 : v; }

    /** Degrees / mm at the edge to SI inside; the count must match the robot's joints. */
    static double[] toSi(KinematicModel m, double[] values, String robot) {
        if (values.length != m.dof())
            throw new IllegalArgumentException(robot + " has " + m.dof() + " joints, got " + values.length + " joint values");
        double[] q = new double[values.length];
        for (int i = 0; i < q.length; i++) {
            if (!Double.isFinite(values[i])) throw new IllegalArgumentException("joint value " + (i + 1) + " is not finite");
            q[i] = m.isPrismatic(i) ? Units.mmToM(values[i]) : Units.degToRad(values[i]);
        }
        return q;
    }
}
