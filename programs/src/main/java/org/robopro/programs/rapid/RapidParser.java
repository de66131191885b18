package org.robopro.programs.rapid;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalDouble;
import java.util.Set;
import org.robopro.kinematics.ConfData;
import org.robopro.kinematics.Units;
import org.robopro.models.InputException;
import org.robopro.models.Vec3;
import org.robopro.programs.Comment;
import org.robopro.programs.Declaration;
import org.robopro.programs.ExtJoints;
import org.robopro.programs.JointTarget;
import org.robopro.programs.LoadData;
import org.robopro.programs.ModuleItem;
import org.robopro.programs.Move;
import org.robopro.programs.ProcCall;
import org.robopro.programs.Procedure;
import org.robopro.programs.Quaternion;
import org.robopro.programs.RapidModule;
import org.robopro.programs.RapidPose;
import org.robopro.programs.RapidValue;
import org.robopro.programs.Ref;
import org.robopro.programs.RobTarget;
import org.robopro.programs.SpeedData;
import org.robopro.programs.Statement;
import org.robopro.programs.ToolData;
import org.robopro.programs.WObjData;
import org.robopro.programs.WaitTime;
import org.robopro.programs.ZoneData;

/**
 * Recursive-descent parser for the RAPID subset robopro models: one MODULE with data
 * declarations (robtarget, jointtarget, tooldata, wobjdata, loaddata, speeddata, zonedata, pose,
 * num, bool, string; CONST/PERS/VAR, LOCAL/TASK), procedures without parameters holding
 * MoveAbsJ/MoveJ/MoveL/MoveC, WaitTime, procedure calls and comments. Anything else is refused
 * with an {@link InputException} naming the file, line and column: a Move is never skipped.
 * RAPID units (mm, degrees) become SI here.
 */
public final class RapidParser {
    private final String file;
    private final List<Token> toks;
    private int i;
    private final IdentityHashMap<Statement, SourcePos> positions = new IdentityHashMap<>();
    /** Declared data by lower-case name: type name, for checking references. */
    private final Map<String, String> declaredTypes = new HashMap<>();
    /** Declared values by lower-case name, for initialisers that name other data. */
    private final Map<String, RapidValue> declaredValues = new HashMap<>();

    private RapidParser(String text, String file) {
        this.file = file;
        this.toks = new RapidLexer(blankHeader(text), file).tokens();
    }

    /** Parses RAPID module text; {@code fileName} names the source in error messages. */
    public static RapidModule parse(String text, String fileName) {
        return parseDetailed(text, fileName).module();
    }

    /** Like {@link #parse} and also keeps each statement's position. */
    public static ParsedModule parseDetailed(String text, String fileName) {
        if (text == null) throw new IllegalArgumentException("text must not be null");
        RapidParser p = new RapidParser(text, fileName == null ? "<rapid>" : fileName);
        RapidModule m = p.module();
        return new ParsedModule(m, p.file, p.positions);
    }

    /**
     * Old controllers write a "%%%\n VERSION:1\n LANGUAGE:ENGLISH\n%%%" header before MODULE. It
     * carries no program meaning; it is blanked (line numbers stay right).
     */
    private static String blankHeader(String text) {
        int start = 0;
        while (start < text.length() && Character.isWhitespace(text.charAt(start))) start++;
        if (!text.startsWith("%%%", start)) return text;
        int end = text.indexOf("%%%", start + 3);
        if (end < 0) return text;
        StringBuilder b = new StringBuilder(text);
        for (int k = start; k < end + 3; k++) if (b.charAt(k) != '\n' && b.charAt(k) != '\r') b.setCharAt(k, ' ');
        return b.toString();
    }

    // ---------------------------------------------------------------- module level

    private RapidModule module() {
        while (peek().kind() == Token.Kind.COMMENT) i++; // comments before MODULE carry no meaning
        expectWord("MODULE");
        String name = ident("module name");
        List<String> options = new ArrayList<>();
        if (peek().is("(")) {
            i++;
            do {
                Token o = next();
                if (o.kind() != Token.Kind.IDENT || !Set.of("SYSMODULE", "NOSTEPIN", "VIEWONLY", "READONLY", "NOVIEW")
                        .contains(o.text().toUpperCase(Locale.ROOT)))
                    throw error(o, "module option", "expected SYSMODULE, NOSTEPIN, VIEWONLY, READONLY or NOVIEW, found " + o.describe());
                options.add(o.text().toUpperCase(Locale.ROOT));
            } while (accept(","));
            expect(")");
        }
        List<ModuleItem> items = new ArrayList<>();
        Map<String, Token> names = new HashMap<>();
        while (true) {
            Token t = peek();
            if (t.kind() == Token.Kind.COMMENT) {
                items.add(new Comment(toks.get(i++).text()));
                continue;
            }
            if (t.isWord("ENDMODULE")) { i++; break; }
            if (t.kind() == Token.Kind.EOF) throw error(t, null, "ENDMODULE missing (module " + name + " opened on line 1)");
            ModuleItem item;
            Token nameTok;
            if (isDeclarationStart()) {
                int at = i;
                Declaration d = declaration();
                item = d;
                nameTok = findNameToken(at, d.name());
                declaredTypes.put(d.name().toLowerCase(Locale.ROOT), d.rapidType());
                declaredValues.putIfAbsent(d.name().toLowerCase(Locale.ROOT), d.value());
            } else if (t.isWord("PROC") || (t.isWord("LOCAL") && peekAt(1).isWord("PROC"))) {
                nameTok = peekAt(t.isWord("LOCAL") ? 2 : 1);
                item = procedure();
            } else if (t.isWord("FUNC") || t.isWord("TRAP") || t.isWord("RECORD") || t.isWord("ALIAS")
                    || (t.isWord("LOCAL") && (peekAt(1).isWord("FUNC") || peekAt(1).isWord("TRAP")))) {
                Token w = t.isWord("LOCAL") ? peekAt(1) : t;
                throw error(w, null, w.text().toUpperCase(Locale.ROOT) + " is not supported (robopro reads data declarations and PROCs)");
            } else {
                throw error(t, null, "expected a declaration, PROC or ENDMODULE, found " + t.describe());
            }
            String key = nameOf(item).toLowerCase(Locale.ROOT);
            Token prev = names.putIfAbsent(key, nameTok);
            if (prev != null)
                throw error(nameTok, nameOf(item), "name already used on line " + prev.line() + " (RAPID names ignore case)");
            items.add(item);
        }
        while (peek().kind() == Token.Kind.COMMENT) i++;
        if (peek().kind() != Token.Kind.EOF) throw error(peek(), null, "text after ENDMODULE: " + peek().describe());
        RapidModule m = new RapidModule(name, options, items);
        checkReferences(m);
        return m;
    }

    private static String nameOf(ModuleItem item) {
        return item instanceof Declaration d ? d.name() : ((Procedure) item).name();
    }

    private Token findNameToken(int from, String name) {
        for (int k = from; k < i; k++) if (toks.get(k).kind() == Token.Kind.IDENT && toks.get(k).text().equals(name)) return toks.get(k);
        return toks.get(from);
    }

    private boolean isDeclarationStart() {
        Token t = peek();
        if (t.isWord("LOCAL") || t.isWord("TASK")) t = peekAt(1);
        return t.isWord("CONST") || t.isWord("PERS") || t.isWord("VAR");
    }

    private Declaration declaration() {
        Declaration.Scope scope = Declaration.Scope.GLOBAL;
        if (peek().isWord("LOCAL")) { i++; scope = Declaration.Scope.LOCAL; }
        else if (peek().isWord("TASK")) { i++; scope = Declaration.Scope.TASK; }
        Token st = next();
        Declaration.Storage storage = Declaration.Storage.valueOf(st.text().toUpperCase(Locale.ROOT));
        Token typeTok = peek();
        String type = ident("data type").toLowerCase(Locale.ROOT);
        Token nameTok = peek();
        String name = ident("data name");
        if (peek().is("{")) throw error(peek(), name, "arrays are not supported");
        RapidValue value;
        if (accept(":=")) {
            Expr e = expr();
            value = convert(type, typeTok, e, name);
        } else {
            if (storage == Declaration.Storage.CONST) throw error(nameTok, name, "CONST needs a value (':=')");
            value = switch (type) {
                case "num" -> new RapidValue.Num(0);
                case "bool" -> new RapidValue.Bool(false);
                case "string" -> new RapidValue.Str("");
                default -> {
                    checkType(type, typeTok, name);
                    throw error(nameTok, name, type + " declared without a value is not supported (give ':= [...]')");
                }
            };
        }
        expect(";");
        return new Declaration(scope, storage, name, value);
    }

    private static final Set<String> TYPES = Set.of("robtarget", "jointtarget", "tooldata", "wobjdata", "loaddata",
            "speeddata", "zonedata", "pose", "num", "bool", "string");

    private void checkType(String type, Token at, String name) {
        if (!TYPES.contains(type))
            throw error(at, name, "data type '" + at.text() + "' is not supported (robopro reads " + String.join(", ", TYPES.stream().sorted().toList()) + ")");
    }

    private Procedure procedure() {
        boolean local = false;
        if (peek().isWord("LOCAL")) { i++; local = true; }
        expectWord("PROC");
        String name = ident("procedure name");
        expect("(");
        if (!peek().is(")")) throw error(peek(), name, "procedure parameters are not supported");
        expect(")");
        List<Statement> body = new ArrayList<>();
        while (true) {
            Token t = peek();
            if (t.kind() == Token.Kind.COMMENT) { body.add(new Comment(toks.get(i++).text())); continue; }
            if (t.isWord("ENDPROC")) { i++; break; }
            if (t.kind() == Token.Kind.EOF) throw error(t, name, "ENDPROC missing for PROC " + name);
            body.add(statement(name));
        }
        return new Procedure(name, local, body);
    }

    private static final Set<String> STATEMENT_KEYWORDS = Set.of("IF", "WHILE", "FOR", "TEST", "GOTO", "RETURN",
            "RAISE", "EXIT", "RETRY", "TRYNEXT", "CONNECT", "ERROR", "UNDO", "BACKWARD", "VAR", "PERS", "CONST",
            "LOCAL", "TASK", "PROC", "FUNC", "TRAP", "ENDMODULE", "ELSE", "ELSEIF", "ENDIF", "ENDWHILE", "ENDFOR",
            "ENDTEST", "CASE", "DEFAULT");

    // ---------------------------------------------------------------- statements

    private Statement statement(String proc) {
        Token head = peek();
        if (head.kind() != Token.Kind.IDENT)
            throw error(head, proc, "expected an instruction, found " + head.describe());
        String upper = head.text().toUpperCase(Locale.ROOT);
        if (STATEMENT_KEYWORDS.contains(upper)) {
            String what = switch (upper) {
                case "VAR", "PERS", "CONST", "LOCAL", "TASK" -> "data declarations inside a PROC are not supported";
                case "PROC", "FUNC", "TRAP", "ENDMODULE" -> "ENDPROC missing before " + upper;
                default -> upper + " is not supported (robopro reads straight-line motion programs)";
            };
            throw error(head, proc, what);
        }
        if (RapidNames.isReserved(upper)) throw error(head, proc, "expected an instruction, found keyword " + head.text());
        i++;
        if (peek().is(":=") || peek().is(".") || peek().is("{"))
            throw error(head, proc, "assignments are not supported");
        if (peek().is("("))
            throw error(head, proc, "function call statement '" + head.text() + "(...)' is not supported");
        List<Arg> args = arguments(proc);
        expect(";");
        Statement s;
        try {
            s = instruction(upper, head, args, proc);
        } catch (IllegalArgumentException bad) {
            throw error(head, proc, bad.getMessage());
        }
        positions.put(s, new SourcePos(file, head.line(), head.column()));
        return s;
    }

    private Statement instruction(String upper, Token head, List<Arg> args, String proc) {
        return switch (upper) {
            case "MOVEL" -> move(Move.Kind.MOVE_L, head, args, proc);
            case "MOVEJ" -> move(Move.Kind.MOVE_J, head, args, proc);
            case "MOVEC" -> move(Move.Kind.MOVE_C, head, args, proc);
            case "MOVEABSJ" -> move(Move.Kind.MOVE_ABS_J, head, args, proc);
            case "WAITTIME" -> waitTime(head, args, proc);
            default -> {
                if (!args.isEmpty())
                    throw error(head, proc, "instruction " + head.text() + " is not supported (robopro reads MoveAbsJ, MoveJ, MoveL, MoveC, WaitTime and calls of PROCs without arguments)");
                yield new ProcCall(head.text());
            }
        };
    }

    /** One argument: positional (name null) or optional ({@code \Name[:=value]}), and how many positional ones precede it. */
    private record Arg(String name, Expr value, int position, Token at) { }

    private List<Arg> arguments(String proc) {
        List<Arg> args = new ArrayList<>();
        int positional = 0;
        if (peek().is(";")) return args;
        while (true) {
            Token at = peek();
            if (accept("\\")) {
                String n = ident("optional argument");
                Expr v = accept(":=") ? expr() : null;
                args.add(new Arg(n, v, positional, at));
            } else {
                if (at.kind() == Token.Kind.IDENT && peekAt(1).is(":="))
                    throw error(at, proc, "named argument '" + at.text() + ":=' is not supported");
                args.add(new Arg(null, expr(), positional, at));
                positional++;
            }
            if (accept(",")) continue;
            if (peek().is("\\")) continue;
            if (peek().is(";")) return args;
            throw error(peek(), proc, "expected ',' or ';' after an argument, found " + peek().describe());
        }
    }

    private Statement waitTime(Token head, List<Arg> args, String proc) {
        for (Arg a : args)
            if (a.name() != null) throw error(a.at(), proc, "WaitTime \\" + a.name() + " is not supported");
        if (args.size() != 1) throw error(head, proc, "WaitTime takes one time in seconds");
        double s = number(args.get(0).value(), proc + ": WaitTime");
        if (s < 0) throw error(args.get(0).at(), proc, "WaitTime needs a time >= 0");
        return new WaitTime(s);
    }

    @SuppressWarnings("unchecked")
    private Statement move(Move.Kind kind, Token head, List<Arg> args, String proc) {
        int base = kind == Move.Kind.MOVE_C ? 1 : 0; // MoveC has CirPoint before ToPoint
        int toIdx = base, speedIdx = base + 1, zoneIdx = base + 2, toolIdx = base + 3;
        List<Arg> pos = new ArrayList<>();
        for (Arg a : args) if (a.name() == null) pos.add(a);
        if (pos.size() != toolIdx + 1) {
            String sig = kind == Move.Kind.MOVE_C ? "CirPoint, ToPoint, Speed, Zone, Tool" : "ToPoint, Speed, Zone, Tool";
            throw error(head, proc, kind.rapidName() + " needs " + (toolIdx + 1) + " arguments (" + sig + "), found " + pos.size());
        }
        boolean conc = false, noEOffs = false;
        OptionalDouble v = OptionalDouble.empty(), t = OptionalDouble.empty(), z = OptionalDouble.empty();
        Optional<String> wobj = Optional.empty();
        for (Arg a : args) {
            if (a.name() == null) continue;
            String n = a.name().toUpperCase(Locale.ROOT);
            int want = switch (n) {
                case "CONC" -> 0;
                case "NOEOFFS" -> kind == Move.Kind.MOVE_ABS_J ? toIdx + 1 : -1;
                case "V", "T" -> speedIdx + 1;
                case "Z" -> zoneIdx + 1;
                case "WOBJ" -> toolIdx + 1;
                default -> -1;
            };
            if (want < 0) throw error(a.at(), proc, "optional argument \\" + a.name() + " of " + kind.rapidName() + " is not supported");
            if (a.position() != want) throw error(a.at(), proc, "\\" + a.name() + " is not in its place in " + kind.rapidName());
            boolean isSwitch = n.equals("CONC") || n.equals("NOEOFFS");
            if (isSwitch != (a.value() == null))
                throw error(a.at(), proc, "\\" + a.name() + (isSwitch ? " takes no value" : " needs a value (\\" + a.name() + ":=...)"));
            switch (n) {
                case "CONC" -> conc = true;
                case "NOEOFFS" -> noEOffs = true;
                case "V" -> v = OptionalDouble.of(positive(a, proc, "\\V", Units.mmToM(number(a.value(), proc + ": \\V"))));
                case "T" -> t = OptionalDouble.of(positive(a, proc, "\\T", number(a.value(), proc + ": \\T")));
                case "Z" -> z = OptionalDouble.of(nonNegative(a, proc, "\\Z", Units.mmToM(number(a.value(), proc + ": \\Z"))));
                case "WOBJ" -> wobj = Optional.of(name(a, proc, "wobjdata"));
                default -> throw new IllegalStateException(n);
            }
        }
        if (v.isPresent() && t.isPresent()) throw error(head, proc, "\\V and \\T exclude each other");
        Optional<Ref<RobTarget>> circ = Optional.empty();
        if (kind == Move.Kind.MOVE_C) circ = Optional.of((Ref<RobTarget>) (Ref<?>) targetRef(pos.get(0), "robtarget", proc));
        Ref<? extends RapidValue> to = targetRef(pos.get(toIdx), kind == Move.Kind.MOVE_ABS_J ? "jointtarget" : "robtarget", proc);
        Ref<SpeedData> speed = (Ref<SpeedData>) (Ref<?>) targetRef(pos.get(speedIdx), "speeddata", proc);
        Ref<ZoneData> zone = (Ref<ZoneData>) (Ref<?>) targetRef(pos.get(zoneIdx), "zonedata", proc);
        String tool = name(pos.get(toolIdx), proc, "tooldata");
        return new Move(kind, conc, circ, to, noEOffs, speed, v, t, zone, z, tool, wobj);
    }

    private double positive(Arg a, String proc, String what, double x) {
        if (!(x > 0)) throw error(a.at(), proc, what + " must be > 0");
        return x;
    }

    private double nonNegative(Arg a, String proc, String what, double x) {
        if (!(x >= 0)) throw error(a.at(), proc, what + " must be >= 0");
        return x;
    }

    /** A data argument: a name (type-checked when this module declares it) or an inline aggregate. */
    private Ref<?> targetRef(Arg a, String type, String proc) {
        Expr e = a.value();
        if (e instanceof NameE n) {
            checkDeclaredType(n, type, proc);
            return Ref.to(n.name());
        }
        if (e instanceof AggE) return Ref.inline(convert(type, a.at(), e, proc + ": inline " + type));
        throw error(a.at(), proc, "expected a " + type + " name or [...] value, found " + e.describe());
    }

    private String name(Arg a, String proc, String type) {
        if (a.value() instanceof NameE n) {
            checkDeclaredType(n, type, proc);
            return n.name();
        }
        throw error(a.at(), proc, "expected the name of a " + type + ", found " + (a.value() == null ? "nothing" : a.value().describe()));
    }

    private void checkDeclaredType(NameE n, String type, String proc) {
        String declared = declaredTypes.get(n.name().toLowerCase(Locale.ROOT));
        if (declared != null && !declared.equals(type))
            throw new InputException(file, n.line(), n.col(), proc, "'" + n.name() + "' is a " + declared + ", a " + type + " is needed here");
    }

    /** References to data declared further down the file are checked once everything is read. */
    private void checkReferences(RapidModule m) {
        for (Procedure p : m.procedures())
            for (Statement s : p.body())
                if (s instanceof Move mv) {
                    SourcePos at = positions.get(s);
                    check(mv.toPoint(), mv.kind() == Move.Kind.MOVE_ABS_J ? "jointtarget" : "robtarget", at, p.name());
                    mv.circPoint().ifPresent(c -> check(c, "robtarget", at, p.name()));
                    check(mv.speed(), "speeddata", at, p.name());
                    check(mv.zone(), "zonedata", at, p.name());
                    checkName(mv.tool(), "tooldata", at, p.name());
                    mv.wobj().ifPresent(w -> checkName(w, "wobjdata", at, p.name()));
                }
    }

    private void check(Ref<?> r, String type, SourcePos at, String proc) {
        if (r instanceof Ref.Named<?> n) checkName(n.name(), type, at, proc);
    }

    private void checkName(String n, String type, SourcePos at, String proc) {
        String declared = declaredTypes.get(n.toLowerCase(Locale.ROOT));
        if (declared != null && !declared.equals(type))
            throw new InputException(file, at.line(), at.column(), proc, "'" + n + "' is a " + declared + ", a " + type + " is needed here");
    }

    // ---------------------------------------------------------------- expressions (literals only)

    private sealed interface Expr permits NumE, BoolE, StrE, NameE, AggE {
        int line();
        int col();
        String describe();
    }

    private record NumE(double value, int line, int col) implements Expr {
        public String describe() { return "number " + value; }
    }

    private record BoolE(boolean value, int line, int col) implements Expr {
        public String describe() { return value ? "TRUE" : "FALSE"; }
    }

    private record StrE(String raw, int line, int col) implements Expr {
        public String describe() { return "string \"" + raw + "\""; }
    }

    private record NameE(String name, int line, int col) implements Expr {
        public String describe() { return "name " + name; }
    }

    private record AggE(List<Expr> items, int line, int col) implements Expr {
        public String describe() { return "aggregate of " + items.size(); }
    }

    private Expr expr() {
        Expr e = primary();
        Token t = peek();
        if (t.is("+") || t.is("-") || t.is("*") || t.is("/") || t.isWord("DIV") || t.isWord("MOD")
                || t.is("=") || t.is("<") || t.is(">") || t.is("<=") || t.is(">=") || t.is("<>")
                || t.isWord("AND") || t.isWord("OR") || t.isWord("XOR"))
            throw error(t, null, "expressions with operators are not supported (only literal values and names)");
        return e;
    }

    private Expr primary() {
        Token t = next();
        if (t.is("-") || t.is("+")) {
            Token n = next();
            if (n.kind() != Token.Kind.NUMBER) throw error(n, null, "expected a number after '" + t.text() + "', found " + n.describe());
            double d = parseNumber(n);
            return new NumE(t.is("-") ? -d : d, t.line(), t.column());
        }
        switch (t.kind()) {
            case NUMBER: return new NumE(parseNumber(t), t.line(), t.column());
            case STRING: return new StrE(t.text(), t.line(), t.column());
            case IDENT:
                if (t.isWord("TRUE")) return new BoolE(true, t.line(), t.column());
                if (t.isWord("FALSE")) return new BoolE(false, t.line(), t.column());
                if (RapidNames.isReserved(t.text())) throw error(t, null, "expected a value, found keyword " + t.text());
                if (peek().is("(")) throw error(t, null, "function call " + t.text() + "(...) is not supported (only literal values and names)");
                if (peek().is(".") || peek().is("{")) throw error(peek(), null, "components and array elements are not supported");
                return new NameE(t.text(), t.line(), t.column());
            case PUNCT:
                if (t.is("[")) {
                    List<Expr> items = new ArrayList<>();
                    if (peek().is("]")) throw error(peek(), null, "empty aggregate");
                    do { items.add(expr()); } while (accept(","));
                    expect("]");
                    return new AggE(items, t.line(), t.column());
                }
                // fall through
            default:
                throw error(t, null, "expected a value, found " + t.describe());
        }
    }

    private double parseNumber(Token t) {
        double d;
        try {
            d = Double.parseDouble(t.text());
        } catch (NumberFormatException e) {
            throw error(t, null, "bad number '" + t.text() + "'");
        }
        if (!Double.isFinite(d)) throw error(t, null, "number out of range '" + t.text() + "'");
        return d;
    }

    // ---------------------------------------------------------------- values

    private RapidValue convert(String type, Token typeTok, Expr e, String field) {
        checkType(type, typeTok, field);
        try {
            return convertChecked(type, e, field);
        } catch (IllegalArgumentException bad) {
            // A model constructor refused a value the syntax allowed (e.g. an infinite sum of zones).
            if (bad instanceof NumberFormatException) throw bad;
            throw err(e, field, bad.getMessage());
        }
    }

    private RapidValue convertChecked(String type, Expr e, String field) {
        if (e instanceof NameE n && !type.equals("num") && !type.equals("bool") && !type.equals("string")) {
            // "CONST zonedata zCorner := z10;": the value of predefined or earlier declared data.
            RapidValue v = declaredValues.get(n.name().toLowerCase(Locale.ROOT));
            if (v == null) v = predefinedValue(n.name());
            if (v == null) throw err(e, field, "unknown " + type + " '" + n.name() + "' (only predefined or earlier declared data)");
            if (!v.rapidType().equals(type)) throw err(e, field, "'" + n.name() + "' is a " + v.rapidType() + ", a " + type + " is needed");
            return v;
        }
        return switch (type) {
            case "robtarget" -> robTarget(e, field);
            case "jointtarget" -> jointTarget(e, field);
            case "tooldata" -> toolData(e, field);
            case "wobjdata" -> wobjData(e, field);
            case "loaddata" -> loadData(e, field);
            case "speeddata" -> speedData(e, field);
            case "zonedata" -> zoneData(e, field);
            case "pose" -> pose(e, field);
            case "num" -> new RapidValue.Num(number(e, field));
            case "bool" -> new RapidValue.Bool(bool(e, field));
            case "string" -> new RapidValue.Str(string(e, field));
            default -> throw new IllegalStateException(type);
        };
    }

    private List<Expr> agg(Expr e, int n, String field) {
        if (!(e instanceof AggE a)) throw err(e, field, "expected [...] with " + n + " components, found " + e.describe());
        if (a.items().size() != n) throw err(e, field, "expected " + n + " components, found " + a.items().size());
        return a.items();
    }

    private double number(Expr e, String field) {
        if (e instanceof NumE n) return n.value();
        throw err(e, field, "expected a number, found " + e.describe());
    }

    private int integer(Expr e, String field) {
        double d = number(e, field);
        if (d != Math.rint(d) || Math.abs(d) > 1e6) throw err(e, field, "expected an integer, found " + d);
        return (int) d;
    }

    private boolean bool(Expr e, String field) {
        if (e instanceof BoolE b) return b.value();
        throw err(e, field, "expected TRUE or FALSE, found " + e.describe());
    }

    private String string(Expr e, String field) {
        if (e instanceof StrE s) return unescape(s, field);
        throw err(e, field, "expected a string, found " + e.describe());
    }

    /** RAPID string escapes: "" is a quote, backslash-backslash a backslash, backslash hh a character code. */
    private String unescape(StrE s, String field) {
        String r = s.raw();
        StringBuilder b = new StringBuilder();
        for (int k = 0; k < r.length(); k++) {
            char c = r.charAt(k);
            if (c == '"') { b.append('"'); k++; continue; }
            if (c == '\\') {
                if (k + 1 < r.length() && r.charAt(k + 1) == '\\') { b.append('\\'); k++; continue; }
                if (k + 2 < r.length() && isHex(r.charAt(k + 1)) && isHex(r.charAt(k + 2))) {
                    b.append((char) Integer.parseInt(r.substring(k + 1, k + 3), 16));
                    k += 2;
                    continue;
                }
                throw err(s, field, "bad escape in string (use \\\\ for a backslash)");
            }
            b.append(c);
        }
        if (b.length() > 80) throw err(s, field, "string longer than RAPID's 80 characters");
        for (int k = 0; k < b.length(); k++)
            if (b.charAt(k) > 0xFF) throw err(s, field, "string holds a character outside ISO-8859-1");
        return b.toString();
    }

    private static RapidValue predefinedValue(String name) {
        String k = name.toLowerCase(Locale.ROOT);
        if (k.equals("tool0")) return ToolData.TOOL0;
        if (k.equals("wobj0")) return WObjData.WOBJ0;
        if (k.equals("load0")) return LoadData.LOAD0;
        Optional<SpeedData> sp = SpeedData.predefined(k);
        if (sp.isPresent()) return sp.get();
        return ZoneData.predefined(k).orElse(null);
    }

    private static boolean isHex(char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F'); }

    private Vec3 posMm(Expr e, String field) {
        List<Expr> c = agg(e, 3, field);
        return new Vec3(Units.mmToM(number(c.get(0), field + ".x")), Units.mmToM(number(c.get(1), field + ".y")),
                Units.mmToM(number(c.get(2), field + ".z")));
    }

    private Quaternion quat(Expr e, String field) {
        List<Expr> c = agg(e, 4, field);
        Quaternion q = new Quaternion(number(c.get(0), field + ".q1"), number(c.get(1), field + ".q2"),
                number(c.get(2), field + ".q3"), number(c.get(3), field + ".q4"));
        double n = q.norm();
        // The controller accepts only (nearly) unit quaternions; a zero one has no orientation.
        if (!(Math.abs(n - 1) < 1e-3)) throw err(e, field, "quaternion is not unit (norm " + n + ")");
        return q;
    }

    private ExtJoints ext(Expr e, String field) {
        List<Expr> c = agg(e, 6, field);
        double[] v = new double[6];
        for (int k = 0; k < 6; k++) v[k] = number(c.get(k), field + ".eax_" + (char) ('a' + k));
        return ExtJoints.of(v);
    }

    private RapidPose pose(Expr e, String field) {
        List<Expr> c = agg(e, 2, field);
        return new RapidPose(posMm(c.get(0), field + ".trans"), quat(c.get(1), field + ".rot"));
    }

    private RobTarget robTarget(Expr e, String field) {
        List<Expr> c = agg(e, 4, field);
        List<Expr> cf = agg(c.get(2), 4, field + ".robconf");
        ConfData conf = new ConfData(integer(cf.get(0), field + ".robconf.cf1"), integer(cf.get(1), field + ".robconf.cf4"),
                integer(cf.get(2), field + ".robconf.cf6"), integer(cf.get(3), field + ".robconf.cfx"));
        return new RobTarget(posMm(c.get(0), field + ".trans"), quat(c.get(1), field + ".rot"), conf, ext(c.get(3), field + ".extax"));
    }

    private JointTarget jointTarget(Expr e, String field) {
        List<Expr> c = agg(e, 2, field);
        List<Expr> r = agg(c.get(0), 6, field + ".robax");
        double[] q = new double[6];
        for (int k = 0; k < 6; k++) q[k] = Units.degToRad(number(r.get(k), field + ".robax.rax_" + (k + 1)));
        return JointTarget.of(q, ext(c.get(1), field + ".extax"));
    }

    private LoadData loadData(Expr e, String field) {
        List<Expr> c = agg(e, 6, field);
        double mass = number(c.get(0), field + ".mass");
        if (mass < 0) throw err(c.get(0), field + ".mass", "mass must be >= 0");
        return new LoadData(mass, posMm(c.get(1), field + ".cog"), quat(c.get(2), field + ".aom"),
                number(c.get(3), field + ".ix"), number(c.get(4), field + ".iy"), number(c.get(5), field + ".iz"));
    }

    private ToolData toolData(Expr e, String field) {
        List<Expr> c = agg(e, 3, field);
        return new ToolData(bool(c.get(0), field + ".robhold"), pose(c.get(1), field + ".tframe"), loadData(c.get(2), field + ".tload"));
    }

    private WObjData wobjData(Expr e, String field) {
        List<Expr> c = agg(e, 5, field);
        return new WObjData(bool(c.get(0), field + ".robhold"), bool(c.get(1), field + ".ufprog"), string(c.get(2), field + ".ufmec"),
                pose(c.get(3), field + ".uframe"), pose(c.get(4), field + ".oframe"));
    }

    private SpeedData speedData(Expr e, String field) {
        List<Expr> c = agg(e, 4, field);
        double[] v = new double[4];
        String[] n = {"v_tcp", "v_ori", "v_leax", "v_reax"};
        for (int k = 0; k < 4; k++) {
            v[k] = number(c.get(k), field + "." + n[k]);
            if (v[k] < 0) throw err(c.get(k), field + "." + n[k], "speed must be >= 0");
        }
        return SpeedData.ofRapid(v[0], v[1], v[2], v[3]);
    }

    private ZoneData zoneData(Expr e, String field) {
        List<Expr> c = agg(e, 7, field);
        double[] v = new double[6];
        String[] n = {"pzone_tcp", "pzone_ori", "pzone_eax", "zone_ori", "zone_leax", "zone_reax"};
        for (int k = 0; k < 6; k++) {
            v[k] = number(c.get(k + 1), field + "." + n[k]);
            if (v[k] < 0) throw err(c.get(k + 1), field + "." + n[k], "zone size must be >= 0");
        }
        return ZoneData.ofRapid(bool(c.get(0), field + ".finep"), v[0], v[1], v[2], v[3], v[4], v[5]);
    }

    // ---------------------------------------------------------------- tokens

    private Token peek() { return toks.get(i); }

    private Token peekAt(int k) { return toks.get(Math.min(i + k, toks.size() - 1)); }

    /** The next token that is not a comment (comments are only statements at line starts). */
    private Token next() {
        Token t = toks.get(i);
        if (t.kind() == Token.Kind.COMMENT) throw error(t, null, "comment inside an instruction or declaration is not supported");
        if (t.kind() != Token.Kind.EOF) i++;
        return t;
    }

    private boolean accept(String punct) {
        if (peek().is(punct)) { i++; return true; }
        return false;
    }

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

    private InputException err(Expr e, String field, String problem) {
        return new InputException(file, e.line(), e.col(), field, problem);
    }
}
