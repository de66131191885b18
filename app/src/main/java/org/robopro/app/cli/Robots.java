package org.robopro.app.cli;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.importers.DhImporter;
import org.robopro.kinematics.importers.UrdfImporter;
import org.robopro.models.InputException;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
import org.robopro.models.TextFiles;

/**
 * ROBOT arguments of the command line: a shipped model name, a robot file, or a DH table
 * ({@code .dh}), modified DH table ({@code .mdh}) or URDF ({@code .urdf}) imported on the fly as
 * {@code robopro model import} would. Any other file that is not JSON gets a one-line hint to
 * {@code model import}.
 */
final class Robots {
    private Robots() { }

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

    static KinematicModel model(String nameOrPath) { return KinematicModel.build(load(nameOrPath)); }
}
