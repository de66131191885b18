package org.robopro.kinematics;

/**
 * One elementary transformation of the seed paper's Table 1 (a rotation about or a translation
 * along an axis of the current frame) with its value and whether calibration identifies it.
 * Fixed elements keep their values (nominal or as built) so the forward kinematics stays exact.
 *
 * @param op         which elementary transformation
 * @param name       readable name, e.g. "j2.a" or "flange.tz"
 * @param value      metres or radians
 * @param identified true when the element belongs to the complete, minimal sub-model
 */
public record Elementary(Op op, String name, double value, boolean identified) {

    /** Translations T_X, T_Y, T_Z and rotations R_X, R_Y, R_Z about the current frame's axes. */
    public enum Op {
        TX, TY, TZ, RX, RY, RZ;

        public boolean isRotation() { return this == RX || this == RY || this == RZ; }

        /** 0 for x, 1 for y, 2 for z. */
        public int axis() { return ordinal() % 3; }

        /** Table 1 notation, e.g. "R_Z". */
        public String symbol() { return (isRotation() ? "R_" : "T_") + "XYZ".charAt(axis()); }
    }

    /** m = m E: applies the transformation {@code op} of {@code value} (rotations by their cosine c and sine s) to a 3x4 transform. */
    static void apply(double[] m, Op op, double value, double c, double s) {
        if (op.isRotation()) Se3.rotate(m, op.axis(), c, s);
        else Se3.translate(m, op.axis(), value);
    }

    Elementary withValue(double v) { return new Elementary(op, name, v, identified); }

    Elementary withIdentified(boolean id) { return new Elementary(op, name, value, id); }

    ModelParameter.Kind kind() {
        return op.isRotation() ? ModelParameter.Kind.ROTATION : ModelParameter.Kind.TRANSLATION;
    }
}
