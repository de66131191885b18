/**
 * Calibration reports: {@code summary.json} and a self-contained HTML page with inline SVG plots.
 */
package org.robopro.calibration.report;
