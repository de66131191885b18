/**
 * Measurements: the measurement file format (docs/measurement-file.md) read with errors naming
 * file, line and field, written back, journaled during a campaign, and held as an immutable
 * {@link org.robopro.calibration.measurement.MeasurementSet}.
 */
package org.robopro.calibration.measurement;
