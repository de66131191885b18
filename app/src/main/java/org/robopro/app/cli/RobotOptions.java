package org.robopro.app.cli;

import org.robopro.kinematics.KinematicModel;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
import picocli.CommandLine.Option;

/**
 * Mixin {@code --robot ROBOT}: a shipped robot name (irb2000, irb2400, puma560) or a robot file
 * (docs/robot-file.md), loaded once; a bad file fails with the InputException naming file, line
 * and field.
 */
public final class RobotOptions {
    @Option(names = "--robot", required = true, paramLabel = "ROBOT",
            description = "shipped robot name (irb2000, irb2400, puma560) or robot file; the nominal model")
    String robot;

    private RobotDescription description;
    private KinematicModel model;

    /** What the user gave. */
    String name() { return robot; }

    RobotDescription description() {
        if (description == null) description = RobotLibrary.load(robot);
        return description;
    }

    KinematicModel model() {
        if (model == null) model = KinematicModel.build(description());
        return model;
    }
}
