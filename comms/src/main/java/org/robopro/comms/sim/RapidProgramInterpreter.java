package org.robopro.comms.sim;

import java.util.ArrayList;
import java.util.List;
import org.robopro.programs.SpeedData;
import org.robopro.kinematics.Pose;
import org.robopro.models.InputException;
import org.robopro.programs.Move;
import org.robopro.programs.ParsedModule;
import org.robopro.programs.RapidParser;
import org.robopro.programs.rapid.SourcePos;
import org.robopro.programs.sim.IoStep;
import org.robopro.programs.sim.MotionInterpreter;
import org.robopro.programs.sim.MoveStep;
import org.robopro.programs.sim.ProgramStep;
import org.robopro.programs.sim.WaitStep;

/**
 * The simulator's program interpreter: org.robopro.programs' {@link RapidParser} and
 * {@link MotionInterpreter} (MoveAbsJ, MoveJ, MoveL, MoveC, WaitTime, procedure calls, and
 * whatever else that interpreter runs), turned into controller {@link ProgramInterpreter.Step}s.
 * What the interpreter cannot simulate is refused with its file:line:column message; a
 * motion is never skipped. Stateless and thread-safe.
 */
public final class RapidProgramInterpreter implements ProgramInterpreter {

    @Override
    public String parseProblem(String text, String name) {
        try {
            RapidParser.parseDetailed(text, name);
            return null;
        } catch (InputException e) {
            return e.getMessage();
        } catch (RuntimeException e) { // a parser bug must not take the controller down
            return name + ": " + e;
        }
    }

    @Override
    public List<Step> compile(String text, String name, int dof) {
        List<ProgramStep> steps;
        try {
            ParsedModule parsed = RapidParser.parseDetailed(text, name);
            steps = MotionInterpreter.of(parsed).strict().run();
        } catch (InputException e) {
            throw new IllegalArgumentException(e.getMessage(), e);
        }
        List<Step> out = new ArrayList<>(steps.size());
        for (ProgramStep ps : steps) out.add(step(ps, name, dof));
        return out;
    }

    private static Step step(ProgramStep ps, String name, int dof) {
        int line = ps.source().map(SourcePos::line).orElse(0);
        if (ps instanceof WaitStep w) return Step.wait(w.seconds(), w.label(), line);
        // I/O and process instructions: the simulated controller has no I/O, so they take no time.
        if (ps instanceof IoStep io) return Step.wait(0, io.label(), line);
        MoveStep m = (MoveStep) ps;
        String at = name + ":" + line + ": " + m.label() + ": ";
        if (!m.tool().robhold())
            throw new IllegalArgumentException(at + "not simulated: stationary tools (tooldata robhold FALSE)");
        SpeedData speed = speed(m.speed(), at);
        double timeS = m.time().isPresent() ? m.time().getAsDouble() : Double.NaN;
        Pose wobj = m.wobj().uframe().toPose().times(m.wobj().oframe().toPose());
        if (m.kind() == Move.Kind.MOVE_ABS_J) {
            double[] q = m.q().orElseThrow();
            if (q.length < dof)
                throw new IllegalArgumentException(at + "jointtarget has " + q.length + " robot axes, the robot has " + dof);
            double[] qd = new double[dof];
            System.arraycopy(q, 0, qd, 0, dof);
            return new Step(Kind.ABS_JOINTS, qd, null, null, speed, timeS, m.flangeTtcp(), wobj, 0, m.label(), line);
        }
        Kind kind = switch (m.kind()) {
            case MOVE_J -> Kind.JOINT_TO_POSE;
            case MOVE_L -> Kind.LINEAR;
            case MOVE_C -> Kind.CIRCULAR;
            case MOVE_ABS_J -> throw new AssertionError();
        };
        return new Step(kind, null, m.baseTflange().orElseThrow(), m.baseTflangeCirc().orElse(null), speed, timeS,
                m.flangeTtcp(), wobj, 0, m.label(), line);
    }

    private static SpeedData speed(SpeedData s, String at) {
        if (!(s.vTcp() > 0 && s.vOri() > 0))
            throw new IllegalArgumentException(at + "speeddata must have TCP and reorientation speeds > 0");
        return s;
    }
}
