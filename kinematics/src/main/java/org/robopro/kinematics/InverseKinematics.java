package org.robopro.kinematics;

import java.util.List;
import java.util.Optional;
import org.ejml.data.DMatrixRMaj;
import org.ejml.dense.row.SingularOps_DDRM;

/**
 * Inverse kinematics of a {@link KinematicModel}: closed form for six-axis arms with a
 * spherical wrist whose axis 2 is perpendicular to axis 1 and parallel to axis 3 (detected from
 * the model's geometry, see {@link ClosedFormIk}), damped least squares for any model (seeded
 * by the closed form of the nearly-spherical geometry for calibrated arms). Immutable; each call
 * allocates its own buffers, so one instance may be shared between threads.
 *
 * <p>Configuration data follows ABB's confdata: cf1, cf4, cf6 are the quadrant numbers
 * floor(q / 90 deg) of axes 1, 4 and 6 (quadrant 0 is 0..90 deg, -1 is 0..-90 deg); cfx = 4
 * (wrist centre behind axis 1) + 2 (wrist centre behind the lower arm) + 1 (axis 5 negative),
 * where "in front" is the side the wrist centre is on at the zero position. The cfx table (0 =
 * front/front/positive ... 7 = behind/behind/negative) as ABB's RAPID reference manual gives it
 * is reproduced in CEAD-group/py-opw-kinematics, AXIS_CONFIGURATION.md. See docs/kinematics.md.
 *
 * <p>A joint on a quadrant boundary (axis 4 at 0, axis 6 at 90 deg, axis 5 at 0 for the cfx
 * bit) lies in both quadrants it separates. Joint values that are exactly on a boundary in
 * theory come out of forward and inverse kinematics, and out of a robtarget written to RAPID
 * and read back, a few 1e-15 to 1e-9 rad to either side, so a strict floor would give either
 * quadrant depending on rounding. Therefore {@link #confOf} counts a value within
 * {@link #CONF_TOLERANCE} below a boundary as on it (the quadrant above, as floor gives for the
 * exact value), and {@link #inConfiguration} and {@link #solveWithConf} accept a solution whose
 * joints are within CONF_TOLERANCE of the asked quadrants.
 */
public final class InverseKinematics {
    /** Convergence of the numerical solver: position (m) and orientation (rad). */
    public static final double TOLERANCE = 1e-10;

    /**
     * Joint values closer than this (rad) to a quadrant boundary are on it (see the class
     * comment). A robtarget written at RAPID's precision (positions to 1e-6 mm, quaternions to
     * 10 digits) and solved again moves the joints by about 1e-9 rad away from singularities;
     * 1e-6 rad (0.2 arc seconds, 1 um at 1 m) leaves a wide margin over that and is far below any
     * joint difference a robot or a program means.
     */
    public static final double CONF_TOLERANCE = 1e-6;

    private final KinematicModel model;
    private final ClosedFormIk closed;
    private final double len;
    private final boolean[] integerColumn;
    private final double[][] numericalSeeds;
    // one solver per thread for the convenience methods (solvers are cheap but not free to make)
    private final ThreadLocal<IkSolver> solvers = ThreadLocal.withInitial(this::newSolver);

    private InverseKinematics(KinematicModel model) {
        this.model = model;
        this.closed = ClosedFormIk.of(model);
        this.len = model.characteristicLength();
        int n = model.dof();
        double[][] c = model.couplingMatrix();
        integerColumn = new boolean[n];
        for (int j = 0; j < n; j++) {
            boolean ok = !model.isPrismatic(j);
            for (int i = 0; i < n; i++) if (c[i][j] != Math.rint(c[i][j]) || (c[i][j] != 0 && model.isPrismatic(i))) ok = false;
            integerColumn[j] = ok;
        }
        double[][] seeds = new double[32][];
        seeds[0] = new double[n];
        double[][] random = model.randomConfigurations(31, 97);
        System.arraycopy(random, 0, seeds, 1, 31);
        numericalSeeds = seeds;
    }

    public static InverseKinematics of(KinematicModel model) { return new InverseKinematics(model); }

    public KinematicModel model() { return model; }

    /**
     * A new allocation-free solver for one thread (the fast path: {@link IkSolver#solveAll},
     * {@link IkSolver#solveNumerical}). This object's own methods use one per calling thread.
     */
    public IkSolver newSolver() { return new IkSolver(this, closed, integerColumn); }

    /** Seeds of the numerical fallback of solveAll for models without a closed form: zero and 31 random ones. */
    double[][] numericalSeeds() { return numericalSeeds; }

    /** True when the closed form applies exactly (spherical wrist etc.); false for approximate or none. */
    public boolean hasExactClosedForm() { return closed != null && closed.exact; }

    /** True when a closed form (exact, or approximate as a seed) is available. */
    public boolean hasClosedForm() { return closed != null; }

    /**
     * Every solution reaching baseTflange (closed form where the geometry allows, else numerical
     * from 32 seeds), with every turn variant (+-2 pi) inside the limits; those inside the limits
     * come first. Each carries its configuration data and manipulability
     * ({@link IkSolution#singularityMeasure()}). Allocation-free equivalent: {@link IkSolver#solveAll}.
     */
    public List<IkSolution> solveAll(Pose baseTflange) {
        double[] target = new double[12];
        Se3.fromPose(baseTflange, target);
        IkSolver solver = solvers.get();
        solver.solveAll(target);
        return solver.solutions();
    }

    /**
     * The solution inside the limits nearest to qSeed (closed-form branches refined
     * numerically on calibrated arms, or damped least squares from the seed), or empty when
     * unreachable. Allocation-free equivalent: {@link IkSolver#solveNear}.
     */
    public Optional<IkSolution> solveNear(Pose baseTflange, double[] qSeed) {
        if (qSeed.length != model.dof()) throw new IllegalArgumentException("seed needs " + model.dof() + " values");
        double[] target = new double[12];
        Se3.fromPose(baseTflange, target);
        double[] q = new double[model.dof()];
        IkSolver solver = solvers.get();
        if (!solver.solveNear(target, qSeed, q)) return Optional.empty();
        return Optional.of(new IkSolution(q, confOf(q), model.withinLimits(q), solver.manipulabilityAt(q)));
    }

    /**
     * The solution with the given configuration data (inside the limits), or empty: one whose
     * confdata is {@code conf}, else one whose joints are in {@code conf}'s quadrants within
     * {@link #CONF_TOLERANCE} ({@link #inConfiguration}), so a target on a quadrant boundary is
     * reached in the configuration it was taught in whichever side rounding puts the solution.
     */
    public Optional<IkSolution> solveWithConf(Pose baseTflange, ConfData conf) {
        List<IkSolution> all = solveAll(baseTflange);
        for (IkSolution s : all) if (s.withinLimits() && s.conf().equals(conf)) return Optional.of(s);
        for (IkSolution s : all) if (s.withinLimits() && matches(s.q(), s.conf(), conf)) return Optional.of(s);
        return Optional.empty();
    }

    /**
     * Whether joint values q are in configuration {@code conf}: their confdata is {@code conf}, or
     * differs only where a joint is within {@link #CONF_TOLERANCE} of the boundary of the asked
     * quadrant (axes 1, 4, 6) or axis 5 is within it of 0 (the cfx sign bit). The arm bits of cfx
     * (wrist centre behind axis 1 / the lower arm) must be equal.
     */
    public boolean inConfiguration(double[] q, ConfData conf) {
        return matches(q, confOf(q), conf);
    }

    private static boolean matches(double[] q, ConfData have, ConfData want) {
        if (have.equals(want)) return true;
        int n = q.length;
        if ((have.cfx() & 6) != (want.cfx() & 6)) return false;
        if ((have.cfx() & 1) != (want.cfx() & 1) && !(n > 4 && Math.abs(q[4]) <= CONF_TOLERANCE)) return false;
        return inQuadrant(q[0], want.cf1()) && (n > 3 ? inQuadrant(q[3], want.cf4()) : want.cf4() == 0)
                && (n > 5 ? inQuadrant(q[5], want.cf6()) : want.cf6() == 0);
    }

    /** q within [k, k + 1] quarter turns, widened by CONF_TOLERANCE on both sides. */
    static boolean inQuadrant(double q, int k) {
        double quarter = Math.PI / 2;
        return q >= k * quarter - CONF_TOLERANCE && q <= (k + 1) * quarter + CONF_TOLERANCE;
    }

    /** ABB configuration data of joint values q. */
    public ConfData confOf(double[] q) {
        int n = model.dof();
        if (q.length != n) throw new IllegalArgumentException("expected " + n + " joint values");
        int cfxArm = 0;
        if (closed != null) {
            double[] f = new double[12];
            model.flange(q, model.newWorkspace(), f);
            double[] th = model.theta(q);
            cfxArm = closed.cfxArmBits(f, th[0], th[1]);
        }
        int[] c = new int[4];
        confInto(q, cfxArm, c, 0);
        return new ConfData(c[0], c[1], c[2], c[3]);
    }

    /**
     * cf1, cf4, cf6, cfx of q into out[off..off+3]; cfxArm holds the arm bits (4, 2) of cfx. A
     * joint within {@link #CONF_TOLERANCE} below a quadrant boundary is on it and gets the
     * quadrant above (floor of the exact value); axis 5 counts as negative only below
     * -CONF_TOLERANCE. So a joint taught at 0 or 90 deg gets the same confdata whichever side
     * of the boundary rounding leaves it.
     */
    static void confInto(double[] q, int cfxArm, int[] out, int off) {
        int n = q.length;
        out[off] = quadrant(q[0]);
        out[off + 1] = n > 3 ? quadrant(q[3]) : 0;
        out[off + 2] = n > 5 ? quadrant(q[5]) : 0;
        out[off + 3] = cfxArm | (n > 4 && q[4] < -CONF_TOLERANCE ? 1 : 0);
    }

    /** ABB's quadrant number floor(q / 90 deg), a value within CONF_TOLERANCE below a boundary on it (-0.0 and 0 give 0). */
    static int quadrant(double q) {
        return (int) Math.floor((q + CONF_TOLERANCE) * (2 / Math.PI));
    }

    /**
     * Closed-form core for benchmarks and batch use: writes up to 8 model-angle solutions
     * (unwrapped turns, no limit check, not refined) into {@code thetaOut} (8 x 6) and returns
     * how many; 0 when the model has no closed form or the pose is unreachable.
     */
    public int closedFormThetas(double[] baseTflange12, double[][] thetaOut) {
        return closed == null ? 0 : closed.solve(baseTflange12, thetaOut, null, null, solvers.get().scratch());
    }

    // ---------------------------------------------------------------- numerical

    /** Result of the numerical solver with its diagnostics. */
    public record NumericalResult(boolean converged, double[] q, int iterations, double positionError,
                                  double orientationError) { }

    /** Outcome of a numerical solve, with the solution when it converged inside the limits. */
    public record NumericalOutcome(NumericalResult diagnostics, Optional<IkSolution> solution) { }

    /**
     * Damped least squares (Levenberg-Marquardt) from {@code qSeed} with the analytic geometric
     * Jacobian, keeping q inside the joint limits. Position rows are scaled by the robot's
     * size so metres and radians weigh alike. Allocation-free equivalent:
     * {@link IkSolver#solveNumerical}.
     */
    public NumericalOutcome solveNumerical(Pose baseTflange, double[] qSeed) {
        if (qSeed.length != model.dof()) throw new IllegalArgumentException("seed needs " + model.dof() + " values");
        double[] target = new double[12];
        Se3.fromPose(baseTflange, target);
        double[] q = new double[model.dof()];
        IkSolver solver = solvers.get();
        boolean ok = solver.solveNumerical(target, qSeed, q);
        NumericalResult r = new NumericalResult(ok, q.clone(), solver.iterations(), solver.positionError(),
                solver.orientationError());
        Optional<IkSolution> sol = ok && model.withinLimits(q)
                ? Optional.of(new IkSolution(q, confOf(q), true, solver.manipulabilityAt(q))) : Optional.empty();
        return new NumericalOutcome(r, sol);
    }

    /**
     * Manipulability at q: |det J| of the 6x6 geometric Jacobian with position rows divided by
     * the robot's size (Yoshikawa's measure for a square Jacobian; 0 at a singularity). 0 for
     * models that are not six-axis. This is what {@link IkSolution#singularityMeasure()} holds.
     */
    public double manipulability(double[] q) {
        if (q.length != model.dof()) throw new IllegalArgumentException("expected " + model.dof() + " joint values");
        return solvers.get().manipulabilityAt(q);
    }

    /**
     * Smallest singular value of the geometric Jacobian with position rows divided by the
     * robot's size (dimensionless; 0 at a singularity, about 0.1-1 far from one). An SVD per
     * call (tens of microseconds): the exact distance to a singularity, for reports and tests;
     * the IK paths use the cheaper {@link #manipulability(double[])}.
     */
    public double singularityMeasure(double[] q) {
        double[][] j = model.geometricJacobian(q);
        for (int r = 0; r < 3; r++) for (int c = 0; c < j[r].length; c++) j[r][c] /= len;
        double[] s = SingularOps_DDRM.singularValues(new DMatrixRMaj(j));
        double min = Double.POSITIVE_INFINITY;
        for (double v : s) min = Math.min(min, v);
        return min;
    }
}
