package org.robopro.app.workbench.model;

import java.util.List;
import org.robopro.kinematics.Pose;
import org.robopro.models.Vec3;

/**
 * The cell the workbench opens with: an IRB-2000 on the floor, a welding table in front of it
 * with a fixture and a part, and a straight welding torch as tool, the arm in a pose ready to
 * teach (torch pointing down above the part).
 */
public final class DefaultCell {
    private DefaultCell() { }

    public static final int ABB_ORANGE = 0xF07A1A;

    public static ProjectData irb2000Welding() {
        var robot = Robots.load("irb2000");
        Tool torch = new Tool("torch", Pose.translation(0, 0, 0.30), 0.035, 0.22, 2.5);
        List<CellObject> objects = List.of(
                new CellObject("table1", "Welding table", CellObject.Kind.TABLE, Pose.translation(1.35, 0, 0),
                        new Vec3(0.9, 1.3, 0.70), null, 0x5A6270),
                new CellObject("fixture1", "Clamp fixture", CellObject.Kind.FIXTURE, Pose.translation(1.35, -0.35, 0.70),
                        new Vec3(0.5, 0.12, 0.10), null, 0x2F7D3A),
                new CellObject("part1", "Bracket (part)", CellObject.Kind.PART,
                        Pose.translation(1.30, 0.05, 0.70).times(Pose.rotZ(Math.toRadians(15))),
                        new Vec3(0.40, 0.25, 0.06), null, 0xB8C4D0));
        List<WorkObject> wobjs = List.of(new WorkObject("wobjTable", Pose.translation(1.35, 0, 0.70)));
        return new ProjectData("irb2000", robot, Pose.IDENTITY, torch, objects, wobjs, List.of(), List.of(), null);
    }

    /** Joint values (rad) of the ready-to-teach pose: torch pointing down over the table. */
    public static double[] readyPose() {
        return new double[] {0, Math.toRadians(25), Math.toRadians(5), 0, Math.toRadians(85), 0};
    }
}
