package org.robopro.calibration.diagnosis;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import java.io.IOException;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.robopro.calibration.report.Figure;
import org.robopro.calibration.report.Html;
import org.robopro.calibration.report.Svg;
import org.robopro.kinematics.Units;

/** diagnosis.json and the self-contained HTML report (inline SVG, no scripts) of a {@link Diagnosis}. */
public final class DiagnosisReport {
    /** Where the data came from, for the report's header. */
    public record Context(String measurements, String validation, String created) { }

    private DiagnosisReport() { }

    private static Double mm(double m) { return Double.isFinite(m) ? Units.mToMm(m) : null; }

    private static Map<String, Object> rms(double train, double val) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("train_rms_mm", mm(train));
        m.put("validate_rms_mm", mm(val));
        return m;
    }

    /** The JSON tree (docs/diagnosis.md; the documented fields first). */
    public static Map<String, Object> summary(Diagnosis d, Context ctx) {
        Map<String, Object> root = new LinkedHashMap<>();
        root.put("robot", d.robot());
        root.put("measurements", ctx.measurements());
        root.put("validation", ctx.validation());
        root.put("created", ctx.created());
        root.put("warnings", d.warnings());
        root.put("geometric", rms(d.geometricTrainRmsM(), d.geometricValidateRmsM()));
        List<Object> effects = new ArrayList<>();
        for (Diagnosis.Finding f : d.effects()) effects.add(finding(f, true));
        root.put("effects", effects);
        root.put("final", rms(d.finalTrainRmsM(), d.finalValidateRmsM()));
        List<Object> loc = new ArrayList<>();
        for (Diagnosis.Located l : d.located()) {
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("variable", l.variable());
            m.put("shape", l.shape());
            m.put("size_mm", mm(l.sizeM()));
            m.put("share_of_unexplained_ss", l.share());
            m.put("f", l.f());
            m.put("df1", l.df1());
            m.put("p_value", l.pValue());
            m.put("holm_threshold", l.threshold());
            m.put("stage", l.stage());
            m.put("explained_by", l.explainedBy());
            m.put("words", l.words());
            loc.add(m);
        }
        root.put("located", loc);
        root.put("outliers", d.outliers());
        List<Object> ni = new ArrayList<>();
        for (Diagnosis.NotIdentifiable n : d.notIdentifiable()) {
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("effect", n.effect());
            m.put("joints", n.joints());
            m.put("unabsorbed_ratio", n.ratio());
            m.put("reason", n.reason());
            ni.add(m);
        }
        root.put("not_identifiable", ni);
        List<Object> impl = new ArrayList<>();
        for (Diagnosis.Finding f : d.implausible()) impl.add(finding(f, false));
        root.put("implausible", impl);
        root.put("recommendations", d.recommendations());
        root.put("notes", d.notes());
        root.put("sigma_mm", Units.mToMm(d.sigmaM()));
        root.put("noise_floor_mm", Units.mToMm(d.noiseFloorM()));
        root.put("candidates_tested", d.candidatesTested());
        root.put("family_alpha", d.alpha());
        root.put("directions", d.directions().words);
        root.put("elapsed_ms", Math.round(d.elapsedMs()));
        return root;
    }

    private static Map<String, Object> finding(Diagnosis.Finding f, boolean withRms) {
        Map<String, Object> m = new LinkedHashMap<>();
        Effect e = f.effect();
        m.put("effect", e.json());
        m.put("joints", e.joints1());
        m.put("label", e.label());
        Map<String, Object> p = new LinkedHashMap<>(), s = new LinkedHashMap<>(), u = new LinkedHashMap<>();
        for (int i = 0; i < e.size(); i++) {
            String n = e.parameterNames().get(i);
            p.put(n, f.values()[i]);
            s.put(n, Double.isFinite(f.sigmas()[i]) ? f.sigmas()[i] : null);
            u.put(n, e.units().get(i));
        }
        if (e.kind() == Effect.Kind.THERMAL) p.put(e.usesTimeProxy() ? "tau_s" : "t0_c", e.usesTimeProxy() ? e.tauS() : e.t0C());
        if (e.buildsUp()) { p.put("build_up_rad", e.buildUpRad()); u.put("build_up_rad", "rad"); }
        if (e.approached()) { p.put("approach_rad", e.approachRad()); u.put("approach_rad", "rad"); }
        if (e.heldByGravity()) {
            p.put("held_above_nm", e.heldAboveNm());
            u.put("held_above_nm", "N·m");
            p.put("held_width", e.heldWidth());
            u.put("held_width", "1");
        }
        m.put("parameters", p);
        m.put("parameter_sigmas", s);
        m.put("units", u);
        if (withRms) {
            m.put("train_rms_mm", mm(f.trainRmsM()));
            m.put("validate_rms_mm", mm(f.validateRmsM()));
        }
        Diagnosis.Evidence ev = f.evidence();
        Map<String, Object> x = new LinkedHashMap<>();
        x.put("f", ev.f());
        x.put("df1", ev.df1());
        x.put("df2", ev.df2());
        x.put("p_value", ev.pValue());
        x.put("holm_threshold", ev.threshold());
        x.put("rss_reduction", ev.rssReduction());
        x.put("press_before", ev.pressBefore());
        x.put("press_after", ev.pressAfter());
        x.put("unabsorbed_ratio", ev.projectionRatio());
        x.put("absorbed_by_geometry", ev.absorbed());
        x.put("plausibility", ev.plausibility());
        x.put("plausible", ev.plausible());
        m.put("evidence", x);
        m.put("words", f.words());
        return m;
    }

    public static String json(Diagnosis d, Context ctx) {
        try {
            return org.robopro.models.JsonMapper.create().writeValueAsString(summary(d, ctx)) + "\n";
        } catch (IOException e) {
            throw new IllegalStateException(e);
        }
    }

    // ------------------------------------------------------------------ HTML

    public static String html(Diagnosis d, Context ctx) {
        StringBuilder h = new StringBuilder();
        h.append("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>Diagnosis of ")
         .append(Html.esc(d.robot())).append("</title><style>")
         .append("body{font-family:sans-serif;max-width:780px;margin:1em auto;color:#222}")
         .append("table{border-collapse:collapse;font-size:12px}td,th{border:1px solid #ccc;padding:2px 6px;text-align:right}")
         .append("th{background:#eee}td.l,th.l{text-align:left}.finding{border-left:4px solid #2a7;padding-left:10px;margin:1.2em 0}")
         .append(".warn{border-left:4px solid #c22;padding-left:10px;background:#fff4f4}.impl{border-left:4px solid #c80;padding-left:10px}.muted{color:#666;font-size:12px}")
         .append("</style></head><body>\n");
        h.append("<h1>Diagnosis of ").append(Html.esc(d.robot())).append("</h1>\n<p>Measurements: <code>")
         .append(Html.esc(ctx.measurements())).append("</code>");
        if (ctx.validation() != null) h.append("; validation: <code>").append(Html.esc(ctx.validation())).append("</code>");
        h.append(". Created ").append(Html.esc(ctx.created())).append(".</p>\n");

        if (!d.warnings().isEmpty()) {
            h.append("<div class=\"warn\"><h2>Error left above the noise</h2>\n<ul>");
            for (String w : d.warnings()) h.append("<li>").append(Html.esc(w)).append("</li>");
            h.append("</ul></div>\n");
        }
        h.append("<h2>Summary</h2>\n<p>");
        if (d.effects().isEmpty())
            h.append("No non-geometric effect was found: the geometric model explains these measurements down to the noise.");
        else {
            h.append("The geometric model left out ").append(d.effects().size() == 1 ? "one effect" : d.effects().size() + " effects")
             .append(": ");
            List<String> names = new ArrayList<>();
            for (Diagnosis.Finding f : d.effects()) names.add("<b>" + Html.esc(f.effect().label()) + "</b>");
            h.append(String.join(", ", names)).append(". Each was added to the model and identified jointly with the geometry.");
        }
        h.append("</p>\n<table><tr><th class=\"l\">model</th><th>training RMS (mm)</th><th>validation RMS (mm)</th></tr>");
        row(h, "geometric", d.geometricTrainRmsM(), d.geometricValidateRmsM());
        for (Diagnosis.Finding f : d.effects()) row(h, "+ " + f.effect().label(), f.trainRmsM(), f.validateRmsM());
        row(h, "final (joint re-identification)", d.finalTrainRmsM(), d.finalValidateRmsM());
        h.append("</table>\n");
        h.append(String.format(Locale.ROOT, "<p class=\"muted\">Noise estimated from the final fit's residuals: &sigma; = %.4f mm %s "
                + "(noise floor %s = %.4f mm). %d candidates (effect &times; joint) "
                + "tested with a family-wise false-positive rate of %.3g; %d outlier poses excluded. %.0f ms.</p>\n",
                Units.mToMm(d.sigmaM()), d.distances() ? "per distance" : "per axis", d.distances() ? "&sigma;" : "&radic;3&middot;&sigma;",
                Units.mToMm(d.noiseFloorM()), d.candidatesTested(), d.alpha(),
                d.outliers().size(), d.elapsedMs()));
        h.append("<p class=\"muted\">Approach directions: ").append(Html.esc(d.directions().words)).append(".</p>\n");
        h.append(rmsChart(d));

        if (!d.effects().isEmpty()) h.append("<h2>Findings</h2>\n");
        for (Diagnosis.Finding f : d.effects()) {
            h.append("<div class=\"finding\"><h3>").append(Html.esc(f.effect().label())).append("</h3>\n<p>")
             .append(Html.esc(f.words())).append("</p>\n");
            h.append(parameterTable(f));
            Diagnosis.Plot p = f.plot();
            if (p != null) {
                h.append(Svg.plot("Evidence: partial residual against the regressor (" + p.x().length + " "
                        + (f.effect().target() == Effect.Target.POSITION || d.distances() ? d.measurementWords() : "poses") + ")", p.xLabel(), p.yLabel(),
                        List.of(new Svg.Series("measured (partial residual)", p.x(), p.y(), "#1f77b4", false),
                                new Svg.Series("fitted " + (f.effect().runout() ? "play over the turn" : f.effect().buildsUp() ? "lost motion building up over the move" : f.effect().heldByGravity()
                                        ? "lost motion held by gravity (centre of the play where the torque is small)" : f.effect().json()), p.curveX(), p.curveY(), "#d62728",
                                        // an effect on the measured point: its fitted size at each measurement, not a curve of the x variable
                                        f.effect().target() != Effect.Target.POSITION)), false));
                if (p.periodogram() != null) {
                    double[] hx = new double[p.periodogram().length];
                    for (int i = 0; i < hx.length; i++) hx[i] = i + 1;
                    h.append(Svg.plot("Periodogram of the partial residual (modelled: " + String.join(", ", java.util.Arrays.stream(
                                    f.effect().orders()).mapToObj(Effect::orderText).toList()) + " cycles per turn)", "cycles per turn of q"
                                    + (f.effect().joint() + 1), "amplitude (mdeg)",
                            List.of(new Svg.Series("amplitude", hx, p.periodogram(), "#2ca02c", true)), false));
                }
            }
            h.append("</div>\n");
        }
        if (!d.located().isEmpty()) {
            h.append("<h2>Located structures</h2>\n<p class=\"muted\">Where the residuals have structure, tested against every "
                    + "variable the data offer (joint angles periodic and smooth, directions, time, temperature, payload, reach, height), "
                    + "whether or not a named effect explains it.</p>\n");
            for (Diagnosis.Located l : d.located()) {
                h.append("<div class=\"finding\"><p>").append(Html.esc(l.words())).append("</p>\n");
                Diagnosis.Plot p = l.plot();
                if (p != null && p.x().length > 0)
                    // the shape in words is in the paragraph above; a long one would run off the figure's title line
                    h.append(Svg.plot("Evidence: " + (l.shape().length() <= 60 ? l.shape() : l.variable()), p.xLabel(), p.yLabel(),
                            List.of(new Svg.Series(p.yLabel().contains("partial residual") ? "partial residual" : "residual along it",
                                            p.x(), p.y(), "#1f77b4", false),
                                    new Svg.Series("located structure", p.curveX(), p.curveY(), "#d62728", false)), false));
                h.append("</div>\n");
            }
        }
        if (!d.implausible().isEmpty()) {
            h.append("<h2>Significant but implausible (not claimed)</h2>\n");
            for (Diagnosis.Finding f : d.implausible()) h.append("<p class=\"impl\">").append(Html.esc(f.words())).append("</p>\n");
        }
        if (!d.recommendations().isEmpty()) {
            h.append("<h2>What to record next</h2>\n<ul>");
            for (String r : d.recommendations()) h.append("<li>").append(Html.esc(r)).append("</li>");
            h.append("</ul>\n");
        }
        h.append("<h2>Outliers</h2>\n<p>");
        if (d.outliers().isEmpty()) h.append("None (calibration rule: position residual above 5 robust sigmas).");
        else h.append("Poses ").append(Html.esc(String.join(", ", d.outliers())))
                .append(" were flagged by the calibration's rule (position residual above 5 robust sigmas) and left out of every fit.");
        h.append("</p>\n");
        if (!d.notIdentifiable().isEmpty()) {
            h.append("<h2>Not identifiable on these data</h2>\n<table><tr><th class=\"l\">candidate</th><th>&#8214;P&#8869;S&#8214;/&#8214;S&#8214;</th><th class=\"l\">why</th></tr>");
            for (Diagnosis.NotIdentifiable n : d.notIdentifiable())
                h.append("<tr><td class=\"l\">").append(Html.esc(n.label())).append("</td><td>")
                 .append(String.format(Locale.ROOT, "%.3f", n.ratio())).append("</td><td class=\"l\">").append(Html.esc(n.reason()))
                 .append("</td></tr>");
            h.append("</table>\n");
        }
        if (!d.notes().isEmpty()) {
            h.append("<h2>Notes</h2>\n<ul>");
            for (String n : d.notes()) h.append("<li>").append(Html.esc(n)).append("</li>");
            h.append("</ul>\n");
        }
        h.append("<p class=\"muted\">Method: docs/diagnosis.md. Each candidate's signature is projected out of the span of the "
                + "geometric Jacobian; nested F-test with Holm&ndash;Bonferroni over the family, leave-one-pose-out cross-validation "
                + "and physical plausibility must all agree before an effect is claimed.</p>\n");
        return h.append("</body></html>\n").toString();
    }

    private static void row(StringBuilder h, String name, double train, double val) {
        h.append("<tr><td class=\"l\">").append(Html.esc(name)).append("</td><td>").append(fmt(train)).append("</td><td>")
         .append(fmt(val)).append("</td></tr>");
    }

    private static String fmt(double m) { return Double.isFinite(m) ? String.format(Locale.ROOT, "%.4f", Units.mToMm(m)) : "&ndash;"; }

    private static String parameterTable(Diagnosis.Finding f) {
        StringBuilder h = new StringBuilder("<table><tr><th class=\"l\">parameter</th><th>value</th><th>&sigma;</th><th class=\"l\">unit (SI)</th></tr>");
        Effect e = f.effect();
        for (int i = 0; i < e.size(); i++)
            h.append("<tr><td class=\"l\">").append(e.parameterNames().get(i)).append("</td><td>")
             .append(String.format(Locale.ROOT, "%.4g", f.values()[i])).append("</td><td>")
             .append(String.format(Locale.ROOT, "%.2g", f.sigmas()[i])).append("</td><td class=\"l\">")
             .append(Html.esc(e.units().get(i))).append("</td></tr>");
        return h.append("</table>\n").toString();
    }

    /** The RMS bar chart ({@link #rmsBars}) as an inline SVG for HTML reports. */
    public static String rmsChart(Diagnosis d) {
        return Svg.draw((c, w, h) -> rmsBars(c, w, h, "RMS error: geometric model, after each effect, final fit", d));
    }

    /**
     * The RMS bar chart of a diagnosis, drawn by the one figure routine (the report's SVG and the
     * workbench panel): bars for the geometric model, after each effect was added and for the
     * final joint fit (the rows of the report's table), training and, when there are validation
     * data, validation side by side; the noise floor (√3·σ for points, σ for distances) as a dashed line.
     */
    public static void rmsBars(Figure.Canvas c, double w, double h, String title, Diagnosis d) {
        List<String> cats = new ArrayList<>();
        List<double[]> v = new ArrayList<>();
        cats.add("geometric");
        v.add(new double[] {d.geometricTrainRmsM(), d.geometricValidateRmsM()});
        for (Diagnosis.Finding f : d.effects()) {
            cats.add("+ " + f.effect().label());
            v.add(new double[] {f.trainRmsM(), f.validateRmsM()});
        }
        if (!d.effects().isEmpty() && Double.isFinite(d.finalTrainRmsM())) {
            cats.add("final fit");
            v.add(new double[] {d.finalTrainRmsM(), d.finalValidateRmsM()});
        }
        double[] train = v.stream().mapToDouble(x -> Units.mToMm(x[0])).toArray();
        double[] val = v.stream().mapToDouble(x -> Units.mToMm(x[1])).toArray();
        List<Svg.Series> series = new ArrayList<>();
        series.add(new Svg.Series("training", null, train, "#f07a1a", false));
        if (java.util.Arrays.stream(val).anyMatch(Double::isFinite)) series.add(new Svg.Series("validation", null, val, "#f5b77f", false));
        double floor = Units.mToMm(d.noiseFloorM());
        List<Svg.Line> lines = floor > 0 && Double.isFinite(floor)
                ? List.of(new Svg.Line(d.distances() ? "noise floor σ" : "noise floor √3·σ", floor, "#2e9e44")) : List.of();
        Figure.bars(c, w, h, title, "RMS (mm)", cats, series, lines, "%.3f");
    }
}
