package org.robopro.kinematics;

import java.util.List;

/**
 * The constant part of one transformation between consecutive frames: {@code index} 0 is the
 * base to joint 1 frame, index k (1..n) leads out of joint k (to joint k+1, or to the flange for
 * k = n) and is preceded by the joint's own motion R_Z(theta_k) or T_Z(theta_k).
 *
 * @param index      0 (base) .. n (last joint to flange)
 * @param label      e.g. "base -> j1", "j2 -> j3", "j6 -> flange"
 * @param convention which Table 1 row built it: "base-x", "base-y", "base-z", "DH", "Hayati",
 *                   "TCP-ZYX" or "TCP-ZYZ"
 * @param axisAngle  angle between the two joint axes (rad), NaN for the base and flange rows
 * @param elements   the elementary transformations in order of application
 */
public record Transformation(int index, String label, String convention, double axisAngle,
                             List<Elementary> elements) {
    public Transformation {
        elements = List.copyOf(elements);
    }

    Transformation withElements(List<Elementary> newElements) {
        return new Transformation(index, label, convention, axisAngle, newElements);
    }
}
