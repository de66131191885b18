package org.robopro.calibration.identification;

import java.util.List;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.Vec3;

/**
 * What a calibration produced. SI units inside; the report writers convert.
 *
 * @param nominal          the model calibration started from
 * @param calibrated       the identified model
 * @param flangeTtool      identified tool frame (origin = measured point)
 * @param instrumentTbase  identified instrument pose, or null for data in the base frame
 * @param parameters       every parameter of the problem: geometry, tool, instrument, effects
 * @param unidentifiable   directions the data cannot see and the parameter fixed for each
 * @param conditionNumber  of the column-scaled Jacobian of the free parameters
 * @param observability    O1 (Borm &amp; Menq) of the free parameters
 * @param outliers         poses flagged by the outlier rule (excluded from the fit)
 * @param train            per-pose errors on the training poses
 * @param validate         per-pose errors on validation poses (empty without validation data)
 * @param nominalFit       solver diagnostics of the nominal fit (instrument and tool only)
 * @param fit              solver diagnostics of the final fit
 * @param sigmaPosM        position noise estimated from the residuals, m
 * @param sigmaRotRad      orientation noise estimated from the residuals, rad (NaN for position-only data)
 * @param sixD             orientations were used
 * @param elapsedMs        wall time of the calibration
 * @param correlations     pairs of identified parameters whose estimates are strongly correlated
 *                         (|ρ| &gt; 0.9), strongest first
 * @param pointNames       names of the measured points when there are several per pose, else empty
 * @param toolPoints       every measured point on the flange (flange coordinates, m), in point order;
 *                         the first is {@code flangeTtool}'s origin
 * @param anchor           distance data: the anchor in the robot base frame, m; null otherwise
 * @param anchorGiven      the anchor was given in the file and kept, not identified
 * @param pairs            distance data between pairs of poses (no anchor)
 */
public record CalibrationResult(KinematicModel nominal, KinematicModel calibrated, Pose flangeTtool, Pose instrumentTbase,
                                List<ParameterEstimate> parameters, List<Identifiability.Direction> unidentifiable,
                                double conditionNumber, double observability, List<Outlier> outliers,
                                List<PoseError> train, List<PoseError> validate,
                                LevenbergMarquardt.Result nominalFit, LevenbergMarquardt.Result fit,
                                double sigmaPosM, double sigmaRotRad, boolean sixD, double elapsedMs,
                                List<Correlation> correlations, List<String> pointNames, List<Vec3> toolPoints,
                                Vec3 anchor, boolean anchorGiven, boolean pairs) {

    public CalibrationResult {
        pointNames = List.copyOf(pointNames);
        toolPoints = List.copyOf(toolPoints);
    }

    /** Distance-only data, to an anchor or between pairs of poses (the errors are distance errors). */
    public boolean distance() { return anchor != null || pairs; }

    /** Correlation coefficient ρ of the estimates of parameters {@code a} and {@code b}. */
    public record Correlation(String a, String b, double rho) { }

    /**
     * One parameter. Values in SI ({@code unitSi}); {@code sigma} NaN when fixed.
     *
     * @param block {@link IdentificationProblem.Block} name in lower case
     */
    public record ParameterEstimate(String name, String block, String unitSi, double nominal, double identified,
                                    double sigma, boolean fixed) { }

    /** A pose flagged as an outlier: its residual (m) and the robust noise estimate it was compared with. */
    public record Outlier(String poseId, double residualM, double robustSigmaM, String reason) { }

    /**
     * Errors at one pose (and measured point): position error norms (m) with the nominal model
     * (after fitting only the instrument and tool) and with the calibrated model; rotation errors
     * (rad, NaN for position-only); whether the pose is an outlier; the calibrated model's position
     * error as a vector, measured minus predicted, in the measurement frame (m; null for a
     * distance); the point's name when a pose has several (else null); for a distance row the
     * calibrated model's distance error, measured minus predicted (m; else NaN), whose magnitude
     * the two norms are.
     */
    public record PoseError(String poseId, double nominalM, double calibratedM, double nominalRotRad,
                            double calibratedRotRad, boolean outlier, Vec3 calibratedErrorM, String point,
                            double distanceErrorM) {
        /** One measured point per pose. */
        public PoseError(String poseId, double nominalM, double calibratedM, double nominalRotRad,
                         double calibratedRotRad, boolean outlier, Vec3 calibratedErrorM) {
            this(poseId, nominalM, calibratedM, nominalRotRad, calibratedRotRad, outlier, calibratedErrorM, null, Double.NaN);
        }
    }

    /** RMS of position errors over non-outlier poses, m. */
    public static double rms(List<PoseError> es, boolean calibratedModel) {
        double s = 0;
        int n = 0;
        for (PoseError e : es) {
            if (e.outlier()) continue;
            double v = calibratedModel ? e.calibratedM() : e.nominalM();
            s += v * v;
            n++;
        }
        return n == 0 ? Double.NaN : Math.sqrt(s / n);
    }

    /** Largest position error over non-outlier poses, m. */
    public static double max(List<PoseError> es, boolean calibratedModel) {
        double m = Double.NaN;
        for (PoseError e : es) {
            if (e.outlier()) continue;
            double v = calibratedModel ? e.calibratedM() : e.nominalM();
            if (Double.isNaN(m) || v > m) m = v;
        }
        return m;
    }

    /** Distinct poses among these errors (several measured points of a pose count once). */
    public static int poses(List<PoseError> es) {
        return (int) es.stream().map(PoseError::poseId).distinct().count();
    }

    public double trainRmsM() { return rms(train, true); }
    public double nominalTrainRmsM() { return rms(train, false); }
    public double validateRmsM() { return rms(validate, true); }
    public double nominalValidateRmsM() { return rms(validate, false); }
    public double trainMaxM() { return max(train, true); }
    public double validateMaxM() { return max(validate, true); }

    /** The parameter with this name, or null. */
    public ParameterEstimate parameter(String name) {
        for (ParameterEstimate p : parameters) if (p.name().equals(name)) return p;
        return null;
    }
}
