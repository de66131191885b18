package org.robopro.app.workbench.model;

import java.util.List;
import org.robopro.kinematics.Pose;
import org.robopro.models.RobotDescription;

/**
 * Everything a project file holds (docs/project-file.md): which robot and where it stands, the
 * tool, the cell objects, work objects, targets, the program and the calibration reference.
 */
public record ProjectData(String robotRef, RobotDescription robot, Pose worldTbase, Tool tool,
                          List<CellObject> objects, List<WorkObject> workObjects, List<Target> targets,
                          List<Instruction> program, String calibrationReference) {
    public ProjectData {
        objects = List.copyOf(objects);
        workObjects = List.copyOf(workObjects);
        targets = List.copyOf(targets);
        program = List.copyOf(program);
    }
}
