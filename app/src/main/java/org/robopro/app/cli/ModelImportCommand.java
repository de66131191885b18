package org.robopro.app.cli;

import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.robopro.kinematics.importers.DhImporter;
import org.robopro.kinematics.importers.UrdfImporter;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
import picocli.CommandLine.ArgGroup;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code robopro model import --dh|--mdh|--urdf FILE --out ROBOT_FILE}: converts a DH table,
 * a modified (Craig) DH table or a URDF into a robot file (docs/robot-file.md). Registered as the
 * {@code import} subcommand of {@code model}.
 */
@Command(name = "import", mixinStandardHelpOptions = true,
        description = "Convert a DH table (--dh), modified DH table (--mdh) or URDF (--urdf) into a robot file.")
public final class ModelImportCommand implements Callable<Integer> {
    static final class Input {
        @Option(names = "--dh", paramLabel = "FILE", description = "standard DH table (docs/robot-file.md)") Path dh;
        @Option(names = "--mdh", paramLabel = "FILE", description = "modified (Craig) DH table") Path mdh;
        @Option(names = "--urdf", paramLabel = "FILE", description = "URDF file (revolute, continuous, prismatic, fixed joints)") Path urdf;
    }

    @ArgGroup(exclusive = true, multiplicity = "1") Input input;

    @Mixin OutputFileOptions out;

    @Spec CommandSpec spec;

    @Override
    public Integer call() {
        RobotDescription robot;
        if (input.dh != null) robot = DhImporter.read(input.dh, DhImporter.Convention.STANDARD);
        else if (input.mdh != null) robot = DhImporter.read(input.mdh, DhImporter.Convention.MODIFIED);
        else robot = UrdfImporter.read(input.urdf);
        RobotLibrary.write(robot, out.file(), out.force());
        spec.commandLine().getOut().printf("wrote %s: %s, %d joints%n", out.file(), robot.displayName(), robot.dof());
        return 0;
    }
}
