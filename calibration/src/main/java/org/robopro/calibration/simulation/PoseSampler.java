package org.robopro.calibration.simulation;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.ejml.data.DMatrixRMaj;
import org.ejml.dense.row.factory.DecompositionFactory_DDRM;
import org.ejml.interfaces.decomposition.SingularValueDecomposition_F64;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.JointDescription;

/**
 * Draws measurement poses spread over the joint ranges. Rule (docs/calibration.md): each q_i
 * uniform in the inner 90 % of its controller range; a pose is rejected when it is outside the
 * joint limits, near a singularity (smallest singular value of the geometric Jacobian, position
 * rows divided by the arm's reach, below {@link #MIN_SINGULAR}), below the base plane (flange
 * z &lt; 0), or with the flange within {@link #MIN_AXIS1_DISTANCE_M} of the axis-1 line (inside
 * the robot's own column, a self-collision stand-in).
 */
public final class PoseSampler {
    public static final double MIN_SINGULAR = 0.05;
    public static final double MIN_AXIS1_DISTANCE_M = 0.25;

    private final KinematicModel model;
    private final double reach;

    public PoseSampler(KinematicModel model) {
        this.model = model;
        double r = 0;
        Pose zero = model.flange(new double[model.dof()]);
        for (JointDescription j : model.description().joints()) r = Math.max(r, j.point().minus(zero.position()).norm());
        this.reach = Math.max(r, 0.1);
    }

    /** {@code n} accepted poses (controller values q). Throws when the rule rejects nearly everything. */
    public List<double[]> sample(int n, Random rng) {
        List<double[]> out = new ArrayList<>(n);
        int tries = 0;
        while (out.size() < n) {
            if (++tries > 200 * n + 1000)
                throw new IllegalStateException("pose rule rejects almost every pose of " + model.description().name());
            double[] q = candidate(rng);
            if (acceptable(q)) out.add(q);
        }
        return out;
    }

    /** One candidate drawn uniformly from the inner 90 % of each joint range. */
    public double[] candidate(Random rng) {
        List<JointDescription> js = model.description().joints();
        double[] q = new double[js.size()];
        for (int i = 0; i < q.length; i++) {
            JointDescription j = js.get(i);
            double lo = j.min(), hi = j.max();
            if (lo == hi && Double.isFinite(lo)) { q[i] = lo; continue; } // a locked joint (a URDF mimic joint's own value)
            if (!(hi > lo) || !Double.isFinite(lo) || !Double.isFinite(hi)) { lo = -Math.PI; hi = Math.PI; }
            double mid = 0.5 * (lo + hi), half = 0.45 * (hi - lo);
            q[i] = mid + half * (2 * rng.nextDouble() - 1);
        }
        return q;
    }

    /** The rejection rule of the class comment. */
    public boolean acceptable(double[] q) {
        if (!model.withinLimits(q)) return false;
        Pose f = model.flange(q);
        if (f.z() < 0) return false;
        JointDescription j1 = model.description().joints().get(0);
        var d = f.position().minus(j1.point());
        var along = j1.axis().normalized();
        double radial = d.minus(along.times(d.dot(along))).norm();
        if (radial < MIN_AXIS1_DISTANCE_M) return false;
        return smallestSingular(q) >= MIN_SINGULAR;
    }

    /** Smallest singular value of the geometric Jacobian with position rows divided by the reach. */
    public double smallestSingular(double[] q) {
        double[][] jg = model.geometricJacobian(q);
        int rows = jg.length, cols = jg[0].length;
        DMatrixRMaj a = new DMatrixRMaj(rows, cols);
        for (int i = 0; i < rows; i++)
            for (int k = 0; k < cols; k++) a.set(i, k, i < 3 ? jg[i][k] / reach : jg[i][k]);
        SingularValueDecomposition_F64<DMatrixRMaj> svd = DecompositionFactory_DDRM.svd(rows, cols, false, false, true);
        if (!svd.decompose(a)) return 0;
        double min = Double.MAX_VALUE;
        for (double s : svd.getSingularValues()) min = Math.min(min, s);
        return svd.numberOfSingularValues() < Math.min(6, cols) ? 0 : min;
    }
}
