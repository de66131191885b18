package org.robopro.programs.check;

import java.util.Optional;
import org.robopro.programs.rapid.SourcePos;

/**
 * One problem a path check found, named by instruction and target.
 *
 * @param severity ERROR: the controller would stop or the robot cannot do it; WARNING: it may work but is risky
 * @param kind     what kind of problem
 * @param step     the instruction's label ("main#3 MoveL p10")
 * @param target   the target's name ("*" inline)
 * @param source   where the instruction was written, if known
 * @param message  human explanation with the numbers
 */
public record Problem(Severity severity, Kind kind, String step, String target, Optional<SourcePos> source, String message) {
    public enum Severity { ERROR, WARNING }

    public enum Kind { UNREACHABLE, CONFIGURATION_MISMATCH, JOINT_LIMIT, CONFIGURATION_CHANGE, NEAR_SINGULARITY, BAD_CIRCLE, UNSUPPORTED, NOT_SIMULATED, IO_WAIT, COLLISION }

    @Override public String toString() {
        return severity + " " + kind + " at " + step + source.map(s -> " (" + s + ")").orElse("") + (target.isEmpty() ? "" : ", target " + target)
                + ": " + message;
    }
}
