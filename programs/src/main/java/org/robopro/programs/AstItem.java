package org.robopro.programs;

import org.robopro.programs.rapid.RapidAst;

/**
 * A module item outside robopro's typed model (a routine with parameters or handlers, a FUNC or
 * TRAP, a RECORD, an ALIAS, data of other types, arrays, data computed by an expression), kept
 * as its syntax tree so an imported module exports with the same meaning.
 */
public record AstItem(RapidAst.Item item) implements ModuleItem {
    public AstItem {
        if (item == null) throw new IllegalArgumentException("item must not be null");
    }

    /** The declared name (data, record, alias or routine); null for a comment line. */
    public String name() {
        if (item instanceof RapidAst.DataDecl d) return d.name();
        if (item instanceof RapidAst.RecordDecl r) return r.name();
        if (item instanceof RapidAst.AliasDecl a) return a.name();
        if (item instanceof RapidAst.Routine r) return r.name();
        return null;
    }
}
