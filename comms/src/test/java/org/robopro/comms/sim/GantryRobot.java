package org.robopro.comms.sim;

import java.util.Optional;
import org.robopro.kinematics.Pose;

/**
 * A test double for {@link SimulatedRobot} with trivial kinematics: the flange position is
 * (0.8 + 0.3 q1, 0.3 q2, 1.0 + 0.3 q3) m and its orientation rotZ(q4) rotY(q5) rotX(q6), so
 * inverse kinematics is closed form. The "true" robot is shifted by {@code errorM} along x.
 */
final class GantryRobot implements SimulatedRobot {
    private final double errorM;

    GantryRobot(double errorM) { this.errorM = errorM; }

    GantryRobot() { this(0.0005); }

    @Override public String name() { return "gantry"; }

    @Override public int dof() { return 6; }

    @Override public double[] lowerLimits() { return new double[] {-2, -2, -2, -3, -1.4, -3}; }

    @Override public double[] upperLimits() { return new double[] {2, 2, 2, 3, 1.4, 3}; }

    @Override public double[] maxSpeeds() { return new double[] {1, 1, 1, 2, 2, 2}; }

    @Override
    public Pose nominalFlange(double[] q) {
        return Pose.translation(0.8 + 0.3 * q[0], 0.3 * q[1], 1.0 + 0.3 * q[2])
                .times(Pose.rotZ(q[3])).times(Pose.rotY(q[4])).times(Pose.rotX(q[5]));
    }

    @Override
    public Pose trueFlange(double[] q, int[] lastDirection) {
        return Pose.translation(errorM, 0, 0).times(nominalFlange(q));
    }

    @Override
    public Optional<double[]> inverse(Pose p, double[] seed) {
        double q1 = (p.x() - 0.8) / 0.3, q2 = p.y() / 0.3, q3 = (p.z() - 1.0) / 0.3;
        // ZYX Euler angles of R = Rz(a) Ry(b) Rx(c)
        double b = Math.asin(Math.max(-1, Math.min(1, -p.rot(2, 0))));
        if (Math.abs(Math.cos(b)) < 1e-9) return Optional.empty();
        double a = Math.atan2(p.rot(1, 0), p.rot(0, 0));
        double c = Math.atan2(p.rot(2, 1), p.rot(2, 2));
        return Optional.of(new double[] {q1, q2, q3, a, b, c});
    }
}
