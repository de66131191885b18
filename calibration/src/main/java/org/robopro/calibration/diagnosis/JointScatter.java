package org.robopro.calibration.diagnosis;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Scatter of one joint's angle beyond the instrument's noise: an error of the joint that is no
 * function of anything recorded, so no shape of the locate scan follows it, yet it moves the
 * measured point only along that joint's motion, by more where the joint's lever to the point is
 * longer. A joint read as whole counts of a coarse encoder (the true angle anywhere within the
 * count: a uniform error of count/√12 RMS; Widrow &amp; Kollár, Quantization Noise, Cambridge
 * 2008, ch. 4) scatters so, and so does a joint still moving when the instrument measures (the arm
 * not settled after its move; ISO 9283:1998 §7.4, position stabilisation time).
 *
 * <p>The residual's covariance at pose i is modelled as Σ₀ + Σ_j s_j²·d_ij d_ijᵀ, Σ₀ the
 * instrument's own (a constant 3 x 3 matrix: its noise need not be the same along and across its
 * beam) and d_ij = ∂p/∂q_j the point's sensitivity to joint j there. The six distinct products of
 * each pose's residual r_i r_iᵀ are regressed on those matrices (a moment estimate of variance
 * components; Searle, Casella &amp; McCulloch, Variance Components, Wiley 1992, ch. 11), and each
 * s_j² is judged by its standard error from the poses' own scatter about the fit (the sandwich
 * estimator with the pose as cluster; White, Econometrica 48 (1980) 817): one-sided, below
 * alpha over the joints tested.
 */
final class JointScatter {
    private JointScatter() { }

    /** A joint whose angle scatters: its joint (0-based), the scatter's RMS (rad), p, and the evidence plot's points. */
    record Found(int joint, double sRad, double p, double threshold, double ratio, double sizeM, double share, double[] lever, double[] along,
                 double sigmaAlongM, double speedRho, double speedP) { }

    /** The six distinct entries of a symmetric 3 x 3 matrix, in the regression's column order: xx, yy, zz, xy, xz, yz. */
    private static final int[][] PAIRS = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};

    /**
     * The joints whose angle scatters beyond the instrument's noise in the residual the tester holds
     * (one measured point per pose, its position rows, with or without orientations; none
     * otherwise), each below {@code alpha} over the number of joints tested.
     */
    static List<Found> scan(Diagnoser.Tester t, double alpha) {
        List<Found> out = new ArrayList<>();
        if (t.ends != 1 || t.perPose != 1 || t.dim != 3 || t.posRows < 3) return out;
        int n = t.m / t.rpp, dof = t.dof, rpp = t.rpp;
        List<Integer> joints = new ArrayList<>();
        for (int j = 0; j < dof; j++) if (!t.w.model.isPrismatic(j)) joints.add(j);
        int nj = joints.size(), p = 6 + nj;
        if (n < 10 * p) return out;
        double[] r = t.rPerp;
        double[][] d = new double[n * dof][3];
        double[][] x = new double[n * 6][p];
        double[] y = new double[n * 6];
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < dof; j++) for (int a = 0; a < 3; a++) d[i * dof + j][a] = t.endDQ[0][(i * rpp + a) * dof + j];
            for (int e = 0; e < 6; e++) {
                int a = PAIRS[e][0], b = PAIRS[e][1], row = i * 6 + e;
                y[row] = r[i * rpp + a] * r[i * rpp + b];
                x[row][e] = 1;
                for (int k = 0; k < nj; k++) {
                    double[] dj = d[i * dof + joints.get(k)];
                    x[row][6 + k] = dj[a] * dj[b];
                }
            }
        }
        double[][] xtx = new double[p][p];
        double[] xty = new double[p];
        for (int row = 0; row < y.length; row++)
            for (int a = 0; a < p; a++) {
                xty[a] += x[row][a] * y[row];
                for (int b = 0; b < p; b++) xtx[a][b] += x[row][a] * x[row][b];
            }
        org.apache.commons.math3.linear.DecompositionSolver solver;
        try {
            solver = new org.apache.commons.math3.linear.LUDecomposition(new org.apache.commons.math3.linear.Array2DRowRealMatrix(xtx)).getSolver();
            if (!solver.isNonSingular()) return out;
        } catch (RuntimeException ex) {
            return out;
        }
        double[] beta = solver.solve(new org.apache.commons.math3.linear.ArrayRealVector(xty)).toArray();
        double[][] ainv = solver.getInverse().getData();
        // the sandwich: each pose's six products a cluster of their own
        double[][] meat = new double[p][p];
        for (int i = 0; i < n; i++) {
            double[] g = new double[p];
            for (int e = 0; e < 6; e++) {
                int row = i * 6 + e;
                double fitted = 0;
                for (int a = 0; a < p; a++) fitted += x[row][a] * beta[a];
                double res = y[row] - fitted;
                for (int a = 0; a < p; a++) g[a] += x[row][a] * res;
            }
            for (int a = 0; a < p; a++) for (int b = 0; b < p; b++) meat[a][b] += g[a] * g[b];
        }
        double threshold = alpha / Math.max(1, nj);
        double sigmaM = t.w.sigmaPos;
        org.apache.commons.math3.distribution.NormalDistribution normal = new org.apache.commons.math3.distribution.NormalDistribution(null, 0, 1);
        for (int k = 0; k < nj; k++) {
            int c = 6 + k, j = joints.get(k);
            double v = 0;
            for (int a = 0; a < p; a++) for (int b = 0; b < p; b++) v += ainv[c][a] * meat[a][b] * ainv[b][c];
            double s2 = beta[c];
            if (!(v > 0) || !(s2 > 0)) continue;
            double z = s2 / Math.sqrt(v), pv = normal.cumulativeProbability(-z);
            if (!(pv < threshold)) continue;
            double[] lever = new double[n], along = new double[n];
            double sumLever = 0, sigAlong = 0, alongSq = 0;
            for (int i = 0; i < n; i++) {
                double[] dj = d[i * dof + j];
                double dd = dj[0] * dj[0] + dj[1] * dj[1] + dj[2] * dj[2];
                if (!(dd > 0)) continue;
                double dr = 0, sd = 0;
                for (int a = 0; a < 3; a++) {
                    dr += dj[a] * r[i * rpp + a];
                    for (int b = 0; b < 3; b++) sd += dj[a] * beta[index(a, b)] * dj[b];
                }
                lever[i] = Math.sqrt(dd) * sigmaM;
                along[i] = dr / Math.sqrt(dd) * sigmaM;
                sumLever += dd;
                sigAlong += Math.max(0, sd / dd);
                alongSq += dr * dr / dd;
            }
            double excess = s2 * sumLever;
            double[] speed = speedFollows(t, j, lever, along);
            out.add(new Found(j, Math.sqrt(s2), pv, threshold, alongSq > excess ? alongSq / (alongSq - excess) : Double.POSITIVE_INFINITY,
                    Math.sqrt(excess / n) * sigmaM, t.rss0 > 0 ? Math.min(1, excess / t.rss0) : 0, lever, along, Math.sqrt(sigAlong / n) * sigmaM,
                    speed[0], speed[1]));
        }
        return out;
    }

    /**
     * Whether the joint's scatter grows with its speed in the move made just before the reading: the
     * rank correlation (Spearman) of the angle each pose's residual implies along the joint's motion,
     * |along| / lever, with the joint's speed in that move ({@link Effect#settling}), over the poses
     * whose lever is at least a third of the longest (the others carry mostly the instrument's
     * noise), and its one-sided p (Student's t with n − 2 degrees of freedom); NaN, NaN where the
     * moves are unknown. A reading taken while the arm still rings after its stop is off by more
     * after a faster move, whatever the phase; a coarse count's error is not.
     */
    static double[] speedFollows(Diagnoser.Tester t, int j, double[] lever, double[] along) {
        if (t.w.moves.isEmpty()) return new double[] {Double.NaN, Double.NaN};
        Effect st = Effect.settling(j, t.w.moves, t.w.speeds);
        double most = 0;
        for (double l : lever) most = Math.max(most, l);
        List<double[]> pts = new ArrayList<>();
        for (int i = 0; i < lever.length; i++)
            if (lever[i] >= most / 3 && lever[i] > 0)
                pts.add(new double[] {Math.abs(along[i]) / lever[i], Math.abs(st.settlingSpeed(t.endRows.get(0).get(i)))});
        int n = pts.size();
        if (n < 10) return new double[] {Double.NaN, Double.NaN};
        double[] a = new double[n], b = new double[n];
        for (int i = 0; i < n; i++) { a[i] = pts.get(i)[0]; b[i] = pts.get(i)[1]; }
        double rho = new org.apache.commons.math3.stat.correlation.SpearmansCorrelation().correlation(a, b);
        if (!Double.isFinite(rho) || Math.abs(rho) >= 1) return new double[] {rho, Double.NaN};
        double tt = rho * Math.sqrt((n - 2) / (1 - rho * rho));
        double p = 1 - new org.apache.commons.math3.distribution.TDistribution(null, n - 2).cumulativeProbability(tt);
        return new double[] {rho, p};
    }

    /** The column of Σ₀'s entry (a, b) among the six distinct ones ({@link #PAIRS}). */
    private static int index(int a, int b) {
        for (int e = 0; e < PAIRS.length; e++)
            if (PAIRS[e][0] == Math.min(a, b) && PAIRS[e][1] == Math.max(a, b)) return e;
        throw new IllegalArgumentException("entry " + a + ", " + b);
    }

    /** One-sided level below which a scatter is said to grow with the move's speed (one test per joint found scattering). */
    static final double SPEED_ALPHA = 0.01;

    /** The located entry of a scattering joint, with its words and evidence plot. */
    static Diagnosis.Located located(Found f) {
        double deg = Math.toDegrees(f.sRad());
        String shape = String.format(Locale.ROOT, "joint %d's angle scatters by %.4f deg RMS beyond the instrument's noise", f.joint() + 1, deg);
        String words = String.format(Locale.ROOT, "%s: the point moves %.4f mm RMS along joint %d's motion, more where the joint's lever "
                + "to the point is longer, and no function of the recorded angles, directions, time or temperature follows it (variance "
                + "of the residual along the joint's motion %.2f x the instrument's, p %s below the corrected threshold %.2g). Joint values "
                + "read as whole counts of %.4f deg scatter so (a count of c gives c/√12 RMS), so does a joint still moving when the "
                + "instrument measured (the arm not settled after its move), and so does an error along the joint's motion that "
                + "follows something the file does not record (the time, a temperature). No model of these poses can compensate it: "
                + "record the joint values at a finer resolution (the controller's measured, not commanded, angles), time_s and "
                + "temp_c, let the arm settle longer before each measurement, and measure a few poses twice to see it", Diagnoser.capital(shape), f.sizeM() * 1e3, f.joint() + 1, f.ratio(),
                Words.p(f.p()), f.threshold(), deg * Math.sqrt(12));
        if (f.speedP() < SPEED_ALPHA)
            words += String.format(Locale.ROOT, ". Here it grows with the joint's speed in the move made just before the reading (rank "
                    + "correlation %.2f, p %s): the arm was read before it settled, a residual vibration after the stop whose phase at the "
                    + "reading varies; wait longer after each stop before the reading", f.speedRho(), Words.p(f.speedP()));
        // evidence: the residual along the joint's motion against the joint's lever, with the ±2σ envelope of the noise and the scatter
        double maxLever = 0;
        for (double l : f.lever()) maxLever = Math.max(maxLever, l);
        int nc = 40;
        double[] cx = new double[2 * nc], cy = new double[2 * nc];
        double perMdeg = Math.toRadians(1e-3) * 1e3; // m/rad -> mm per mdeg
        for (int i = 0; i < nc; i++) {
            double l = maxLever * i / (nc - 1), env = 2 * Math.sqrt(f.sigmaAlongM() * f.sigmaAlongM() + f.sRad() * f.sRad() * l * l) * 1e3;
            cx[i] = l * perMdeg;
            cy[i] = env;
            cx[2 * nc - 1 - i] = l * perMdeg;
            cy[2 * nc - 1 - i] = -env;
        }
        double[] x = new double[f.lever().length], y = new double[f.lever().length];
        for (int i = 0; i < x.length; i++) { x[i] = f.lever()[i] * perMdeg; y[i] = f.along()[i] * 1e3; }
        Diagnosis.Plot plot = new Diagnosis.Plot("lever of joint " + (f.joint() + 1) + " at the point (mm per mdeg)",
                "residual along joint " + (f.joint() + 1) + "'s motion (mm)", x, y, cx, cy, null);
        return new Diagnosis.Located("joint " + (f.joint() + 1) + " reading", shape, f.sizeM(), f.share(), f.ratio(), 1, f.p(),
                f.threshold(), "final", null, words, plot);
    }
}
