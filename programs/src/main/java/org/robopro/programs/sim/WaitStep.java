package org.robopro.programs.sim;

import java.util.Optional;
import org.robopro.programs.rapid.SourcePos;

/** {@code WaitTime}: the program waits {@code seconds}. */
public record WaitStep(String procedure, int statementIndex, Optional<SourcePos> source, double seconds) implements ProgramStep {
    @Override public String label() { return procedure + "#" + (statementIndex + 1) + " WaitTime"; }
}
