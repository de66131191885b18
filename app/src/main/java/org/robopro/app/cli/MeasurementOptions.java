package org.robopro.app.cli;

import java.io.IOException;
import java.nio.file.Path;
import org.robopro.calibration.workflow.CalibrationWorkflow;
import org.robopro.models.RobotDescription;
import picocli.CommandLine.Option;

/**
 * Mixin {@code --measurements FILE [--validate FILE]} of the commands that fit a model to
 * measurements (calibrate, diagnose). Validation poses come from {@code --validate}, else from the
 * file's {@code set} column, else (when the command offers it) from a hold-out of every n-th pose.
 */
public final class MeasurementOptions {
    @Option(names = "--measurements", required = true, paramLabel = "FILE", description = "measurement file (docs/measurement-file.md)")
    Path measurements;

    @Option(names = "--validate", paramLabel = "FILE", description = "measurement file of validation poses (default: the file's set column)")
    Path validate;

    /**
     * Reads the files for robot {@code d} and splits them by the calibration workflow's rule.
     *
     * @param holdout fraction of poses kept out of the fit when neither {@code --validate} nor a
     *                set column gives validation poses; null for none
     */
    CalibrationWorkflow.Campaign read(RobotDescription d, Double holdout) throws IOException {
        return CalibrationWorkflow.load(d, measurements, validate, holdout);
    }

    Path file() { return measurements; }
}
