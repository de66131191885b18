/**
 * Identification of the model parameters from measurements (seed paper §5): the least-squares
 * problem as parameter blocks (geometry, tool, instrument frame, effects), Levenberg-Marquardt,
 * identifiability (which parameters the data determine), error statistics and the calibration
 * result ({@link org.robopro.calibration.identification.Calibrator}).
 */
package org.robopro.calibration.identification;
