package org.robopro.calibration.diagnosis;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.robopro.calibration.PoseConditions;
import org.robopro.calibration.measurement.Measurement;

/** Evidence plot data for a finding (see {@link Diagnosis.Plot}). */
final class Plots {
    private Plots() { }

    /**
     * Partial residuals: per pose, the effect's own value plus the final residual resolved along
     * the effect's signature, y_i = g_i·v − d_iᵀ r_i / ‖d_i‖² (r = predicted − measured) (d_i: the pose's residual rows'
     * sensitivity to the effect's Δθ or strain). Poses where the measured point barely moves
     * with the effect (‖d_i‖ below 0.3 x the median) are left out: they carry no information.
     * Angles in millidegrees, strains in ppm.
     */
    static Diagnosis.Plot partialResidual(Diagnoser.Tester t, Effect e, double[] v) {
        int rpp = t.rpp, poses = t.m / rpp, dof = t.dof;
        double[] dn = new double[poses];
        for (int i = 0; i < poses; i++) {
            double s = 0;
            for (int a = 0; a < 3; a++) {
                double d = e.isStrain() ? t.dStrain[i * rpp + a] : t.dTheta[(i * rpp + a) * dof + e.joint()];
                s += d * d;
            }
            dn[i] = s;
        }
        double[] sorted = dn.clone();
        Arrays.sort(sorted);
        double cut = 0.09 * sorted[poses / 2];
        double unit = e.isStrain() ? 1e6 : Math.toDegrees(1) * 1e3;
        List<double[]> pts = new ArrayList<>();
        for (int i = 0; i < poses; i++) {
            if (!(dn[i] > cut) || dn[i] == 0) continue;
            Measurement row = t.w.rows.get(i);
            PoseConditions c = t.w.conditions.get(i);
            double proj = 0;
            for (int a = 0; a < 3; a++) {
                double d = e.isStrain() ? t.dStrain[i * rpp + a] : t.dTheta[(i * rpp + a) * dof + e.joint()];
                proj += d * t.fit.r[i * rpp + a];
            }
            double y = e.value(v, row.q(), c) - proj / dn[i]; // residual is predicted - measured
            double x = xOf(e, row, c);
            if (e.kind() == Effect.Kind.BACKLASH) x += 0.3 * (((i * 0.6180339887) % 1) - 0.5); // spread the two columns of points
            pts.add(new double[] {x, y * unit});
        }
        double[] x = new double[pts.size()], y = new double[pts.size()];
        for (int i = 0; i < x.length; i++) { x[i] = pts.get(i)[0]; y[i] = pts.get(i)[1]; }
        double lo = Arrays.stream(x).min().orElse(0), hi = Arrays.stream(x).max().orElse(1);
        int nc = e.kind() == Effect.Kind.PERIODIC ? 200 : 2;
        double[] cx = new double[nc], cy = new double[nc];
        for (int i = 0; i < nc; i++) {
            cx[i] = lo + (hi - lo) * i / (nc - 1);
            cy[i] = curve(e, v, cx[i]) * unit;
        }
        double[] gram = null;
        if (e.kind() == Effect.Kind.PERIODIC) gram = periodogram(x, y, 8);
        return new Diagnosis.Plot(xLabel(e), e.isStrain() ? "partial residual strain (ppm)"
                : "partial residual of joint " + (e.joint() + 1) + " angle (mdeg)", x, y, cx, cy, gram);
    }

    static String xLabel(Effect e) {
        return switch (e.kind()) {
            case COMPLIANCE -> "gravity torque about joint " + (e.joint() + 1) + " (N·m)";
            case PERIODIC, SCALE -> "joint " + (e.joint() + 1) + " angle q" + (e.joint() + 1) + " (deg)";
            case BACKLASH -> "approach direction dir" + (e.joint() + 1);
            case THERMAL -> e.usesTimeProxy() ? "time since start (s)" : "temperature (°C)";
            case COUPLING -> "joint " + (e.source() + 1) + " angle q" + (e.source() + 1) + " (deg)";
        };
    }

    private static double xOf(Effect e, Measurement row, PoseConditions c) {
        return switch (e.kind()) {
            case COMPLIANCE -> e.gravity().torques(row.q(), c.payloadKg())[e.joint()];
            case PERIODIC, SCALE -> Math.toDegrees(row.q(e.joint()));
            case BACKLASH -> c.direction(e.joint());
            case THERMAL -> e.usesTimeProxy() ? c.timeS() : c.tempC();
            case COUPLING -> Math.toDegrees(row.q(e.source()));
        };
    }

    /** The fitted effect (rad or strain) as a function of the plot's x. */
    private static double curve(Effect e, double[] v, double x) {
        return switch (e.kind()) {
            case COMPLIANCE -> v[0] * x;
            case PERIODIC -> {
                double q = Math.toRadians(x), s = 0;
                for (int h = 1; h <= Effect.HARMONICS; h++) s += v[2 * h - 2] * Math.sin(h * q) + v[2 * h - 1] * Math.cos(h * q);
                yield s;
            }
            case BACKLASH -> -0.5 * v[0] * x; // output lags: θ − q = −(b/2)·dir
            case THERMAL -> e.usesTimeProxy() ? v[0] * (1 - Math.exp(-x / e.tauS())) : v[0] * (x - e.t0C());
            case SCALE, COUPLING -> v[0] * Math.toRadians(x);
        };
    }

    /** Amplitude of harmonics 1..n of y against the angle x (deg), each fitted alone with a constant. */
    static double[] periodogram(double[] xDeg, double[] y, int n) {
        double[] out = new double[n];
        for (int h = 1; h <= n; h++) {
            double[] a = new double[9], b = new double[3];
            for (int i = 0; i < y.length; i++) {
                double q = Math.toRadians(xDeg[i]);
                double[] f = {Math.sin(h * q), Math.cos(h * q), 1};
                for (int r = 0; r < 3; r++) {
                    b[r] += f[r] * y[i];
                    for (int c = 0; c < 3; c++) a[3 * r + c] += f[r] * f[c];
                }
            }
            out[h - 1] = Diagnoser.solve(a, b, 3) ? Math.hypot(b[0], b[1]) : 0;
        }
        return out;
    }
}
