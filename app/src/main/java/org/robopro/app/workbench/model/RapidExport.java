package org.robopro.app.workbench.model;

import java.util.LinkedHashSet;
import java.util.Locale;
import java.util.Set;
import org.robopro.kinematics.ConfData;
import org.robopro.kinematics.Pose;
import org.robopro.kinematics.Units;

/**
 * Writes the workbench program as a RAPID module: the tool (tooldata), the targets the program
 * uses (robtarget, mm and quaternions in wobj0 = world coordinates, configuration data) and
 * PROC main with one MoveJ/MoveL per instruction. The workbench's own minimal writer until the
 * programs module's RAPID export is wired in.
 */
public final class RapidExport {
    private RapidExport() { }

    public static String module(String moduleName, WorkbenchModel m) {
        StringBuilder sb = new StringBuilder();
        Tool tool = m.tool();
        sb.append("MODULE ").append(moduleName).append('\n');
        sb.append("  ! Written by the robopro workbench for ").append(m.robot().displayName()).append('\n');
        Pose t = tool.flangeTtcp();
        double[] tq = t.quaternion();
        sb.append(String.format(Locale.ROOT, "  PERS tooldata %s:=[TRUE,[[%.2f,%.2f,%.2f],[%.6f,%.6f,%.6f,%.6f]],[%.2f,[0,0,%.1f],[1,0,0,0],0,0,0]];%n",
                tool.name(), Units.mToMm(t.x()), Units.mToMm(t.y()), Units.mToMm(t.z()), tq[0], tq[1], tq[2], tq[3],
                tool.massKg(), Units.mToMm(tool.bodyLength() / 2)));
        Set<String> used = new LinkedHashSet<>();
        for (Instruction i : m.program()) used.add(i.target());
        for (String name : used) {
            Target tg = m.target(name).orElseThrow(() -> new IllegalStateException("program uses unknown target " + name));
            Pose p = tg.worldTtcp();
            double[] q = p.quaternion();
            ConfData c = tg.conf();
            sb.append(String.format(Locale.ROOT,
                    "  CONST robtarget %s:=[[%.2f,%.2f,%.2f],[%.6f,%.6f,%.6f,%.6f],[%d,%d,%d,%d],[9E9,9E9,9E9,9E9,9E9,9E9]];%n",
                    name, Units.mToMm(p.x()), Units.mToMm(p.y()), Units.mToMm(p.z()), q[0], q[1], q[2], q[3],
                    c.cf1(), c.cf4(), c.cf6(), c.cfx()));
        }
        sb.append("  PROC main()\n");
        for (Instruction i : m.program())
            sb.append("    ").append(i.type().rapid()).append(' ').append(i.target()).append(", ").append(i.speedName())
                    .append(", ").append(i.zoneName()).append(", ").append(tool.name()).append("\\WObj:=wobj0;\n");
        sb.append("  ENDPROC\n");
        sb.append("ENDMODULE\n");
        return sb.toString();
    }
}
