package org.robopro.programs.rapid;

import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import org.robopro.models.InputException;
import org.robopro.programs.rapid.RapidAst.Arg;
import org.robopro.programs.rapid.RapidAst.ArgKind;
import org.robopro.programs.rapid.RapidAst.Expr;
import org.robopro.programs.rapid.RapidAst.Stmt;

/**
 * Recursive-descent parser of the RAPID kernel grammar (ABB technical reference manual, "RAPID
 * kernel": modules, data, records, aliases, routines with parameters and error/undo/backward
 * handlers, statements and expressions with RAPID's precedence) into {@link RapidAst}. Syntax it
 * does not know is an {@link InputException} with file, line and column. Comments are kept as
 * comment lines: one written inside a statement follows that statement.
 */
public final class RapidAstParser {
    private final String file;
    private final List<Token> toks;
    private int i;
    private final IdentityHashMap<Object, SourcePos> positions = new IdentityHashMap<>();
    /** Comments met inside the statement being read; they are placed after it. */
    private List<String> pending = new ArrayList<>();
    /** Nesting of blocks and parentheses, bounded so hostile input cannot overflow the stack. */
    private int depth;
    /** ENDPROC, ENDFUNC or ENDTRAP of the routine being read (for messages). */
    private String currentEnd = "ENDPROC";
    private static final int MAX_DEPTH = 200;
    /**
     * Binary operators in one expression: a left-associative chain nests one level per operator,
     * and every reader of the tree (simulation, export) walks it recursively, so the chain is
     * bounded here with a located error instead of a stack overflow later.
     */
    public static final int MAX_OPERATORS = 1000;
    /** Binary operators read so far in the current top-level expression. */
    private int operators;

    private RapidAstParser(String text, String file) {
        this.file = file;
        this.toks = new RapidLexer(blankHeader(text), file).tokens();
    }

    /**
     * The syntax tree of RAPID module text (the whole kernel grammar; nothing is interpreted),
     * with where each node was written; {@code file} names the text in error messages
     * ({@link org.robopro.models.InputException}: file, line, column).
     */
    public static ParsedAst parse(String text, String file) {
        if (text == null) throw new IllegalArgumentException("text must not be null");
        if (file == null) file = "<rapid>";
        RapidAstParser p = new RapidAstParser(text, file);
        RapidAst.Module m = p.module();
        return new ParsedAst(m, file, p.positions);
    }

    /**
     * Old controllers write a "%%%\n VERSION:1\n LANGUAGE:ENGLISH\n%%%" header before MODULE. It
     * carries no program meaning; it is blanked (line numbers stay right).
     */
    static String blankHeader(String text) {
        int start = 0;
        while (start < text.length() && Character.isWhitespace(text.charAt(start))) start++;
        if (!text.startsWith("%%%", start)) return text;
        int end = text.indexOf("%%%", start + 3);
        if (end < 0) return text;
        StringBuilder b = new StringBuilder(text);
        for (int k = start; k < end + 3; k++) if (b.charAt(k) != '\n' && b.charAt(k) != '\r') b.setCharAt(k, ' ');
        return b.toString();
    }

    private <T> T at(T node, Token t) {
        positions.put(node, new SourcePos(file, t.line(), t.column()));
        return node;
    }

    // ---------------------------------------------------------------- module

    private static final Set<String> MODULE_OPTIONS = Set.of("SYSMODULE", "NOSTEPIN", "VIEWONLY", "READONLY", "NOVIEW");

    private RapidAst.Module module() {
        List<RapidAst.Item> items = new ArrayList<>();
        // Comments before MODULE are kept as the module's first lines.
        while (raw().kind() == Token.Kind.COMMENT) items.add(at(new RapidAst.CommentLine(toks.get(i).text()), toks.get(i++)));
        Token mt = peek();
        expectWord("MODULE");
        String name = ident("module name");
        List<String> options = new ArrayList<>();
        if (accept("(")) {
            do {
                Token o = next();
                if (o.kind() != Token.Kind.IDENT || !MODULE_OPTIONS.contains(o.text().toUpperCase(Locale.ROOT)))
                    throw error(o, "module option", "expected SYSMODULE, NOSTEPIN, VIEWONLY, READONLY or NOVIEW, found " + o.describe());
                options.add(o.text().toUpperCase(Locale.ROOT));
            } while (accept(","));
            expect(")");
        }
        flush(items);
        while (true) {
            Token t = raw();
            if (t.kind() == Token.Kind.COMMENT) {
                items.add(at(new RapidAst.CommentLine(t.text()), t));
                i++;
                continue;
            }
            if (t.isWord("ENDMODULE")) { i++; break; }
            if (t.kind() == Token.Kind.EOF) throw error(t, null, "ENDMODULE missing (module " + name + " opened on line " + mt.line() + ")");
            items.add(item());
            flush(items);
        }
        while (raw().kind() == Token.Kind.COMMENT) items.add(at(new RapidAst.CommentLine(toks.get(i).text()), toks.get(i++)));
        if (peek().kind() != Token.Kind.EOF) throw error(peek(), null, "text after ENDMODULE: " + peek().describe());
        return at(new RapidAst.Module(name, options, items), mt);
    }

    @SuppressWarnings("unchecked")
    private <T> void flush(List<T> into) {
        for (String c : pending) into.add((T) new RapidAst.CommentLine(c));
        pending = new ArrayList<>();
    }

    private RapidAst.Item item() {
        Token t = peek();
        boolean local = t.isWord("LOCAL");
        Token w = local ? peekAt(1) : t;
        if (isDeclarationStart()) return dataDecl(true);
        if (w.isWord("PROC") || w.isWord("FUNC") || w.isWord("TRAP")) return routine();
        if (w.isWord("RECORD")) return record();
        if (w.isWord("ALIAS")) {
            if (local) i++;
            i++;
            String type = ident("data type");
            String name = ident("alias name");
            expect(";");
            return at(new RapidAst.AliasDecl(local, type, name), t);
        }
        throw error(t, null, "expected a declaration, RECORD, ALIAS, PROC, FUNC, TRAP or ENDMODULE, found " + t.describe());
    }

    private boolean isDeclarationStart() {
        Token t = peek();
        if (t.isWord("LOCAL") || t.isWord("TASK")) t = peekAt(1);
        return t.isWord("CONST") || t.isWord("PERS") || t.isWord("VAR");
    }

    private RapidAst.DataDecl dataDecl(boolean moduleLevel) {
        Token start = peek();
        RapidAst.Scope scope = RapidAst.Scope.GLOBAL;
        if (peek().isWord("LOCAL") || peek().isWord("TASK")) {
            if (!moduleLevel) throw error(peek(), null, peek().text().toUpperCase(Locale.ROOT) + " is only allowed for module data");
            scope = next().isWord("LOCAL") ? RapidAst.Scope.LOCAL : RapidAst.Scope.TASK;
        }
        Token st = next();
        RapidAst.Storage storage = RapidAst.Storage.valueOf(st.text().toUpperCase(Locale.ROOT));
        String type = ident("data type");
        Token nameTok = peek();
        String name = ident("data name");
        List<Expr> dims = new ArrayList<>();
        if (accept("{")) {
            do dims.add(expr()); while (accept(","));
            expect("}");
            if (dims.size() > 3) throw error(nameTok, name, "RAPID arrays have at most 3 dimensions");
        }
        Expr init = null;
        if (accept(":=")) init = expr();
        else if (storage == RapidAst.Storage.CONST) throw error(nameTok, name, "CONST needs a value (':=')");
        expect(";");
        return at(new RapidAst.DataDecl(scope, storage, type, name, dims, init), start);
    }

    private RapidAst.RecordDecl record() {
        Token start = peek();
        boolean local = accept("LOCAL", true);
        expectWord("RECORD");
        String name = ident("record name");
        List<RapidAst.Member> members = new ArrayList<>();
        flush(members);
        while (true) {
            Token t = raw();
            if (t.kind() == Token.Kind.COMMENT) { members.add(new RapidAst.CommentLine(t.text())); i++; continue; }
            if (t.isWord("ENDRECORD")) { i++; break; }
            if (t.kind() == Token.Kind.EOF) throw error(t, name, "ENDRECORD missing for RECORD " + name);
            String type = ident("component type");
            String field = ident("component name");
            expect(";");
            members.add(new RapidAst.Field(type, field));
            flush(members);
        }
        if (members.stream().noneMatch(m -> m instanceof RapidAst.Field)) throw error(start, name, "RECORD needs at least one component");
        return at(new RapidAst.RecordDecl(local, name, members), start);
    }

    private RapidAst.Routine routine() {
        Token start = peek();
        boolean local = accept("LOCAL", true);
        Token kw = next();
        RapidAst.RoutineKind kind = RapidAst.RoutineKind.valueOf(kw.text().toUpperCase(Locale.ROOT));
        String returnType = kind == RapidAst.RoutineKind.FUNC ? ident("return type") : null;
        String name = ident("routine name");
        List<RapidAst.Param> params = new ArrayList<>();
        if (kind != RapidAst.RoutineKind.TRAP) {
            expect("(");
            if (!peek().is(")")) {
                do params.add(param(name)); while (accept(","));
            }
            expect(")");
        }
        String end = "END" + kind.name();
        currentEnd = end;
        List<Stmt> body = new ArrayList<>();
        flush(body);
        body.addAll(stmts(name, Set.of(end, "BACKWARD", "ERROR", "UNDO"), true));
        List<Stmt> backward = null, error = null, undo = null;
        List<Expr> errnos = null;
        if (peek().isWord("BACKWARD")) {
            if (kind != RapidAst.RoutineKind.PROC) throw error(peek(), name, "BACKWARD handlers belong to PROCs");
            i++;
            backward = stmts(name, Set.of(end, "ERROR", "UNDO"), false);
        }
        if (peek().isWord("ERROR")) {
            i++;
            if (accept("(")) {
                errnos = new ArrayList<>();
                do errnos.add(expr()); while (accept(","));
                expect(")");
            }
            error = stmts(name, Set.of(end, "UNDO"), false);
        }
        if (peek().isWord("UNDO")) {
            i++;
            undo = stmts(name, Set.of(end), false);
        }
        Token e = next();
        if (!e.isWord(end)) {
            if (e.kind() == Token.Kind.EOF || e.isWord("ENDMODULE") || e.isWord("PROC") || e.isWord("FUNC") || e.isWord("TRAP"))
                throw error(e, name, end + " missing before " + e.describe());
            throw error(e, name, "expected " + end + ", found " + e.describe());
        }
        return at(new RapidAst.Routine(local, kind, returnType, name, params, body, backward, errnos, error, undo), start);
    }

    private RapidAst.Param param(String routine) {
        boolean optional = accept("\\");
        List<RapidAst.ParamAlt> alts = new ArrayList<>();
        do alts.add(paramAlt()); while (optional && accept("|"));
        if (!optional && peek().is("|")) throw error(peek(), routine, "alternatives ('|') are only allowed for optional parameters");
        return new RapidAst.Param(optional, alts);
    }

    private RapidAst.ParamAlt paramAlt() {
        String mode = null;
        Token t = peek();
        if (t.isWord("VAR") || t.isWord("PERS") || t.isWord("INOUT")) {
            mode = t.text().toUpperCase(Locale.ROOT);
            i++;
        }
        String type = ident("parameter type");
        String name = ident("parameter name");
        int dims = 0;
        if (accept("{")) {
            do { expect("*"); dims++; } while (accept(","));
            expect("}");
            if (dims > 3) throw error(t, name, "RAPID arrays have at most 3 dimensions");
        }
        return new RapidAst.ParamAlt(mode, type, name, dims);
    }

    // ---------------------------------------------------------------- statements

    /** Statements up to (not including) one of the terminator keywords. */
    private List<Stmt> stmts(String routine, Set<String> terminators, boolean dataAllowed) {
        if (++depth > MAX_DEPTH) throw error(peek(), routine, "statements nested deeper than " + MAX_DEPTH);
        List<Stmt> out = new ArrayList<>();
        while (true) {
            Token t = raw();
            if (t.kind() == Token.Kind.COMMENT) {
                out.add(at(new RapidAst.CommentLine(t.text()), t));
                i++;
                continue;
            }
            if (t.kind() == Token.Kind.EOF) throw error(t, routine, "END" + " missing: expected " + String.join(" or ", terminators.stream().sorted().toList()) + ", found end of file");
            if (t.kind() == Token.Kind.IDENT && terminators.contains(t.text().toUpperCase(Locale.ROOT))) break;
            if (t.kind() == Token.Kind.IDENT && BLOCK_WORDS.contains(t.text().toUpperCase(Locale.ROOT))
                    && !Set.of("LOCAL", "PROC", "FUNC", "TRAP", "ENDMODULE", "MODULE", "RECORD", "ALIAS").contains(t.text().toUpperCase(Locale.ROOT)))
                throw error(t, routine, "expected " + String.join(" or ", terminators.stream().sorted().toList()) + ", found " + t.describe());
            if (t.kind() == Token.Kind.IDENT && (t.isWord("VAR") || t.isWord("PERS") || t.isWord("CONST"))) {
                out.add(dataDecl(false));
            } else {
                out.add(stmt(routine));
            }
            flush(out);
        }
        depth--;
        return out;
    }

    private static final Set<String> BLOCK_WORDS = Set.of("ENDMODULE", "ENDPROC", "ENDFUNC", "ENDTRAP", "PROC", "FUNC", "TRAP",
            "ELSE", "ELSEIF", "ENDIF", "ENDWHILE", "ENDFOR", "ENDTEST", "CASE", "DEFAULT", "BACKWARD", "ERROR", "UNDO",
            "LOCAL", "TASK", "MODULE", "RECORD", "ENDRECORD", "ALIAS");

    private Stmt stmt(String routine) {
        Token h = peek();
        if (h.is("%")) return call(routine);
        if (h.kind() != Token.Kind.IDENT) throw error(h, routine, "expected a statement, found " + h.describe());
        String up = h.text().toUpperCase(Locale.ROOT);
        switch (up) {
            case "IF": return ifStmt(routine);
            case "WHILE": {
                i++;
                Expr c = expr();
                expectWord("DO");
                List<Stmt> body = stmts(routine, Set.of("ENDWHILE"), false);
                expectWord("ENDWHILE");
                return at(new RapidAst.While(c, body), h);
            }
            case "FOR": {
                i++;
                String v = ident("loop variable");
                expectWord("FROM");
                Expr from = expr();
                expectWord("TO");
                Expr to = expr();
                Expr step = acceptWord("STEP") ? expr() : null;
                expectWord("DO");
                List<Stmt> body = stmts(routine, Set.of("ENDFOR"), false);
                expectWord("ENDFOR");
                return at(new RapidAst.For(v, from, to, step, body), h);
            }
            case "TEST": return test(routine);
            case "GOTO": {
                i++;
                String l = ident("label");
                expect(";");
                return at(new RapidAst.Goto(l), h);
            }
            case "RETURN": {
                i++;
                Expr v = peek().is(";") ? null : expr();
                expect(";");
                return at(new RapidAst.Return(v), h);
            }
            case "RAISE": {
                i++;
                Expr v = peek().is(";") ? null : expr();
                expect(";");
                return at(new RapidAst.Raise(v), h);
            }
            case "RETRY": i++; expect(";"); return at(new RapidAst.Retry(), h);
            case "TRYNEXT": i++; expect(";"); return at(new RapidAst.TryNext(), h);
            case "EXIT": i++; expect(";"); return at(new RapidAst.Exit(), h);
            case "CONNECT": {
                i++;
                Expr target = target(routine);
                expectWord("WITH");
                String trap = ident("trap routine");
                expect(";");
                return at(new RapidAst.Connect(target, trap), h);
            }
            default:
                break;
        }
        if (BLOCK_WORDS.contains(up)) {
            if (Set.of("PROC", "FUNC", "TRAP", "ENDMODULE", "MODULE", "LOCAL", "RECORD", "ALIAS").contains(up))
                throw error(h, routine, currentEnd + " missing before " + up);
            throw error(h, routine, up + " without its opening statement");
        }
        if (RapidNames.isReserved(up)) throw error(h, routine, "expected a statement, found keyword " + h.text());
        if (peekAt(1).is(":")) {
            i += 2;
            return at(new RapidAst.Label(h.text()), h);
        }
        if (peekAt(1).is(":=") || peekAt(1).is(".") || peekAt(1).is("{")) {
            Expr target = target(routine);
            expect(":=");
            Expr v = expr();
            expect(";");
            return at(new RapidAst.Assign(target, v), h);
        }
        return call(routine);
    }

    /** An assignment or CONNECT target: a name with components and array indices. */
    private Expr target(String routine) {
        Token t = peek();
        Expr e = at(new RapidAst.Name(ident("variable")), t);
        return postfix(e);
    }

    private Stmt call(String routine) {
        Token h = peek();
        String name = null;
        Expr late = null;
        if (accept("%")) {
            late = expr();
            expect("%");
        } else {
            name = ident("procedure name");
        }
        List<Arg> args;
        Token paren = peek();
        try {
            // "WaitUntil (a = b);" is a call whose first argument is in parentheses
            args = args(";", routine);
            expect(";");
        } catch (InputException e) {
            if (paren.is("(") && name != null)
                throw error(paren, routine, "'" + name + "(' : a procedure call takes its arguments without parentheses");
            throw e;
        }
        return at(new RapidAst.Call(name, late, args), h);
    }

    private Stmt ifStmt(String routine) {
        Token h = next();
        Expr c = expr();
        if (!acceptWord("THEN")) {
            // Compact IF: one simple statement on the same line.
            Token s = peek();
            if (s.isWord("IF") || s.isWord("WHILE") || s.isWord("FOR") || s.isWord("TEST") || s.isWord("VAR") || s.isWord("PERS") || s.isWord("CONST"))
                throw error(s, routine, "expected THEN or a simple statement after the IF condition, found " + s.describe());
            Stmt one = stmt(routine);
            if (!(one instanceof RapidAst.Call || one instanceof RapidAst.Assign || one instanceof RapidAst.Goto
                    || one instanceof RapidAst.Return || one instanceof RapidAst.Raise || one instanceof RapidAst.Exit
                    || one instanceof RapidAst.Retry || one instanceof RapidAst.TryNext))
                throw error(s, routine, "a compact IF takes one simple statement (a call, assignment, GOTO, RETURN, RAISE, EXIT, RETRY or TRYNEXT), found "
                        + s.describe());
            return at(new RapidAst.CompactIf(c, one), h);
        }
        Set<String> stop = Set.of("ELSEIF", "ELSE", "ENDIF");
        List<Stmt> then = stmts(routine, stop, false);
        List<RapidAst.ElseIf> elseIfs = new ArrayList<>();
        List<Stmt> otherwise = null;
        while (true) {
            Token t = next();
            if (t.isWord("ELSEIF")) {
                Expr ec = expr();
                expectWord("THEN");
                elseIfs.add(new RapidAst.ElseIf(ec, stmts(routine, stop, false)));
            } else if (t.isWord("ELSE")) {
                if (otherwise != null) throw error(t, routine, "second ELSE in one IF");
                otherwise = stmts(routine, stop, false);
            } else if (t.isWord("ENDIF")) {
                break;
            } else {
                throw error(t, routine, "expected ENDIF, found " + t.describe());
            }
        }
        return at(new RapidAst.If(c, then, elseIfs, otherwise), h);
    }

    private Stmt test(String routine) {
        Token h = next();
        Expr v = expr();
        List<RapidAst.Case> cases = new ArrayList<>();
        List<Stmt> otherwise = null;
        Set<String> stop = Set.of("CASE", "DEFAULT", "ENDTEST");
        while (true) {
            Token t = next();
            if (t.isWord("CASE")) {
                if (otherwise != null) throw error(t, routine, "CASE after DEFAULT");
                List<Expr> vals = new ArrayList<>();
                do vals.add(expr()); while (accept(","));
                expect(":");
                cases.add(new RapidAst.Case(vals, stmts(routine, stop, false)));
            } else if (t.isWord("DEFAULT")) {
                if (otherwise != null) throw error(t, routine, "second DEFAULT in one TEST");
                expect(":");
                otherwise = stmts(routine, stop, false);
            } else if (t.isWord("ENDTEST")) {
                break;
            } else {
                throw error(t, routine, "expected CASE, DEFAULT or ENDTEST, found " + t.describe());
            }
        }
        return at(new RapidAst.Test(v, cases, otherwise), h);
    }

    /** Arguments up to {@code end} (not consumed): positional, Name:=v, \Name:=v, \Name, \Name?param. */
    private List<Arg> args(String end, String routine) {
        List<Arg> out = new ArrayList<>();
        if (peek().is(end)) return out;
        while (true) {
            Token t = peek();
            Arg a;
            if (accept("\\")) {
                String n = ident("optional argument");
                if (accept(":=")) a = new Arg(ArgKind.OPTIONAL, n, expr());
                else if (accept("?")) {
                    Token pt = peek();
                    a = new Arg(ArgKind.CONDITIONAL, n, at(new RapidAst.Name(ident("parameter")), pt));
                } else a = new Arg(ArgKind.SWITCH, n, null);
            } else if (t.kind() == Token.Kind.IDENT && peekAt(1).is(":=") && !RapidNames.isReserved(t.text())) {
                i += 2;
                a = new Arg(ArgKind.NAMED, t.text(), expr());
            } else {
                a = Arg.positional(expr());
            }
            out.add(at(a, t));
            if (accept(",")) {
                if (peek().is(end)) throw error(peek(), routine, "argument missing after ','");
                continue;
            }
            if (peek().is("\\")) continue;
            if (peek().is(end)) return out;
            throw error(peek(), routine, "expected ',' or '" + end + "' after an argument, found " + peek().describe());
        }
    }

    // ---------------------------------------------------------------- expressions

    /** expr := [NOT] and-term { (OR|XOR) [NOT] and-term } (RAPID: NOT, OR, XOR bind weakest). */
    Expr expr() {
        if (depth == 0) operators = 0;
        if (++depth > MAX_DEPTH) throw error(peek(), null, "expression nested deeper than " + MAX_DEPTH);
        Token s = peek();
        Expr e = notOperand();
        while (peek().isWord("OR") || peek().isWord("XOR")) {
            String op = next().text().toUpperCase(Locale.ROOT);
            e = binary(new RapidAst.Binary(op, e, notOperand()), s);
        }
        depth--;
        return e;
    }

    private Expr binary(RapidAst.Binary b, Token start) {
        if (++operators > MAX_OPERATORS)
            throw error(toks.get(Math.max(0, i - 1)), null, "expression with more than " + MAX_OPERATORS
                    + " operators: split it over several assignments");
        return at(b, start);
    }

    private Expr notOperand() {
        Token t = peek();
        if (acceptWord("NOT")) return at(new RapidAst.Unary("NOT", logicalTerm()), t);
        return logicalTerm();
    }

    private Expr logicalTerm() {
        Token s = peek();
        Expr e = relation();
        while (peek().isWord("AND")) {
            i++;
            Token t = peek();
            Expr r = acceptWord("NOT") ? at(new RapidAst.Unary("NOT", relation()), t) : relation();
            e = binary(new RapidAst.Binary("AND", e, r), s);
        }
        return e;
    }

    private static final Set<String> RELOPS = Set.of("=", "<>", "<", ">", "<=", ">=");

    private Expr relation() {
        Token s = peek();
        Expr e = simple();
        Token t = peek();
        if (t.kind() == Token.Kind.PUNCT && RELOPS.contains(t.text())) {
            i++;
            e = binary(new RapidAst.Binary(t.text(), e, simple()), s);
            Token u = peek();
            if (u.kind() == Token.Kind.PUNCT && RELOPS.contains(u.text()))
                throw error(u, null, "comparisons do not chain: put one in parentheses");
        }
        return e;
    }

    private Expr simple() {
        Token s = peek();
        Expr e;
        if (peek().is("-") || peek().is("+")) {
            String op = next().text();
            e = at(new RapidAst.Unary(op, term()), s);
        } else {
            e = term();
        }
        while (peek().is("+") || peek().is("-")) {
            String op = next().text();
            e = binary(new RapidAst.Binary(op, e, term()), s);
        }
        return e;
    }

    private Expr term() {
        Token s = peek();
        Expr e = primary();
        while (peek().is("*") || peek().is("/") || peek().isWord("DIV") || peek().isWord("MOD")) {
            String op = next().text().toUpperCase(Locale.ROOT);
            e = binary(new RapidAst.Binary(op, e, primary()), s);
        }
        return e;
    }

    private Expr primary() {
        if (++depth > MAX_DEPTH) throw error(peek(), null, "expression nested deeper than " + MAX_DEPTH);
        Token t = next();
        Expr e;
        switch (t.kind()) {
            case NUMBER -> {
                try {
                    double d = RapidAst.numberValue(t.text());
                    if (!Double.isFinite(d)) throw error(t, null, "number out of range '" + t.text() + "'");
                } catch (NumberFormatException bad) {
                    throw error(t, null, "bad number '" + t.text() + "'");
                }
                e = at(new RapidAst.Num(t.text()), t);
            }
            case STRING -> e = at(new RapidAst.Str(t.text()), t);
            case IDENT -> {
                if (t.isWord("TRUE") || t.isWord("FALSE")) {
                    e = at(new RapidAst.Bool(t.isWord("TRUE")), t);
                } else {
                    if (RapidNames.isReserved(t.text())) throw error(t, null, "expected a value, found keyword " + t.text());
                    if (peek().is("(")) {
                        i++;
                        List<Arg> a = args(")", null);
                        expect(")");
                        e = at(new RapidAst.FuncCall(t.text(), a), t);
                    } else {
                        e = postfix(at(new RapidAst.Name(t.text()), t));
                    }
                }
            }
            case PUNCT -> {
                if (t.is("[")) {
                    List<Expr> items = new ArrayList<>();
                    if (peek().is("]")) throw error(peek(), null, "empty aggregate");
                    do items.add(expr()); while (accept(","));
                    expect("]");
                    e = at(new RapidAst.Aggregate(items), t);
                } else if (t.is("(")) {
                    e = expr();
                    expect(")");
                } else if (t.is("-") || t.is("+")) {
                    // "a * -b": accepted as a signed operand, as the controller does
                    e = at(new RapidAst.Unary(t.text(), primary()), t);
                } else {
                    throw error(t, null, "expected a value, found " + t.describe());
                }
            }
            default -> throw error(t, null, "expected a value, found " + t.describe());
        }
        depth--;
        return e;
    }

    private Expr postfix(Expr e) {
        while (true) {
            Token t = peek();
            if (accept(".")) {
                Token c = peek();
                e = at(new RapidAst.Component(e, ident("component")), c);
            } else if (accept("{")) {
                List<Expr> idx = new ArrayList<>();
                do idx.add(expr()); while (accept(","));
                expect("}");
                e = at(new RapidAst.Index(e, idx), t);
            } else {
                return e;
            }
        }
    }

    // ---------------------------------------------------------------- tokens

    /** The next token, comments included. */
    private Token raw() { return toks.get(i); }

    /** The next token that is not a comment (a comment inside a statement is kept for later). */
    private Token peek() {
        int k = i;
        while (toks.get(k).kind() == Token.Kind.COMMENT) k++;
        return toks.get(k);
    }

    private Token peekAt(int n) {
        int k = i;
        for (int c = 0; ; k++) {
            if (toks.get(k).kind() == Token.Kind.EOF) return toks.get(k);
            if (toks.get(k).kind() == Token.Kind.COMMENT) continue;
            if (c++ == n) return toks.get(k);
        }
    }

    private Token next() {
        while (toks.get(i).kind() == Token.Kind.COMMENT) pending.add(toks.get(i++).text());
        Token t = toks.get(i);
        if (t.kind() != Token.Kind.EOF) i++;
        return t;
    }

    private boolean accept(String punct) {
        if (peek().is(punct)) { next(); return true; }
        return false;
    }

    private boolean accept(String word, boolean isWord) {
        if (peek().isWord(word)) { next(); return true; }
        return false;
    }

    private boolean acceptWord(String word) { return accept(word, true); }

    private void expect(String punct) {
        Token t = next();
        if (!t.is(punct)) throw error(t, null, "expected '" + punct + "', found " + t.describe());
    }

    private void expectWord(String word) {
        Token t = next();
        if (!t.isWord(word)) throw error(t, null, "expected " + word + ", found " + t.describe());
    }

    private String ident(String what) {
        Token t = next();
        if (t.kind() != Token.Kind.IDENT) throw error(t, what, "expected a " + what + ", found " + t.describe());
        if (RapidNames.isReserved(t.text())) throw error(t, what, "'" + t.text() + "' is a reserved word");
        return t.text();
    }

    private InputException error(Token t, String field, String problem) {
        return new InputException(file, t.line(), t.column(), field, problem);
    }
}
