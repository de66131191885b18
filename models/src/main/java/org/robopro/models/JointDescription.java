package org.robopro.models;

/**
 * One joint as the seed paper's model construction takes it (§6, Fig. 7): its type, a point on
 * its axis and the axis direction, both in base coordinates with every controller joint value at
 * zero. SI units: metres, radians (revolute) or metres (prismatic) for limits, per second for speed.
 *
 * @param name      joint name (e.g. "j1")
 * @param type      revolute or prismatic
 * @param point     a point on the joint axis, base coordinates, m
 * @param axis      unit axis direction (positive rotation by the right-hand rule / direction of motion)
 * @param min       lower limit of the controller value q (rad or m)
 * @param max       upper limit of the controller value q (rad or m)
 * @param maxSpeed  maximum joint speed (rad/s or m/s), > 0
 */
public record JointDescription(String name, JointType type, Vec3 point, Vec3 axis,
                               double min, double max, double maxSpeed) {
    public JointDescription {
        if (name == null || type == null || point == null || axis == null)
            throw new IllegalArgumentException("joint fields must not be null");
    }
}
