package org.robopro.calibration.diagnosis;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import org.robopro.calibration.measurement.Measurement;

/**
 * The stage-frequency scan (docs/diagnosis.md "Reducer stages"): a periodogram of each joint's
 * partial residual over frequencies in cycles per turn of the joint, continuous (not only whole
 * harmonics), from 1 up to {@link #maxOrder}. A reducer's stages each repeat their error at their
 * own speed relative to the output: an RV reducer's input stage at the total ratio (81 cycles per
 * turn), a harmonic drive twice per wave-generator turn (480 behind a belt), an intermediate shaft
 * of a spur train at a ratio that need not be whole (7.1 turns per output turn).
 *
 * <p>For one joint j the residual r (already orthogonal to the geometric model's span) is fitted
 * with d_j·(a sin f q_j + b cos f q_j), d_j the rows' sensitivity to drive j; the power
 * P(f) = bᵀN⁻¹b (N the 2×2 normal matrix) is the drop of the residual sum of squares. This is the
 * generalised Lomb–Scargle periodogram for uneven sampling (Lomb 1976, Astrophys. Space Sci. 39:447;
 * Scargle 1982, ApJ 263:835, whose false-alarm law for M independent frequencies is used here) with
 * per-pose weights; the geometric model's span is left out of N (the residual is already orthogonal
 * to it), which under-states P at the lowest orders only and so errs on the side of silence. The
 * grid steps {@code 1/(OVERSAMPLE·span in turns)} cycles per turn; sin and cos advance by rotation
 * (a recurrence, one complex multiply per pose and step), so a scan costs poses × grid points.
 *
 * <p>False-positive control: the number of independent frequencies searched on joint j is
 * M_j = (f_max − 1)·(span of q_j in turns) + 1 (the Rayleigh resolution; Horne and Baliunas 1986,
 * ApJ 302:757), and a peak must have p &lt; α / Σ_j M_j (Bonferroni over every joint and frequency),
 * p from F(2, ν). A peak found is refined (golden section within one grid step), taken as a whole
 * order when fixing it there raises the residual by less than χ²₁(0.95)·σ², subtracted, and the
 * scan repeats for the next. The peaks found become probes of the locate scan (with its own
 * Holm, leave-one-pose-out and backward control) and, through it, the gear-periodic family
 * carrying those orders, judged on held-out error like every family.
 */
final class StageScan {
    /** Grid points per independent frequency. */
    static final double OVERSAMPLE = 3;
    /** Stage orders searched at most, cycles per turn: a harmonic drive of ratio 250 (twice per wave-generator turn) behind a 2:1 belt. */
    static final double MAX_ORDER = 1000;
    /** RMS phase error (rad) the angle reading's rounding may add at the highest order searched. */
    static final double PHASE_LIMIT = 0.1;
    /** Stages looked for at most per campaign. */
    static final int MAX_STAGES = 6;
    /**
     * Orders below this are taken as whole: a fraction of a cycle over the range at orders 1–3 is what the
     * geometric model and the low harmonics already hold (the scan's power there ignores the geometric
     * model's span, so a peak between two low harmonics is an artefact of that).
     */
    static final double MIN_STAGE_ORDER = 4;
    /**
     * A stage fitted on the even poses and tested on the odd ones (and the other way) must keep this share
     * of its drop of the residual sum of squares on the poses it did not see: a line of the spectrum that is
     * a function of the joint angle predicts the poses between; power a structure in something else (the
     * order of the moves, time) leaks to one frequency of this pose set does not.
     */
    static final double HELD_OUT_SHARE = 0.5;
    /** χ²₁ at 0.95: fixing a refined peak at the nearest whole order may cost this much (in σ²). */
    static final double WHOLE_ORDER_CHI2 = 3.84;

    /** A stage frequency found on a joint: its order, and the sinusoid's sin and cos coefficients there (rad). */
    record Stage(int joint, double order, boolean whole, double refined, double p, double sinRad, double cosRad) { }

    /**
     * The line of the spectrum at a grid peak {@code gridF} of the error d·(a sin f q + b cos f q) in
     * residual r, when it holds: refined within one grid step, taken as a whole order where that costs
     * little, p from F(2, ν) and against the spectrum's continuum below {@code threshold}, and kept on
     * the poses it did not see ({@link #HELD_OUT_SHARE}); null otherwise.
     */
    static Stage line(int j, double[][] d, int rpp, double[][] q, double[] r, double gridF, double median, double step,
                      double fMax, int nu, double threshold) {
        double rss = 0;
        for (double v : r) rss += v * v;
        double f = refine(d, rpp, q, r, Math.max(1, gridF - step), Math.min(fMax, gridF + step));
        double[] at = fitAt(d, rpp, q, r, f);
        double whole = Math.max(1, Math.rint(f));
        double[] atWhole = fitAt(d, rpp, q, r, whole);
        double s2 = (rss - at[0]) / nu;
        // the spectrum's continuum (2 ln 2 σ² is white noise's median power)
        double continuum = median / (2 * Math.log(2));
        // below MIN_STAGE_ORDER a fraction of a cycle over the range is geometry's and the low harmonics' alias: whole
        boolean isWhole = f < MIN_STAGE_ORDER || (at[0] - atWhole[0]) < WHOLE_ORDER_CHI2 * s2;
        double refined = f;
        if (isWhole) { f = whole; at = atWhole; }
        double fStat = (at[0] / 2) / ((rss - at[0]) / nu);
        double p = Math.pow(1 + 2 * fStat / nu, -nu / 2.0);
        // against the spectrum's own continuum: a residual with structure the model lacks raises every
        // frequency's power (its median is 2 ln 2 σ² for white noise); a line must stand out of that
        if (continuum > s2) p = Math.max(p, Math.exp(-at[0] / (2 * continuum)));
        if (!(p < threshold)) return null;
        // held out: fitted on every other pose, the sinusoid must predict the poses between (both ways)
        if (heldOutDrop(d, rpp, q, r, f) < HELD_OUT_SHARE * at[0]) return null;
        return new Stage(j, f, isWhole, refined, p, at[1], at[2]);
    }

    private StageScan() { }

    /**
     * The highest order the readings of a joint can resolve: the reading's rounding step δ (deg,
     * from the file's decimals) moves the phase of order f by f·δ/√12 rms (uniform rounding); that must
     * stay below {@link #PHASE_LIMIT}. Above {@link #MAX_ORDER} the scan stops anyway (cost, and each
     * doubling of the range raises the false-alarm threshold by 2 ln 2 σ²).
     */
    static double maxOrder(double[] qDeg) {
        double step = readingStep(qDeg);
        double byPrecision = step > 0 ? PHASE_LIMIT * Math.sqrt(12) / Math.toRadians(step) : Double.POSITIVE_INFINITY;
        return Math.min(MAX_ORDER, byPrecision);
    }

    /** The rounding step of angle readings (deg): the coarsest power of ten all readings are multiples of, 0 when finer than 1e-9. */
    static double readingStep(double[] qDeg) {
        for (int d = 0; d <= 9; d++) {
            double scale = Math.pow(10, d);
            boolean all = true;
            for (double q : qDeg) {
                double x = q * scale;
                if (Math.abs(x - Math.rint(x)) > 1e-6) { all = false; break; }
            }
            if (all) return 1 / scale;
        }
        return 0;
    }

    /** The stages found in what the tester's model leaves. */
    static List<Stage> scan(Diagnoser.Tester t, double alpha) {
        int m = t.m, rpp = t.rpp, poses = m / rpp, ends = t.ends, dof = t.dof;
        List<Stage> out = new ArrayList<>();
        int nu = m - t.rank - 2;
        if (nu < 10 || poses < 20) return out;
        double[] r = t.rPerp.clone();
        double[][][] q = new double[dof][ends][poses];
        double[] fMax = new double[dof], span = new double[dof];
        double mTotal = 0;
        for (int j = 0; j < dof; j++) {
            if (t.w.model.isPrismatic(j)) continue;
            double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
            double[] deg = new double[ends * poses];
            for (int e = 0; e < ends; e++)
                for (int i = 0; i < poses; i++) {
                    double v = t.endRows.get(e).get(i).q(j);
                    q[j][e][i] = v;
                    deg[e * poses + i] = Math.toDegrees(v);
                    lo = Math.min(lo, v);
                    hi = Math.max(hi, v);
                }
            span[j] = (hi - lo) / (2 * Math.PI);
            if (!(span[j] > 1e-3)) continue;
            fMax[j] = maxOrder(deg);
            mTotal += (fMax[j] - 1) * span[j] + 1;
        }
        if (mTotal <= 0) return out;
        double thr = alpha / mTotal;
        for (int k = 0; k < MAX_STAGES; k++) {
            int bestJ = -1;
            double bestF = 0, bestP = 0, bestMedian = 0;
            for (int j = 0; j < dof; j++) {
                if (!(fMax[j] > 1)) continue;
                double[] peak = gridPeak(drive(t, j), t.rpp, q[j], r, 1, fMax[j], 1 / (OVERSAMPLE * span[j]));
                if (peak[1] > bestP) { bestP = peak[1]; bestF = peak[0]; bestJ = j; bestMedian = peak[2]; }
            }
            if (bestJ < 0) break;
            int j = bestJ;
            double[][] d = drive(t, j);
            Stage s = line(j, d, t.rpp, q[j], r, bestF, bestMedian, 1 / (OVERSAMPLE * span[j]), fMax[j], nu, thr);
            if (s == null) break;
            out.add(s);
            subtract(d, t.rpp, q[j], r, s.order(), s.sinRad(), s.cosRad());
        }
        return out;
    }

    /**
     * Orders of a play's change searched at most: an intermediate pinion or gear of the last stage
     * turning up to this many times per output turn (one with a few teeth driving a large output gear).
     */
    static final double MAX_PLAY_ORDER = 40;

    /**
     * The order at which a lost motion's play changes over the turn of its joint, where the residual
     * shows one: the scan of {@link #scan} for the error d_j·g·(a sin f q_j + b cos f q_j), g each
     * pose's lost-motion regressor (the lag's direction and built-up share), so only a change of the
     * play itself, seen with the lag's sign, can raise the power. An output gear running off its
     * centre changes the play once per turn; an eccentric pinion meshing with it z_gear/z_pinion
     * times per turn, an order that need not be whole. Same false-alarm control as the stage scan,
     * over the orders {@link #MIN_STAGE_ORDER}..{@link #MAX_PLAY_ORDER} of this joint alone; null when
     * no line holds. Below them a play's change cannot be told from gravity holding the gear on one
     * flank over part of the range (the gravity torque is a low-order function of the angles), nor
     * from the once-per-turn form of an output gear's runout.
     */
    static PlayLine playOrder(Diagnoser.Tester t, Effect lostMotion, double alpha) {
        int j = lostMotion.joint(), rpp = t.rpp, poses = t.m / rpp, nu = t.m - t.rank - 2;
        if (t.w.model.isPrismatic(j) || nu < 10 || poses < 20) return null;
        double[][] q = new double[t.ends][poses], d = drive(t, j);
        double[] g = new double[lostMotion.size()], deg = new double[t.ends * poses];
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
        for (int e = 0; e < t.ends; e++)
            for (int i = 0; i < poses; i++) {
                Measurement row = t.endRows.get(e).get(i);
                lostMotion.regressor(row, t.endConditions.get(e).get(i), g);
                for (int a = 0; a < rpp; a++) d[e][i * rpp + a] *= g[0];
                q[e][i] = row.q(j);
                deg[e * poses + i] = Math.toDegrees(q[e][i]);
                lo = Math.min(lo, q[e][i]);
                hi = Math.max(hi, q[e][i]);
            }
        double span = (hi - lo) / (2 * Math.PI), fMax = Math.min(MAX_PLAY_ORDER, maxOrder(deg));
        if (!(span > 1e-3) || !(fMax > MIN_STAGE_ORDER)) return null;
        double step = 1 / (OVERSAMPLE * span);
        double[] peak = gridPeak(d, rpp, q, t.rPerp, MIN_STAGE_ORDER, fMax, step);
        Stage s = line(j, d, rpp, q, t.rPerp, peak[0], peak[2], step, fMax, nu, alpha / ((fMax - MIN_STAGE_ORDER) * span + 1));
        return s == null || s.order() < MIN_STAGE_ORDER ? null : new PlayLine(s, step);
    }

    /** A play's line ({@link #playOrder}) and the scan's grid step there, cycles per turn: the order is known to about that. */
    record PlayLine(Stage stage, double step) { }

    /**
     * The locate probes of the stages found that the harmonic probes (whole orders 1..{@code hMax})
     * do not already hold.
     */
    static List<Locator.Probe> probes(Diagnoser.Tester t, List<Stage> stages, int hMax) {
        List<Locator.Probe> out = new ArrayList<>();
        for (Stage s : stages) {
            if (System.getenv("ROBOPRO_STAGES_DEBUG") != null) System.err.println("stage " + s);
            // a line above every harmonic the locate scan searches, whole or not, is a probe (a shaft's turn:
            // Effect.shaftOrders); below, the whole orders are the harmonic probes', and a bump in an angle has lines
            // at orders 4-16 that are not whole
            if (s.order() <= Math.max(hMax, Effect.SHAFT_ORDER)) continue;
            out.add(Locator.stageProbe(t, s.joint(), Effect.roundOrder(s.order())));
        }
        return out;
    }

    /** Words for order f of joint j (1-based in the text). */
    static String words(int joint, double order) {
        String f = Effect.orderText(order);
        return f + " cycles per turn of joint " + (joint + 1) + " (a stage turning " + f + " times per output turn)";
    }

    /** Each end's sensitivity of the residual rows to drive j (ends x rows): the weights d of a scan of joint j's error. */
    static double[][] drive(Diagnoser.Tester t, int j) {
        double[][] d = new double[t.ends][t.m];
        for (int e = 0; e < t.ends; e++)
            for (int row = 0; row < t.m; row++) d[e][row] = t.endDQ[e][row * t.dof + j];
        return d;
    }

    /**
     * Grid search of P(f) on [lo, hi] with step df for the error d·(a sin f q + b cos f q) (d per end
     * and row, rpp rows per pose, q per end and pose): {f, P} at the largest P, and the median P over the grid.
     */
    static double[] gridPeak(double[][] d, int rpp, double[][] q, double[] r, double lo, double hi, double df) {
        int ends = d.length, poses = q[0].length;
        // per end and pose: the current (sin, cos) of f q and the rotation by df q
        double[][] sn = new double[ends][poses], cs = new double[ends][poses], rs = new double[ends][poses], rc = new double[ends][poses];
        // one end: each pose's weight Σ d² and partial residual Σ r d (rows of a pose share its angle)
        double[] w = null, z = null;
        if (ends == 1) {
            w = new double[poses];
            z = new double[poses];
            for (int i = 0; i < poses; i++)
                for (int a = 0; a < rpp; a++) {
                    double v = d[0][i * rpp + a];
                    w[i] += v * v;
                    z[i] += v * r[i * rpp + a];
                }
        }
        int n = (int) Math.floor((hi - lo) / df) + 1;
        double bestF = lo, bestP = 0;
        double[] all = new double[n];
        for (int g = 0; g < n; g++) {
            double f = lo + g * df;
            if (g % 256 == 0) {
                for (int e = 0; e < ends; e++)
                    for (int i = 0; i < poses; i++) {
                        sn[e][i] = Math.sin(f * q[e][i]);
                        cs[e][i] = Math.cos(f * q[e][i]);
                        if (g == 0) { rs[e][i] = Math.sin(df * q[e][i]); rc[e][i] = Math.cos(df * q[e][i]); }
                    }
            }
            double sss = 0, scc = 0, ssc = 0, bs = 0, bc = 0;
            if (ends == 1) {
                double[] s0 = sn[0], c0 = cs[0];
                for (int i = 0; i < poses; i++) {
                    double s = s0[i], c = c0[i], wi = w[i], zi = z[i];
                    sss += wi * s * s;
                    scc += wi * c * c;
                    ssc += wi * s * c;
                    bs += zi * s;
                    bc += zi * c;
                }
            } else {
                for (int i = 0; i < poses; i++)
                    for (int a = 0; a < rpp; a++) {
                        int row = i * rpp + a;
                        double s = 0, c = 0;
                        for (int e = 0; e < ends; e++) { s += d[e][row] * sn[e][i]; c += d[e][row] * cs[e][i]; }
                        sss += s * s;
                        scc += c * c;
                        ssc += s * c;
                        bs += r[row] * s;
                        bc += r[row] * c;
                    }
            }
            double det = sss * scc - ssc * ssc;
            if (det > 1e-12 * (sss * scc) && det > 0) {
                double p = (scc * bs * bs - 2 * ssc * bs * bc + sss * bc * bc) / det;
                all[g] = p;
                if (p > bestP) { bestP = p; bestF = f; }
            }
            for (int e = 0; e < ends; e++) {
                double[] se = sn[e], ce = cs[e], rse = rs[e], rce = rc[e];
                for (int i = 0; i < poses; i++) {
                    double s = se[i], c = ce[i];
                    se[i] = s * rce[i] + c * rse[i];
                    ce[i] = c * rce[i] - s * rse[i];
                }
            }
        }
        // the median by selection (Commons Math's quickselect), not a sort of the whole grid
        double median = new org.apache.commons.math3.util.KthSelector().select(all, null, n / 2);
        return new double[] {bestF, bestP, median};
    }

    /** {P, a, b} at order f: the drop of the residual sum of squares and the sin, cos coefficients (rad). */
    static double[] fitAt(double[][] d, int rpp, double[][] q, double[] r, double f) {
        int ends = d.length, poses = q[0].length;
        double sss = 0, scc = 0, ssc = 0, bs = 0, bc = 0;
        for (int i = 0; i < poses; i++)
            for (int a = 0; a < rpp; a++) {
                int row = i * rpp + a;
                double s = 0, c = 0;
                for (int e = 0; e < ends; e++) {
                    double dv = d[e][row];
                    s += dv * Math.sin(f * q[e][i]);
                    c += dv * Math.cos(f * q[e][i]);
                }
                sss += s * s;
                scc += c * c;
                ssc += s * c;
                bs += r[row] * s;
                bc += r[row] * c;
            }
        double det = sss * scc - ssc * ssc;
        if (!(det > 0)) return new double[] {0, 0, 0};
        double a = (scc * bs - ssc * bc) / det, b = (sss * bc - ssc * bs) / det;
        return new double[] {a * bs + b * bc, a, b};
    }

    /** The drop of the residual sum of squares on each half of the poses from the sinusoid of order f fitted on the other half, summed. */
    static double heldOutDrop(double[][] d, int rpp, double[][] q, double[] r, double f) {
        int ends = d.length, poses = q[0].length;
        double[][] n = new double[2][5]; // per half: sss, scc, ssc, bs, bc
        double[] s = new double[poses * rpp], c = new double[poses * rpp];
        for (int i = 0; i < poses; i++)
            for (int a = 0; a < rpp; a++) {
                int row = i * rpp + a;
                for (int e = 0; e < ends; e++) {
                    double dv = d[e][row];
                    s[row] += dv * Math.sin(f * q[e][i]);
                    c[row] += dv * Math.cos(f * q[e][i]);
                }
                double[] h = n[i % 2];
                h[0] += s[row] * s[row];
                h[1] += c[row] * c[row];
                h[2] += s[row] * c[row];
                h[3] += r[row] * s[row];
                h[4] += r[row] * c[row];
            }
        double drop = 0;
        for (int half = 0; half < 2; half++) {
            double[] h = n[half];
            double det = h[0] * h[1] - h[2] * h[2];
            if (!(det > 0)) return 0;
            double a = (h[1] * h[3] - h[2] * h[4]) / det, b = (h[0] * h[4] - h[2] * h[3]) / det;
            for (int i = 1 - half; i < poses; i += 2)
                for (int x = 0; x < rpp; x++) {
                    int row = i * rpp + x;
                    double v = a * s[row] + b * c[row];
                    drop += r[row] * r[row] - (r[row] - v) * (r[row] - v);
                }
        }
        return drop;
    }

    /** Golden-section search of the largest P on [lo, hi]. */
    static double refine(double[][] d, int rpp, double[][] q, double[] r, double lo, double hi) {
        double g = (Math.sqrt(5) - 1) / 2;
        double a = lo, b = hi, x1 = b - g * (b - a), x2 = a + g * (b - a);
        double p1 = fitAt(d, rpp, q, r, x1)[0], p2 = fitAt(d, rpp, q, r, x2)[0];
        for (int it = 0; it < 40 && b - a > 1e-6; it++) {
            if (p1 > p2) { b = x2; x2 = x1; p2 = p1; x1 = b - g * (b - a); p1 = fitAt(d, rpp, q, r, x1)[0]; }
            else { a = x1; x1 = x2; p1 = p2; x2 = a + g * (b - a); p2 = fitAt(d, rpp, q, r, x2)[0]; }
        }
        return p1 > p2 ? x1 : x2;
    }

    /** r −= d_j (a sin f q + b cos f q). */
    private static void subtract(double[][] d, int rpp, double[][] q, double[] r, double f, double a, double b) {
        int ends = d.length, poses = q[0].length;
        for (int i = 0; i < poses; i++)
            for (int x = 0; x < rpp; x++) {
                int row = i * rpp + x;
                for (int e = 0; e < ends; e++)
                    r[row] -= d[e][row] * (a * Math.sin(f * q[e][i]) + b * Math.cos(f * q[e][i]));
            }
    }
}
