package org.robopro.programs.rapid;

import java.util.List;
import java.util.Set;
import org.robopro.programs.rapid.RapidAst.Arg;
import org.robopro.programs.rapid.RapidAst.Binary;
import org.robopro.programs.rapid.RapidAst.Expr;
import org.robopro.programs.rapid.RapidAst.Stmt;
import org.robopro.programs.rapid.RapidAst.Unary;

/**
 * RAPID pretty-printer for {@link RapidAst}: two-space indentation, upper-case keywords, one
 * statement per line, parentheses only where RAPID's precedence needs them. Reading the text
 * back gives an equal tree (tested on fixtures and seeded random trees). Names, number and
 * string literals are written as they were read.
 */
public final class RapidAstWriter {
    private static final String IND = "  ";

    private RapidAstWriter() { }

    /** The module as RAPID text (ends with a line break). */
    public static String write(RapidAst.Module m) {
        StringBuilder b = new StringBuilder("MODULE ").append(m.name());
        if (!m.options().isEmpty()) b.append('(').append(String.join(", ", m.options())).append(')');
        b.append('\n');
        for (RapidAst.Item it : m.items()) {
            if (it instanceof RapidAst.Routine) b.append('\n'); // a blank line before every routine
            item(b, it, IND);
        }
        return b.append("ENDMODULE\n").toString();
    }

    /** One statement as RAPID text without indentation (nested blocks indented; ends with a line break). */
    public static String statement(Stmt s) {
        StringBuilder b = new StringBuilder();
        stmt(b, s, "");
        return b.toString();
    }

    /** One module item, each line starting with {@code ind}. */
    static void item(StringBuilder b, RapidAst.Item it, String ind) {
        if (it instanceof RapidAst.CommentLine c) b.append(ind).append('!').append(c.text()).append('\n');
        else if (it instanceof RapidAst.DataDecl d) b.append(ind).append(decl(d)).append('\n');
        else if (it instanceof RapidAst.AliasDecl a) b.append(ind).append(a.local() ? "LOCAL " : "").append("ALIAS ").append(a.type()).append(' ').append(a.name()).append(";\n");
        else if (it instanceof RapidAst.RecordDecl r) {
            b.append(ind).append(r.local() ? "LOCAL " : "").append("RECORD ").append(r.name()).append('\n');
            for (RapidAst.Member mem : r.members()) {
                if (mem instanceof RapidAst.Field f) b.append(ind).append(IND).append(f.type()).append(' ').append(f.name()).append(";\n");
                else b.append(ind).append(IND).append('!').append(((RapidAst.CommentLine) mem).text()).append('\n');
            }
            b.append(ind).append("ENDRECORD\n");
        } else routine(b, (RapidAst.Routine) it, ind);
    }

    static String decl(RapidAst.DataDecl d) {
        StringBuilder b = new StringBuilder();
        if (d.scope() == RapidAst.Scope.LOCAL) b.append("LOCAL ");
        if (d.scope() == RapidAst.Scope.TASK) b.append("TASK ");
        b.append(d.storage().name()).append(' ').append(d.type()).append(' ').append(d.name());
        if (!d.dims().isEmpty()) b.append('{').append(list(d.dims())).append('}');
        if (d.init() != null) b.append(":=").append(expr(d.init()));
        return b.append(';').toString();
    }

    private static void routine(StringBuilder b, RapidAst.Routine r, String ind) {
        b.append(ind).append(r.local() ? "LOCAL " : "").append(r.kind().name()).append(' ');
        if (r.returnType() != null) b.append(r.returnType()).append(' ');
        b.append(r.name());
        if (r.kind() != RapidAst.RoutineKind.TRAP) {
            b.append('(');
            for (int k = 0; k < r.params().size(); k++) {
                RapidAst.Param p = r.params().get(k);
                if (k > 0) b.append(", ");
                if (p.optional()) b.append('\\');
                for (int a = 0; a < p.alternatives().size(); a++) {
                    RapidAst.ParamAlt alt = p.alternatives().get(a);
                    if (a > 0) b.append(" | ");
                    if (alt.mode() != null) b.append(alt.mode()).append(' ');
                    b.append(alt.type()).append(' ').append(alt.name());
                    if (alt.arrayDims() > 0) b.append('{').append(String.join(",", java.util.Collections.nCopies(alt.arrayDims(), "*"))).append('}');
                }
            }
            b.append(')');
        }
        b.append('\n');
        String in = ind + IND;
        block(b, r.body(), in);
        if (r.backward() != null) { b.append(ind).append("BACKWARD\n"); block(b, r.backward(), in); }
        if (r.error() != null) {
            b.append(ind).append("ERROR");
            if (r.errorNumbers() != null) b.append(" (").append(list(r.errorNumbers())).append(')');
            b.append('\n');
            block(b, r.error(), in);
        }
        if (r.undo() != null) { b.append(ind).append("UNDO\n"); block(b, r.undo(), in); }
        b.append(ind).append("END").append(r.kind().name()).append('\n');
    }

    static void block(StringBuilder b, List<Stmt> body, String ind) {
        for (Stmt s : body) stmt(b, s, ind);
    }

    /** One statement (and its nested blocks), each line starting with {@code ind}. */
    static void stmt(StringBuilder b, Stmt s, String ind) {
        String in = ind + IND;
        if (s instanceof RapidAst.If f) {
            b.append(ind).append("IF ").append(expr(f.condition())).append(" THEN\n");
            block(b, f.then(), in);
            for (RapidAst.ElseIf e : f.elseIfs()) {
                b.append(ind).append("ELSEIF ").append(expr(e.condition())).append(" THEN\n");
                block(b, e.body(), in);
            }
            if (f.otherwise() != null) { b.append(ind).append("ELSE\n"); block(b, f.otherwise(), in); }
            b.append(ind).append("ENDIF\n");
        } else if (s instanceof RapidAst.While w) {
            b.append(ind).append("WHILE ").append(expr(w.condition())).append(" DO\n");
            block(b, w.body(), in);
            b.append(ind).append("ENDWHILE\n");
        } else if (s instanceof RapidAst.For f) {
            b.append(ind).append("FOR ").append(f.variable()).append(" FROM ").append(expr(f.from())).append(" TO ").append(expr(f.to()));
            if (f.step() != null) b.append(" STEP ").append(expr(f.step()));
            b.append(" DO\n");
            block(b, f.body(), in);
            b.append(ind).append("ENDFOR\n");
        } else if (s instanceof RapidAst.Test t) {
            b.append(ind).append("TEST ").append(expr(t.value())).append('\n');
            for (RapidAst.Case c : t.cases()) {
                b.append(ind).append("CASE ").append(list(c.values())).append(":\n");
                block(b, c.body(), in);
            }
            if (t.otherwise() != null) { b.append(ind).append("DEFAULT:\n"); block(b, t.otherwise(), in); }
            b.append(ind).append("ENDTEST\n");
        } else if (s instanceof RapidAst.CommentLine c) {
            b.append(ind).append('!').append(c.text()).append('\n');
        } else if (s instanceof RapidAst.Label l) {
            b.append(ind).append(l.name()).append(":\n");
        } else {
            b.append(ind).append(simple(s)).append('\n');
        }
    }

    /** A one-line statement (ends with ';'). */
    static String simple(Stmt s) {
        if (s instanceof RapidAst.DataDecl d) return decl(d);
        if (s instanceof RapidAst.Assign a) return expr(a.target()) + ":=" + expr(a.value()) + ";";
        if (s instanceof RapidAst.Call c) {
            String head = c.name() != null ? c.name() : "%" + expr(c.lateBinding()) + "%";
            return c.args().isEmpty() ? head + ";" : head + " " + args(c.args()) + ";";
        }
        if (s instanceof RapidAst.CompactIf ci) return "IF " + expr(ci.condition()) + " " + simple(ci.stmt());
        if (s instanceof RapidAst.Goto g) return "GOTO " + g.label() + ";";
        if (s instanceof RapidAst.Return r) return r.value() == null ? "RETURN;" : "RETURN " + expr(r.value()) + ";";
        if (s instanceof RapidAst.Raise r) return r.value() == null ? "RAISE;" : "RAISE " + expr(r.value()) + ";";
        if (s instanceof RapidAst.Retry) return "RETRY;";
        if (s instanceof RapidAst.TryNext) return "TRYNEXT;";
        if (s instanceof RapidAst.Exit) return "EXIT;";
        if (s instanceof RapidAst.Connect c) return "CONNECT " + expr(c.target()) + " WITH " + c.trap() + ";";
        throw new IllegalArgumentException("not a one-line statement: " + s);
    }

    /** Arguments: ", " before a required one, an optional one follows directly ({@code p1\WObj:=w}). */
    static String args(List<Arg> args) {
        StringBuilder b = new StringBuilder();
        for (int k = 0; k < args.size(); k++) {
            Arg a = args.get(k);
            boolean opt = a.kind() == RapidAst.ArgKind.OPTIONAL || a.kind() == RapidAst.ArgKind.SWITCH
                    || a.kind() == RapidAst.ArgKind.CONDITIONAL;
            if (k > 0 && !opt) b.append(", ");
            switch (a.kind()) {
                case POSITIONAL -> b.append(expr(a.value()));
                case NAMED -> b.append(a.name()).append(":=").append(expr(a.value()));
                case OPTIONAL -> b.append('\\').append(a.name()).append(":=").append(expr(a.value()));
                case SWITCH -> b.append('\\').append(a.name());
                case CONDITIONAL -> b.append('\\').append(a.name()).append('?').append(expr(a.value()));
            }
        }
        return b.toString();
    }

    private static String list(List<Expr> es) {
        StringBuilder b = new StringBuilder();
        for (int k = 0; k < es.size(); k++) b.append(k > 0 ? "," : "").append(expr(es.get(k)));
        return b.toString();
    }

    // ---------------------------------------------------------------- expressions

    private static final Set<String> REL = Set.of("=", "<>", "<", ">", "<=", ">=");

    /** Binding level of a binary operator: OR/XOR 1, AND 2, comparisons 3, + - 4, * / DIV MOD 5. */
    private static int level(String op) {
        return switch (op) {
            case "OR", "XOR" -> 1;
            case "AND" -> 2;
            case "+", "-" -> 4;
            case "*", "/", "DIV", "MOD" -> 5;
            default -> REL.contains(op) ? 3 : 6;
        };
    }

    /** Level of an expression as an operand: binary by operator, unary minus 4 (it starts a sum), NOT 1, else 6. */
    private static int levelOf(Expr e) {
        if (e instanceof Binary b) return level(b.op());
        if (e instanceof Unary u) return u.op().equals("NOT") ? 1 : 4;
        return 6;
    }

    /** An expression in a place that takes any expression. */
    public static String expr(Expr e) {
        if (e instanceof RapidAst.Num n) return n.text();
        if (e instanceof RapidAst.Str s) return "\"" + s.raw() + "\"";
        if (e instanceof RapidAst.Bool bo) return bo.value() ? "TRUE" : "FALSE";
        if (e instanceof RapidAst.Name n) return n.name();
        if (e instanceof RapidAst.Component c) return postfixBase(c.base()) + "." + c.component();
        if (e instanceof RapidAst.Index x) return postfixBase(x.base()) + "{" + list(x.indices()) + "}";
        if (e instanceof RapidAst.FuncCall f) return f.name() + "(" + args(f.args()) + ")";
        if (e instanceof RapidAst.Aggregate a) return "[" + list(a.items()) + "]";
        if (e instanceof Unary u) {
            if (u.op().equals("NOT")) {
                // NOT takes an AND-term (or a comparison after AND): anything weaker goes in parentheses.
                return "NOT " + (levelOf(u.operand()) >= 3 ? expr(u.operand()) : "(" + expr(u.operand()) + ")");
            }
            // A sign applies to the first term of a sum: a product or anything tighter.
            if (isSign(u.operand())) return u.op() + " " + signedPrimary((Unary) u.operand());
            return u.op() + (levelOf(u.operand()) >= 5 && !(u.operand() instanceof Unary) ? expr(u.operand()) : "(" + expr(u.operand()) + ")");
        }
        Binary b = (Binary) e;
        int p = level(b.op());
        String sep = p == 1 || p == 2 || b.op().equals("DIV") || b.op().equals("MOD") ? " " + b.op() + " " : b.op();
        if (p == 1 || p == 2 || p == 3) sep = " " + b.op() + " ";
        String right = operand(b.right(), b, false);
        if (!sep.endsWith(" ") && (right.startsWith("-") || right.startsWith("+"))) sep += " "; // "a- -b", never "a--b"
        return operand(b.left(), b, true) + sep + right;
    }

    private static String postfixBase(Expr base) {
        return base instanceof RapidAst.Name || base instanceof RapidAst.Component || base instanceof RapidAst.Index
                || base instanceof RapidAst.FuncCall ? expr(base) : "(" + expr(base) + ")";
    }

    private static boolean isSign(Expr e) { return e instanceof Unary u && !u.op().equals("NOT"); }

    /**
     * A sign read as an operand ("a * -b", "- -b"): it applies to one primary, so the operand
     * is a primary or in parentheses. Written so rather than "a*(-b)", the text nests no deeper
     * than the source did (the parser bounds nesting).
     */
    private static String signedPrimary(Unary u) {
        Expr x = u.operand();
        if (isSign(x)) return u.op() + " " + signedPrimary((Unary) x);
        return u.op() + (levelOf(x) >= 6 ? expr(x) : "(" + expr(x) + ")");
    }

    private static String operand(Expr e, Binary parent, boolean left) {
        int p = level(parent.op());
        boolean bare;
        if (e instanceof Unary u && u.op().equals("NOT")) {
            // NOT starts an OR operand, or follows AND; elsewhere it needs parentheses.
            bare = p == 1 || (p == 2 && !left);
        } else if (e instanceof Unary u) {
            // A sign starts a sum: the left of + -, or any operand of a comparison or logical operator.
            bare = p <= 3 || (p == 4 && left);
            // Elsewhere, on the right, it is a signed primary: "a - -b", "a * -(b + c)".
            if (!bare && !left) return signedPrimary(u);
        } else {
            int q = levelOf(e);
            if (p == 3) bare = q > 3; // comparisons do not chain
            else bare = left ? q >= p : q > p;
        }
        return bare ? expr(e) : "(" + expr(e) + ")";
    }
}
