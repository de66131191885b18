/**
 * Kinematics of serial robots: the calibration model built from a robot description (the seed
 * paper's elementary transformations, {@link org.robopro.kinematics.KinematicModel}), forward
 * kinematics and Jacobians with preallocated workspaces, inverse kinematics (closed form and
 * numerical, {@link org.robopro.kinematics.InverseKinematics}), ABB configuration data, and
 * rigid transforms at two levels: the immutable {@link org.robopro.kinematics.Pose} and the
 * allocation-free {@link org.robopro.kinematics.Se3} on arrays. SI units inside; conversions
 * at the edges through {@link org.robopro.kinematics.Units}.
 */
package org.robopro.kinematics;
