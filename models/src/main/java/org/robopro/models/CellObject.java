package org.robopro.models;

/**
 * A static object of a robot cell (table, fixture, part, fence). SI units.
 *
 * @param name      unique within the cell
 * @param kind      box, cylinder or mesh
 * @param worldTobject pose of the object's frame in the world: the centre of a box or cylinder
 *                  (cylinder axis along the object's z), the mesh's own origin for a mesh
 * @param size      box: lengths along x, y, z; cylinder: diameter, diameter, height (m); mesh: unused (zero)
 * @param colour    display colour
 * @param meshPath  mesh file relative to the cell file (mesh only; empty otherwise)
 * @param meshScale mesh units to metres (mesh only; 1 otherwise)
 */
public record CellObject(String name, Kind kind, PoseDescription worldTobject, Vec3 size, Rgba colour,
                         String meshPath, double meshScale) {
    public enum Kind {
        BOX, CYLINDER, MESH;

        public String fileName() { return name().toLowerCase(java.util.Locale.ROOT); }

        /** "box", "cylinder", "mesh"; null if unknown. */
        public static Kind parse(String s) {
            for (Kind k : values()) if (k.fileName().equals(s)) return k;
            return null;
        }
    }
}
