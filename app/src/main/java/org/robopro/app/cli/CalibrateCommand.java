package org.robopro.app.cli;

import java.time.Instant;
import java.time.temporal.ChronoUnit;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.concurrent.CancellationException;
import org.robopro.calibration.Cancellation;
import org.robopro.calibration.identification.CalibrationResult;
import org.robopro.calibration.identification.ErrorStats;
import org.robopro.calibration.workflow.CalibrationWorkflow;
import org.robopro.kinematics.Pose;
import org.robopro.kinematics.Units;
import org.robopro.models.RobotDescription;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code robopro calibrate}: the calibration workflow ({@link CalibrationWorkflow}) from the command
 * line: writes {@code DIR/calibrated.robot.json} (with provenance), {@code DIR/report.html},
 * {@code DIR/summary.json} and {@code DIR/residuals.csv} (docs/calibration.md). Validation data come from {@code --validate},
 * else from the file's {@code set} column. Ctrl-C cancels cleanly (nothing half-written).
 */
@Command(name = "calibrate", mixinStandardHelpOptions = true,
        description = "Identify a robot's geometry from measurements; write the calibrated model and a report.")
public final class CalibrateCommand implements Callable<Integer> {
    @Mixin RobotOptions robot;

    @Mixin MeasurementOptions measurements;

    @Option(names = "--target", defaultValue = "0,0,0", paramLabel = "X,Y,Z",
            description = "start value of the measured point on the flange, mm (default ${DEFAULT-VALUE})")
    String target;

    @Option(names = "--outlier-k", defaultValue = "5", paramLabel = "K", description = "outlier threshold in robust sigmas (default ${DEFAULT-VALUE})")
    double outlierK;

    @Option(names = "--keep-outliers", description = "report outliers but keep them in the fit")
    boolean keepOutliers;

    @Mixin OutputDirOptions out;

    @Spec CommandSpec spec;

    @Option(names = "--folds", paramLabel = "K", description = "K-fold cross-validation of the training poses (K >= 2), per fold and overall")
    Integer folds;

    @Option(names = "--fold-seed", defaultValue = "1", paramLabel = "SEED", description = "seed of the fold assignment (default ${DEFAULT-VALUE})")
    long foldSeed;

    @Option(names = "--base", paramLabel = "POSE|FILE",
            description = "known pose of the robot base in the instrument frame (a tracker registration): x,y,z mm[,qw,qx,qy,qz], "
                    + "or a JSON file with instrument_T_base (a summary.json or truth.json); kept fixed unless --free-base")
    String base;

    @Option(names = "--free-base", description = "with --base: start from the given pose but identify it")
    boolean freeBase;

    @Option(names = "--tool", paramLabel = "POSE|FILE",
            description = "known tool frame on the flange (origin = measured point; a hand-eye result): x,y,z mm[,qw,qx,qy,qz], "
                    + "or a JSON file with flange_T_tool; kept fixed unless --free-tool (replaces --target)")
    String tool;

    @Option(names = "--free-tool", description = "with --tool: start from the given frame but identify it")
    boolean freeTool;

    @Override
    public Integer call() throws Exception {
        RobotDescription desc = robot.description();
        double[] t = CliSupport.numbers("--target", target, 3);
        if (freeBase && base == null) throw new IllegalArgumentException("--free-base needs --base");
        if (freeTool && tool == null) throw new IllegalArgumentException("--free-tool needs --tool");
        if (tool != null && !"0,0,0".equals(target)) throw new IllegalArgumentException("give either --tool or --target, not both");
        CalibrationWorkflow.Settings settings = CalibrationWorkflow.Settings.defaults().withFolds(folds == null ? 0 : folds, foldSeed)
                .withInitialTool(Pose.translation(Units.mmToM(t[0]), Units.mmToM(t[1]), Units.mmToM(t[2])))
                .withOutliers(outlierK, !keepOutliers);
        if (base != null) settings = settings.withInstrument(pose("--base", base, "instrument_T_base"), !freeBase);
        if (tool != null) settings = settings.withTool(pose("--tool", tool, "flange_T_tool"), !freeTool);
        CalibrationWorkflow.Campaign data = measurements.read(desc);
        Cancellation cancel = new Cancellation();
        Thread hook = CliSupport.cancelOnInterrupt(cancel, Thread.currentThread());
        CalibrationWorkflow.Outcome oc;
        try {
            oc = CalibrationWorkflow.run(desc, data, settings, Instant.now().truncatedTo(ChronoUnit.SECONDS).toString(), cancel,
                    CliSupport.progressBar(spec.commandLine().getErr()));
        } catch (CancellationException e) {
            spec.commandLine().getErr().println("robopro: calibration cancelled; nothing written");
            return 130;
        } finally {
            CliSupport.removeHook(hook);
        }
        oc.write(out.dir(), out.force());
        CalibrationResult r = oc.result();
        var w = spec.commandLine().getOut();
        String kind = r.sixD() ? "6-D" : r.pairs() ? "distances between pairs of poses" : r.distance() ? "distances" : r.pointNames().isEmpty() ? "positions"
                : r.pointNames().size() + " points per pose, errors per point";
        w.printf(Locale.ROOT, "calibrated %s from %d poses (%s): RMS %.4f mm -> %.4f mm (train)%n", desc.name(),
                CalibrationResult.poses(r.train()), kind, Units.mToMm(r.nominalTrainRmsM()), Units.mToMm(r.trainRmsM()));
        String of = r.pointNames().isEmpty() ? "poses" : "points";
        w.printf(Locale.ROOT, "  training:   %s%n", stats(ErrorStats.position(r.train(), true), of));
        if (data.validate() != null) w.printf(Locale.ROOT, "  validation (%d poses): RMS %.4f mm -> %.4f mm, max %.4f mm%n    %s%n",
                CalibrationResult.poses(r.validate()), Units.mToMm(r.nominalValidateRmsM()), Units.mToMm(r.validateRmsM()), Units.mToMm(r.validateMaxM()),
                stats(ErrorStats.position(r.validate(), true), of));
        var cv = oc.crossValidation();
        if (cv != null) {
            StringBuilder per = new StringBuilder();
            for (CalibrationResult f : cv.folds()) per.append(per.length() == 0 ? "" : ", ").append(String.format(Locale.ROOT, "%.4f", Units.mToMm(f.validateRmsM())));
            w.printf(Locale.ROOT, "  %d-fold cross-validation (each pose predicted by the model that did not see it): %s%n    per fold RMS: %s mm%n",
                    cv.folds().size(), stats(ErrorStats.position(cv.heldOut(), true), of), per);
        }
        w.printf(Locale.ROOT, "  %d parameters fixed as unidentifiable, condition number %.3g, %d outliers%s%n",
                r.unidentifiable().size(), r.conditionNumber(), r.outliers().size(),
                r.outliers().isEmpty() ? "" : " (" + String.join(", ", r.outliers().stream().map(CalibrationResult.Outlier::poseId).toList()) + ")");
        if (!oc.concerns().isEmpty())
            w.printf(Locale.ROOT, "  not determined by these data (see the warnings): %s%n",
                    String.join(", ", oc.concerns().stream().map(c -> c.parameter()).toList()));
        w.printf("  wrote %s%n", out.dir().toAbsolutePath());
        for (String warning : oc.warnings()) spec.commandLine().getErr().println("robopro: warning: " + warning);
        return 0;
    }

    /**
     * A pose given on the command line: "x,y,z" or "x,y,z,qw,qx,qy,qz" (mm, unit quaternion), or
     * a JSON file holding {@code key} (as summary.json and truth.json write it: x_mm, y_mm, z_mm,
     * qw, qx, qy, qz) or those fields at its top level.
     */
    static Pose pose(String option, String spec, String key) throws java.io.IOException {
        java.nio.file.Path f = java.nio.file.Path.of(spec);
        if (!spec.contains(",") && java.nio.file.Files.isRegularFile(f)) {
            com.fasterxml.jackson.databind.JsonNode root;
            try {
                root = new com.fasterxml.jackson.databind.ObjectMapper().readTree(org.robopro.models.TextFiles.readUtf8(f));
            } catch (com.fasterxml.jackson.core.JsonProcessingException e) {
                throw new org.robopro.models.InputException(spec, e.getLocation() == null ? 0 : e.getLocation().getLineNr(),
                        e.getLocation() == null ? 0 : e.getLocation().getColumnNr(), null, "not JSON: " + e.getOriginalMessage());
            }
            com.fasterxml.jackson.databind.JsonNode n = root != null && root.has(key) ? root.get(key) : root;
            double[] v = new double[7];
            String[] fields = {"x_mm", "y_mm", "z_mm", "qw", "qx", "qy", "qz"};
            for (int i = 0; i < 7; i++) {
                if (n == null || !n.has(fields[i]) || !n.get(fields[i]).isNumber())
                    throw new org.robopro.models.InputException(spec, 0, 0, key + "." + fields[i], "missing number; " + option
                            + " reads '" + key + "' {x_mm, y_mm, z_mm, qw, qx, qy, qz} as summary.json writes it");
                v[i] = n.get(fields[i]).asDouble();
            }
            return quaternionPose(option, v);
        }
        double[] v = CliSupport.numbers(option, spec, 3, 7);
        if (v.length == 3) return Pose.translation(Units.mmToM(v[0]), Units.mmToM(v[1]), Units.mmToM(v[2]));
        return quaternionPose(option, v);
    }

    private static Pose quaternionPose(String option, double[] v) {
        double norm = Math.sqrt(v[3] * v[3] + v[4] * v[4] + v[5] * v[5] + v[6] * v[6]);
        if (Math.abs(norm - 1) > 1e-3)
            throw new IllegalArgumentException(option + ": the quaternion qw,qx,qy,qz must have length 1, got " + norm);
        return Pose.fromQuaternion(v[3], v[4], v[5], v[6], Units.mmToM(v[0]), Units.mmToM(v[1]), Units.mmToM(v[2]));
    }

    /** RMS, mean, median, 95th percentile and max of position errors, mm. */
    /** The statistics line; {@code of} names what was counted ("poses", "points"). */
    static String stats(ErrorStats st, String of) {
        ErrorStats v = st.scaled(1e3);
        return String.format(Locale.ROOT, "RMS %.4f, mean %.4f, median %.4f, p95 %.4f, max %.4f mm (%d %s)",
                v.rms(), v.mean(), v.median(), v.p95(), v.max(), v.n(), of);
    }
}
