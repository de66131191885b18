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

    /** Preallocated buffers for allocation-free hot loops (FK, Jacobians); one per thread. */
    public Workspace newWorkspace() { throw new UnsupportedOperationException(); }

    /** Buffers owned by one thread; made by {@link #newWorkspace()}. Contents are implementation-defined. */
    public static final class Workspace {
        private Workspace() { }
    }

    /**
     * Allocation-free FK: writes baseTflange at q into {@code out12} as a row-major 3x4 matrix
     * [R | t] (metres).
     */
    public void flange(double[] q, Workspace ws, double[] out12) { throw new UnsupportedOperationException(); }

    /**
     * Identification Jacobian (analytic) of a point fixed on the flange: writes the point's
     * position in base coordinates (m) into {@code posOut} (length 3) and d(position)/d(parameter)
     * into {@code jacOut}, row-major 3 x P with P = parameters().size(). {@code pointInFlange}
     * is in flange coordinates (m).
     */
    public void pointJacobian(double[] q, double[] pointInFlange, Workspace ws, double[] posOut, double[] jacOut) {
        throw new UnsupportedOperationException();
    }

    /**
     * Identification Jacobian of the full pose of a tool frame {@code flangeTtool}: writes the
     * 3x4 [R | t] of baseTtool into {@code pose12} and a row-major 6 x P Jacobian into
     * {@code jacOut}: rows 0-2 d(position)/dp (m per unit), rows 3-5 the small rotation
     * (rad per unit) about base x, y, z.
     */
    public void poseJacobian(double[] q, Pose flangeTtool, Workspace ws, double[] pose12, double[] jacOut) {
        throw new UnsupportedOperationException();
    }
}
