package org.robopro.programs.sim;

import java.util.Optional;
import org.robopro.programs.rapid.RapidAst;
import org.robopro.programs.rapid.SourcePos;

/**
 * {@code WaitTime}: the program waits {@code seconds}; {@code context} is the call path and loop
 * iteration, empty at the top level; {@code statement} the syntax-tree node that ran (as
 * {@link MoveStep#statement()}).
 */
public record WaitStep(String procedure, int statementIndex, Optional<SourcePos> source, double seconds, String context,
                       Optional<RapidAst.Stmt> statement) implements ProgramStep {
    @Override public String label() { return (context.isEmpty() ? "" : context + " > ") + procedure + "#" + (statementIndex + 1) + " WaitTime"; }
}
