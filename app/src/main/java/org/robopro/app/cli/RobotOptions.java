package org.robopro.app.cli;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.importers.DhImporter;
import org.robopro.kinematics.importers.UrdfImporter;
import org.robopro.models.InputException;
import org.robopro.models.TextFiles;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
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
        if (description == null) description = load(robot);
        return description;
    }

    /**
     * A ROBOT argument: a shipped model name, a robot file, or a DH table ({@code .dh}), modified
     * DH table ({@code .mdh}) or URDF ({@code .urdf}) imported on the fly as {@code robopro model
     * import} would. Any other file that is not JSON gets a one-line hint to {@code model import}.
     */
    static RobotDescription load(String nameOrPath) {
        Path p = Path.of(nameOrPath);
        if (Files.isRegularFile(p)) {
            String n = p.getFileName().toString().toLowerCase(Locale.ROOT);
            if (n.endsWith(".urdf") || n.endsWith(".urdf.xml")) return UrdfImporter.read(p);
            if (n.endsWith(".mdh")) return DhImporter.read(p, DhImporter.Convention.MODIFIED);
            if (n.endsWith(".dh")) return DhImporter.read(p, DhImporter.Convention.STANDARD);
            if (!n.endsWith(".json")) {
                String text = TextFiles.readUtf8(p).strip();
                if (!text.startsWith("{"))
                    throw new InputException(nameOrPath, 1, 1, null, (text.startsWith("<") ? "looks like a URDF" : "is not a robot file (JSON)")
                            + "; name a DH table .dh, a modified DH table .mdh or a URDF .urdf to use it directly, or convert it with "
                            + "'robopro model import --dh|--mdh|--urdf " + nameOrPath + " --out ROBOT.robot.json'");
            }
        }
        return RobotLibrary.load(nameOrPath);
    }

    KinematicModel model() {
        if (model == null) model = KinematicModel.build(description());
        return model;
    }
}
