package org.robopro.programs;

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
import org.robopro.programs.rapid.RapidAst.Expr;
import org.robopro.programs.rapid.ParsedAst;
import org.robopro.programs.rapid.RapidAst;
import org.robopro.programs.rapid.RapidAstParser;
import org.robopro.programs.rapid.RapidAstWriter;
import org.robopro.programs.rapid.SourcePos;

/**
 * Reads RAPID modules. The whole RAPID kernel grammar is parsed into a {@link RapidAst}
 * ({@link #parseAst}); {@link #parse} then maps what robopro models into typed form: data
 * declarations of robtarget, jointtarget, tooldata, wobjdata, loaddata, speeddata, zonedata,
 * pose, num, bool, string with literal values; PROCs without parameters or handlers; MoveAbsJ/
 * MoveJ/MoveL/MoveC with named or literal arguments, WaitTime, calls without arguments, comments.
 * Everything else stays as syntax tree ({@link AstItem}, {@link AstStatement}) so the module
 * exports with the same meaning. Errors: {@link InputException} naming the file, line and column.
 * RAPID units (mm, degrees) become SI in the typed model.
 */
public final class RapidParser {
    private final String file;
    private final ParsedAst ast;
    /** Each typed item and statement to the tree node it was read from. */
    private final IdentityHashMap<Object, Object> nodes = new IdentityHashMap<>();
    /**
     * A file is read strictly (names used twice, data of the wrong type, values a controller
     * refuses: errors); a tree built in code is viewed leniently (what does not read typed stays
     * syntax tree; the writer renames names used twice).
     */
    private final boolean strict;
    /** Declared data by lower-case name: type name, for checking references. */
    private final Map<String, String> declaredTypes = new HashMap<>();
    /** Declared values by lower-case name, for initialisers that name other data. */
    private final Map<String, RapidValue> declaredValues = new HashMap<>();

    private RapidParser(ParsedAst ast, boolean strict) {
        this.file = ast.file();
        this.ast = ast;
        this.strict = strict;
    }

    /** Parses RAPID module text; {@code fileName} names the source in error messages. */
    public static RapidModule parse(String text, String fileName) {
        return parseDetailed(text, fileName).module();
    }

    /** Like {@link #parse} and also keeps each statement's position and the syntax tree. */
    public static ParsedModule parseDetailed(String text, String fileName) {
        ParsedAst a = RapidAstParser.parse(text, fileName);
        RapidParser p = new RapidParser(a, true);
        RapidModule m = new RapidModule(a.module(), new RapidModule.View(p.module(a.module()), p.nodes));
        return new ParsedModule(m, a);
    }

    /** The typed view of a tree (built in code or edited): read leniently, see {@link #strict}. */
    static RapidModule.View view(RapidAst.Module tree) {
        RapidParser p = new RapidParser(ParsedAst.of(tree, tree.name()), false);
        return new RapidModule.View(p.module(tree), p.nodes);
    }

    /**
     * A typed value from a literal expression (aggregates of numbers, strings, booleans, names
     * of predefined data), RAPID units to SI; errors name {@code file} and the expression's place
     * in {@code where} when known.
     */
    public static RapidValue literalValue(String type, Expr e, String file, String field) {
        RapidParser p = new RapidParser(ParsedAst.of(new RapidAst.Module("M", List.of(), List.of()), file), true);
        if (!TYPES.contains(type)) throw new InputException(file, 0, 0, field, "data type '" + type + "' is not a typed value");
        try {
            return p.convertChecked(type, e, field);
        } catch (IllegalArgumentException bad) {
            if (bad instanceof NumberFormatException) throw bad;
            throw new InputException(file, 0, 0, field, bad.getMessage());
        }
    }

    /** The RAPID data types robopro holds typed. */
    public static final Set<String> TYPES = Set.of("robtarget", "jointtarget", "tooldata", "wobjdata", "loaddata",
            "speeddata", "zonedata", "pose", "num", "bool", "string");

    // ---------------------------------------------------------------- module level

    private List<ModuleItem> module(RapidAst.Module am) {
        List<ModuleItem> items = new ArrayList<>();
        Map<String, SourcePos> names = new HashMap<>();
        for (RapidAst.Item it : am.items()) {
            ModuleItem item = item(it);
            nodes.put(item, it);
            String n = item instanceof Declaration d ? d.name() : item instanceof Procedure p ? p.name()
                    : item instanceof AstItem a ? a.name() : null;
            if (n != null && strict) {
                SourcePos at = pos(it);
                SourcePos prev = names.putIfAbsent(n.toLowerCase(Locale.ROOT), at);
                if (prev != null)
                    throw new InputException(file, at.line(), nameColumn(it, at), n, "name already used on line " + prev.line() + " (RAPID names ignore case)");
            }
            items.add(item);
        }
        if (strict) checkReferences(items);
        return items;
    }

    /** Column of the declared name on its line (for messages), the item's column when not found. */
    private int nameColumn(RapidAst.Item it, SourcePos at) { return at.column() + (it instanceof RapidAst.DataDecl d ? declOffset(d) : 0); }

    private static int declOffset(RapidAst.DataDecl d) {
        int o = d.scope() == RapidAst.Scope.GLOBAL ? 0 : d.scope().name().length() + 1;
        return o + d.storage().name().length() + 1 + d.type().length() + 1;
    }

    private SourcePos pos(Object node) {
        return ast.position(node).orElse(new SourcePos(file, 0, 0));
    }

    private ModuleItem item(RapidAst.Item it) {
        if (it instanceof RapidAst.CommentLine c) return new Comment(c.text());
        if (it instanceof RapidAst.DataDecl d) {
            Declaration typed;
            try {
                typed = typedDeclaration(d);
            } catch (InputException | IllegalArgumentException bad) {
                if (strict) throw bad;
                typed = null;
            }
            if (typed == null) {
                declaredTypes.put(d.name().toLowerCase(Locale.ROOT), d.dims().isEmpty() ? d.type().toLowerCase(Locale.ROOT) : "array");
                return new AstItem(d);
            }
            declaredTypes.put(d.name().toLowerCase(Locale.ROOT), typed.rapidType());
            declaredValues.putIfAbsent(d.name().toLowerCase(Locale.ROOT), typed.value());
            return typed;
        }
        if (it instanceof RapidAst.Routine r && r.kind() == RapidAst.RoutineKind.PROC && r.params().isEmpty()
                && r.backward() == null && r.error() == null && r.undo() == null) {
            List<Statement> body = new ArrayList<>();
            for (RapidAst.Stmt s : r.body()) body.add(statement(s, r.name()));
            return new Procedure(r.name(), r.local(), body);
        }
        return new AstItem(it);
    }

    /** The typed declaration, or null when the data stays a syntax tree (other type, array, computed value). */
    private Declaration typedDeclaration(RapidAst.DataDecl d) {
        String type = d.type().toLowerCase(Locale.ROOT);
        if (!TYPES.contains(type) || !d.dims().isEmpty()) return null;
        RapidValue value;
        if (d.init() == null) {
            value = switch (type) {
                case "num" -> new RapidValue.Num(0);
                case "bool" -> new RapidValue.Bool(false);
                case "string" -> new RapidValue.Str("");
                default -> null; // a record's zero value (e.g. a zero quaternion) is no typed value
            };
            if (value == null) return null;
        } else {
            if (!isLiteral(d.init(), type)) return null;
            value = convert(type, d.init(), d.name());
        }
        return new Declaration(d.scope(), d.storage(), d.name(), value);
    }

    /**
     * A literal value robopro reads typed: numbers (signed), strings, booleans, aggregates of
     * these; for record types also a plain name (predefined or earlier data, e.g. z10).
     */
    private boolean isLiteral(Expr e, String type) {
        if (e instanceof RapidAst.Name n)
            return !type.equals("num") && !type.equals("bool") && !type.equals("string")
                    && (declaredValues.containsKey(n.name().toLowerCase(Locale.ROOT)) || predefinedValue(n.name()) != null);
        return pureLiteral(e);
    }

    private static boolean pureLiteral(Expr e) {
        if (e instanceof RapidAst.Num || e instanceof RapidAst.Str || e instanceof RapidAst.Bool) return true;
        if (e instanceof RapidAst.Unary u && (u.op().equals("-") || u.op().equals("+"))) return u.operand() instanceof RapidAst.Num;
        if (e instanceof RapidAst.Aggregate a) {
            for (Expr x : a.items()) if (!pureLiteral(x)) return false;
            return true;
        }
        return false;
    }

    // ---------------------------------------------------------------- statements

    private static final Set<String> MOVE_OPTIONS = Set.of("CONC", "NOEOFFS", "V", "T", "Z", "WOBJ");

    private Statement statement(RapidAst.Stmt s, String proc) {
        Statement out;
        try {
            out = typedStatement(s, proc);
        } catch (InputException | IllegalArgumentException bad) {
            if (strict) throw bad;
            out = new AstStatement(s);
        }
        nodes.put(out, s);
        return out;
    }

    private Statement typedStatement(RapidAst.Stmt s, String proc) {
        if (s instanceof RapidAst.CommentLine c) return new Comment(c.text());
        if (!(s instanceof RapidAst.Call c) || c.name() == null) return new AstStatement(s);
        String upper = c.name().toUpperCase(Locale.ROOT);
        switch (upper) {
            case "MOVEL", "MOVEJ", "MOVEC", "MOVEABSJ" -> {
                for (RapidAst.Arg a : c.args()) {
                    if (a.kind() == RapidAst.ArgKind.NAMED || a.kind() == RapidAst.ArgKind.CONDITIONAL) return new AstStatement(s);
                    if (a.kind() != RapidAst.ArgKind.POSITIONAL && !MOVE_OPTIONS.contains(a.name().toUpperCase(Locale.ROOT))) return new AstStatement(s);
                    if (a.value() != null && !(a.value() instanceof RapidAst.Name) && !pureLiteral(a.value())) return new AstStatement(s);
                    // a name of data the module holds untyped (a VAR robtarget without value, an array) stays untyped too
                    if (a.value() instanceof RapidAst.Name n && isUntypedData(n.name())) return new AstStatement(s);
                }
                Move.Kind kind = switch (upper) {
                    case "MOVEL" -> Move.Kind.MOVE_L;
                    case "MOVEJ" -> Move.Kind.MOVE_J;
                    case "MOVEC" -> Move.Kind.MOVE_C;
                    default -> Move.Kind.MOVE_ABS_J;
                };
                try {
                    return move(kind, c, proc);
                } catch (IllegalArgumentException bad) {
                    throw errAt(s, proc, bad.getMessage());
                }
            }
            case "WAITTIME" -> {
                if (c.args().size() == 1 && c.args().get(0).kind() == RapidAst.ArgKind.POSITIONAL && pureLiteral(c.args().get(0).value())) {
                    double sec = number(c.args().get(0).value(), proc + ": WaitTime");
                    if (sec < 0) throw err(c.args().get(0).value(), proc, "WaitTime needs a time >= 0");
                    return new WaitTime(sec);
                }
                return new AstStatement(s);
            }
            default -> {
                return c.args().isEmpty() ? new ProcCall(c.name()) : new AstStatement(s);
            }
        }
    }

    private boolean isUntypedData(String name) {
        String t = declaredTypes.get(name.toLowerCase(Locale.ROOT));
        return t != null && !declaredValues.containsKey(name.toLowerCase(Locale.ROOT));
    }

    @SuppressWarnings("unchecked")
    private Statement move(Move.Kind kind, RapidAst.Call c, String proc) {
        int base = kind == Move.Kind.MOVE_C ? 1 : 0; // MoveC has CirPoint before ToPoint
        int toIdx = base, speedIdx = base + 1, zoneIdx = base + 2, toolIdx = base + 3;
        List<RapidAst.Arg> pos = new ArrayList<>();
        for (RapidAst.Arg a : c.args()) if (a.kind() == RapidAst.ArgKind.POSITIONAL) pos.add(a);
        if (pos.size() != toolIdx + 1) {
            String sig = kind == Move.Kind.MOVE_C ? "CirPoint, ToPoint, Speed, Zone, Tool" : "ToPoint, Speed, Zone, Tool";
            throw errAt(c, proc, kind.rapidName() + " needs " + (toolIdx + 1) + " arguments (" + sig + "), found " + pos.size());
        }
        boolean conc = false, noEOffs = false;
        OptionalDouble v = OptionalDouble.empty(), t = OptionalDouble.empty(), z = OptionalDouble.empty();
        Optional<String> wobj = Optional.empty();
        int positional = 0;
        for (RapidAst.Arg a : c.args()) {
            if (a.kind() == RapidAst.ArgKind.POSITIONAL) { positional++; continue; }
            String n = a.name().toUpperCase(Locale.ROOT);
            int want = switch (n) {
                case "CONC" -> 0;
                case "NOEOFFS" -> kind == Move.Kind.MOVE_ABS_J ? toIdx + 1 : -1;
                case "V", "T" -> speedIdx + 1;
                case "Z" -> zoneIdx + 1;
                case "WOBJ" -> toolIdx + 1;
                default -> -1;
            };
            if (want < 0) throw errAt(a, proc, "optional argument \\" + a.name() + " of " + kind.rapidName() + " is not supported");
            if (positional != want) throw errAt(a, proc, "\\" + a.name() + " is not in its place in " + kind.rapidName());
            boolean isSwitch = n.equals("CONC") || n.equals("NOEOFFS");
            if (isSwitch != (a.value() == null))
                throw errAt(a, proc, "\\" + a.name() + (isSwitch ? " takes no value" : " needs a value (\\" + a.name() + ":=...)"));
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
        if (v.isPresent() && t.isPresent()) throw errAt(c, proc, "\\V and \\T exclude each other");
        Optional<Ref<RobTarget>> circ = Optional.empty();
        if (kind == Move.Kind.MOVE_C) circ = Optional.of((Ref<RobTarget>) (Ref<?>) targetRef(pos.get(0), "robtarget", proc));
        Ref<? extends RapidValue> to = targetRef(pos.get(toIdx), kind == Move.Kind.MOVE_ABS_J ? "jointtarget" : "robtarget", proc);
        Ref<SpeedData> speed = (Ref<SpeedData>) (Ref<?>) targetRef(pos.get(speedIdx), "speeddata", proc);
        Ref<ZoneData> zone = (Ref<ZoneData>) (Ref<?>) targetRef(pos.get(zoneIdx), "zonedata", proc);
        String tool = name(pos.get(toolIdx), proc, "tooldata");
        return new Move(kind, conc, circ, to, noEOffs, speed, v, t, zone, z, tool, wobj);
    }

    private double positive(RapidAst.Arg a, String proc, String what, double x) {
        if (!(x > 0)) throw errAt(a, proc, what + " must be > 0");
        return x;
    }

    private double nonNegative(RapidAst.Arg a, String proc, String what, double x) {
        if (!(x >= 0)) throw errAt(a, proc, what + " must be >= 0");
        return x;
    }

    /** A data argument: a name (type-checked when this module declares it) or an inline aggregate. */
    private Ref<?> targetRef(RapidAst.Arg a, String type, String proc) {
        Expr e = a.value();
        if (e instanceof RapidAst.Name n) {
            checkDeclaredType(n, type, proc);
            return Ref.to(n.name());
        }
        if (e instanceof RapidAst.Aggregate) return Ref.inline(convert(type, e, proc + ": inline " + type));
        throw errAt(a, proc, "expected a " + type + " name or [...] value, found " + describe(e));
    }

    private String name(RapidAst.Arg a, String proc, String type) {
        if (a.value() instanceof RapidAst.Name n) {
            checkDeclaredType(n, type, proc);
            return n.name();
        }
        throw errAt(a, proc, "expected the name of a " + type + ", found " + (a.value() == null ? "nothing" : describe(a.value())));
    }

    private void checkDeclaredType(RapidAst.Name n, String type, String proc) {
        String declared = declaredTypes.get(n.name().toLowerCase(Locale.ROOT));
        if (declared != null && !declared.equals(type))
            throw err(n, proc, "'" + n.name() + "' is a " + declared + ", a " + type + " is needed here");
    }

    /** References to data declared further down the file are checked once everything is read. */
    private void checkReferences(List<ModuleItem> items) {
        for (ModuleItem it : items)
            if (it instanceof Procedure p) for (Statement s : p.body())
                if (s instanceof Move mv) {
                    SourcePos at = ast.position(nodes.get(s)).orElse(null);
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
        if (declared != null && !declared.equals(type) && at != null)
            throw new InputException(file, at.line(), at.column(), proc, "'" + n + "' is a " + declared + ", a " + type + " is needed here");
    }

    private static String describe(Expr e) {
        if (e instanceof RapidAst.Num n) return "number " + n.text();
        if (e instanceof RapidAst.Bool b) return b.value() ? "TRUE" : "FALSE";
        if (e instanceof RapidAst.Str s) return "string \"" + s.raw() + "\"";
        if (e instanceof RapidAst.Name n) return "name " + n.name();
        if (e instanceof RapidAst.Aggregate a) return "aggregate of " + a.items().size();
        if (e instanceof RapidAst.FuncCall f) return "function call " + f.name() + "(...)";
        return "expression " + RapidAstWriter.expr(e);
    }

    // ---------------------------------------------------------------- values

    private RapidValue convert(String type, Expr e, String field) {
        try {
            return convertChecked(type, e, field);
        } catch (IllegalArgumentException bad) {
            // A model constructor refused a value the syntax allowed (e.g. an infinite sum of zones).
            if (bad instanceof NumberFormatException) throw bad;
            throw err(e, field, bad.getMessage());
        }
    }

    private RapidValue convertChecked(String type, Expr e, String field) {
        if (e instanceof RapidAst.Name n && !type.equals("num") && !type.equals("bool") && !type.equals("string")) {
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
        if (!(e instanceof RapidAst.Aggregate a)) throw err(e, field, "expected [...] with " + n + " components, found " + describe(e));
        if (a.items().size() != n) throw err(e, field, "expected " + n + " components, found " + a.items().size());
        return a.items();
    }

    private double number(Expr e, String field) {
        if (e instanceof RapidAst.Num n) return n.value();
        if (e instanceof RapidAst.Unary u && u.operand() instanceof RapidAst.Num n && (u.op().equals("-") || u.op().equals("+")))
            return u.op().equals("-") ? -n.value() : n.value();
        throw err(e, field, "expected a number, found " + describe(e));
    }

    private int integer(Expr e, String field) {
        double d = number(e, field);
        if (d != Math.rint(d) || Math.abs(d) > 1e6) throw err(e, field, "expected an integer, found " + d);
        return (int) d;
    }

    private boolean bool(Expr e, String field) {
        if (e instanceof RapidAst.Bool b) return b.value();
        throw err(e, field, "expected TRUE or FALSE, found " + describe(e));
    }

    private String string(Expr e, String field) {
        if (e instanceof RapidAst.Str s) return unescape(s, field);
        throw err(e, field, "expected a string, found " + describe(e));
    }

    /** The literal's string ({@link RapidAst.Str#value}), within RAPID's 80 ISO-8859-1 characters. */
    private String unescape(RapidAst.Str s, String field) {
        String v;
        try {
            v = s.value();
        } catch (IllegalArgumentException bad) {
            throw err(s, field, bad.getMessage());
        }
        if (v.length() > 80) throw err(s, field, "string longer than RAPID's 80 characters");
        for (int k = 0; k < v.length(); k++)
            if (v.charAt(k) > 0xFF) throw err(s, field, "string holds a character outside ISO-8859-1");
        return v;
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

    // ---------------------------------------------------------------- errors

    private InputException err(Object node, String field, String problem) {
        SourcePos p = pos(node);
        return new InputException(file, p.line(), p.column(), field, problem);
    }

    private InputException errAt(Object node, String field, String problem) { return err(node, field, problem); }
}
