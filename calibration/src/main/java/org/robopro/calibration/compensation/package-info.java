/**
 * Compensation (seed paper Fig. 5): the pose to command to a controller that knows only the nominal
 * model so that the real robot reaches a target. One interface with a status,
 * {@link org.robopro.calibration.compensation.TargetCompensator}, implemented once by
 * {@link org.robopro.calibration.compensation.Compensator} (geometric or extended model, plus a
 * fast batch path); and the targets file reader.
 */
package org.robopro.calibration.compensation;
