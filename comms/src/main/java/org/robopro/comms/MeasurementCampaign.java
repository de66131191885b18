package org.robopro.comms;

import java.io.IOException;
import java.io.UncheckedIOException;
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
import org.robopro.calibration.measurement.MeasurementJournal;
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
        return run(invoker, poses, metadata(robot, instrument), null, null, progress);
    }

    /** The metadata of a campaign's measurement file. */
    public static Map<String, String> metadata(String robot, String instrument) {
        Map<String, String> meta = new LinkedHashMap<>();
        meta.put("robot", robot.toLowerCase(Locale.ROOT));
        meta.put("frame", "tracker");
        meta.put("instrument", instrument);
        return meta;
    }

    /**
     * Moves through {@code poses} (rad) and measures at each, appending every row to
     * {@code journal} (synced) as it arrives, so a failure or a kill keeps everything measured.
     * {@code done} (may be null) holds the poses a resumed journal already has: they must be the
     * first poses of {@code poses}, and measuring continues after them.
     */
    public static MeasurementSet run(CommandInvoker invoker, List<double[]> poses, Map<String, String> meta,
                                     MeasurementJournal journal, MeasurementSet done, IntConsumer progress) {
        List<Measurement> rows = new ArrayList<>();
        if (done != null) {
            if (done.size() > poses.size())
                throw new IllegalArgumentException("the journal holds " + done.size() + " poses but the campaign has " + poses.size());
            for (int k = 0; k < done.size(); k++) {
                Measurement m = done.rows().get(k);
                double[] q = poses.get(k);
                boolean same = m.poseId().equals(Integer.toString(k + 1)) && m.dof() == q.length;
                for (int j = 0; same && j < q.length; j++) same = Math.abs(m.q(j) - q[j]) < 1e-8;
                if (!same)
                    throw new IllegalArgumentException("the journal's pose " + m.poseId() + " (line " + m.line()
                            + ") is not pose " + (k + 1) + " of this campaign; resume with the same --poses, --seed and --robot");
                rows.add(m.withPosition(m.position()));
            }
        }
        for (int k = rows.size(); k < poses.size(); k++) {
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
            Measurement row = new Measurement(Integer.toString(k + 1), q, m.position(), null, dirs, c.timeS(), c.tempC(),
                    c.payloadKg(), null, 0);
            if (journal != null) {
                try {
                    journal.append(row);
                } catch (IOException e) {
                    throw new UncheckedIOException("cannot append to the journal " + journal.file() + ": " + e.getMessage(), e);
                }
            }
            rows.add(row);
            progress.accept(k + 1);
        }
        return new MeasurementSet("campaign", meta, "tracker", rows);
    }

    /** Writes the file atomically with calibration's writer; refuses to replace an existing one unless {@code overwrite}. */
    public static void write(MeasurementSet set, List<JointType> jointTypes, Path file, boolean overwrite) throws IOException {
        MeasurementWriter.write(set, jointTypes, file, overwrite);
    }
}
