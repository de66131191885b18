package org.robopro.programs;

/** One statement of a procedure body that robopro understands. */
public sealed interface Statement permits Move, ProcCall, WaitTime, Comment, AstStatement { }
