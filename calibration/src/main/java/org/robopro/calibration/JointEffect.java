package org.robopro.calibration;

import org.robopro.kinematics.KinematicModel;

/**
 * A non-geometric effect on a robot, as the simulator injects it and the diagnosis models it:
 * a perturbation of the model joint angles (θ, rad; added before forward kinematics) and/or a
 * scale on every length (thermal expansion), as functions of the controller joint values q and
 * the pose conditions. Implementations are immutable.
 */
public interface JointEffect {
    /** Short name in the diagnosis vocabulary, e.g. "backlash". */
    String name();

    /** Adds this effect's Δθ (rad, model angles, length dof) at q into {@code dThetaOut}. */
    default void addDeltaTheta(KinematicModel model, double[] q, PoseConditions conditions, double[] dThetaOut) { }

    /** Relative length change ε (every length scales by 1 + ε, about the base origin); 0 for none. */
    default double lengthStrain(PoseConditions conditions) { return 0; }
}
