/**
 * Diagnosis: the non-geometric effects (joint compliance, gear errors, backlash, thermal
 * expansion, scale and coupling errors) a geometric calibration leaves in the residuals, found by
 * stepwise selection with held-out validation ({@link org.robopro.calibration.diagnosis.Diagnoser}),
 * the extended model that predicts with them ({@link org.robopro.calibration.diagnosis.ExtendedModel})
 * and the diagnosis report (docs/diagnosis.md).
 */
package org.robopro.calibration.diagnosis;
