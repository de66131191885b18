package org.robopro.calibration.identification;

/**
 * A non-linear least-squares problem min ½‖r(x)‖² for {@link LevenbergMarquardt}.
 * Residuals are predicted minus measured (already weighted); the Jacobian is dr/dx, written
 * row-major (residualCount x parameterCount). Parameters may live on a manifold: the solver
 * moves by {@link #retract}, and the Jacobian is taken with respect to that step.
 */
public interface LeastSquaresProblem {
    int parameterCount();

    int residualCount();

    /** Writes r(x) into {@code residuals} and, when {@code jacobian} is not null, dr/dstep into it. */
    void evaluate(double[] x, double[] residuals, double[] jacobian);

    /** x ⊞ step into {@code out} (may not alias x); plain addition unless a block lives on a manifold. */
    default void retract(double[] x, double[] step, double[] out) {
        for (int i = 0; i < x.length; i++) out[i] = x[i] + step[i];
    }
}
