package org.robopro.comms.sim;

import java.util.Optional;
import java.util.Random;
import org.robopro.calibration.PoseConditions;
import org.robopro.kinematics.Pose;
import org.robopro.models.Vec3;

/**
 * A test double for {@link SimulatedRobot} with trivial kinematics: the flange position is
 * (0.8 + 0.3 q1, 0.3 q2, 1.0 + 0.3 q3) m and its orientation rotZ(q4) rotY(q5) rotX(q6), so
 * inverse kinematics is closed form. The "true" robot is shifted by {@code errorM} along x; the
 * tracker target sits at {@link #TARGET} on the flange, the tracker at {@link #TRACKER_T_BASE}.
 */
final class GantryRobot implements SimulatedRobot {
    static final Pose TRACKER_T_BASE = Pose.rotZ(Math.toRadians(160)).times(Pose.translation(-3.0, 0.4, -0.2));
    static final Vec3 TARGET = new Vec3(0, 0, 0.1);
    private final double errorM;
    private final double noiseM;

    GantryRobot(double errorM, double noiseM) {
        this.errorM = errorM;
        this.noiseM = noiseM;
    }

    GantryRobot(double noiseM) { this(0.0005, noiseM); }

    GantryRobot() { this(0.0005, 0); }

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

    Pose trueFlange(double[] q) {
        return Pose.translation(errorM, 0, 0).times(nominalFlange(q));
    }

    /** The tracker target's true position in the tracker frame, without noise. */
    Vec3 truePoint(double[] q) { return TRACKER_T_BASE.times(trueFlange(q)).apply(TARGET); }

    @Override
    public Vec3 measure(double[] q, PoseConditions c, Random rng) {
        Vec3 p = truePoint(q);
        return new Vec3(p.x() + noiseM * rng.nextGaussian(), p.y() + noiseM * rng.nextGaussian(), p.z() + noiseM * rng.nextGaussian());
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
