package org.robopro.comms.sim;

import java.util.List;
import org.robopro.programs.SpeedData;
import org.robopro.kinematics.Pose;

/**
 * Turns a stored RAPID program into the steps the simulated controller executes. The simulator
 * uses {@link RapidProgramInterpreter} (org.robopro.programs' parser and motion interpreter);
 * tests may plug in others.
 */
public interface ProgramInterpreter {

    enum Kind { ABS_JOINTS, JOINT_TO_POSE, LINEAR, CIRCULAR, WAIT }

    /**
     * One step, poses in the robot base frame (m, rad):
     * <ul>
     * <li>ABS_JOINTS: MoveAbsJ to {@code joints};</li>
     * <li>JOINT_TO_POSE: MoveJ, flange to {@code baseTflange} (nominal inverse kinematics);</li>
     * <li>LINEAR: MoveL, the TCP ({@code flangeTtool}) on a straight line to {@code baseTflange · flangeTtool};</li>
     * <li>CIRCULAR: MoveC, the TCP on the arc through {@code baseTflangeCirc · flangeTtool};</li>
     * <li>WAIT: WaitTime {@code waitS}.</li>
     * </ul>
     * {@code speed}, {@code flangeTtool} and {@code baseTwobj} are the instruction's (they become the
     * controller's current ones); {@code timeS} is RAPID's {@code \T} (NaN when absent).
     *
     * @param label "main#3 MoveL p10"
     * @param line  source line (0 when unknown)
     */
    record Step(Kind kind, double[] joints, Pose baseTflange, Pose baseTflangeCirc, SpeedData speed, double timeS,
                Pose flangeTtool, Pose baseTwobj, double waitS, String label, int line) {
        public static Step abs(double[] q, SpeedData s, Pose tool, Pose wobj, String label, int line) {
            return new Step(Kind.ABS_JOINTS, q.clone(), null, null, s, Double.NaN, tool, wobj, 0, label, line);
        }

        public static Step wait(double seconds, String label, int line) {
            return new Step(Kind.WAIT, null, null, null, null, Double.NaN, null, null, seconds, label, line);
        }

        /** "main#3 MoveL p10 (line 12)". */
        public String where() { return label + (line > 0 ? " (line " + line + ")" : ""); }
    }

    /**
     * Null if the program text parses, else what is wrong with it, naming the line and column
     * (e.g. "PROG:12:7: ..."). Called on download: a program that does not parse is not stored.
     */
    String parseProblem(String programText, String name);

    /**
     * The steps of running the program's {@code main}; {@link IllegalArgumentException} naming the
     * line when it cannot be simulated (unknown data, an instruction the simulator does not run).
     * Never drops a motion silently.
     */
    List<Step> compile(String programText, String name, int dof);
}
