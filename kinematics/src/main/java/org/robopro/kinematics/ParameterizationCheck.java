package org.robopro.kinematics;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.ejml.data.DMatrixRMaj;
import org.ejml.dense.row.SingularOps_DDRM;

/**
 * Singularity check of a model's parameterization (seed paper §3): for every transformation
 * between consecutive frames, the rank of dT/dp and det(J^T J) of its 6 x |p| Jacobian at the
 * current values; for the whole model, the rank and condition number of the scaled
 * identification Jacobian over random configurations. A parameterization is singular where
 * dT/dp loses rank (DH for parallel axes, Eq. 4b; Hayati for perpendicular ones, Eq. 7).
 *
 * <p>Columns are twists at the transformation's end frame, translations divided by the robot's
 * size and every column normalised, so det(J^T J) lies in [0, 1] (1: orthogonal columns,
 * 0: singular) and the smallest singular value is a scale-free distance to the singularity.
 */
public final class ParameterizationCheck {
    /** Below this smallest singular value a transformation is reported as near-singular. */
    public static final double NEAR_SINGULAR = 0.05;
    /** Above this condition number the identification Jacobian is reported as ill-conditioned. */
    public static final double ILL_CONDITIONED = 1e4;

    private ParameterizationCheck() { }

    /** One transformation's check. */
    public record TransformationCheck(int index, String label, String convention, double axisAngle,
                                      List<String> parameters, int rank, double detJtJ, double smallestSingularValue) {
        public boolean singular() { return rank < parameters.size(); }
    }

    /** The whole model's check with the warnings a user should see. */
    public record Result(List<TransformationCheck> transformations, int parameterCount, int expectedCount,
                         int identificationRank, double conditionNumber, List<String> warnings) { }

    public static Result check(KinematicModel model) {
        double len = model.characteristicLength();
        List<TransformationCheck> rows = new ArrayList<>();
        List<String> warnings = new ArrayList<>();
        int n = model.dof();
        for (Transformation t : model.transformations()) {
            List<Elementary> els = t.elements();
            // parameters examined: base without its constant rotation; the flange row's identified
            // ones (its fixed joint offset is redundant by construction); joint rows complete.
            boolean[] use = new boolean[els.size()];
            for (int i = 0; i < els.size(); i++) {
                Elementary e = els.get(i);
                use[i] = t.index() == 0 ? !e.name().endsWith(".r0") : t.index() == n ? e.identified() : true;
            }
            double[] m = new double[12];
            Se3.identity(m);
            List<double[]> axes = new ArrayList<>(), origins = new ArrayList<>();
            List<Boolean> rot = new ArrayList<>();
            List<String> names = new ArrayList<>();
            for (int i = 0; i < els.size(); i++) {
                Elementary e = els.get(i);
                int a = e.op().axis();
                if (use[i]) {
                    axes.add(new double[] {m[a], m[4 + a], m[8 + a]});
                    origins.add(new double[] {m[3], m[7], m[11]});
                    rot.add(e.op().isRotation());
                    names.add(e.name());
                }
                Elementary.apply(m, e.op(), e.value(), Math.cos(e.value()), Math.sin(e.value()));
            }
            int k = names.size();
            double[][] j = new double[6][k];
            for (int c = 0; c < k; c++) {
                double[] u = axes.get(c), o = origins.get(c);
                double[] col = new double[6];
                if (rot.get(c)) {
                    double rx = m[3] - o[0], ry = m[7] - o[1], rz = m[11] - o[2];
                    col[0] = (u[1] * rz - u[2] * ry) / len;
                    col[1] = (u[2] * rx - u[0] * rz) / len;
                    col[2] = (u[0] * ry - u[1] * rx) / len;
                    col[3] = u[0]; col[4] = u[1]; col[5] = u[2];
                } else {
                    col[0] = u[0] / len; col[1] = u[1] / len; col[2] = u[2] / len;
                }
                double nn = 0;
                for (double v : col) nn += v * v;
                nn = Math.sqrt(nn);
                for (int r = 0; r < 6; r++) j[r][c] = col[r] / nn;
            }
            double[] s = SingularOps_DDRM.singularValues(new DMatrixRMaj(j));
            Arrays.sort(s);
            double det = 1;
            int rank = 0;
            for (double v : s) {
                det *= v * v;
                if (v > 1e-9) rank++;
            }
            double smin = s.length == 0 ? 1 : s[0];
            if (s.length < k) { smin = 0; det = 0; }
            TransformationCheck tc = new TransformationCheck(t.index(), t.label(), t.convention(), t.axisAngle(),
                    List.copyOf(names), Math.min(rank, k), det, smin);
            rows.add(tc);
            if (tc.singular())
                warnings.add(t.label() + " (" + t.convention() + "): singular parameterization, rank " + tc.rank()
                        + " < " + k + " (det(J^T J) = " + fmt(det) + ")");
            else if (smin < NEAR_SINGULAR)
                warnings.add(t.label() + " (" + t.convention() + "): near a singular parameterization (smallest singular value "
                        + fmt(smin) + ")");
        }
        int rank = model.identificationRank();
        double cond = model.identificationConditionNumber();
        int count = model.parameters().size(), expected = model.expectedParameterCount();
        if (rank < count)
            warnings.add("identification Jacobian has rank " + rank + " < " + count + " parameters: some are not identifiable");
        else if (cond > ILL_CONDITIONED)
            warnings.add("identification Jacobian is ill-conditioned (condition number " + fmt(cond) + ")");
        if (count != expected)
            warnings.add(count + " identified parameters, but a complete minimal model has 4R + 2P + 6 = " + expected);
        if (!model.identifiabilityNote().isEmpty() && !model.isPlainDh()) warnings.add(model.identifiabilityNote());
        return new Result(List.copyOf(rows), count, expected, rank, cond, List.copyOf(warnings));
    }

    static String fmt(double v) { return String.format(java.util.Locale.ROOT, "%.3g", v); }
}
