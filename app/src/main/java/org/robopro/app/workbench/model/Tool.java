package org.robopro.app.workbench.model;

import java.util.Objects;
import org.robopro.kinematics.Pose;

/**
 * A tool on the flange: its TCP ({@code flangeTtcp}) and a simple geometry built from it — a body
 * cylinder along the flange z axis and a tip from the body's end to the TCP. SI units.
 *
 * @param name         RAPID tooldata name
 * @param flangeTtcp   tool centre point in flange coordinates
 * @param bodyRadius   radius of the tool body (m)
 * @param bodyLength   length of the body along flange z (m)
 * @param massKg       tool mass (RAPID loaddata)
 */
public record Tool(String name, Pose flangeTtcp, double bodyRadius, double bodyLength, double massKg) {
    public Tool {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(flangeTtcp, "flangeTtcp");
        if (!(bodyRadius > 0) || !(bodyLength >= 0) || !(massKg > 0))
            throw new IllegalArgumentException("tool " + name + ": radius and mass must be > 0, length >= 0");
    }

    /** tool0: the bare flange. */
    public static Tool flange() { return new Tool("tool0", Pose.IDENTITY, 0.04, 0.0, 0.001); }
}
