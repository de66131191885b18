/**
 * Collision and clearance of a checked program: robot links and tool as capsules, cell objects
 * as convex hulls, distances by GJK ({@link org.robopro.programs.collision.ClearanceChecker}).
 */
package org.robopro.programs.collision;
