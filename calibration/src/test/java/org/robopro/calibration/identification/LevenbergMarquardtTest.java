package org.robopro.calibration.identification;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import java.util.concurrent.CancellationException;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.Cancellation;

class LevenbergMarquardtTest {
    /** r = (10 (x2 - x1²), 1 - x1): Rosenbrock's valley, minimum (1, 1) with zero cost. */
    static final LeastSquaresProblem ROSENBROCK = new LeastSquaresProblem() {
        public int parameterCount() { return 2; }
        public int residualCount() { return 2; }
        public void evaluate(double[] x, double[] r, double[] j) {
            r[0] = 10 * (x[1] - x[0] * x[0]);
            r[1] = 1 - x[0];
            if (j != null) { j[0] = -20 * x[0]; j[1] = 10; j[2] = -1; j[3] = 0; }
        }
    };

    /** y = a exp(b t) + c with noise; badly scaled on purpose (a ~ 1e3, b ~ 1e-2). */
    static final class ExpFit implements LeastSquaresProblem {
        final double[] t, y;
        ExpFit(long seed, double a, double b, double c, double sigma) {
            Random rnd = new Random(seed);
            t = new double[50];
            y = new double[50];
            for (int i = 0; i < 50; i++) {
                t[i] = i * 4;
                y[i] = a * Math.exp(b * t[i]) + c + sigma * rnd.nextGaussian();
            }
        }
        public int parameterCount() { return 3; }
        public int residualCount() { return t.length; }
        public void evaluate(double[] x, double[] r, double[] j) {
            for (int i = 0; i < t.length; i++) {
                double e = Math.exp(x[1] * t[i]);
                r[i] = x[0] * e + x[2] - y[i];
                if (j != null) { j[3 * i] = e; j[3 * i + 1] = x[0] * t[i] * e; j[3 * i + 2] = 1; }
            }
        }
    }

    @Test
    void solve_rosenbrockFromClassicStart_reachesMinimum() {
        var res = new LevenbergMarquardt(ROSENBROCK).solve(new double[] {-1.2, 1}, Cancellation.NONE);
        assertTrue(res.converged(), res.reason().toString());
        assertEquals(1, res.x()[0], 1e-8);
        assertEquals(1, res.x()[1], 1e-8);
    }

    @Test
    void solve_noisyBadlyScaledFit_hasZeroGradientAndRecoversTruth() {
        ExpFit p = new ExpFit(11, 1500, -0.012, 40, 0.5);
        LevenbergMarquardt lm = new LevenbergMarquardt(p);
        var res = lm.solve(new double[] {1000, -0.02, 0}, Cancellation.NONE);
        assertTrue(res.converged(), res.reason().toString());
        // Optimality: Jᵀr = 0 at the solution, relative to the sizes involved.
        double[] r = new double[50], j = new double[150];
        p.evaluate(res.x(), r, j);
        for (int c = 0; c < 3; c++) {
            double g = 0, colNorm = 0;
            for (int i = 0; i < 50; i++) { g += j[3 * i + c] * r[i]; colNorm += j[3 * i + c] * j[3 * i + c]; }
            assertTrue(Math.abs(g) <= 1e-6 * Math.sqrt(colNorm) * Math.sqrt(2 * res.cost()), "gradient " + c + " = " + g);
        }
        assertEquals(1500, res.x()[0], 5);
        assertEquals(-0.012, res.x()[1], 1e-4);
        // Cost history is non-increasing.
        double[] h = res.costHistory();
        for (int i = 1; i < h.length; i++) assertTrue(h[i] <= h[i - 1]);
    }

    @Test
    void solve_nearStartWithSmallInitialDamping_reachesTheSamePointInFewerSteps() {
        ExpFit p = new ExpFit(11, 1500, -0.012, 40, 0.5);
        // a start within a few per cent of the solution, as a refit after a small change of the model has
        double[] near = {1450, -0.0118, 41};
        var slow = new LevenbergMarquardt(p).solve(near, Cancellation.NONE);
        var quick = new LevenbergMarquardt(p).initialDamping(1e-6).solve(near, Cancellation.NONE);
        assertTrue(slow.converged() && quick.converged(), slow.reason() + " " + quick.reason());
        assertEquals(slow.x()[0], quick.x()[0], 1e-6 * 1500);
        assertEquals(slow.x()[1], quick.x()[1], 1e-6 * 0.012);
        assertEquals(slow.x()[2], quick.x()[2], 1e-6 * 40);
        assertTrue(quick.iterations() < slow.iterations(), quick.iterations() + " iterations against " + slow.iterations());
        // from a poor start the small damping costs rejected steps, not the answer
        var far = new LevenbergMarquardt(p).initialDamping(1e-6).solve(new double[] {1000, -0.02, 0}, Cancellation.NONE);
        assertTrue(far.converged(), far.reason().toString());
        assertEquals(slow.x()[1], far.x()[1], 1e-6 * 0.012);
        assertThrows(IllegalArgumentException.class, () -> new LevenbergMarquardt(p).initialDamping(0));
    }

    @Test
    void solve_cancelledToken_throws() {
        Cancellation c = new Cancellation();
        c.cancel();
        assertThrows(CancellationException.class,
                () -> new LevenbergMarquardt(ROSENBROCK).solve(new double[] {-1.2, 1}, c));
    }
}
