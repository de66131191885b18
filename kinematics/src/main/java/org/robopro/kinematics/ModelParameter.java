package org.robopro.kinematics;

/**
 * One identifiable parameter of a kinematic model: e.g. name "p2.tx" (translation along x in
 * the transformation into joint frame 2), its kind (translation in m / rotation in rad), the
 * transformation index it belongs to and its nominal value.
 */
public record ModelParameter(String name, Kind kind, int transform, double nominal) {
    public enum Kind { TRANSLATION, ROTATION }

    public String unitSi() { return kind == Kind.TRANSLATION ? "m" : "rad"; }
}
