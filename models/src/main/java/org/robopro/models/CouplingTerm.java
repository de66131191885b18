package org.robopro.models;

/**
 * One term of the joint coupling theta = C q: model angle {@code theta[joint]} receives
 * {@code factor * q[source]}. Joints are 1-based as in the files. Without any term for a joint,
 * theta_i = q_i. Example (parallel-arm ABB): theta3 = q3 - q2 is the two terms
 * (3, 3, 1) and (3, 2, -1).
 */
public record CouplingTerm(int joint, int source, double factor) { }
