/**
 * Robot programs in RAPID's terms: typed RAPID data (robtarget, tooldata, wobjdata, speeddata,
 * zonedata ...) in SI units, the typed view of a module ({@link org.robopro.programs.RapidModule},
 * read from the syntax tree by {@link org.robopro.programs.RapidParser} and mapped back to a tree
 * by {@link org.robopro.programs.RapidWriter}), teaching targets, and the compensated export of a
 * program through the calibration module's compensator
 * ({@link org.robopro.programs.compensation.ProgramCompensation}).
 */
package org.robopro.programs;
