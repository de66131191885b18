package org.robopro.programs;

import org.robopro.kinematics.ConfData;
import org.robopro.kinematics.Pose;
import org.robopro.models.Vec3;

/**
 * RAPID's {@code robtarget}: the TCP position (m) and orientation in the work object's object
 * frame, the robot configuration (cf1, cf4, cf6, cfx) and the external axes.
 */
public record RobTarget(Vec3 trans, Quaternion rot, ConfData robconf, ExtJoints extax) implements RapidValue {
    public RobTarget {
        if (trans == null || rot == null || robconf == null || extax == null)
            throw new IllegalArgumentException("robtarget fields must not be null");
    }

    public static RobTarget of(Pose objTtcp, ConfData conf) {
        return new RobTarget(objTtcp.position(), Quaternion.of(objTtcp), conf, ExtJoints.NONE);
    }

    @Override public String rapidType() { return "robtarget"; }

    /** The target as a pose in the object frame (quaternion normalised). */
    public Pose pose() { return new RapidPose(trans, rot).toPose(); }

    public RobTarget withPose(Pose objTtcp) { return new RobTarget(objTtcp.position(), Quaternion.of(objTtcp), robconf, extax); }

    public RobTarget withConf(ConfData conf) { return new RobTarget(trans, rot, conf, extax); }
}
