package org.robopro.app.cli;

import java.util.concurrent.Callable;
import org.robopro.kinematics.ModelReport;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Parameters;
import org.robopro.kinematics.KinematicModel;

/** {@code robopro model show ROBOT}: the frames and Table 1 parameters (the paper's Fig. 8). */
@Command(name = "show", mixinStandardHelpOptions = true,
        description = "Print a robot's kinematic model: frames at the zero position and every transformation's parameters.")
public final class ModelShowCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "ROBOT", description = "shipped robot name (e.g. irb2000) or robot file")
    String robot;

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Override
    public Integer call() {
        spec.commandLine().getOut().print(ModelReport.of(KinematicModel.build(RobotOptions.load(robot))));
        spec.commandLine().getOut().flush();
        return 0;
    }
}
