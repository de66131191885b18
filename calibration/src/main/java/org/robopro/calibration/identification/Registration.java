package org.robopro.calibration.identification;

import java.util.List;
import org.ejml.data.DMatrixRMaj;
import org.ejml.dense.row.CommonOps_DDRM;
import org.ejml.dense.row.factory.DecompositionFactory_DDRM;
import org.ejml.interfaces.decomposition.SingularValueDecomposition_F64;
import org.robopro.kinematics.Pose;
import org.robopro.models.Vec3;

/**
 * Rigid registration of point sets (Kabsch 1976 / Umeyama 1991 without scale): the pose T that
 * minimises Σ‖T a_i − b_i‖², used to start the instrument frame from nominal predictions.
 */
public final class Registration {
    private Registration() { }

    /** bTa: the transform taking points given in frame a to frame b. Needs >= 3 non-collinear points. */
    public static Pose rigid(List<Vec3> a, List<Vec3> b) {
        int n = a.size();
        if (n != b.size() || n < 3) throw new IllegalArgumentException("need >= 3 point pairs, got " + n + " and " + b.size());
        Vec3 ca = centroid(a), cb = centroid(b);
        DMatrixRMaj h = new DMatrixRMaj(3, 3);
        for (int i = 0; i < n; i++) {
            Vec3 p = a.get(i).minus(ca), q = b.get(i).minus(cb);
            double[] pa = p.toArray(), qa = q.toArray();
            for (int r = 0; r < 3; r++) for (int c = 0; c < 3; c++) h.add(r, c, pa[r] * qa[c]);
        }
        SingularValueDecomposition_F64<DMatrixRMaj> svd = DecompositionFactory_DDRM.svd(3, 3, true, true, false);
        if (!svd.decompose(h)) throw new IllegalStateException("SVD failed");
        DMatrixRMaj u = svd.getU(null, false), v = svd.getV(null, false);
        DMatrixRMaj r = new DMatrixRMaj(3, 3);
        CommonOps_DDRM.multTransB(v, u, r);
        if (CommonOps_DDRM.det(r) < 0) {
            // Reflection: flip the axis of the smallest singular value.
            double[] s = svd.getSingularValues();
            int k = 0;
            for (int i = 1; i < 3; i++) if (s[i] < s[k]) k = i;
            for (int i = 0; i < 3; i++) v.set(i, k, -v.get(i, k));
            CommonOps_DDRM.multTransB(v, u, r);
        }
        double[] rm = r.data.clone();
        double[] rc = {rm[0] * ca.x() + rm[1] * ca.y() + rm[2] * ca.z(), rm[3] * ca.x() + rm[4] * ca.y() + rm[5] * ca.z(),
                rm[6] * ca.x() + rm[7] * ca.y() + rm[8] * ca.z()};
        return IdentificationProblem.poseOf(rm, new double[] {cb.x() - rc[0], cb.y() - rc[1], cb.z() - rc[2]});
    }

    /**
     * Rigid registration that trims points far from the rest: fit, drop the points whose residual
     * exceeds {@code max(4 x median residual, 1 mm)}, refit, until the kept set no longer
     * changes (at most 10 fits). A single wild point cannot tilt the result. {@code keep} (one
     * entry per point) receives the points used for the returned pose.
     */
    public static Pose trimmed(List<Vec3> a, List<Vec3> b, boolean[] keep) {
        int n = a.size();
        java.util.Arrays.fill(keep, true);
        Pose t = rigid(a, b);
        for (int round = 0; round < 10; round++) {
            double[] res = new double[n];
            for (int i = 0; i < n; i++) res[i] = t.apply(a.get(i)).minus(b.get(i)).norm();
            double[] sorted = res.clone();
            java.util.Arrays.sort(sorted);
            double limit = Math.max(4 * sorted[n / 2], 1e-3);
            boolean changed = false;
            List<Vec3> ka = new java.util.ArrayList<>(), kb = new java.util.ArrayList<>();
            for (int i = 0; i < n; i++) {
                boolean k = res[i] <= limit;
                changed |= k != keep[i];
                keep[i] = k;
                if (k) { ka.add(a.get(i)); kb.add(b.get(i)); }
            }
            if (!changed || ka.size() < 3) break;
            t = rigid(ka, kb);
        }
        return t;
    }

    /** The singular values (descending) of the centred point cloud: how well it spans 3-D, m. */
    public static double[] spread(List<Vec3> pts) {
        for (Vec3 p : pts)
            if (!Double.isFinite(p.x() * p.x() + p.y() * p.y() + p.z() * p.z()))
                throw new IllegalArgumentException("point " + p + " is not finite (or its square overflows)");
        Vec3 c = centroid(pts);
        DMatrixRMaj m = new DMatrixRMaj(3, 3);
        for (Vec3 p : pts) {
            double[] d = p.minus(c).toArray();
            for (int r = 0; r < 3; r++) for (int k = 0; k < 3; k++) m.add(r, k, d[r] * d[k]);
        }
        SingularValueDecomposition_F64<DMatrixRMaj> svd = DecompositionFactory_DDRM.svd(3, 3, false, false, false);
        if (!svd.decompose(m)) throw new IllegalStateException("SVD failed");
        double[] s = svd.getSingularValues().clone();
        java.util.Arrays.sort(s);
        return new double[] {Math.sqrt(s[2] / pts.size()), Math.sqrt(s[1] / pts.size()), Math.sqrt(Math.max(0, s[0]) / pts.size())};
    }

    static Vec3 centroid(List<Vec3> pts) {
        double x = 0, y = 0, z = 0;
        for (Vec3 p : pts) { x += p.x(); y += p.y(); z += p.z(); }
        int n = pts.size();
        return new Vec3(x / n, y / n, z / n);
    }
}
