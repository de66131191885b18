package org.robopro.app.workbench.model;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.robopro.kinematics.Pose;
import org.robopro.models.CellDescription;
import org.robopro.models.CellFile;
import org.robopro.models.PoseDescription;
import org.robopro.models.RobotDescription;
import org.robopro.models.Rgba;
import org.robopro.models.ToolDescription;
import org.robopro.models.Vec3;
import org.robopro.models.WorkObjectDescription;

/**
 * The cell the workbench opens with — robopro's shipped {@code irb2000-welding} cell
 * (docs/cell-file.md): an IRB-2000, a welding table with two plates, the controller cabinet, a
 * bent welding torch — and the conversion of any cell file into the workbench's model.
 */
public final class DefaultCell {
    private DefaultCell() { }

    public static final int ABB_ORANGE = 0xF07A1A;

    public static ProjectData irb2000Welding() {
        return fromCell(CellFile.shipped("irb2000-welding"), null);
    }

    /** A cell file's content as a workbench project (first tool mounted; no targets yet). */
    public static ProjectData fromCell(CellDescription cell, java.nio.file.Path cellFile) {
        RobotDescription robot = CellFile.loadRobot(cell, cellFile);
        List<CellObject> objects = new ArrayList<>();
        for (org.robopro.models.CellObject o : cell.objects()) {
            Pose centre = pose(o.worldTobject());
            String id = o.name().replaceAll("[^A-Za-z0-9_]", "_");
            int rgb = rgb(o.colour());
            switch (o.kind()) {
                case MESH -> objects.add(new CellObject(id, o.name(), CellObject.Kind.MESH, centre,
                        new Vec3(o.meshScale(), o.meshScale(), o.meshScale()), o.meshPath(), rgb));
                case BOX, CYLINDER -> {
                    // Cell files place boxes and cylinders by their centre; the workbench by the underside.
                    Pose underside = centre.times(Pose.translation(0, 0, -o.size().z() / 2));
                    CellObject.Kind kind = o.kind() == org.robopro.models.CellObject.Kind.CYLINDER ? CellObject.Kind.CYLINDER
                            : kindByName(o.name());
                    objects.add(new CellObject(id, o.name(), kind, underside, o.size(), null, rgb));
                }
            }
        }
        Tool tool = Tool.flange();
        if (!cell.tools().isEmpty()) {
            ToolDescription t = cell.tools().get(0);
            Pose tcp = pose(t.flangeTtcp());
            double body = Math.max(0.05, tcp.z() * 0.55);
            tool = new Tool(t.name(), tcp, 0.03, body, Math.max(0.001, t.massKg()));
        }
        List<WorkObject> wobjs = new ArrayList<>();
        for (WorkObjectDescription w : cell.workObjects()) wobjs.add(new WorkObject(w.name(), pose(w.worldTuser())));
        return new ProjectData(cell.robot(), robot, pose(cell.worldTbase()), tool, objects, wobjs, List.of(), List.of(), null);
    }

    private static CellObject.Kind kindByName(String name) {
        String n = name.toLowerCase(Locale.ROOT);
        if (n.contains("table")) return CellObject.Kind.TABLE;
        if (n.contains("fixture") || n.contains("clamp")) return CellObject.Kind.FIXTURE;
        return CellObject.Kind.PART;
    }

    static Pose pose(PoseDescription p) {
        return Pose.fromQuaternion(p.qw(), p.qx(), p.qy(), p.qz(), p.position().x(), p.position().y(), p.position().z());
    }

    private static int rgb(Rgba c) {
        if (c == null) return 0x9AA5B1;
        return (int) Math.round(c.r() * 255) << 16 | (int) Math.round(c.g() * 255) << 8 | (int) Math.round(c.b() * 255);
    }

    /** Joint values (rad) of the ready-to-teach pose: torch over the table. */
    public static double[] readyPose() {
        return new double[] {0, Math.toRadians(25), Math.toRadians(5), 0, Math.toRadians(60), 0};
    }
}
