package org.robopro.calibration.identification;

import java.util.Arrays;
import org.robopro.calibration.Cancellation;

/**
 * Levenberg–Marquardt for {@link LeastSquaresProblem}s, own implementation on plain arrays:
 * normal equations with Jacobian column scaling (Moré 1978: scale_j = max over iterations of
 * ‖J_j‖), damping updated by Nielsen's gain-ratio rule (Madsen, Nielsen &amp; Tingleff,
 * "Methods for non-linear least squares problems", 2004, §3.2), and a Cholesky solve. Buffers
 * are allocated once per solver; a solver is for one thread. Diagnostics (iterations, cost
 * history, the reason it stopped) come back in the {@link Result}.
 */
public final class LevenbergMarquardt {
    /** Why the iteration stopped. */
    public enum Reason {
        /** The relative cost reduction fell below the tolerance. */
        COST_CONVERGED,
        /** The scaled step fell below the tolerance. */
        STEP_CONVERGED,
        /** The scaled gradient is orthogonal to the residual to within the tolerance. */
        GRADIENT_CONVERGED,
        /** The residual is zero. */
        EXACT_FIT,
        MAX_ITERATIONS,
        /** Damping grew without producing a decrease: the problem is degenerate or the Jacobian wrong. */
        STALLED
    }

    /**
     * @param x           the solution
     * @param cost        ½‖r‖² at the solution
     * @param iterations  accepted and rejected iterations
     * @param evaluations residual evaluations
     * @param costHistory cost at the start and after each accepted step
     * @param reason      why it stopped
     */
    public record Result(double[] x, double cost, int iterations, int evaluations, double[] costHistory, Reason reason) {
        public boolean converged() { return reason != Reason.MAX_ITERATIONS && reason != Reason.STALLED; }
    }

    private final LeastSquaresProblem problem;
    private final int m, n;
    private final double[] r, rTrial, jac, a, aFactor, g, step, stepUnscaled, scale, xTrial;
    private int maxIterations = 100;
    private double costTolerance = 1e-12, stepTolerance = 1e-10, gradientTolerance = 1e-10;
    private double initialDamping = 1e-3;

    public LevenbergMarquardt(LeastSquaresProblem problem) {
        this.problem = problem;
        this.m = problem.residualCount();
        this.n = problem.parameterCount();
        if (n == 0) throw new IllegalArgumentException("no free parameters");
        r = new double[m];
        rTrial = new double[m];
        jac = new double[m * n];
        a = new double[n * n];
        aFactor = new double[n * n];
        g = new double[n];
        step = new double[n];
        stepUnscaled = new double[n];
        scale = new double[n];
        xTrial = new double[n];
    }

    public LevenbergMarquardt maxIterations(int v) { maxIterations = v; return this; }
    public LevenbergMarquardt costTolerance(double v) { costTolerance = v; return this; }
    public LevenbergMarquardt stepTolerance(double v) { stepTolerance = v; return this; }

    /**
     * The damping the solver starts with, relative to the scaled normal matrix's diagonal (about 1):
     * 1e-3 (the default) for a start of unknown quality; about 1e-6 for a start believed close to the
     * solution, where a larger one spends an accepted step for every threefold decrease of the
     * damping before the steps become Gauss-Newton's (Madsen, Nielsen & Tingleff, "Methods for
     * non-linear least squares problems", 2nd ed., DTU 2004, section 3.2: tau = 1e-6 for a good x0,
     * 1e-3 or 1 otherwise). A poor start costs only rejected steps, each doubling it and more.
     */
    public LevenbergMarquardt initialDamping(double v) {
        if (!(v > 0) || !Double.isFinite(v)) throw new IllegalArgumentException("initial damping must be positive and finite: " + v);
        initialDamping = v;
        return this;
    }

    /** The Jacobian at the last accepted point (row-major m x n); valid after {@link #solve}. */
    public double[] lastJacobian() { return jac; }

    /** The residuals at the last accepted point; valid after {@link #solve}. */
    public double[] lastResiduals() { return r; }

    public Result solve(double[] x0, Cancellation cancel) {
        double[] x = x0.clone();
        problem.evaluate(x, r, jac);
        int evals = 1;
        double cost = 0.5 * Dense.dot(r, r, m);
        double[] history = new double[maxIterations + 1];
        int nh = 0;
        history[nh++] = cost;
        Arrays.fill(scale, 0);
        updateScale();
        Dense.normalMatrix(jac, m, n, scale, a);
        Dense.gradient(jac, r, m, n, scale, g);
        double lambda = initialDamping; // scaled problem: diag(A) is about 1
        double nu = 2;
        int it = 0;
        Reason reason = Reason.MAX_ITERATIONS;
        if (cost == 0) reason = Reason.EXACT_FIT;
        else if (gradientSmall(cost)) reason = Reason.GRADIENT_CONVERGED;
        else {
            while (it < maxIterations) {
                cancel.check();
                it++;
                System.arraycopy(a, 0, aFactor, 0, n * n);
                for (int i = 0; i < n; i++) aFactor[i * n + i] += lambda;
                for (int i = 0; i < n; i++) step[i] = -g[i];
                if (!Dense.cholesky(aFactor, n)) {
                    lambda *= nu;
                    nu *= 2;
                    if (lambda > 1e16) { reason = Reason.STALLED; break; }
                    continue;
                }
                Dense.choleskySolve(aFactor, n, step);
                double stepNorm = 0, xNorm = 0;
                for (int i = 0; i < n; i++) {
                    stepUnscaled[i] = step[i] / scale[i];
                    stepNorm += step[i] * step[i];
                    xNorm += (x[i] * scale[i]) * (x[i] * scale[i]);
                }
                stepNorm = Math.sqrt(stepNorm);
                xNorm = Math.sqrt(xNorm);
                if (stepNorm <= stepTolerance * (xNorm + stepTolerance)) { reason = Reason.STEP_CONVERGED; break; }
                problem.retract(x, stepUnscaled, xTrial);
                problem.evaluate(xTrial, rTrial, null);
                evals++;
                double costTrial = 0.5 * Dense.dot(rTrial, rTrial, m);
                double predicted = 0;
                for (int i = 0; i < n; i++) predicted += step[i] * (lambda * step[i] - g[i]);
                predicted *= 0.5;
                double rho = predicted > 0 ? (cost - costTrial) / predicted : -1;
                if (rho > 0 && Double.isFinite(costTrial)) {
                    System.arraycopy(xTrial, 0, x, 0, n);
                    double reduction = cost - costTrial;
                    cost = costTrial;
                    problem.evaluate(x, r, jac);
                    evals++;
                    history[nh++] = cost;
                    updateScale();
                    Dense.normalMatrix(jac, m, n, scale, a);
                    Dense.gradient(jac, r, m, n, scale, g);
                    double t = 2 * rho - 1;
                    lambda *= Math.max(1.0 / 3, 1 - t * t * t);
                    nu = 2;
                    if (cost == 0) { reason = Reason.EXACT_FIT; break; }
                    if (reduction <= costTolerance * (cost + reduction) && predicted <= costTolerance * (cost + reduction)) {
                        reason = Reason.COST_CONVERGED;
                        break;
                    }
                    if (gradientSmall(cost)) { reason = Reason.GRADIENT_CONVERGED; break; }
                } else {
                    lambda *= nu;
                    nu *= 2;
                    if (lambda > 1e16) { reason = Reason.STALLED; break; }
                }
            }
        }
        // Leave r and jac at x (a rejected last trial only touched rTrial).
        return new Result(x, cost, it, evals, Arrays.copyOf(history, nh), reason);
    }

    private void updateScale() {
        for (int j = 0; j < n; j++) {
            double s = 0;
            for (int i = 0; i < m; i++) {
                double v = jac[i * n + j];
                s += v * v;
            }
            s = Math.sqrt(s);
            if (s > scale[j]) scale[j] = s;
            if (scale[j] == 0) scale[j] = 1; // a column that is zero everywhere: leave unscaled
        }
    }

    private boolean gradientSmall(double cost) {
        double rn = Math.sqrt(2 * cost);
        double gmax = 0;
        for (int i = 0; i < n; i++) gmax = Math.max(gmax, Math.abs(g[i]));
        return gmax <= gradientTolerance * rn;
    }
}
