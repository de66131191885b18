/**
 * Robot programs in RAPID's terms: typed RAPID data (robtarget, tooldata, wobjdata, speeddata,
 * zonedata ...) in SI units, the module ({@link org.robopro.programs.RapidModule}: its syntax tree
 * is the program; its typed items are a read-only view {@link org.robopro.programs.RapidParser}
 * reads from that tree; typed items built in code become tree nodes first), the export
 * ({@link org.robopro.programs.RapidWriter}: the view at a file's precision, names made valid),
 * teaching targets, and the compensated export of a
 * program through the calibration module's compensator
 * ({@link org.robopro.programs.compensation.ProgramCompensation}).
 */
package org.robopro.programs;
