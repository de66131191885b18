package org.robopro.comms.sim;

import java.util.Optional;
import java.util.Random;
import org.robopro.calibration.PoseConditions;
import org.robopro.kinematics.Pose;
import org.robopro.models.Vec3;

/**
 * The robot behind the simulated controller: the controller's own (nominal) model, which it
 * uses for CRobT and inverse kinematics, and the physical robot the laser tracker sees, which
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

    /** Joint values near {@code qSeed} reaching {@code baseTflange} in the nominal model, if any (limits unchecked). */
    Optional<double[]> inverse(Pose baseTflange, double[] qSeed);

    /**
     * A tracker reading: the target on the physical robot's tool at q, reached and measured under
     * conditions {@code c}, in the tracker frame (m), with the instrument's noise drawn from {@code rng}.
     */
    Vec3 measure(double[] q, PoseConditions c, Random rng);

    /** True when the physical robot depends on temperature (the controller then simulates a warm-up). */
    default boolean thermal() { return false; }
}
