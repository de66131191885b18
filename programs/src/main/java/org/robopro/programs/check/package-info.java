/**
 * The path check of a program: reachability along the sampled path, joint limits, configuration
 * changes, singularities, degenerate circles and cycle time ({@link org.robopro.programs.check.PathChecker}).
 */
package org.robopro.programs.check;
