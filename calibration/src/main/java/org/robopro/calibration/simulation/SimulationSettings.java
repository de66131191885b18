package org.robopro.calibration.simulation;

import org.robopro.models.Vec3;

/**
 * What a simulated calibration campaign looks like. SI units.
 *
 * @param poses            training poses to measure
 * @param validatePoses    extra poses for a separate validation file (0 for none)
 * @param sigmaM           position noise per axis, m
 * @param sigmaRotRad      orientation noise per axis, rad (6-D only)
 * @param errorM           RMS flange position error of the nominal model against the true robot, m
 * @param targetErrorM     error of the measured point on the flange per axis, m
 * @param nominalTarget    where the measured point nominally sits, flange coordinates, m
 * @param sixD             also measure the tool's orientation
 * @param baseFrame        the instrument measures in the robot base frame (no unknown instrument pose)
 * @param seed             random seed: the same seed gives the same campaign
 */
public record SimulationSettings(int poses, int validatePoses, double sigmaM, double sigmaRotRad, double errorM,
                                 double targetErrorM, Vec3 nominalTarget, boolean sixD, boolean baseFrame, long seed) {
    public SimulationSettings {
        if (poses < 1) throw new IllegalArgumentException("poses must be >= 1, got " + poses);
        if (validatePoses < 0) throw new IllegalArgumentException("validate poses must be >= 0, got " + validatePoses);
        if (!(sigmaM >= 0) || !(sigmaRotRad >= 0)) throw new IllegalArgumentException("noise must be >= 0");
        if (!(errorM >= 0)) throw new IllegalArgumentException("error size must be >= 0, got " + errorM);
    }

    /** 200 poses, σ 0.02 mm, 10 mm of error, measured point 100 mm along the flange z axis, unknown instrument pose. */
    public static SimulationSettings defaults() {
        return new SimulationSettings(200, 0, 0.02e-3, 20e-6, 10e-3, 2e-3, new Vec3(0, 0, 0.1), false, false, 1);
    }

    public SimulationSettings withPoses(int n) { return new SimulationSettings(n, validatePoses, sigmaM, sigmaRotRad, errorM, targetErrorM, nominalTarget, sixD, baseFrame, seed); }
    public SimulationSettings withValidatePoses(int n) { return new SimulationSettings(poses, n, sigmaM, sigmaRotRad, errorM, targetErrorM, nominalTarget, sixD, baseFrame, seed); }
    public SimulationSettings withSigma(double m) { return new SimulationSettings(poses, validatePoses, m, sigmaRotRad, errorM, targetErrorM, nominalTarget, sixD, baseFrame, seed); }
    public SimulationSettings withSigmaRot(double rad) { return new SimulationSettings(poses, validatePoses, sigmaM, rad, errorM, targetErrorM, nominalTarget, sixD, baseFrame, seed); }
    public SimulationSettings withError(double m) { return new SimulationSettings(poses, validatePoses, sigmaM, sigmaRotRad, m, targetErrorM, nominalTarget, sixD, baseFrame, seed); }
    public SimulationSettings withSixD(boolean b) { return new SimulationSettings(poses, validatePoses, sigmaM, sigmaRotRad, errorM, targetErrorM, nominalTarget, b, baseFrame, seed); }
    public SimulationSettings withBaseFrame(boolean b) { return new SimulationSettings(poses, validatePoses, sigmaM, sigmaRotRad, errorM, targetErrorM, nominalTarget, sixD, b, seed); }
    public SimulationSettings withSeed(long s) { return new SimulationSettings(poses, validatePoses, sigmaM, sigmaRotRad, errorM, targetErrorM, nominalTarget, sixD, baseFrame, s); }
    public SimulationSettings withNominalTarget(Vec3 t) { return new SimulationSettings(poses, validatePoses, sigmaM, sigmaRotRad, errorM, targetErrorM, t, sixD, baseFrame, seed); }
}
