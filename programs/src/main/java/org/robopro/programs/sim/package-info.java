/**
 * Running a program off-line: the interpreter that turns a procedure into motion, wait and I/O
 * steps with their base poses and joint values ({@link org.robopro.programs.sim.MotionInterpreter}).
 */
package org.robopro.programs.sim;
