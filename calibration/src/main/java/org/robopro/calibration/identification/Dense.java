package org.robopro.calibration.identification;

/** Small allocation-free dense linear algebra on row-major arrays, for the LM inner loop. */
final class Dense {
    private Dense() { }

    /** out (n x n, upper triangle and mirrored) = Jᵀ J with columns scaled by 1/scale. */
    static void normalMatrix(double[] j, int m, int n, double[] scale, double[] out) {
        java.util.Arrays.fill(out, 0, n * n, 0);
        for (int r = 0; r < m; r++) {
            int base = r * n;
            for (int a = 0; a < n; a++) {
                double ja = j[base + a];
                if (ja == 0) continue;
                int row = a * n;
                for (int b = a; b < n; b++) out[row + b] += ja * j[base + b];
            }
        }
        for (int a = 0; a < n; a++)
            for (int b = a; b < n; b++) {
                double v = out[a * n + b] / (scale[a] * scale[b]);
                out[a * n + b] = v;
                out[b * n + a] = v;
            }
    }

    /** out = Jᵀ r with entries scaled by 1/scale. */
    static void gradient(double[] j, double[] r, int m, int n, double[] scale, double[] out) {
        java.util.Arrays.fill(out, 0, n, 0);
        for (int k = 0; k < m; k++) {
            double rk = r[k];
            if (rk == 0) continue;
            int base = k * n;
            for (int a = 0; a < n; a++) out[a] += j[base + a] * rk;
        }
        for (int a = 0; a < n; a++) out[a] /= scale[a];
    }

    /** In-place Cholesky A = L Lᵀ (lower triangle written); false when A is not positive definite. */
    static boolean cholesky(double[] a, int n) {
        for (int i = 0; i < n; i++) {
            for (int k = 0; k <= i; k++) {
                double s = a[i * n + k];
                for (int p = 0; p < k; p++) s -= a[i * n + p] * a[k * n + p];
                if (i == k) {
                    if (!(s > 0)) return false;
                    a[i * n + i] = Math.sqrt(s);
                } else {
                    a[i * n + k] = s / a[k * n + k];
                }
            }
        }
        return true;
    }

    /** Solves L Lᵀ x = b in place (b becomes x) with the factor from {@link #cholesky}. */
    static void choleskySolve(double[] l, int n, double[] b) {
        for (int i = 0; i < n; i++) {
            double s = b[i];
            for (int p = 0; p < i; p++) s -= l[i * n + p] * b[p];
            b[i] = s / l[i * n + i];
        }
        for (int i = n - 1; i >= 0; i--) {
            double s = b[i];
            for (int p = i + 1; p < n; p++) s -= l[p * n + i] * b[p];
            b[i] = s / l[i * n + i];
        }
    }

    static double dot(double[] a, double[] b, int n) {
        double s = 0;
        for (int i = 0; i < n; i++) s += a[i] * b[i];
        return s;
    }
}
