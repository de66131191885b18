/**
 * Simulated calibration campaigns for tests, demos and the command line's {@code simulate}: a
 * true robot with random errors on the model's own parameters, sampled poses and noisy
 * measurements. (The independent truth for benchmarks lives in the {@code world} module.)
 */
package org.robopro.calibration.simulation;
