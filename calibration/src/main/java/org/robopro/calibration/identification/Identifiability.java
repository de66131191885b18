package org.robopro.calibration.identification;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.ejml.data.DMatrixRMaj;
import org.ejml.dense.row.factory.DecompositionFactory_DDRM;
import org.ejml.interfaces.decomposition.QRDecomposition;
import org.ejml.interfaces.decomposition.SingularValueDecomposition_F64;

/**
 * Which parameters a set of measurements can determine. From the SVD of the column-scaled
 * identification Jacobian: a singular value below {@code tolerance} times the largest marks a
 * direction in parameter space the data cannot see; its right singular vector names the
 * parameters that move together. Rule for what to fix: in the weakest such direction, the
 * parameter with the largest component times its block's fix priority (robot geometry 1,
 * measured point 0.5, instrument frame 0.25, so the genuinely unknown frames stay free and the
 * robot keeps its nominal value); fix it, repeat until the rest has full rank.
 * Reports the condition number and the observability index O1 = (s1···sL)^(1/L)/√poses
 * (Borm &amp; Menq 1991) of what stays free.
 */
public final class Identifiability {
    /** Default relative singular-value threshold; structural redundancies sit at ~1e-13. */
    public static final double DEFAULT_TOLERANCE = 1e-8;

    /**
     * One direction the data cannot see.
     *
     * @param fixed       name of the parameter fixed for it
     * @param combination the direction: parameter name to component (largest first, small ones dropped)
     * @param ratio       its singular value over the largest
     */
    public record Direction(String fixed, Map<String, Double> combination, double ratio) {
        /** E.g. "p1.rz ≈ -0.71·instrument.rz" style text: "0.71 p1.rz - 0.71 instrument.rz". */
        public String describe() {
            StringBuilder sb = new StringBuilder();
            for (var e : combination.entrySet()) {
                double v = e.getValue();
                if (sb.length() > 0) sb.append(v < 0 ? " - " : " + ");
                else if (v < 0) sb.append('-');
                sb.append(String.format(Locale.ROOT, "%.2f %s", Math.abs(v), e.getKey()));
            }
            return sb.toString();
        }
    }

    /**
     * @param free            indices of the parameters left free, ascending
     * @param fixed           indices fixed, in the order chosen
     * @param directions      one per fixed parameter
     * @param singularValues  of the scaled Jacobian restricted to the free parameters, descending
     * @param conditionNumber s1 / sL of the free part
     * @param observability   O1 of the free part
     */
    public record Result(int[] free, int[] fixed, List<Direction> directions, double[] singularValues,
                         double conditionNumber, double observability) { }

    private Identifiability() { }

    /**
     * Analyses a Jacobian (row-major, m x n). {@code priority[j]} weighs how willingly parameter j
     * is fixed; {@code preFixed} are never free (e.g. fixed by the user); {@code poses} counts
     * the measured poses for O1.
     */
    public static Result analyze(double[] jac, int m, int n, List<String> names, double[] priority,
                                 boolean[] preFixed, int poses, double tolerance) {
        double[] colNorm = new double[n];
        for (int i = 0; i < m; i++)
            for (int j = 0; j < n; j++) colNorm[j] += jac[i * n + j] * jac[i * n + j];
        double maxNorm = 0;
        for (int j = 0; j < n; j++) { colNorm[j] = Math.sqrt(colNorm[j]); maxNorm = Math.max(maxNorm, colNorm[j]); }
        List<Integer> free = new ArrayList<>();
        List<Integer> fixed = new ArrayList<>();
        List<Direction> dirs = new ArrayList<>();
        for (int j = 0; j < n; j++) {
            if (preFixed != null && preFixed[j]) continue;
            if (!(colNorm[j] > 1e-14 * Math.max(maxNorm, 1e-300))) {
                fixed.add(j);
                dirs.add(new Direction(names.get(j), Map.of(names.get(j), 1.0), 0));
            } else free.add(j);
        }
        // Reduce to the n x n triangle once: J = QR has the singular values of R, column by column.
        int nf = free.size();
        DMatrixRMaj a = new DMatrixRMaj(m, nf);
        for (int i = 0; i < m; i++)
            for (int k = 0; k < nf; k++) a.set(i, k, jac[i * n + free.get(k)] / colNorm[free.get(k)]);
        DMatrixRMaj rMat;
        if (m > nf && nf > 0) {
            QRDecomposition<DMatrixRMaj> qr = DecompositionFactory_DDRM.qr(m, nf);
            if (!qr.decompose(a)) throw new IllegalStateException("QR failed");
            rMat = qr.getR(null, true);
        } else rMat = a;
        List<Integer> cols = new ArrayList<>(); // columns of rMat still free
        for (int k = 0; k < nf; k++) cols.add(k);
        double[] sv = new double[0];
        while (!cols.isEmpty()) {
            DMatrixRMaj sub = new DMatrixRMaj(rMat.numRows, cols.size());
            for (int i = 0; i < rMat.numRows; i++)
                for (int k = 0; k < cols.size(); k++) sub.set(i, k, rMat.get(i, cols.get(k)));
            SingularValueDecomposition_F64<DMatrixRMaj> svd =
                    DecompositionFactory_DDRM.svd(sub.numRows, sub.numCols, false, true, false);
            if (!svd.decompose(sub)) throw new IllegalStateException("SVD failed");
            double[] s = Arrays.copyOf(svd.getSingularValues(), svd.numberOfSingularValues());
            DMatrixRMaj v = svd.getV(null, false);
            int kMin = 0;
            double sMax = 0;
            for (int k = 0; k < s.length; k++) {
                if (s[k] < s[kMin]) kMin = k;
                sMax = Math.max(sMax, s[k]);
            }
            boolean deficient = s.length < cols.size() || s[kMin] < tolerance * sMax;
            if (!deficient) {
                sv = s;
                break;
            }
            double[] dir = new double[cols.size()];
            if (s.length < cols.size()) {
                // More columns than rows: a null vector of sub exists but the compact SVD omits it;
                // use the first column of the full V beyond the rank.
                SingularValueDecomposition_F64<DMatrixRMaj> full =
                        DecompositionFactory_DDRM.svd(sub.numRows, sub.numCols, false, true, false);
                full.decompose(sub.copy());
                DMatrixRMaj vf = full.getV(null, false);
                int col = Math.min(vf.numCols - 1, s.length);
                for (int k = 0; k < dir.length; k++) dir[k] = vf.get(k, col);
            } else for (int k = 0; k < dir.length; k++) dir[k] = v.get(k, kMin);
            int pick = -1;
            double best = -1, maxComp = 0;
            for (int k = 0; k < dir.length; k++) {
                int j = free.get(cols.get(k));
                double score = Math.abs(dir[k]) * (priority == null ? 1 : priority[j]);
                if (score > best + 1e-9) { best = score; pick = k; }
                maxComp = Math.max(maxComp, Math.abs(dir[k]));
            }
            // Name the direction by its significant components, largest first.
            Integer[] order = new Integer[dir.length];
            for (int k = 0; k < dir.length; k++) order[k] = k;
            final double[] d = dir;
            Arrays.sort(order, (p, q) -> Double.compare(Math.abs(d[q]), Math.abs(d[p])));
            double sign = Math.signum(dir[pick]) == 0 ? 1 : Math.signum(dir[pick]);
            Map<String, Double> combo = new LinkedHashMap<>();
            for (int k : order) {
                if (Math.abs(dir[k]) < 0.1 * maxComp || combo.size() >= 6) break;
                combo.put(names.get(free.get(cols.get(k))), sign * dir[k]);
            }
            int j = free.get(cols.get(pick));
            fixed.add(j);
            double ratio = s.length < cols.size() ? 0 : s[kMin] / sMax;
            dirs.add(new Direction(names.get(j), combo, ratio));
            cols.remove(pick);
        }
        int[] freeIdx = new int[cols.size()];
        for (int k = 0; k < cols.size(); k++) freeIdx[k] = free.get(cols.get(k));
        Arrays.sort(freeIdx);
        double[] sDesc = sv.clone();
        Arrays.sort(sDesc);
        for (int i = 0; i < sDesc.length / 2; i++) {
            double t = sDesc[i]; sDesc[i] = sDesc[sDesc.length - 1 - i]; sDesc[sDesc.length - 1 - i] = t;
        }
        double cond = sDesc.length == 0 ? Double.NaN : sDesc[0] / sDesc[sDesc.length - 1];
        double logSum = 0;
        for (double s : sDesc) logSum += Math.log(s);
        double o1 = sDesc.length == 0 ? 0 : Math.exp(logSum / sDesc.length) / Math.sqrt(Math.max(poses, 1));
        return new Result(freeIdx, fixed.stream().mapToInt(Integer::intValue).toArray(), dirs, sDesc, cond, o1);
    }
}
