/**
 * Robot programs in RAPID's terms: modules, procedures, move instructions and RAPID data
 * (robtarget, tooldata, wobjdata, speeddata, zonedata) in SI units, teaching targets, and the
 * compensated export of a program through the calibration module's compensator
 * ({@link org.robopro.programs.compensation.ProgramCompensation}).
 */
package org.robopro.programs;
