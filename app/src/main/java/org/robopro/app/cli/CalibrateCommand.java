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
import org.robopro.calibration.identification.CalibrationResult;
import org.robopro.calibration.identification.Calibrator;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.measurement.MeasurementReader;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.calibration.report.CalibrationReport;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
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
 * {@code robopro calibrate}: identifies a robot from a measurement file and writes
 * {@code DIR/calibrated.robot.json} (with provenance), {@code DIR/report.html} and
 * {@code DIR/summary.json} (docs/calibration.md). Validation data come from {@code --validate},
 * else from the file's {@code set} column. Ctrl-C cancels cleanly (nothing half-written).
 */
@Command(name = "calibrate", mixinStandardHelpOptions = true,
        description = "Identify a robot's geometry from measurements; write the calibrated model and a report.")
public final class CalibrateCommand implements Callable<Integer> {
    @Mixin RobotOptions robot;

    @Mixin MeasurementOptions measurements;

    @Option(names = "--holdout", paramLabel = "FRACTION",
            description = "without --validate or a set column: keep every (1/FRACTION)-th pose out of the fit for validation")
    Double holdout;

    @Option(names = "--target", defaultValue = "0,0,0", paramLabel = "X,Y,Z",
            description = "start value of the measured point on the flange, mm (default ${DEFAULT-VALUE})")
    String target;

    @Option(names = "--outlier-k", defaultValue = "5", paramLabel = "K", description = "outlier threshold in robust sigmas (default ${DEFAULT-VALUE})")
    double outlierK;

    @Option(names = "--keep-outliers", description = "report outliers but keep them in the fit")
    boolean keepOutliers;

    @Mixin OutputDirOptions out;

    @Spec CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        RobotDescription desc = robot.description();
        KinematicModel nominal = robot.model();
        MeasurementOptions.Data data = measurements.read(desc, holdout);
        MeasurementSet all = data.all(), train = data.train(), val = data.validate();
        if (all.robot() != null && !all.robot().equalsIgnoreCase(desc.name()))
            spec.commandLine().getErr().printf("robopro: warning: %s was measured on '%s', calibrating '%s'%n", measurements.file(),
                    all.robot(), desc.name());
        double[] t = CliSupport.numbers("--target", target, 3);
        Cancellation cancel = new Cancellation();
        Calibrator.Options o = Calibrator.Options.defaults()
                .withInitialTool(Pose.translation(Units.mmToM(t[0]), Units.mmToM(t[1]), Units.mmToM(t[2])))
                .withOutliers(outlierK, !keepOutliers).withCancel(cancel)
                .withProgress(CliSupport.progressBar(spec.commandLine().getErr()));
        Thread hook = CliSupport.cancelOnInterrupt(cancel, Thread.currentThread());
        CalibrationResult r;
        try {
            r = Calibrator.calibrate(nominal, train, val, o);
        } catch (CancellationException e) {
            spec.commandLine().getErr().println("robopro: calibration cancelled; nothing written");
            return 130;
        } finally {
            CliSupport.removeHook(hook);
        }
        String created = Instant.now().truncatedTo(ChronoUnit.SECONDS).toString();
        CalibrationReport.Context ctx = new CalibrationReport.Context(desc.name(), measurements.file().toString(), data.source(), created);
        Map<String, String> prov = new LinkedHashMap<>(desc.provenance());
        prov.put("calibrated-from", measurements.file().toString());
        prov.put("calibrated-on", created);
        prov.put("calibrated-nominal", desc.name());
        prov.put("calibration-train-rms-mm", String.format(Locale.ROOT, "%.5f", Units.mToMm(r.trainRmsM())));
        if (val != null) prov.put("calibration-validate-rms-mm", String.format(Locale.ROOT, "%.5f", Units.mToMm(r.validateRmsM())));
        var p = r.flangeTtool().position();
        prov.put("calibration-measured-point-mm", String.format(Locale.ROOT, "%.5f,%.5f,%.5f",
                Units.mToMm(p.x()), Units.mToMm(p.y()), Units.mToMm(p.z())));
        RobotDescription calibrated = r.calibrated().toDescription().withProvenance(prov);
        java.util.List<String> warnings = CalibrationReport.warnings(r, train, val);
        out.set()
                .addString("calibrated.robot.json", RobotFile.format(calibrated))
                .addString("summary.json", CalibrationReport.summaryJson(r, ctx, warnings))
                .addString("report.html", CalibrationReport.html(r, ctx, warnings))
                .commit();
        var w = spec.commandLine().getOut();
        w.printf(Locale.ROOT, "calibrated %s from %d poses (%s): RMS %.4f mm -> %.4f mm (train)%n", desc.name(), r.train().size(),
                r.sixD() ? "6-D" : "positions", Units.mToMm(r.nominalTrainRmsM()), Units.mToMm(r.trainRmsM()));
        if (val != null) w.printf(Locale.ROOT, "  validation (%d poses): RMS %.4f mm -> %.4f mm, max %.4f mm%n", r.validate().size(),
                Units.mToMm(r.nominalValidateRmsM()), Units.mToMm(r.validateRmsM()), Units.mToMm(r.validateMaxM()));
        w.printf(Locale.ROOT, "  %d parameters fixed as unidentifiable, condition number %.3g, %d outliers%s%n",
                r.unidentifiable().size(), r.conditionNumber(), r.outliers().size(),
                r.outliers().isEmpty() ? "" : " (" + String.join(", ", r.outliers().stream().map(CalibrationResult.Outlier::poseId).toList()) + ")");
        w.printf("  wrote %s%n", out.dir().toAbsolutePath());
        for (String warning : warnings) spec.commandLine().getErr().println("robopro: warning: " + warning);
        return 0;
    }
}
