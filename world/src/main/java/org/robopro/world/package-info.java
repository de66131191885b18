/**
 * An independent "real robot" and campaign simulator: the truth the calibration and diagnosis
 * benchmarks measure against, written with its own physics (product of exponentials, drive
 * errors, elasticity, thermal growth) and sharing no code with the kinematics or calibration
 * modules, so that an estimator's assumptions cannot leak into its test data.
 */
package org.robopro.world;
