package org.robopro.app.cli;

import org.robopro.kinematics.KinematicModel;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;

/** ROBOT arguments of the command line: a shipped model name or a robot file path. */
final class Robots {
    private Robots() { }

    static RobotDescription load(String nameOrPath) {
        try {
            return RobotLibrary.load(nameOrPath);
        } catch (UnsupportedOperationException e) {
            throw new IllegalArgumentException("robot files cannot be read in this build (RobotLibrary missing): " + nameOrPath, e);
        }
    }

    static KinematicModel model(String nameOrPath) { return KinematicModel.build(load(nameOrPath)); }
}
