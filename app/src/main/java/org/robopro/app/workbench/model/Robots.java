package org.robopro.app.workbench.model;

import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;

/** Finds robot descriptions for the workbench (the robot library: shipped names or robot files). */
public final class Robots {
    private Robots() { }

    /** A shipped robot by name or a robot file by path. */
    public static RobotDescription load(String nameOrPath) {
        return RobotLibrary.load(nameOrPath);
    }

    static RobotDescription irb2000() { return RobotLibrary.load("irb2000"); }
}
