package org.robopro.comms.sim;

import java.util.List;
import org.robopro.comms.SpeedData;
import org.robopro.kinematics.Pose;

/**
 * Turns a stored RAPID program into the motions the simulated controller executes. The
 * simulator ships a small one ({@link MiniRapidInterpreter}); the full RAPID interpreter of
 * org.robopro.programs can be plugged in instead.
 */
public interface ProgramInterpreter {

    enum Kind { ABS_JOINTS, JOINT_TO_POSE, LINEAR }

    /**
     * One motion: MoveAbsJ to {@code joints} (rad), MoveJ to {@code pose}, or MoveL to
     * {@code pose} ({@code wobjTtool}, m); with the speed, tool ({@code flangeTtool}) and work
     * object ({@code baseTwobj}) of the instruction (null: keep the controller's).
     */
    record Step(Kind kind, double[] joints, Pose pose, SpeedData speed, Pose tool, Pose wobj, int line) { }

    /** Null if the program can be run, else what is wrong with it (with the line). */
    String check(String programText, int dof);

    /** The motions of the program's main procedure; IllegalArgumentException naming the line if it cannot. */
    List<Step> compile(String programText, int dof);
}
