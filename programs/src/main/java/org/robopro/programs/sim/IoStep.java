package org.robopro.programs.sim;

import java.util.Optional;
import org.robopro.programs.rapid.RapidAst;
import org.robopro.programs.rapid.SourcePos;

/**
 * An I/O or process instruction in a program run: an output set or pulsed, a wait for a signal
 * or a condition, a trigger fired during the preceding motion, the welding arc switched on or
 * off. The interpreter only records what the program asks; the path check places it on the
 * cycle's time line (when inputs change, how long a wait takes).
 *
 * @param context     call path and loop iteration ("main#4[i=2] > weld#3"), empty at the top
 * @param kind        what the instruction does
 * @param instruction the RAPID instruction as written (SetDO, WaitDI, ArcLStart, TriggIO, ...)
 * @param signal      the signal's name (empty for conditions and the arc)
 * @param value       the value set or waited for
 * @param seconds     SET: \SDelay; PULSE: pulse length; WAIT_*: \MaxTime (infinite without);
 *                    TRIGGER: distance (m) or time (s) before/after the motion's end or start
 * @param trigger     TRIGGER: how {@code seconds} is measured; empty otherwise
 * @param text        the condition (WAIT_CONDITION), the arc's seam and weld data (ARC_*), or empty
 * @param statement   the syntax-tree node that ran (as {@link MoveStep#statement()}); a trigger
 *                    firing points to the TriggL/TriggJ/TriggC that fired it
 */
public record IoStep(String procedure, int statementIndex, Optional<SourcePos> source, String context, Kind kind,
                     String instruction, String signal, double value, double seconds, Optional<Trigger> trigger, String text,
                     Optional<RapidAst.Stmt> statement)
        implements ProgramStep {

    public enum Kind { SET, PULSE, WAIT_SIGNAL, WAIT_CONDITION, TRIGGER, ARC_ON, ARC_OFF }

    /**
     * When a trigger fires relative to its motion (TriggIO): {@code fromStart} distances count
     * from the motion's start, otherwise back from its end; {@code time}: the amount is seconds
     * before the end (\Time), otherwise metres along the path.
     */
    public record Trigger(boolean fromStart, boolean time) { }

    @Override public String label() {
        return (context.isEmpty() ? "" : context + " > ") + procedure + "#" + (statementIndex + 1) + " " + instruction
                + (signal.isEmpty() ? "" : " " + signal);
    }
}
