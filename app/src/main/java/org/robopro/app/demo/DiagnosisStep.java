package org.robopro.app.demo;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.time.temporal.ChronoUnit;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.robopro.calibration.PoseConditions;
import org.robopro.calibration.compensation.Compensator;
import org.robopro.calibration.diagnosis.Diagnoser;
import org.robopro.calibration.diagnosis.Diagnosis;
import org.robopro.calibration.diagnosis.DiagnosisReport;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.calibration.report.Html;
import org.robopro.calibration.report.Svg;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.kinematics.Units;
import org.robopro.models.AtomicFiles;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;

/**
 * Step 4's diagnosis ({@link Diagnoser}, docs/diagnosis.md): names the effect the geometric model left out,
 * writes its report, and gives the extended model's compensator and tracker registration.
 */
final class DiagnosisStep {
    private DiagnosisStep() { }

    /** What the diagnosis gave the demo. */
    static final class Outcome {
        private final Diagnosis d;

        Outcome(Diagnosis d) { this.d = d; }

        /** Physical effects named, as "kind jN" labels (a located structure of no known family is not named). */
        List<String> named() { return d.effects().stream().filter(f -> !f.effect().isFallback()).map(f -> f.effect().label()).toList(); }

        /** Structures located that no physical effect explains: those modelled by a fallback, then the others. */
        List<String> located() {
            List<String> out = new ArrayList<>();
            for (Diagnosis.Finding f : d.effects()) if (f.effect().isFallback()) out.add(f.effect().label());
            for (Diagnosis.Located l : d.located()) if (l.explainedBy() == null && !out.contains(l.shape())) out.add(l.shape());
            return out;
        }

        /** Whether the diagnosis models anything beyond the geometry (a named effect, or a located structure's fallback that held on held-out poses). */
        boolean modelsSomething() { return !d.effects().isEmpty(); }

        /** The tracker registration of the extended model's fit. */
        Pose instrumentTbase() { return d.finalInstrumentTbase(); }

        /** Fig. 5 with the extended model: geometry and the named effects under the target's conditions (unknown ones count as none). */
        Compensator compensator(KinematicModel nominal, Pose flangeTtcp, PoseConditions conditions) {
            Pose point = d.finalFlangeTtool();
            Pose toolCal = Pose.of(flangeTtcp.rotationRowMajor(), point.x(), point.y(), point.z());
            return new Compensator(nominal, d.model(), flangeTtcp, toolCal, conditions);
        }

        /** The report's diagnosis section: each finding in words with its evidence plot. */
        String html() {
            StringBuilder h = new StringBuilder();
            h.append(String.format(Locale.ROOT, "<p>Validation RMS with the geometric model %.4f mm, with the effects found %.4f mm"
                            + " (%d candidate effects tested, family-wise false-positive rate %.3g). Full report: "
                            + "<a href=\"diagnosis/report.html\">diagnosis/report.html</a>.</p>\n",
                    Units.mToMm(d.geometricValidateRmsM()), Units.mToMm(d.finalValidateRmsM()), d.candidatesTested(), d.alpha()));
            h.append(DiagnosisReport.rmsChart(d)).append('\n');
            if (d.effects().isEmpty()) h.append("<p>No non-geometric effect found.</p>\n");
            for (Diagnosis.Finding f : d.effects()) {
                h.append("<h3>").append(Html.esc(f.effect().label())).append("</h3>\n<p>").append(Html.esc(f.words())).append("</p>\n");
                Diagnosis.Plot p = f.plot();
                if (p != null) {
                    List<Svg.Series> s = new ArrayList<>();
                    s.add(new Svg.Series("partial residual", p.x(), p.y(), "#1f77b4", false));
                    if (p.curveX() != null) s.add(new Svg.Series("fitted effect", p.curveX(), p.curveY(), "#d62728", true));
                    h.append(Svg.plot("Evidence: " + f.effect().label(), p.xLabel(), p.yLabel(), s, false)).append('\n');
                }
            }
            for (String r : d.recommendations()) h.append("<p>Advice: ").append(Html.esc(r)).append("</p>\n");
            return h.toString();
        }
    }

    static Outcome run(Console con, RobotDescription desc, MeasurementSet train, MeasurementSet validate, Path out) throws IOException {
        Diagnosis d = Diagnoser.diagnose(desc, train, validate);
        Path dir = out.resolve("diagnosis");
        Files.createDirectories(dir);
        DiagnosisReport.Context ctx = new DiagnosisReport.Context("measurements.csv (set = train)", "measurements.csv (set = validate)",
                Instant.now().truncatedTo(ChronoUnit.SECONDS).toString());
        RobotLibrary.write(d.model().toDescription(), dir.resolve("extended.robot.json"), true);
        AtomicFiles.writeString(dir.resolve("diagnosis.json"), DiagnosisReport.json(d, ctx), true);
        AtomicFiles.writeString(dir.resolve("report.html"), DiagnosisReport.html(d, ctx), true);
        con.line("diagnosed (%d candidate effects tested, %.0f ms): validation RMS %.4f mm (geometric) -> %.4f mm with the effects found",
                d.candidatesTested(), d.elapsedMs(), Units.mToMm(d.geometricValidateRmsM()), Units.mToMm(d.finalValidateRmsM()));
        for (String warning : d.warnings()) con.line("  first: %s", warning);
        if (d.effects().isEmpty()) con.line("  no non-geometric effect found");
        for (Diagnosis.Finding f : d.effects())
            con.line(f.effect().isFallback() ? "  located, no known effect explains it: %s - %s" : "  named: %s - %s", f.effect().label(), f.words());
        for (Diagnosis.Located l : d.located())
            if (l.explainedBy() == null && d.effects().stream().noneMatch(f -> f.effect().isFallback())) con.line("  located: %s", l.words());
        for (String r : d.recommendations()) con.line("  advice: %s", r);
        return new Outcome(d);
    }
}
