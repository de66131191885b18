/**
 * {@code robopro demo}: the seed paper's whole loop, headless, on a simulated controller (an
 * off-line welding program, a campaign through the link, calibration, diagnosis, compensation,
 * before and after) with its console output and HTML report.
 */
package org.robopro.app.demo;
