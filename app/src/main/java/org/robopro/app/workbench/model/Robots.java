package org.robopro.app.workbench.model;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.robopro.models.CouplingTerm;
import org.robopro.models.FrameDescription;
import org.robopro.models.JointDescription;
import org.robopro.models.JointType;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
import org.robopro.models.Vec3;

/** Finds robot descriptions for the workbench: the robot library, or a built-in IRB-2000 while the library is a stub. */
public final class Robots {
    private Robots() { }

    /** A shipped robot by name or a robot file by path. */
    public static RobotDescription load(String nameOrPath) {
        try {
            return RobotLibrary.load(nameOrPath);
        } catch (UnsupportedOperationException stub) {
            if (nameOrPath.equalsIgnoreCase("irb2000")) return irb2000();
            throw new IllegalArgumentException("robot '" + nameOrPath
                    + "': the robot library is not available yet; only the built-in irb2000 can be loaded");
        }
    }

    /**
     * ABB IRB-2000 nominal geometry from /work/shared/reference/robots.md (joint points and axes at
     * the zero position, mm there, metres here), with the parallel-arm coupling theta3 = q3 - q2.
     */
    static RobotDescription irb2000() {
        double d = Math.PI / 180;
        List<JointDescription> j = List.of(
                joint("j1", 0, 0, 0, 0, 0, 1, -180, 180, 150),
                joint("j2", 0, 0, 780, 0, 1, 0, -100, 100, 150),
                joint("j3", 0, 0, 1490, 0, 1, 0, -60, 60, 150),
                joint("j4", 0, 0, 1615, 1, 0, 0, -200, 200, 360),
                joint("j5", 850, 0, 1615, 0, 1, 0, -120, 120, 360),
                joint("j6", 850, 0, 1615, 1, 0, 0, -200, 200, 450));
        FrameDescription flange = new FrameDescription(new Vec3(1.0, 0, 1.615), new Vec3(0, 0, -1), new Vec3(1, 0, 0));
        return new RobotDescription("irb2000", "ABB IRB 2000", j, flange,
                List.of(new CouplingTerm(3, 3, 1), new CouplingTerm(3, 2, -1)), Optional.empty(), List.of(), List.of(),
                "robots.md (nominal, MRCore aseairb2000sim)", Map.of());
    }

    private static JointDescription joint(String name, double x, double y, double z, double ax, double ay, double az,
                                          double minDeg, double maxDeg, double speedDeg) {
        return new JointDescription(name, JointType.REVOLUTE, new Vec3(x / 1000, y / 1000, z / 1000), new Vec3(ax, ay, az),
                Math.toRadians(minDeg), Math.toRadians(maxDeg), Math.toRadians(speedDeg));
    }
}
