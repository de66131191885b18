package org.robopro.comms;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.robopro.comms.protocol.OpenAbb;
import org.robopro.kinematics.Units;
import org.robopro.models.AtomicFiles;
import org.robopro.models.Vec3;

/**
 * A calibration campaign against a controller with a tracker (the simulator's MEASURE): move to
 * each joint pose, measure the target on the tool, and save the rows as a measurement file
 * (/work/shared/formats/measurements.md, version 1: mm, deg, frame "tracker", dir1..dirN).
 */
public final class MeasurementCampaign {
    private MeasurementCampaign() { }

    /** One measured pose: id, joint values (rad), measured position (m, tracker frame), last-motion signs. */
    public record Row(String pose, double[] q, Vec3 measured, int[] direction) { }

    /** Moves through {@code poses} (rad) and measures at each; stops at the first failure. */
    public static List<Row> run(CommandInvoker invoker, List<double[]> poses) {
        List<Row> rows = new ArrayList<>();
        double[] prev = invoker.execute(Commands.readJoints());
        int[] dir = new int[prev.length];
        for (int k = 0; k < poses.size(); k++) {
            double[] q = poses.get(k);
            invoker.execute(Commands.moveJoints(q));
            for (int i = 0; i < q.length; i++) if (q[i] != prev[i]) dir[i] = q[i] > prev[i] ? 1 : -1;
            Vec3 m = invoker.execute(Commands.measure());
            rows.add(new Row(Integer.toString(k + 1), q.clone(), m, dir.clone()));
            prev = q;
        }
        return rows;
    }

    /** The measurement file text. */
    public static String format(String robot, String instrument, List<Row> rows) {
        StringBuilder sb = new StringBuilder();
        sb.append("# robopro-measurements 1\n# robot: ").append(robot).append("\n# length-unit: mm\n# angle-unit: deg\n")
                .append("# frame: tracker\n# instrument: ").append(instrument.replace('\n', ' ')).append('\n');
        int n = rows.isEmpty() ? 6 : rows.get(0).q().length;
        sb.append("pose");
        for (int i = 1; i <= n; i++) sb.append(",q").append(i);
        sb.append(",x,y,z");
        for (int i = 1; i <= n; i++) sb.append(",dir").append(i);
        sb.append('\n');
        for (Row r : rows) {
            sb.append(r.pose());
            for (double v : r.q()) sb.append(',').append(OpenAbb.num(Units.radToDeg(v), 6));
            sb.append(',').append(OpenAbb.num(Units.mToMm(r.measured().x()), 4)).append(',')
                    .append(OpenAbb.num(Units.mToMm(r.measured().y()), 4)).append(',')
                    .append(OpenAbb.num(Units.mToMm(r.measured().z()), 4));
            for (int d : r.direction()) sb.append(',').append(d);
            sb.append('\n');
        }
        return sb.toString();
    }

    /** Writes the file atomically; refuses to replace an existing one unless {@code overwrite}. */
    public static void write(Path file, String robot, String instrument, List<Row> rows, boolean overwrite) throws IOException {
        AtomicFiles.writeString(file, format(robot.toLowerCase(Locale.ROOT), instrument, rows), overwrite);
    }
}
