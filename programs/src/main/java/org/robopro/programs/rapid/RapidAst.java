package org.robopro.programs.rapid;

import java.math.BigInteger;
import java.util.List;
import java.util.Locale;

/**
 * The syntax tree of a RAPID module as written (ABB RAPID kernel grammar): every declaration,
 * routine, statement and expression, with comments kept as lines. Immutable records with value
 * equality, so "parse, write, parse" can be compared with {@code equals}. Keywords and operators
 * are held upper-case; names and literals as written (RAPID names ignore case, look-ups here
 * do too). Where each node was written is kept apart ({@link ParsedAst#position}).
 */
public final class RapidAst {
    private RapidAst() { }

    /** Where data is visible: everywhere (no keyword), in its module ({@code LOCAL}) or its task ({@code TASK}). */
    public enum Scope { GLOBAL, LOCAL, TASK }

    /** How data is kept: a constant, a persistent (its value written back to the module) or a variable. */
    public enum Storage { CONST, PERS, VAR }

    /** {@code MODULE name[(options)] items ENDMODULE}. */
    public record Module(String name, List<String> options, List<Item> items) {
        public Module {
            if (name == null || name.isEmpty()) throw new IllegalArgumentException("module needs a name");
            options = List.copyOf(options);
            items = List.copyOf(items);
        }
    }

    /** A module-level item. */
    public sealed interface Item permits CommentLine, DataDecl, RecordDecl, AliasDecl, Routine { }

    /** A statement of a routine body. */
    public sealed interface Stmt permits CommentLine, DataDecl, Assign, Call, If, CompactIf, While, For, Test, Goto,
            Label, Return, Raise, Retry, TryNext, Exit, Connect { }

    /** A member of a RECORD: a component or a comment line. */
    public sealed interface Member permits Field, CommentLine { }

    /** {@code !text}: a comment line (text after the '!', verbatim). */
    public record CommentLine(String text) implements Item, Stmt, Member {
        public CommentLine {
            if (text == null || text.indexOf('\n') >= 0 || text.indexOf('\r') >= 0) throw new IllegalArgumentException("a comment is one line");
        }
    }

    /**
     * {@code [LOCAL|TASK] VAR|PERS|CONST type name[{dims}] [:= init];}: module data, or routine data
     * (then scope is GLOBAL). {@code init} is null when none is written (the type's zero value).
     */
    public record DataDecl(RapidAst.Scope scope, RapidAst.Storage storage, String type, String name, List<Expr> dims,
                           Expr init) implements Item, Stmt {
        public DataDecl {
            if (scope == null || storage == null || type == null || name == null) throw new IllegalArgumentException("declaration fields must not be null");
            dims = List.copyOf(dims);
        }
    }

    /** {@code [LOCAL] RECORD name members ENDRECORD}. */
    public record RecordDecl(boolean local, String name, List<Member> members) implements Item {
        public RecordDecl { members = List.copyOf(members); }

        public List<Field> fields() { return members.stream().filter(m -> m instanceof Field).map(m -> (Field) m).toList(); }
    }

    /** A record component {@code type name;}. */
    public record Field(String type, String name) implements Member { }

    /** {@code [LOCAL] ALIAS type name;}. */
    public record AliasDecl(boolean local, String type, String name) implements Item { }

    public enum RoutineKind { PROC, FUNC, TRAP }

    /**
     * A routine. {@code returnType} only for FUNC; {@code params} empty for TRAP. {@code backward},
     * {@code error}, {@code undo} are null when the handler is absent; {@code errorNumbers} is the
     * ERROR handler's list {@code ERROR (n, ...)}, null when not written.
     */
    public record Routine(boolean local, RoutineKind kind, String returnType, String name, List<Param> params, List<Stmt> body,
                          List<Stmt> backward, List<Expr> errorNumbers, List<Stmt> error, List<Stmt> undo) implements Item {
        public Routine {
            if (kind == null || name == null) throw new IllegalArgumentException("routine needs a kind and a name");
            if ((kind == RoutineKind.FUNC) != (returnType != null)) throw new IllegalArgumentException("a return type belongs to FUNC");
            params = List.copyOf(params);
            body = List.copyOf(body);
            backward = backward == null ? null : List.copyOf(backward);
            errorNumbers = errorNumbers == null ? null : List.copyOf(errorNumbers);
            error = error == null ? null : List.copyOf(error);
            undo = undo == null ? null : List.copyOf(undo);
            if (errorNumbers != null && error == null) throw new IllegalArgumentException("error numbers need an ERROR handler");
        }
    }

    /**
     * A routine parameter: required (one alternative) or optional ({@code \alt1 | alt2 ...}).
     */
    public record Param(boolean optional, List<ParamAlt> alternatives) {
        public Param {
            alternatives = List.copyOf(alternatives);
            if (alternatives.isEmpty() || (!optional && alternatives.size() > 1))
                throw new IllegalArgumentException("a required parameter has exactly one alternative");
        }
    }

    /** {@code [VAR|PERS|INOUT] type name[{*,...}]}; mode null for a plain (in) parameter; type "switch" for switches. */
    public record ParamAlt(String mode, String type, String name, int arrayDims) { }

    // ---------------------------------------------------------------- statements

    /** {@code target := value;} (target: a name, component or array element). */
    public record Assign(Expr target, Expr value) implements Stmt { }

    /** A procedure call {@code name args;} or late bound {@code %expr% args;} (then name is null). */
    public record Call(String name, Expr lateBinding, List<Arg> args) implements Stmt {
        public Call {
            if ((name == null) == (lateBinding == null)) throw new IllegalArgumentException("a call has a name or a late binding");
            args = List.copyOf(args);
        }
    }

    public record If(Expr condition, List<Stmt> then, List<ElseIf> elseIfs, List<Stmt> otherwise) implements Stmt {
        public If {
            then = List.copyOf(then);
            elseIfs = List.copyOf(elseIfs);
            otherwise = otherwise == null ? null : List.copyOf(otherwise);
        }
    }

    public record ElseIf(Expr condition, List<Stmt> body) {
        public ElseIf { body = List.copyOf(body); }
    }

    /** {@code IF cond stmt} on one line (stmt: a call, assignment, GOTO, RETURN, RAISE, EXIT, RETRY, TRYNEXT). */
    public record CompactIf(Expr condition, Stmt stmt) implements Stmt { }

    public record While(Expr condition, List<Stmt> body) implements Stmt {
        public While { body = List.copyOf(body); }
    }

    /** {@code FOR var FROM from TO to [STEP step] DO body ENDFOR}; step null when not written. */
    public record For(String variable, Expr from, Expr to, Expr step, List<Stmt> body) implements Stmt {
        public For { body = List.copyOf(body); }
    }

    /** {@code TEST value CASE ...: ... DEFAULT: ... ENDTEST}; otherwise null without DEFAULT. */
    public record Test(Expr value, List<Case> cases, List<Stmt> otherwise) implements Stmt {
        public Test {
            cases = List.copyOf(cases);
            otherwise = otherwise == null ? null : List.copyOf(otherwise);
        }
    }

    public record Case(List<Expr> values, List<Stmt> body) {
        public Case {
            values = List.copyOf(values);
            body = List.copyOf(body);
            if (values.isEmpty()) throw new IllegalArgumentException("CASE needs a value");
        }
    }

    public record Goto(String label) implements Stmt { }

    /** {@code label:}. */
    public record Label(String name) implements Stmt { }

    /** {@code RETURN [value];}. */
    public record Return(Expr value) implements Stmt { }

    /** {@code RAISE [errno];}. */
    public record Raise(Expr value) implements Stmt { }

    public record Retry() implements Stmt { }

    public record TryNext() implements Stmt { }

    public record Exit() implements Stmt { }

    /** {@code CONNECT interrupt WITH trap;}. */
    public record Connect(Expr target, String trap) implements Stmt { }

    // ---------------------------------------------------------------- arguments

    public enum ArgKind {
        /** {@code value} */
        POSITIONAL,
        /** {@code Name:=value} (a required argument given by name) */
        NAMED,
        /** {@code \Name:=value} */
        OPTIONAL,
        /** {@code \Name} */
        SWITCH,
        /** {@code \Name?param}: passed on only when the caller's optional param is present */
        CONDITIONAL
    }

    /** One argument; name null for POSITIONAL, value null for SWITCH. */
    public record Arg(ArgKind kind, String name, Expr value) {
        public Arg {
            if (kind == null || (kind == ArgKind.POSITIONAL) != (name == null) || (kind == ArgKind.SWITCH) != (value == null))
                throw new IllegalArgumentException("bad argument " + kind + " " + name + " " + value);
        }

        public static Arg positional(Expr v) { return new Arg(ArgKind.POSITIONAL, null, v); }
    }

    // ---------------------------------------------------------------- expressions

    public sealed interface Expr permits Num, Str, Bool, Name, Component, Index, FuncCall, Aggregate, Unary, Binary { }

    /**
     * A number literal as written: decimal with optional exponent, or 0x/0b/0o integer. A
     * leading '.' gets a 0 in front ({@code .01} is held as {@code 0.01}: same value, and
     * rapidchecker refuses the bare form).
     */
    public record Num(String text) implements Expr {
        public Num {
            if (text == null || text.isEmpty()) throw new IllegalArgumentException("empty number");
            if (text.charAt(0) == '.') text = "0" + text;
        }

        public double value() { return numberValue(text); }

        /**
         * A literal that reads back as exactly {@code v} (v >= 0): Java's own text of the double
         * (exponent form "1.0E-5" for small and large values, which RAPID reads too). For files,
         * where the shortest digits matter, see {@link RapidNumbers#formatExact}; this one is
         * cheap, for values the interpreter converts at run time.
         */
        public static Num of(double v) {
            if (!(v >= 0) || !Double.isFinite(v)) throw new IllegalArgumentException("number literals are finite and >= 0: " + v);
            return new Num(v == 0 ? "0" : Double.toString(v));
        }
    }

    /** The value of a RAPID number literal (NumberFormatException when it is none). */
    public static double numberValue(String text) {
        String t = text.toLowerCase(Locale.ROOT);
        if (t.length() > 2 && t.charAt(0) == '0' && (t.charAt(1) == 'x' || t.charAt(1) == 'b' || t.charAt(1) == 'o')) {
            int radix = t.charAt(1) == 'x' ? 16 : t.charAt(1) == 'b' ? 2 : 8;
            return new BigInteger(t.substring(2), radix).doubleValue();
        }
        return Double.parseDouble(text);
    }

    /** A string literal; {@code raw} is the text between the quotes as written (escapes unresolved). */
    public record Str(String raw) implements Expr {
        /**
         * The string the literal stands for, RAPID's escapes resolved: {@code ""} a quote,
         * backslash-backslash a backslash, backslash and two hex digits that character code.
         * IllegalArgumentException for any other backslash.
         */
        public String value() {
            StringBuilder b = new StringBuilder(raw.length());
            for (int k = 0; k < raw.length(); k++) {
                char c = raw.charAt(k);
                if (c == '"') { b.append('"'); k++; continue; }
                if (c == '\\') {
                    if (k + 1 < raw.length() && raw.charAt(k + 1) == '\\') { b.append('\\'); k++; continue; }
                    if (k + 2 < raw.length() && isHex(raw.charAt(k + 1)) && isHex(raw.charAt(k + 2))) {
                        b.append((char) Integer.parseInt(raw.substring(k + 1, k + 3), 16));
                        k += 2;
                        continue;
                    }
                    throw new IllegalArgumentException("bad escape in string (use \\\\ for a backslash)");
                }
                b.append(c);
            }
            return b.toString();
        }

        private static boolean isHex(char c) { return c < 128 && Character.digit(c, 16) >= 0; }

        /**
         * The literal of {@code value}: backslashes doubled, the quote and control characters as a
         * backslash and two hex digits (RAPID also allows a doubled quote, but rapidchecker 0.1.5
         * rejects it; backslash 22 is the same character and passes both).
         */
        public static Str of(String value) {
            StringBuilder b = new StringBuilder();
            for (char c : value.toCharArray()) {
                if (c == '"') b.append("\\22");
                else if (c == '\\') b.append("\\\\");
                else if (c < ' ' || c > '~') b.append(String.format("\\%02X", (int) (c & 0xFF)));
                else b.append(c);
            }
            return new Str(b.toString());
        }
    }

    public record Bool(boolean value) implements Expr { }

    public record Name(String name) implements Expr { }

    /** {@code base.component}. */
    public record Component(Expr base, String component) implements Expr { }

    /** {@code base{i, j}}. */
    public record Index(Expr base, List<Expr> indices) implements Expr {
        public Index { indices = List.copyOf(indices); }
    }

    public record FuncCall(String name, List<Arg> args) implements Expr {
        public FuncCall { args = List.copyOf(args); }
    }

    /** {@code [a, b, ...]}: a record or array value. */
    public record Aggregate(List<Expr> items) implements Expr {
        public Aggregate { items = List.copyOf(items); }
    }

    /** {@code -x}, {@code +x} or {@code NOT x}. */
    public record Unary(String op, Expr operand) implements Expr { }

    /** Binary operator: OR XOR AND = <> < > <= >= + - * / DIV MOD (word operators upper-case). */
    public record Binary(String op, Expr left, Expr right) implements Expr { }
}
