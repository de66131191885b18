package org.robopro.programs;

/** A comment line; {@code text} is what follows the '!' (kept verbatim, without the line break). */
public record Comment(String text) implements Statement, ModuleItem {
    public Comment {
        if (text == null || text.indexOf('\n') >= 0 || text.indexOf('\r') >= 0)
            throw new IllegalArgumentException("a comment is one line");
    }
}
