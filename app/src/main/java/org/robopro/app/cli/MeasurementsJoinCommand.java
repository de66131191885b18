package org.robopro.app.cli;

import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.robopro.calibration.measurement.MeasurementJoin;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.calibration.measurement.MeasurementWriter;
import org.robopro.models.JointType;
import org.robopro.models.RobotDescription;
import org.robopro.models.TextFiles;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code robopro measurements join --points FILE --joints FILE --robot ROBOT --out FILE}: a
 * measurement file from the instrument's point list and the controller's joint log, matched by
 * name or by time ({@link MeasurementJoin}, docs/measurement-file.md).
 */
@Command(name = "join", mixinStandardHelpOptions = true,
        description = "Build a measurement file from an instrument's point list and a controller's joint log, matched by name or time.")
public final class MeasurementsJoinCommand implements Callable<Integer> {
    @Mixin RobotOptions robot;

    @Option(names = "--points", required = true, paramLabel = "FILE", description = "point list: name or time, then x,y,z")
    Path points;

    @Option(names = "--joints", required = true, paramLabel = "FILE", description = "joint log: name or time, then q1..qN")
    Path joints;

    @Option(names = "--max-dt", defaultValue = "0.5", paramLabel = "S",
            description = "matching by time: largest time difference accepted, s (default ${DEFAULT-VALUE})")
    double maxDt;

    @Mixin OutputFileOptions out;

    @Spec CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        if (!(maxDt > 0)) throw new IllegalArgumentException("--max-dt must be > 0, got " + maxDt);
        RobotDescription d = robot.description();
        List<JointType> types = d.joints().stream().map(j -> j.type()).toList();
        MeasurementSet s = MeasurementJoin.join(points.toString(), TextFiles.readUtf8(points), joints.toString(), TextFiles.readUtf8(joints),
                types, maxDt);
        MeasurementWriter.write(s, types, out.file(), out.force());
        spec.commandLine().getOut().printf(Locale.ROOT, "wrote %s: %d poses (%s)%n", out.file(), s.size(), s.metadata().get("joined-from"));
        return 0;
    }
}
