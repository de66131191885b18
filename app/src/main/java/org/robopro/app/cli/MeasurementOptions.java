package org.robopro.app.cli;

import java.io.IOException;
import java.nio.file.Path;
import org.robopro.calibration.workflow.CalibrationWorkflow;
import org.robopro.models.RobotDescription;
import picocli.CommandLine.Option;

/**
 * Mixin {@code --measurements FILE [--validate FILE] [--holdout FRACTION]} of the commands that
 * fit a model to measurements (calibrate, diagnose). Validation poses come from {@code --validate},
 * else from the file's {@code set} column, else from a hold-out of every n-th pose (the
 * workbench's split, so both give the same figures on the same file).
 */
public final class MeasurementOptions {
    @Option(names = "--measurements", required = true, paramLabel = "FILE", description = "measurement file (docs/measurement-file.md)")
    Path measurements;

    @Option(names = "--validate", paramLabel = "FILE", description = "measurement file of validation poses (default: the file's set column)")
    Path validate;

    @Option(names = "--holdout", paramLabel = "FRACTION",
            description = "without --validate or a set column: keep every (1/FRACTION)-th pose out of the fit for validation")
    Double holdout;

    /** Reads the files for robot {@code d} and splits them by the calibration workflow's rule. */
    CalibrationWorkflow.Campaign read(RobotDescription d) throws IOException {
        return CalibrationWorkflow.load(d, measurements, validate, holdout);
    }

    Path file() { return measurements; }
}
