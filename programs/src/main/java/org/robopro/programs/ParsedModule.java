package org.robopro.programs;

import java.util.Optional;
import org.robopro.programs.rapid.ParsedAst;
import org.robopro.programs.rapid.SourcePos;

/** A module read from a file: the module (its syntax tree and typed view) and where each node was written. */
public final class ParsedModule {
    private final RapidModule module;
    private final ParsedAst ast;

    ParsedModule(RapidModule module, ParsedAst ast) {
        this.module = module;
        this.ast = ast;
    }

    public RapidModule module() { return module; }

    public String file() { return ast.file(); }

    /** The syntax tree the module is (the same tree as {@code module().tree()}), with positions of every node. */
    public ParsedAst ast() { return ast; }

    /** Where {@code s} (a statement of {@link #module()}'s view, this very object) was written: its tree node's position. */
    public Optional<SourcePos> position(Statement s) { return module.node(s).flatMap(ast::position); }
}
