package org.robopro.kinematics;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Random;
import org.robopro.models.CouplingTerm;
import org.robopro.models.FrameDescription;
import org.robopro.models.JointDescription;
import org.robopro.models.JointType;
import org.robopro.models.RobotDescription;
import org.robopro.models.Vec3;

/**
 * Test fixture: the reference robots of robots.md as descriptions (until the shipped robot
 * files land), plus textbook DH / modified-DH forward kinematics as independent references.
 */
final class ReferenceRobots {
    private ReferenceRobots() { }

    static final double DEG = Math.PI / 180;

    private static JointDescription r(int i, double x, double y, double z, Vec3 axis, double minDeg, double maxDeg, double speedDeg) {
        return new JointDescription("j" + i, JointType.REVOLUTE, new Vec3(x * 1e-3, y * 1e-3, z * 1e-3), axis,
                minDeg * DEG, maxDeg * DEG, speedDeg * DEG);
    }

    private static RobotDescription robot(String name, List<JointDescription> joints, FrameDescription flange, List<CouplingTerm> coupling) {
        return new RobotDescription(name, name, joints, flange, coupling, Optional.empty(), List.of(), List.of(),
                "robots.md (test fixture)", Map.of());
    }

    /** theta3 = q3 - q2 (parallel-arm ABB robots). */
    static final List<CouplingTerm> ABB_COUPLING = List.of(new CouplingTerm(3, 3, 1), new CouplingTerm(3, 2, -1));

    static RobotDescription irb2000() {
        return robot("irb2000", List.of(
                r(1, 0, 0, 0, Vec3.Z, -180, 180, 150),
                r(2, 0, 0, 780, Vec3.Y, -100, 100, 150),
                r(3, 0, 0, 1490, Vec3.Y, -60, 60, 150),
                r(4, 0, 0, 1615, Vec3.X, -200, 200, 360),
                r(5, 850, 0, 1615, Vec3.Y, -120, 120, 360),
                r(6, 850, 0, 1615, Vec3.X, -200, 200, 450)),
                new FrameDescription(new Vec3(1.0, 0, 1.615), new Vec3(0, 0, -1), Vec3.X), ABB_COUPLING);
    }

    static RobotDescription irb2400() {
        return robot("irb2400", List.of(
                r(1, 0, 0, 0, Vec3.Z, -180, 180, 150),
                r(2, 100, 0, 615, Vec3.Y, -100, 110, 150),
                r(3, 100, 0, 1320, Vec3.Y, -60, 65, 150),
                r(4, 100, 0, 1455, Vec3.X, -200, 200, 360),
                r(5, 855, 0, 1455, Vec3.Y, -120, 120, 360),
                r(6, 855, 0, 1455, Vec3.X, -400, 400, 450)),
                new FrameDescription(new Vec3(0.94, 0, 1.455), new Vec3(0, 0, -1), Vec3.X), ABB_COUPLING);
    }

    /** PUMA 560 standard DH (d, a, alpha) of robots.md, metres and radians. */
    static final double[][] PUMA_DH = {
            {0.672, 0, 90 * DEG}, {0, 0.4318, 0}, {0.15005, 0.0203, -90 * DEG},
            {0.4318, 0, 90 * DEG}, {0, 0, -90 * DEG}, {0, 0, 0}};
    static final double[][] PUMA_LIMITS_DEG = {{-160, 160}, {-45, 225}, {-225, 45}, {-110, 170}, {-100, 100}, {-266, 266}};

    /** Standard DH FK: prod Rz(theta_i) Tz(d_i) Tx(a_i) Rx(alpha_i). */
    static Pose standardDh(double[][] dh, double[] theta) {
        Pose t = Pose.IDENTITY;
        for (int i = 0; i < dh.length; i++)
            t = t.times(Pose.rotZ(theta[i])).times(Pose.translation(0, 0, dh[i][0]))
                    .times(Pose.translation(dh[i][1], 0, 0)).times(Pose.rotX(dh[i][2]));
        return t;
    }

    /** Modified (Craig) DH FK: prod Rx(alpha_{i-1}) Tx(a_{i-1}) Rz(theta_i + offset_i) Tz(d_i); rows (alpha, a, d, offset). */
    static Pose modifiedDh(double[][] mdh, double[] theta) {
        Pose t = Pose.IDENTITY;
        for (int i = 0; i < mdh.length; i++)
            t = t.times(Pose.rotX(mdh[i][0])).times(Pose.translation(mdh[i][1], 0, 0))
                    .times(Pose.rotZ(theta[i] + mdh[i][3])).times(Pose.translation(0, 0, mdh[i][2]));
        return t;
    }

    /** IRB-2400 modified DH of robots.md (alpha, a, d, theta offset). */
    static final double[][] IRB2400_MDH = {
            {0, 0, 0.615, 0}, {-90 * DEG, 0.100, 0, -90 * DEG}, {0, 0.705, 0, 0},
            {-90 * DEG, 0.135, 0.755, 0}, {90 * DEG, 0, 0, 0}, {-90 * DEG, 0, 0.085, 180 * DEG}};

    /** PUMA 560 built from its joint axes: axis i is z_{i-1} of the DH frames at theta = 0. */
    static RobotDescription puma560() {
        List<JointDescription> joints = new ArrayList<>();
        Pose t = Pose.IDENTITY;
        for (int i = 0; i < 6; i++) {
            joints.add(new JointDescription("j" + (i + 1), JointType.REVOLUTE, t.position(), t.zAxis(),
                    PUMA_LIMITS_DEG[i][0] * DEG, PUMA_LIMITS_DEG[i][1] * DEG, 180 * DEG));
            t = t.times(Pose.translation(0, 0, PUMA_DH[i][0])).times(Pose.translation(PUMA_DH[i][1], 0, 0))
                    .times(Pose.rotX(PUMA_DH[i][2]));
        }
        return robot("puma560", joints, t.toFrame(), List.of());
    }

    static List<RobotDescription> all() { return List.of(irb2000(), irb2400(), puma560()); }

    /**
     * A random user robot: n joints with random axis directions and points (some parallel
     * neighbours, some intersecting), optionally prismatic joints, random flange.
     */
    static RobotDescription randomRobot(Random rnd, int n, boolean allowPrismatic) {
        List<JointDescription> joints = new ArrayList<>();
        Vec3 p = new Vec3(rnd.nextGaussian() * 0.1, rnd.nextGaussian() * 0.1, rnd.nextDouble() * 0.3);
        Vec3 u = unit(rnd);
        for (int i = 0; i < n; i++) {
            double kind = rnd.nextDouble();
            if (i > 0) {
                if (kind < 0.3) { /* parallel to the previous axis */ }
                else u = unit(rnd);
                p = p.plus(new Vec3(rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()).times(0.3));
            }
            boolean prism = allowPrismatic && rnd.nextDouble() < 0.3;
            Vec3 axis = kind < 0.3 && i > 0 && rnd.nextBoolean() ? u.times(-1) : u;
            joints.add(new JointDescription("j" + (i + 1), prism ? JointType.PRISMATIC : JointType.REVOLUTE, p, axis,
                    prism ? -0.5 : -Math.PI, prism ? 0.5 : Math.PI, 1));
        }
        Vec3 z = unit(rnd), x0 = unit(rnd);
        Vec3 x = x0.minus(z.times(x0.dot(z))).normalized();
        Vec3 o = p.plus(new Vec3(rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()).times(0.2));
        return robot("random", joints, new FrameDescription(o, x, z), List.of());
    }

    static Vec3 unit(Random rnd) {
        return new Vec3(rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()).normalized();
    }
}
