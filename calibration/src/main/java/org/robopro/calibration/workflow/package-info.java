/**
 * The calibration job as the front ends run it: campaign split, identification, cross-validation,
 * provenance and the output folder ({@link org.robopro.calibration.workflow.CalibrationWorkflow}).
 */
package org.robopro.calibration.workflow;
