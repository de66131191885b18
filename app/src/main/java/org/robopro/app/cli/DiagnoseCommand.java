package org.robopro.app.cli;

import java.nio.file.Path;
import java.time.Instant;
import java.time.temporal.ChronoUnit;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.concurrent.CancellationException;
import org.robopro.calibration.Cancellation;
import org.robopro.calibration.diagnosis.Diagnoser;
import org.robopro.calibration.diagnosis.Diagnosis;
import org.robopro.calibration.diagnosis.DiagnosisReport;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.measurement.MeasurementReader;
import org.robopro.calibration.measurement.MeasurementSet;
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

    @Option(names = "--alpha", defaultValue = "0.001", paramLabel = "A", description = "family-wise false-positive rate (default ${DEFAULT-VALUE})")
    double alpha;

    @Mixin OutputDirOptions out;

    @Spec CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        if (!(alpha > 0 && alpha < 1)) throw new IllegalArgumentException("--alpha must be in (0, 1), got " + alpha);
        RobotDescription desc = robot.description();
        org.robopro.calibration.workflow.CalibrationWorkflow.Campaign data = measurements.read(desc, null);
        MeasurementSet train = data.train(), val = data.validate();
        Cancellation cancel = new Cancellation();
        Diagnoser.Options o = Diagnoser.Options.defaults().withAlpha(alpha).withCancel(cancel)
                .withProgress(CliSupport.progressBar(spec.commandLine().getErr()));
        Thread hook = CliSupport.cancelOnInterrupt(cancel, Thread.currentThread());
        Diagnosis d;
        try {
            d = Diagnoser.diagnose(desc, train, val, o);
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
        out.set()
                .addString("extended.robot.json", RobotFile.format(extended))
                .addString("diagnosis.json", DiagnosisReport.json(d, ctx))
                .addString("report.html", DiagnosisReport.html(d, ctx))
                .commit();
        var w = spec.commandLine().getOut();
        w.printf(Locale.ROOT, "diagnosed %s from %d poses: geometric RMS %.4f mm -> %.4f mm with effects (train)%n", desc.name(),
                train.size(), Units.mToMm(d.geometricTrainRmsM()), Units.mToMm(d.finalTrainRmsM()));
        if (val != null) w.printf(Locale.ROOT, "  validation: %.4f mm -> %.4f mm%n", Units.mToMm(d.geometricValidateRmsM()),
                Units.mToMm(d.finalValidateRmsM()));
        if (d.effects().isEmpty()) w.println("  no non-geometric effect found");
        for (Diagnosis.Finding f : d.effects()) w.println("  found " + f.effect().label());
        for (String r : d.recommendations()) w.println("  advice: " + r);
        if (!d.outliers().isEmpty()) w.println("  outliers: " + String.join(", ", d.outliers()));
        w.printf("  wrote %s%n", out.dir().toAbsolutePath());
        return 0;
    }
}
