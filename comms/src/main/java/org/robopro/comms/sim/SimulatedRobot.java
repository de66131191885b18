package org.robopro.comms.sim;

import java.util.Optional;
import org.robopro.kinematics.Pose;

/**
 * The robot behind the simulated controller: the controller's own (nominal) model, which it
 * uses for CRobT and inverse kinematics, and the "true" robot the laser tracker sees, which
 * differs by the errors calibration is meant to find. SI units; q are controller joint values.
 */
public interface SimulatedRobot {
    String name();

    int dof();

    double[] lowerLimits();

    double[] upperLimits();

    /** Maximum joint speeds (rad/s or m/s), all > 0. */
    double[] maxSpeeds();

    /** baseTflange of the controller's nominal model at q. */
    Pose nominalFlange(double[] q);

    /**
     * baseTflange of the physical robot at q, reached with the last motion of each joint in
     * direction {@code lastDirection} (1, -1 or 0; for backlash-like effects).
     */
    Pose trueFlange(double[] q, int[] lastDirection);

    /** Joint values near {@code qSeed} reaching {@code baseTflange} in the nominal model, if any (limits unchecked). */
    Optional<double[]> inverse(Pose baseTflange, double[] qSeed);
}
