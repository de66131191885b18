package org.robopro.calibration.workflow;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.robopro.calibration.Cancellation;
import org.robopro.calibration.Progress;
import org.robopro.calibration.identification.CalibrationResult;
import org.robopro.calibration.identification.Calibrator;
import org.robopro.calibration.identification.Trust;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.measurement.MeasurementReader;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.calibration.report.CalibrationReport;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.kinematics.Units;
import org.robopro.models.OutputSet;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotFile;

/**
 * The calibration job from a measurement file to its output folder, the one implementation the
 * command line, the workbench and the demo call, so the same data and settings give the same
 * figures and byte-identical {@code summary.json}:
 * <ol>
 * <li>{@link #load}: read the campaign and choose the validation poses: a {@code --validate} file,
 *     else the file's {@code set} column, else a hold-out of every n-th pose, else none;
 *     metadata that disagree with the robot become warnings;</li>
 * <li>{@link #run}: identification with the outlier policy of the settings
 *     ({@link Calibrator}), and with {@code folds} &ge; 2 a K-fold cross-validation of the training
 *     poses (folds drawn reproducibly from {@code foldSeed});</li>
 * <li>{@link Outcome#write}: {@code calibrated.robot.json} (with provenance), {@code summary.json},
 *     {@code residuals.csv} and {@code report.html}, written whole or not at all.</li>
 * </ol>
 * {@code summary.json} depends only on the data and the settings (file names, not paths; no clock):
 * the date and the wall time are in the report and in the calibrated file's provenance.
 */
public final class CalibrationWorkflow {
    private CalibrationWorkflow() { }

    /** Output file names inside the output folder. */
    public static final String ROBOT_FILE = "calibrated.robot.json", SUMMARY = "summary.json", RESIDUALS = "residuals.csv",
            REPORT = "report.html";

    /**
     * How to calibrate (how to split is {@link #load}'s business).
     *
     * @param folds           K of the K-fold cross-validation of the training poses; 0 for none
     * @param foldSeed        seed of the fold assignment (same seed, same folds)
     * @param initialTool     start of the tool frame (origin = measured point), flange coordinates
     * @param outlierK        outlier threshold in robust sigmas
     * @param rejectOutliers  drop flagged poses from the fit (else report them only)
     * @param knownInstrument a known instrument pose (instrument_T_base) to start from; null for none
     * @param fixInstrument   keep {@code knownInstrument} (a trusted registration) instead of identifying it
     * @param fixTool         keep {@code initialTool} (a trusted tool, e.g. from hand-eye calibration)
     */
    public record Settings(int folds, long foldSeed, Pose initialTool, double outlierK, boolean rejectOutliers,
                           Pose knownInstrument, boolean fixInstrument, boolean fixTool) {
        public Settings {
            if (folds < 0 || folds == 1) throw new IllegalArgumentException("--folds must be at least 2, got " + folds);
            if (!(outlierK > 0)) throw new IllegalArgumentException("--outlier-k must be > 0, got " + outlierK);
            if (fixInstrument && knownInstrument == null) throw new IllegalArgumentException("a fixed instrument pose needs its value");
        }

        public static Settings defaults() { return new Settings(0, 1, Pose.IDENTITY, 5.0, true, null, false, false); }

        public Settings withFolds(int k, long seed) { return new Settings(k, seed, initialTool, outlierK, rejectOutliers, knownInstrument, fixInstrument, fixTool); }
        public Settings withInitialTool(Pose t) { return new Settings(folds, foldSeed, t, outlierK, rejectOutliers, knownInstrument, fixInstrument, fixTool); }
        public Settings withOutliers(double k, boolean reject) { return new Settings(folds, foldSeed, initialTool, k, reject, knownInstrument, fixInstrument, fixTool); }
        /** Starts from, or with {@code fix} keeps, a known instrument pose. */
        public Settings withInstrument(Pose instrumentTbase, boolean fix) { return new Settings(folds, foldSeed, initialTool, outlierK, rejectOutliers, instrumentTbase, fix, fixTool); }
        /** Starts from, or with {@code fix} keeps, a known tool frame. */
        public Settings withTool(Pose flangeTtool, boolean fix) { return new Settings(folds, foldSeed, flangeTtool, outlierK, rejectOutliers, knownInstrument, fixInstrument, fix); }

        Calibrator.Options options(Cancellation cancel, Progress progress) {
            Calibrator.Options o = Calibrator.Options.defaults().withInitialTool(initialTool).withOutliers(outlierK, rejectOutliers)
                    .withCancel(cancel).withProgress(progress).withToolFixed(fixTool);
            return knownInstrument == null ? o : o.withInstrument(knownInstrument, fixInstrument);
        }
    }

    /**
     * A campaign split into training and validation poses.
     *
     * @param file     the measurement file
     * @param all      every pose of the file
     * @param validate validation poses, or null
     * @param source   where the validation poses came from (for the reports), or null
     * @param warnings metadata that disagree with the robot or between the files
     */
    public record Campaign(Path file, MeasurementSet all, MeasurementSet train, MeasurementSet validate, String source,
                           List<String> warnings) { }

    /**
     * Reads {@code file} (and {@code validateFile}, may be null) for {@code robot} and chooses the
     * validation poses: the validation file, else the {@code set} column, else every
     * (1/holdout)-th pose when {@code holdout} is given, else none.
     */
    public static Campaign load(RobotDescription robot, Path file, Path validateFile, Double holdout) throws IOException {
        if (holdout != null && !(holdout > 0 && holdout < 1))
            throw new IllegalArgumentException("--holdout must be between 0 and 1, got " + holdout);
        MeasurementSet all = MeasurementReader.read(file, robot);
        String name = fileName(file);
        MeasurementSet train = all, validate = null;
        String source = null;
        if (validateFile != null) {
            validate = MeasurementReader.read(validateFile, robot);
            source = fileName(validateFile);
        } else if (all.hasSplit()) {
            MeasurementSet v = all.split(Measurement.Split.VALIDATE);
            train = all.split(Measurement.Split.TRAIN);
            if (v.size() > 0) {
                validate = v;
                source = name + " (set=validate)";
            }
        } else if (holdout != null) {
            List<Measurement>[] parts = holdout(all.rows(), holdout);
            train = all.withRows(parts[0]);
            validate = all.withRows(parts[1]);
            source = name + String.format(Locale.ROOT, " (hold-out: every %d%s pose)", every(holdout), ordinal(every(holdout)));
        }
        List<String> warnings = new ArrayList<>();
        metadataWarnings(robot, name, all, warnings);
        if (validate != null && validateFile != null) metadataWarnings(robot, fileName(validateFile), validate, warnings);
        return new Campaign(file, all, train, validate, source, List.copyOf(warnings));
    }

    /** The hold-out rule: every n-th pose (n = round(1/fraction), at least 2), the last of each n, validates. */
    @SuppressWarnings("unchecked")
    public static List<Measurement>[] holdout(List<Measurement> rows, double fraction) {
        List<Measurement> tr = new ArrayList<>(), va = new ArrayList<>();
        for (int i = 0; i < rows.size(); i++) (heldOut(i, fraction) ? va : tr).add(rows.get(i));
        return new List[] {tr, va};
    }

    /** Whether the pose at {@code index} (0-based, file order) is held out by {@link #holdout}. */
    public static boolean heldOut(int index, double fraction) {
        int n = every(fraction);
        return index % n == n - 1;
    }

    private static int every(double fraction) { return (int) Math.max(2, Math.round(1 / fraction)); }

    private static String ordinal(int n) {
        return n % 100 >= 11 && n % 100 <= 13 ? "th" : switch (n % 10) { case 1 -> "st"; case 2 -> "nd"; case 3 -> "rd"; default -> "th"; };
    }

    private static void metadataWarnings(RobotDescription robot, String name, MeasurementSet s, List<String> out) {
        String measured = s.robot();
        if (measured != null && !measured.equalsIgnoreCase(robot.name()))
            out.add(String.format(Locale.ROOT, "%s was measured on '%s', but the robot given is '%s'", name, measured, robot.name()));
    }

    static String fileName(Path p) {
        Path f = p.getFileName();
        return f == null ? p.toString() : f.toString();
    }

    /** A fit on the training part of one fold, evaluated on its held-out part. */
    public interface FoldFit<T> {
        T fit(int fold, MeasurementSet train, MeasurementSet heldOut);
    }

    /**
     * K-fold cross-validation of any fit (calibration, diagnosis): the poses of {@code data} split
     * by {@link #folds}, {@code fit} called once per fold with the other folds as training data
     * and the fold as held-out data; the results in fold order.
     */
    public static <T> List<T> crossValidate(MeasurementSet data, int k, long seed, FoldFit<T> fit) {
        return crossValidate(data, MeasurementSet.folds(data.size(), k, seed), k, fit);
    }

    /** {@link #crossValidate(MeasurementSet, int, long, FoldFit)} over a given split: {@code fold} holds each pose's fold, 0..k-1. */
    public static <T> List<T> crossValidate(MeasurementSet data, int[] fold, int k, FoldFit<T> fit) {
        List<T> out = new ArrayList<>();
        for (int f = 0; f < k; f++) {
            MeasurementSet.FoldSplit s = data.foldSplit(fold, f);
            out.add(fit.fit(f, s.train(), s.heldOut()));
        }
        return out;
    }

    /**
     * One fold of the cross-validation: the model fitted without it, and its errors.
     *
     * @param fold   0-based fold number
     * @param result calibration on the other folds, validated on this one
     */
    public record Fold(int fold, CalibrationResult result) { }

    /**
     * What a run produced.
     *
     * @param campaign   the data
     * @param settings   the settings
     * @param result     the calibration on every training pose
     * @param folds      per fold (empty without cross-validation)
     * @param foldOf     fold of each training pose, by pose id (empty without cross-validation)
     * @param concerns   identified parameters the data do not determine ({@link Trust})
     * @param warnings   metadata, validation and identifiability warnings, in the order shown
     * @param calibrated the calibrated robot with provenance
     * @param created    when the run finished (ISO-8601, seconds), for the report and provenance
     */
    public record Outcome(Campaign campaign, Settings settings, CalibrationResult result, List<Fold> folds, Map<String, Integer> foldOf,
                          List<Trust.Concern> concerns, List<String> warnings, RobotDescription calibrated, String created) {

        public CalibrationReport.Context context() {
            return new CalibrationReport.Context(calibrated.provenance().getOrDefault("calibrated-nominal", calibrated.name()),
                    fileName(campaign.file()), campaign.source(), created);
        }

        /** summary.json: a function of the data and settings only. */
        public String summaryJson() {
            return CalibrationReport.summaryJson(result, context(), crossValidation(), concerns, warnings);
        }

        /** report.html. */
        public String reportHtml() {
            return CalibrationReport.html(result, context(), crossValidation(), concerns, warnings);
        }

        /** The cross-validation for the reports, or null without folds. */
        public CalibrationReport.CrossValidation crossValidation() {
            if (folds.isEmpty()) return null;
            return new CalibrationReport.CrossValidation(settings.foldSeed(), folds.stream().map(Fold::result).toList());
        }

        /**
         * residuals.csv: one row per pose (training then validation, file order): id, set, fold
         * (1-based; empty when not cross-validated or for validation poses), outlier flag, the
         * nominal model's error norm, the calibrated model's error (measured minus predicted, in
         * the measurement frame) and its norm, in mm; for 6-D data the rotation errors in degrees;
         * with folds, the error of the model that did not see the pose. With several measured points
         * per pose, one row per pose and point (a {@code point} column after the pose); for
         * distance data the distance error {@code dd_mm} (measured minus predicted) instead of the vector.
         */
        public String residualsCsv() {
            boolean sixD = result.sixD(), cv = !folds.isEmpty(), multi = !result.pointNames().isEmpty(), dist = result.distance();
            Map<String, CalibrationResult.PoseError> heldOut = new LinkedHashMap<>();
            for (Fold f : folds) for (CalibrationResult.PoseError e : f.result().validate()) heldOut.put(key(e), e);
            if (dist) return distanceCsv(heldOut);
            StringBuilder b = new StringBuilder(multi ? "pose,point,set,fold,outlier,nominal_mm,dx_mm,dy_mm,dz_mm,norm_mm"
                    : "pose,set,fold,outlier,nominal_mm,dx_mm,dy_mm,dz_mm,norm_mm");
            if (sixD) b.append(",nominal_deg,rotation_deg");
            if (cv) b.append(",cv_dx_mm,cv_dy_mm,cv_dz_mm,cv_norm_mm").append(sixD ? ",cv_rotation_deg" : "");
            b.append('\n');
            for (int pass = 0; pass < 2; pass++) {
                for (CalibrationResult.PoseError e : pass == 0 ? result.train() : result.validate()) {
                    Integer f = pass == 0 ? foldOf.get(e.poseId()) : null;
                    b.append(csv(e.poseId())).append(',');
                    if (multi) b.append(csv(e.point())).append(',');
                    b.append(pass == 0 ? "train" : "validate").append(',')
                     .append(f == null ? "" : Integer.toString(f + 1)).append(',').append(e.outlier()).append(',')
                     .append(num(Units.mToMm(e.nominalM())));
                    vector(b, e);
                    if (sixD) b.append(',').append(num(Math.toDegrees(e.nominalRotRad()))).append(',').append(num(Math.toDegrees(e.calibratedRotRad())));
                    if (cv) {
                        CalibrationResult.PoseError h = pass == 0 ? heldOut.get(key(e)) : null;
                        if (h == null) b.append(",,,,").append(sixD ? "," : "");
                        else {
                            vector(b, h);
                            if (sixD) b.append(',').append(num(Math.toDegrees(h.calibratedRotRad())));
                        }
                    }
                    b.append('\n');
                }
            }
            return b.toString();
        }

        private static String key(CalibrationResult.PoseError e) {
            return e.point() == null ? e.poseId() : e.poseId() + '\u0000' + e.point();
        }

        private String distanceCsv(Map<String, CalibrationResult.PoseError> heldOut) {
            boolean cv = !folds.isEmpty();
            StringBuilder b = new StringBuilder("pose,set,fold,outlier,nominal_mm,dd_mm,norm_mm");
            if (cv) b.append(",cv_dd_mm,cv_norm_mm");
            b.append('\n');
            for (int pass = 0; pass < 2; pass++) {
                for (CalibrationResult.PoseError e : pass == 0 ? result.train() : result.validate()) {
                    Integer f = pass == 0 ? foldOf.get(e.poseId()) : null;
                    b.append(csv(e.poseId())).append(',').append(pass == 0 ? "train" : "validate").append(',')
                     .append(f == null ? "" : Integer.toString(f + 1)).append(',').append(e.outlier()).append(',')
                     .append(num(Units.mToMm(e.nominalM()))).append(',').append(num(Units.mToMm(e.distanceErrorM()))).append(',')
                     .append(num(Units.mToMm(e.calibratedM())));
                    if (cv) {
                        CalibrationResult.PoseError h = pass == 0 ? heldOut.get(key(e)) : null;
                        if (h == null) b.append(",,");
                        else b.append(',').append(num(Units.mToMm(h.distanceErrorM()))).append(',').append(num(Units.mToMm(h.calibratedM())));
                    }
                    b.append('\n');
                }
            }
            return b.toString();
        }

        private static void vector(StringBuilder b, CalibrationResult.PoseError e) {
            var v = e.calibratedErrorM();
            b.append(',').append(num(Units.mToMm(v.x()))).append(',').append(num(Units.mToMm(v.y()))).append(',')
             .append(num(Units.mToMm(v.z()))).append(',').append(num(Units.mToMm(e.calibratedM())));
        }

        /** Writes the four files into {@code dir}, whole or not at all; {@code overwrite} false refuses existing files. */
        public void write(Path dir, boolean overwrite) throws IOException {
            OutputSet.in(dir, overwrite).addString(ROBOT_FILE, RobotFile.format(calibrated)).addString(SUMMARY, summaryJson())
                    .addString(RESIDUALS, residualsCsv()).addString(REPORT, reportHtml()).commit();
        }
    }

    private static String num(double v) {
        return Double.isNaN(v) ? "" : String.format(Locale.ROOT, "%.6f", v);
    }

    private static String csv(String s) {
        return s.contains(",") || s.contains("\"") ? '"' + s.replace("\"", "\"\"") + '"' : s;
    }

    /**
     * Calibrates {@code robot} from the campaign; blocking (throws CancellationException when
     * {@code cancel} fires). {@code created} is the timestamp recorded in the report and the
     * calibrated file (ISO-8601).
     */
    public static Outcome run(RobotDescription robot, Campaign c, Settings s, String created, Cancellation cancel, Progress progress) {
        KinematicModel nominal = KinematicModel.build(robot);
        List<Fold> folds = new ArrayList<>();
        Map<String, Integer> foldOf = new LinkedHashMap<>();
        Progress main = progress;
        if (s.folds() >= 2) {
            List<Measurement> rows = c.train().rows();
            int[] fold = MeasurementSet.folds(rows.size(), s.folds(), s.foldSeed());
            for (int i = 0; i < rows.size(); i++) foldOf.put(rows.get(i).poseId(), fold[i]);
            double share = 1.0 / (s.folds() + 1);
            List<CalibrationResult> rs = crossValidate(c.train(), s.folds(), s.foldSeed(), (k, tr, va) -> Calibrator.calibrate(nominal, tr, va,
                    s.options(cancel, (stage, f) -> progress.update("fold " + (k + 1) + ": " + stage, share * (k + f)))));
            for (int k = 0; k < rs.size(); k++) folds.add(new Fold(k, rs.get(k)));
            main = (stage, f) -> progress.update(stage, share * (s.folds() + f));
        }
        CalibrationResult r = Calibrator.calibrate(nominal, c.train(), c.validate(), s.options(cancel, main));
        List<String> warnings = new ArrayList<>(c.warnings());
        warnings.addAll(CalibrationReport.warnings(r, c.train(), c.validate()));
        List<Trust.Concern> concerns = Trust.assess(r, c.train());
        for (Trust.Concern k : concerns) warnings.add(k.sentence());
        OutlierHint.sentence(r.outliers().stream().map(CalibrationResult.Outlier::poseId).toList(), c.train().rows()).ifPresent(warnings::add);
        Map<String, String> prov = new LinkedHashMap<>(robot.provenance());
        prov.put("calibrated-from", fileName(c.file()));
        prov.put("calibrated-on", created);
        prov.put("calibrated-nominal", robot.name());
        if (c.all().robot() != null) prov.put("calibration-measured-robot", c.all().robot());
        String instrument = c.all().metadata().get("instrument");
        if (instrument != null) prov.put("calibration-instrument", instrument);
        if (c.source() != null) prov.put("calibration-validated-on", c.source());
        prov.put("calibration-train-rms-mm", String.format(Locale.ROOT, "%.5f", Units.mToMm(r.trainRmsM())));
        if (c.validate() != null) prov.put("calibration-validate-rms-mm", String.format(Locale.ROOT, "%.5f", Units.mToMm(r.validateRmsM())));
        prov.put("calibration-untrustworthy-parameters", Trust.provenance(concerns));
        if (s.knownInstrument() != null) prov.put("calibration-instrument-pose", s.fixInstrument() ? "given, kept fixed" : "given as the start");
        if (s.fixTool()) prov.put("calibration-tool", "given, kept fixed");
        var p = r.flangeTtool().position();
        prov.put("calibration-measured-point-mm", String.format(Locale.ROOT, "%.5f,%.5f,%.5f",
                Units.mToMm(p.x()), Units.mToMm(p.y()), Units.mToMm(p.z())));
        if (!r.pointNames().isEmpty()) {
            List<String> pts = new ArrayList<>();
            for (int k = 0; k < r.pointNames().size(); k++) {
                var t = r.toolPoints().get(k);
                pts.add(String.format(Locale.ROOT, "%s: %.5f,%.5f,%.5f", r.pointNames().get(k),
                        Units.mToMm(t.x()), Units.mToMm(t.y()), Units.mToMm(t.z())));
            }
            prov.put("calibration-measured-points-mm", String.join("; ", pts));
        }
        if (r.pairs()) prov.put("calibration-distances", "between pairs of poses (no anchor)");
        else if (r.distance()) {
            var a = r.anchor();
            prov.put("calibration-anchor-mm", String.format(Locale.ROOT, "%.5f,%.5f,%.5f%s", Units.mToMm(a.x()), Units.mToMm(a.y()),
                    Units.mToMm(a.z()), r.anchorGiven() ? " (given)" : " (identified, base frame)"));
        }
        RobotDescription calibrated = r.calibrated().toDescription().withProvenance(prov);
        return new Outcome(c, s, r, List.copyOf(folds), Collections.unmodifiableMap(foldOf), concerns, List.copyOf(warnings), calibrated, created);
    }
}
