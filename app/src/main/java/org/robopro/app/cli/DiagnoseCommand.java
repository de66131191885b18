package org.robopro.app.cli;

import java.nio.file.Path;
import java.time.Instant;
import java.time.temporal.ChronoUnit;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.concurrent.CancellationException;
import org.robopro.calibration.Cancellation;
import org.robopro.calibration.diagnosis.Diagnoser;
import org.robopro.calibration.diagnosis.Diagnosis;
import org.robopro.calibration.diagnosis.DiagnosisReport;
import org.robopro.calibration.identification.CalibrationResult;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.measurement.MeasurementReader;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.calibration.workflow.CalibrationWorkflow;
import org.robopro.kinematics.Units;
import org.robopro.models.RobotFile;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code robopro diagnose}: after geometric calibration, finds the non-geometric effects the
 * model left out (docs/diagnosis.md) and writes {@code DIR/report.html},
 * {@code DIR/diagnosis.json} and the extended model {@code DIR/extended.robot.json} (geometry plus
 * its {@code effects} section, which {@code robopro compensate} uses). Validation data come from
 * {@code --validate}, else from the file's {@code set} column.
 */
@Command(name = "diagnose", mixinStandardHelpOptions = true,
        description = "Find the physics a geometric calibration left out; write a report, diagnosis.json and the extended model.")
public final class DiagnoseCommand implements Callable<Integer> {
    @Mixin RobotOptions robot;

    @Mixin MeasurementOptions measurements;

    @Option(names = "--folds", paramLabel = "K",
            description = "also diagnose K times, each time without one of K folds of the training poses, and report the held-out errors and how often each effect is found")
    Integer folds;

    @Option(names = "--fold-seed", defaultValue = "1", paramLabel = "SEED", description = "seed of the fold assignment (default ${DEFAULT-VALUE})")
    long foldSeed;

    @Option(names = "--alpha", defaultValue = "0.001", paramLabel = "A", description = "family-wise false-positive rate (default ${DEFAULT-VALUE})")
    double alpha;

    @Mixin OutputDirOptions out;

    @Spec CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        if (!(alpha > 0 && alpha < 1)) throw new IllegalArgumentException("--alpha must be in (0, 1), got " + alpha);
        RobotDescription desc = robot.description();
        CalibrationWorkflow.Campaign data = measurements.read(desc);
        MeasurementSet train = data.train(), val = data.validate();
        Cancellation cancel = new Cancellation();
        Diagnoser.Options o = Diagnoser.Options.defaults().withAlpha(alpha).withCancel(cancel)
                .withProgress(CliSupport.progressBar(spec.commandLine().getErr()));
        Thread hook = CliSupport.cancelOnInterrupt(cancel, Thread.currentThread());
        Diagnosis d;
        List<Diagnosis> cv = List.of();
        try {
            if (folds != null) {
                if (folds < 2) throw new IllegalArgumentException("--folds must be at least 2, got " + folds);
                cv = CalibrationWorkflow.crossValidate(train, folds, foldSeed, (k, tr, va) -> Diagnoser.diagnose(desc, tr, va, o));
            }
            d = Diagnoser.diagnose(desc, train, val, o).withWarningsFirst(data.warnings());
        } catch (CancellationException e) {
            spec.commandLine().getErr().println("robopro: diagnosis cancelled; nothing written");
            return 130;
        } finally {
            CliSupport.removeHook(hook);
        }
        String created = Instant.now().truncatedTo(ChronoUnit.SECONDS).toString();
        DiagnosisReport.Context ctx = new DiagnosisReport.Context(measurements.file().toString(), data.source(), created);
        Map<String, String> prov = new LinkedHashMap<>(desc.provenance());
        prov.put("diagnosed-from", measurements.file().toString());
        prov.put("diagnosed-on", created);
        prov.put("diagnosed-nominal", desc.name());
        prov.put("diagnosis-train-rms-mm", String.format(Locale.ROOT, "%.5f", Units.mToMm(d.finalTrainRmsM())));
        var p = d.geometric().flangeTtool().position();
        prov.put("calibration-measured-point-mm", String.format(Locale.ROOT, "%.5f,%.5f,%.5f",
                Units.mToMm(p.x()), Units.mToMm(p.y()), Units.mToMm(p.z())));
        RobotDescription extended = d.model().toDescription().withProvenance(prov);
        String json = DiagnosisReport.json(d, ctx);
        if (!cv.isEmpty()) json = withCrossValidation(json, cv);
        out.set()
                .addString("extended.robot.json", RobotFile.format(extended))
                .addString("diagnosis.json", json)
                .addString("report.html", DiagnosisReport.html(d, ctx))
                .commit();
        for (String warning : data.warnings()) spec.commandLine().getErr().println("robopro: warning: " + warning);
        var w = spec.commandLine().getOut();
        String kind = d.distances() ? " (distances)" : d.pointsPerPose() > 1 ? " (" + d.pointsPerPose() + " points each; RMS over every point)" : "";
        w.printf(Locale.ROOT, "diagnosed %s from %d poses%s: geometric RMS %.4f mm -> %.4f mm with effects (train)%n", desc.name(),
                train.size(), kind, Units.mToMm(d.geometricTrainRmsM()), Units.mToMm(d.finalTrainRmsM()));
        if (val != null) w.printf(Locale.ROOT, "  validation: %.4f mm -> %.4f mm%n", Units.mToMm(d.geometricValidateRmsM()),
                Units.mToMm(d.finalValidateRmsM()));
        if (d.effects().isEmpty()) w.println("  no non-geometric effect found");
        // a fallback models a located structure without naming its physics: said so, not "found"
        for (Diagnosis.Finding f : d.effects())
            w.println(f.effect().isFallback() ? "  located " + f.effect().label() + " (modelled, no known family)" : "  found " + f.effect().label());
        for (String r : d.recommendations()) w.println("  advice: " + r);
        if (!cv.isEmpty()) {
            w.printf(Locale.ROOT, "  %d-fold cross-validation, held-out RMS: geometric %.4f mm -> %.4f mm with the effects of each fold%n",
                    cv.size(), Units.mToMm(pooledRms(cv, true)), Units.mToMm(pooledRms(cv, false)));
            Map<String, Integer> counts = effectCounts(cv);
            if (counts.isEmpty()) w.println("    no effect found in any fold");
            int k = cv.size();
            counts.forEach((label, n) -> w.printf(Locale.ROOT, "    %s found in %d of %d folds%n", label, n, k));
        }
        if (!d.outliers().isEmpty()) w.println("  outliers: " + String.join(", ", d.outliers()));
        w.printf("  wrote %s%n", out.dir().toAbsolutePath());
        return 0;
    }

    /** RMS over every held-out measurement (point or distance) of the folds (geometric model, or with each fold's effects), m. */
    static double pooledRms(List<Diagnosis> cv, boolean geometric) {
        double s = 0;
        int n = 0;
        for (Diagnosis d : cv) {
            int k = d.geometric().validate().size();
            double r = geometric ? d.geometricValidateRmsM() : d.finalValidateRmsM();
            s += k * r * r;
            n += k;
        }
        return Math.sqrt(s / n);
    }

    /** How many folds named each effect, in order of first appearance. */
    static Map<String, Integer> effectCounts(List<Diagnosis> cv) {
        Map<String, Integer> counts = new LinkedHashMap<>();
        for (Diagnosis d : cv) for (Diagnosis.Finding f : d.effects()) counts.merge(f.effect().label(), 1, Integer::sum);
        return counts;
    }

    /** Puts a number, or null when it is not finite (JSON has no NaN). */
    private static void finite(ObjectNode o, String key, double v) {
        if (Double.isFinite(v)) o.put(key, v);
        else o.putNull(key);
    }

    /** diagnosis.json with a cross_validation section: per fold and overall held-out RMS, effects per fold. */
    private String withCrossValidation(String json, List<Diagnosis> cv) throws java.io.IOException {
        ObjectMapper mapper = org.robopro.models.JsonMapper.create();
        ObjectNode root = (ObjectNode) mapper.readTree(json);
        ObjectNode c = root.putObject("cross_validation");
        c.put("folds", cv.size());
        c.put("seed", foldSeed);
        finite(c, "held_out_geometric_rms_mm", Units.mToMm(pooledRms(cv, true)));
        finite(c, "held_out_final_rms_mm", Units.mToMm(pooledRms(cv, false)));
        ObjectNode counts = c.putObject("effect_counts");
        effectCounts(cv).forEach(counts::put);
        ArrayNode per = c.putArray("per_fold");
        for (int k = 0; k < cv.size(); k++) {
            Diagnosis d = cv.get(k);
            ObjectNode f = per.addObject();
            f.put("fold", k + 1);
            f.put("poses_train", CalibrationResult.poses(d.geometric().train()));
            f.put("poses_held_out", CalibrationResult.poses(d.geometric().validate()));
            finite(f, "held_out_geometric_rms_mm", Units.mToMm(d.geometricValidateRmsM()));
            finite(f, "held_out_final_rms_mm", Units.mToMm(d.finalValidateRmsM()));
            ArrayNode e = f.putArray("effects");
            for (Diagnosis.Finding x : d.effects()) e.add(x.effect().label());
        }
        return mapper.writeValueAsString(root) + "\n";
    }
}
