package org.robopro.app.cli;

import org.robopro.kinematics.KinematicModel;
import org.robopro.models.RobotDescription;
import picocli.CommandLine.Option;

/**
 * Mixin {@code --robot ROBOT}: a shipped robot name (irb2000, irb2400, puma560), a robot file
 * (docs/robot-file.md) or a DH / modified DH table or URDF imported on the fly, loaded once; a bad file fails with the InputException naming file, line
 * and field.
 */
public final class RobotOptions {
    @Option(names = "--robot", required = true, paramLabel = "ROBOT",
            description = "shipped robot name (irb2000, irb2400, puma560), robot file, or DH (.dh), modified DH (.mdh) or URDF (.urdf) file; the nominal model")
    String robot;

    private RobotDescription description;
    private KinematicModel model;

    /** What the user gave. */
    String name() { return robot; }

    RobotDescription description() {
        if (description == null) description = Robots.load(robot);
        return description;
    }

    KinematicModel model() {
        if (model == null) model = KinematicModel.build(description());
        return model;
    }
}
