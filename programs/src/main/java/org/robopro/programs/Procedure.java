package org.robopro.programs;

import java.util.List;

/** {@code [LOCAL] PROC name() ... ENDPROC} without parameters. */
public record Procedure(String name, boolean local, List<Statement> body) implements ModuleItem {
    public Procedure {
        if (name == null || name.isEmpty()) throw new IllegalArgumentException("procedure needs a name");
        body = List.copyOf(body);
    }

    public Procedure(String name, List<Statement> body) { this(name, false, body); }

    public Procedure withBody(List<Statement> newBody) { return new Procedure(name, local, newBody); }
}
