package org.robopro.comms.sim;

import java.util.Optional;
import org.robopro.kinematics.IkSolution;
import org.robopro.kinematics.InverseKinematics;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.JointDescription;
import org.robopro.models.RobotDescription;

/**
 * The controller's side of a simulated robot: its name, joint limits and speeds from the robot
 * file, and forward/inverse kinematics of its nominal model. Subclasses add the physical robot
 * the tracker sees.
 */
abstract class NominalController implements SimulatedRobot {
    protected final RobotDescription description;
    protected final KinematicModel nominal;
    private final InverseKinematics ik;

    NominalController(RobotDescription description, KinematicModel nominal) {
        this.description = description;
        this.nominal = nominal;
        this.ik = InverseKinematics.of(nominal);
    }

    @Override public String name() { return description.name(); }

    @Override public int dof() { return nominal.dof(); }

    @Override public double[] lowerLimits() { return description.joints().stream().mapToDouble(JointDescription::min).toArray(); }

    @Override public double[] upperLimits() { return description.joints().stream().mapToDouble(JointDescription::max).toArray(); }

    @Override public double[] maxSpeeds() { return description.joints().stream().mapToDouble(JointDescription::maxSpeed).toArray(); }

    @Override public Pose nominalFlange(double[] q) { return nominal.flange(q); }

    @Override
    public Optional<double[]> inverse(Pose baseTflange, double[] qSeed) {
        return ik.solveNear(baseTflange, qSeed).map(IkSolution::q);
    }
}
