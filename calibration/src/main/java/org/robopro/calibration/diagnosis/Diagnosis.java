package org.robopro.calibration.diagnosis;

import java.util.List;
import org.robopro.calibration.identification.CalibrationResult;

/**
 * What a diagnosis found (docs/diagnosis.md). SI units inside (m, rad); the report writers convert.
 *
 * @param robot            robot name
 * @param geometric        the geometric calibration the diagnosis started from
 * @param sigmaM           position noise per axis (or per distance) estimated from the final fit's residuals (degrees of freedom corrected), m
 * @param geometricTrainRmsM  RMS position error of the geometric model on the training poses (outliers excluded)
 * @param geometricValidateRmsM  same on the validation poses (NaN without validation data)
 * @param effects          the effects claimed, in the order they were selected
 * @param finalTrainRmsM   RMS after joint re-identification of geometry and effects
 * @param finalValidateRmsM  same on the validation poses
 * @param outliers         poses flagged by the calibration's outlier rule (excluded from every fit)
 * @param notIdentifiable  candidates whose signature the geometric model absorbs on these data
 * @param implausible      significant candidates rejected for an estimate outside physical bounds
 * @param recommendations  what to record next, in words
 * @param notes            other remarks (what was not tested and why)
 * @param model            the extended model (identified geometry plus effects)
 * @param finalFlangeTtool the measured point (tool frame) of the final joint fit
 * @param finalInstrumentTbase the instrument pose of the final joint fit (identity for data in the base frame)
 * @param candidatesTested size of the tested family (for the multiple-testing correction)
 * @param alpha            family-wise false-positive rate of the test
 * @param elapsedMs        wall time
 * @param directions       where the approach directions came from (recorded, inferred from the measuring order, none)
 * @param located          structures found in the residuals by the locate scan, named or not
 * @param warnings         what the report must say first (error left above the noise, what cannot be told)
 */
public record Diagnosis(String robot, CalibrationResult geometric, double sigmaM, double geometricTrainRmsM,
                        double geometricValidateRmsM, List<Finding> effects, double finalTrainRmsM,
                        double finalValidateRmsM, List<String> outliers, List<NotIdentifiable> notIdentifiable,
                        List<Finding> implausible, List<String> recommendations, List<String> notes,
                        ExtendedModel model, org.robopro.kinematics.Pose finalFlangeTtool,
                        org.robopro.kinematics.Pose finalInstrumentTbase, int candidatesTested, double alpha, double elapsedMs,
                        Directions.Source directions, List<Located> located, List<String> warnings) {

    /** This diagnosis with {@code first} (what the files themselves warn of, such as another robot's name) before its warnings. */
    public Diagnosis withWarningsFirst(List<String> first) {
        if (first.isEmpty()) return this;
        List<String> all = new java.util.ArrayList<>(first);
        all.addAll(warnings);
        return new Diagnosis(robot, geometric, sigmaM, geometricTrainRmsM, geometricValidateRmsM, effects, finalTrainRmsM,
                finalValidateRmsM, outliers, notIdentifiable, implausible, recommendations, notes, model, finalFlangeTtool,
                finalInstrumentTbase, candidatesTested, alpha, elapsedMs, directions, located, List.copyOf(all));
    }

    /** The measurements are distances (one component each), not measured points. */
    public boolean distances() { return geometric.distance(); }

    /** Measured points per pose (1 for distances). */
    public int pointsPerPose() { return geometric.distance() ? 1 : Math.max(1, geometric.toolPoints().size()); }

    /** The RMS a perfect model leaves on this noise: √3 σ for measured points, σ for distances, m. */
    public double noiseFloorM() { return Diagnoser.noiseFloor(sigmaM, distances() ? 1 : 3); }

    /** What one plotted or counted measurement is, in words: "poses", "points" or "distances". */
    public String measurementWords() { return distances() ? "distances" : pointsPerPose() > 1 ? "points" : "poses"; }

    /**
     * One effect with its evidence.
     *
     * @param effect          the effect
     * @param values          identified parameters (SI, {@link Effect#parameterNames()} order; final joint fit)
     * @param sigmas          their standard deviations
     * @param trainRmsM       training RMS of the model once this effect was added (cumulative)
     * @param validateRmsM    validation RMS of that model (NaN without validation data)
     * @param evidence        the test that selected it
     * @param plot            partial residual against the effect's regressor
     * @param words           the finding in plain words
     */
    public record Finding(Effect effect, double[] values, double[] sigmas, double trainRmsM, double validateRmsM,
                          Evidence evidence, Plot plot, String words) { }

    /**
     * The statistics of a candidate at the step it was tested.
     *
     * @param f                nested F statistic (RSS reduction per extra parameter over residual variance)
     * @param df1              extra parameters (identifiable columns)
     * @param df2              residual degrees of freedom
     * @param pValue           P(F(df1, df2) &gt; f)
     * @param threshold        the Holm–Bonferroni threshold it had to beat
     * @param rssReduction     fraction of the residual sum of squares it removes
     * @param pressBefore      leave-one-pose-out prediction error sum of squares without it (σ units)
     * @param pressAfter       with it
     * @param projectionRatio  ‖P⊥S‖/‖S‖: the part of its signature the geometry cannot absorb (smallest kept column)
     * @param absorbed         columns dropped as absorbed by the geometry (e.g. "a1", "b1")
     * @param plausibility     the physical bound checked, in words
     * @param plausible        whether the estimate is inside it
     */
    public record Evidence(double f, int df1, int df2, double pValue, double threshold, double rssReduction,
                           double pressBefore, double pressAfter, double projectionRatio, List<String> absorbed,
                           String plausibility, boolean plausible) { }

    /**
     * Evidence plot data: partial residuals (the final residual plus this effect's own
     * contribution) against the effect's regressor, with the fitted curve.
     *
     * @param xLabel      regressor axis label with unit
     * @param yLabel      residual axis label with unit
     * @param x           regressor per pose
     * @param y           partial residual per pose
     * @param curveX      fitted model, x
     * @param curveY      fitted model, y
     * @param periodogram amplitude (y units) of harmonics 1..n of the partial residual; null unless periodic
     */
    public record Plot(String xLabel, String yLabel, double[] x, double[] y, double[] curveX, double[] curveY,
                       double[] periodogram) { }

    /** A candidate the geometry absorbs: its name and how much of its signature is left (‖P⊥S‖/‖S‖). */
    public record NotIdentifiable(String effect, List<Integer> joints, String label, double ratio, String reason) { }

    /**
     * A structure the locate scan found in the residuals (after the geometric fit, or what is
     * left after the effects), whether or not a physical effect explains it.
     *
     * @param variable    the variable it follows ("joint 2 angle", "direction of joint 1", "temperature", ...)
     * @param shape       its shape in words ("7 cycles per turn of joint 2", "smooth, 7-knot spline")
     * @param sizeM       RMS of its contribution at the measured point over the poses, m
     * @param share       share of the unexplained sum of squares it removes
     * @param f           F statistic of its test
     * @param df1         its degrees of freedom
     * @param pValue      p-value
     * @param threshold   the Holm threshold it beat
     * @param stage       "geometric" (in the geometric fit's residuals) or "final" (left after the effects)
     * @param explainedBy the named effect that explains it, or null
     * @param words       in plain words
     * @param plot        evidence: the structure's partial residual against its variable
     */
    public record Located(String variable, String shape, double sizeM, double share, double f, int df1, double pValue,
                          double threshold, String stage, String explainedBy, String words, Plot plot) { }
}
