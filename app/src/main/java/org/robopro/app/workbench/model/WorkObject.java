package org.robopro.app.workbench.model;

import java.util.Objects;
import org.robopro.kinematics.Pose;

/** A RAPID work object (wobjdata) user frame in world coordinates; wobj0 is the world itself. */
public record WorkObject(String name, Pose worldTuser) {
    public WorkObject {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(worldTuser, "worldTuser");
    }
}
