package org.robopro.programs.rapid;

import java.util.Locale;
import java.util.Set;

/** RAPID identifier rules: a letter, then letters, digits or '_'; at most 32 characters; no reserved word. */
public final class RapidNames {
    private RapidNames() { }

    public static final int MAX_LENGTH = 32;

    /** RAPID's reserved words (Technical reference manual, RAPID kernel, "Reserved words"). */
    public static final Set<String> RESERVED = Set.of("ALIAS", "AND", "BACKWARD", "CASE", "CONNECT", "CONST",
            "DEFAULT", "DIV", "DO", "ELSE", "ELSEIF", "ENDFOR", "ENDFUNC", "ENDIF", "ENDMODULE", "ENDPROC",
            "ENDRECORD", "ENDTEST", "ENDTRAP", "ENDWHILE", "ERROR", "EXIT", "FALSE", "FOR", "FROM", "FUNC", "GOTO",
            "IF", "INOUT", "LOCAL", "MOD", "MODULE", "NOSTEPIN", "NOT", "NOVIEW", "OR", "PERS", "PROC", "RAISE",
            "READONLY", "RECORD", "RETRY", "RETURN", "STEP", "SYSMODULE", "TASK", "TEST", "THEN", "TO", "TRAP",
            "TRUE", "TRYNEXT", "UNDO", "VAR", "VIEWONLY", "WHILE", "WITH", "XOR");

    public static boolean isReserved(String s) { return RESERVED.contains(s.toUpperCase(Locale.ROOT)); }

    public static boolean isValid(String s) {
        if (s == null || s.isEmpty() || s.length() > MAX_LENGTH) return false;
        if (!isAsciiLetter(s.charAt(0))) return false;
        for (int i = 1; i < s.length(); i++) {
            char c = s.charAt(i);
            if (!(isAsciiLetter(c) || (c >= '0' && c <= '9') || c == '_')) return false;
        }
        return !isReserved(s);
    }

    /** A valid identifier close to {@code s} (invalid characters to '_', a letter prefix, cut to 32). */
    public static String sanitize(String s) {
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < (s == null ? 0 : s.length()); i++) {
            char c = s.charAt(i);
            b.append(isAsciiLetter(c) || (c >= '0' && c <= '9') || c == '_' ? c : '_');
        }
        if (b.length() == 0 || !isAsciiLetter(b.charAt(0))) b.insert(0, 'r');
        String out = b.length() > MAX_LENGTH ? b.substring(0, MAX_LENGTH) : b.toString();
        if (isReserved(out)) out = out.length() < MAX_LENGTH ? out + "_" : "r" + out.substring(1);
        return out;
    }

    static boolean isAsciiLetter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
}
