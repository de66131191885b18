package org.robopro.models;

import java.util.List;

/**
 * A robot cell (docs/cell-file.md): the robot and where it stands, the static objects, the tools
 * and the work objects. Immutable, SI units, free of GUI types (the workbench embeds it in its
 * project file).
 *
 * @param name        identifier of the cell
 * @param robot       a shipped robot name or a robot file path (relative to the cell file), as written
 * @param worldTbase  the robot base frame seen from the world
 * @param objects     tables, fixtures, parts
 * @param tools       tools that can be mounted on the flange
 * @param workObjects user frames
 * @param signals     the I/O signals programs use (names, types, simulated inputs)
 */
public record CellDescription(String name, String robot, PoseDescription worldTbase, List<CellObject> objects,
                              List<ToolDescription> tools, List<WorkObjectDescription> workObjects, List<SignalDescription> signals) {
    public CellDescription {
        objects = List.copyOf(objects);
        tools = List.copyOf(tools);
        workObjects = List.copyOf(workObjects);
        signals = List.copyOf(signals);
    }

    /** A cell without I/O signals. */
    public CellDescription(String name, String robot, PoseDescription worldTbase, List<CellObject> objects,
                           List<ToolDescription> tools, List<WorkObjectDescription> workObjects) {
        this(name, robot, worldTbase, objects, tools, workObjects, List.of());
    }
}
