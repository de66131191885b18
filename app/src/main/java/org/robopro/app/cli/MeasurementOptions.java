package org.robopro.app.cli;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.measurement.MeasurementReader;
import org.robopro.calibration.measurement.MeasurementSet;
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
     * Training and validation data.
     *
     * @param all      the measurement file as read
     * @param validate the validation poses, or null when there are none
     * @param source   where the validation poses came from (for reports), or null
     */
    record Data(MeasurementSet all, MeasurementSet train, MeasurementSet validate, String source) { }

    /**
     * Reads the files for robot {@code d}.
     *
     * @param holdout fraction of poses kept out of the fit when neither {@code --validate} nor a
     *                set column gives validation poses; null for none
     */
    Data read(RobotDescription d, Double holdout) throws IOException {
        MeasurementSet all = MeasurementReader.read(measurements, d);
        if (validate != null) return new Data(all, all, MeasurementReader.read(validate, d), validate.toString());
        if (all.hasSplit()) {
            MeasurementSet v = all.split(Measurement.Split.VALIDATE);
            return new Data(all, all.split(Measurement.Split.TRAIN), v.size() == 0 ? null : v,
                    v.size() == 0 ? null : measurements + " (set=validate)");
        }
        if (holdout != null) {
            if (!(holdout > 0 && holdout < 1)) throw new IllegalArgumentException("--holdout must be between 0 and 1, got " + holdout);
            int every = (int) Math.max(2, Math.round(1 / holdout));
            List<Measurement> tr = new ArrayList<>(), va = new ArrayList<>();
            for (int i = 0; i < all.size(); i++) (i % every == every - 1 ? va : tr).add(all.rows().get(i));
            return new Data(all, all.withRows(tr), all.withRows(va), measurements + " (hold-out)");
        }
        return new Data(all, all, null, null);
    }

    Path file() { return measurements; }
}
