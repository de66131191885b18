package org.robopro.calibration.report;

import java.io.IOException;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.robopro.calibration.identification.CalibrationResult;
import org.robopro.calibration.identification.CalibrationResult.ParameterEstimate;
import org.robopro.calibration.identification.CalibrationResult.PoseError;
import org.robopro.calibration.identification.ErrorStats;
import org.robopro.calibration.identification.Identifiability;
import org.robopro.calibration.identification.LevenbergMarquardt;
import org.robopro.calibration.identification.Trust;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.kinematics.Pose;
import org.robopro.kinematics.Units;

/**
 * Writes what a calibration found: {@code summary.json} (machine-readable, mm and degrees) and
 * a self-contained {@code report.html} with inline SVG plots (errors per pose before and after,
 * histograms, convergence) and the parameter table with σ.
 */
public final class CalibrationReport {
    private CalibrationReport() { }

    /** Where the data came from, for the report header. */
    public record Context(String robot, String measurements, String validation, String created) { }

    /**
     * A K-fold cross-validation: each fold's calibration, whose validation poses are the fold
     * held out.
     *
     * @param seed  seed the folds were drawn with
     * @param folds per fold, in fold order
     */
    public record CrossValidation(long seed, List<CalibrationResult> folds) {
        /** Every held-out pose error, each training pose once (predicted by the model that did not see it). */
        public List<PoseError> heldOut() {
            List<PoseError> all = new ArrayList<>();
            for (CalibrationResult f : folds) all.addAll(f.validate());
            return all;
        }
    }

    /** Position statistics of these poses in mm, as summary.json writes them. */
    static Map<String, Object> statsJson(ErrorStats st, double k, String unit) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("n", st.n());
        ErrorStats v = st.scaled(k);
        m.put("rms_" + unit, num(v.rms()));
        m.put("mean_" + unit, num(v.mean()));
        m.put("median_" + unit, num(v.median()));
        m.put("p95_" + unit, num(v.p95()));
        m.put("max_" + unit, num(v.max()));
        return m;
    }

    private static Double num(double v) { return Double.isNaN(v) ? null : v; }

    /** Nominal and calibrated statistics (position, and rotation for 6-D) of one set of poses. */
    static Map<String, Object> errorsJson(List<PoseError> es, boolean sixD) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("nominal", statsJson(ErrorStats.position(es, false), 1e3, "mm"));
        m.put("calibrated", statsJson(ErrorStats.position(es, true), 1e3, "mm"));
        if (sixD) {
            m.put("nominal_rotation", statsJson(ErrorStats.rotation(es, false), 180 / Math.PI, "deg"));
            m.put("calibrated_rotation", statsJson(ErrorStats.rotation(es, true), 180 / Math.PI, "deg"));
        }
        return m;
    }

    /** A value in display units: m → mm, rad → deg, anything else as is. */
    static double display(double v, String unitSi) {
        return switch (unitSi) {
            case "m" -> Units.mToMm(v);
            case "rad" -> Units.radToDeg(v);
            default -> v;
        };
    }

    static String displayUnit(String unitSi) {
        return switch (unitSi) {
            case "m" -> "mm";
            case "rad" -> "deg";
            default -> unitSi;
        };
    }

    private static Double mm(double m) { return Double.isNaN(m) ? null : Units.mToMm(m); }

    /** Validation RMS this many times the training RMS, and above {@link #VALIDATION_SUSPECT_M}, is suspect. */
    public static final double VALIDATION_SUSPECT_RATIO = 10;
    public static final double VALIDATION_SUSPECT_M = 1e-3;

    /**
     * Warnings about a calibration's data: a validation RMS more than 10x the training RMS and above
     * 1 mm means the validation file was almost certainly measured with another instrument set-up
     * (instrument frame) or on another robot — the instrument pose identified from the training file
     * does not hold for it — rather than that the model is bad. {@code train} and {@code validate}
     * (may be null) let the message name the metadata that differ.
     */
    public static List<String> warnings(CalibrationResult r, MeasurementSet train, MeasurementSet validate) {
        List<String> w = new ArrayList<>();
        if (r.distance()) w.add(distanceWords(r));
        String line = collinearWords(r);
        if (line != null) w.add(line);
        if (r.validate().isEmpty()) return w;
        double tr = r.trainRmsM(), va = r.validateRmsM();
        if (va > VALIDATION_SUSPECT_M && va > VALIDATION_SUSPECT_RATIO * tr) {
            StringBuilder sb = new StringBuilder(String.format(Locale.ROOT,
                    "validation RMS %.3f mm is %.0fx the training RMS %.4f mm: the validation file was probably measured with a "
                            + "different instrument set-up or robot (a different frame / instrument pose, or a simulation with another "
                            + "seed), so the instrument pose fitted on the training file does not apply to it; validate with poses "
                            + "measured in the same set-up (same session, or the file's set column)", Units.mToMm(va), va / tr, Units.mToMm(tr)));
            if (train != null && validate != null) {
                List<String> diff = new ArrayList<>();
                if (!train.frame().equalsIgnoreCase(validate.frame())) diff.add("frame '" + train.frame() + "' vs '" + validate.frame() + "'");
                for (String k : List.of("robot", "instrument")) {
                    String a = train.metadata().get(k), b = validate.metadata().get(k);
                    if (a != null && b != null && !a.equals(b)) diff.add(k + " '" + a + "' vs '" + b + "'");
                }
                if (!diff.isEmpty()) sb.append("; the files differ: ").append(String.join(", ", diff));
            }
            w.add(sb.toString());
        }
        return w;
    }

    /** Points closer than this to the line through the two farthest apart do not show the rotation about it, m. */
    static final double COLLINEAR_M = 0.005;

    /**
     * Several points per pose that lie on a line (two points always do) do not show the tool's
     * rotation about that line: the calibrated file then holds for points on that line only.
     * Null when the points span a plane, or for one point.
     */
    static String collinearWords(CalibrationResult r) {
        List<org.robopro.models.Vec3> pts = r.toolPoints();
        if (pts.size() < 2) return null;
        org.robopro.models.Vec3 a = pts.get(0), b = pts.get(1);
        for (var p : pts) for (var q : pts) if (p.minus(q).norm() > a.minus(b).norm()) { a = p; b = q; }
        org.robopro.models.Vec3 u = b.minus(a);
        double len = u.norm();
        double off = 0;
        for (var p : pts) off = Math.max(off, len == 0 ? p.minus(a).norm() : p.minus(a).cross(u).norm() / len);
        if (off >= COLLINEAR_M) return null;
        return String.format(Locale.ROOT, "the %d measured points lie on a line (within %.1f mm): the tool's rotation about that "
                + "line is not seen, so the calibrated file holds for points on that line only; a third reflector off the line "
                + "(%.0f mm or more) shows the flange's full orientation", pts.size(), Units.mToMm(off), Units.mToMm(COLLINEAR_M));
    }

    /**
     * What distance-only data cannot show, in words: a length to one anchor is unchanged when the
     * robot and the anchor move together (three translations, three rotations), so the robot's
     * placement relative to the anchor keeps its nominal value unless the anchor is given in the
     * robot base frame; each pose sees only the direction towards the anchor.
     */
    public static String distanceWords(CalibrationResult r) {
        if (r.pairs()) {
            List<String> kept = new ArrayList<>();
            for (ParameterEstimate p : r.parameters())
                if (p.fixed() && p.block().equals("geometry") && !p.name().startsWith("flange.")) kept.add(p.name());
            return "distances between pairs of poses: a length between two places of the measured point does not change when "
                    + "the whole robot is moved or turned, so where the robot stands is not observable: " + (kept.isEmpty()
                    ? "the base placement" : String.join(", ", kept)) + " keep their nominal values. The data determine the "
                    + "arm's shape (link lengths and offsets, joint zeros after joint 1) and the measured point on the flange: "
                    + "the calibrated file predicts lengths and relative motions, not absolute positions; for those, measure "
                    + "positions (x, y, z). Each pair shows only the length along the line between its two places, so vary "
                    + "the pairs' directions and lengths";
        }
        var a = r.anchor();
        String at = String.format(Locale.ROOT, "(%.3f, %.3f, %.3f) mm", Units.mToMm(a.x()), Units.mToMm(a.y()), Units.mToMm(a.z()));
        if (r.anchorGiven())
            return "distance-only data with the anchor given at " + at + " in the robot base frame: the robot's placement relative "
                    + "to it is identified, no better than the anchor's coordinates are known; each pose measures only the length "
                    + "along the line to the anchor, so spread the poses around it";
        List<String> kept = new ArrayList<>();
        for (ParameterEstimate p : r.parameters())
            if (p.fixed() && p.block().equals("geometry") && !p.name().startsWith("flange.")) kept.add(p.name());
        return "distance-only data: a length to the anchor does not change when the robot and the anchor move together, so "
                + "where the robot stands relative to the anchor is not observable: " + (kept.isEmpty() ? "the base placement"
                : String.join(", ", kept)) + " keep their nominal values and the anchor, " + at + " in the robot base frame, is found "
                + "relative to that placement. The data determine the arm's shape (link lengths and offsets, joint zeros after "
                + "joint 1) and the measured point on the flange: the calibrated file predicts lengths and relative motions, not "
                + "absolute positions; for those, measure positions (x, y, z) or give the anchor's position in the robot base "
                + "frame ('# anchor: x, y, z')";
    }

    /**
     * The summary with these {@code warnings} (see {@link #warnings}): a function of the data and
     * settings only (no date, no wall time; those are in the report), so the same campaign gives
     * the same bytes whichever front end ran it.
     */
    public static Map<String, Object> summary(CalibrationResult r, Context ctx, CrossValidation cv, List<Trust.Concern> concerns,
                                              List<String> warnings) {
        Map<String, Object> s = new LinkedHashMap<>();
        s.put("robot", ctx.robot());
        s.put("measurements", ctx.measurements());
        s.put("validation", ctx.validation());
        s.put("poses_train", CalibrationResult.poses(r.train()));
        s.put("poses_validate", CalibrationResult.poses(r.validate()));
        if (!r.pointNames().isEmpty()) {
            // Several measured points per pose: every error figure is over the points (poses x points).
            List<Map<String, Object>> pts = new ArrayList<>();
            for (int k = 0; k < r.pointNames().size(); k++) {
                Map<String, Object> e = new LinkedHashMap<>();
                e.put("name", r.pointNames().get(k));
                var t = r.toolPoints().get(k);
                e.put("flange_mm", List.of(Units.mToMm(t.x()), Units.mToMm(t.y()), Units.mToMm(t.z())));
                pts.add(e);
            }
            s.put("measured_points", pts);
        }
        if (r.distance()) {
            // Distance-only data: every error figure is a distance error |measured - predicted|.
            s.put("distance_only", true);
            if (r.pairs()) s.put("distances_between", "pairs of poses");
            else {
                var a = r.anchor();
                s.put("anchor_base_mm", List.of(Units.mToMm(a.x()), Units.mToMm(a.y()), Units.mToMm(a.z())));
                s.put("anchor", r.anchorGiven() ? "given in the file, kept" : "identified");
            }
        }
        s.put("six_d", r.sixD());
        s.put("nominal_train_rms_mm", mm(r.nominalTrainRmsM()));
        s.put("train_rms_mm", mm(r.trainRmsM()));
        s.put("nominal_validate_rms_mm", mm(r.nominalValidateRmsM()));
        s.put("validate_rms_mm", mm(r.validateRmsM()));
        s.put("nominal_train_max_mm", mm(CalibrationResult.max(r.train(), false)));
        s.put("train_max_mm", mm(r.trainMaxM()));
        s.put("validate_max_mm", mm(r.validateMaxM()));
        Map<String, Object> errors = new LinkedHashMap<>();
        errors.put("train", errorsJson(r.train(), r.sixD()));
        if (!r.validate().isEmpty()) errors.put("validate", errorsJson(r.validate(), r.sixD()));
        if (cv != null) errors.put("cross_validation", errorsJson(cv.heldOut(), r.sixD()));
        s.put("errors", errors);
        if (cv != null) {
            Map<String, Object> c = new LinkedHashMap<>();
            c.put("folds", cv.folds().size());
            c.put("seed", cv.seed());
            List<Map<String, Object>> per = new ArrayList<>();
            for (int k = 0; k < cv.folds().size(); k++) {
                CalibrationResult f = cv.folds().get(k);
                Map<String, Object> e = new LinkedHashMap<>();
                e.put("fold", k + 1);
                e.put("poses_train", CalibrationResult.poses(f.train()));
                e.put("poses_held_out", CalibrationResult.poses(f.validate()));
                e.put("train_rms_mm", mm(f.trainRmsM()));
                e.put("held_out", statsJson(ErrorStats.position(f.validate(), true), 1e3, "mm"));
                per.add(e);
            }
            c.put("per_fold", per);
            s.put("cross_validation", c);
        }
        s.put("noise_sigma_mm", mm(r.sigmaPosM()));
        if (r.sixD()) s.put("noise_sigma_deg", Units.radToDeg(r.sigmaRotRad()));
        s.put("condition_number", r.conditionNumber());
        s.put("observability_o1", r.observability());
        java.util.Set<String> untrusted = new java.util.HashSet<>();
        for (Trust.Concern c : concerns) untrusted.add(c.parameter());
        List<Map<String, Object>> ps = new ArrayList<>();
        for (ParameterEstimate p : r.parameters()) {
            Map<String, Object> e = new LinkedHashMap<>();
            e.put("name", p.name());
            e.put("block", p.block());
            e.put("nominal", display(p.nominal(), p.unitSi()));
            e.put("identified", display(p.identified(), p.unitSi()));
            e.put("sigma", p.fixed() || Double.isNaN(p.sigma()) ? null : display(p.sigma(), p.unitSi()));
            e.put("unit", displayUnit(p.unitSi()));
            e.put("fixed", p.fixed());
            e.put("trustworthy", !p.fixed() && !untrusted.contains(p.name()));
            ps.add(e);
        }
        s.put("parameters", ps);
        List<Map<String, Object>> cs = new ArrayList<>();
        for (Trust.Concern c : concerns) {
            Map<String, Object> e = new LinkedHashMap<>();
            e.put("parameter", c.parameter());
            e.put("reason", c.reason());
            e.put("advice", c.advice());
            cs.add(e);
        }
        s.put("untrustworthy", cs);
        List<Map<String, Object>> corr = new ArrayList<>();
        for (CalibrationResult.Correlation c : r.correlations()) {
            Map<String, Object> e = new LinkedHashMap<>();
            e.put("a", c.a());
            e.put("b", c.b());
            e.put("rho", c.rho());
            corr.add(e);
        }
        s.put("correlations", corr);
        List<Map<String, Object>> un = new ArrayList<>();
        for (Identifiability.Direction d : r.unidentifiable()) {
            Map<String, Object> e = new LinkedHashMap<>();
            e.put("fixed", d.fixed());
            e.put("combination", d.describe());
            un.add(e);
        }
        s.put("unidentifiable", un);
        List<Map<String, Object>> ol = new ArrayList<>();
        for (CalibrationResult.Outlier o : r.outliers()) {
            Map<String, Object> e = new LinkedHashMap<>();
            e.put("pose", o.poseId());
            e.put("residual_mm", Units.mToMm(o.residualM()));
            e.put("reason", o.reason());
            e.put("dropped", true);
            ol.add(e);
        }
        s.put("outliers", ol);
        if (r.instrumentTbase() != null) s.put("instrument_T_base", poseJson(r.instrumentTbase()));
        s.put("flange_T_tool", poseJson(r.flangeTtool()));
        Map<String, Object> solver = new LinkedHashMap<>();
        solver.put("method", "Levenberg-Marquardt (robopro, scaled normal equations)");
        solver.put("nominal_fit", lm(r.nominalFit()));
        solver.put("fit", lm(r.fit()));
        s.put("solver", solver);
        s.put("warnings", List.copyOf(warnings));
        return s;
    }

    private static Map<String, Object> lm(LevenbergMarquardt.Result f) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("iterations", f.iterations());
        m.put("evaluations", f.evaluations());
        m.put("reason", f.reason().name());
        m.put("cost_history", f.costHistory());
        return m;
    }

    /** A pose as the JSON files write it (mm, unit quaternion w x y z): summary.json and truth.json share it. */
    public static Map<String, Object> poseJson(Pose p) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("x_mm", Units.mToMm(p.x()));
        m.put("y_mm", Units.mToMm(p.y()));
        m.put("z_mm", Units.mToMm(p.z()));
        double[] q = p.quaternion();
        m.put("qw", q[0]);
        m.put("qx", q[1]);
        m.put("qy", q[2]);
        m.put("qz", q[3]);
        return m;
    }

    public static String summaryJson(CalibrationResult r, Context ctx, CrossValidation cv, List<Trust.Concern> concerns,
                                     List<String> warnings) {
        try {
            return org.robopro.models.JsonMapper.create().writeValueAsString(summary(r, ctx, cv, concerns, warnings)) + "\n";
        } catch (IOException e) {
            throw new IllegalStateException(e);
        }
    }

    // ------------------------------------------------------------------ HTML

    /** The report with these {@code warnings} shown under the header. */
    public static String html(CalibrationResult r, Context ctx, CrossValidation cv, List<Trust.Concern> concerns, List<String> warnings) {
        StringBuilder h = new StringBuilder();
        h.append("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>Calibration of ")
         .append(Html.esc(ctx.robot())).append("</title><style>")
         .append("body{font-family:sans-serif;max-width:780px;margin:1em auto;color:#222}")
         .append("table{border-collapse:collapse;font-size:12px}td,th{border:1px solid #ccc;padding:2px 6px;text-align:right}")
         .append("th{background:#eee}td.l,th.l{text-align:left}.fixed{color:#888}.warn{color:#a40}")
         .append("</style></head><body>\n");
        h.append("<h1>Calibration of ").append(Html.esc(ctx.robot())).append("</h1>\n<p>Measurements: <code>")
         .append(Html.esc(ctx.measurements())).append("</code>");
        if (ctx.validation() != null) h.append("; validation: <code>").append(Html.esc(ctx.validation())).append("</code>");
        String kind = r.sixD() ? " with orientations" : r.pairs() ? " (distances between pairs of poses)" : r.distance() ? " (distances to an anchor)"
                : r.pointNames().isEmpty() ? " (positions)" : " (" + r.pointNames().size() + " points each: " + String.join(", ", r.pointNames()) + ")";
        h.append(". ").append(CalibrationResult.poses(r.train())).append(" training poses").append(kind)
         .append(", ").append(CalibrationResult.poses(r.validate())).append(" validation poses. Created ").append(Html.esc(ctx.created())).append(".</p>\n");
        for (String w : warnings) h.append("<p class=\"warn\"><b>Warning:</b> ").append(Html.esc(w)).append("</p>\n");

        // Distances: one length error per pose; several points: one error per pose and point.
        String err = r.distance() ? "distance error (mm)" : "position error (mm)";
        String counted = r.pointNames().isEmpty() ? "poses" : "points", along = r.pointNames().isEmpty()
                ? "pose (training, then validation; each in file order)"
                : "measured point (training, then validation poses in file order, " + r.pointNames().size() + " each)";
        h.append("<h2>Result</h2><table><tr><th class=\"l\">").append(err).append("</th><th class=\"l\">model</th><th>").append(counted).append("</th>")
         .append("<th>RMS</th><th>mean</th><th>median</th><th>95th pct</th><th>max</th></tr>");
        statsRows(h, "training", r.train(), false);
        if (!r.validate().isEmpty()) statsRows(h, "validation", r.validate(), false);
        if (cv != null) statsRows(h, cv.folds().size() + "-fold cross-validation (held out)", cv.heldOut(), false);
        if (r.sixD()) {
            h.append("<tr><th class=\"l\">rotation error (deg)</th><th></th><th></th><th></th><th></th><th></th><th></th><th></th></tr>");
            statsRows(h, "training", r.train(), true);
            if (!r.validate().isEmpty()) statsRows(h, "validation", r.validate(), true);
            if (cv != null) statsRows(h, "cross-validation (held out)", cv.heldOut(), true);
        }
        h.append("</table>\n<p>The nominal rows fit only the instrument frame and the measured point with the nominal geometry. ")
         .append(String.format(Locale.ROOT, "Noise estimated from the residuals: &sigma; = %.4f mm per axis", Units.mToMm(r.sigmaPosM())));
        if (r.sixD()) h.append(String.format(Locale.ROOT, ", %.5f&deg; per axis", Units.radToDeg(r.sigmaRotRad())));
        h.append(String.format(Locale.ROOT, "; the noise floor &radic;3&middot;&sigma; = %.4f mm. ", Math.sqrt(3) * Units.mToMm(r.sigmaPosM())));
        h.append(String.format(Locale.ROOT, "Condition number of the scaled identification Jacobian %.3g, observability index O1 = %.3g (Borm &amp; Menq).</p>\n",
                r.conditionNumber(), r.observability()));

        List<Svg.Series> before = new ArrayList<>(), after = new ArrayList<>();
        // Validation errors are numbered on from the training ones, so the two sets do not overlap.
        addSeries(before, r.train(), false, "training", "#1f77b4", 0);
        addSeries(before, r.validate(), false, "validation", "#ff7f0e", r.train().size());
        addSeries(after, r.train(), true, "training", "#1f77b4", 0);
        addSeries(after, r.validate(), true, "validation", "#ff7f0e", r.train().size());
        if (cv != null) {
            h.append(String.format(Locale.ROOT, "<h2>Cross-validation</h2>\n<p>%d folds (seed %d): each fold is predicted by the model "
                    + "fitted on the other folds; every training pose is held out once.</p><table><tr><th>fold</th><th>training poses</th>"
                    + "<th>training RMS (mm)</th><th>held out</th><th>held-out RMS (mm)</th><th>held-out max (mm)</th></tr>",
                    cv.folds().size(), cv.seed()));
            for (int k = 0; k < cv.folds().size(); k++) {
                CalibrationResult f = cv.folds().get(k);
                ErrorStats st = ErrorStats.position(f.validate(), true);
                h.append("<tr><td>").append(k + 1).append("</td><td>").append(CalibrationResult.poses(f.train())).append("</td><td>")
                 .append(fmt(Units.mToMm(f.trainRmsM()))).append("</td><td>").append(st.n()).append("</td><td>")
                 .append(fmt(Units.mToMm(st.rms()))).append("</td><td>").append(fmt(Units.mToMm(st.max()))).append("</td></tr>");
            }
            h.append("</table>\n");
        }
        h.append("<h2>Error per pose</h2>\n").append(Svg.plot("Before: nominal model", along, err, before, false))
         .append("\n").append(Svg.plot("After: calibrated model", along, err, after, false,
                 // The noise floor: the RMS of a 3-D error whose components have the estimated noise sigma (σ itself for a length).
                 !Double.isFinite(r.sigmaPosM()) ? List.of() : r.distance()
                         ? List.of(new Svg.Line("noise floor σ", Units.mToMm(r.sigmaPosM()), "#2ca02c"))
                         : List.of(new Svg.Line("noise floor √3·σ", Units.mToMm(r.sigmaPosM()) * Math.sqrt(3), "#2ca02c")))).append("\n");
        List<Svg.Series> hist = new ArrayList<>();
        hist.add(new Svg.Series("training", null, values(r.train(), true), "#1f77b4", false));
        if (!r.validate().isEmpty()) hist.add(new Svg.Series("validation", null, values(r.validate(), true), "#ff7f0e", false));
        h.append(Svg.histogram("Calibrated errors", err, hist, 20)).append("\n");
        List<Svg.Series> histNom = new ArrayList<>();
        histNom.add(new Svg.Series("training", null, values(r.train(), false), "#1f77b4", false));
        if (!r.validate().isEmpty()) histNom.add(new Svg.Series("validation", null, values(r.validate(), false), "#ff7f0e", false));
        h.append(Svg.histogram("Nominal errors", err, histNom, 20)).append("\n");

        h.append("<h2>Convergence</h2>\n");
        double[] ch = r.fit().costHistory();
        double[] it = new double[ch.length];
        for (int i = 0; i < ch.length; i++) it[i] = i;
        h.append(Svg.plot("Cost ½‖r‖² per accepted step", "iteration", "cost (weighted)", List.of(new Svg.Series("cost", it, ch, "#2ca02c", true)), true));
        h.append(String.format(Locale.ROOT, "<p>Levenberg&ndash;Marquardt: %d iterations, %d evaluations, stopped: %s. Nominal fit: %d iterations, %s. Wall time %.1f ms.</p>\n",
                r.fit().iterations(), r.fit().evaluations(), r.fit().reason(), r.nominalFit().iterations(), r.nominalFit().reason(), r.elapsedMs()));

        h.append("<h2>Identifiability</h2>\n");
        if (r.unidentifiable().isEmpty()) h.append("<p>Every parameter is identifiable from these data.</p>\n");
        else {
            h.append("<p>These data cannot separate the following combinations (right singular vectors of the scaled Jacobian with a zero singular value); ")
             .append("for each, the named parameter was fixed at its nominal value (rule: the largest component, robot geometry before the measured point before the instrument frame):</p><table><tr><th class=\"l\">fixed</th><th class=\"l\">combination</th></tr>");
            for (Identifiability.Direction d : r.unidentifiable())
                h.append("<tr><td class=\"l\">").append(Html.esc(d.fixed())).append("</td><td class=\"l\">").append(Html.esc(d.describe())).append("</td></tr>");
            h.append("</table>\n");
        }

        if (concerns.isEmpty())
            h.append(String.format(Locale.ROOT, "<p>Every identified parameter is determined by the data (&sigma; &le; %.0f mm or %.1f&deg;, "
                    + "no correlation above %.2f).</p>\n", Trust.SIGMA_MM, Trust.SIGMA_DEG, Trust.CORRELATION));
        else {
            h.append("<p class=\"warn\">Identified, but not determined by these data (the calibrated file is reliable for this measured point "
                    + "only, not for another tool point or orientation):</p><table><tr><th class=\"l\">parameter</th><th class=\"l\">why</th>"
                    + "<th class=\"l\">what would fix it</th></tr>");
            for (Trust.Concern c : concerns)
                h.append("<tr><td class=\"l\">").append(Html.esc(c.parameter())).append("</td><td class=\"l\">").append(Html.esc(c.reason()))
                 .append("</td><td class=\"l\">").append(Html.esc(c.advice())).append("</td></tr>");
            h.append("</table>\n");
        }
        h.append("<h2>Outliers</h2>\n");
        if (r.outliers().isEmpty()) h.append("<p>None: no pose exceeded the outlier rule.</p>\n");
        else {
            h.append("<p class=\"warn\">Dropped from the fit and reported (rule: residual &gt; k &times; robust &sigma; from the median residual, iterated):</p><table><tr><th class=\"l\">pose</th><th>residual (mm)</th><th class=\"l\">reason</th></tr>");
            for (CalibrationResult.Outlier o : r.outliers())
                h.append("<tr><td class=\"l\">").append(Html.esc(o.poseId())).append("</td><td>").append(fmt(Units.mToMm(o.residualM())))
                 .append("</td><td class=\"l\">").append(Html.esc(o.reason())).append("</td></tr>");
            h.append("</table>\n");
        }

        h.append("<h2>Parameters</h2>\n<table><tr><th class=\"l\">name</th><th class=\"l\">block</th><th>nominal</th><th>identified</th><th>change</th><th>&sigma;</th><th class=\"l\">unit</th></tr>");
        for (ParameterEstimate p : r.parameters()) {
            String cls = p.fixed() ? " class=\"fixed\"" : "";
            double nom = display(p.nominal(), p.unitSi()), id = display(p.identified(), p.unitSi());
            h.append("<tr").append(cls).append("><td class=\"l\">").append(Html.esc(p.name())).append("</td><td class=\"l\">").append(p.block())
             .append("</td><td>").append(fmt(nom)).append("</td><td>").append(fmt(id)).append("</td><td>").append(fmt(id - nom))
             .append("</td><td>").append(p.fixed() ? "fixed" : fmt(display(p.sigma(), p.unitSi()))).append("</td><td class=\"l\">")
             .append(displayUnit(p.unitSi())).append("</td></tr>");
        }
        h.append("</table>\n<p>&sigma; from s&sup2;(J<sup>T</sup>J)<sup>&minus;1</sup>; rotation-vector parameters of the tool and instrument are reported as values of the rotation vector.</p>\n");
        h.append("</body></html>\n");
        return h.toString();
    }

    private static void statsRows(StringBuilder h, String label, List<PoseError> es, boolean rotation) {
        for (boolean calibrated : new boolean[] {false, true}) {
            ErrorStats st = (rotation ? ErrorStats.rotation(es, calibrated) : ErrorStats.position(es, calibrated))
                    .scaled(rotation ? 180 / Math.PI : 1e3);
            h.append("<tr><td class=\"l\">").append(calibrated ? "" : Html.esc(label)).append("</td><td class=\"l\">")
             .append(calibrated ? "calibrated" : "nominal").append("</td><td>").append(st.n()).append("</td><td>").append(fmt(st.rms()))
             .append("</td><td>").append(fmt(st.mean())).append("</td><td>").append(fmt(st.median())).append("</td><td>")
             .append(fmt(st.p95())).append("</td><td>").append(fmt(st.max())).append("</td></tr>");
        }
    }

    private static void addSeries(List<Svg.Series> out, List<PoseError> es, boolean calibrated, String name, String color, int first) {
        if (es.isEmpty()) return;
        double[] x = new double[es.size()];
        for (int i = 0; i < x.length; i++) x[i] = first + i + 1;
        out.add(new Svg.Series(name, x, values(es, calibrated), color, false));
    }

    private static double[] values(List<PoseError> es, boolean calibrated) {
        double[] y = new double[es.size()];
        for (int i = 0; i < y.length; i++) y[i] = Units.mToMm(calibrated ? es.get(i).calibratedM() : es.get(i).nominalM());
        return y;
    }

    static String fmt(double v) {
        if (Double.isNaN(v)) return "&ndash;";
        return String.format(Locale.ROOT, Math.abs(v) >= 100 ? "%.3f" : "%.5f", v);
    }
}
