package org.robopro.calibration.identification;

import java.util.Arrays;
import java.util.List;
import java.util.function.ToDoubleFunction;

/**
 * Summary statistics of a set of error magnitudes, in the unit of the values (m or rad): count,
 * RMS, mean, median, 95th percentile and maximum. Percentiles interpolate linearly between
 * order statistics (Hyndman &amp; Fan type 7, the default of R, NumPy and spreadsheet PERCENTILE), so
 * they compare with figures from other tools. An empty set gives n = 0 and NaN everywhere.
 */
public record ErrorStats(int n, double rms, double mean, double median, double p95, double max) {

    public static final ErrorStats EMPTY = new ErrorStats(0, Double.NaN, Double.NaN, Double.NaN, Double.NaN, Double.NaN);

    /** Statistics of {@code values}; NaN values (no data for that pose) are skipped. */
    public static ErrorStats of(double[] values) {
        double[] v = Arrays.stream(values).filter(d -> !Double.isNaN(d)).sorted().toArray();
        int n = v.length;
        if (n == 0) return EMPTY;
        double s = 0, s2 = 0;
        for (double d : v) {
            s += d;
            s2 += d * d;
        }
        return new ErrorStats(n, Math.sqrt(s2 / n), s / n, quantile(v, 0.5), quantile(v, 0.95), v[n - 1]);
    }

    /** Statistics of one quantity of the non-outlier poses. */
    public static ErrorStats of(List<CalibrationResult.PoseError> es, ToDoubleFunction<CalibrationResult.PoseError> value) {
        return of(es.stream().filter(e -> !e.outlier()).mapToDouble(value).toArray());
    }

    /** Position errors of the non-outlier poses with the calibrated model (or the nominal one). */
    public static ErrorStats position(List<CalibrationResult.PoseError> es, boolean calibrated) {
        return of(es, calibrated ? CalibrationResult.PoseError::calibratedM : CalibrationResult.PoseError::nominalM);
    }

    /** Rotation errors of the non-outlier poses with the calibrated model (or the nominal one); EMPTY for position-only data. */
    public static ErrorStats rotation(List<CalibrationResult.PoseError> es, boolean calibrated) {
        return of(es, calibrated ? CalibrationResult.PoseError::calibratedRotRad : CalibrationResult.PoseError::nominalRotRad);
    }

    /** Quantile {@code p} of sorted values, type 7: h = (n-1)p, linear between the neighbouring order statistics. */
    static double quantile(double[] sorted, double p) {
        double h = (sorted.length - 1) * p;
        int lo = (int) Math.floor(h);
        int hi = Math.min(lo + 1, sorted.length - 1);
        return sorted[lo] + (h - lo) * (sorted[hi] - sorted[lo]);
    }

    /** The same statistics multiplied by {@code k} (unit conversion). */
    public ErrorStats scaled(double k) {
        return new ErrorStats(n, rms * k, mean * k, median * k, p95 * k, max * k);
    }
}
