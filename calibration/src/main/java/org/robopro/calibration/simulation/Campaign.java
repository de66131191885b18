package org.robopro.calibration.simulation;

import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.kinematics.KinematicModel;

/**
 * A simulated campaign: the nominal model, the true robot, the settings, and what was measured.
 *
 * @param nominal         the model the calibration starts from
 * @param truth           the simulated real robot
 * @param settings        how it was made
 * @param measurements    training measurements
 * @param validation      separate validation measurements, or null
 * @param nominalErrorRmsM RMS flange position error of the nominal model against the truth over the training poses, m
 * @param morePoints      true places of measured points 2.. on the flange (m) when a pose measures several, else empty
 * @param anchor          distance-only campaigns: the anchor in the robot base frame, m; else null
 */
public record Campaign(KinematicModel nominal, TrueRobot truth, SimulationSettings settings, MeasurementSet measurements,
                       MeasurementSet validation, double nominalErrorRmsM, java.util.List<org.robopro.models.Vec3> morePoints,
                       org.robopro.models.Vec3 anchor) {
    public Campaign {
        morePoints = java.util.List.copyOf(morePoints);
    }

    /** A campaign of one measured point per pose. */
    public Campaign(KinematicModel nominal, TrueRobot truth, SimulationSettings settings, MeasurementSet measurements,
                    MeasurementSet validation, double nominalErrorRmsM) {
        this(nominal, truth, settings, measurements, validation, nominalErrorRmsM, java.util.List.of(), null);
    }
}
