package org.robopro.programs;

import java.util.IdentityHashMap;
import java.util.Map;
import java.util.Optional;
import org.robopro.programs.rapid.ParsedAst;
import org.robopro.programs.rapid.SourcePos;

/** A parsed module together with where each statement was written (for error messages) and its syntax tree. */
public final class ParsedModule {
    private final RapidModule module;
    private final String file;
    private final IdentityHashMap<Statement, SourcePos> positions;
    private final ParsedAst ast;

    ParsedModule(RapidModule module, String file, IdentityHashMap<Statement, SourcePos> positions, ParsedAst ast) {
        this.module = module;
        this.ast = ast;
        this.file = file;
        this.positions = new IdentityHashMap<>(positions);
    }

    public RapidModule module() { return module; }

    public String file() { return file; }

    /** The syntax tree the module was read from, with positions of every node. */
    public ParsedAst ast() { return ast; }

    /** Where {@code s} (this very statement object of {@link #module()}) was written. */
    public Optional<SourcePos> position(Statement s) { return Optional.ofNullable(positions.get(s)); }

    Map<Statement, SourcePos> positions() { return positions; }
}
