package org.robopro.programs.sim;

import java.util.Optional;
import org.robopro.programs.rapid.SourcePos;

/** One step of a program run: a motion, a wait or an I/O or process instruction. */
public sealed interface ProgramStep permits MoveStep, WaitStep, IoStep {
    /** The procedure the statement is in. */
    String procedure();

    /** 0-based index of the statement in its procedure's body. */
    int statementIndex();

    /** Where the statement was written, when the program came from a file. */
    Optional<SourcePos> source();

    /** Call path and loop iteration leading to the statement ("main#4[i=2] > weld#3"), empty at the top level. */
    String context();

    /** A human label: "main#3 MoveL p10" (procedure, statement number from 1, instruction, target), after the context. */
    String label();
}
