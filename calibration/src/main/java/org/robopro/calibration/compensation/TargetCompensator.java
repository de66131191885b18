package org.robopro.calibration.compensation;

import java.util.Locale;
import org.robopro.kinematics.Pose;

/**
 * Compensation of one target (seed paper Fig. 5): the pose to command to a controller that knows
 * only the nominal model so that the real robot, as a calibrated model predicts it, reaches the
 * target. Implemented once, by {@link Compensator}; programs, the command line, the workbench and
 * the demo all compensate through this interface.
 */
@FunctionalInterface
public interface TargetCompensator {

    /** How a compensation ended. */
    enum Status {
        /** The calibrated prediction at {@code q} lands on the target and {@code q} is inside the joint limits. */
        CONVERGED,
        /** The iteration did not reach the tolerances (or its linear system was singular). */
        NOT_CONVERGED,
        /** The nominal inverse kinematics has no solution for a commanded pose. */
        UNREACHABLE,
        /** Converged, but the joint values leave the nominal model's limits. */
        OUT_OF_LIMITS;

        /** Whether the commanded pose may be sent to the controller. */
        public boolean ok() { return this == CONVERGED; }

        /** Lower-case words for reports ("not converged"). */
        public String label() { return name().toLowerCase(Locale.ROOT).replace('_', ' '); }
    }

    /**
     * @param commanded   X_comp: the pose to send to the nominal controller (same frame as the target)
     * @param q           the joint values the nominal controller computes for X_comp (send these instead if it takes joints)
     * @param residualM   distance between the target and the calibrated prediction at q, m
     * @param residualRad angle between them, rad
     * @param iterations  iterations used
     * @param status      how it ended
     */
    record Result(Pose commanded, double[] q, double residualM, double residualRad, int iterations, Status status) { }

    /**
     * Compensates {@code baseTtarget}, the pose of a tool {@code flangeTtool} in base coordinates,
     * starting from the controller joint values {@code qSeed} (the nominal IK branch nearest to them).
     *
     * @param flangeTtool the tool as the controller knows it (the program's tool data)
     */
    Result compensate(Pose baseTtarget, Pose flangeTtool, double[] qSeed);
}
