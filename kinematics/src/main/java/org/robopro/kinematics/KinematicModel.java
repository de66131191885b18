package org.robopro.kinematics;

import java.util.List;
import org.robopro.models.RobotDescription;

/**
 * API STUB — to be implemented by the kinematics work (issue 2). Other modules compile against
 * these signatures; keep them (add, don't rename) when implementing.
 *
 * An immutable, thread-safe kinematic model built from a {@link RobotDescription} by the seed
 * paper's method (§4 frame assignment, Table 1 elementary transformations). SI units.
 * q = controller joint values, theta = model joint angles (theta = C q, the coupling).
 */
public final class KinematicModel {
    private KinematicModel() { }

    /** Builds the complete, minimal, model-continuous model of a robot description. */
    public static KinematicModel build(RobotDescription description) {
        throw new UnsupportedOperationException("not implemented yet");
    }

    public RobotDescription description() { throw new UnsupportedOperationException(); }

    public int dof() { throw new UnsupportedOperationException(); }

    /** Model angles theta from controller values q (coupling). */
    public double[] theta(double[] q) { throw new UnsupportedOperationException(); }

    /** Controller values q from model angles theta (inverse coupling). */
    public double[] q(double[] theta) { throw new UnsupportedOperationException(); }

    /** baseTflange at controller joint values q. */
    public Pose flange(double[] q) { throw new UnsupportedOperationException(); }

    /**
     * Frames of every link at q, in base coordinates: index 0 the base (identity), index i the
     * frame attached to the link moved by joint i, last index (dof+1) the flange.
     */
    public Pose[] linkFrames(double[] q) { throw new UnsupportedOperationException(); }

    /** 6 x dof geometric Jacobian of the flange w.r.t. q (rows vx vy vz wx wy wz, base frame). */
    public double[][] geometricJacobian(double[] q) { throw new UnsupportedOperationException(); }

    /** The identifiable parameters (Table 1), named, in order. */
    public List<ModelParameter> parameters() { throw new UnsupportedOperationException(); }

    public double[] parameterValues() { throw new UnsupportedOperationException(); }

    /** The same structure with other parameter values (e.g. identified ones). */
    public KinematicModel withParameterValues(double[] values) { throw new UnsupportedOperationException(); }

    /** This model written back as a robot description (joint axes and flange at the zero position). */
    public RobotDescription toDescription() { throw new UnsupportedOperationException(); }

    /** True when every q is inside its joint limits. */
    public boolean withinLimits(double[] q) { throw new UnsupportedOperationException(); }
}
