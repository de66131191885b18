package org.robopro.programs;

import org.robopro.kinematics.Pose;

/**
 * An orientation as RAPID writes it: [q1, q2, q3, q4] with q1 the scalar part. Stored as given
 * (an imported file's digits survive a round trip); {@link #normalized()} makes it unit.
 */
public record Quaternion(double q1, double q2, double q3, double q4) {
    public static final Quaternion IDENTITY = new Quaternion(1, 0, 0, 0);

    public Quaternion {
        if (!(Double.isFinite(q1) && Double.isFinite(q2) && Double.isFinite(q3) && Double.isFinite(q4)))
            throw new IllegalArgumentException("non-finite quaternion [" + q1 + ", " + q2 + ", " + q3 + ", " + q4 + "]");
    }

    public double norm() { return Math.sqrt(q1 * q1 + q2 * q2 + q3 * q3 + q4 * q4); }

    /** The unit quaternion of the same rotation; throws when the norm is (near) zero. */
    public Quaternion normalized() {
        double n = norm();
        if (!(n > 1e-9)) throw new IllegalArgumentException("quaternion " + this + " has no direction");
        return new Quaternion(q1 / n, q2 / n, q3 / n, q4 / n);
    }

    /** The quaternion of a pose's rotation (scalar first, scalar >= 0). */
    public static Quaternion of(Pose pose) {
        double[] q = pose.quaternion();
        return new Quaternion(q[0], q[1], q[2], q[3]);
    }

    /** Rotation angle (rad, 0..pi) between this orientation and {@code o}'s. */
    public double angleTo(Quaternion o) {
        Quaternion a = normalized(), b = o.normalized();
        double d = Math.abs(a.q1 * b.q1 + a.q2 * b.q2 + a.q3 * b.q3 + a.q4 * b.q4);
        return 2 * Math.acos(Math.min(1, d));
    }
}
