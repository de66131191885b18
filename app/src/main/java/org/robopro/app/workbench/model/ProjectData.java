package org.robopro.app.workbench.model;

import java.util.List;
import org.robopro.kinematics.Pose;
import org.robopro.models.RobotDescription;

/**
 * Everything a project file holds (docs/project-file.md): which robot and where it stands, the
 * tool, the cell objects, work objects, targets, the program, the calibration reference, the
 * work object new targets are taught in and the robot's joint values (null: the ready pose);
 * {@code source} the RAPID module the program was imported from (null: taught here), whose
 * other statements and items the program keeps ({@link ProgramModule}).
 */
public record ProjectData(String robotRef, RobotDescription robot, Pose worldTbase, Tool tool,
                          List<CellObject> objects, List<WorkObject> workObjects, List<Target> targets,
                          List<Instruction> program, String calibrationReference, String activeWorkObject, double[] q,
                          ProgramModule.Source source) {
    public ProjectData {
        objects = List.copyOf(objects);
        workObjects = List.copyOf(workObjects);
        targets = List.copyOf(targets);
        program = List.copyOf(program);
        activeWorkObject = activeWorkObject == null || activeWorkObject.isBlank() ? Target.WOBJ0 : activeWorkObject;
        q = q == null ? null : q.clone();
    }

    /** A project whose program was taught here (no imported RAPID module). */
    public ProjectData(String robotRef, RobotDescription robot, Pose worldTbase, Tool tool, List<CellObject> objects,
                       List<WorkObject> workObjects, List<Target> targets, List<Instruction> program, String calibrationReference,
                       String activeWorkObject, double[] q) {
        this(robotRef, robot, worldTbase, tool, objects, workObjects, targets, program, calibrationReference, activeWorkObject, q, null);
    }

    /** A project taught in wobj0 with the robot at its ready pose. */
    public ProjectData(String robotRef, RobotDescription robot, Pose worldTbase, Tool tool, List<CellObject> objects,
                       List<WorkObject> workObjects, List<Target> targets, List<Instruction> program, String calibrationReference) {
        this(robotRef, robot, worldTbase, tool, objects, workObjects, targets, program, calibrationReference, null, null);
    }

    @Override public double[] q() { return q == null ? null : q.clone(); }

    /** The same project with the given active work object and joint values. */
    public ProjectData withState(String active, double[] joints) {
        return new ProjectData(robotRef, robot, worldTbase, tool, objects, workObjects, targets, program, calibrationReference, active, joints, source);
    }
}
