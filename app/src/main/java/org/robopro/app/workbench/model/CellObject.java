package org.robopro.app.workbench.model;

import java.util.Objects;
import org.robopro.kinematics.Pose;
import org.robopro.models.Vec3;

/**
 * A thing in the cell: a table, fixture, part, or an imported mesh. Its frame {@code worldTobject}
 * sits at the centre of its footprint on its underside (boxes stand on it). SI units.
 *
 * @param id           unique within the project
 * @param name         shown in the tree
 * @param kind         what it is (drives the default look)
 * @param worldTobject placement in the cell
 * @param size         box size (m) along the object's x, y, z; for meshes, the mesh scale (x = scale)
 * @param meshPath     mesh file (STL/OBJ/glTF) relative to the project, or null for a box
 * @param rgb          colour, 0xRRGGBB
 */
public record CellObject(String id, String name, Kind kind, Pose worldTobject, Vec3 size, String meshPath, int rgb) {
    public enum Kind { TABLE, FIXTURE, PART, CYLINDER, MESH }

    public CellObject {
        Objects.requireNonNull(id, "id");
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(kind, "kind");
        Objects.requireNonNull(worldTobject, "worldTobject");
        Objects.requireNonNull(size, "size");
        if (!(size.x() > 0 && size.y() > 0 && size.z() > 0) || !size.isFinite())
            throw new IllegalArgumentException("object " + id + ": size must be positive, got " + size);
    }

    public CellObject withPose(Pose p) { return new CellObject(id, name, kind, p, size, meshPath, rgb); }
    public CellObject withSize(Vec3 s) { return new CellObject(id, name, kind, worldTobject, s, meshPath, rgb); }
    public CellObject withName(String n) { return new CellObject(id, n, kind, worldTobject, size, meshPath, rgb); }
}
