package org.robopro.world;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import org.robopro.models.JointType;
import org.robopro.models.RobotDescription;

/**
 * The same campaign read by other instruments: several reflectors on the flange (a tracker
 * measuring three SMRs at every pose), one length per pose from a fixed anchor (a draw-wire
 * sensor, a tracker in distance mode), or lengths between the point's places at two poses (a
 * length artefact or ballbar probed by the robot). Every pose of a {@link Campaign.Result} is measured again
 * on the same {@link WorldRobot}, with the same joint values, approach directions, times,
 * temperatures and payloads, so that every concealed effect acts on the new readings as it did on
 * the campaign's. Written in the public measurement format (shared/formats/measurements.md:
 * the long form with a {@code point} column, or a {@code distance} column with an optional
 * {@code # anchor:} line).
 * <p>
 * Limits: the campaign must not be joint-by-joint (there the file holds the controller's read-back,
 * not the true values) and must have no injected outliers. Each drive's last move is the campaign's
 * (it matters only for lost motion that builds up over the move).
 */
public final class Readings {
    private Readings() { }

    /**
     * The campaign with every point of {@code flangePointsM} (flange coordinates, m) measured at each
     * pose in the campaign's instrument frame, each with noise σ = the plan's per axis; the long
     * form, points named P1..Pk.
     */
    public static String points(WorldRobot world, RobotDescription nominal, Campaign.Result c, double[][] flangePointsM, long seed) {
        check(c);
        Random noise = new Random(seed * 2_147_483_647L + 17);
        List<Campaign.Row> rows = c.rows();
        StringBuilder sb = header(nominal, c, "# frame: " + c.frame() + "\n");
        sb.append(columns(nominal, c, true, "x,y,z", false));
        for (int i = 0; i < rows.size(); i++) {
            Campaign.Row r = rows.get(i);
            for (int k = 0; k < flangePointsM.length; k++) {
                double[] pt = flangePointsM[k];
                WorldRobot w = at(world, Rigid.translation(pt[0], pt[1], pt[2]));
                double[] p = Rigid.plus(w.target(r.q(), r.dir(), r.side(), r.lastMove(), c.warmup().at(r.timeS()), r.timeS(), r.payloadKg()).p(),
                        Arm.gauss(noise, c.plan().sigmaM()));
                sb.append(r.id()).append(",P").append(k + 1);
                row(sb, nominal, c, r, String.format(Locale.ROOT, "%s,%s,%s",
                        Campaign.fmt(p[0] * 1e3, 5), Campaign.fmt(p[1] * 1e3, 5), Campaign.fmt(p[2] * 1e3, 5)), null);
            }
        }
        return sb.toString();
    }

    /**
     * The campaign as lengths from {@code anchorBaseM} (robot base frame, m; fixed to the floor, so
     * the instrument's drift does not reach it) to the campaign's measured target, each with noise
     * σ = the plan's; {@code writeAnchor} writes the anchor as {@code # anchor:} (else the reader
     * must identify it).
     */
    public static String distances(WorldRobot world, RobotDescription nominal, Campaign.Result c, double[] anchorBaseM,
                                   boolean writeAnchor, long seed) {
        check(c);
        Random noise = new Random(seed * 2_147_483_647L + 19);
        WorldRobot inBase = inBase(world);
        List<Campaign.Row> rows = c.rows();
        String anchor = writeAnchor ? String.format(Locale.ROOT, "# anchor: %s, %s, %s\n", Campaign.fmt(anchorBaseM[0] * 1e3, 4),
                Campaign.fmt(anchorBaseM[1] * 1e3, 4), Campaign.fmt(anchorBaseM[2] * 1e3, 4)) : "";
        StringBuilder sb = header(nominal, c, anchor);
        sb.append(columns(nominal, c, false, "distance", false));
        for (int i = 0; i < rows.size(); i++) {
            Campaign.Row r = rows.get(i);
            double[] p = inBase.target(r.q(), r.dir(), r.side(), r.lastMove(), c.warmup().at(r.timeS()), r.timeS(), r.payloadKg()).p();
            double d = Rigid.norm(Rigid.minus(p, anchorBaseM)) + c.plan().sigmaM() * noise.nextGaussian();
            sb.append(r.id());
            row(sb, nominal, c, r, Campaign.fmt(d * 1e3, 5), null);
        }
        return sb.toString();
    }

    /**
     * The campaign as lengths between the measured target's places at consecutive poses (a length
     * artefact or a ballbar probed by the robot, or a tracker's distance between two stops): one
     * row per pose after the first, with the pose before it in {@code from_q1..} (and its
     * directions in {@code from_dir1..}), each length with noise σ = the plan's. The instrument
     * plays no part (a length does not depend on where it is seen from); the row's time and
     * temperature are the second pose's, while each end is measured at its own.
     */
    public static String pairs(WorldRobot world, RobotDescription nominal, Campaign.Result c, long seed) {
        check(c);
        Random noise = new Random(seed * 2_147_483_647L + 23);
        WorldRobot inBase = inBase(world);
        List<Campaign.Row> rows = c.rows();
        StringBuilder sb = header(nominal, c, "");
        sb.append(columns(nominal, c, false, "distance", true));
        double[] prev = null;
        for (int i = 0; i < rows.size(); i++) {
            Campaign.Row r = rows.get(i);
            double[] p = inBase.target(r.q(), r.dir(), r.side(), r.lastMove(), c.warmup().at(r.timeS()), r.timeS(), r.payloadKg()).p();
            if (prev != null) {
                Campaign.Row a = rows.get(i - 1);
                double d = Rigid.norm(Rigid.minus(p, prev)) + c.plan().sigmaM() * noise.nextGaussian();
                sb.append(r.id());
                row(sb, nominal, c, r, Campaign.fmt(d * 1e3, 5), a);
            }
            prev = p;
        }
        return sb.toString();
    }

    /** The world measured in its base frame: no instrument pose, no instrument drift (link growth stays). */
    static WorldRobot inBase(WorldRobot w) {
        WorldRobot b = w.withInstrument(Rigid.IDENTITY);
        WorldRobot.Thermal t = w.thermal();
        if (t != null) b = b.withThermal(new WorldRobot.Thermal(t.refC(), t.linkAlpha(), new double[3], new double[3], t.holderAlpha()));
        return b;
    }

    private static WorldRobot at(WorldRobot w, Rigid flangeToTool) {
        return w.withTool(flangeToTool);
    }

    private static void check(Campaign.Result c) {
        if (c.plan().movedJoints() > 0)
            throw new IllegalArgumentException("a joint-by-joint campaign writes the controller's read-back, not the true joint values");
        if (c.plan().outliers() > 0) throw new IllegalArgumentException("a campaign with injected outliers cannot be read again");
        if (c.plan().sixD()) throw new IllegalArgumentException("other readings of a 6-D campaign are not written");
    }

    private static StringBuilder header(RobotDescription robot, Campaign.Result c, String more) {
        StringBuilder sb = new StringBuilder();
        sb.append("# robopro-measurements 1\n# robot: ").append(robot.name()).append('\n');
        sb.append("# length-unit: mm\n# angle-unit: deg\n").append(more);
        sb.append(String.format(Locale.ROOT, "# instrument: simulated by robopro world, sigma %.4f mm, seed %d%n",
                c.plan().sigmaM() * 1e3, c.plan().seed()));
        return sb;
    }

    /** The header row; {@code pairs} adds the first pose's columns (from_q1.., from_dir1..) at the end. */
    private static String columns(RobotDescription robot, Campaign.Result c, boolean point, String measured, boolean pairs) {
        Campaign.Plan plan = c.plan();
        List<String> head = new ArrayList<>(List.of("pose"));
        if (point) head.add("point");
        for (int j = 1; j <= robot.dof(); j++) head.add("q" + j);
        head.add(measured);
        if (plan.dirColumns()) for (int j = 1; j <= robot.dof(); j++) head.add("dir" + j);
        if (plan.conditionColumns()) head.addAll(List.of("time_s", "temp_c"));
        if (plan.payloadStepsKg().length > 0) head.add("payload_kg");
        if (plan.validatePoses() > 0) head.add("set");
        if (pairs) {
            for (int j = 1; j <= robot.dof(); j++) head.add("from_q" + j);
            if (plan.dirColumns()) for (int j = 1; j <= robot.dof(); j++) head.add("from_dir" + j);
        }
        return String.join(",", head) + "\n";
    }

    /** A data row after its leading column(s); {@code from} (or null) is the first pose of a length between two poses. */
    private static void row(StringBuilder sb, RobotDescription robot, Campaign.Result c, Campaign.Row r, String measured, Campaign.Row from) {
        Campaign.Plan plan = c.plan();
        joints(sb, robot, r.q());
        sb.append(',').append(measured);
        if (plan.dirColumns()) for (int d : r.dir()) sb.append(',').append(d);
        if (plan.conditionColumns()) sb.append(',').append(Campaign.fmt(r.timeS(), 1)).append(',').append(Campaign.fmt(r.tempC(), 2));
        if (plan.payloadStepsKg().length > 0) sb.append(',').append(Campaign.fmt(r.payloadKg(), 2));
        if (plan.validatePoses() > 0) sb.append(',').append(r.validate() ? "validate" : "train");
        if (from != null) {
            joints(sb, robot, from.q());
            if (plan.dirColumns()) for (int d : from.dir()) sb.append(',').append(d);
        }
        sb.append('\n');
    }

    /** The joint values, each after a comma, in the file's units (degrees; mm for a prismatic joint). */
    private static void joints(StringBuilder sb, RobotDescription robot, double[] q) {
        for (int j = 0; j < robot.dof(); j++) {
            boolean prismatic = robot.joints().get(j).type() == JointType.PRISMATIC;
            sb.append(',').append(Campaign.fmt(prismatic ? q[j] * 1e3 : Math.toDegrees(q[j]), 7));
        }
    }
}
