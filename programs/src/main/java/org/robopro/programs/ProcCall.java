package org.robopro.programs;

/** A call of a procedure without arguments ({@code approach;}). */
public record ProcCall(String procedure) implements Statement {
    public ProcCall {
        if (procedure == null || procedure.isEmpty()) throw new IllegalArgumentException("procedure name needed");
    }
}
