/**
 * Calibration of a robot from measurements, diagnosis of what the geometric model leaves out,
 * and compensation of targets. This package holds what the sub-packages share: the conditions a
 * pose was measured under ({@link org.robopro.calibration.PoseConditions}), progress reporting and
 * cancellation.
 */
package org.robopro.calibration;
