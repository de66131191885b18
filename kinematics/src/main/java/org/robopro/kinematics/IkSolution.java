package org.robopro.kinematics;

/**
 * One inverse-kinematics solution: controller joint values q (rad / m), its configuration data,
 * whether q is inside the joint limits, and a singularity proximity measure (the smallest
 * singular value of the geometric Jacobian, scaled; near 0 means near a singularity).
 */
public record IkSolution(double[] q, ConfData conf, boolean withinLimits, double singularityMeasure) { }
