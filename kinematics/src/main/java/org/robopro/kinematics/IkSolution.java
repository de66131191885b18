package org.robopro.kinematics;

/**
 * One inverse-kinematics solution: controller joint values q (rad / m), its configuration data,
 * whether q is inside the joint limits, and a singularity proximity measure: the manipulability
 * |det J| of the 6x6 geometric Jacobian with position rows divided by the robot's size
 * (dimensionless, 0 at a singularity; see {@link InverseKinematics#manipulability(double[])}; the
 * exact smallest singular value is {@link InverseKinematics#singularityMeasure(double[])}).
 */
public record IkSolution(double[] q, ConfData conf, boolean withinLimits, double singularityMeasure) { }
