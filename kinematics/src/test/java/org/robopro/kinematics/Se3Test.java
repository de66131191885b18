package org.robopro.kinematics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The fast array level against slow references written here from textbook formulas: the matrix
 * exponential as its power series, the logarithm through the quaternion (θ = 2 atan2(|v|, w)),
 * and the left Jacobian inverse by finite differences.
 */
class Se3Test {

    // ------------------------------------------------------------------ references

    /** Exp([w]×) as the power series Σ Kⁿ/n!, summed until the terms vanish. */
    static double[] expSeries(double wx, double wy, double wz) {
        double[] k = {0, -wz, wy, wz, 0, -wx, -wy, wx, 0};
        double[] sum = {1, 0, 0, 0, 1, 0, 0, 0, 1}, term = sum.clone();
        for (int n = 1; n < 60; n++) {
            double[] next = new double[9];
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                    for (int l = 0; l < 3; l++) next[3 * i + j] += term[3 * i + l] * k[3 * l + j] / n;
            term = next;
            for (int u = 0; u < 9; u++) sum[u] += term[u];
        }
        return sum;
    }

    /** Rotation vector from the quaternion (w, v): angle 2 atan2(|v|, w), axis v / |v|. */
    static double[] logViaQuaternion(double qw, double qx, double qy, double qz) {
        if (qw < 0) { qw = -qw; qx = -qx; qy = -qy; qz = -qz; }
        double nv = Math.sqrt(qx * qx + qy * qy + qz * qz);
        if (nv == 0) return new double[3];
        double th = 2 * Math.atan2(nv, qw);
        return new double[] {th * qx / nv, th * qy / nv, th * qz / nv};
    }

    /** Rotation of a unit quaternion, written out independently of the class under test. */
    static double[] matrixOf(double w, double x, double y, double z) {
        return new double[] {
                w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y),
                2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x),
                2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z};
    }

    static double[] randomUnitAxis(Random r) {
        double x = r.nextGaussian(), y = r.nextGaussian(), z = r.nextGaussian(), n = Math.sqrt(x * x + y * y + z * z);
        return new double[] {x / n, y / n, z / n};
    }

    // ------------------------------------------------------------------ tests

    @Test
    void rotExp_randomVectors_matchesPowerSeries() {
        Random r = new Random(1);
        double[] m = new double[9];
        for (int i = 0; i < 200; i++) {
            double[] a = randomUnitAxis(r);
            double th = i < 20 ? Math.pow(10, -i / 2.0) : r.nextDouble() * Math.PI;
            Se3.rotExp(a[0] * th, a[1] * th, a[2] * th, m);
            double[] ref = expSeries(a[0] * th, a[1] * th, a[2] * th);
            for (int u = 0; u < 9; u++) assertEquals(ref[u], m[u], 1e-14, "entry " + u + " at angle " + th);
        }
    }

    @Test
    void rotLog_allAnglesIncludingNear180_matchesQuaternionReference() {
        Random r = new Random(2);
        double[] w = new double[3];
        for (int i = 0; i < 400; i++) {
            double[] a = randomUnitAxis(r);
            double th;
            if (i < 16) th = Math.PI - Math.pow(10, -i);          // down to 180° - 1e-15 rad
            else if (i < 32) th = Math.pow(10, -(i - 16));        // down to 1e-15 rad
            else if (i == 32) th = Math.PI;
            else th = r.nextDouble() * Math.PI;
            double qw = Math.cos(th / 2), s = Math.sin(th / 2);
            double[] m = matrixOf(qw, a[0] * s, a[1] * s, a[2] * s);
            Se3.rotLog(m, w, 0);
            double[] ref = logViaQuaternion(qw, a[0] * s, a[1] * s, a[2] * s);
            double normW = Math.sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
            assertEquals(th, normW, 1e-13, "angle at " + th);
            if (Math.PI - th < 1e-13) {
                // At 180° w and -w are the same rotation: compare the rotation they give back.
                double[] back = new double[9];
                Se3.rotExp(w[0], w[1], w[2], back);
                for (int u = 0; u < 9; u++) assertEquals(m[u], back[u], 1e-13);
            } else {
                for (int k = 0; k < 3; k++) assertEquals(ref[k], w[k], 1e-13, "component " + k + " at angle " + th);
            }
        }
    }

    @Test
    void rotQuaternion_roundTrip_scalarNonNegative() {
        Random r = new Random(3);
        double[] m = new double[9], q = new double[4], back = new double[9];
        for (int i = 0; i < 200; i++) {
            double[] a = randomUnitAxis(r);
            double th = i == 0 ? Math.PI : r.nextDouble() * 2 * Math.PI;
            Se3.rotExp(a[0] * th, a[1] * th, a[2] * th, m);
            Se3.rotQuaternion(m, q, 0);
            assertTrue(q[0] >= 0);
            assertEquals(1, Math.sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]), 1e-15);
            double[] ref = matrixOf(q[0], q[1], q[2], q[3]);
            Se3.rotFromQuaternion(q[0], q[1], q[2], q[3], back);
            for (int u = 0; u < 9; u++) {
                assertEquals(m[u], ref[u], 1e-14);
                assertEquals(m[u], back[u], 1e-14);
            }
        }
        assertThrows(IllegalArgumentException.class, () -> Se3.rotFromQuaternion(0, 0, 0, 0, back));
    }

    @Test
    void rotLeftJacobianInverse_matchesFiniteDifferencesOfLeftCompose() {
        Random r = new Random(4);
        double[] j = new double[9], base = new double[3], plus = new double[3], minus = new double[3], work = new double[27];
        double h = 1e-6;
        for (int i = 0; i < 50; i++) {
            double[] a = randomUnitAxis(r);
            double th = i == 0 ? 1e-9 : r.nextDouble() * 3;
            double[] e = {a[0] * th, a[1] * th, a[2] * th};
            Se3.rotLeftJacobianInverse(e, j);
            for (int c = 0; c < 3; c++) {
                double[] d = new double[3];
                d[c] = h;
                Se3.rotLeftCompose(e, 0, d, 0, plus, 0, work);
                d[c] = -h;
                Se3.rotLeftCompose(e, 0, d, 0, minus, 0, work);
                for (int row = 0; row < 3; row++)
                    assertEquals((plus[row] - minus[row]) / (2 * h), j[3 * row + c], 1e-7, "J(" + row + "," + c + ") at " + th);
            }
            Se3.rotLeftCompose(e, 0, new double[3], 0, base, 0, work);
            for (int k = 0; k < 3; k++) assertEquals(e[k], base[k], 1e-14);
        }
    }

    @Test
    void transforms_mulAndRotationLogBetween_agreeWithPose() {
        Random r = new Random(5);
        double[] a = new double[12], b = new double[12], ab = new double[12], w = new double[4], q = new double[4];
        for (int i = 0; i < 100; i++) {
            Pose pa = Pose.rotAxis(new org.robopro.models.Vec3(r.nextGaussian(), r.nextGaussian(), r.nextGaussian()), r.nextDouble() * 3)
                    .times(Pose.translation(r.nextGaussian(), r.nextGaussian(), r.nextGaussian()));
            Pose pb = Pose.rotAxis(new org.robopro.models.Vec3(r.nextGaussian(), r.nextGaussian(), r.nextGaussian()),
                    i == 0 ? Math.PI : r.nextDouble() * 3).times(Pose.translation(r.nextGaussian(), 0, 1));
            Se3.fromPose(pa, a);
            Se3.fromPose(pb, b);
            Se3.mul(a, b, ab);
            Pose pab = pa.times(pb);
            assertEquals(0, Se3.toPose(ab).distanceTo(pab), 1e-14);
            assertEquals(0, Se3.toPose(ab).angleTo(pab), 1e-14);
            double[] mi = a.clone();
            Se3.mulInPlace(mi, b);
            for (int u = 0; u < 12; u++) assertEquals(ab[u], mi[u], 1e-15);
            // Log(R_a R_bᵀ) against the quaternion reference of the product.
            Se3.rotationLogBetween(a, b, w, 1);
            double[] qq = pa.times(Pose.of(pb.rotationRowMajor(), 0, 0, 0).inverse()).quaternion();
            double[] ref = logViaQuaternion(qq[0], qq[1], qq[2], qq[3]);
            if (Math.PI - Math.sqrt(ref[0] * ref[0] + ref[1] * ref[1] + ref[2] * ref[2]) > 1e-6)
                for (int k = 0; k < 3; k++) assertEquals(ref[k], w[1 + k], 1e-12);
            Se3.quaternion(ab, q, 0);
            double[] pq = pab.quaternion();
            for (int k = 0; k < 4; k++) assertEquals(pq[k], q[k], 1e-14);
            double[] p = {0.1, 0.2, 0.3}, m = new double[12];
            Se3.fromQuaternion(pq, p, m);
            assertEquals(0, Se3.toPose(m).angleTo(pab), 1e-12);
            assertEquals(0.2, m[7]);
        }
    }

    @Test
    void rotate_badAxis_throwsNamingIt() {
        double[] m = new double[12];
        Se3.identity(m);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Se3.rotate(m, 3, 1, 0));
        assertTrue(e.getMessage().contains("3"), e.getMessage());
    }
}
