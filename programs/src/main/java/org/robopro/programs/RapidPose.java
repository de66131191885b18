package org.robopro.programs;

import org.robopro.kinematics.Pose;
import org.robopro.models.Vec3;

/** RAPID's {@code pose}: a translation (m) and an orientation (frames of tools and work objects). */
public record RapidPose(Vec3 trans, Quaternion rot) implements RapidValue {
    public static final RapidPose IDENTITY = new RapidPose(new Vec3(0, 0, 0), Quaternion.IDENTITY);

    public RapidPose {
        if (trans == null || rot == null) throw new IllegalArgumentException("pose needs trans and rot");
    }

    @Override public String rapidType() { return "pose"; }

    public Pose toPose() {
        return Pose.fromQuaternion(rot.q1(), rot.q2(), rot.q3(), rot.q4(), trans.x(), trans.y(), trans.z());
    }

    public static RapidPose of(Pose p) { return new RapidPose(p.position(), Quaternion.of(p)); }
}
