package org.robopro.programs.sim;

import java.util.Optional;
import org.robopro.programs.rapid.SourcePos;

/** {@code WaitTime}: the program waits {@code seconds}; {@code context} is the call path and loop iteration, empty at the top level. */
public record WaitStep(String procedure, int statementIndex, Optional<SourcePos> source, double seconds, String context) implements ProgramStep {
    public WaitStep(String procedure, int statementIndex, Optional<SourcePos> source, double seconds) {
        this(procedure, statementIndex, source, seconds, "");
    }

    @Override public String label() { return (context.isEmpty() ? "" : context + " > ") + procedure + "#" + (statementIndex + 1) + " WaitTime"; }
}
