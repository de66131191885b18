package org.robopro.world;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import org.robopro.models.JointDescription;
import org.robopro.models.RobotDescription;

/**
 * A measurement campaign on a {@link WorldRobot}, as a person with an instrument would take it:
 * poses drawn within the joint limits (the planner knows only the robot file), visited in a
 * realistic order (nearest next pose in travel time from the home position, or as drawn), each
 * drive's direction of approach following from that order, time stamps from the travel, settle
 * and measuring times, the temperature following a warm-up curve, payload changes, noise. The
 * result is the measurement file's text in the public format (shared/formats/measurements.md) so
 * that the estimator reads it like a user's file, plus the rows and the warm-up as truth.
 */
public final class Campaign {
    private Campaign() { }

    /** Order in which the poses are measured. */
    public enum Order {
        /** From the home pose, always the next pose that is quickest to reach (what a person or a planner does). */
        NEAREST,
        /** In the order drawn (a scripted random sequence). */
        AS_DRAWN
    }

    /** Where the robot is when the campaign starts. */
    public enum Start {
        /** At the home position (zero where the limits allow it), every drive last moved up. */
        HOME,
        /** Wherever the previous program left it: a random pose, each drive last moved either way. */
        ELSEWHERE
    }

    /**
     * What to measure and write.
     *
     * @param poses          training poses
     * @param validatePoses  validation poses, interleaved in the sequence, written with set = validate
     * @param sigmaM         position noise per axis, m
     * @param sigmaRotRad    orientation noise per axis, rad (6-D only)
     * @param sixD           write the measured orientation (qw, qx, qy, qz)
     * @param dirColumns     write dir1..dirN (the directions exist in the robot anyway)
     * @param conditionColumns write time_s and temp_c
     * @param payloadStepsKg payloads carried in turn, changed every {@link #POSES_PER_PAYLOAD} poses; empty: no payload column (0 kg)
     * @param order          measuring order
     * @param seed           the same seed gives the same campaign
     * @param outliers       training poses whose reading is grossly wrong (target knocked, beam broken and re-locked):
     *                       moved by 0.5–3 mm in a random direction
     * @param start          where the robot is before the first pose
     * @param movedJoints    0: every joint moves between poses (drawn poses, in {@code order}); k: each pose moves only k
     *                       joints, chosen at random, from the one before (the sequence is the order), and the controller
     *                       reports its values with a read-back jitter of {@link #READBACK_JITTER_RAD}
     * @param approach       null: each pose is reached by one move from the pose before; else the drives it rules take
     *                       each pose by a short move from a fixed side ({@link Approach})
     * @param linkageRange   a linkage's joint kept within its limits as the arm's own angle θ = C q, not only as the drive's
     *                       value q (a parallel arm's crank cannot turn through the upper arm; without this the drives' ranges
     *                       alone are kept, as a planner reading only the drive limits would)
     */
    public record Plan(int poses, int validatePoses, double sigmaM, double sigmaRotRad, boolean sixD, boolean dirColumns,
                       boolean conditionColumns, double[] payloadStepsKg, Order order, long seed, int outliers, Start start,
                       int movedJoints, Approach approach, boolean linkageRange) {
        public Plan {
            if (poses < 1 || validatePoses < 0) throw new IllegalArgumentException("poses " + poses + ", validate " + validatePoses);
            if (outliers < 0 || outliers > poses / 10) throw new IllegalArgumentException("outliers " + outliers + " of " + poses + " poses");
            if (!(sigmaM >= 0) || !(sigmaRotRad >= 0)) throw new IllegalArgumentException("noise must be >= 0");
            payloadStepsKg = payloadStepsKg.clone();
        }

        @Override public double[] payloadStepsKg() { return payloadStepsKg.clone(); }

        /** 200 training and 100 validation poses, σ 0.02 mm, directions, time and temperature written, no payload, nearest order. */
        public static Plan defaults(long seed) {
            return new Plan(200, 100, 0.02e-3, Math.toRadians(0.002), false, true, true, new double[0], Order.NEAREST, seed, 0, Start.HOME, 0, null, false);
        }

        public Plan withPoses(int n, int validate) { return new Plan(n, validate, sigmaM, sigmaRotRad, sixD, dirColumns, conditionColumns, payloadStepsKg, order, seed, outliers, start, movedJoints, approach, linkageRange); }
        public Plan withSigma(double m) { return new Plan(poses, validatePoses, m, sigmaRotRad, sixD, dirColumns, conditionColumns, payloadStepsKg, order, seed, outliers, start, movedJoints, approach, linkageRange); }
        public Plan withSigmaRot(double rad) { return new Plan(poses, validatePoses, sigmaM, rad, sixD, dirColumns, conditionColumns, payloadStepsKg, order, seed, outliers, start, movedJoints, approach, linkageRange); }
        public Plan withSixD(boolean b) { return new Plan(poses, validatePoses, sigmaM, sigmaRotRad, b, dirColumns, conditionColumns, payloadStepsKg, order, seed, outliers, start, movedJoints, approach, linkageRange); }
        public Plan withDirColumns(boolean b) { return new Plan(poses, validatePoses, sigmaM, sigmaRotRad, sixD, b, conditionColumns, payloadStepsKg, order, seed, outliers, start, movedJoints, approach, linkageRange); }
        public Plan withConditionColumns(boolean b) { return new Plan(poses, validatePoses, sigmaM, sigmaRotRad, sixD, dirColumns, b, payloadStepsKg, order, seed, outliers, start, movedJoints, approach, linkageRange); }
        public Plan withPayloads(double... kg) { return new Plan(poses, validatePoses, sigmaM, sigmaRotRad, sixD, dirColumns, conditionColumns, kg, order, seed, outliers, start, movedJoints, approach, linkageRange); }
        public Plan withOrder(Order o) { return new Plan(poses, validatePoses, sigmaM, sigmaRotRad, sixD, dirColumns, conditionColumns, payloadStepsKg, o, seed, outliers, start, movedJoints, approach, linkageRange); }
        public Plan withOutliers(int n) { return new Plan(poses, validatePoses, sigmaM, sigmaRotRad, sixD, dirColumns, conditionColumns, payloadStepsKg, order, seed, n, start, movedJoints, approach, linkageRange); }
        public Plan withStart(Start s) { return new Plan(poses, validatePoses, sigmaM, sigmaRotRad, sixD, dirColumns, conditionColumns, payloadStepsKg, order, seed, outliers, s, movedJoints, approach, linkageRange); }
        public Plan withMovedJoints(int k) { return new Plan(poses, validatePoses, sigmaM, sigmaRotRad, sixD, dirColumns, conditionColumns, payloadStepsKg, order, seed, outliers, start, k, approach, linkageRange); }
        public Plan withApproach(Approach a) { return new Plan(poses, validatePoses, sigmaM, sigmaRotRad, sixD, dirColumns, conditionColumns, payloadStepsKg, order, seed, outliers, start, movedJoints, a, linkageRange); }
        public Plan withLinkageRange(boolean b) { return new Plan(poses, validatePoses, sigmaM, sigmaRotRad, sixD, dirColumns, conditionColumns, payloadStepsKg, order, seed, outliers, start, movedJoints, approach, b); }
        public Plan withSeed(long s) { return new Plan(poses, validatePoses, sigmaM, sigmaRotRad, sixD, dirColumns, conditionColumns, payloadStepsKg, order, s, outliers, start, movedJoints, approach, linkageRange); }
    }

    /**
     * A one-sided approach, as a careful calibration engineer programs it to take the play out of
     * the data: each pose is reached through an approach pose short of it, so that every drive the
     * rule holds takes the pose by a short move from a fixed side (e.g. every last move positive).
     * The controller moves all drives at once to the approach pose (the drives without a rule
     * straight to their values at the pose), stops there, then moves the ruled drives onto the pose.
     * The file records only the measured pose, with the side in its dir columns; the move lengths
     * are in the controller's program, not in the file.
     *
     * <p>What a drive's play and friction see is its last motion since it last reversed: the
     * approach move alone when the travel to the approach pose went the other way (the motor turns
     * round at the approach pose and crosses the play), the travel and the approach together when
     * both went the same way (a stop does not reverse the gear's flank nor unwind its friction).
     *
     * @param side       per drive: +1 (each pose taken moving up), -1 (moving down), 0 (no rule: one move, as without
     *                   an approach)
     * @param minRad     the shortest approach move (rad, or m for a prismatic drive)
     * @param maxRad     the longest; each pose and drive draws its approach length between the two, log-uniformly
     *                   (equal to the shortest: a fixed approach length); never beyond the drive's limits
     * @param otherSide  the share of poses (drawn at random) at which every ruled drive is approached from the other side
     */
    public record Approach(int[] side, double minRad, double maxRad, double otherSide) {
        public Approach {
            side = side.clone();
            for (int s : side) if (s < -1 || s > 1) throw new IllegalArgumentException("approach side " + s + " is not -1, 0 or 1");
            if (!(minRad > 0) || !(maxRad >= minRad)) throw new IllegalArgumentException("approach length " + minRad + ".." + maxRad);
            if (!(otherSide >= 0 && otherSide < 1)) throw new IllegalArgumentException("share from the other side " + otherSide);
        }

        @Override public int[] side() { return side.clone(); }

        /** Every drive approached from {@code side}, by {@code minRad}..{@code maxRad}, a share {@code otherSide} of the poses from the other side. */
        public static Approach all(int dof, int side, double minRad, double maxRad, double otherSide) {
            int[] s = new int[dof];
            Arrays.fill(s, side);
            return new Approach(s, minRad, maxRad, otherSide);
        }

        /** Whether drive j is ruled. */
        boolean rules(int j) { return j < side.length && side[j] != 0; }
    }

    /**
     * The controller's read-back jitter, rad (0.0001°, a few motor encoder counts through the
     * gear): a joint that did not move shows this much change in the file.
     */
    public static final double READBACK_JITTER_RAD = Math.toRadians(0.0001);

    /** Poses between payload changes. */
    public static final int POSES_PER_PAYLOAD = 15;

    /**
     * The temperature near the robot: T(t) = ambient + rise (1 - exp(-t/tau)), a first-order
     * warm-up of the structure after the robot starts moving; the sensor adds noise.
     */
    public record Warmup(double ambientC, double riseK, double tauS, double sensorNoiseK) {
        public double at(double tS) { return ambientC + riseK * (1 - Math.exp(-tS / tauS)); }

        /** Ambient 19–22 °C, rise 6–15 K, tau 900–2400 s, sensor noise 0.05 K. */
        public static Warmup draw(Random r) {
            return new Warmup(19 + 3 * r.nextDouble(), 6 + 9 * r.nextDouble(), 900 + 1500 * r.nextDouble(), 0.05);
        }
    }

    /**
     * One measured pose.
     *
     * @param q           the controller's values as it reports them (with read-back jitter in a joint-by-joint campaign)
     * @param dir         the sign of each drive's last commanded motion, as a controller logs it (the dir columns)
     * @param side        where each drive's output really rests within its play, +1 (lagging, after a rise) to -1:
     *                    a reversal shorter than the play leaves it where it stood
     * @param lastMove    each drive's last motion, signed (rad or m; infinite: none yet, taken as long): the move from the pose
     *                    before; with an {@link Approach} the approach move, or the travel and the approach together when both
     *                    went the same way
     * @param point       measured position, instrument frame, m (with noise)
     * @param quaternion  measured orientation (w, x, y, z), or null
     * @param truePoint   the position without noise, m
     * @param outlier     the reading is grossly wrong (an injected outlier)
     */
    public record Row(String id, double[] q, int[] dir, double[] side, double[] lastMove, double timeS, double tempC, double payloadKg, double[] point,
                      double[] quaternion, double[] truePoint, boolean validate, boolean outlier) { }

    /** A campaign: the measurement file's text, the rows, and the warm-up the temperatures followed. */
    public record Result(String text, List<Row> rows, Warmup warmup, Plan plan, String frame) {
        public List<Row> train() { return rows.stream().filter(r -> !r.validate()).toList(); }

        public List<Row> validation() { return rows.stream().filter(Row::validate).toList(); }
    }

    /** Measures {@code world} (planning with the robot file {@code nominal}) following {@code plan}. */
    public static Result run(WorldRobot world, RobotDescription nominal, Plan plan) {
        Random rng = new Random(plan.seed() * 1_000_003L + 11);
        Random noise = new Random(plan.seed() * 7_919L + 3);
        // the gross errors have their own stream, so that a campaign without them (a twin) keeps every other draw
        Random gross = new Random(plan.seed() * 104_729L + 17);
        int total = plan.poses() + plan.validatePoses();
        List<double[]> drawn = new PoseRule(nominal, plan.linkageRange()).sample(total, rng);
        double[] start = plan.start() == Start.ELSEWHERE
                ? new PoseRule(nominal).sample(1, new Random(plan.seed() * 65_537L + 5)).get(0) : home(nominal);
        List<double[]> seq = plan.movedJoints() > 0 ? new PoseRule(nominal, plan.linkageRange()).walk(total, plan.movedJoints(), rng)
                : plan.order() == Order.NEAREST ? nearestOrder(nominal, drawn, start) : drawn;
        Random jitter = new Random(plan.seed() * 524_287L + 13);
        Random approach = new Random(plan.seed() * 2_305_843L + 29);
        boolean[] validate = new boolean[total];
        List<Integer> idx = new ArrayList<>();
        for (int i = 0; i < total; i++) idx.add(i);
        java.util.Collections.shuffle(idx, rng);
        for (int i = 0; i < plan.validatePoses(); i++) validate[idx.get(i)] = true;
        Warmup warm = Warmup.draw(rng);
        boolean[] outlier = new boolean[total];
        for (int i = plan.validatePoses(), k = 0; k < plan.outliers(); i++, k++) outlier[idx.get(i)] = true;

        int n = nominal.dof();
        double[] prev = start;
        int[] dir = new int[n];
        Arrays.fill(dir, 1);
        double[] lastMove = new double[n];
        Arrays.fill(lastMove, Double.POSITIVE_INFINITY);
        if (plan.start() == Start.ELSEWHERE) {
            Random d = new Random(plan.seed() * 131L + 7);
            for (int j = 0; j < n; j++) dir[j] = d.nextBoolean() ? 1 : -1;
        }
        double[] side = new double[n];
        for (int j = 0; j < n; j++) side[j] = dir[j];
        double t = 0;
        List<Row> rows = new ArrayList<>();
        double[] payloads = plan.payloadStepsKg();
        for (int i = 0; i < total; i++) {
            double[] q = seq.get(i);
            double travel;
            if (plan.approach() == null) {
                travel = travelS(nominal, prev, q);
                for (int j = 0; j < n; j++)
                    if (q[j] != prev[j]) {
                        dir[j] = q[j] > prev[j] ? 1 : -1;
                        lastMove[j] = q[j] - prev[j];
                    }
                moveWithinPlay(world, side, prev, q);
            } else {
                double[] via = approachPose(nominal, plan.approach(), q, approach);
                travel = travelS(nominal, prev, via) + travelS(nominal, via, q);
                moveWithinPlay(world, side, prev, via);
                moveWithinPlay(world, side, via, q);
                for (int j = 0; j < n; j++) {
                    double first = via[j] - prev[j], last = q[j] - via[j];
                    if (last == 0) last = first;                      // no approach move: the travel was the last motion
                    else if (first != 0 && (first > 0) == (last > 0)) last += first; // one motion with a stop in it
                    if (last != 0) {
                        dir[j] = last > 0 ? 1 : -1;
                        lastMove[j] = last;
                    }
                }
            }
            t += travel + 3 + 5 + 4 * rng.nextDouble(); // travel, settle, measure, operator
            double temp = warm.at(t);
            double payload = payloads.length == 0 ? 0 : payloads[(i / POSES_PER_PAYLOAD) % payloads.length];
            Rigid pose = world.target(q, dir, side, lastMove, temp, t, payload);
            double[] truth = pose.p();
            double[] p = Rigid.plus(truth, Arm.gauss(noise, plan.sigmaM()));
            if (outlier[i]) p = Rigid.plus(p, Rigid.scale(Rigid.unit(Arm.gauss(gross, 1)), 0.5e-3 + 2.5e-3 * gross.nextDouble()));
            double[] quat = null;
            if (plan.sixD()) {
                double[] rv = Arm.gauss(noise, plan.sigmaRotRad());
                double a = Rigid.norm(rv);
                Rigid turn = a > 0 ? Rigid.rotation(Rigid.unit(rv), a, new double[3]) : Rigid.IDENTITY;
                quat = turn.times(new Rigid(pose.r(), new double[3])).quaternion();
            }
            double tempRead = temp + warm.sensorNoiseK() * noise.nextGaussian();
            double[] read = q.clone();
            if (plan.movedJoints() > 0) for (int j = 0; j < n; j++) read[j] += READBACK_JITTER_RAD * jitter.nextGaussian();
            rows.add(new Row(Integer.toString(i + 1), read, dir.clone(), side.clone(), lastMove.clone(), t, tempRead, payload, p, quat, truth, validate[i], outlier[i]));
            prev = q;
        }
        boolean base = isIdentity(world.instrumentFromBase());
        String frame = base ? "base" : "tracker";
        return new Result(write(nominal, plan, rows, frame), rows, warm, plan, frame);
    }

    /**
     * Each drive's output moved through its play by a commanded move from {@code a} to {@code b}: the
     * output stays put until the motor has crossed the play, then follows it on the far flank (the
     * play operator of a backlash, out = clamp(out_before, in - b/2, in + b/2); Nordin &amp; Gutman,
     * "Controlling mechanical systems with backlash: a survey", Automatica 38 (2002) 1633, §2).
     * {@code side} (+1 lagging after a rise, -1 after a fall) is updated in place; a drive without
     * play rests on the flank of its last move.
     */
    static void moveWithinPlay(WorldRobot world, double[] side, double[] a, double[] b) {
        for (int j = 0; j < side.length; j++) {
            double move = b[j] - a[j];
            if (move == 0) continue;
            double wa = world.playWidth(j, a), wb = world.playWidth(j, b);
            if (!(wb > 0)) { side[j] = move > 0 ? 1 : -1; continue; }
            double offset = -0.5 * wa * side[j] - move;              // output minus motor if the output stood still
            side[j] = -2 * Math.max(-0.5 * wb, Math.min(0.5 * wb, offset)) / wb;
        }
    }

    /**
     * The approach pose before {@code q}: each ruled drive short of its value by a length drawn from
     * the rule's range, on the rule's side (the other side at a drawn share of the poses), within
     * the drive's limits; the other drives at their values.
     */
    static double[] approachPose(RobotDescription robot, Approach a, double[] q, Random r) {
        int flip = r.nextDouble() < a.otherSide() ? -1 : 1;
        double[] via = q.clone();
        for (int j = 0; j < q.length; j++) {
            double len = a.minRad() * Math.pow(a.maxRad() / a.minRad(), r.nextDouble());
            if (!a.rules(j)) continue;
            JointDescription d = robot.joints().get(j);
            via[j] = Math.min(d.max(), Math.max(d.min(), q[j] - flip * a.side()[j] * len));
        }
        return via;
    }

    /** The measurement file text (shared/formats/measurements.md): mm and degrees. */
    static String write(RobotDescription robot, Plan plan, List<Row> rows, String frame) {
        int n = robot.dof();
        boolean[] prismatic = new boolean[n];
        for (int j = 0; j < n; j++) prismatic[j] = robot.joints().get(j).type() == org.robopro.models.JointType.PRISMATIC;
        StringBuilder sb = new StringBuilder();
        sb.append("# robopro-measurements 1\n# robot: ").append(robot.name()).append('\n');
        sb.append("# length-unit: mm\n# angle-unit: deg\n# frame: ").append(frame).append('\n');
        sb.append(String.format(Locale.ROOT, "# instrument: simulated by robopro world, sigma %.4f mm, seed %d%n", plan.sigmaM() * 1e3, plan.seed()));
        List<String> head = new ArrayList<>(List.of("pose"));
        for (int j = 1; j <= n; j++) head.add("q" + j);
        head.addAll(List.of("x", "y", "z"));
        if (plan.sixD()) head.addAll(List.of("qw", "qx", "qy", "qz"));
        if (plan.dirColumns()) for (int j = 1; j <= n; j++) head.add("dir" + j);
        if (plan.conditionColumns()) head.addAll(List.of("time_s", "temp_c"));
        if (plan.payloadStepsKg().length > 0) head.add("payload_kg");
        if (plan.validatePoses() > 0) head.add("set");
        sb.append(String.join(",", head)).append('\n');
        for (Row r : rows) {
            sb.append(r.id());
            for (int j = 0; j < n; j++) sb.append(',').append(fmt(prismatic[j] ? r.q()[j] * 1e3 : Math.toDegrees(r.q()[j]), 7));
            for (double v : r.point()) sb.append(',').append(fmt(v * 1e3, 5));
            if (plan.sixD()) for (double v : r.quaternion()) sb.append(',').append(fmt(v, 10));
            if (plan.dirColumns()) for (int d : r.dir()) sb.append(',').append(d);
            if (plan.conditionColumns()) sb.append(',').append(fmt(r.timeS(), 1)).append(',').append(fmt(r.tempC(), 2));
            if (plan.payloadStepsKg().length > 0) sb.append(',').append(fmt(r.payloadKg(), 2));
            if (plan.validatePoses() > 0) sb.append(',').append(r.validate() ? "validate" : "train");
            sb.append('\n');
        }
        return sb.toString();
    }

    static String fmt(double v, int decimals) { return String.format(Locale.ROOT, "%." + decimals + "f", v); }

    /** The home pose: zero where the limits allow it, else the middle of the range. */
    static double[] home(RobotDescription robot) {
        double[] h = new double[robot.dof()];
        for (int j = 0; j < h.length; j++) {
            JointDescription d = robot.joints().get(j);
            if (!(d.min() <= 0 && d.max() >= 0)) h[j] = 0.5 * (d.min() + d.max());
        }
        return h;
    }

    /** Seconds to move from a to b at a third of each joint's top speed (the slowest joint decides), plus 1 s to accelerate. */
    static double travelS(RobotDescription robot, double[] a, double[] b) {
        double t = 0;
        for (int j = 0; j < a.length; j++) {
            double v = robot.joints().get(j).maxSpeed();
            if (!(v > 0)) v = Math.toRadians(90);
            t = Math.max(t, Math.abs(b[j] - a[j]) / (v / 3));
        }
        return t + 1;
    }

    static List<double[]> nearestOrder(RobotDescription robot, List<double[]> poses, double[] start) {
        List<double[]> left = new ArrayList<>(poses), out = new ArrayList<>();
        double[] at = start;
        while (!left.isEmpty()) {
            int best = 0;
            double bestT = Double.MAX_VALUE;
            for (int i = 0; i < left.size(); i++) {
                double tt = travelS(robot, at, left.get(i));
                if (tt < bestT) { bestT = tt; best = i; }
            }
            at = left.remove(best);
            out.add(at);
        }
        return out;
    }

    static boolean isIdentity(Rigid t) {
        double[] r = t.r(), p = t.p();
        for (int i = 0; i < 9; i++) if (Math.abs(r[i] - (i % 4 == 0 ? 1 : 0)) > 1e-15) return false;
        return p[0] == 0 && p[1] == 0 && p[2] == 0;
    }
}
