package org.robopro.programs;

import org.robopro.programs.rapid.RapidAst;

/**
 * A statement outside robopro's typed model (control flow, assignments, other instructions,
 * Moves with computed arguments), kept as its syntax tree; the interpreter runs what it can and
 * names what it cannot simulate.
 */
public record AstStatement(RapidAst.Stmt stmt) implements Statement {
    public AstStatement {
        if (stmt == null) throw new IllegalArgumentException("stmt must not be null");
    }
}
