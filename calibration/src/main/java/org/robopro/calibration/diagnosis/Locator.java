package org.robopro.calibration.diagnosis;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import org.ejml.data.DMatrixRMaj;
import org.ejml.dense.row.CommonOps_DDRM;
import org.robopro.calibration.PoseConditions;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.Vec3;

/**
 * The locate scan (docs/diagnosis.md "Locate"): where does what the model leaves live? The
 * residual is tested against every variable the data offer, each as a block of signature
 * columns projected out of the current model's span (closed form, no fit):
 * <ul>
 * <li>each joint angle, periodic: harmonics h = 1..H of q_j acting on drive j (H from the number
 *     of poses, {@link #harmonicsFor}), each harmonic its own 2-column test;</li>
 * <li>each joint angle, non-periodic: a cubic B-spline of q_j over its sampled range at each resolution of
 *     {@link Effect#SMOOTH_RESOLUTIONS} the poses support (a slow drift, or a place-bound bump);</li>
 * <li>each drive and each other joint: the drive's error as the products of the two angles' sines and
 *     cosines ({@link Effect#pair}), structure no function of one joint holds;</li>
 * <li>each joint's approach direction (recorded or inferred);</li>
 * <li>time, temperature: a point translation and a length change, each a 4-function spline of the variable;</li>
 * <li>payload: its torque on each drive, and a point translation proportional to it;</li>
 * <li>reach and height of the measured point: a point translation as a 4-function spline of each.</li>
 * </ul>
 * Structures are accepted greedily (lowest BIC among those that pass) with the same
 * false-positive control as the effects: Holm over the family (step s uses α/(N − s)), a smaller
 * leave-one-pose-out error, and a backward step that drops a structure the others made redundant.
 */
final class Locator {
    /**
     * Poses per harmonic: up to n/5 harmonics are scanned, and at least 40 (gear stages) while
     * there are 3 poses per cycle; above that a joint's harmonics cannot be told apart.
     */
    static final int POSES_PER_HARMONIC = 5;
    /** Harmonics scanned at most (a gear stage up to 40 cycles per turn and its neighbours). */
    static final int MAX_HARMONIC = 60;
    /** Harmonics the scan should reach to cover gear stages. */
    static final int WANTED_HARMONIC = 40;

    enum Var { ANGLE_PERIODIC, ANGLE_SMOOTH, ANGLE_STEP, JOINT_PAIR, DIRECTION, SETTLING, TIME, TIME_STEP, TARGET_STEP, BASE_STEP, RANGE_STEP, TEMPERATURE, PAYLOAD, PAYLOAD_REACH, REACH, HEIGHT, SIGHT, BASE_MOMENT, AXIS_WOBBLE, AXIAL_RUNOUT, TOOL_GRAVITY, TOOL_PLAY, LINK_BEND, LINK_TWIST, TARGET_SIGHT, GRAVITY_PLAY, TARGET_DRIFT, BASE_CREEP, LINK_PERIODIC, WARM_PERIODIC, TOOL_PULL, LOAD_TILT, STATION }

    /** Spline functions of an instrument's distance reading tried: a scale-like trend, then a cyclic error of a few hundred mm. */
    static final int[] RANGE_RESOLUTIONS = {4, 13, 25};
    /** Spline functions of an instrument's angle reading tried (an encoder's error once or twice per turn over the angles seen). */
    static final int[] ANGLE_RESOLUTIONS = {4, 7};
    /**
     * Shortest period of a distance meter's cyclic error scanned, m: phase-measuring meters repeat
     * their error over half a modulation wavelength, decimetres to metres; a shorter one is within
     * the noise of a campaign's poses (a few per period at least are needed).
     */
    static final double MIN_RANGE_CYCLE_M = 0.02;

    /**
     * Places of a step (a reading's step in a joint's angle, a joint's zero step or the target's move
     * in time): these quantiles of the poses' values, and a found step's finer places within this
     * share of the poses either side (a step found is then placed between the two poses that explain
     * it best; at 10 places a step in an angle between two of them lost to the smooth curve before it
     * could be placed).
     */
    static final int STEP_PLACES = 20;

    /** One probe: a block of signature columns. */
    static final class Probe {
        Var var;
        int joint = -1, harmonic, other = -1, basis;
        double order;               // a stage order that is not whole (cycles per turn; ANGLE_PERIODIC from the stage scan), else 0
        boolean stage;              // from the stage scan (placed there, above the harmonic probes)
        double lo, hi;              // range of the variable (smooth, reach, height, time, temperature)
        boolean lengths;            // a length change (not a point translation or a drive)
        double[] linkAngle;         // the link angle a LINK_PERIODIC harmonic repeats with (Effect#linkAngle)
        String variable, shape, detail;
        private double[] s; // m x k, projected out of the model's span (made from raw when first asked for)
        double[] raw;       // m x k before that projection, or null when the projected columns were given
        double[] span;      // with raw: its coefficients on the span's orthonormal basis, Uᵀ raw (k x rank)
        private double[] u; // with raw: that basis (m x rank)
        private int rank;
        double[] n0;  // unprojected column norms
        int k;

        /** The columns projected out of the model's span. */
        double[] s() {
            if (s == null) s = Diagnoser.subtractSpan(u, rank, raw.length / k, raw, k, span);
            return s;
        }

        /** The raw columns s (m x k) and their coefficients on the rank orthonormal columns u, projected out of u when first asked for. */
        void unprojected(double[] s, double[] u, int rank, double[] span) {
            raw = s;
            this.u = u;
            this.rank = rank;
            this.span = span;
        }
        double[][] x; // per end and pose, the variable (plots)
        double[][] endS; // with two ends: each end's own columns (m x k, unprojected), else null
        double[][][] rf; // a move of the target on the flange: each end's and pose's flange rotation (row-major)
        double[] sens;   // RANGE_STEP: each residual row's change for a unit change of the instrument's distance
        Angle angle;     // a drive's error as a function of its joint angle: the regressor (ANGLE_PERIODIC, ANGLE_SMOOTH)
        Effect.Sight sight;                      // SIGHT: the instrument's reading
        org.robopro.kinematics.Pose instrument;  // SIGHT, RANGE_STEP: instrumentTbase at the scanned fit
        double azimuthRef;                       // SIGHT: the azimuth the readings are taken about
        double cycle;                            // SIGHT: the period of a cyclic error of the reading (0: a spline)
        int cycleOrders = 1;                     // SIGHT with a cycle: its harmonics 1..this
        double[] reading;                        // SIGHT with a cycle: each residual row's reading (its sensitivity in sens)
        Directions.Source dirs;                  // DIRECTION: where the directions came from
        Effect settling;                         // DIRECTION, SETTLING: the joint's settling after the move, where the moves are known
        Effect tilt;                             // BASE_MOMENT, once found: the base tilt that predicts left-out poses best
        Effect bend;                             // LINK_BEND, LINK_TWIST, LOAD_TILT: the link's sag or twist, the axis's tilt
        Effect incidence;                        // TARGET_SIGHT: the reflector's error with the direction it is seen from
        Effect play;                             // GRAVITY_PLAY: the joint's play taken up by gravity
        Effect creep;                            // BASE_CREEP: the base's turns with joint 1's large moves
        Effect pull;                             // TOOL_PULL, once found: the pull toward the anchor that fits best
        Vec3 pullAttach;                         // TOOL_PULL: where the pull acts, flange frame
        Vec3 facing;                             // STATION: the side the second station's poses face
        Effect station;                          // STATION, once found: the split that explains most
        String xLabel;
    }

    /** A structure found. */
    static final class Found {
        Probe probe;
        Diagnoser.Candidate c;
        double sizeM;
        /**
         * A harmonic located (ANGLE_PERIODIC): the lowest and highest harmonic numbers the poses allow
         * for it ({@link #placeHarmonics}); equal when it is placed exactly.
         */
        int placeLo, placeHi;
        /**
         * A smooth structure of a joint's angle (ANGLE_SMOOTH) that a few resolvable harmonics of the
         * joint hold as well ({@link #sparseHarmonics}), with each one's allowed range, or null.
         */
        int[] sparse, sparseLo, sparseHi;
        /** The harmonics {@link #sparse} predict left-out poses better than every smooth curve of the angle (else they are as good an explanation, not a better one). */
        boolean sparseBetter;

        /** The harmonics {@link #sparse} are a family's candidate: better than every smooth curve and each placed to one number. */
        boolean sparseClaim() {
            if (sparse == null || !sparseBetter) return false;
            for (int i = 0; i < sparse.length; i++) if (sparseHi[i] > sparseLo[i]) return false;
            return true;
        }
    }

    /** The harmonics of each joint a campaign of {@code poses} poses can resolve. */
    static int harmonicsFor(int poses) {
        return Math.max(WANTED_HARMONIC, Math.min(MAX_HARMONIC, poses / POSES_PER_HARMONIC));
    }

    private Locator() { }

    /**
     * The probes the data offer at this fit. A residual row depends on one pose, or on two for a
     * distance between a pair of poses ({@link Diagnoser.Tester#ends}): a probe's column is then
     * the sum over both ends of each end's sensitivity times the regressor at that end's own
     * joints, conditions and measured point (a joint error f(q) changes the length by
     * uᵀ(J_b f(q_b) − J_a f(q_a)), not by a function of one pose's variable).
     */
    static List<Probe> probes(Diagnoser.Tester t, Directions.Source dirs) { return probes(t, dirs, true); }

    /**
     * As above; without {@code steps} the steps of a joint's reading at one angle and of the target
     * on the flange at one time, the reflector's error with the line of sight, a wrist joint's error with
     * its housing's angle and a joint's error growing with the temperature are left out (the
     * stepwise search's re-scans: such a structure shows in the geometric fit's residuals already, and
     * its probes are a good share of the scan's cost).
     */
    static List<Probe> probes(Diagnoser.Tester t, Directions.Source dirs, boolean steps) {
        Diagnoser.Work w = t.w;
        int dof = t.dof, poses = w.rows.size(), ends = t.ends;
        List<Probe> out = new ArrayList<>();
        int hMax = harmonicsFor(poses);
        for (int j = 0; j < dof; j++) {
            double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
            double[][] qx = new double[ends][poses];
            for (int e = 0; e < ends; e++)
                for (int i = 0; i < poses; i++) {
                    double q = t.endRows.get(e).get(i).q(j);
                    lo = Math.min(lo, q);
                    hi = Math.max(hi, q);
                    qx[e][i] = Math.toDegrees(q);
                }
            if (!(hi - lo > 1e-6) || w.model.isPrismatic(j)) continue;
            final int jj = j;
            // the harmonics', the smooth curves' and the two-joint products' columns on drive j, projected in one pass
            List<Reg> regs = new ArrayList<>();
            List<Integer> ks = new ArrayList<>();
            for (int h = 1; h <= hMax; h++) {
                final int hh = h;
                regs.add((e, i, g) -> { double q = t.endRows.get(e).get(i).q(jj); g[0] = Math.sin(hh * q); g[1] = Math.cos(hh * q); });
                ks.add(2);
            }
            final double l0 = lo, h0 = hi;
            List<Integer> resolutions = new ArrayList<>();
            for (int nb : Effect.SMOOTH_RESOLUTIONS) {
                if (!Effect.supported(nb, Effect.SMOOTH_BASIS, poses)) continue;
                resolutions.add(nb);
                regs.add((e, i, g) -> Effect.bspline(t.endRows.get(e).get(i).q(jj), l0, h0, g));
                ks.add(nb);
            }
            List<Integer> others = new ArrayList<>();
            for (int k = 0; k < dof; k++) {
                if (k == j || w.model.isPrismatic(k)) continue;
                final int kk = k;
                others.add(k);
                // the products only: the linear terms are scale and coupling shapes, which the families' own tests hold
                regs.add((e, i, g) -> Effect.pairProducts(t.endRows.get(e).get(i).q(), jj, kk, g));
                ks.add(4);
            }
            List<Probe> batch = drives(t, j, ks, regs);
            int b = 0;
            for (int h = 1; h <= hMax; h++) {
                final int hh = h;
                Angle f = (q, g) -> { g[0] = Math.sin(hh * q); g[1] = Math.cos(hh * q); };
                Probe p = batch.get(b++);
                p.angle = f;
                p.var = Var.ANGLE_PERIODIC;
                p.joint = j;
                p.harmonic = h;
                p.variable = "joint " + (j + 1) + " angle";
                p.shape = h + (h == 1 ? " cycle" : " cycles") + " per turn of joint " + (j + 1);
                p.x = qx;
                p.xLabel = "joint " + (j + 1) + " angle q" + (j + 1) + " (deg)";
                out.add(p);
            }
            for (int nb : resolutions) {
                Angle f = (q, g) -> Effect.bspline(q, l0, h0, g);
                Probe p = batch.get(b++);
                p.angle = f;
                p.var = Var.ANGLE_SMOOTH;
                p.joint = j;
                p.basis = nb;
                p.lo = lo;
                p.hi = hi;
                p.variable = "joint " + (j + 1) + " angle";
                p.shape = String.format(Locale.ROOT, "a smooth, non-periodic function of joint %d's angle over %.0f..%.0f deg%s", j + 1,
                        Math.toDegrees(lo), Math.toDegrees(hi), nb == Effect.SMOOTH_BASIS ? ""
                                : String.format(Locale.ROOT, " with features about %.0f deg wide", Math.toDegrees(hi - lo) / (nb - 3)));
                p.x = qx;
                p.xLabel = "joint " + (j + 1) + " angle q" + (j + 1) + " (deg)";
                out.add(p);
            }
            // the reading jumps where the joint passes one angle (an absolute encoder's track): a step at quantiles of q_j
            if (steps) for (double q0 : stepPlaces(qx[0], STEP_PLACES)) out.add(angleStep(t, j, Math.toRadians(q0), qx));
            for (int k : others) {
                Probe p = batch.get(b++);
                p.var = Var.JOINT_PAIR;
                p.joint = j;
                p.other = k;
                p.variable = "joints " + (j + 1) + " and " + (k + 1);
                p.shape = "joint " + (j + 1) + "'s error depends on joints " + (j + 1) + " and " + (k + 1) + " together";
                p.x = qx;
                p.xLabel = "joint " + (j + 1) + " angle q" + (j + 1) + " (deg)";
                out.add(p);
            }
            // the joint's settling after the move, where the measuring order gives the moves
            Effect settling = t.w.moves.isEmpty() ? null : Effect.settling(j, t.w.moves, t.w.speeds);
            if (dirs != Directions.Source.NONE && t.endRows.stream().allMatch(er -> er.stream().allMatch(r -> r.directions() != null))) {
                Probe d = drive(t, j, 1, (e, i, g) -> g[0] = -0.5 * t.endConditions.get(e).get(i).direction(jj));
                d.var = Var.DIRECTION;
                d.dirs = dirs;
                d.settling = settling;
                d.joint = j;
                d.variable = "direction of joint " + (j + 1);
                d.shape = "changes sign with the direction joint " + (j + 1) + " last moved in (directions " + dirs.words + ")";
                d.x = new double[ends][poses];
                for (int e = 0; e < ends; e++) for (int i = 0; i < poses; i++) d.x[e][i] = t.endConditions.get(e).get(i).direction(j);
                d.xLabel = "approach direction dir" + (j + 1);
                out.add(d);
            }
            // the joint's speed in the move just made (from the whole file's measuring order): the arm read before it settled
            if (settling != null) {
                double[][] speed = new double[ends][poses]; // rad/s
                for (int e = 0; e < ends; e++)
                    for (int i = 0; i < poses; i++) speed[e][i] = settling.settlingSpeed(t.endRows.get(e).get(i));
                Probe sp = drive(t, j, 1, (e, i, g) -> g[0] = speed[e][i]);
                sp.var = Var.SETTLING;
                sp.joint = j;
                sp.settling = settling;
                sp.variable = "speed of joint " + (j + 1) + " in the move before the reading";
                sp.shape = "follows joint " + (j + 1) + "'s speed in the move made just before the reading (the arm not settled when read)";
                sp.x = new double[ends][poses];
                for (int e = 0; e < ends; e++)
                    for (int i = 0; i < poses; i++) sp.x[e][i] = Math.toDegrees(speed[e][i]);
                sp.xLabel = "speed of joint " + (j + 1) + " in the move before the reading, synchronised (deg/s)";
                out.add(sp);
            }
        }
        out.addAll(linkPeriodics(t, hMax, steps));
        double[][] time = column(t, c -> c.timeS()), temp = column(t, c -> c.tempC()), pay = column(t, c -> c.payloadKg());
        if (steps && varies(temp, 0.5)) out.addAll(warmPeriodics(t, temp));
        if (varies(time, 1)) {
            out.add(scalar(t, Var.TIME, time, "time", "time since the start (s)", true));
            out.add(scalar(t, Var.TIME, time, "time", "time since the start (s)", false));
            for (int j = 0; j < dof; j++) out.add(zero(t, j, Var.TIME, time, "time", "time since the start (s)"));
            // each pose's flange orientation (row-major), for a move of the measured point on the flange
            double[][][] rf = steps ? new double[ends][poses][] : null;
            if (steps)
                for (int e = 0; e < ends; e++) for (int i = 0; i < poses; i++) rf[e][i] = w.model.flange(t.endRows.get(e).get(i).q()).rotationRowMajor();
            if (steps) out.add(targetDrift(t, time, rf));
            if (steps && ends == 1) out.addAll(baseCreeps(t));
            for (double tau : stepPlaces(time[0], STEP_PLACES)) {
                if (steps) out.add(targetStep(t, tau, time, rf));
                if (steps && ends == 1) out.add(baseStep(t, tau, time));
                for (int j = 0; j < dof; j++) out.add(zeroStep(t, j, tau, time));
            }
        }
        if (varies(temp, 0.5)) {
            out.add(scalar(t, Var.TEMPERATURE, temp, "temperature", "temperature (°C)", true));
            out.add(scalar(t, Var.TEMPERATURE, temp, "temperature", "temperature (°C)", false));
            for (int j = 0; j < dof; j++) out.add(zero(t, j, Var.TEMPERATURE, temp, "temperature", "temperature (°C)"));
        }
        if (varies(pay, 0.1)) {
            double[][][] tau = new double[ends][][];
            for (int e = 0; e < ends; e++) tau[e] = payloadTorques(t, e, pay[e]);
            for (int j = 0; j < dof; j++) {
                final int jj = j;
                Probe p = drive(t, j, 1, (e, i, g) -> g[0] = tau[e][i][jj]);
                p.var = Var.PAYLOAD;
                p.joint = j;
                p.variable = "payload";
                p.shape = "joint " + (j + 1) + " gives way in proportion to the payload's torque on it";
                p.x = pay;
                p.xLabel = "payload (kg)";
                out.add(p);
            }
        }
        double[][] reach = new double[ends][poses], height = new double[ends][poses];
        for (int e = 0; e < ends; e++)
            for (int i = 0; i < poses; i++) {
                reach[e][i] = Math.hypot(t.endPoint[e][i][0], t.endPoint[e][i][1]);
                height[e][i] = t.endPoint[e][i][2];
            }
        if (varies(reach, 0.05)) out.add(scalar(t, Var.REACH, reach, "reach of the measured point", "reach (m)", true));
        if (varies(reach, 0.05) && varies(pay, 0.1)) {
            // the same spline of reach, times the payload
            double lo = min(reach), hi = max(reach);
            int k = 3 * Effect.POINT_BASIS;
            Probe q = translation(t, k, (e, i, g) -> {
                Effect.bspline(reach[e][i], lo, hi, g); // g holds the POINT_BASIS functions; then times the payload
                for (int c = 0; c < Effect.POINT_BASIS; c++) g[c] *= pay[e][i];
            });
            q.var = Var.PAYLOAD_REACH;
            q.variable = "payload and reach";
            q.shape = "the measured point moves with the payload, the more the farther it reaches";
            q.x = reach;
            q.xLabel = "reach (m)";
            q.lo = lo;
            q.hi = hi;
            q.basis = Effect.POINT_BASIS;
            out.add(q);
        }
        if (varies(height, 0.05)) out.add(scalar(t, Var.HEIGHT, height, "height of the measured point", "height (m)", true));
        out.addAll(baseMoment(t));
        out.addAll(gravityPlays(t));
        out.addAll(axisWobbles(t));
        out.addAll(axialRunouts(t));
        if (steps) out.addAll(loadTilts(t));
        if (steps) out.addAll(stations(t));
        out.add(toolGravity(t));
        out.add(toolPlay(t));
        out.addAll(linkBends(t));
        out.addAll(linkTwist(t));
        // a pull on the tool: eighteen columns on a six-axis arm, in the geometric fit's and the final scans only
        Probe pull = steps ? toolPull(t) : null;
        if (pull != null) out.add(pull);
        out.addAll(sightProbes(t, steps, steps));
        // the reflector's error shows in the geometric fit's residuals already; its 32 columns are left out of the stepwise re-scans
        Probe incidence = steps ? targetSight(t) : null;
        if (incidence != null) out.add(incidence);
        return out;
    }

    /** The directions the point is seen from must spread this far about their mean (RMS angle, deg) for the reflector's incidence to show. */
    static final double MIN_INCIDENCE_SPREAD_DEG = 5;

    /**
     * An error of the measured point that follows the direction the instrument sees it from, in the
     * tool's frame ({@link Effect#targetIncidence}): a reflector seen off its axis. Positions of one
     * point per pose seen by an instrument; null when the directions barely change.
     */
    static Probe targetSight(Diagnoser.Tester t) {
        if (!t.w.instrument || t.ends != 1 || t.perPose != 1) return null;
        Diagnoser.Work w = t.w;
        int poses = w.rows.size();
        Pose inst = t.fit.problem.instrumentOf(t.fit.full);
        Vec3 origin = Effect.instrumentOrigin(inst);
        Pose[] f = new Pose[poses];
        Vec3[] u = new Vec3[poses];
        double mx = 0, my = 0, mz = 0;
        for (int i = 0; i < poses; i++) {
            f[i] = w.model.flange(w.rows.get(i).q());
            u[i] = Effect.sightInFlange(f[i], origin, t.pointsBase[i][0]);
            mx += u[i].x();
            my += u[i].y();
            mz += u[i].z();
        }
        Vec3 axis = new Vec3(mx, my, mz);
        if (!(axis.norm() > 0)) return null;
        axis = axis.times(1 / axis.norm());
        double[][] x = new double[1][poses];
        double spread = 0;
        double[][] rg = new double[poses][3 * Effect.INCIDENCE_TERMS];
        Vec3[] across = Effect.acrossAxis(axis);
        for (int i = 0; i < poses; i++) {
            x[0][i] = Effect.incidenceAngle(u[i], axis);
            spread += x[0][i] * x[0][i];
            Effect.incidenceRegressor(f[i], origin, axis, across, t.pointsBase[i][0], rg[i]);
        }
        if (!(Math.sqrt(spread / poses) >= MIN_INCIDENCE_SPREAD_DEG)) return null;
        int k = Effect.INCIDENCE_TERMS;
        Probe p = columns(t, k, (e, row, g, col) -> row % t.rpp >= t.posRows ? 0
                : t.endDTrans[e][row * 3] * g[col] + t.endDTrans[e][row * 3 + 1] * g[k + col] + t.endDTrans[e][row * 3 + 2] * g[2 * k + col],
                3 * k, (e, i, g) -> System.arraycopy(rg[i], 0, g, 0, 3 * k));
        p.var = Var.TARGET_SIGHT;
        p.incidence = Effect.targetIncidence(w.model, inst, axis);
        p.variable = "the direction the point is seen from, in the tool's frame";
        p.shape = "the measured point moves with the direction the instrument sees it from, in the tool's frame (a reflector seen off its axis)";
        p.x = x;
        p.xLabel = "angle of the line of sight from its mean direction in the tool's frame (deg)";
        return p;
    }

    /** The least number of poses on each side of a joint's gravity torque for its play taken up by gravity to be probed. */
    static final int MIN_PLAY_SIDE = 3;

    /**
     * Each joint's play taken up by gravity ({@link Effect#gravityPlay}): its reading steps where the
     * gravity torque on its drive changes sign, whatever the last motion, one column. The torque is
     * the robot file's masses', or without them an estimate from the link lengths; probed where at
     * least {@link #MIN_PLAY_SIDE} poses lie on each side of it (one measured point per pose).
     */
    static List<Probe> gravityPlays(Diagnoser.Tester t) {
        List<Probe> out = new ArrayList<>();
        GravityTorques g0 = t.w.gravity;
        if (g0 == null || t.ends != 1) return out;
        GravityTorques g = g0.massesUnknown() ? GravityTorques.fromLengths(t.w.model) : g0;
        double[][] torques = driveTorques(t.endRows.get(0), g);
        int poses = torques.length;
        for (int j = 0; j < t.dof; j++) {
            if (t.w.model.isPrismatic(j)) continue;
            double[][] tau = new double[1][poses];
            int pos = 0, neg = 0;
            for (int i = 0; i < poses; i++) {
                tau[0][i] = torques[i][j];
                if (tau[0][i] > 0) pos++;
                else if (tau[0][i] < 0) neg++;
            }
            if (Math.min(pos, neg) < MIN_PLAY_SIDE) continue;
            Probe p = drive(t, j, 1, (e, i, gg) -> gg[0] = 0.5 * Math.signum(tau[e][i]));
            p.var = Var.GRAVITY_PLAY;
            p.joint = j;
            p.play = Effect.gravityPlay(j, g, 0, 0);
            p.variable = "gravity torque on drive " + (j + 1);
            p.shape = "joint " + (j + 1) + "'s reading steps where the gravity torque on it changes sign, whatever the last motion "
                    + "(a play taken up by the arm's weight)";
            p.x = tau;
            p.xLabel = "gravity torque on drive " + (j + 1) + " (N·m)";
            out.add(p);
        }
        return out;
    }

    /**
     * The robot's base giving way on its foundation under the arm's overturning moment M (a loose
     * anchor bolt, a soft floor or base plate): the base turns by ω = C·M about horizontal axes, C a
     * symmetric 2 x 2 compliance (an elastic foundation's rotation under a moment: a rotational
     * spring per axis, Winkler foundation), and lifts by l·M where it pivots about an edge of its
     * foot. Five columns: C₁₁, C₂₂, C₁₂ and the lift's two; every measured point moves by ω × p + l·M ẑ.
     * The slide of a base that rocks about a point below its plate (a pedestal) is not probed: its
     * columns cost the probe power on small campaigns, and the tilt searched once the structure is
     * found carries it ({@link Effect#baseTilt}).
     * A base that tilts only one way (above a held moment) is partly in this span; the tilt itself
     * is searched once the structure is found ({@link Diagnoser#bestBaseTilt}). Beside it, a foot
     * that rocks toward whichever side the arm leans once the moment exceeds what its bolts hold
     * ({@link #BASE_HOLD_SHARES} of the poses tilted): two columns each, its tilt about the moment's
     * own axis and its lift. Positions only, one pose per row, with the robot file's masses; none
     * otherwise or when the moment does not vary.
     */
    static List<Probe> baseMoment(Diagnoser.Tester t) {
        GravityTorques g = t.w.gravity;
        List<Probe> out = new ArrayList<>();
        if (g == null || g.massesUnknown() || t.ends != 1) return out;
        int poses = t.m / t.rpp;
        double[][] mom = Diagnoser.moments(g, t.endRows.get(0));
        double[][] x = new double[1][poses];
        for (int i = 0; i < poses; i++) x[0][i] = Math.hypot(mom[i][0], mom[i][1]);
        if (!varies(x, 1)) return out;
        int k = 5;
        double[] sig = new double[t.m * k], g3 = new double[3 * k];
        double[] dt = t.endDTrans[0], dr = t.endDRot[0];
        for (int i = 0; i < poses; i++) {
            for (int a = 0; a < t.posRows; a++) {
                int row = i * t.rpp + a;
                baseMomentRegressor(mom[i], t.pointsBase[i][t.pointOfRow(a)], g3);
                for (int c = 0; c < k; c++) sig[row * k + c] = dt[row * 3] * g3[c] + dt[row * 3 + 1] * g3[k + c] + dt[row * 3 + 2] * g3[2 * k + c];
            }
            // orientation rows: the measured frame turns with the base by ω = C·M (C11, C22, C12; the lift turns nothing)
            for (int a = t.posRows; a < t.rpp; a++) {
                int row = i * t.rpp + a;
                double wx = dr[row * 3], wy = dr[row * 3 + 1];
                sig[row * k] = wx * mom[i][0];
                sig[row * k + 1] = wy * mom[i][1];
                sig[row * k + 2] = wx * mom[i][1] + wy * mom[i][0];
            }
        }
        Probe p = finish(t, sig, k);
        p.var = Var.BASE_MOMENT;
        p.variable = "the arm's overturning moment on the base";
        p.shape = "the robot's base tilts in proportion to the arm's moment on its foundation (an anchor bolt, the floor or the base plate gives way)";
        p.x = x;
        p.xLabel = "horizontal moment of the arm's weight on the base (N·m)";
        out.add(p);
        for (double share : BASE_HOLD_SHARES) {
            double hold = Diagnoser.tiltHold(mom, Double.NaN, share, 1);
            // the tilt and the lift (the slide of a pivot below the base plate is left to the tilt the fallback searches)
            double[] s2 = Diagnoser.tiltColumns(t, mom, Double.NaN, hold, 1, 2);
            if (s2 == null) continue;
            Probe q = finish(t, s2, 2);
            q.var = Var.BASE_MOMENT;
            q.variable = p.variable;
            q.shape = String.format(Locale.ROOT, "the robot's base rocks toward whichever side the arm leans once its moment exceeds "
                    + "about %.0f N·m (anchor bolts slack, a foot that rocks on its pad)", hold);
            q.x = x;
            q.xLabel = p.xLabel;
            out.add(q);
        }
        return out;
    }

    /**
     * The measured point's holder bending under its own weight ({@link Effect#toolSag}): the point
     * moves by a linear map of gravity's direction seen from the flange, nine columns. Positions
     * only (a point's holder turns no measured frame of its own).
     */
    static Probe toolGravity(Diagnoser.Tester t) {
        Probe p = flangeGravity(t, 9, (f, down, g3, r3) -> Effect.toolSagRegressor(f, down, g3));
        p.var = Var.TOOL_GRAVITY;
        p.shape = "the measured point moves with the direction of gravity seen from the flange (its holder bends under its own weight)";
        return p;
    }

    /**
     * The measured point's holder or the flange tipping within a clearance toward gravity ({@link Effect#toolPlay}):
     * six columns that move the point, and where orientations are measured four that tip the flange.
     */
    static Probe toolPlay(Diagnoser.Tester t) {
        boolean tips = t.rpp > t.posRows;
        int k = Effect.PLAY_SHIFTS + (tips ? Effect.PLAY_TIPS : 0);
        Probe p = flangeGravity(t, k, (f, down, g3, r3) -> {
            Effect.toolPlayRegressor(f, down, false, g3, k, 0);
            if (tips) Effect.toolPlayRegressor(f, down, true, r3, k, Effect.PLAY_SHIFTS);
        });
        p.var = Var.TOOL_PLAY;
        p.shape = "the measured point moves across the tool's axis toward the side gravity pulls it to, by the same amount whichever "
                + "way (a play taken up by the tool's weight)";
        return p;
    }

    /**
     * The 3 x k regressors (row-major, base axes) of an effect of gravity seen from the flange, at
     * flange pose f: g3 moves the measured point, r3 turns the measured frame (both zeroed before).
     */
    private interface FlangeRegressor { void at(Pose f, Vec3 down, double[] g3, double[] r3); }

    /** A probe of k columns that move the measured point, and turn the measured frame, with gravity seen from the flange. */
    private static Probe flangeGravity(Diagnoser.Tester t, int k, FlangeRegressor r) {
        Diagnoser.Work w = t.w;
        Vec3 down = Effect.DOWN;
        int poses = w.rows.size();
        double[][][] rf = new double[t.ends][poses][];
        double[][] x = new double[t.ends][poses];
        for (int e = 0; e < t.ends; e++)
            for (int i = 0; i < poses; i++) {
                Pose f = w.model.flange(t.endRows.get(e).get(i).q());
                double[] g3 = new double[3 * k], r3 = new double[3 * k];
                r.at(f, down, g3, r3);
                rf[e][i] = new double[6 * k];
                System.arraycopy(g3, 0, rf[e][i], 0, 3 * k);
                System.arraycopy(r3, 0, rf[e][i], 3 * k, 3 * k);
                x[e][i] = Effect.angleFromDown(f, down);
            }
        // column c moves the point along base axis a by rf[a·k + c] and turns the frame about it by rf[(3 + a)·k + c]
        Probe p = columns(t, k, (e, row, g, col) -> {
                    double[] d = row % t.rpp >= t.posRows ? t.endDRot[e] : t.endDTrans[e];
                    int o = row % t.rpp >= t.posRows ? 3 * k : 0;
                    return d[row * 3] * g[o + col] + d[row * 3 + 1] * g[o + k + col] + d[row * 3 + 2] * g[o + 2 * k + col];
                }, 6 * k, (e, i, g) -> System.arraycopy(rf[e][i], 0, g, 0, 6 * k));
        p.variable = "the flange's orientation to gravity";
        p.x = x;
        p.xLabel = "angle of the flange's axis from straight down (deg)";
        return p;
    }

    /**
     * The upper arm and the forearm each bending under gravity as a beam ({@link Effect#linkSag}):
     * its columns, on links that the geometric model places at least {@link Effect#MIN_LINK_M}
     * across their joint's axis. Positions and orientations, one pose per row.
     */
    static List<Probe> linkBends(Diagnoser.Tester t) {
        List<Probe> out = new ArrayList<>();
        KinematicModel model = t.w.model;
        if (t.ends != 1 || model.dof() < 4) return out;
        boolean payload = Diagnoser.payloadVaries(t.w.rows);
        int poses = t.m / t.rpp;
        for (int j = 1; j <= 2; j++) {
            if (model.isPrismatic(j)) continue;
            Effect e = Effect.linkSag(model, j, payload);
            double[][] x = new double[1][poses];
            for (int i = 0; i < poses; i++) x[0][i] = e.sagAcross(t.endRows.get(0).get(i).q());
            if (!varies(x, 0.2)) continue; // the link's angle to gravity hardly changes: its sag is the geometry's
            Probe p = finish(t, t.signature(e, t.w.conditions), e.size());
            p.var = Var.LINK_BEND;
            p.joint = j;
            p.bend = e;
            p.variable = (j == 1 ? "the upper arm's" : "the forearm's") + " angle to gravity";
            p.shape = (j == 1 ? "the upper arm (joint 2 to joint 3)" : "the forearm (joint 3 to the wrist)")
                    + " bends under gravity as a beam (its far end moves across it and turns with the weight across it)";
            p.x = x;
            p.xLabel = "share of gravity across link " + (j + 1) + " (g)";
            out.add(p);
        }
        return out;
    }

    /**
     * The upper arm twisting about its long axis under the weights beyond it ({@link Effect#linkTwist}):
     * its columns, where the flange's lever across the arm's plane changes over the poses by at least
     * {@link #MIN_TWIST_LEVER_M} (the wrist swings the tool's weight from side to side). Positions and
     * orientations, one pose per row.
     */
    static List<Probe> linkTwist(Diagnoser.Tester t) {
        KinematicModel model = t.w.model;
        if (t.ends != 1 || model.dof() < 6 || model.isPrismatic(1) || model.isPrismatic(2)) return List.of();
        Effect e = Effect.linkTwist(model, Diagnoser.payloadVaries(t.w.rows));
        int poses = t.m / t.rpp;
        double[][] x = new double[1][poses];
        for (int i = 0; i < poses; i++) x[0][i] = e.twistLever(t.endRows.get(0).get(i).q());
        if (!varies(x, MIN_TWIST_LEVER_M)) return List.of();
        Probe p = finish(t, t.signature(e, t.w.conditions), e.size());
        p.var = Var.LINK_TWIST;
        p.joint = 1;
        p.bend = e;
        p.variable = "the weights' lever across the upper arm's plane";
        p.shape = "the upper arm (joint 2 to joint 3) twists about its long axis under the weights beyond it (the tool's and the "
                + "payload's, swung across the arm's plane by the wrist)";
        p.x = x;
        p.xLabel = "the flange's lever across the upper arm's plane, times gravity across the arm (m)";
        return List.of(p);
    }

    /**
     * A steady pull on the tool from outside the robot ({@link Effect#toolPull}), acting at the
     * measured point: its columns for a force of one direction (three per revolute joint, each
     * joint's coefficients free: what a pull from an anchor metres away mostly is, whatever the
     * anchor). Once found, {@link #bestPull} places its anchor. One pose per row.
     */
    static Probe toolPull(Diagnoser.Tester t) {
        KinematicModel model = t.w.model;
        int poses = t.m / t.rpp;
        if (t.ends != 1 || model.dof() < 2 || poses < 2) return null;
        Vec3 attach = targetInFlange(t);
        if (!Effect.hasRevolute(model)) return null;
        Effect free = Effect.toolPull(model, attach, null);
        Probe p = finish(t, t.signature(free, t.w.conditions), free.size());
        p.var = Var.TOOL_PULL;
        p.variable = "a steady force on the tool";
        p.shape = "the measured point moves as the joints yield to a steady pull on the tool from outside the robot (a hose, "
                + "cable or balancer hung from a boom)";
        // a pull from one side shows as the point's direction about axis 1 turns toward it and away
        double[][] x = new double[1][poses];
        for (int i = 0; i < poses; i++) x[0][i] = Math.toDegrees(Math.atan2(t.pointBase[i][1], t.pointBase[i][0]));
        p.x = x;
        p.xLabel = "azimuth of the measured point about axis 1 (deg)";
        p.pullAttach = attach;
        return p;
    }

    /** The measured point in the flange's frame, as the tester's fit predicts it (the first point where a pose holds several). */
    private static Vec3 targetInFlange(Diagnoser.Tester t) {
        return t.w.model.flange(t.endRows.get(0).get(0).q()).inverse().apply(new Vec3(t.pointBase[0][0], t.pointBase[0][1], t.pointBase[0][2]));
    }

    /**
     * The pull toward a fixed point ({@link Effect#toolPull} with an anchor) that explains most of what
     * the geometric fit left, once a pull was located: anchors every 30° about axis 1 at
     * {@link #PULL_ANCHOR_M} from it and three heights, and far off in every direction (a pull of one
     * direction), then refined by a pattern search, each with one coefficient per yielding joint.
     */
    static Effect bestPull(Diagnoser.Tester t, Probe p) { return bestPull(t, p.pullAttach, null); }

    /**
     * The pull acting at {@code attach} (flange frame) whose anchor explains most of the tester's
     * residual, the grid's best or {@code from} (an anchor found before), refined.
     */
    static Effect bestPull(Diagnoser.Tester t, Vec3 attach, double[] from) {
        KinematicModel model = t.w.model;
        List<double[]> grid = new ArrayList<>();
        for (int a = 0; a < 12; a++) {
            double az = Math.toRadians(30 * a), c = Math.cos(az), s = Math.sin(az);
            for (double d : PULL_ANCHOR_M) for (double h : PULL_ANCHOR_HEIGHT_M) grid.add(new double[] {d * c, d * s, h});
            for (double el : new double[] {-45, 0, 45}) {
                double e = Math.toRadians(el);
                grid.add(new double[] {PULL_FAR_M * Math.cos(e) * c, PULL_FAR_M * Math.cos(e) * s, PULL_FAR_M * Math.sin(e)});
            }
        }
        grid.add(new double[] {0, 0, PULL_FAR_M});
        grid.add(new double[] {0, 0, -PULL_FAR_M});
        if (from != null) grid.add(from.clone());
        double[] best = null;
        double bestGain = Double.NEGATIVE_INFINITY;
        for (double[] a : grid) {
            double g = explained(t, Effect.toolPull(model, attach, a));
            if (g > bestGain) { bestGain = g; best = a; }
        }
        if (best == null) return null;
        // pattern search about the best, its steps a share of the anchor's distance from axis 1
        double step = 0.25 * Math.max(0.5, Math.hypot(best[0], best[1]));
        for (int it = 0; it < 60 && step > 0.02; it++) {
            boolean moved = false;
            for (int axis = 0; axis < 3 && !moved; axis++)
                for (int sign = -1; sign <= 1 && !moved; sign += 2) {
                    double[] a = best.clone();
                    a[axis] += sign * step;
                    double g = explained(t, Effect.toolPull(model, attach, a));
                    if (g > bestGain) { bestGain = g; best = a; moved = true; }
                }
            if (!moved) step /= 2;
        }
        return Effect.toolPull(model, attach, best);
    }

    /** The sum of squares of the tester's residual that effect {@code e} explains (its columns out of the model's span). */
    private static double explained(Diagnoser.Tester t, Effect e) {
        int k = e.size();
        double[] s = Diagnoser.projectOut(t.u, t.rank, t.m, t.signature(e, t.w.conditions), k);
        DMatrixRMaj a = new DMatrixRMaj(k, k), b = new DMatrixRMaj(k, 1);
        for (int i = 0; i < t.m; i++) {
            double r = t.rPerp[i];
            for (int c = 0; c < k; c++) {
                double x = s[i * k + c];
                if (x == 0) continue;
                b.data[c] += x * r;
                for (int d = 0; d < k; d++) a.data[c * k + d] += x * s[i * k + d];
            }
        }
        DMatrixRMaj inv = new DMatrixRMaj(k, k), x = new DMatrixRMaj(k, 1);
        CommonOps_DDRM.pinv(a, inv);
        CommonOps_DDRM.mult(inv, b, x);
        double g = 0;
        for (int c = 0; c < k; c++) g += x.data[c] * b.data[c];
        return Double.isFinite(g) ? g : Double.NEGATIVE_INFINITY;
    }

    /** A pull's anchors tried: their distances from axis 1 (m) and heights above the base (m), a boom or a balancer beside the cell. */
    static final double[] PULL_ANCHOR_M = {1, 2, 3.5}, PULL_ANCHOR_HEIGHT_M = {-0.5, 1, 2.5};
    /** An anchor this far off (m) pulls the tool in one direction over the whole workspace. */
    static final double PULL_FAR_M = 100;

    /** Least change over the poses of the flange's lever across the upper arm's plane for its twist to be probed, m. */
    static final double MIN_TWIST_LEVER_M = 0.05;

    /** Orders of a joint's axis wobble probed (cycles per turn in the stator's frame). */
    static final int WOBBLE_ORDERS = 4;

    /**
     * A joint's bearing wobbling ({@link Effect#axisWobble}): for each revolute joint that turns over
     * a range and each order h, the four columns of the axis's tilt across itself, cos and sin of h·θ
     * about the stator's two axes across the joint. Positions and orientations, one pose per row.
     */
    static List<Probe> axisWobbles(Diagnoser.Tester t) {
        return bearingProbes(t, Var.AXIS_WOBBLE, Effect::axisWobble,
                (j, h) -> "the axis of joint " + (j + 1) + " tilts across itself " + times(h) + " per turn of the joint (its bearing wobbles)");
    }

    /**
     * A joint's bearing running out along its axis ({@link Effect#axialRunout}): for each revolute
     * joint that turns over a range and each order h, the two columns of the shift along the axis,
     * cos and sin of h·θ. Positions (and orientations, which it leaves), one pose per row.
     */
    static List<Probe> axialRunouts(Diagnoser.Tester t) {
        return bearingProbes(t, Var.AXIAL_RUNOUT, Effect::axialRunout,
                (j, h) -> "the arm beyond joint " + (j + 1) + " moves along the joint's axis " + times(h) + " per turn of the joint "
                        + "(its bearing runs out axially)");
    }

    /** "once" or "h times". */
    private static String times(int h) { return h == 1 ? "once" : h + " times"; }

    /** Each row's gravity torque on every drive (N·m) with masses {@code g}, the payload as recorded (none: 0 kg). */
    private static double[][] driveTorques(List<Measurement> rows, GravityTorques g) {
        double[][] out = new double[rows.size()][];
        for (int i = 0; i < out.length; i++) {
            Measurement r = rows.get(i);
            out[i] = g.driveTorques(r.q(), Double.isFinite(r.payloadKg()) ? r.payloadKg() : 0);
        }
        return out;
    }

    /**
     * A joint's axis tilting with its drive's torque ({@link Effect#loadTilt}): for each revolute joint
     * the arm's weight loads (the robot file's masses, or the links' from their lengths; more than
     * {@link Diagnoser#LOADED_NM} at some pose), its eight columns. Positions and orientations, one pose
     * per row.
     */
    static List<Probe> loadTilts(Diagnoser.Tester t) {
        List<Probe> out = new ArrayList<>();
        GravityTorques g = t.w.gravity == null || t.w.gravity.massesUnknown() ? GravityTorques.fromLengths(t.w.model) : t.w.gravity;
        if (t.ends != 1 || g == null) return out;
        double[][] torques = driveTorques(t.endRows.get(0), g);
        int poses = torques.length;
        for (int j = 0; j < t.dof; j++) {
            if (t.w.model.isPrismatic(j)) continue;
            double ref = 0;
            double[][] x = new double[1][poses];
            for (int i = 0; i < poses; i++) {
                x[0][i] = torques[i][j];
                ref = Math.max(ref, Math.abs(x[0][i]));
            }
            if (!(ref > Diagnoser.LOADED_NM) || Double.isInfinite(ref)) continue;
            Effect e = Effect.loadTilt(t.w.model, j, g, ref);
            Probe p = finish(t, t.signature(e, t.w.conditions), e.size());
            p.var = Var.LOAD_TILT;
            p.joint = j;
            p.bend = e;
            p.variable = "the gravity torque on drive " + (j + 1);
            p.shape = "the axis of joint " + (j + 1) + " tilts across itself with the torque its drive carries (the gear mesh's forces "
                    + "bending the output shaft)";
            p.x = x;
            p.xLabel = "gravity torque on drive " + (j + 1) + " (N·m)";
            out.add(p);
        }
        return out;
    }

    /**
     * The poses read from a second instrument station ({@link Effect#secondStation}): for each facing
     * direction of a half sphere (every 30° of azimuth at 45° up, every 30° over half a turn level, and
     * straight up; the other half splits the poses alike), the rigid motion of the poses whose flange
     * axis faces that side, where between a tenth and nine tenths of the poses do. Positions and
     * orientations, one pose per row.
     */
    static List<Probe> stations(Diagnoser.Tester t) {
        List<Probe> out = new ArrayList<>();
        if (t.ends != 1 || t.perPose != 1) return out;
        int poses = t.m / t.rpp;
        List<Vec3> sides = new ArrayList<>();
        for (int a = 0; a < 12; a++) sides.add(new Vec3(Math.cos(Math.toRadians(30 * a)), Math.sin(Math.toRadians(30 * a)), 1));
        for (int a = 0; a < 6; a++) sides.add(new Vec3(Math.cos(Math.toRadians(30 * a)), Math.sin(Math.toRadians(30 * a)), 0));
        sides.add(new Vec3(0, 0, 1));
        for (Vec3 side : sides) {
            Effect e = Effect.secondStation(t.w.model, side);
            double[][] x = new double[1][poses];
            int seen = 0;
            for (int i = 0; i < poses; i++) {
                x[0][i] = e.facingPart(t.endRows.get(0).get(i).q());
                if (x[0][i] > 0) seen++;
            }
            if (seen < MIN_STATION_SHARE * poses || seen > (1 - MIN_STATION_SHARE) * poses) continue;
            Probe p = finish(t, pointColumns(t, e), e.size());
            p.var = Var.STATION;
            p.facing = e.facing();
            p.variable = "the side the target faces";
            p.shape = String.format(Locale.ROOT, "the poses whose target faces (%.2f, %.2f, %.2f) moved together by one rigid motion, "
                    + "whatever the arm's pose (read from a second instrument station)", p.facing.x(), p.facing.y(), p.facing.z());
            p.x = x;
            p.xLabel = "the flange axis's part along that side";
            out.add(p);
        }
        return out;
    }

    /**
     * The side a second station's poses face that explains most of the residual, refined from {@code from}
     * by a pattern search over its azimuth and elevation (steps of 8° down to 1°): the split between two
     * stations follows the line between them, not the probes' grid.
     */
    static Vec3 bestFacing(Diagnoser.Tester t, Vec3 from) {
        double az = Math.atan2(from.y(), from.x()), el = Math.asin(Math.max(-1, Math.min(1, from.z() / from.norm())));
        double best = explained(t, Effect.secondStation(t.w.model, from));
        for (double step = Math.toRadians(8); step > Math.toRadians(0.9); ) {
            boolean moved = false;
            for (double[] d : new double[][] {{step, 0}, {-step, 0}, {0, step}, {0, -step}}) {
                double a = az + d[0], e = Math.max(-Math.PI / 2, Math.min(Math.PI / 2, el + d[1]));
                double g = explained(t, Effect.secondStation(t.w.model, new Vec3(Math.cos(e) * Math.cos(a), Math.cos(e) * Math.sin(a), Math.sin(e))));
                if (g > best) { best = g; az = a; el = e; moved = true; break; }
            }
            if (!moved) step /= 2;
        }
        return new Vec3(Math.cos(el) * Math.cos(az), Math.cos(el) * Math.sin(az), Math.sin(el));
    }

    /**
     * The second station's split that explains most of the residual: by the side the target faces
     * ({@link #bestFacing}), or, where the positions are the instrument's own, by where the second
     * station stands beside the first (the instrument the geometric fit placed): every 15° about axis 1 at
     * 1.5 to 4.5 m and three heights, then from each of the best few a search on the poses' membership
     * softened and hardened again.
     */
    static Effect bestStation(Diagnoser.Tester t, Vec3 facing) {
        KinematicModel model = t.w.model;
        Effect best = Effect.secondStation(model, bestFacing(t, facing));
        double gain = explained(t, best);
        if (!t.w.instrument) return best;
        Vec3 first = Effect.instrumentOrigin(t.fit.problem.instrumentOf(t.fit.full));
        Vec3 target = targetInFlange(t);
        Split split = new Split(t, first, target);
        // the grid's places, best first
        List<double[]> places = new ArrayList<>();
        for (int a = 0; a < 24; a++)
            for (double d : new double[] {1.5, 2.25, 3, 4.5})
                for (double h : new double[] {-0.25, 0.5, 1.5}) {
                    double[] s = {d * Math.cos(Math.toRadians(15 * a)), d * Math.sin(Math.toRadians(15 * a)), h, 0};
                    s[3] = split.explained(s, 0);
                    places.add(s);
                }
        places.sort((x, y) -> Double.compare(y[3], x[3]));
        // The split changes in steps as the place moves, so no gradient leads to the best: from each of the grid's best few, the
        // poses' membership is softened (a logistic of how much better the target faces the second station, its width shrinking),
        // and places are drawn about the best so far in balls that shrink with it (a fixed seed: the same file gives the same answer).
        java.util.Random draw = new java.util.Random(1);
        double[] at = places.get(0);
        double[][] anneal = {{0.05, 0.4}, {0.02, 0.2}, {0.008, 0.1}, {0.003, 0.05}, {0, 0.025}}; // width, ball radius (m)
        for (double[] start : places.subList(0, Math.min(STATION_STARTS, places.size()))) {
            double[] here = start.clone();
            for (double[] stage : anneal) {
                double soft = split.explained(here, stage[0]);
                for (int i = 0; i < STATION_DRAWS; i++) {
                    double[] s = {here[0] + stage[1] * draw.nextGaussian(), here[1] + stage[1] * draw.nextGaussian(), here[2] + stage[1] * draw.nextGaussian(), 0};
                    double g = split.explained(s, stage[0]);
                    if (g > soft) { soft = g; here = s; }
                }
            }
            here[3] = split.explained(here, 0);
            if (here[3] > at[3]) at = here;
        }
        Effect found = Effect.secondStation(model, first, new Vec3(at[0], at[1], at[2]), target);
        return explained(t, found) > gain ? found : best;
    }

    /**
     * A second station's split by where it stands, scored fast: each pose's six columns (every pose read
     * from the second station) through the residual's sensitivities, their products with themselves,
     * with the model's span and with the residual summed over the poses the place assigns to the second
     * station. The explained sum of squares is bᵀA⁺b with A = Σ SᵢᵀSᵢ − (Σ SᵢᵀUᵢ)(Σ UᵢᵀSᵢ) and b = Σ Sᵢᵀrᵢ
     * (the residual is already out of the span), as the projected columns of {@link #explained} give it.
     */
    private static final class Split {
        final int poses, k = Effect.BASE_STEP_TERMS, rank;
        final double[][] ss, su, sr; // per pose: SᵢᵀSᵢ (k x k), SᵢᵀUᵢ (k x rank), Sᵢᵀrᵢ (k)
        final double[][] o, z, to1;  // per pose: the target's place and the flange's axis (base frame), the unit vector to the first station

        Split(Diagnoser.Tester t, Vec3 first, Vec3 target) {
            poses = t.m / t.rpp;
            rank = t.rank;
            ss = new double[poses][k * k];
            su = new double[poses][k * rank];
            sr = new double[poses][k];
            o = new double[poses][];
            z = new double[poses][];
            to1 = new double[poses][];
            double[] g3 = new double[3 * k], w3 = new double[3 * k], row = new double[k];
            double[] dt = t.endDTrans[0], dr = t.endDRot[0];
            for (int i = 0; i < poses; i++) {
                Pose f = t.w.model.flange(t.endRows.get(0).get(i).q());
                Vec3 oi = f.apply(target), zi = f.zAxis(), u1 = first.minus(oi);
                o[i] = oi.toArray();
                z[i] = zi.toArray();
                to1[i] = u1.times(1 / u1.norm()).toArray();
                for (int a = 0; a < t.rpp; a++) {
                    int r = i * t.rpp + a;
                    boolean turn = a >= t.posRows;
                    Effect.baseStepRegressor(turn ? null : t.pointsBase[i][t.pointOfRow(a)], turn ? null : g3, turn ? w3 : null);
                    double[] d = turn ? dr : dt, g = turn ? w3 : g3;
                    for (int c = 0; c < k; c++) row[c] = d[r * 3] * g[c] + d[r * 3 + 1] * g[k + c] + d[r * 3 + 2] * g[2 * k + c];
                    for (int c = 0; c < k; c++) {
                        sr[i][c] += row[c] * t.rPerp[r];
                        for (int e = 0; e < k; e++) ss[i][c * k + e] += row[c] * row[e];
                        for (int e = 0; e < rank; e++) su[i][c * rank + e] += row[c] * t.u[r * rank + e];
                    }
                }
            }
        }

        /**
         * The sum of squares explained with the second station at {@code s} (its first three), each pose
         * counted by its membership: 0 or 1 ({@code width} 0), or softened, 1/(1 + exp(−(c₂ − c₁)/width)).
         */
        double explained(double[] s, double width) {
            double[] a = new double[k * k], m = new double[k * rank], b = new double[k];
            double n = 0;
            for (int i = 0; i < poses; i++) {
                double[] oi = o[i], zi = z[i];
                double dx = s[0] - oi[0], dy = s[1] - oi[1], dz = s[2] - oi[2], dn = Math.sqrt(dx * dx + dy * dy + dz * dz);
                double c2 = (zi[0] * dx + zi[1] * dy + zi[2] * dz) / dn, c1 = zi[0] * to1[i][0] + zi[1] * to1[i][1] + zi[2] * to1[i][2];
                double w = width > 0 ? 1 / (1 + Math.exp(-(c2 - c1) / width)) : c2 > c1 ? 1 : 0;
                if (w == 0) continue;
                n += w;
                for (int c = 0; c < a.length; c++) a[c] += w * w * ss[i][c];
                for (int c = 0; c < m.length; c++) m[c] += w * su[i][c];
                for (int c = 0; c < k; c++) b[c] += w * sr[i][c];
            }
            if (n < 0.5 || n > poses - 0.5) return 0;
            for (int c = 0; c < k; c++)
                for (int e = 0; e < k; e++) {
                    double x = 0;
                    for (int r = 0; r < rank; r++) x += m[c * rank + r] * m[e * rank + r];
                    a[c * k + e] -= x;
                }
            DMatrixRMaj am = new DMatrixRMaj(k, k, true, a), inv = new DMatrixRMaj(k, k);
            CommonOps_DDRM.pinv(am, inv);
            double g = 0;
            for (int c = 0; c < k; c++) for (int e = 0; e < k; e++) g += b[c] * inv.data[c * k + e] * b[e];
            return Double.isFinite(g) ? g : 0;
        }
    }

    /** Places drawn for a second station at each stage of its search, from each of the grid's best {@link #STATION_STARTS}. */
    static final int STATION_DRAWS = 40, STATION_STARTS = 12;

    /** The least share of the poses on either side of a second station's split for it to be probed. */
    static final double MIN_STATION_SHARE = 0.1;

    /** Mass scales a load tilt's search tries for each mass in turn (a data sheet's masses are rarely better than ±30 %). */
    static final double[] LOAD_MASS_SCALES = {0.7, 0.85, 1.15, 1.3};

    /**
     * A located load tilt with the masses that shape its drive's torque re-estimated: each mass scaled in
     * turn, twice round, kept where the leave-one-pose-out error with the tilt added falls; the tilt as it
     * was when none does.
     */
    static Effect remassedLoadTilt(Diagnoser.Tester t, Effect e) {
        GravityTorques g = e.gravity();
        int n = g.massCount();
        double[] sc = new double[n];
        Arrays.fill(sc, 1);
        double best = t.pressAddingColumns(t.signature(e, t.w.conditions), e.size());
        Effect kept = e;
        for (int round = 0; round < 2; round++)
            for (int m = 0; m < n; m++) {
                if (m == g.payloadIndex()) continue;
                double keep = sc[m];
                for (double f : LOAD_MASS_SCALES) {
                    double[] trial = sc.clone();
                    trial[m] = keep * f;
                    Effect x = Effect.loadTilt(t.w.model, e.joint(), g, e.loadRefNm(), trial);
                    double press = t.pressAddingColumns(t.signature(x, t.w.conditions), x.size());
                    // kept only when clearly better: a few per cent of the left-out error
                    if (press < best * (1 - LOAD_MASS_GAIN)) { best = press; kept = x; sc = trial; }
                }
            }
        return kept;
    }

    /** The share by which a mass scale must lower a load tilt's leave-one-pose-out error to be kept. */
    static final double LOAD_MASS_GAIN = 0.01;

    /** A bearing's error motion at orders of its joint's angle. */
    private interface BearingEffect { Effect of(KinematicModel model, int joint, int[] orders); }

    /** The words of a bearing probe of joint j at order h. */
    private interface BearingShape { String of(int joint, int order); }

    /**
     * A bearing probe of {@code var} for each revolute joint that turns 30° or more and each order up
     * to {@link #WOBBLE_ORDERS}: the columns of {@code effect} at that one order.
     */
    private static List<Probe> bearingProbes(Diagnoser.Tester t, Var var, BearingEffect effect, BearingShape shape) {
        List<Probe> out = new ArrayList<>();
        if (t.ends != 1) return out;
        KinematicModel model = t.w.model;
        int poses = t.m / t.rpp;
        for (int j = 0; j < t.dof; j++) {
            double[][] qx = new double[1][poses];
            for (int i = 0; i < poses; i++) qx[0][i] = Math.toDegrees(t.endRows.get(0).get(i).q(j));
            // a joint that turns less than this shows no pattern of its turn
            if (model.isPrismatic(j) || !varies(qx, 30)) continue;
            for (int h = 1; h <= WOBBLE_ORDERS; h++) {
                Effect e = effect.of(model, j, new int[] {h});
                Probe p = finish(t, t.signature(e, t.w.conditions), e.size());
                p.var = var;
                p.joint = j;
                p.harmonic = h;
                p.variable = "joint " + (j + 1) + " angle";
                p.shape = shape.of(j, h);
                p.x = qx;
                p.xLabel = "joint " + (j + 1) + " angle q" + (j + 1) + " (deg)";
                out.add(p);
            }
        }
        return out;
    }

    /** Shares of the poses a base that rocks toward the lean is probed as tilting at (above the moment it holds). */
    static final double[] BASE_HOLD_SHARES = {0.5, 0.25};

    /**
     * The 3 x 5 regressor (row-major) of {@link #baseMoment} at moment {@code m} for a point at
     * {@code p} (base frame): ω = (C₁₁ Mx + C₁₂ My, C₁₂ Mx + C₂₂ My, 0), displacement
     * ω × p = (ω_y p_z, −ω_x p_z, ω_x p_y − ω_y p_x), plus the lift (l_x Mx + l_y My) along z.
     */
    static void baseMomentRegressor(double[] m, double[] p, double[] g3) {
        double mx = m[0], my = m[1];
        // columns: C11 (ωx from Mx), C22 (ωy from My), C12 (ωx from My and ωy from Mx), lift from Mx, lift from My
        g3[0] = 0;            g3[1] = my * p[2];     g3[2] = mx * p[2];             g3[3] = 0;  g3[4] = 0;
        g3[5] = -mx * p[2];   g3[6] = 0;             g3[7] = -my * p[2];            g3[8] = 0;  g3[9] = 0;
        g3[10] = mx * p[1];   g3[11] = -my * p[0];   g3[12] = my * p[1] - mx * p[0]; g3[13] = mx; g3[14] = my;
    }

    /**
     * The instrument's own errors, when the positions are in its frame (a laser tracker): the
     * measured point moved along the line of sight by a smooth function of the distance reading, or
     * across it by the distance times a smooth function of the azimuth or elevation reading
     * ({@link Effect#instrumentReading}). A tracker's distance meter and angle encoders err as
     * functions of their own readings, which over a robot's workspace seen from metres away are
     * neither a joint's angle nor the point's reach; without these shapes such an error was named a
     * transmission error of joint 1. Points only (3 rows each), one pose per row. With {@code cycles},
     * also a distance meter's cyclic error at every period ({@link #rangeCycles}); with {@code jumps}
     * and a time column, the distances jumping at each of the scan's time places ({@link #rangeStep}).
     * The stepwise search's re-scans leave both out (such errors show in the geometric fit's residuals
     * already, and the cycle's hundred-odd probes are most of the instrument's share of a scan).
     */
    static List<Probe> sightProbes(Diagnoser.Tester t, boolean cycles, boolean jumps) {
        List<Probe> out = new ArrayList<>();
        if (!t.w.instrument || t.ends != 1 || t.dim != 3) return out;
        int poses = t.w.rows.size(), pts = t.perPose;
        org.robopro.kinematics.Pose inst = t.fit.problem.instrumentOf(t.fit.full);
        double[][][] pi = new double[poses][pts][];
        double cx = 0, cy = 0;
        for (int i = 0; i < poses; i++)
            for (int p = 0; p < pts; p++) {
                double[] b = t.pointsBase[i][p];
                pi[i][p] = inst.apply(new org.robopro.models.Vec3(b[0], b[1], b[2])).toArray();
                double h = Math.hypot(pi[i][p][0], pi[i][p][1]);
                if (h > 0) { cx += pi[i][p][0] / h; cy += pi[i][p][1] / h; }
            }
        double azRef = Math.atan2(cy, cx);
        int rpp = t.rpp;
        for (Effect.Sight sight : Effect.Sight.values()) {
            // per residual row of a point: the instrument's reading of that point, and the row's sensitivity to an error of it
            double[] u = new double[t.m], sens = new double[t.m];
            double[][] x = new double[1][poses];
            double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
            for (int i = 0; i < poses; i++)
                for (int p = 0; p < pts; p++) {
                    double r = Effect.sightReading(sight, azRef, pi[i][p]);
                    double[] d = Effect.sightDirection(sight, pi[i][p]), db = new double[3];
                    for (int a = 0; a < 3; a++) db[a] = inst.rot(0, a) * d[0] + inst.rot(1, a) * d[1] + inst.rot(2, a) * d[2];
                    for (int a = 0; a < t.posRows; a++) {
                        if (t.pointOfRow(a) != p) continue;
                        int row = i * rpp + a;
                        u[row] = r;
                        for (int ax = 0; ax < 3; ax++) sens[row] += t.endDTrans[0][row * 3 + ax] * db[ax];
                    }
                    if (p == 0) x[0][i] = r;
                    lo = Math.min(lo, r);
                    hi = Math.max(hi, r);
                }
            if (!(max(x) - min(x) > (sight == Effect.Sight.RANGE ? 0.05 : Math.toRadians(2)))) continue;
            double l0 = lo, h0 = hi;
            for (int nb : sight == Effect.Sight.RANGE ? RANGE_RESOLUTIONS : ANGLE_RESOLUTIONS) {
                if (!Effect.supported(nb, Effect.POINT_BASIS, poses)) continue;
                double[] s = new double[t.m * nb], g = new double[nb];
                for (int row = 0; row < t.m; row++) {
                    if (sens[row] == 0) continue;
                    Effect.bspline(u[row], l0, h0, g);
                    for (int c = 0; c < nb; c++) s[row * nb + c] = sens[row] * g[c];
                }
                Probe pr = finish(t, s, nb);
                pr.var = Var.SIGHT;
                pr.sight = sight;
                pr.instrument = inst;
                pr.azimuthRef = azRef;
                pr.lo = l0;
                pr.hi = h0;
                pr.basis = nb;
                boolean range = sight == Effect.Sight.RANGE;
                pr.variable = "instrument " + sight.words;
                pr.shape = String.format(Locale.ROOT, "the measured positions err %s the instrument's line of sight with its %s reading "
                        + "(%s%s)", range ? "along" : "across", sight.words, range ? String.format(Locale.ROOT, "%.2f..%.2f m", l0, h0)
                        : String.format(Locale.ROOT, "%.0f..%.0f deg", Math.toDegrees(l0), Math.toDegrees(h0)),
                        nb == Effect.POINT_BASIS ? "" : range ? String.format(Locale.ROOT, ", with features about %.0f mm long", 1e3 * (h0 - l0) / (nb - 3))
                                : String.format(Locale.ROOT, ", with features about %.0f deg wide", Math.toDegrees(h0 - l0) / (nb - 3)));
                double[][] xs = new double[1][poses];
                for (int i = 0; i < poses; i++) xs[0][i] = range ? x[0][i] : Math.toDegrees(x[0][i]);
                pr.x = xs;
                pr.xLabel = "the instrument's " + sight.words + " reading" + (range ? " (m)" : " (deg)");
                out.add(pr);
            }
            if (sight == Effect.Sight.RANGE && cycles) out.addAll(rangeCycles(t, inst, u, sens, x, l0, h0));
            if (sight == Effect.Sight.RANGE && jumps) {
                double[][] time = column(t, c -> c.timeS());
                if (varies(time, 1)) for (double tau : stepPlaces(time[0], STEP_PLACES)) out.add(rangeStep(t, inst, sens, tau, time));
            }
        }
        return out;
    }

    /**
     * A distance meter's cyclic error: sin and cos of 2π·r/λ along the line of sight, for periods λ
     * from the readings' span down to {@link #MIN_RANGE_CYCLE_M} and at least 3 poses per period,
     * on a grid of 3 points per independent frequency (1 / span cycles per metre): each period its
     * own 2-column probe, as each harmonic of a joint is.
     */
    private static List<Probe> rangeCycles(Diagnoser.Tester t, org.robopro.kinematics.Pose inst, double[] u, double[] sens,
                                           double[][] x, double lo, double hi) {
        List<Probe> out = new ArrayList<>();
        double span = hi - lo, fMax = cycleFrequencyMax(x[0].length, span), step = 1 / (3 * span);
        for (double f = 2 / span; f <= fMax; f += step) out.add(cycleProbe(t, inst, u, sens, x, lo, hi, 1 / f, 1));
        // and with as many of its harmonics as the poses resolve (up to MAX_CYCLE_ORDERS), for the periods the residual holds
        // most of alone (a k x k cost each): a phase meter's error repeats at its cycle's halves and quarters too, and spread
        // over them each alone may be too weak
        double[] res = t.residualOutOf(new double[0], 0);
        List<double[]> ranked = new ArrayList<>(); // {what the period takes of the residual (two columns each: its F test's order), frequency}
        for (Probe pr : out) {
            double f = 1 / pr.cycle;
            if (mostCycleOrders(f, fMax) < 2 || pr.raw == null) continue;
            double[] r = new Gram(pr).reduction(t, res);
            ranked.add(new double[] {r == null ? 0 : r[0], f});
        }
        ranked.sort((a, b) -> Double.compare(b[0], a[0]));
        for (int i = 0; i < Math.min(CYCLES_WITH_HARMONICS, ranked.size()); i++) {
            double f = ranked.get(i)[1];
            out.add(cycleProbe(t, inst, u, sens, x, lo, hi, 1 / f, mostCycleOrders(f, fMax)));
        }
        return out;
    }

    /**
     * The periods of a distance meter's cycle also probed with their harmonics: those whose period alone the residual holds
     * most of (a cycle with strong overtones is among them by its fundamental or by an overtone, whose own probe the
     * tuning in the model takes to the fundamental).
     */
    static final int CYCLES_WITH_HARMONICS = 24;

    /** The highest frequency of a distance meter's cycle scanned (1/m): down to {@link #MIN_RANGE_CYCLE_M}, 3 poses per period. */
    private static double cycleFrequencyMax(int poses, double span) { return Math.min(1 / MIN_RANGE_CYCLE_M, poses / (3 * span)); }

    /** The most harmonics of a cycle at frequency f the scan resolves (each at most fMax), up to {@link Diagnoser#MAX_CYCLE_ORDERS}. */
    private static int mostCycleOrders(double f, double fMax) {
        return Math.min(Diagnoser.MAX_CYCLE_ORDERS, (int) Math.floor(fMax / f + 1e-9));
    }

    /** A distance meter's cyclic error of period {@code lambda} (m) with its harmonics 1..{@code orders}: 2·orders columns. */
    private static Probe cycleProbe(Diagnoser.Tester t, org.robopro.kinematics.Pose inst, double[] u, double[] sens, double[][] x,
                                    double lo, double hi, double lambda, int orders) {
        int k = 2 * orders;
        double[] s = new double[t.m * k];
        for (int row = 0; row < t.m; row++) {
            if (sens[row] == 0) continue;
            for (int h = 1; h <= orders; h++) {
                double ph = 2 * Math.PI * h * u[row] / lambda;
                s[row * k + 2 * h - 2] = sens[row] * Math.sin(ph);
                s[row * k + 2 * h - 1] = sens[row] * Math.cos(ph);
            }
        }
        Probe pr = finish(t, s, k);
        pr.var = Var.SIGHT;
        pr.sight = Effect.Sight.RANGE;
        pr.instrument = inst;
        pr.cycle = lambda;
        pr.cycleOrders = orders;
        pr.reading = u;
        pr.sens = sens;
        pr.lo = lo;
        pr.hi = hi;
        pr.variable = "instrument distance";
        // one probe per period tried, a few hundred: the words without the formatter (the same rounding as %.0f)
        pr.shape = "the measured positions err along the instrument's line of sight, repeating every "
                + Math.round(1e3 * lambda) + " mm of its distance reading" + (orders > 1 ? " with its harmonics 1-" + orders : "")
                + " (a distance meter's cyclic error)";
        pr.x = x;
        pr.xLabel = "the instrument's distance reading (m)";
        return pr;
    }

    /**
     * A distance meter's cycle found: its period on a grid eight times finer than the scan's, half a
     * step either side, alone and with as many of its harmonics as the poses resolve. Over a span of
     * metres a period a fraction of the scan's step off leaves a phase error that grows with the
     * harmonic: a quarter cycle at the fourth, where the cycle itself is followed.
     */
    static List<Probe> finerCycles(Diagnoser.Tester t, Probe p) {
        if (p.var != Var.SIGHT || !(p.cycle > 0) || p.reading == null) return List.of();
        double span = p.hi - p.lo, fMax = cycleFrequencyMax(p.x[0].length, span), step = 1 / (3 * span), f0 = 1 / p.cycle;
        List<Probe> out = new ArrayList<>();
        for (int i = -4; i <= 4; i++) {
            double f = f0 + i * step / 8;
            if (!(f > 0) || f > fMax) continue;
            int most = mostCycleOrders(f, fMax);
            for (int orders = 1; orders <= most; orders *= 2)
                if (i != 0 || orders != p.cycleOrders) out.add(cycleProbe(t, p.instrument, p.reading, p.sens, p.x, p.lo, p.hi, 1 / f, orders));
            if (most > 1 && Integer.bitCount(most) != 1 && (i != 0 || most != p.cycleOrders))
                out.add(cycleProbe(t, p.instrument, p.reading, p.sens, p.x, p.lo, p.hi, 1 / f, most));
        }
        return out;
    }

    /** A drive's error as a function of its own joint's angle (rad): the regressor's k values. */
    interface Angle { void at(double q, double[] g); }

    /**
     * Places of a step in a variable: halfway between two poses' values at the quantiles k/{@link #STEP_PLACES}
     * (k = 1..19), leaving at least 3 poses on each side.
     */
    static List<Double> stepPlaces(double[] x, int quantiles) {
        double[] sorted = x.clone();
        Arrays.sort(sorted);
        int poses = sorted.length;
        List<Double> out = new ArrayList<>();
        double last = Double.NaN;
        for (int k = 1; k < quantiles; k++) {
            int i = k * poses / quantiles;
            if (i < 3 || i > poses - 3 || !(sorted[i] > sorted[i - 1])) continue;
            double at = 0.5 * (sorted[i - 1] + sorted[i]);
            if (at == last) continue;
            last = at;
            out.add(at);
        }
        return out;
    }

    /** A reducer stage's error: order f (cycles per turn of joint j, whole or not) acting on drive j ({@link StageScan}). */
    static Probe stageProbe(Diagnoser.Tester t, int j, double f) {
        int poses = t.w.rows.size();
        double[][] qx = new double[t.ends][poses];
        for (int e = 0; e < t.ends; e++) for (int i = 0; i < poses; i++) qx[e][i] = Math.toDegrees(t.endRows.get(e).get(i).q(j));
        Angle a = (q, g) -> { g[0] = Math.sin(f * q); g[1] = Math.cos(f * q); };
        Probe p = drive(t, j, 2, (e, i, g) -> a.at(t.endRows.get(e).get(i).q(j), g));
        p.angle = a;
        p.var = Var.ANGLE_PERIODIC;
        p.joint = j;
        p.harmonic = (int) Math.rint(f);
        p.stage = true;
        if (f != Math.rint(f)) p.order = Effect.roundOrder(f);
        p.variable = "joint " + (j + 1) + " angle";
        p.shape = StageScan.words(j, f);
        p.x = qx;
        p.xLabel = "joint " + (j + 1) + " angle q" + (j + 1) + " (deg)";
        return p;
    }

    /** Drive j's reading jumps where it passes {@code at} (rad). */
    private static Probe angleStep(Diagnoser.Tester t, int j, double at, double[][] qx) {
        Probe p = drive(t, j, 1, (e, i, g) -> g[0] = t.endRows.get(e).get(i).q(j) > at ? 1 : 0);
        p.var = Var.ANGLE_STEP;
        p.joint = j;
        p.lo = at;
        p.variable = "joint " + (j + 1) + " angle";
        p.shape = String.format(Locale.ROOT, "joint %d's reading jumps where it passes about %.1f deg", j + 1, Math.toDegrees(at));
        p.x = qx;
        p.xLabel = "joint " + (j + 1) + " angle q" + (j + 1) + " (deg)";
        return p;
    }

    /** The measured point moved on the flange (3 translations in the flange frame, {@code rf} each pose's flange rotation) at tau. */
    private static Probe targetStep(Diagnoser.Tester t, double tau, double[][] time, double[][][] rf) {
        int rpp = t.rpp;
        Probe tp = columns(t, 3, (e, row, g, col) -> {
            double[] r = rf[e][row / rpp];
            double v = 0;
            for (int a = 0; a < 3; a++) v += t.endDTrans[e][row * 3 + a] * r[3 * a + col];
            return v * g[0];
        }, 1, (e, pi, g) -> g[0] = time[e][pi] > tau ? 1 : 0);
        tp.var = Var.TARGET_STEP;
        tp.lo = tau;
        tp.variable = "time";
        tp.shape = String.format(Locale.ROOT, "the measured point moved on the flange at about %.0f s", tau);
        tp.x = time;
        tp.xLabel = "time since the start (s)";
        tp.rf = rf;
        return tp;
    }

    /** The least moves of joint 1 (deg) whose slips of the base are probed ({@link Effect#baseCreep}). */
    static final double[] CREEP_MOVES_DEG = {15, 30, 60};

    /**
     * The robot's base turning a little with each move of joint 1 larger than each of {@link
     * #CREEP_MOVES_DEG} ({@link Effect#baseCreep}), three columns; joint 1's moves from the training
     * and validation poses in time order. None without times, or where no move is that large.
     */
    static List<Probe> baseCreeps(Diagnoser.Tester t) {
        List<Probe> out = new ArrayList<>();
        List<Measurement> all = new ArrayList<>(t.w.rows);
        if (t.w.validate != null) all.addAll(t.w.validate.rows());
        double[][] moves = t.dof > 0 && !t.w.model.isPrismatic(0) ? Directions.movesInTime(all, 0) : null;
        if (moves == null) return out;
        int k = Effect.CREEP_TERMS;
        double[][] time = column(t, c -> c.timeS());
        for (double deg : CREEP_MOVES_DEG) {
            Effect creep = Effect.baseCreep(moves, Math.toRadians(deg));
            double[] s = pointColumns(t, creep);
            if (Arrays.stream(s).allMatch(x -> x == 0)) continue;
            Probe p = finish(t, s, k);
            p.var = Var.BASE_CREEP;
            p.creep = creep;
            p.variable = "joint 1's moves over the campaign";
            p.shape = String.format(Locale.ROOT, "the robot's base turns a little with each move of joint 1 over %.0f deg, adding up (its "
                    + "bolts slip)", deg);
            p.x = time;
            p.xLabel = "time since the start (s)";
            out.add(p);
        }
        return out;
    }

    /**
     * The columns (m x size, row-major) of effect {@code e} on the measured point at the scanned
     * fit's poses (one pose per row): its move of each point and its turn of the measured frame,
     * through the residual's sensitivity to them.
     */
    private static double[] pointColumns(Diagnoser.Tester t, Effect e) {
        int k = e.size(), poses = t.m / t.rpp;
        double[] s = new double[t.m * k], g3 = new double[3 * k], w3 = new double[3 * k];
        double[] dt = t.endDTrans[0], dr = t.endDRot[0];
        for (int i = 0; i < poses; i++) {
            PoseConditions c = t.endConditions.get(0).get(i);
            double[] q = t.endRows.get(0).get(i).q();
            for (int a = 0; a < t.rpp; a++) {
                int row = i * t.rpp + a;
                boolean turn = a >= t.posRows;
                if (turn) e.rotationRegressor(q, c, w3);
                else e.positionRegressor(q, c, t.pointsBase[i][t.pointOfRow(a)], g3);
                double[] d = turn ? dr : dt, g = turn ? w3 : g3;
                for (int col = 0; col < k; col++) s[row * k + col] = d[row * 3] * g[col] + d[row * 3 + 1] * g[k + col] + d[row * 3 + 2] * g[2 * k + col];
            }
        }
        return s;
    }

    /**
     * The measured point moving on the flange with time ({@link Effect#targetDrift}): a cubic B-spline
     * of the time per flange axis ({@link Effect#POINT_BASIS} functions each), {@code rf} each pose's
     * flange rotation.
     */
    private static Probe targetDrift(Diagnoser.Tester t, double[][] time, double[][][] rf) {
        int rpp = t.rpp, nb = Effect.POINT_BASIS;
        double lo = min(time), hi = max(time);
        Probe p = columns(t, 3 * nb, (e, row, g, col) -> {
            double[] r = rf[e][row / rpp];
            int axis = col / nb;
            double v = 0;
            for (int a = 0; a < 3; a++) v += t.endDTrans[e][row * 3 + a] * r[3 * a + axis];
            return v * g[col % nb];
        }, nb, (e, pi, g) -> Effect.bspline(time[e][pi], lo, hi, g));
        p.var = Var.TARGET_DRIFT;
        p.lo = lo;
        p.hi = hi;
        p.basis = nb;
        p.variable = "time";
        p.shape = "the measured point moves on the flange with time (a tool that grows as it warms, a holder that creeps)";
        p.x = time;
        p.xLabel = "time since the start (s)";
        p.rf = rf;
        return p;
    }

    /**
     * The instrument and the robot's base moved against each other at tau ({@link Effect#baseStep}):
     * a translation and a turn in base axes before it, six columns (one pose per row).
     */
    private static Probe baseStep(Diagnoser.Tester t, double tau, double[][] time) {
        double[] s = pointColumns(t, Effect.baseStep(tau));
        int k = Effect.BASE_STEP_TERMS;
        Probe p = finish(t, s, k);
        p.var = Var.BASE_STEP;
        p.lo = tau;
        p.variable = "time";
        p.shape = String.format(Locale.ROOT, "every measured point moved by one rigid motion at about %.0f s, whatever the arm's pose "
                + "(the instrument or the robot's base moved)", tau);
        p.x = time;
        p.xLabel = "time since the start (s)";
        return p;
    }

    /**
     * The instrument's distances jumped at tau ({@link Effect#rangeStep}): −1 along the line of sight
     * before it, {@code sens} each residual row's change for a unit change of the distance.
     */
    private static Probe rangeStep(Diagnoser.Tester t, org.robopro.kinematics.Pose inst, double[] sens, double tau, double[][] time) {
        double[] s = new double[t.m];
        for (int row = 0; row < t.m; row++) if (time[0][row / t.rpp] <= tau) s[row] = -sens[row];
        Probe p = finish(t, s, 1);
        p.var = Var.RANGE_STEP;
        p.instrument = inst;
        p.sens = sens;
        p.lo = tau;
        p.variable = "time";
        p.shape = String.format(Locale.ROOT, "the instrument's distances jump at about %.0f s", tau);
        p.x = time;
        p.xLabel = "time since the start (s)";
        return p;
    }

    /** Drive j's zero jumps at tau. */
    private static Probe zeroStep(Diagnoser.Tester t, int j, double tau, double[][] time) {
        Probe p = drive(t, j, 1, (e, pi, g) -> g[0] = time[e][pi] > tau ? 1 : 0);
        p.var = Var.TIME_STEP;
        p.joint = j;
        p.lo = tau;
        p.variable = "time";
        p.shape = String.format(Locale.ROOT, "joint %d's zero jumps at about %.0f s", j + 1, tau);
        p.x = time;
        p.xLabel = "time since the start (s)";
        return p;
    }

    /**
     * The step probes at every place between two poses' values within a twentieth of the poses
     * either side of a found step's place (the scan's places are quantiles; a step's place matters
     * to the pose: the poses between a quantile and the true place would be mispredicted).
     */
    static List<Probe> finerSteps(Diagnoser.Tester t, Probe p) {
        if (p.var != Var.ANGLE_STEP && p.var != Var.TIME_STEP && p.var != Var.TARGET_STEP && p.var != Var.BASE_STEP && p.var != Var.RANGE_STEP)
            return List.of();
        double[] v = p.var == Var.ANGLE_STEP ? t.endRows.get(0).stream().mapToDouble(r -> r.q(p.joint)).toArray() : p.x[0];
        List<Probe> out = new ArrayList<>();
        for (double place : placesNear(v, p.lo))
            out.add(switch (p.var) {
                case ANGLE_STEP -> angleStep(t, p.joint, place, p.x);
                case TARGET_STEP -> targetStep(t, place, p.x, p.rf);
                case BASE_STEP -> baseStep(t, place, p.x);
                case RANGE_STEP -> rangeStep(t, p.instrument, p.sens, place, p.x);
                default -> zeroStep(t, p.joint, place, p.x);
            });
        return out;
    }

    /**
     * The places of a step near {@code place}: halfway between two neighbouring values (sorted) within
     * a {@link #STEP_PLACES}th of the values either side of it, without {@code place} itself and
     * without ties.
     */
    static List<Double> placesNear(double[] values, double place) {
        double[] v = values.clone();
        Arrays.sort(v);
        int at = 0;
        while (at < v.length && v[at] <= place) at++;
        int reach = Math.max(1, v.length / STEP_PLACES);
        List<Double> out = new ArrayList<>();
        for (int i = Math.max(1, at - reach); i <= Math.min(v.length - 1, at + reach); i++) {
            double mid = 0.5 * (v[i - 1] + v[i]);
            if (mid == place || !(v[i] > v[i - 1])) continue;
            out.add(mid);
        }
        return out;
    }

    /**
     * Each joint's error repeating with its link's other angle ({@link Effect#linkAngle}: against the
     * link before it where the controller reads it against the ground, or the other way round), at
     * harmonics 1..{@code hMax} of that angle, each its own 2-column test like a joint's own harmonics;
     * with {@code housings}, also with the angle of each wrist housing its drive passes through.
     */
    private static List<Probe> linkPeriodics(Diagnoser.Tester t, int hMax, boolean housings) {
        List<Probe> out = new ArrayList<>();
        for (int j = 0; j < t.dof; j++) {
            double[] c = Effect.linkAngle(t.w.model, j);
            if (c != null) out.addAll(angleHarmonics(t, j, c, hMax));
            // the wrist housings the joint's drive passes through, at the low orders of a seat or gear out of round
            if (housings) for (int k : Effect.housingsOf(t.w.model, j)) out.addAll(angleHarmonics(t, j, Effect.jointAngle(t.dof, k), Math.min(hMax, HOUSING_ORDERS)));
        }
        return out;
    }

    /**
     * Each joint's error at its own angle's low orders 1..{@link #WARM_ORDERS} growing with the temperature
     * ({@link Effect#periodicWarming}): u·sin h q and u·cos h q, u the temperature about its mean over
     * its span, each order its own 2-column test. On a joint the arm's weight loads, from order 2: the
     * gravity torque is nearly a first order of the joint's angle, and its give changing through a
     * warm-up (a joint softening, a carried mass emptying) has the forms of its own physics.
     */
    private static List<Probe> warmPeriodics(Diagnoser.Tester t, double[][] temp) {
        List<Probe> out = new ArrayList<>();
        int poses = t.w.rows.size(), ends = t.ends;
        double lo = min(temp), hi = max(temp), mean = Arrays.stream(temp).flatMapToDouble(Arrays::stream).average().orElse(0);
        for (int j = 0; j < t.dof; j++) {
            if (t.w.model.isPrismatic(j)) continue;
            final int jj = j;
            int first = t.w.gravity != null && Diagnoser.loaded(t.w.gravity, j, t.w.rows) ? 2 : 1;
            double[][] qx = new double[ends][poses];
            for (int e = 0; e < ends; e++) for (int i = 0; i < poses; i++) qx[e][i] = Math.toDegrees(t.endRows.get(e).get(i).q(j));
            List<Reg> regs = new ArrayList<>();
            List<Integer> ks = new ArrayList<>();
            for (int h = first; h <= WARM_ORDERS; h++) {
                final int hh = h;
                regs.add((e, i, g) -> {
                    double u = (temp[e][i] - mean) / (hi - lo), q = t.endRows.get(e).get(i).q(jj);
                    g[0] = u * Math.sin(hh * q);
                    g[1] = u * Math.cos(hh * q);
                });
                ks.add(2);
            }
            List<Probe> batch = drives(t, j, ks, regs);
            for (int h = first; h <= WARM_ORDERS; h++) {
                Probe p = batch.get(h - first);
                p.var = Var.WARM_PERIODIC;
                p.joint = j;
                p.harmonic = h;
                p.lo = lo;
                p.hi = hi;
                p.variable = "joint " + (j + 1) + " angle and temperature";
                p.shape = h + (h == 1 ? " cycle" : " cycles") + " per turn of joint " + (j + 1) + ", growing with the temperature";
                p.x = qx;
                p.xLabel = "joint " + (j + 1) + " angle q" + (j + 1) + " (deg)";
                out.add(p);
            }
        }
        return out;
    }

    /** Orders of a joint's own angle probed for an error growing with the temperature (an encoder's channels once and twice a turn, and two above). */
    static final int WARM_ORDERS = 4;

    /** Orders of a wrist housing's angle probed on the joints whose drives pass through it. */
    static final int HOUSING_ORDERS = 6;

    /** Joint j's error at harmonics 1..hMax of the angle Σ_l c_l·q_l, each its own 2-column test. */
    private static List<Probe> angleHarmonics(Diagnoser.Tester t, int j, double[] c, int hMax) {
        List<Probe> out = new ArrayList<>();
        int poses = t.w.rows.size(), ends = t.ends;
        double[][] psi = new double[ends][poses], x = new double[ends][poses];
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
        for (int e = 0; e < ends; e++)
            for (int i = 0; i < poses; i++) {
                double[] q = t.endRows.get(e).get(i).q();
                double a = 0;
                for (int l = 0; l < c.length; l++) a += c[l] * q[l];
                psi[e][i] = a;
                x[e][i] = Math.toDegrees(a);
                lo = Math.min(lo, a);
                hi = Math.max(hi, a);
            }
        if (!(hi - lo > 1e-6)) return out;
        List<Reg> regs = new ArrayList<>();
        List<Integer> ks = new ArrayList<>();
        for (int h = 1; h <= hMax; h++) {
            final int hh = h;
            regs.add((e, i, g) -> { g[0] = Math.sin(hh * psi[e][i]); g[1] = Math.cos(hh * psi[e][i]); });
            ks.add(2);
        }
        List<Probe> batch = drives(t, j, ks, regs);
        String text = Effect.linkAngleText(c);
        boolean housing = Effect.isAnotherJointsAngle(c, j);
        String angle = housing ? "joint " + text.substring(1) + "'s angle" : "the link angle " + text;
        for (int h = 1; h <= hMax; h++) {
            Probe p = batch.get(h - 1);
            p.var = Var.LINK_PERIODIC;
            p.joint = j;
            p.harmonic = h;
            p.linkAngle = c;
            p.variable = housing ? "joint " + text.substring(1) + " angle" : "link angle " + text;
            p.shape = h + (h == 1 ? " cycle" : " cycles") + " per turn of " + angle + " on joint " + (j + 1);
            p.x = x;
            p.xLabel = housing ? "joint " + text.substring(1) + " angle " + text + " (deg)" : "link angle " + text + " (deg)";
            out.add(p);
        }
        return out;
    }

    /** A regressor: its k values at one end (0, or 0 and 1 for a pair of poses) of one residual row's pose. */
    private interface Reg { void at(int end, int pose, double[] g); }

    /** Drive j's zero following a spline of x (time or temperature): encoder slip or creep, a drive warming up. */
    private static Probe zero(Diagnoser.Tester t, int j, Var var, double[][] x, String name, String xLabel) {
        double lo = min(x), hi = max(x);
        Probe p = drive(t, j, Effect.POINT_BASIS, (e, i, g) -> Effect.bspline(x[e][i], lo, hi, g));
        p.var = var;
        p.joint = j;
        p.variable = name;
        p.shape = "joint " + (j + 1) + "'s zero moves with " + name;
        p.x = x;
        p.xLabel = xLabel;
        p.lo = lo;
        p.hi = hi;
        p.basis = Effect.POINT_BASIS;
        return p;
    }

    /**
     * Several probes on drive j at once: probe b has ks[b] columns from regs[b]. Their columns are
     * projected out of the model's span in one pass over it (each column as it would be alone).
     */
    private static List<Probe> drives(Diagnoser.Tester t, int j, List<Integer> ks, List<Reg> regs) {
        int n = ks.size(), kt = 0;
        int[] off = new int[n];
        double[][] part = new double[n][];
        for (int b = 0; b < n; b++) { off[b] = kt; kt += ks.get(b); part[b] = new double[ks.get(b)]; }
        Probe all = drive(t, j, kt, (e, i, g) -> {
            for (int b = 0; b < n; b++) {
                regs.get(b).at(e, i, part[b]);
                System.arraycopy(part[b], 0, g, off[b], part[b].length);
            }
        });
        int m = t.m;
        List<Probe> out = new ArrayList<>();
        for (int b = 0; b < n; b++) {
            int k = ks.get(b), o = off[b];
            Probe p = new Probe();
            p.k = k;
            p.n0 = Arrays.copyOfRange(all.n0, o, o + k);
            double[] raw = new double[m * k];
            for (int i = 0; i < m; i++) System.arraycopy(all.raw, i * kt + o, raw, i * k, k);
            p.unprojected(raw, all.u, all.rank, Arrays.copyOfRange(all.span, o * all.rank, (o + k) * all.rank));
            if (all.endS != null) {
                p.endS = new double[all.endS.length][m * k];
                for (int e = 0; e < all.endS.length; e++)
                    for (int i = 0; i < m; i++) System.arraycopy(all.endS[e], i * kt + o, p.endS[e], i * k, k);
            }
            out.add(p);
        }
        return out;
    }

    /**
     * k columns on drive j: at each end, its sensitivity to drive j times the regressor there. With one
     * end a column is d_j ∘ g over the rows of a pose, so its coefficients on the span's basis U are
     * Σ_poses g · (Σ_rows of the pose d_j U): one pass over U for all k columns.
     */
    private static Probe drive(Diagnoser.Tester t, int j, int k, Reg reg) {
        if (t.ends > 1) return columns(t, k, (e, row, g, col) -> t.endDQ[e][row * t.dof + j] * g[col], k, reg);
        int m = t.m, rpp = t.rpp, poses = m / rpp, rank = t.rank, dof = t.dof;
        double[] dq = t.endDQ[0], u = t.u;
        double[] s = new double[m * k], g = new double[k], span = new double[k * rank], w = new double[rank];
        for (int i = 0; i < poses; i++) {
            reg.at(0, i, g);
            Arrays.fill(w, 0);
            for (int a = 0; a < rpp; a++) {
                int row = i * rpp + a;
                double d = dq[row * dof + j];
                for (int c = 0; c < k; c++) s[row * k + c] = d * g[c];
                for (int r = 0; r < rank; r++) w[r] += u[row * rank + r] * d;
            }
            for (int c = 0; c < k; c++) {
                double gc = g[c];
                if (gc == 0) continue;
                for (int r = 0; r < rank; r++) span[c * rank + r] += gc * w[r];
            }
        }
        return finish(t, s, k, span);
    }

    /** k / 3 functions moving the measured point along each base axis (column b·3 + axis): the point's sensitivity times the regressor. */
    private static Probe translation(Diagnoser.Tester t, int k, Reg reg) {
        return columns(t, k, (e, row, g, col) -> t.endDTrans[e][row * 3 + col % 3] * g[col / 3], k / 3, reg);
    }

    private interface Sens { double at(int end, int row, double[] g, int col); }

    /**
     * The k signature columns Σ_ends sens(end, row, g(end, pose), col), projected out of the model's
     * span; with two ends, each end's own columns are kept too (the evidence plot's choice of end).
     */
    private static Probe columns(Diagnoser.Tester t, int k, Sens sens, int nReg, Reg reg) {
        int m = t.m, rpp = t.rpp, poses = m / rpp, ends = t.ends;
        double[] s = new double[m * k], g = new double[nReg];
        double[][] own = ends > 1 ? new double[ends][m * k] : null;
        for (int e = 0; e < ends; e++)
            for (int i = 0; i < poses; i++) {
                reg.at(e, i, g);
                for (int a = 0; a < rpp; a++) {
                    int row = i * rpp + a;
                    for (int c = 0; c < k; c++) {
                        double v = sens.at(e, row, g, c);
                        s[row * k + c] += v;
                        if (own != null) own[e][row * k + c] = v;
                    }
                }
            }
        Probe p = finish(t, s, k);
        p.endS = own;
        return p;
    }

    /** A translation of the point (3 x 4 columns) or a length change (4 columns) following a spline of x. */
    private static Probe scalar(Diagnoser.Tester t, Var var, double[][] x, String name, String xLabel, boolean translation) {
        int nb = Effect.POINT_BASIS;
        double lo = min(x), hi = max(x);
        Reg spline = (e, i, g) -> Effect.bspline(x[e][i], lo, hi, g);
        Probe p = translation ? translation(t, 3 * nb, spline)
                : columns(t, nb, (e, row, g, col) -> t.endDStrain[e][row] * g[col], nb, spline);
        p.var = var;
        p.lengths = !translation;
        p.variable = name;
        p.shape = translation ? "the measured point moves with " + name : "every length changes with " + name;
        p.x = x;
        p.xLabel = xLabel;
        p.lo = lo;
        p.hi = hi;
        p.basis = nb;
        return p;
    }

    /** A probe of the k columns s (m x k, row-major), projected out of the model's span, with their norms before. */
    private static Probe finish(Diagnoser.Tester t, double[] s, int k) {
        return finish(t, s, k, Diagnoser.spanCoefficients(t.u, t.rank, t.m, s, k));
    }

    /** As above, with the columns' coefficients on the span's basis (k x rank). */
    private static Probe finish(Diagnoser.Tester t, double[] s, int k, double[] span) {
        Probe p = new Probe();
        p.k = k;
        p.n0 = new double[k];
        for (int i = 0; i < t.m; i++) for (int col = 0; col < k; col++) p.n0[col] += s[i * k + col] * s[i * k + col];
        for (int col = 0; col < k; col++) p.n0[col] = Math.sqrt(p.n0[col]);
        p.unprojected(s, t.u, t.rank, span);
        return p;
    }

    /** A condition per end and pose. */
    private static double[][] column(Diagnoser.Tester t, java.util.function.ToDoubleFunction<PoseConditions> f) {
        double[][] out = new double[t.ends][t.w.rows.size()];
        for (int e = 0; e < t.ends; e++) for (int i = 0; i < out[e].length; i++) out[e][i] = f.applyAsDouble(t.endConditions.get(e).get(i));
        return out;
    }

    private static double min(double[][] x) { return Arrays.stream(x).flatMapToDouble(Arrays::stream).min().orElse(0); }

    private static double max(double[][] x) { return Arrays.stream(x).flatMapToDouble(Arrays::stream).max().orElse(1); }

    private static boolean varies(double[][] x, double minRange) {
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
        for (double[] xe : x)
            for (double v : xe) { if (!Double.isFinite(v)) return false; lo = Math.min(lo, v); hi = Math.max(hi, v); }
        return hi - lo >= minRange;
    }

    /** Torque of the payload (a point mass at the flange, gravity −z) on each drive at one end's poses: τ_q = Cᵀ τ_θ. */
    static double[][] payloadTorques(Diagnoser.Tester t, int end, double[] payload) {
        int dof = t.dof;
        double[][] c = t.w.model.couplingMatrix();
        double[][] out = new double[payload.length][dof];
        for (int i = 0; i < payload.length; i++) {
            Pose[] f = t.w.model.linkFrames(t.endRows.get(end).get(i).q());
            Vec3 pf = f[f.length - 1].position(), force = new Vec3(0, 0, -9.80665 * payload[i]);
            double[] th = new double[dof];
            for (int a = 0; a < dof; a++)
                th[a] = t.w.model.isPrismatic(a) ? force.dot(f[a + 1].zAxis()) : pf.minus(f[a + 1].position()).cross(force).dot(f[a + 1].zAxis());
            for (int j = 0; j < dof; j++) for (int a = 0; a < dof; a++) out[i][j] += c[a][j] * th[a];
        }
        return out;
    }

    /**
     * A probe's columns X as the scan's F test sees them, through their Gram matrix XᵀX: X is the raw
     * columns S projected out of the model's span U and the structures B found so far, all
     * orthonormal to one another, so XᵀX = SᵀS − (UᵀS)ᵀ(UᵀS) − Σ (BᵀS)ᵀ(BᵀS) and, for a residual
     * orthogonal to them all, Xᵀr = Sᵀr. The test's kept columns, reduction of the residual and p
     * follow from a Cholesky factor of XᵀX in the order Gram–Schmidt takes the columns; a probe this
     * says may pass is tested on its projected columns.
     */
    static final class Gram {
        final Probe p;
        final double[] g; // k x k

        Gram(Probe p) {
            this.p = p;
            int k = p.k, m = p.raw.length / k, rank = p.span.length / k;
            g = new double[k * k];
            for (int i = 0; i < m; i++)
                for (int a = 0; a < k; a++) {
                    double x = p.raw[i * k + a];
                    if (x == 0) continue;
                    for (int b = a; b < k; b++) g[a * k + b] += x * p.raw[i * k + b];
                }
            for (int a = 0; a < k; a++)
                for (int b = a; b < k; b++) {
                    double v = 0;
                    for (int r = 0; r < rank; r++) v += p.span[a * rank + r] * p.span[b * rank + r];
                    g[a * k + b] -= v;
                    g[b * k + a] = g[a * k + b];
                }
        }

        /** Out of the structure's orthonormal columns b (m x nb) too. */
        void remove(double[] b, int nb) {
            int k = p.k, m = p.raw.length / k;
            double[] d = new double[nb * k]; // Bᵀ S
            for (int i = 0; i < m; i++)
                for (int c = 0; c < nb; c++) {
                    double x = b[i * nb + c];
                    if (x == 0) continue;
                    for (int a = 0; a < k; a++) d[c * k + a] += x * p.raw[i * k + a];
                }
            for (int a = 0; a < k; a++)
                for (int bb = 0; bb < k; bb++) {
                    double v = 0;
                    for (int c = 0; c < nb; c++) v += d[c * k + a] * d[c * k + bb];
                    g[a * k + bb] -= v;
                }
        }

        /**
         * Whether the probe may pass the F test at threshold thr against the residual res (orthogonal to
         * the span and the nq columns found, sum of squares rss): false only when it clearly fails.
         */
        boolean mayPass(Diagnoser.Tester t, double[] res, double rss, int nq, double thr) {
            return p(t, res, rss, nq) < 2 * thr; // the exact test decides near the threshold
        }

        /** The F test's p, as the test on the projected columns finds it; 0 when a column's share left is too close to the bound to tell, NaN with no column kept. */
        double p(Diagnoser.Tester t, double[] res, double rss, int nq) {
            double[] r = reduction(t, res);
            if (r == null) return 0;
            int q = (int) r[1];
            if (q == 0) return Double.NaN;
            double drss = r[0];
            int df2 = t.m - t.rank - nq - q;
            double rss1 = Math.max(rss - drss, 1e-300);
            double f = (drss / q) / (rss1 / Math.max(1, df2));
            return Stats.fUpperTail(f, q, df2);
        }

        /**
         * The residual's sum of squares the probe's kept columns take and how many are kept, {drss, q}; null when a column
         * lies too close to the absorbed-ratio bound to tell here.
         */
        double[] reduction(Diagnoser.Tester t, double[] res) {
            int k = p.k, m = t.m;
            double ar = t.w.o.absorbedRatio();
            double[] rr = new double[k * k]; // row t: the kept column t's factor entries, by column
            int[] kept = new int[k];
            int q = 0;
            for (int col = 0; col < k; col++) {
                double n0 = p.n0[col] * p.n0[col];
                if (!(n0 > 0)) continue;
                double d = g[col * k + col];
                for (int a = 0; a < q; a++) {
                    double r = g[kept[a] * k + col];
                    for (int b = 0; b < a; b++) r -= rr[b * k + kept[a]] * rr[b * k + col];
                    r /= rr[a * k + kept[a]];
                    rr[a * k + col] = r;
                    d -= r * r;
                }
                double ratio = Math.sqrt(Math.max(d, 0) / n0);
                if (Math.abs(ratio - ar) <= 1e-6 * ar) return null; // too close to the bound to tell here
                if (ratio >= ar) {
                    rr[q * k + col] = Math.sqrt(d);
                    kept[q++] = col;
                }
            }
            double[] coef = new double[q];
            double drss = 0;
            for (int a = 0; a < q; a++) {
                int col = kept[a];
                double x = 0;
                for (int i = 0; i < m; i++) x += p.raw[i * k + col] * res[i];
                for (int b = 0; b < a; b++) x -= rr[b * k + col] * coef[b];
                coef[a] = x / rr[a * k + col];
                drss += coef[a] * coef[a];
            }
            return new double[] {drss, q};
        }
    }

    /**
     * Greedy scan: accept structures one by one (lowest BIC among the probes that pass Holm at
     * step s and lower the leave-one-pose-out error), each conditional on those before; then the
     * backward step.
     */
    static List<Found> scan(Diagnoser.Tester t, List<Probe> probes, double alpha, int maxFound) {
        int n = probes.size();
        List<Found> found = new ArrayList<>();
        double[] q = new double[0];
        int nq = 0;
        boolean[] used = new boolean[n];
        // each probe's columns projected out of the structures accepted so far, one block at a time (they are orthonormal to
        // one another), made when first needed: left[pi] is out of the first done[pi] blocks
        List<double[]> blocks = new ArrayList<>();
        double[][] left = new double[n][];
        int[] done = new int[n];
        // the probes' Gram matrices, out of the span and the blocks: most probes fail the F test, which these tell at a k x k cost
        Gram[] gram = new Gram[n];
        for (int pi = 0; pi < n; pi++) if (probes.get(pi).raw != null) gram[pi] = new Gram(probes.get(pi));
        for (int step = 0; step < maxFound; step++) {
            double thr = alpha / Math.max(1, n - step);
            double[] res = t.residualOutOf(q, nq);
            double rss = t.rssOutOf(q, nq);
            Found best = null;
            for (int pi = 0; pi < n; pi++) {
                if (used[pi]) continue;
                if (gram[pi] != null && !gram[pi].mayPass(t, res, rss, nq, thr)) continue;
                Probe p = probes.get(pi);
                if (left[pi] == null) left[pi] = p.s();
                for (; done[pi] < blocks.size(); done[pi]++)
                    left[pi] = Diagnoser.projectOut(blocks.get(done[pi]), blocks.get(done[pi]).length / t.m, t.m, left[pi], p.k);
                Diagnoser.Candidate c = test(t, p, left[pi], q, nq, thr);
                if (c == null || !(c.p < thr) || !(c.pressAfter < c.pressBefore)) continue;
                c.threshold = thr;
                if (best == null || Diagnoser.lowerBic(c.bic, best.c.bic)) { best = new Found(); best.probe = probes.get(pi); best.c = c; }
            }
            if (best == null) break;
            used[probes.indexOf(best.probe)] = true;
            // a step: the place between two poses that explains most, near the quantile found
            for (Probe fine : finerSteps(t, best.probe)) {
                Diagnoser.Candidate c = test(t, fine, q, nq, best.c.threshold);
                if (c != null && c.p < best.c.threshold && c.drss > best.c.drss) {
                    c.threshold = best.c.threshold;
                    best.probe = fine;
                    best.c = c;
                }
            }
            // a cycle: the period and the harmonics that explain most for their count (BIC)
            for (Probe fine : finerCycles(t, best.probe)) {
                Diagnoser.Candidate c = test(t, fine, q, nq, best.c.threshold);
                if (c != null && c.p < best.c.threshold && Diagnoser.lowerBic(c.bic, best.c.bic)) {
                    c.threshold = best.c.threshold;
                    best.probe = fine;
                    best.c = c;
                }
            }
            found.add(best);
            int add = best.c.df1;
            double[] nqArr = new double[t.m * (nq + add)];
            for (int i = 0; i < t.m; i++) {
                System.arraycopy(q, i * nq, nqArr, i * (nq + add), nq);
                System.arraycopy(best.c.basis, i * add, nqArr, i * (nq + add) + nq, add);
            }
            q = nqArr;
            nq += add;
            blocks.add(best.c.basis);
            for (int pi = 0; pi < n; pi++) if (!used[pi] && gram[pi] != null) gram[pi].remove(best.c.basis, add);
        }
        // Backward: a structure the later ones made redundant leaves.
        for (int k = found.size() - 1; k >= 0 && found.size() > 1; k--) {
            Found f = found.get(k);
            List<double[]> others = new ArrayList<>();
            int no = 0;
            for (Found g : found) if (g != f) { others.add(g.c.basis); no += g.c.df1; }
            double[] qo = new double[t.m * no];
            int off = 0;
            for (Found g : found) {
                if (g == f) continue;
                for (int i = 0; i < t.m; i++) System.arraycopy(g.c.basis, i * g.c.df1, qo, i * no + off, g.c.df1);
                off += g.c.df1;
            }
            double thr = alpha / Math.max(1, n - found.size() + 1);
            Diagnoser.Candidate c = test(t, f.probe, qo, no, thr);
            if (c == null || !(c.p < thr)) found.remove(k);
        }
        for (Found f : found) f.sizeM = size(t, f);
        placeHarmonics(t, probes, found, alpha);
        for (Found f : found) {
            if (f.probe.var == Var.BASE_MOMENT)
                f.probe.tilt = Diagnoser.bestBaseTilt(t, -1, null, t.w.gravity, t.w.rows, t.w.conditions);
            if (f.probe.var == Var.TOOL_PULL) f.probe.pull = bestPull(t, f.probe);
            if (f.probe.var == Var.LOAD_TILT) f.probe.bend = remassedLoadTilt(t, f.probe.bend);
            if (f.probe.var == Var.STATION) f.probe.station = bestStation(t, f.probe.facing);
        }
        return found;
    }

    /** Stage harmonics (above 1-3) at most this many are tried in place of a smooth structure of one joint's angle. */
    static final int MAX_STAGES = 2;
    /**
     * A harmonic h' is as good a place as the best, h, when h's fit is better by less than this
     * many noise variances (the 99 % point of χ² on 2 degrees of freedom: a sine and a cosine).
     */
    static final double PLACE_CHI2 = 9.21;

    /**
     * The joint's frequency resolution in cycles per turn: over a sampled range R (rad) two
     * harmonics closer than 2π/R cannot be told apart (a record of length R resolves frequencies
     * 1/R apart; Bracewell, The Fourier Transform and its Applications, ch. 10, sampling and
     * resolution).
     */
    static double resolution(double lo, double hi) { return hi > lo ? 2 * Math.PI / (hi - lo) : Double.POSITIVE_INFINITY; }

    /**
     * For each located harmonic: the range of harmonic numbers of its joint the poses allow (every h'
     * whose fit, given the other structures, is within {@link #PLACE_CHI2} noise variances of the
     * best h); the best h within the joint's resolution of the one found replaces it. For each smooth
     * structure of a joint with no harmonic located: whether a few resolvable harmonics hold it
     * ({@link #sparseHarmonics}).
     */
    private static void placeHarmonics(Diagnoser.Tester t, List<Probe> probes, List<Found> found, double alpha) {
        double thr = alpha / Math.max(1, probes.size());
        for (Found f : found) {
            if (f.probe.var != Var.ANGLE_PERIODIC && f.probe.var != Var.ANGLE_SMOOTH) continue;
            if (f.probe.stage) { f.placeLo = f.placeHi = f.probe.harmonic; continue; } // placed by the stage scan's refinement
            int j = f.probe.joint;
            List<Probe> per = periodic(probes, j);
            double[] range = range(t, j);
            double res = resolution(range[0], range[1]);
            Basis others = basisOf(t, found, f);
            if (f.probe.var == Var.ANGLE_PERIODIC) {
                int[] pl = place(t, per, f.probe.harmonic, res, List.of(), others);
                f.placeLo = Math.min(pl[1], f.probe.harmonic);
                f.placeHi = Math.max(pl[2], f.probe.harmonic);
            } else if (found.stream().noneMatch(g -> g.probe.var == Var.ANGLE_PERIODIC && g.probe.joint == j))
                sparseHarmonics(t, probes, per, f, res, others, thr);
        }
    }

    /** The periodic probes of joint j, by harmonic (index h − 1). */
    private static List<Probe> periodic(List<Probe> probes, int j) {
        List<Probe> out = new ArrayList<>();
        for (Probe p : probes) if (p.var == Var.ANGLE_PERIODIC && p.joint == j && !p.stage) out.add(p);
        return out;
    }

    /** Joint j's sampled range (rad) over every end's poses. */
    private static double[] range(Diagnoser.Tester t, int j) {
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
        for (List<org.robopro.calibration.measurement.Measurement> er : t.endRows)
            for (org.robopro.calibration.measurement.Measurement r : er) { lo = Math.min(lo, r.q(j)); hi = Math.max(hi, r.q(j)); }
        return new double[] {lo, hi};
    }

    /** Orthonormal columns (m x n, row-major) spanning some structures' probes. */
    private static final class Basis {
        double[] q = new double[0];
        int n;

        void add(Diagnoser.Candidate c, int m) {
            if (c == null || c.df1 == 0) return;
            double[] nq = new double[m * (n + c.df1)];
            for (int i = 0; i < m; i++) {
                System.arraycopy(q, i * n, nq, i * (n + c.df1), n);
                System.arraycopy(c.basis, i * c.df1, nq, i * (n + c.df1) + n, c.df1);
            }
            q = nq;
            n += c.df1;
        }

        Basis copy() { Basis b = new Basis(); b.q = q; b.n = n; return b; }
    }

    /** One probe of two probes' columns side by side. */
    private static Probe join(Probe a, Probe b) {
        Probe p = new Probe();
        p.k = a.k + b.k;
        p.n0 = new double[p.k];
        System.arraycopy(a.n0, 0, p.n0, 0, a.k);
        System.arraycopy(b.n0, 0, p.n0, a.k, b.k);
        double[] as = a.s(), bs = b.s();
        int m = as.length / a.k;
        p.s = new double[m * p.k];
        for (int i = 0; i < m; i++) {
            System.arraycopy(as, i * a.k, p.s, i * p.k, a.k);
            System.arraycopy(bs, i * b.k, p.s, i * p.k + a.k, b.k);
        }
        return p;
    }

    /** The span of every found structure but {@code except}, each projected out of those before it. */
    private static Basis basisOf(Diagnoser.Tester t, List<Found> found, Found except) {
        Basis b = new Basis();
        for (Found g : found) if (g != except) b.add(test(t, g.probe, b.q, b.n, 0), t.m);
        return b;
    }

    /**
     * Where the poses place a harmonic found at h of a joint, given the other structures and the
     * harmonics {@code chosen} (their probes): the best harmonic within the resolution of h, and the
     * lowest and highest harmonic numbers whose fit is within {@link #PLACE_CHI2} noise variances of
     * it (searched out to twice the resolution and, past it, as long as one still qualifies).
     * Returns {best, lo, hi}.
     */
    static int[] place(Diagnoser.Tester t, List<Probe> per, int h, double res, List<Probe> chosen, Basis others) {
        Basis b = others.copy();
        for (Probe p : chosen) b.add(test(t, p, b.q, b.n, 0), t.m);
        int hMax = per.size();
        double[] drss = new double[hMax + 1];
        double s2 = Double.NaN;
        Arrays.fill(drss, Double.NaN);
        java.util.function.IntToDoubleFunction at = k -> {
            if (k < 1 || k > hMax) return Double.NaN;
            if (Double.isNaN(drss[k])) {
                Diagnoser.Candidate c = test(t, per.get(k - 1), b.q, b.n, 0);
                drss[k] = c == null ? 0 : c.drss;
            }
            return drss[k];
        };
        int reach = (int) Math.ceil(res);
        int best = h;
        for (int k = Math.max(1, h - reach + 1); k <= Math.min(hMax, h + reach - 1); k++)
            if (at.applyAsDouble(k) > at.applyAsDouble(best)) best = k;
        Diagnoser.Candidate cb = test(t, per.get(best - 1), b.q, b.n, 0);
        if (cb == null) return new int[] {h, h, h};
        s2 = (cb.drss / cb.df1) / Math.max(cb.f, 1e-300);
        double tol = PLACE_CHI2 * s2, top = at.applyAsDouble(best);
        int lo = best, hi = best;
        for (int k = best - 1; k >= 1 && (k >= best - 2 * reach || top - at.applyAsDouble(k + 1) <= tol); k--)
            if (top - at.applyAsDouble(k) <= tol) lo = k;
        for (int k = best + 1; k <= hMax && (k <= best + 2 * reach || top - at.applyAsDouble(k - 1) <= tol); k++)
            if (top - at.applyAsDouble(k) <= tol) hi = k;
        return new int[] {best, lo, hi};
    }

    /**
     * Whether one or two stage harmonics of joint j (above a single-stage gear's 1-3, which are taken
     * with them) hold a smooth structure located on its angle. The best single harmonic, and the best
     * pair searched over every pair at least the joint's resolution apart (two harmonics closer than
     * that are one feature of the record, the signature of a place-bound shape, not of a gear; and two
     * stages a few cycles apart interfere, so one at a time lands between them): the pair when each
     * of its harmonics is significant at {@code thr} given the other and lowers the leave-one-pose-out
     * error. A reducer has one or two stages; a comb of several harmonics is the Fourier series of a
     * shape that repeats or stays in one place, which the smooth curve holds as well. They hold the
     * structure when, with them and harmonics 1-3, no smooth function of the joint's angle at any
     * resolution finds anything significant left; they are as good an explanation as the smooth curve,
     * or a better one when they predict left-out poses better than every smooth curve of the angle.
     */
    private static void sparseHarmonics(Diagnoser.Tester t, List<Probe> probes, List<Probe> per, Found f, double res, Basis others, double thr) {
        if (per.size() <= Effect.HARMONICS) return;
        Basis low = others.copy();
        for (int h = 1; h <= Effect.HARMONICS; h++) low.add(test(t, per.get(h - 1), low.q, low.n, 0), t.m);
        Diagnoser.Candidate best1 = null;
        Probe p1 = null;
        for (Probe p : per) {
            if (p.harmonic <= Effect.HARMONICS) continue;
            Diagnoser.Candidate c = test(t, p, low.q, low.n, thr);
            if (c == null || !(c.p < thr) || !(c.pressAfter < c.pressBefore)) continue;
            if (best1 == null || c.drss > best1.drss) { best1 = c; p1 = p; }
        }
        if (best1 == null) return;
        List<Probe> chosen = new ArrayList<>(List.of(p1));
        // each harmonic's columns once projected out of the model and harmonics 1-3 (orthonormal): a pair's
        // reduction of the residual is then that of the two blocks side by side
        Probe[] own = new Probe[per.size()];
        for (int a = Effect.HARMONICS; a < per.size(); a++) {
            Diagnoser.Candidate c = test(t, per.get(a), low.q, low.n, 0);
            if (c == null) continue;
            own[a] = new Probe();
            own[a].k = c.df1;
            own[a].s = c.basis;
            own[a].n0 = new double[c.df1];
            Arrays.fill(own[a].n0, 1);
        }
        double bestPair = -1;
        Probe[] pair = null;
        for (int a = Effect.HARMONICS; a < per.size(); a++)
            for (int c2 = a + 1; c2 < per.size(); c2++) {
                Probe pa = per.get(a), pb = per.get(c2);
                if (pb.harmonic - pa.harmonic < res || own[a] == null || own[c2] == null) continue;
                Diagnoser.Candidate c = test(t, join(own[a], own[c2]), null, 0, 0);
                if (c != null && c.drss > bestPair) { bestPair = c.drss; pair = new Probe[] {pa, pb}; }
            }
        if (pair != null) {
            boolean both = true;
            for (int i = 0; i < 2 && both; i++) {
                Basis with = low.copy();
                with.add(test(t, pair[1 - i], with.q, with.n, 0), t.m);
                Diagnoser.Candidate c = test(t, pair[i], with.q, with.n, thr);
                both = c != null && c.p < thr && c.pressAfter < c.pressBefore;
            }
            if (both) chosen = new ArrayList<>(List.of(pair));
        }
        // where the poses place each, given the other
        int[] lo = new int[chosen.size()], hi = new int[chosen.size()];
        for (int i = 0; i < chosen.size(); i++) {
            List<Probe> rest = new ArrayList<>(chosen);
            rest.remove(i);
            int[] pl = place(t, per, chosen.get(i).harmonic, res, rest, low);
            lo[i] = Math.max(Effect.HARMONICS + 1, pl[1]);
            hi[i] = pl[2];
        }
        Basis all = low.copy();
        Diagnoser.Candidate lastC = null;
        for (Probe p : chosen) { lastC = test(t, p, all.q, all.n, 1); all.add(lastC, t.m); }
        if (lastC == null) return;
        // nothing a smooth curve of the angle finds is left
        for (Probe p : probes) {
            if (p.var != Var.ANGLE_SMOOTH || p.joint != f.probe.joint) continue;
            Diagnoser.Candidate c = test(t, p, all.q, all.n, thr);
            if (c != null && c.p < thr && c.pressAfter < c.pressBefore) return;
        }
        // they must predict left-out poses better than a smooth curve of the angle at every resolution, by the alias margin
        double[] rg = range(t, f.probe.joint);
        int jj = f.probe.joint;
        double bestSmooth = Double.POSITIVE_INFINITY;
        for (int nb : Effect.SMOOTH_RESOLUTIONS) {
            Probe sp = drive(t, jj, nb, (e, i, g) -> Effect.bspline(t.endRows.get(e).get(i).q(jj), rg[0], rg[1], g));
            Diagnoser.Candidate c = test(t, sp, others.q, others.n, 1);
            if (c != null) bestSmooth = Math.min(bestSmooth, c.pressAfter);
        }
        Diagnoser.Candidate sm = test(t, f.probe, others.q, others.n, 1);
        if (sm != null) bestSmooth = Math.min(bestSmooth, sm.pressAfter);
        f.sparseBetter = lastC.pressAfter < (1 - Diagnoser.ALIAS_MARGIN) * bestSmooth;
        List<Integer> idx = new ArrayList<>();
        for (int i = 0; i < chosen.size(); i++) idx.add(i);
        List<Probe> picked = chosen;
        idx.sort((a, c) -> Integer.compare(picked.get(a).harmonic, picked.get(c).harmonic));
        f.sparse = new int[chosen.size()];
        f.sparseLo = new int[chosen.size()];
        f.sparseHi = new int[chosen.size()];
        for (int i = 0; i < idx.size(); i++) {
            f.sparse[i] = chosen.get(idx.get(i)).harmonic;
            f.sparseLo[i] = Math.min(lo[idx.get(i)], f.sparse[i]);
            f.sparseHi[i] = Math.max(hi[idx.get(i)], f.sparse[i]);
        }
    }

    /**
     * Words on where the poses place a located harmonic (or the harmonics that hold a smooth
     * structure), and what to measure when they cannot place it to one number; "" when placed.
     */
    static String placement(Found f) {
        if (f.probe.var == Var.ANGLE_PERIODIC && f.placeHi > f.placeLo)
            return String.format(Locale.ROOT, " These poses place it only between %d and %d cycles per turn (each fits within the "
                    + "noise), so its number is not known; measure joint %d over as much of a turn as its limits allow, with at "
                    + "least %d poses per cycle, to place it.", f.placeLo, f.placeHi, f.probe.joint + 1, POSES_PER_HARMONIC);
        if (f.probe.var == Var.ANGLE_SMOOTH && f.sparse != null) {
            List<String> hs = new ArrayList<>();
            boolean vague = false;
            for (int i = 0; i < f.sparse.length; i++) {
                vague |= f.sparseHi[i] > f.sparseLo[i];
                hs.add(f.sparseHi[i] > f.sparseLo[i] ? f.sparse[i] + " (" + f.sparseLo[i] + "-" + f.sparseHi[i] + ")" : "" + f.sparse[i]);
            }
            String which = (hs.size() == 1 ? "Harmonic " : "Harmonics ") + String.join(" and ", hs) + " of joint " + (f.probe.joint + 1)
                    + ", with 1-3,";
            if (f.sparseBetter && !vague)
                return " " + which + " hold it and predict left-out poses better than any smooth curve of the angle: a reducer's stage harmonics.";
            return String.format(Locale.ROOT, " %s hold it %s: over the %.0f deg sampled these poses cannot tell a reducer's stage "
                    + "harmonics from a shape bound to one place; measure joint %d over as much of a turn as its limits allow, with at "
                    + "least %d poses per cycle, to tell.", which, vague ? "as well, but these poses cannot place their numbers (in "
                    + "brackets: the numbers they allow)" : String.format(Locale.ROOT, "about as well (within %.0f %% on left-out poses)",
                    100 * Diagnoser.ALIAS_MARGIN), Math.toDegrees(f.probe.hi - f.probe.lo), f.probe.joint + 1, POSES_PER_HARMONIC);
        }
        return "";
    }

    /** A probe's test against the model plus the already located columns (q, m x nq). */
    static Diagnoser.Candidate test(Diagnoser.Tester t, Probe p, double[] q, int nq, double pGate) {
        return test(t, p, null, q, nq, pGate);
    }

    /** As above, with the probe's columns already projected out of q ({@code left}), or null. */
    private static Diagnoser.Candidate test(Diagnoser.Tester t, Probe p, double[] left, double[] q, int nq, double pGate) {
        List<String> names = new ArrayList<>();
        for (int c = 0; c < p.k; c++) names.add("c" + c);
        Diagnoser.Candidate c = left == null ? t.testProjected(p.s(), p.n0, p.k, names, q, nq, pGate)
                : t.testProjected(left, p.n0, p.k, names, q, nq, pGate, true);
        return c.keptColumns == 0 ? null : c;
    }

    /** RMS over the measurements (every measured point, or every distance) of the structure's fitted displacement, m. */
    static double size(Diagnoser.Tester t, Found f) {
        int q = f.c.df1, n = t.measurements();
        double s = 0;
        for (int mi = 0; mi < n; mi++)
            for (int a = 0; a < t.dim; a++) {
                int row = t.rowOf(mi) + a;
                double v = 0;
                for (int k = 0; k < q; k++) v += f.c.basis[row * q + k] * f.c.coef[k];
                s += v * v;
            }
        return Math.sqrt(s / Math.max(1, n)) * t.fit.problem.sigmaPos();
    }

    /**
     * Evidence plot: per measurement (each measured point of a pose, or each distance), the
     * structure's fitted displacement along its own direction plus the residual along it (mm),
     * against the variable. A distance between two poses is plotted at the value of the variable
     * at the pose whose own part of the structure's change is the larger (the structure changes
     * the length at both ends; its curve is the fitted change of that length).
     */
    static Diagnosis.Plot plot(Diagnoser.Tester t, Found f) {
        if (f.probe.endS != null && f.probe.angle != null) return pairPartialResidual(t, f);
        int q = f.c.df1, n = t.measurements(), d = t.dim;
        double unit = t.fit.problem.sigmaPos() * 1e3;
        List<double[]> pts = new ArrayList<>();
        for (int mi = 0; mi < n; mi++) {
            int r0 = t.rowOf(mi);
            double[] c = new double[d];
            for (int a = 0; a < d; a++) for (int k = 0; k < q; k++) c[a] += f.c.basis[(r0 + a) * q + k] * f.c.coef[k];
            double norm = 0;
            for (double v : c) norm += v * v;
            norm = Math.sqrt(norm);
            if (norm == 0) continue;
            double along = 0;
            for (int a = 0; a < d; a++) along += c[a] / norm * t.rPerp[r0 + a];
            pts.add(new double[] {f.probe.x[end(f, r0)][t.poseOf(mi)], along * unit, norm * unit});
        }
        double[] x = new double[pts.size()], y = new double[pts.size()], cy = new double[pts.size()];
        for (int i = 0; i < x.length; i++) { x[i] = pts.get(i)[0]; y[i] = pts.get(i)[1]; cy[i] = pts.get(i)[2]; }
        String xLabel = f.probe.endS == null ? f.probe.xLabel : f.probe.xLabel + ", at the pose of the pair that carries more of the change";
        return new Diagnosis.Plot(xLabel, d == 1 ? "distance residual along the structure's change (mm)"
                : "residual along the structure's displacement (mm)", x, y, x.clone(), cy, null);
    }

    /** The end (pose of a pair) whose own columns, at the structure's estimate, change residual row {@code row} the more; 0 with one end. */
    static int end(Found f, int row) {
        double[][] own = f.probe.endS;
        if (own == null) return 0;
        int k = f.probe.k, best = 0;
        double bestAbs = -1;
        for (int e = 0; e < own.length; e++) {
            double v = 0;
            for (int c = 0; c < k; c++) v += own[e][row * k + c] * f.c.estimate[c];
            if (Math.abs(v) > bestAbs) { bestAbs = Math.abs(v); best = e; }
        }
        return best;
    }

    /**
     * Evidence plot of a joint-angle structure located in distances between pairs of poses: the
     * joint's error itself. Each length is put at the pose of the pair that carries more of the
     * fitted change (e), and the error there is estimated as the fitted function plus what the
     * structure leaves of the length's residual, resolved through that pose's sensitivity d_e to
     * the joint: y = f̂(q_e) − (r⊥ − c) / d_e (r = predicted − measured, c the structure's fitted part
     * of it). The other pose's share of the error is noise to this estimate. Lengths whose d_e is
     * below 0.3 x the median carry little about the joint and are left out. Millidegrees against the
     * joint angle, with the fitted f̂ as the curve: the same reading as an effect's partial residual.
     */
    static Diagnosis.Plot pairPartialResidual(Diagnoser.Tester t, Found f) {
        int q = f.c.df1, k = f.probe.k, rows = t.m, j = f.probe.joint;
        double unit = Math.toDegrees(1) * 1e3;
        double[] g = new double[k], d = new double[rows];
        int[] end = new int[rows];
        for (int i = 0; i < rows; i++) {
            end[i] = end(f, i);
            d[i] = Math.abs(t.endDQ[end[i]][i * t.dof + j]);
        }
        double[] sorted = d.clone();
        Arrays.sort(sorted);
        double cut = 0.3 * sorted[rows / 2];
        List<double[]> pts = new ArrayList<>();
        for (int i = 0; i < rows; i++) {
            if (!(d[i] > cut)) continue;
            double c = 0;
            for (int b = 0; b < q; b++) c += f.c.basis[i * q + b] * f.c.coef[b];
            double qe = t.endRows.get(end[i]).get(i).q(j);
            f.probe.angle.at(qe, g);
            double fit = 0;
            for (int b = 0; b < k; b++) fit += g[b] * f.c.estimate[b];
            double y = fit - (t.rPerp[i] - c) / t.endDQ[end[i]][i * t.dof + j];
            pts.add(new double[] {Math.toDegrees(qe), y * unit});
        }
        double[] x = new double[pts.size()], y = new double[pts.size()];
        for (int i = 0; i < x.length; i++) { x[i] = pts.get(i)[0]; y[i] = pts.get(i)[1]; }
        int nc = 400;
        double lo = Arrays.stream(x).min().orElse(0), hi = Arrays.stream(x).max().orElse(1);
        double[] cx = new double[nc], cy = new double[nc];
        for (int i = 0; i < nc; i++) {
            cx[i] = lo + (hi - lo) * i / (nc - 1);
            f.probe.angle.at(Math.toRadians(cx[i]), g);
            for (int b = 0; b < k; b++) cy[i] += g[b] * f.c.estimate[b] * unit;
        }
        return new Diagnosis.Plot(f.probe.xLabel + ", at the pose of the pair that carries more of the change",
                "joint " + (j + 1) + " error at that pose, partial residual (mdeg)", x, y, cx, cy, null);
    }
}
