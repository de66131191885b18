package org.robopro.comms;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Random;
import java.util.function.IntConsumer;
import org.robopro.calibration.PoseConditions;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.calibration.measurement.MeasurementWriter;
import org.robopro.calibration.simulation.PoseSampler;
import org.robopro.kinematics.KinematicModel;
import org.robopro.models.JointType;

/**
 * A calibration campaign through the controller link against a controller with a tracker (the
 * simulator's MEASURE): move to each joint pose, take a tracker reading, and collect the rows as
 * a calibration {@link MeasurementSet}, written with calibration's {@link MeasurementWriter}
 * (/work/shared/formats/measurements.md: frame "tracker", dir1..dirN from the controller's real
 * approach direction of each joint, time_s from the controller clock, temp_c when the controller
 * models temperature, payload_kg).
 */
public final class MeasurementCampaign {
    private MeasurementCampaign() { }

    /** The campaign stopped at a pose; {@link #getCause()} is the link's or the controller's failure. */
    public static final class Stopped extends RuntimeException {
        private static final long serialVersionUID = 1L;
        private final int pose;

        Stopped(int pose, int of, CommsException cause) {
            super("campaign stopped at pose " + pose + " of " + of + ": " + cause.getMessage(), cause);
            this.pose = pose;
        }

        /** 1-based index of the pose that failed. */
        public int pose() { return pose; }
    }

    /** {@code n} poses by calibration's pose rule (docs/calibration.md, "Pose rule"), seeded. */
    public static List<double[]> samplePoses(KinematicModel nominal, int n, long seed) {
        return new PoseSampler(nominal).sample(n, new Random(seed));
    }

    /** Moves through {@code poses} (rad) and measures at each; stops at the first failure (the exception says which pose). */
    public static MeasurementSet run(CommandInvoker invoker, List<double[]> poses, String robot, String instrument) {
        return run(invoker, poses, robot, instrument, k -> { });
    }

    /**
     * As {@link #run(CommandInvoker, List, String, String)}, telling {@code progress} the number of
     * poses done after each.
     */
    public static MeasurementSet run(CommandInvoker invoker, List<double[]> poses, String robot, String instrument,
                                     IntConsumer progress) {
        List<Measurement> rows = new ArrayList<>();
        for (int k = 0; k < poses.size(); k++) {
            double[] q = poses.get(k);
            TrackerReading m;
            try {
                invoker.execute(Commands.moveJoints(q));
                m = invoker.execute(Commands.measureReading());
            } catch (CommsException e) {
                throw new Stopped(k + 1, poses.size(), e);
            }
            PoseConditions c = m.conditions();
            int[] dirs = c.directions();
            if (dirs == null || dirs.length != q.length) dirs = null;
            rows.add(new Measurement(Integer.toString(k + 1), q, m.position(), null, dirs, c.timeS(), c.tempC(), c.payloadKg(), null, 0));
            progress.accept(k + 1);
        }
        Map<String, String> meta = new LinkedHashMap<>();
        meta.put("robot", robot.toLowerCase(Locale.ROOT));
        meta.put("frame", "tracker");
        meta.put("instrument", instrument);
        return new MeasurementSet("campaign", meta, "tracker", rows);
    }

    /** Writes the file atomically with calibration's writer; refuses to replace an existing one unless {@code overwrite}. */
    public static void write(MeasurementSet set, List<JointType> jointTypes, Path file, boolean overwrite) throws IOException {
        MeasurementWriter.write(set, jointTypes, file, overwrite);
    }
}
