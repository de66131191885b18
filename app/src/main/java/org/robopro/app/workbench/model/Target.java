package org.robopro.app.workbench.model;

import java.util.Objects;
import org.robopro.kinematics.ConfData;
import org.robopro.kinematics.Pose;

/**
 * A taught target: the TCP pose in world (wobj0) coordinates, the joint values it was taught at
 * (the IK seed that keeps the configuration) and its configuration data.
 */
public record Target(String name, Pose worldTtcp, double[] qTaught, ConfData conf) {
    public Target {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(worldTtcp, "worldTtcp");
        qTaught = qTaught.clone();
    }

    @Override public double[] qTaught() { return qTaught.clone(); }

    public Target withPose(Pose p) { return new Target(name, p, qTaught, conf); }
}
