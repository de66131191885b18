package org.robopro.app.workbench.model;

import java.util.List;
import java.util.Optional;
import org.robopro.kinematics.ConfData;
import org.robopro.kinematics.InverseKinematics;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.JointDescription;
import org.robopro.models.RobotDescription;

/**
 * The workbench's view of a robot's kinematics: link frames for drawing, the flange, IK for
 * Cartesian jogging and teaching, configuration data. Delegates to the kinematics module
 * ({@link KinematicModel}, {@link InverseKinematics}); the tests compare it with an independent
 * product-of-exponentials model. Immutable and thread-safe.
 */
public abstract class RobotKinematics {
    protected final RobotDescription description;

    RobotKinematics(RobotDescription description) {
        this.description = description;
    }

    /** The best available kinematics for {@code description}. */
    public static RobotKinematics of(RobotDescription description) {
        KinematicModel model = KinematicModel.build(description);
        return new ModuleKinematics(description, model, InverseKinematics.of(model));
    }

    public RobotDescription description() { return description; }

    public int dof() { return description.dof(); }

    /** Which implementation answers (shown in the status bar). */
    public abstract String implementation();

    /**
     * Rigid displacement of each link from its zero-position pose, in base coordinates: index 0
     * the base (identity), i the link moved by joint i. Shapes given in base coordinates at the
     * zero position (as CAD exports them) are drawn at {@code displacement[i] * shape}.
     */
    public abstract Pose[] linkDisplacements(double[] q);

    /** baseTflange at q. */
    public abstract Pose flange(double[] q);

    /** IK solution nearest to {@code qSeed}, or empty when unreachable. */
    public abstract Optional<double[]> solveNear(Pose baseTflange, double[] qSeed);

    /** ABB configuration data of q. */
    public abstract ConfData confOf(double[] q);

    /** The kinematics module's model (path checks need it). */
    public abstract Optional<KinematicModel> kinematicModel();

    /** True when every q is inside its joint limits. */
    public boolean withinLimits(double[] q) {
        List<JointDescription> js = description.joints();
        for (int i = 0; i < js.size(); i++)
            if (q[i] < js.get(i).min() - 1e-9 || q[i] > js.get(i).max() + 1e-9) return false;
        return true;
    }

    /** Index of the first joint outside its limits, or -1. */
    public int firstLimitViolation(double[] q) {
        List<JointDescription> js = description.joints();
        for (int i = 0; i < js.size(); i++)
            if (q[i] < js.get(i).min() - 1e-9 || q[i] > js.get(i).max() + 1e-9) return i;
        return -1;
    }

    /** Delegates to the kinematics module. */
    static final class ModuleKinematics extends RobotKinematics {
        private final KinematicModel model;
        private final InverseKinematics ik;
        private final Pose[] zeroInverse;

        ModuleKinematics(RobotDescription d, KinematicModel model, InverseKinematics ik) {
            super(d);
            this.model = model;
            this.ik = ik;
            Pose[] f0 = model.linkFrames(new double[d.dof()]);
            zeroInverse = new Pose[d.dof() + 1];
            for (int i = 0; i <= d.dof(); i++) zeroInverse[i] = f0[i].inverse();
        }

        @Override public String implementation() { return "kinematics module"; }

        @Override
        public Pose[] linkDisplacements(double[] q) {
            Pose[] f = model.linkFrames(q);
            Pose[] out = new Pose[dof() + 1];
            for (int i = 0; i <= dof(); i++) out[i] = f[i].times(zeroInverse[i]);
            return out;
        }

        @Override public Pose flange(double[] q) { return model.flange(q); }

        @Override
        public Optional<double[]> solveNear(Pose baseTflange, double[] qSeed) {
            return ik.solveNear(baseTflange, qSeed).map(s -> s.q().clone());
        }

        @Override public ConfData confOf(double[] q) { return ik.confOf(q); }

        @Override public Optional<KinematicModel> kinematicModel() { return Optional.of(model); }
    }
}
