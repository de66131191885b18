package org.robopro.programs.sim;

import java.util.Optional;
import org.robopro.programs.rapid.SourcePos;

/** One step of a program run: a motion or a wait. */
public sealed interface ProgramStep permits MoveStep, WaitStep {
    /** The procedure the statement is in. */
    String procedure();

    /** 0-based index of the statement in its procedure's body. */
    int statementIndex();

    /** Where the statement was written, when the program came from a file. */
    Optional<SourcePos> source();

    /** A human label: "main#3 MoveL p10" (procedure, statement number from 1, instruction, target). */
    String label();
}
