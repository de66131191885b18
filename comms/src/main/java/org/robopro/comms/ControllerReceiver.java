package org.robopro.comms;

import java.time.Duration;
import java.util.List;
import org.robopro.kinematics.Pose;
import org.robopro.models.Vec3;
import org.robopro.programs.SpeedData;
import org.robopro.programs.ZoneData;

/**
 * The Receiver of the seed paper's Command pattern (§2.1, Fig. 3): the controller as the
 * commands see it. Implemented by {@link org.robopro.comms.client.ProtocolClient} (TCP and
 * serial) and, in process, by {@link org.robopro.comms.sim.SimulatedController}.
 *
 * <p>SI units throughout (m, rad, s); the protocol converts to mm and degrees at the wire.
 * Methods throw {@link CommsException} subclasses. Implementations need not be thread-safe:
 * the {@link CommandInvoker} calls them from one thread.
 */
public interface ControllerReceiver extends AutoCloseable {

    void ping();

    /** Controller joint values q (rad). */
    double[] readJoints();

    /** The current tool frame seen from the current work object (CRobT with tool and wobj). */
    Pose readPose();

    /**
     * Moves to joint values q (rad). {@code requestId} identifies this motion: a controller
     * that {@link #deduplicatesRequests() de-duplicates} executes one id at most once.
     */
    MotionResult moveJoints(long requestId, double[] q);

    /** Linear move of the tool to {@code wobjTtool} (MoveL). */
    MotionResult moveLinear(long requestId, Pose wobjTtool);

    void setTool(Pose flangeTtool);

    void setWorkObject(Pose baseTwobj);

    void setSpeed(SpeedData speed);

    void setZone(ZoneData zone);

    /** Stores a program; returns what the controller stored, already checked against {@code text}. */
    ProgramInfo downloadProgram(String name, byte[] text);

    /** A stored program's bytes, checked against the length and CRC the controller announced. */
    byte[] uploadProgram(String name);

    List<ProgramInfo> listPrograms();

    /** Starts a stored program ({@code requestId} as for motions: started at most once). */
    void startProgram(long requestId, String name);

    void stopProgram();

    ControllerStatus readStatus();

    /** The laser tracker's reading of the target on the tool, in the tracker frame (m). */
    Vec3 measure();

    /** A tracker reading with the conditions the controller knows (approach directions, clock, temperature, payload). */
    TrackerReading measureReading();

    /** True when request ids are honoured, so a motion may be re-sent safely after a lost reply. */
    boolean deduplicatesRequests();

    /** How long to wait for each reply; the invoker sets it per command. */
    void setReplyTimeout(Duration timeout);

    /** Drops the current connection (if any) and opens a new one. */
    void reconnect();

    @Override
    void close();
}
