package org.robopro.app.cli;

import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.robopro.calibration.PoseConditions;
import org.robopro.calibration.compensation.Compensator;
import org.robopro.calibration.compensation.TargetCompensator;
import org.robopro.calibration.compensation.TargetsFile;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.kinematics.Units;
import org.robopro.models.AtomicFiles;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code robopro compensate}: seed paper Fig. 5. Reads targets (docs/calibration.md, "Targets
 * file"), writes per target the compensated coordinates to send to a controller that knows only
 * the nominal model, the joint values, and the residual of the calibrated prediction.
 */
@Command(name = "compensate", mixinStandardHelpOptions = true,
        description = "Compensate targets with a calibrated model for a controller that knows only the nominal model.")
public final class CompensateCommand implements Callable<Integer> {
    @Option(names = "--nominal", required = true, paramLabel = "ROBOT", description = "the controller's (nominal) robot")
    String nominal;

    @Option(names = "--calibrated", required = true, paramLabel = "FILE", description = "calibrated robot file (from robopro calibrate)")
    String calibrated;

    @Option(names = "--targets", required = true, paramLabel = "FILE", description = "targets: CSV x,y,z[,qw,qx,qy,qz] in mm")
    Path targets;

    @Mixin OutputFileOptions out;

    @Option(names = "--tool", defaultValue = "0,0,0", paramLabel = "X,Y,Z[,QW,QX,QY,QZ]", description = "TCP in flange coordinates, mm (default: the flange)")
    String tool;

    @Option(names = "--orientation", defaultValue = "0,0,1,0", paramLabel = "QW,QX,QY,QZ",
            description = "tool orientation for targets without one (default: tool z pointing down)")
    String orientation;

    @Option(names = "--frame", paramLabel = "base|world", description = "frame of the targets (overrides the file's '# frame:')")
    String frame;

    @Option(names = "--world-base", defaultValue = "0,0,0,1,0,0,0", paramLabel = "X,Y,Z,QW,QX,QY,QZ", description = "the robot base in world coordinates, mm")
    String worldBase;

    @Option(names = "--seed-joints", paramLabel = "Q1,...", description = "joint values (deg) to choose the first IK branch near (default: all zero)")
    String seedJoints;

    @Option(names = "--temp-c", paramLabel = "C", description = "temperature the program runs at (for a thermal effect of an extended model)")
    Double tempC;

    @Option(names = "--payload-kg", paramLabel = "KG", description = "payload the program carries (for joint compliance of an extended model)")
    Double payloadKg;

    @Spec CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        KinematicModel nom = KinematicModel.build(RobotLibrary.load(nominal));
        RobotDescription calDesc = RobotLibrary.load(calibrated);
        KinematicModel cal = KinematicModel.build(calDesc);
        if (nom.dof() != cal.dof())
            throw new IllegalArgumentException("--nominal has " + nom.dof() + " joints but --calibrated " + cal.dof());
        Pose flangeTtool = CliSupport.poseMm("--tool", tool);
        double[] o = CliSupport.numbers("--orientation", orientation, 4);
        Pose defaultOrientation = Pose.fromQuaternion(o[0], o[1], o[2], o[3], 0, 0, 0);
        Pose worldTbase = CliSupport.poseMm("--world-base", worldBase);
        TargetsFile.Targets ts = TargetsFile.read(targets, defaultOrientation);
        String f = frame != null ? frame.toLowerCase(Locale.ROOT) : ts.frame();
        if (!f.equals("base") && !f.equals("world")) throw new IllegalArgumentException("--frame must be base or world");
        boolean world = f.equals("world");
        double[] q = new double[nom.dof()];
        if (seedJoints != null) {
            double[] s = CliSupport.numbers("--seed-joints", seedJoints, nom.dof());
            q = Units.degToRad(s);
        }
        // An extended model (robopro diagnose) brings its effects, evaluated under the given conditions.
        Compensator comp = Compensator.forRobotFile(nom, calDesc, calibrated, flangeTtool, flangeTtool,
                        new PoseConditions(null, Double.NaN, tempC == null ? Double.NaN : tempC, payloadKg == null ? Double.NaN : payloadKg));
        Compensator.Batch batch = comp.batch();
        StringBuilder sb = new StringBuilder("# robopro compensated targets: ").append(f).append(" frame, mm, deg\n");
        sb.append("id,x,y,z,qw,qx,qy,qz");
        for (int j = 1; j <= nom.dof(); j++) sb.append(",q").append(j);
        sb.append(",residual_mm,residual_deg,status\n");
        int bad = 0;
        double[] cmd = new double[7], res = new double[2];
        for (TargetsFile.Target t : ts.targets()) {
            Pose base = world ? worldTbase.inverse().times(t.pose()) : t.pose();
            double[] quat = base.quaternion();
            double[] seed = q.clone();
            TargetCompensator.Status st = batch.compensate(new double[] {base.x(), base.y(), base.z()}, quat, q, cmd, res);
            if (!st.ok()) bad++;
            boolean values = st != TargetCompensator.Status.UNREACHABLE && allFinite(cmd) && allFinite(q);
            sb.append(t.id());
            if (values) {
                Pose c = Pose.fromQuaternion(cmd[3], cmd[4], cmd[5], cmd[6], cmd[0], cmd[1], cmd[2]);
                if (world) c = worldTbase.times(c);
                double[] cq = c.quaternion();
                sb.append(String.format(Locale.ROOT, ",%.6f,%.6f,%.6f,%.9f,%.9f,%.9f,%.9f",
                        Units.mToMm(c.x()), Units.mToMm(c.y()), Units.mToMm(c.z()), cq[0], cq[1], cq[2], cq[3]));
                for (double v : q) sb.append(String.format(Locale.ROOT, ",%.8f", Units.radToDeg(v)));
                sb.append(',').append(number(Units.mToMm(res[0]))).append(',').append(number(Units.radToDeg(res[1])));
            } else {
                // No solution for this target: empty fields, never the values left from another target.
                sb.append(",".repeat(7 + nom.dof() + 2));
                q = seed;
            }
            sb.append(',').append(st.name().toLowerCase(Locale.ROOT)).append('\n');
        }
        AtomicFiles.writeString(out.file(), sb.toString(), out.force());
        spec.commandLine().getOut().printf("compensated %d targets (%d not converged/unreachable), wrote %s%n",
                ts.targets().size(), bad, out.file());
        return bad == 0 ? 0 : 1;
    }

    private static boolean allFinite(double[] v) {
        for (double d : v) if (!Double.isFinite(d)) return false;
        return true;
    }

    /** A residual, or an empty field when there is none. */
    private static String number(double v) {
        return Double.isFinite(v) ? String.format(Locale.ROOT, "%.3e", v) : "";
    }
}
