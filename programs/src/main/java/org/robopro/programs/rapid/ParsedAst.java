package org.robopro.programs.rapid;

import java.util.IdentityHashMap;
import java.util.Map;
import java.util.Optional;

/** A module's syntax tree and where each item, statement and expression was written. */
public final class ParsedAst {
    private final RapidAst.Module module;
    private final String file;
    private final IdentityHashMap<Object, SourcePos> positions;

    ParsedAst(RapidAst.Module module, String file, IdentityHashMap<Object, SourcePos> positions) {
        this.module = module;
        this.file = file;
        this.positions = new IdentityHashMap<>(positions);
    }

    /** A tree built in code: no positions; {@code file} names it in messages. */
    public static ParsedAst of(RapidAst.Module module, String file) { return new ParsedAst(module, file, new IdentityHashMap<>()); }

    public RapidAst.Module module() { return module; }

    public String file() { return file; }

    /** Where {@code node} (this very object of {@link #module()}) was written. */
    public Optional<SourcePos> position(Object node) { return Optional.ofNullable(positions.get(node)); }

    Map<Object, SourcePos> positions() { return positions; }
}
