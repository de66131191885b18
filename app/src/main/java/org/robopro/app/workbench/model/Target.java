package org.robopro.app.workbench.model;

import java.util.Objects;
import org.robopro.kinematics.ConfData;
import org.robopro.kinematics.Pose;

/**
 * A taught target: the TCP pose in world coordinates, the joint values it was taught at (the IK
 * seed that keeps the configuration), its configuration data and the work object it belongs to
 * (RAPID export writes the robtarget in that work object's frame; "wobj0" is the world).
 */
public record Target(String name, Pose worldTtcp, double[] qTaught, ConfData conf, String wobj) {
    public static final String WOBJ0 = "wobj0";

    public Target {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(worldTtcp, "worldTtcp");
        qTaught = qTaught.clone();
        wobj = wobj == null || wobj.isBlank() ? WOBJ0 : wobj;
    }

    /** A target in wobj0 (world coordinates). */
    public Target(String name, Pose worldTtcp, double[] qTaught, ConfData conf) { this(name, worldTtcp, qTaught, conf, WOBJ0); }

    @Override public double[] qTaught() { return qTaught.clone(); }

    public Target withPose(Pose p) { return new Target(name, p, qTaught, conf, wobj); }

    public Target withWobj(String w) { return new Target(name, worldTtcp, qTaught, conf, w); }
}
