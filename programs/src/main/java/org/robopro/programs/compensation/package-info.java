/**
 * Compensated export of a program: every robtarget rewritten with the calibration module's
 * {@link org.robopro.calibration.compensation.TargetCompensator} so that the real robot reaches
 * what the program intends ({@link org.robopro.programs.compensation.ProgramCompensation}).
 */
package org.robopro.programs.compensation;
