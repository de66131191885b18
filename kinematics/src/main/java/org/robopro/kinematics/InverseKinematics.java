package org.robopro.kinematics;

import java.util.List;
import java.util.Optional;

/**
 * API STUB — to be implemented by the kinematics work (issue 2).
 * Closed form for six-axis arms with a spherical wrist, numerical for any model.
 */
public final class InverseKinematics {
    private InverseKinematics() { }

    public static InverseKinematics of(KinematicModel model) { throw new UnsupportedOperationException(); }

    /** Every solution reaching baseTflange (closed form where the geometry allows, else numerical). */
    public List<IkSolution> solveAll(Pose baseTflange) { throw new UnsupportedOperationException(); }

    /** The solution nearest to qSeed (numerical refinement), or empty when unreachable. */
    public Optional<IkSolution> solveNear(Pose baseTflange, double[] qSeed) { throw new UnsupportedOperationException(); }

    /** The solution with the given configuration data, or empty. */
    public Optional<IkSolution> solveWithConf(Pose baseTflange, ConfData conf) { throw new UnsupportedOperationException(); }

    /** ABB configuration data of joint values q. */
    public ConfData confOf(double[] q) { throw new UnsupportedOperationException(); }
}
