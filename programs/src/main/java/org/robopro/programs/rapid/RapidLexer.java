package org.robopro.programs.rapid;

import java.util.ArrayList;
import java.util.List;
import org.robopro.models.InputException;

/** Splits RAPID text into tokens with line and column; bad characters fail with their position. */
final class RapidLexer {
    private final String s;
    private final String file;
    private int pos;
    private int line = 1;
    private int col = 1;

    RapidLexer(String text, String file) {
        this.s = text;
        this.file = file;
    }

    List<Token> tokens() {
        List<Token> out = new ArrayList<>();
        while (true) {
            skipSpace();
            if (pos >= s.length()) {
                out.add(new Token(Token.Kind.EOF, "", line, col));
                return out;
            }
            int l = line, c = col;
            char ch = s.charAt(pos);
            if (ch == '!') {
                int start = pos + 1;
                while (pos < s.length() && s.charAt(pos) != '\n' && s.charAt(pos) != '\r') advance();
                out.add(new Token(Token.Kind.COMMENT, s.substring(start, pos), l, c));
            } else if (RapidNames.isAsciiLetter(ch)) {
                int start = pos;
                while (pos < s.length() && (RapidNames.isAsciiLetter(s.charAt(pos)) || isDigit(s.charAt(pos)) || s.charAt(pos) == '_'))
                    advance();
                String id = s.substring(start, pos);
                if (id.length() > RapidNames.MAX_LENGTH)
                    throw new InputException(file, l, c, id.substring(0, 12) + "...", "identifier longer than "
                            + RapidNames.MAX_LENGTH + " characters (" + id.length() + ")");
                out.add(new Token(Token.Kind.IDENT, id, l, c));
            } else if (isDigit(ch) || (ch == '.' && pos + 1 < s.length() && isDigit(s.charAt(pos + 1)))) {
                out.add(number(l, c));
            } else if (ch == '"') {
                out.add(string(l, c));
            } else {
                String two = pos + 1 < s.length() ? s.substring(pos, pos + 2) : "";
                if (two.equals(":=") || two.equals("<=") || two.equals(">=") || two.equals("<>")) {
                    advance();
                    advance();
                    out.add(new Token(Token.Kind.PUNCT, two, l, c));
                } else if ("[](){},;:\\+-*/=<>.%?|".indexOf(ch) >= 0) {
                    advance();
                    out.add(new Token(Token.Kind.PUNCT, String.valueOf(ch), l, c));
                } else {
                    throw new InputException(file, l, c, null, "unexpected character "
                            + (ch >= ' ' && ch < 127 ? "'" + ch + "'" : String.format("U+%04X", (int) ch)));
                }
            }
        }
    }

    private Token number(int l, int c) {
        int start = pos;
        if (s.charAt(pos) == '0' && pos + 2 < s.length() && "xXbBoO".indexOf(s.charAt(pos + 1)) >= 0
                && digitOf(s.charAt(pos + 2), radix(s.charAt(pos + 1))) >= 0) {
            // 0x1F, 0b101, 0o17: RAPID's hexadecimal, binary and octal literals
            int radix = radix(s.charAt(pos + 1));
            advance();
            advance();
            while (pos < s.length() && digitOf(s.charAt(pos), radix) >= 0) advance();
            if (pos < s.length() && (RapidNames.isAsciiLetter(s.charAt(pos)) || isDigit(s.charAt(pos)) || s.charAt(pos) == '_'))
                throw new InputException(file, line, col, null, "unexpected '" + s.charAt(pos) + "' in number '" + s.substring(start, pos) + "'");
            return new Token(Token.Kind.NUMBER, s.substring(start, pos), l, c);
        }
        while (pos < s.length() && isDigit(s.charAt(pos))) advance();
        if (pos < s.length() && s.charAt(pos) == '.') {
            advance();
            while (pos < s.length() && isDigit(s.charAt(pos))) advance();
        }
        if (pos < s.length() && (s.charAt(pos) == 'e' || s.charAt(pos) == 'E')) {
            advance();
            if (pos < s.length() && (s.charAt(pos) == '+' || s.charAt(pos) == '-')) advance();
            if (pos >= s.length() || !isDigit(s.charAt(pos)))
                throw new InputException(file, line, col, null, "number '" + s.substring(start, pos) + "' has no exponent digits");
            while (pos < s.length() && isDigit(s.charAt(pos))) advance();
        }
        if (pos < s.length() && (RapidNames.isAsciiLetter(s.charAt(pos)) || s.charAt(pos) == '_'))
            throw new InputException(file, line, col, null, "unexpected '" + s.charAt(pos) + "' after number '" + s.substring(start, pos) + "'");
        return new Token(Token.Kind.NUMBER, s.substring(start, pos), l, c);
    }

    private Token string(int l, int c) {
        int start = pos;
        advance();
        while (true) {
            if (pos >= s.length() || s.charAt(pos) == '\n' || s.charAt(pos) == '\r')
                throw new InputException(file, l, c, null, "string not closed on its line");
            char ch = s.charAt(pos);
            if (ch == '"') {
                if (pos + 1 < s.length() && s.charAt(pos + 1) == '"') { advance(); advance(); continue; }
                advance();
                break;
            }
            if (ch == '\\' && pos + 1 < s.length() && s.charAt(pos + 1) != '\n') { advance(); advance(); continue; }
            advance();
        }
        String raw = s.substring(start + 1, pos - 1);
        return new Token(Token.Kind.STRING, raw, l, c);
    }

    private void skipSpace() {
        while (pos < s.length()) {
            char ch = s.charAt(pos);
            if (ch == ' ' || ch == '\t' || ch == '\n' || ch == '\r' || ch == '\f' || ch == '\uFEFF') advance();
            else break;
        }
    }

    private void advance() {
        char ch = s.charAt(pos++);
        if (ch == '\n' || (ch == '\r' && (pos >= s.length() || s.charAt(pos) != '\n'))) {
            line++;
            col = 1;
        } else if (ch != '\r') {
            col++;
        }
    }

    private static boolean isDigit(char c) { return c >= '0' && c <= '9'; }

    private static int radix(char c) {
        char k = Character.toLowerCase(c);
        return k == 'x' ? 16 : k == 'b' ? 2 : 8;
    }

    private static int digitOf(char c, int radix) { return c < 128 ? Character.digit(c, radix) : -1; }
}
