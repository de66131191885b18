package org.robopro.app.workbench.model;

import java.util.Optional;
import org.robopro.kinematics.ConfData;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.JointDescription;
import org.robopro.models.JointType;
import org.robopro.models.RobotDescription;
import org.robopro.models.Vec3;

/**
 * Test reference for {@link RobotKinematics}: a second, independent formalism built directly from
 * the joint axes at the zero position (the seed paper's Fig. 7 inputs), sharing no FK or IK code with the
 * kinematics module.
 *
 * <p>Product of exponentials (Brockett): baseTlink_i(q) = exp(xi_1 theta_1) ... exp(xi_i theta_i)
 * applied to the link's zero pose, xi_j the joint's screw from its axis point and direction at
 * the zero position, theta = C q (coupling). IK by damped least squares from the seed.
 */
final class ScrewKinematics extends RobotKinematics {
    private final double[][] c;
    private final Pose flangeZero;

    ScrewKinematics(RobotDescription d) {
        super(d);
        c = d.couplingMatrix();
        flangeZero = Pose.fromFrame(d.flange());
    }

    @Override public String implementation() { return "built-in screw model"; }

    private double[] theta(double[] q) {
        int n = dof();
        double[] t = new double[n];
        for (int i = 0; i < n; i++) {
            double s = 0;
            for (int j = 0; j < n; j++) s += c[i][j] * q[j];
            t[i] = s;
        }
        return t;
    }

    private static Pose exp(JointDescription j, double theta) {
        if (j.type() == JointType.PRISMATIC) {
            Vec3 a = j.axis().normalized().times(theta);
            return Pose.translation(a);
        }
        Vec3 p = j.point();
        return Pose.translation(p).times(Pose.rotAxis(j.axis(), theta)).times(Pose.translation(p.times(-1)));
    }

    @Override
    public Pose[] linkDisplacements(double[] q) {
        double[] t = theta(q);
        Pose[] out = new Pose[dof() + 1];
        out[0] = Pose.IDENTITY;
        Pose acc = Pose.IDENTITY;
        for (int i = 0; i < dof(); i++) {
            acc = acc.times(exp(description.joints().get(i), t[i]));
            out[i + 1] = acc;
        }
        return out;
    }

    @Override
    public Pose flange(double[] q) {
        Pose[] d = linkDisplacements(q);
        return d[dof()].times(flangeZero);
    }

    @Override
    public Optional<double[]> solveNear(Pose target, double[] qSeed) {
        int n = dof();
        double[] q = qSeed.clone();
        double lambda = 1e-3, h = 1e-6;
        for (int iter = 0; iter < 200; iter++) {
            Pose cur = flange(q);
            double[] e = error(cur, target);
            double en = Math.sqrt(dot(e, e));
            if (en < 1e-9) return Optional.of(q);
            double[][] jac = new double[6][n];
            for (int k = 0; k < n; k++) {
                double[] qh = q.clone();
                qh[k] += h;
                double[] eh = error(flange(qh), cur);
                for (int r = 0; r < 6; r++) jac[r][k] = -eh[r] / h;
            }
            // (J^T J + lambda I) dq = J^T e
            double[][] a = new double[n][n + 1];
            for (int i = 0; i < n; i++) {
                for (int j = 0; j < n; j++) {
                    double s = 0;
                    for (int r = 0; r < 6; r++) s += jac[r][i] * jac[r][j];
                    a[i][j] = s + (i == j ? lambda : 0);
                }
                double s = 0;
                for (int r = 0; r < 6; r++) s += jac[r][i] * e[r];
                a[i][n] = s;
            }
            double[] dq = solve(a, n);
            for (int i = 0; i < n; i++) q[i] += dq[i];
        }
        double[] e = error(flange(q), target);
        return Math.sqrt(dot(e, e)) < 1e-6 ? Optional.of(q) : Optional.empty();
    }

    /** Pose error target - current as (dx, dy, dz, rotation vector), base frame. */
    private static double[] error(Pose cur, Pose target) {
        Vec3 w = cur.rotate(cur.inverse().times(target).rotationVector());
        return new double[] {target.x() - cur.x(), target.y() - cur.y(), target.z() - cur.z(), w.x(), w.y(), w.z()};
    }

    private static double dot(double[] a, double[] b) {
        double s = 0;
        for (int i = 0; i < a.length; i++) s += a[i] * b[i];
        return s;
    }

    private static double[] solve(double[][] a, int n) {
        for (int col = 0; col < n; col++) {
            int piv = col;
            for (int r = col + 1; r < n; r++) if (Math.abs(a[r][col]) > Math.abs(a[piv][col])) piv = r;
            double[] tmp = a[col]; a[col] = a[piv]; a[piv] = tmp;
            for (int r = col + 1; r < n; r++) {
                double f = a[r][col] / a[col][col];
                for (int k = col; k <= n; k++) a[r][k] -= f * a[col][k];
            }
        }
        double[] x = new double[n];
        for (int r = n - 1; r >= 0; r--) {
            double s = a[r][n];
            for (int k = r + 1; k < n; k++) s -= a[r][k] * x[k];
            x[r] = s / a[r][r];
        }
        return x;
    }

    @Override
    public Optional<KinematicModel> kinematicModel() { return Optional.empty(); }

    /** ABB quadrant convention: cf = floor(q / 90 deg) for axes 1, 4, 6; cfx from wrist/elbow signs. */
    @Override
    public ConfData confOf(double[] q) {
        int cf1 = (int) Math.floor(q[0] / (Math.PI / 2));
        int cf4 = q.length > 3 ? (int) Math.floor(q[3] / (Math.PI / 2)) : 0;
        int cf6 = q.length > 5 ? (int) Math.floor(q[5] / (Math.PI / 2)) : 0;
        int cfx = q.length > 4 && q[4] < 0 ? 1 : 0;
        return new ConfData(cf1, cf4, cf6, cfx);
    }
}
