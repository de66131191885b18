package org.robopro.calibration.identification;

import java.util.List;
import org.ejml.data.DMatrixRMaj;
import org.ejml.dense.row.CommonOps_DDRM;
import org.ejml.dense.row.factory.DecompositionFactory_DDRM;
import org.ejml.interfaces.decomposition.SingularValueDecomposition_F64;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.kinematics.KinematicModel;
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
    /**
     * Where each measured point sits on the flange, seen through a starting instrument frame:
     * the flange coordinates T_bf(q)⁻¹ · instrumentTbase⁻¹ · p_k averaged over the poses (those
     * in {@code skip} left out); the start of a fit with several points per pose.
     */
    static List<Vec3> toolPoints(KinematicModel nominal, List<Measurement> rows, Pose instrumentTbase, java.util.Set<String> skip) {
        int pts = rows.get(0).points().size();
        Pose baseTinst = instrumentTbase == null ? Pose.IDENTITY : instrumentTbase.inverse();
        double[][] sum = new double[pts][3];
        int n = 0;
        for (Measurement m : rows) {
            if (skip.contains(m.poseId())) continue;
            Pose fb = nominal.flange(m.q()).inverse();
            for (int k = 0; k < pts; k++) {
                Vec3 f = fb.apply(baseTinst.apply(m.point(k)));
                sum[k][0] += f.x(); sum[k][1] += f.y(); sum[k][2] += f.z();
            }
            n++;
        }
        List<Vec3> out = new java.util.ArrayList<>();
        for (int k = 0; k < pts; k++) out.add(new Vec3(sum[k][0] / n, sum[k][1] / n, sum[k][2] / n));
        return out;
    }

    /**
     * The anchor of distance rows by linear multilateration on the nominal predictions of the
     * measured point p_i: |p_i − a|² = d_i² gives 2 p_iᵀa − c = |p_i|² − d_i² with c = |a|²,
     * linear in (a, c); least squares over the poses. A start for the fit, not its result.
     */
    static Vec3 multilaterate(KinematicModel nominal, List<Measurement> rows, Vec3 toolPoint, String source) {
        double[] ata = new double[16], atb = new double[4];
        for (Measurement m : rows) {
            Vec3 p = nominal.flange(m.q()).apply(toolPoint);
            double[] a = {2 * p.x(), 2 * p.y(), 2 * p.z(), -1};
            double b = p.dot(p) - m.distance() * m.distance();
            for (int r = 0; r < 4; r++) {
                atb[r] += a[r] * b;
                for (int c = 0; c < 4; c++) ata[4 * r + c] += a[r] * a[c];
            }
        }
        double[] scale = new double[4];
        for (int r = 0; r < 4; r++) scale[r] = Math.sqrt(Math.max(ata[5 * r], 1e-300));
        for (int r = 0; r < 4; r++) {
            atb[r] /= scale[r];
            for (int c = 0; c < 4; c++) ata[4 * r + c] /= scale[r] * scale[c];
        }
        double[] l = ata.clone();
        boolean ok = rows.size() >= 4 && Dense.cholesky(l, 4);
        if (ok) {
            // Condition of the scaled system: a pivot near zero means the points lie (nearly) on a plane.
            for (int r = 0; r < 4; r++) ok &= l[5 * r] > 1e-6;
        }
        if (!ok)
            throw new org.robopro.models.InputException(source, 0, 0, "distance", "the measured point does not move in all three "
                    + "directions over these " + rows.size() + " poses, so the anchor cannot be located from distances; add poses that "
                    + "move it up and down, sideways and towards the anchor, or give the anchor ('# anchor: x, y, z')");
        Dense.choleskySolve(l, 4, atb);
        return new Vec3(atb[0] / scale[0], atb[1] / scale[1], atb[2] / scale[2]);
    }
}
