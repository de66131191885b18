package org.robopro.programs.rapid;

/** One RAPID token with its 1-based line and column; {@code text} is the source text (a comment's text after '!'). */
record Token(Kind kind, String text, int line, int column) {
    enum Kind { IDENT, NUMBER, STRING, PUNCT, COMMENT, EOF }

    boolean is(String punct) { return kind == Kind.PUNCT && text.equals(punct); }

    boolean isWord(String word) { return kind == Kind.IDENT && text.equalsIgnoreCase(word); }

    String describe() {
        return switch (kind) {
            case EOF -> "end of file";
            case COMMENT -> "comment";
            case STRING -> "string " + text;
            default -> "'" + text + "'";
        };
    }
}
