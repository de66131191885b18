package org.robopro.app.demo;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.robopro.calibration.identification.CalibrationResult;
import org.robopro.calibration.report.Html;
import org.robopro.calibration.report.Svg;
import org.robopro.kinematics.Units;

/** The demo's outputs: the before/after table, {@code demo.json} and the self-contained {@code report.html}. */
final class DemoReport {
    private DemoReport() { }

    /** The concealed effect's label ("backlash j2", diagnosis' vocabulary) from the controller's truth file; "none" without one. */
    static String concealedEffect(Path truthFile) throws IOException {
        JsonNode effects = Json.read(Files.readString(truthFile)).path("effects");
        List<String> labels = new ArrayList<>();
        effects.forEach(e -> labels.add(e.path("label").asText()));
        return labels.isEmpty() ? "none" : String.join(", ", labels);
    }

    static String table(Demo.Result r) {
        StringBuilder sb = new StringBuilder();
        sb.append(String.format(Locale.ROOT, "%-34s %10s %10s%n", "target error of the welding program", "mean (mm)", "max (mm)"));
        row(sb, "nominal (off-line, uncalibrated)", r.nominal());
        row(sb, "geometric calibration", r.calibrated());
        row(sb, "with the diagnosed effect", r.diagnosed());
        sb.append(String.format(Locale.ROOT, "%-34s %10.4f%n", "noise floor (√3·σ of the tracker)", r.noiseFloorMm()));
        return sb.toString();
    }

    private static void row(StringBuilder sb, String label, Demo.Run run) {
        sb.append(String.format(Locale.ROOT, "%-34s %10.4f %10.4f%n", label, run.meanMm(), run.maxMm()));
    }

    private static Double round(double mm) { return Double.isFinite(mm) ? Math.round(mm * 1e5) / 1e5 : null; }

    /** {@code demo.json}: exactly the table's numbers and the effects. */
    static String json(Demo.Result r) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("nominal_mean_mm", round(r.nominal().meanMm()));
        m.put("nominal_max_mm", round(r.nominal().maxMm()));
        m.put("calibrated_mean_mm", round(r.calibrated().meanMm()));
        m.put("calibrated_max_mm", round(r.calibrated().maxMm()));
        m.put("diagnosed_mean_mm", round(r.diagnosed().meanMm()));
        m.put("diagnosed_max_mm", round(r.diagnosed().maxMm()));
        m.put("concealed_effect", r.concealedEffect());
        m.put("named_effects", r.namedEffects());
        return Json.write(m);
    }

    static String html(Demo.Result r, Demo.Options o, CalibrationResult cal, DiagnosisStep.Outcome diag, List<String> targetNames,
                       String created) {
        StringBuilder h = new StringBuilder();
        h.append("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>robopro demo</title><style>")
         .append("body{font-family:sans-serif;max-width:780px;margin:1em auto;color:#222}")
         .append("table{border-collapse:collapse;font-size:13px}td,th{border:1px solid #ccc;padding:2px 8px;text-align:right}")
         .append("th{background:#eee}td.l,th.l{text-align:left}")
         .append("</style></head><body>\n");
        h.append("<h1>robopro demo: an off-line program, calibrated</h1>\n<p>")
         .append(String.format(Locale.ROOT, "Seed %d, concealed effect chosen: <code>%s</code>, %d campaign poses, %d welding passes. "
                 + "Created %s; the whole loop took %.1f s.</p>\n", o.seed(), Html.esc(o.effect()), o.poses(), o.passes(),
                 Html.esc(created), r.elapsedS()));
        h.append("<p>A simulated IRB-2000 controller (its own process, open_abb protocol on TCP) drives a robot with seeded "
                + "geometric errors and one concealed non-geometric effect. A welding program taught off-line on the nominal "
                + "model was run and its TCP measured by the controller's laser tracker at every target; then a measurement "
                + "campaign through the controller link, a geometric calibration and a diagnosis modelled the robot, and the "
                + "program compensated with each model (seed paper Fig. 5) was run and measured again. Errors are tracker "
                + "readings in the robot base frame as the calibration registered the tracker, against the programmed TCP "
                + "positions.</p>\n");
        h.append("<h2>Target errors</h2>\n<table><tr><th class=\"l\">program</th><th>mean (mm)</th><th>max (mm)</th></tr>");
        hrow(h, "nominal (off-line, uncalibrated)", r.nominal());
        hrow(h, "geometric calibration", r.calibrated());
        hrow(h, "with the diagnosed effect", r.diagnosed());
        h.append(String.format(Locale.ROOT, "</table>\n<p>Noise floor of the tracker (&radic;3&middot;&sigma;, &sigma; = %.3f mm "
                + "per axis): %.4f mm. Concealed effect: <b>%s</b>; named by the diagnosis: <b>%s</b>.</p>\n", Demo.NOISE_MM, r.noiseFloorMm(),
                Html.esc(r.concealedEffect()), r.namedEffects().isEmpty() ? "nothing"
                        : Html.esc(String.join(", ", r.namedEffects()))));

        List<Svg.Series> per = new ArrayList<>();
        per.add(series("nominal", r.nominal(), "#d62728"));
        per.add(series("geometric calibration", r.calibrated(), "#1f77b4"));
        per.add(series("diagnosed effect", r.diagnosed(), "#2ca02c"));
        h.append(Svg.plot("Error at each target of the welding program (log scale)", "target (program order)",
                "error (mm, log scale)", per, true)).append("\n<p>Targets: ");
        for (int i = 0; i < targetNames.size(); i++) h.append(i == 0 ? "" : ", ").append(i + 1).append(" ").append(Html.esc(targetNames.get(i)));
        h.append(".</p>\n");

        h.append("<h2>Calibration</h2>\n").append(String.format(Locale.ROOT, "<p>%d training and %d validation poses: "
                        + "validation RMS %.3f mm (nominal model, instrument fitted) &rarr; %.4f mm (calibrated). "
                        + "Full report: <a href=\"calibration/report.html\">calibration/report.html</a>.</p>\n",
                cal.train().size(), cal.validate().size(), Units.mToMm(cal.nominalValidateRmsM()), Units.mToMm(cal.validateRmsM())));
        List<Svg.Series> before = new ArrayList<>(), after = new ArrayList<>();
        before.add(poseSeries("training", cal.train(), false, "#1f77b4"));
        before.add(poseSeries("validation", cal.validate(), false, "#ff7f0e"));
        after.add(poseSeries("training", cal.train(), true, "#1f77b4"));
        after.add(poseSeries("validation", cal.validate(), true, "#ff7f0e"));
        h.append(Svg.plot("Campaign poses, nominal model", "pose (campaign order)", "position error (mm)", before, false)).append("\n")
         .append(Svg.plot("Campaign poses, calibrated model", "pose (campaign order)", "position error (mm)", after, false)).append("\n");

        h.append("<h2>Diagnosis</h2>\n").append(diag.html());
        h.append("<h2>Files</h2>\n<ul><li><code>DemoWeld.mod</code>: the off-line program; <code>DemoWeldCal.mod</code>, "
                + "<code>DemoWeldDiag.mod</code>: compensated</li><li><code>measurements.csv</code>: the campaign "
                + "(docs/measurement-file.md)</li><li><code>calibration/</code>: calibrated robot file, summary.json, report.html</li>"
                + "<li><code>diagnosis/</code>: the diagnosis report and extended robot file</li><li><code>truth.json</code>: "
                + "what the simulator concealed</li><li><code>controller.log</code>: the controller process's output</li></ul>\n");
        return h.append("</body></html>\n").toString();
    }

    private static void hrow(StringBuilder h, String label, Demo.Run run) {
        h.append(String.format(Locale.ROOT, "<tr><td class=\"l\">%s</td><td>%.4f</td><td>%.4f</td></tr>", Html.esc(label), run.meanMm(), run.maxMm()));
    }

    private static Svg.Series series(String name, Demo.Run run, String colour) {
        double[] x = new double[run.errorsMm().length];
        for (int i = 0; i < x.length; i++) x[i] = i + 1;
        return new Svg.Series(name, x, run.errorsMm(), colour, true);
    }

    private static double campaignIndex(String poseId, int fallback) {
        try {
            return Integer.parseInt(poseId);
        } catch (NumberFormatException e) {
            return fallback;
        }
    }

    private static Svg.Series poseSeries(String name, List<CalibrationResult.PoseError> es, boolean calibrated, String colour) {
        double[] x = new double[es.size()], y = new double[es.size()];
        for (int i = 0; i < x.length; i++) {
            x[i] = campaignIndex(es.get(i).poseId(), i + 1); // training and validation poses interleave in the campaign
            y[i] = Units.mToMm(calibrated ? es.get(i).calibratedM() : es.get(i).nominalM());
        }
        return new Svg.Series(name, x, y, colour, false);
    }
}
