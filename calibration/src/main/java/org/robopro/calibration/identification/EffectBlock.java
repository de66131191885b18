package org.robopro.calibration.identification;

import java.util.List;
import org.robopro.calibration.measurement.Measurement;

/**
 * A pluggable block of non-geometric parameters (the diagnosis adds these): per pose it may
 * perturb the model joint angles θ before forward kinematics and/or add a position term in
 * base coordinates after it, and it supplies the derivatives of both with respect to its
 * parameters. {@link IdentificationProblem} chains them with the kinematic Jacobians and the
 * instrument frame. Implementations must be thread-safe (stateless).
 */
public interface EffectBlock {
    /** Block name, used as the prefix of its parameters ("backlash"). */
    String name();

    /** Parameter names (without the block prefix), e.g. "j2.halfPlay". */
    List<String> parameterNames();

    /** SI unit of each parameter, e.g. "rad", "1", "rad/(N·m)". */
    List<String> units();

    /** Start values of the parameters. */
    double[] initialValues();

    /** How willingly the identifiability analysis fixes this block's parameters (geometry is 1). */
    default double fixPriority() { return 1.0; }

    /**
     * Writes the joint-angle perturbation Δθ (rad, length dof) at this pose into {@code dTheta}
     * (add to it; it arrives zeroed by the caller for the first block) and, when
     * {@code dThetaDv} is not null, ∂Δθ/∂v into it (row-major dof x size, overwrite).
     */
    void jointDelta(double[] values, Measurement row, double[] dTheta, double[] dThetaDv);

    /**
     * Optional additive position term in base coordinates (m) given the predicted point
     * {@code pointBase}: add it to {@code dp}, write ∂dp/∂v (3 x size, overwrite) into
     * {@code dpDv} when not null, and add ∂dp/∂pointBase (3 x 3, row-major) into {@code dpDpoint}
     * when not null (e.g. the strain ε·I of a length scaling). The default adds nothing.
     */
    default void positionDelta(double[] values, Measurement row, double[] pointBase, double[] dp, double[] dpDv,
                               double[] dpDpoint) {
        if (dpDv != null) java.util.Arrays.fill(dpDv, 0);
    }

    /**
     * Optional small rotation of the measured frame in base coordinates (a rotation vector, rad;
     * only orientations see it: the position's share is in {@link #positionDelta}), e.g. the whole
     * robot tilting on its base: add it to {@code dw}, and write ∂dw/∂v (3 x size, overwrite) into
     * {@code dwDv} when not null. The default turns nothing.
     */
    default void rotationDelta(double[] values, Measurement row, double[] pointBase, double[] dw, double[] dwDv) {
        if (dwDv != null) java.util.Arrays.fill(dwDv, 0);
    }
}
