package org.robopro.app.demo;

import org.robopro.kinematics.KinematicModel;
import org.robopro.models.CellFile;
import org.robopro.programs.RapidWriter;

/** Test access to the demo's weld program. */
public final class DemoPrograms {
    private DemoPrograms() { }

    /** DemoWeld.mod as the demo writes it (two passes, taught in the shipped welding cell). */
    public static String demoWeldText() {
        var cell = CellFile.shipped("irb2000-welding");
        WeldProgram weld = WeldProgram.teach(cell, KinematicModel.build(CellFile.loadRobot(cell, null)), 2);
        return RapidWriter.export(weld.module).text();
    }
}
