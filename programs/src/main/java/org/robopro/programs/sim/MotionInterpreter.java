package org.robopro.programs.sim;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalDouble;
import java.util.Set;
import org.robopro.kinematics.Pose;
import org.robopro.kinematics.Units;
import org.robopro.models.InputException;
import org.robopro.models.SignalDescription;
import org.robopro.programs.JointTarget;
import org.robopro.programs.Move;
import org.robopro.programs.RapidModule;
import org.robopro.programs.RapidValue;
import org.robopro.programs.RobTarget;
import org.robopro.programs.SpeedData;
import org.robopro.programs.ToolData;
import org.robopro.programs.WObjData;
import org.robopro.programs.ZoneData;
import org.robopro.programs.rapid.ParsedAst;
import org.robopro.programs.ParsedModule;
import org.robopro.programs.rapid.RapidAst;
import org.robopro.programs.RapidParser;
import org.robopro.programs.rapid.SourcePos;
import org.robopro.programs.sim.Values.Arr;
import org.robopro.programs.sim.Values.Opaque;
import org.robopro.programs.sim.Values.Rec;
import org.robopro.programs.sim.Values.Typed;

/**
 * Runs a module's procedure the way the controller would step through it, without a robot,
 * and yields {@link ProgramStep}s with poses in base coordinates and SI speeds. It executes
 * RAPID's control flow (data of num, bool, string and record types, assignments, arithmetic,
 * IF, WHILE, FOR, TEST, GOTO, procedure and function calls with arguments, Offs, RelTool,
 * CRobT/CJointT as the last commanded position) and logs TPWrite, Stop and motion settings as
 * no-ops. What it cannot simulate (I/O, sockets, interrupts, error recovery) is an
 * {@link InputException} "not simulated: X" at the statement: a Move is never skipped. Every
 * run is bounded ({@link #MAX_STATEMENTS} statements), so a server's WHILE TRUE loop stops
 * with a clear message. Thread-safe (each run has its own state).
 */
public final class MotionInterpreter {
    /** Procedure calls nested deeper than this are taken as runaway recursion. */
    public static final int MAX_CALL_DEPTH = 32;
    /** Runs producing more steps than this are refused (nested calls can multiply). */
    public static final int MAX_STEPS = 1_000_000;
    /** Default bound on executed statements per run. */
    public static final int MAX_STATEMENTS = 200_000;
    /** RAPID functions reading a signal's value. */
    private static final Set<String> SIGNAL_READS = Set.of("DINPUT", "DOUTPUT", "AINPUT", "AOUTPUT", "GINPUT", "GOUTPUT", "TESTDI");

    /** The program: the module's syntax tree, and the trees of the task's other modules. */
    private final RapidAst.Module module;
    private final List<RapidAst.Module> libraries;
    private final String file;
    /** Syntax trees of the module and its parsed libraries (positions for messages). */
    private final List<ParsedAst> asts;
    private final int maxStatements;
    /** Where the robot stands when the run starts (CJointT before any move); null: unknown. */
    private final JointTarget startJoints;
    /** The cell's I/O signals (empty: every signal a program names is taken as it comes, inputs at 0). */
    private final List<SignalDescription> signals;
    /** Unknown instructions are errors (a controller refuses such a program) instead of notices. */
    private final boolean strict;

    private MotionInterpreter(RapidAst.Module module, List<RapidAst.Module> libraries, String file, List<ParsedAst> asts, int maxStatements, JointTarget startJoints, List<SignalDescription> signals,
                              boolean strict) {
        this.signals = List.copyOf(signals);
        this.strict = strict;
        this.module = module;
        this.libraries = List.copyOf(libraries);
        this.file = file;
        this.asts = List.copyOf(asts);
        this.maxStatements = maxStatements;
        this.startJoints = startJoints;
    }

    /**
     * An interpreter of a module's syntax tree ({@link RapidModule#tree()}; no positions: errors
     * name the module); {@code libraries} provide data declared elsewhere (e.g. tools in user.sys).
     */
    public static MotionInterpreter of(RapidModule module, RapidModule... libraries) {
        return new MotionInterpreter(module.tree(), trees(libraries), module.name(), List.of(), MAX_STATEMENTS, null,
                List.of(), false);
    }

    /** An interpreter of a parsed file: errors name the file, line and column. */
    public static MotionInterpreter of(ParsedModule parsed, RapidModule... libraries) { return of(parsed.ast(), libraries); }

    /** An interpreter of a syntax tree read from a file: errors name the file, line and column. */
    public static MotionInterpreter of(ParsedAst parsed, RapidModule... libraries) {
        return new MotionInterpreter(parsed.module(), trees(libraries), parsed.file(), List.of(parsed), MAX_STATEMENTS, null, List.of(), false);
    }

    private static List<RapidAst.Module> trees(RapidModule... modules) {
        List<RapidAst.Module> out = new ArrayList<>();
        for (RapidModule m : modules) out.add(m.tree());
        return out;
    }

    /**
     * An interpreter of a task's parsed modules: {@code main} runs, {@code others} (e.g. system
     * modules) provide data, records and routines; errors inside any of them name its file,
     * line and column.
     */
    public static MotionInterpreter ofTask(ParsedModule main, List<ParsedModule> others) {
        List<ParsedModule> all = new ArrayList<>();
        all.add(main);
        all.addAll(others);
        return new MotionInterpreter(main.ast().module(), others.stream().map(o -> o.ast().module()).toList(), main.file(),
                all.stream().map(ParsedModule::ast).toList(), MAX_STATEMENTS, null, List.of(), false);
    }

    /** The same interpreter with another bound on executed statements. */
    public MotionInterpreter withMaxStatements(int max) {
        if (max < 1) throw new IllegalArgumentException("max statements must be >= 1: " + max);
        return new MotionInterpreter(module, libraries, file, asts, max, startJoints, signals, strict);
    }

    /**
     * The same interpreter with the robot standing at {@code joints} when the run starts, so
     * {@code CJointT()} before any move returns it (a server reads its start position this way).
     */
    public MotionInterpreter withStartJoints(JointTarget joints) {
        if (joints == null) throw new IllegalArgumentException("start joints must not be null");
        return new MotionInterpreter(module, libraries, file, asts, maxStatements, joints, signals, strict);
    }

    /**
     * The same interpreter with the cell's I/O signal table: signals read in conditions start at
     * their table value; a signal the program names that is not in the table is a notice.
     */
    public MotionInterpreter withSignals(List<SignalDescription> table) {
        return new MotionInterpreter(module, libraries, file, asts, maxStatements, startJoints, table, strict);
    }

    /**
     * The same interpreter refusing what it does not know, as a controller refuses to start a
     * program naming a routine it does not have: an unknown instruction is an
     * {@link InputException} "not simulated: X at line:col" instead of a notice.
     */
    public MotionInterpreter strict() {
        return new MotionInterpreter(module, libraries, file, asts, maxStatements, startJoints, signals, true);
    }

    /** The signal table this interpreter runs with. */
    public List<SignalDescription> signals() { return signals; }

    /** The steps of running {@code main}. */
    public List<ProgramStep> run() { return run("main"); }

    /** The steps of running procedure {@code entry}. */
    public List<ProgramStep> run(String entry) { return simulate(entry).steps(); }

    /** Steps and the log of no-op instructions of running {@code entry}. */
    public Simulation simulate(String entry) {
        Run r = new Run();
        Object p = r.routine(entry);
        if (p == null) throw new InputException(file, 0, 0, entry, "no procedure " + entry + " in module " + module.name());
        try {
            r.call(p, entry, List.of(), null, null, 0);
        } catch (ExitSignal done) {
            // EXIT / ExitCycle: the program ends here
        }
        return new Simulation(r.out, r.log, r.notices);
    }

    /** Only the motions of running {@code entry}. */
    public List<MoveStep> moves(String entry) {
        List<MoveStep> out = new ArrayList<>();
        for (ProgramStep s : run(entry)) if (s instanceof MoveStep m) out.add(m);
        return out;
    }

    // ---------------------------------------------------------------- control signals

    private static final class ExitSignal extends RuntimeException {
        ExitSignal() { super(null, null, false, false); }
    }

    private static final class ReturnSignal extends RuntimeException {
        final Object value;
        ReturnSignal(Object value) { super(null, null, false, false); this.value = value; }
    }

    private static final class GotoSignal extends RuntimeException {
        final String label;
        final Object at;
        GotoSignal(String label, Object at) { super(null, null, false, false); this.label = label; this.at = at; }
    }

    /** A variable: its declared type (lower case, null when unknown) and value; shared for INOUT/VAR/PERS arguments. */
    private static final class Var {
        final String type;
        Object value;
        final boolean constant;
        Var(String type, Object value, boolean constant) { this.type = type; this.value = value; this.constant = constant; }
    }

    /** One procedure or function activation: its data and parameters; absent optional parameters are missing. */
    private static final class Frame {
        final String routine;
        final Map<String, Var> vars = new HashMap<>();
        final java.util.Set<String> optionalParams = new java.util.HashSet<>();
        Frame(String routine) { this.routine = routine; }
    }

    // ---------------------------------------------------------------- one run

    private final class Run {
        final List<ProgramStep> out = new ArrayList<>();
        final List<String> log = new ArrayList<>();
        final List<Simulation.Notice> notices = new ArrayList<>();
        /** Instructions already reported as not simulated (each once). */
        final java.util.Set<String> noticed = new java.util.HashSet<>();
        /** Call sites and loop iterations leading to the running statement, outermost first. */
        final java.util.ArrayDeque<String> ctx = new java.util.ArrayDeque<>();
        /** The cell's signals by lower-case name, and the value each has as far as the program can tell. */
        final Map<String, SignalDescription> table = new HashMap<>();
        final Map<String, Double> signalValues = new HashMap<>();
        final Map<String, String> signalNames = new HashMap<>();
        /** TriggIO/TriggEquip definitions by lower-case triggdata name. */
        final Map<String, List<IoStep>> triggers = new HashMap<>();
        boolean arcOn;
        final Map<String, Var> globals = new HashMap<>();
        final Map<String, List<Values.FieldDef>> records = new HashMap<>(Values.BUILTIN);
        final Map<String, String> aliases = new HashMap<>();
        final Map<String, Object> routines = new HashMap<>();
        long executed;
        /** The loop statement executing most recently (named when the statement bound is hit). */
        Object lastLoop;
        Object lastRobTarget;
        Object lastJointTarget;
        int depth;

        Run() {
            for (SignalDescription d : signals) {
                table.put(d.key(), d);
                signalValues.put(d.key(), d.value());
                signalNames.put(d.key(), d.name());
            }
            if (startJoints != null) {
                currentJoint = new Typed(startJoints);
                lastJointTarget = currentJoint;
            }
            List<RapidAst.Module> all = new ArrayList<>();
            all.add(module);
            all.addAll(libraries);
            // Record types and routines first: data initialisers may use them.
            for (RapidAst.Module m : all)
                for (RapidAst.Item it : m.items()) {
                    if (it instanceof RapidAst.Routine r) routines.putIfAbsent(Values.lower(r.name()), r);
                    else if (it instanceof RapidAst.RecordDecl rd) {
                        List<Values.FieldDef> fs = new ArrayList<>();
                        for (RapidAst.Field f : rd.fields()) fs.add(new Values.FieldDef(f.name(), Values.lower(f.type())));
                        records.putIfAbsent(Values.lower(rd.name()), fs);
                    } else if (it instanceof RapidAst.AliasDecl al)
                        aliases.putIfAbsent(Values.lower(al.name()), Values.lower(al.type()));
                }
            Frame none = new Frame(module.name());
            for (RapidAst.Module m : all)
                for (RapidAst.Item it : m.items())
                    if (it instanceof RapidAst.DataDecl dd && !globals.containsKey(Values.lower(dd.name()))) {
                        Var v = typedDeclaration(dd);
                        globals.put(Values.lower(dd.name()), v != null ? v : declare(dd, none));
                    }
        }

        /**
         * Module data of a RAPID data type robopro models (robtarget, tooldata, speeddata, ...)
         * with a literal value, read once as its typed value (so each motion naming it does not
         * convert it again); null for anything else, which {@link #declare} evaluates.
         */
        Var typedDeclaration(RapidAst.DataDecl d) {
            String type = base(d.type());
            if (d.init() == null || !d.dims().isEmpty() || !RapidParser.TYPES.contains(type)
                    || type.equals("num") || type.equals("bool") || type.equals("string")
                    || !(d.init() instanceof RapidAst.Aggregate || d.init() instanceof RapidAst.Name)) return null;
            try {
                return new Var(type, new Typed(RapidParser.literalValue(type, d.init(), file, d.name())), d.storage() == RapidAst.Storage.CONST);
            } catch (IllegalArgumentException | InputException notLiteral) {
                return null; // computed, or naming other data: evaluated as written
            }
        }

        Object routine(String name) { return routines.get(Values.lower(name)); }

        String context() { return ctx.isEmpty() ? "" : String.join(" > ", ctx); }

        String stepLabel(String proc, int index, String what) {
            String c = context();
            return (c.isEmpty() ? "" : c + " > ") + proc + "#" + (index + 1) + " " + what;
        }

        /** Reports {@code message} once per {@code key} (e.g. once per unknown instruction). */
        void notice(String key, String step, Object at, String message) {
            if (noticed.add(Values.lower(key))) notices.add(new Simulation.Notice(step, source(at), message));
        }

        String base(String type) {
            String t = Values.lower(type);
            for (int k = 0; k < 8 && aliases.containsKey(t); k++) t = aliases.get(t);
            return Values.NUM_ALIASES.contains(t) ? "num" : t;
        }

        Var declare(RapidAst.DataDecl d, Frame f) {
            String type = base(d.type());
            Object v;
            List<Integer> dims = new ArrayList<>();
            for (RapidAst.Expr e : d.dims()) dims.add(index(eval(e, f), e));
            if (d.init() != null) v = coerce(eval(d.init(), f), type, dims, d.init());
            else v = zero(type, dims, 0);
            return new Var(type, v, d.storage() == RapidAst.Storage.CONST);
        }

        Object zero(String type, List<Integer> dims, int k) {
            if (k < dims.size()) {
                Object[] items = new Object[dims.get(k)];
                for (int n = 0; n < items.length; n++) items[n] = zero(type, dims, k + 1);
                return new Arr(items);
            }
            String t = base(type);
            if (t.equals("num")) return 0.0;
            if (t.equals("bool")) return false;
            if (t.equals("string")) return "";
            List<Values.FieldDef> fs = records.get(t);
            if (fs == null) return new Opaque(t);
            Object[] f = new Object[fs.size()];
            for (int n = 0; n < f.length; n++) f[n] = zero(fs.get(n).type(), List.of(), 0);
            return new Rec(t, f);
        }

        /** Gives an aggregate its declared type (recursively), checks sizes. */
        Object coerce(Object v, String type, List<Integer> dims, Object at) {
            String t = base(type);
            if (!dims.isEmpty()) {
                Object[] items = v instanceof Arr a ? a.items : v instanceof Rec r && r.type == null ? r.f : null;
                if (items == null || items.length != dims.get(0)) throw error(at, "expected an array of " + dims.get(0) + " " + t + ", found " + Values.describe(v));
                Object[] out = new Object[items.length];
                for (int n = 0; n < items.length; n++) out[n] = coerce(items[n], t, dims.subList(1, dims.size()), at);
                return new Arr(out);
            }
            if (v instanceof Typed ty) {
                if (!ty.value().rapidType().equals(t) && records.containsKey(t)) throw error(at, "a " + t + " is needed, found a " + ty.value().rapidType());
                return v;
            }
            if (v instanceof Rec r && records.containsKey(t)) {
                List<Values.FieldDef> fs = records.get(t);
                if (r.type != null && !r.type.equals(t)) throw error(at, "a " + t + " is needed, found a " + r.type);
                if (r.f.length != fs.size()) throw error(at, "a " + t + " has " + fs.size() + " components, found " + r.f.length);
                Object[] f = new Object[r.f.length];
                for (int n = 0; n < f.length; n++) f[n] = coerce(r.f[n], fs.get(n).type(), List.of(), at);
                return new Rec(t, f);
            }
            if (t.equals("num") && !(v instanceof Double)) throw error(at, "a num is needed, found " + Values.describe(v));
            if (t.equals("bool") && !(v instanceof Boolean)) throw error(at, "a bool is needed, found " + Values.describe(v));
            if (t.equals("string") && !(v instanceof String)) throw error(at, "a string is needed, found " + Values.describe(v));
            return Values.copy(v);
        }

        // ------------------------------------------------------------ calls

        void call(Object routine, String name, List<RapidAst.Arg> args, Frame caller, Object at, int callDepth) {
            if (callDepth > MAX_CALL_DEPTH) throw error(at, "procedure calls nested deeper than " + MAX_CALL_DEPTH + " (recursion?)");
            RapidAst.Routine r = (RapidAst.Routine) routine;
            if (r.kind() != RapidAst.RoutineKind.PROC) throw error(at, r.name() + " is a " + r.kind() + ", not a procedure");
            Frame f = bind(r, args, caller, at);
            runAst(r, f, callDepth);
        }

        Object runAst(RapidAst.Routine r, Frame f, int callDepth) {
            int saved = depth;
            depth = callDepth;
            try {
                execAstList(r.body(), f);
                if (r.kind() == RapidAst.RoutineKind.FUNC) throw error(r, "function " + r.name() + " ended without RETURN");
                return null;
            } catch (ReturnSignal ret) {
                return ret.value;
            } catch (GotoSignal g) {
                throw error(g.at, "GOTO " + g.label + ": no such label in " + r.name());
            } finally {
                depth = saved;
            }
        }

        Frame bind(RapidAst.Routine r, List<RapidAst.Arg> args, Frame caller, Object at) {
            Frame f = new Frame(r.name());
            List<RapidAst.ParamAlt> required = new ArrayList<>();
            Map<String, RapidAst.ParamAlt> optional = new HashMap<>();
            Map<String, RapidAst.ParamAlt> byName = new HashMap<>();
            for (RapidAst.Param p : r.params()) {
                for (RapidAst.ParamAlt a : p.alternatives()) {
                    byName.put(Values.lower(a.name()), a);
                    if (p.optional()) { optional.put(Values.lower(a.name()), a); f.optionalParams.add(Values.lower(a.name())); }
                }
                if (!p.optional()) required.add(p.alternatives().get(0));
            }
            int next = 0;
            for (RapidAst.Arg a : args) {
                RapidAst.ParamAlt p;
                switch (a.kind()) {
                    case POSITIONAL -> {
                        if (next >= required.size()) throw error(at, "too many arguments for " + r.name());
                        p = required.get(next++);
                    }
                    case NAMED -> {
                        p = byName.get(Values.lower(a.name()));
                        if (p == null || optional.containsKey(Values.lower(a.name()))) throw error(at, r.name() + " has no required parameter " + a.name());
                        next = Math.max(next, required.indexOf(p) + 1);
                    }
                    default -> {
                        p = optional.get(Values.lower(a.name()));
                        if (p == null) throw error(at, r.name() + " has no optional parameter \\" + a.name());
                    }
                }
                if (a.kind() == RapidAst.ArgKind.SWITCH) {
                    f.vars.put(Values.lower(p.name()), new Var("switch", true, true));
                    continue;
                }
                if (a.kind() == RapidAst.ArgKind.CONDITIONAL) {
                    String src = Values.lower(((RapidAst.Name) a.value()).name());
                    Var v = caller == null ? null : caller.vars.get(src);
                    if (v != null) f.vars.put(Values.lower(p.name()), v);
                    continue;
                }
                boolean byRef = p.mode() != null && a.value() instanceof RapidAst.Name;
                Var v;
                if (byRef) {
                    v = variable(((RapidAst.Name) a.value()).name(), caller, a.value());
                    if (v.value instanceof Typed t) v.value = Values.untyped(t.value());
                } else {
                    Object val = eval(a.value(), caller);
                    v = new Var(base(p.type()), p.arrayDims() > 0 ? Values.copy(val) : coerce(val, p.type(), List.of(), a.value()), false);
                }
                f.vars.put(Values.lower(p.name()), v);
            }
            if (next < required.size()) throw error(at, r.name() + " needs the argument " + required.get(next).name());
            return f;
        }

        // ------------------------------------------------------------ statements

        void tick(Object at) {
            if (++executed > maxStatements) {
                String loop = lastLoop == null ? "" : " (a loop at " + where(lastLoop) + " never ended?)";
                throw error(at, "simulation stopped after " + maxStatements + " statements" + loop);
            }
            if (out.size() >= MAX_STEPS) throw error(at, "program runs more than " + MAX_STEPS + " steps");
        }

        void execAstList(List<RapidAst.Stmt> body, Frame f) {
            int k = 0;
            while (k < body.size()) {
                try {
                    RapidAst.Stmt s = body.get(k);
                    if (!(s instanceof RapidAst.CommentLine)) {
                        tick(s);
                        exec(s, f, s, f.routine, k);
                    }
                    k++;
                } catch (GotoSignal g) {
                    int target = -1;
                    for (int n = 0; n < body.size(); n++)
                        if (body.get(n) instanceof RapidAst.Label l && l.name().equalsIgnoreCase(g.label)) target = n;
                    if (target < 0) throw g;
                    k = target;
                }
            }
        }

        /** A branch of an IF or TEST at statement {@code index}: its statements are labelled inside that statement. */
        void nested(List<RapidAst.Stmt> body, Frame f, String proc, int index) {
            ctx.addLast(proc + "#" + (index + 1));
            try {
                execAstList(body, f);
            } finally {
                ctx.removeLast();
            }
        }

        /** One syntax-tree statement; {@code at} locates it, {@code index} is its place in the procedure body for step labels. */
        void exec(RapidAst.Stmt s, Frame f, Object at, String proc, int index) {
            if (s instanceof RapidAst.CommentLine || s instanceof RapidAst.Label) return;
            if (s instanceof RapidAst.DataDecl d) { f.vars.put(Values.lower(d.name()), declare(d, f)); return; }
            if (s instanceof RapidAst.Assign a) { assign(a.target(), eval(a.value(), f), f, at); return; }
            if (s instanceof RapidAst.Call c) {
                if (c.name() == null) {
                    Object n = eval(c.lateBinding(), f);
                    if (!(n instanceof String name)) throw error(at, "late binding needs a string, found " + Values.describe(n));
                    callNamed(name, c.args(), f, at, proc, index);
                } else {
                    callNamed(c.name(), c.args(), f, at, proc, index);
                }
                return;
            }
            if (s instanceof RapidAst.If i) {
                if (bool(eval(i.condition(), f), i.condition())) { nested(i.then(), f, proc, index); return; }
                for (RapidAst.ElseIf e : i.elseIfs())
                    if (bool(eval(e.condition(), f), e.condition())) { nested(e.body(), f, proc, index); return; }
                if (i.otherwise() != null) nested(i.otherwise(), f, proc, index);
                return;
            }
            if (s instanceof RapidAst.CompactIf ci) {
                if (bool(eval(ci.condition(), f), ci.condition())) exec(ci.stmt(), f, at, proc, index);
                return;
            }
            if (s instanceof RapidAst.While w) {
                int pass = 0;
                while (bool(eval(w.condition(), f), w.condition())) {
                    lastLoop = at;
                    tick(at);
                    ctx.addLast(proc + "#" + (index + 1) + "[pass " + (++pass) + "]");
                    try {
                        execAstList(w.body(), f);
                    } finally {
                        ctx.removeLast();
                    }
                }
                return;
            }
            if (s instanceof RapidAst.For fo) {
                double from = num(eval(fo.from(), f), fo.from()), to = num(eval(fo.to(), f), fo.to());
                double step = fo.step() == null ? (from <= to ? 1 : -1) : num(eval(fo.step(), f), fo.step());
                if (step == 0) throw error(at, "FOR with STEP 0 never ends");
                Var v = new Var("num", from, false);
                Var saved = f.vars.put(Values.lower(fo.variable()), v);
                try {
                    for (double x = from; step > 0 ? x <= to : x >= to; x += step) {
                        v.value = x;
                        lastLoop = at;
                        tick(at);
                        ctx.addLast(proc + "#" + (index + 1) + "[" + fo.variable() + "=" + fmt(x) + "]");
                        try {
                            execAstList(fo.body(), f);
                        } finally {
                            ctx.removeLast();
                        }
                    }
                } finally {
                    if (saved != null) f.vars.put(Values.lower(fo.variable()), saved);
                    else f.vars.remove(Values.lower(fo.variable()));
                }
                return;
            }
            if (s instanceof RapidAst.Test t) {
                Object v = eval(t.value(), f);
                for (RapidAst.Case c : t.cases())
                    for (RapidAst.Expr e : c.values())
                        if (same(v, eval(e, f))) { nested(c.body(), f, proc, index); return; }
                if (t.otherwise() != null) nested(t.otherwise(), f, proc, index);
                return;
            }
            if (s instanceof RapidAst.Goto g) throw new GotoSignal(g.label(), at);
            if (s instanceof RapidAst.Return r) throw new ReturnSignal(r.value() == null ? null : eval(r.value(), f));
            if (s instanceof RapidAst.Exit) throw new ExitSignal();
            if (s instanceof RapidAst.Raise) throw error(at, "not simulated: RAISE (error recovery) at " + where(at));
            if (s instanceof RapidAst.Retry || s instanceof RapidAst.TryNext)
                throw error(at, "not simulated: " + (s instanceof RapidAst.Retry ? "RETRY" : "TRYNEXT") + " (error recovery) at " + where(at));
            if (s instanceof RapidAst.Connect) throw error(at, "not simulated: CONNECT (interrupts) at " + where(at));
            throw error(at, "not simulated: " + s.getClass().getSimpleName() + " at " + where(at));
        }

        void callNamed(String name, List<RapidAst.Arg> args, Frame f, Object at, String proc, int index) {
            Object r = routine(name);
            if (r != null) {
                ctx.addLast(proc + "#" + (index + 1));
                try {
                    call(r, name, args, f, at, depth + 1);
                } finally {
                    ctx.removeLast();
                }
                return;
            }
            String up = name.toUpperCase(Locale.ROOT);
            if (io(up, name, args, f, at, proc, index)) return;
            switch (up) {
                case "MOVEL", "MOVEJ", "MOVEC", "MOVEABSJ" -> {
                    MoveStep step = astMove(up, args, f, at, proc, index);
                    remember(step);
                    out.add(step);
                }
                case "WAITTIME" -> {
                    double sec = -1;
                    for (RapidAst.Arg a : args) if (a.kind() == RapidAst.ArgKind.POSITIONAL) sec = num(eval(a.value(), f), a.value());
                    if (!(sec >= 0)) throw error(at, "WaitTime needs a time >= 0");
                    out.add(new WaitStep(proc, index, source(at), sec, context(), statementOf(at)));
                }
                case "TPWRITE", "TPERASE", "STOP", "BREAK", "CONFJ", "CONFL", "SINGAREA", "VELSET", "ACCSET", "PATHACCLIM",
                        "ERRWRITE", "TPSHOW", "STOPMOVE", "STARTMOVE", "CLEARPATH", "WAITROB" -> {
                    StringBuilder b = new StringBuilder(name);
                    for (RapidAst.Arg a : args)
                        if (a.value() != null) {
                            try {
                                Object v = eval(a.value(), f);
                                b.append(' ').append(v instanceof String str ? "\"" + str + "\"" : v instanceof Double d ? fmt(d) : Values.describe(v));
                            } catch (InputException e) {
                                b.append(" ?");
                            }
                        }
                    log.add(b + " (not simulated, no motion) at " + where(at));
                }
                case "WAITUNTIL" -> {
                    // Nothing else runs in the simulation: a false condition would wait forever.
                    RapidAst.Expr cond = args.stream().filter(a -> a.kind() == RapidAst.ArgKind.POSITIONAL).map(RapidAst.Arg::value)
                            .findFirst().orElseThrow(() -> error(at, "WaitUntil needs a condition"));
                    if (bool(eval(cond, f), cond)) {
                        log.add(name + " (condition true, not simulated) at " + where(at));
                    } else {
                        // A wait for one signal is placed on the I/O time line by the path check; any other
                        // condition cannot change in the simulation and is reported there as assumed true.
                        String[] sv = signalCondition(cond);
                        double max = optionalNum(args, "MAXTIME", f, Double.POSITIVE_INFINITY);
                        setTimeFlag(args, f, at);
                        if (sv != null) {
                            double value = Double.parseDouble(sv[1]);
                            out.add(ioStep(proc, index, at, IoStep.Kind.WAIT_SIGNAL, name, signal(sv[0], null, name, at, proc, index), value, max, ""));
                            setSignal(sv[0], value);
                        } else {
                            out.add(ioStep(proc, index, at, IoStep.Kind.WAIT_CONDITION, name, "", 0, max,
                                    org.robopro.programs.rapid.RapidAstWriter.expr(cond)));
                        }
                    }
                }
                case "EXITCYCLE" -> throw new ExitSignal();
                case "INCR", "DECR", "ADD", "CLEAR" -> {
                    RapidAst.Expr target = args.isEmpty() ? null : args.get(0).value();
                    if (target == null) throw error(at, name + " needs a num variable");
                    double v = num(eval(target, f), target);
                    double nv = switch (up) {
                        case "INCR" -> v + 1;
                        case "DECR" -> v - 1;
                        case "CLEAR" -> 0;
                        default -> {
                            if (args.size() < 2) throw error(at, "Add needs a value");
                            yield v + num(eval(args.get(1).value(), f), args.get(1).value());
                        }
                    };
                    assign(target, nv, f, at);
                }
                default -> {
                    if (strict)
                        throw error(at, "not simulated: " + name + " at " + where(at) + " (no such PROC in the module; sockets and other system instructions are not simulated)");
                    // Kept in the program as written; the run goes on without it.
                    notice(name, stepLabel(proc, index, name), at, "not simulated: " + name + " at " + where(at)
                            + " (no such PROC in the module and not an instruction robopro simulates; kept as written)");
                    log.add(name + " (not simulated) at " + where(at));
                }
            }
        }

        private static final Set<String> ARC_PASSIVE = Set.of("ON", "WEAVE", "TRACK", "SEAMNAME", "CORR", "PREPROCESSTRACKING", "SEAM", "DECEL");
        private static final Set<String> TRIGG_PASSIVE = Set.of("T2", "T3", "T4", "T5", "T6", "T7", "T8", "CORR", "MODE");

        /** I/O, trigger and arc-welding instructions; false when {@code up} is none of them. */
        boolean io(String up, String name, List<RapidAst.Arg> args, Frame f, Object at, String proc, int index) {
            List<RapidAst.Arg> pos = args.stream().filter(a -> a.kind() == RapidAst.ArgKind.POSITIONAL || a.kind() == RapidAst.ArgKind.NAMED).toList();
            switch (up) {
                case "SETDO", "SETAO", "SETGO" -> {
                    if (pos.size() != 2) throw error(at, name + " needs a signal and a value");
                    SignalDescription.Type type = up.equals("SETDO") ? SignalDescription.Type.DO
                            : up.equals("SETAO") ? SignalDescription.Type.AO : SignalDescription.Type.GO;
                    double v = num(eval(pos.get(1).value(), f), pos.get(1).value());
                    if (type == SignalDescription.Type.DO && v != 0 && v != 1) throw error(at, name + " sets 0 or 1, found " + fmt(v));
                    if (!Double.isFinite(v)) throw error(at, name + " needs a finite value");
                    double delay = optionalNum(args, "SDELAY", f, 0);
                    if (!(delay >= 0) || !Double.isFinite(delay)) throw error(at, "\\SDelay must be a finite time >= 0");
                    String sig = signal(signalName(pos.get(0), at), type, name, at, proc, index);
                    out.add(ioStep(proc, index, at, IoStep.Kind.SET, name, sig, v, delay, ""));
                    setSignal(sig, v);
                }
                case "SET", "RESET", "INVERTDO" -> {
                    if (pos.size() != 1) throw error(at, name + " needs a signal");
                    String sig = signal(signalName(pos.get(0), at), SignalDescription.Type.DO, name, at, proc, index);
                    double v = up.equals("SET") ? 1 : up.equals("RESET") ? 0 : 1 - signalValues.getOrDefault(Values.lower(sig), 0.0);
                    out.add(ioStep(proc, index, at, IoStep.Kind.SET, name, sig, v, 0, ""));
                    setSignal(sig, v);
                }
                case "PULSEDO" -> {
                    if (pos.size() != 1) throw error(at, name + " needs a signal");
                    // ABB RAPID reference, PulseDO: \PLength 0.001..2000 s, default 0.2 s.
                    double length = optionalNum(args, "PLENGTH", f, 0.2);
                    if (!(length > 0) || !Double.isFinite(length)) throw error(at, "\\PLength must be a finite time > 0");
                    String sig = signal(signalName(pos.get(0), at), SignalDescription.Type.DO, name, at, proc, index);
                    out.add(ioStep(proc, index, at, IoStep.Kind.PULSE, name, sig, 1, length, ""));
                }
                case "WAITDI", "WAITDO" -> {
                    if (pos.size() != 2) throw error(at, name + " needs a signal and a value");
                    double v = num(eval(pos.get(1).value(), f), pos.get(1).value());
                    if (v != 0 && v != 1) throw error(at, name + " waits for 0 or 1, found " + fmt(v));
                    double max = optionalNum(args, "MAXTIME", f, Double.POSITIVE_INFINITY);
                    String sig = signal(signalName(pos.get(0), at), up.equals("WAITDI") ? SignalDescription.Type.DI : SignalDescription.Type.DO,
                            name, at, proc, index);
                    setTimeFlag(args, f, at);
                    out.add(ioStep(proc, index, at, IoStep.Kind.WAIT_SIGNAL, name, sig, v, max, ""));
                    setSignal(sig, v);
                }
                case "TRIGGIO", "TRIGGEQUIP" -> {
                    int need = up.equals("TRIGGIO") ? 3 : 4;
                    if (pos.size() != need) throw error(at, name + " needs " + need + " arguments, found " + pos.size());
                    String data = signalName(pos.get(0), at);
                    double amount = num(eval(pos.get(1).value(), f), pos.get(1).value());
                    double value = num(eval(pos.get(need - 1).value(), f), pos.get(need - 1).value());
                    boolean time = false, start = false;
                    String sig = null;
                    SignalDescription.Type type = SignalDescription.Type.DO;
                    for (RapidAst.Arg a : args) {
                        if (a.kind() == RapidAst.ArgKind.POSITIONAL || a.kind() == RapidAst.ArgKind.NAMED) continue;
                        String n = a.name().toUpperCase(Locale.ROOT);
                        if (n.equals("TIME")) time = true;
                        else if (n.equals("START")) start = true;
                        else if (n.equals("DOP") || n.equals("GOP") || n.equals("AOP")) {
                            sig = signalName(a, at);
                            type = n.equals("DOP") ? SignalDescription.Type.DO : n.equals("GOP") ? SignalDescription.Type.GO : SignalDescription.Type.AO;
                        }
                    }
                    if (sig == null) {
                        notice(name + " without signal", stepLabel(proc, index, name), at, "not simulated: " + name + " at " + where(at)
                                + " without \\DOp, \\GOp or \\AOp (a process trigger); kept as written");
                        triggers.put(Values.lower(data), List.of());
                        return true;
                    }
                    if (!(amount >= 0) || !Double.isFinite(amount)) throw error(at, name + " distance/time must be finite and >= 0");
                    if (time && start) throw error(at, name + ": \\Time counts back from the end, it does not go with \\Start");
                    sig = signal(sig, type, name, at, proc, index);
                    String lag = up.equals("TRIGGEQUIP") ? "EquipLag " + fmt(num(eval(pos.get(2).value(), f), pos.get(2).value())) + " s" : "";
                    // A definition only: it fires when a TriggL/TriggJ/TriggC names it.
                    triggers.put(Values.lower(data), List.of(new IoStep(proc, index, source(at), context(), IoStep.Kind.TRIGGER, name, sig, value,
                            time ? amount : amount / 1000, Optional.of(new IoStep.Trigger(start, time)), lag, statementOf(at))));
                }
                case "TRIGGL", "TRIGGJ", "TRIGGC" -> {
                    Move.Kind kind = up.equals("TRIGGL") ? Move.Kind.MOVE_L : up.equals("TRIGGJ") ? Move.Kind.MOVE_J : Move.Kind.MOVE_C;
                    List<RapidAst.Arg> extra = new ArrayList<>();
                    MoveStep step = motion(name, kind, 1, TRIGG_PASSIVE, args, f, at, proc, index, extra);
                    remember(step);
                    out.add(step);
                    for (RapidAst.Arg a : extra) {
                        if (a.value() == null || a.name() != null && !a.name().toUpperCase(Locale.ROOT).matches("T[2-8]")
                                && a.kind() != RapidAst.ArgKind.POSITIONAL && a.kind() != RapidAst.ArgKind.NAMED) continue;
                        String data = signalName(a, at);
                        List<IoStep> defs = triggers.get(Values.lower(data));
                        if (defs == null) {
                            notice("trigger " + data, step.label(), at, "trigger data " + data + " is used at " + where(at)
                                    + " before any TriggIO or TriggEquip defines it: nothing fires");
                            continue;
                        }
                        for (IoStep d : defs) {
                            out.add(new IoStep(proc, index, source(at), context(), IoStep.Kind.TRIGGER, name, d.signal(), d.value(), d.seconds(),
                                    d.trigger(), (data + " " + d.text()).trim(), statementOf(at)));
                            setSignal(d.signal(), d.value());
                        }
                    }
                }
                case "ARCLSTART", "ARCL", "ARCLEND", "ARCCSTART", "ARCC", "ARCCEND" -> {
                    Move.Kind kind = up.startsWith("ARCC") ? Move.Kind.MOVE_C : Move.Kind.MOVE_L;
                    List<RapidAst.Arg> extra = new ArrayList<>();
                    MoveStep step = motion(name, kind, 2, ARC_PASSIVE, args, f, at, proc, index, extra);
                    String data = extra.stream().filter(a -> a.kind() == RapidAst.ArgKind.POSITIONAL || a.kind() == RapidAst.ArgKind.NAMED)
                            .map(a -> label(a.value())).collect(java.util.stream.Collectors.joining(", "));
                    boolean flyingStart = extra.stream().anyMatch(a -> a.name() != null && a.name().equalsIgnoreCase("On"));
                    boolean start = up.endsWith("START"), end = up.endsWith("END");
                    if (flyingStart && !arcOn) {
                        out.add(ioStep(proc, index, at, IoStep.Kind.ARC_ON, name, "", 1, 0, data));
                        arcOn = true;
                    }
                    if (!start && !arcOn)
                        notice("arc off " + where(at), step.label(), at, name + " at " + where(at) + " runs with the arc off (no ArcLStart, ArcCStart or \\On before it)");
                    remember(step);
                    out.add(step);
                    if (start) {
                        if (arcOn) notice("arc on " + where(at), step.label(), at, name + " at " + where(at) + " starts an arc that is already burning");
                        out.add(ioStep(proc, index, at, IoStep.Kind.ARC_ON, name, "", 1, 0, data));
                        arcOn = true;
                    } else if (end) {
                        out.add(ioStep(proc, index, at, IoStep.Kind.ARC_OFF, name, "", 0, 0, data));
                        arcOn = false;
                    }
                }
                default -> { return false; }
            }
            return true;
        }

        IoStep ioStep(String proc, int index, Object at, IoStep.Kind kind, String instruction, String signal, double value, double seconds, String text) {
            return new IoStep(proc, index, source(at), context(), kind, instruction, signal, value, seconds, Optional.empty(), text, statementOf(at));
        }

        /** The signal an argument names (signals are system data, not RAPID variables: never evaluated). */
        String signalName(RapidAst.Arg a, Object at) {
            if (a.value() instanceof RapidAst.Name n) return n.name();
            throw error(at, "a signal name is needed, found " + (a.value() == null ? "nothing" : org.robopro.programs.rapid.RapidAstWriter.expr(a.value())));
        }

        /**
         * Registers a signal the program uses and returns its name as the cell table writes it;
         * one notice per signal that is not in a given table or is used against its type.
         */
        String signal(String name, SignalDescription.Type type, String instruction, Object at, String proc, int index) {
            String key = Values.lower(name);
            SignalDescription d = table.get(key);
            if (d == null) {
                if (!table.isEmpty())
                    notice("signal " + key, stepLabel(proc, index, instruction), at, "signal " + name + " (" + instruction + " at " + where(at)
                            + ") is not in the cell's signal table" + (type == null ? "" : "; taken as a " + type));
                signalNames.putIfAbsent(key, name);
                signalValues.putIfAbsent(key, 0.0);
                return signalNames.get(key);
            }
            if (type != null && !type.input() && d.type().input())
                notice("input " + key, stepLabel(proc, index, instruction), at, instruction + " at " + where(at) + " writes " + d.name()
                        + ", which is an input (" + d.type() + "): the controller refuses this");
            return d.name();
        }

        /** The program's view of a signal after it set or waited for it; inputs that follow an output take its value. */
        void setSignal(String name, double v) {
            String key = Values.lower(name);
            signalValues.put(key, v);
            for (SignalDescription d : table.values()) if (d.follows().equalsIgnoreCase(name)) signalValues.put(d.key(), v);
        }

        double optionalNum(List<RapidAst.Arg> args, String name, Frame f, double otherwise) {
            for (RapidAst.Arg a : args)
                if (a.kind() != RapidAst.ArgKind.POSITIONAL && a.kind() != RapidAst.ArgKind.NAMED && a.name().equalsIgnoreCase(name) && a.value() != null)
                    return num(eval(a.value(), f), a.value());
            return otherwise;
        }

        /** \TimeFlag:=flag: the simulation assumes the wait ends in time, so the flag is FALSE. */
        void setTimeFlag(List<RapidAst.Arg> args, Frame f, Object at) {
            for (RapidAst.Arg a : args)
                if (a.kind() != RapidAst.ArgKind.POSITIONAL && a.kind() != RapidAst.ArgKind.NAMED && a.name().equalsIgnoreCase("TimeFlag")
                        && a.value() != null)
                    assign(a.value(), false, f, at);
        }

        /** {signal, value} of a condition "signal = value" or "DInput(signal) = value" or "TestDI(signal)"; null otherwise. */
        String[] signalCondition(RapidAst.Expr cond) {
            if (cond instanceof RapidAst.FuncCall fc && fc.name().equalsIgnoreCase("TestDI") && fc.args().size() == 1
                    && fc.args().get(0).value() instanceof RapidAst.Name n)
                return new String[] {n.name(), "1"};
            if (!(cond instanceof RapidAst.Binary b) || !b.op().equals("=") || !(b.right() instanceof RapidAst.Num v)) return null;
            String sig = null;
            if (b.left() instanceof RapidAst.Name n && signalValues.containsKey(Values.lower(n.name()))) sig = n.name();
            if (b.left() instanceof RapidAst.FuncCall fc && SIGNAL_READS.contains(fc.name().toUpperCase(Locale.ROOT)) && fc.args().size() == 1
                    && fc.args().get(0).value() instanceof RapidAst.Name n) sig = n.name();
            return sig == null ? null : new String[] {sig, String.valueOf(v.value())};
        }

        void remember(MoveStep step) {
            if (step.kind() == Move.Kind.MOVE_ABS_J) { lastJointTarget = currentJoint; lastRobTarget = null; }
            else { lastRobTarget = currentRob; lastJointTarget = null; }
        }

        Object currentRob;
        Object currentJoint;

        // ------------------------------------------------------------ moves

        MoveStep astMove(String up, List<RapidAst.Arg> args, Frame f, Object at, String proc, int index) {
            Move.Kind kind = switch (up) {
                case "MOVEL" -> Move.Kind.MOVE_L;
                case "MOVEJ" -> Move.Kind.MOVE_J;
                case "MOVEC" -> Move.Kind.MOVE_C;
                default -> Move.Kind.MOVE_ABS_J;
            };
            return motion(kind.rapidName(), kind, 0, Set.of(), args, f, at, proc, index, new ArrayList<>());
        }

        /**
         * A motion instruction whose arguments are [CirPoint,] ToPoint, Speed, {@code extras}
         * process arguments (seam and weld data, trigger data: kept unevaluated in
         * {@code extraOut}), Zone, Tool. Optional arguments in {@code passive} are kept in the
         * program and do not change the motion.
         */
        MoveStep motion(String instruction, Move.Kind kind, int extras, Set<String> passive, List<RapidAst.Arg> args, Frame f, Object at,
                        String proc, int index, List<RapidAst.Arg> extraOut) {
            List<RapidAst.Arg> pos = new ArrayList<>();
            OptionalDouble v = OptionalDouble.empty(), t = OptionalDouble.empty(), z = OptionalDouble.empty();
            String wobjName = "wobj0";
            Object wobjV = null;
            for (RapidAst.Arg a : args) {
                if (a.kind() == RapidAst.ArgKind.POSITIONAL || a.kind() == RapidAst.ArgKind.NAMED) { pos.add(a); continue; }
                String n = a.name().toUpperCase(Locale.ROOT);
                if (passive.contains(n)) { extraOut.add(a); continue; }
                switch (n) {
                    case "CONC", "NOEOFFS", "ID", "INPOS", "TLOAD" -> { }
                    case "V" -> v = OptionalDouble.of(Units.mmToM(num(eval(a.value(), f), a.value())));
                    case "T" -> t = OptionalDouble.of(num(eval(a.value(), f), a.value()));
                    case "Z" -> z = OptionalDouble.of(Units.mmToM(num(eval(a.value(), f), a.value())));
                    case "WOBJ" -> {
                        wobjName = a.value() instanceof RapidAst.Name nm ? nm.name() : "*";
                        wobjV = data(a.value(), f);
                    }
                    default -> {
                        if (passive.isEmpty()) throw error(at, "not simulated: " + instruction + " \\" + a.name() + " at " + where(at));
                        notice(instruction + "\\" + a.name(), stepLabel(proc, index, instruction), at,
                                "not simulated: " + instruction + " \\" + a.name() + " at " + where(at) + " (kept as written)");
                    }
                }
            }
            int b = kind == Move.Kind.MOVE_C ? 1 : 0;
            int need = b + 4 + extras;
            if (pos.size() != need) throw error(at, instruction + " needs " + need + " arguments, found " + pos.size());
            Object circ = b == 1 ? data(pos.get(0).value(), f) : null;
            Object to = data(pos.get(b).value(), f);
            SpeedData speed = typed(data(pos.get(b + 1).value(), f), "speeddata", SpeedData.class, at, label(pos.get(b + 1).value()));
            for (int k = 0; k < extras; k++) extraOut.add(pos.get(b + 2 + k));
            int zi = b + 2 + extras;
            ZoneData zone = typed(data(pos.get(zi).value(), f), "zonedata", ZoneData.class, at, label(pos.get(zi).value()));
            String toolName = label(pos.get(zi + 1).value());
            ToolData tool = typed(data(pos.get(zi + 1).value(), f), "tooldata", ToolData.class, at, toolName);
            WObjData wobj = wobjV == null ? WObjData.WOBJ0 : typed(wobjV, "wobjdata", WObjData.class, at, wobjName);
            if (v.isPresent() && !(v.getAsDouble() > 0 && Double.isFinite(v.getAsDouble())))
                throw error(at, "\\V must be a finite speed > 0, got " + v.getAsDouble());
            if (z.isPresent() && !(z.getAsDouble() >= 0 && Double.isFinite(z.getAsDouble())))
                throw error(at, "\\Z must be a finite zone size >= 0, got " + z.getAsDouble());
            try {
                return step(proc, index, at, kind, label(pos.get(b).value()), to, b == 1 ? Optional.of(label(pos.get(0).value())) : Optional.empty(),
                        circ, speed, v, t, zone, z, toolName, tool, wobjName, wobj, instruction);
            } catch (IllegalArgumentException e) {
                // A program value the data types reject (e.g. a non-finite pose): the user's input, located.
                throw error(at, instruction + ": " + e.getMessage());
            }
        }

        /**
         * A motion's data argument: a name is looked up as data (null when unknown, so the motion
         * reports "unknown robtarget 'p'" at the instruction); anything else is evaluated.
         */
        Object data(RapidAst.Expr e, Frame f) {
            if (!(e instanceof RapidAst.Name n)) return eval(e, f);
            Object v = named(n.name(), f, e);
            // Opaque data and an absent optional parameter: eval says what is wrong.
            if (v instanceof Opaque || (v == null && f.optionalParams.contains(Values.lower(n.name())))) return eval(e, f);
            return v;
        }

        String label(RapidAst.Expr e) {
            if (e instanceof RapidAst.Name n) return n.name();
            if (e instanceof RapidAst.Aggregate) return "*";
            return org.robopro.programs.rapid.RapidAstWriter.expr(e);
        }

        MoveStep step(String proc, int index, Object at, Move.Kind kind, String toLabel, Object toV, Optional<String> circName, Object circV,
                      SpeedData speed, OptionalDouble v, OptionalDouble t, ZoneData zone, OptionalDouble z, String toolName, ToolData tool,
                      String wobjName, WObjData wobj, String instruction) {
            if (v.isPresent()) speed = new SpeedData(v.getAsDouble(), speed.vOri(), speed.vLeax(), speed.vReax());
            if (z.isPresent())
                zone = new ZoneData(zone.finep(), z.getAsDouble(), Math.max(zone.pzoneOri(), z.getAsDouble()),
                        Math.max(zone.pzoneEax(), z.getAsDouble()), zone.zoneOri(), zone.zoneLeax(), zone.zoneReax());
            Pose flangeTtcp = tool.tframe().toPose();
            Optional<SourcePos> src = source(at);
            if (kind == Move.Kind.MOVE_ABS_J) {
                JointTarget jt = typed(toV, "jointtarget", JointTarget.class, at, toLabel);
                currentJoint = new Typed(jt);
                return new MoveStep(proc, index, src, kind, toLabel, Optional.empty(), Optional.empty(), Optional.empty(),
                        Optional.empty(), Optional.empty(), Optional.empty(), Optional.of(jt.robax()), speed, t, zone,
                        toolName, tool, wobjName, wobj, flangeTtcp, context(), instruction, statementOf(at));
            }
            RobTarget to = typed(toV, "robtarget", RobTarget.class, at, toLabel);
            currentRob = new Typed(to);
            Pose[] toPoses = basePoses(to, tool, wobj, at);
            Optional<Pose> circFlange = Optional.empty(), circTcp = Optional.empty();
            if (circV != null) {
                RobTarget c = typed(circV, "robtarget", RobTarget.class, at, circName.orElse("*"));
                Pose[] cp = basePoses(c, tool, wobj, at);
                circFlange = Optional.of(cp[0]);
                circTcp = Optional.of(cp[1]);
            }
            return new MoveStep(proc, index, src, kind, toLabel, circName, Optional.of(toPoses[0]), Optional.of(toPoses[1]),
                    circFlange, circTcp, Optional.of(to.robconf()), Optional.empty(), speed, t, zone, toolName, tool, wobjName, wobj,
                    flangeTtcp, context(), instruction, statementOf(at));
        }

        /** The statement a step ran: the syntax-tree node itself (absent for a statement of no tree). */
        Optional<RapidAst.Stmt> statementOf(Object at) {
            return at instanceof RapidAst.Stmt st ? Optional.of(st) : Optional.empty();
        }

        /**
         * {baseTflange, baseTtcp} of a robtarget. Robot-held tool: baseTtcp = uframe oframe objTtarget,
         * baseTflange = baseTtcp tframe^-1. Stationary tool with a robot-held work object: the target
         * frame meets the tool frame, baseTflange = worldTtool objTtarget^-1 (uframe oframe)^-1.
         */
        Pose[] basePoses(RobTarget t, ToolData tool, WObjData wobj, Object at) {
            if (!wobj.ufprog() || !wobj.ufmec().isEmpty())
                throw error(at, "work objects moved by a mechanical unit (ufprog FALSE or ufmec \"" + wobj.ufmec() + "\") are not supported");
            Pose objT = t.pose();
            Pose userTobj = wobj.uframe().toPose().times(wobj.oframe().toPose());
            Pose tframe = tool.tframe().toPose();
            if (tool.robhold() && !wobj.robhold()) {
                Pose baseTtcp = userTobj.times(objT);
                return new Pose[] {baseTtcp.times(tframe.inverse()), baseTtcp};
            }
            if (!tool.robhold() && wobj.robhold()) {
                Pose baseTflange = tframe.times(objT.inverse()).times(userTobj.inverse());
                return new Pose[] {baseTflange, tframe};
            }
            throw error(at, tool.robhold() ? "tool and work object are both held by the robot" : "neither the tool nor the work object is held by the robot");
        }

        /** A name's value: routine data, module data, library data, then RAPID's predefined data; null when unknown. */
        Object named(String name, Frame f, Object at) {
            Var v = f.vars.get(Values.lower(name));
            if (v == null) v = globals.get(Values.lower(name));
            if (v != null) return v.value;
            RapidValue pre = predefined(name);
            return pre == null ? null : new Typed(pre);
        }

        <T extends RapidValue> T typed(Object v, String type, Class<T> cls, Object at, String name) {
            if (v == null) throw error(at, "unknown " + type + " '" + name + "'");
            if (v instanceof Typed t) {
                if (!cls.isInstance(t.value())) throw error(at, "'" + name + "' is a " + t.value().rapidType() + ", a " + type + " is needed");
                return cls.cast(t.value());
            }
            if (v instanceof Rec r && r.type != null && !r.type.equals(type))
                throw error(at, "'" + name + "' is a " + r.type + ", a " + type + " is needed");
            try {
                return cls.cast(RapidParser.literalValue(type, Values.literal(v), file, name));
            } catch (InputException e) {
                throw error(at, "'" + name + "' is no valid " + type + ": " + e.problem());
            } catch (IllegalArgumentException e) {
                throw error(at, "'" + name + "' is no valid " + type + ": " + e.getMessage());
            }
        }

        // ------------------------------------------------------------ data

        Var variable(String name, Frame f, Object at) {
            Var v = f == null ? null : f.vars.get(Values.lower(name));
            if (v == null) v = globals.get(Values.lower(name));
            if (v == null) {
                if (f != null && f.optionalParams.contains(Values.lower(name))) throw error(at, "optional parameter " + name + " is not present");
                throw error(at, "unknown data '" + name + "'");
            }
            return v;
        }

        void assign(RapidAst.Expr target, Object value, Frame f, Object at) {
            if (target instanceof RapidAst.Name n) {
                Var v = variable(n.name(), f, at);
                if (v.constant) throw error(at, n.name() + " is a constant");
                v.value = v.type == null ? Values.copy(value) : coerce(value, v.type, dimsOf(v.value), at);
                return;
            }
            // A component or an element: find the enclosing value and replace inside it.
            RapidAst.Expr baseE = target instanceof RapidAst.Component c ? c.base() : ((RapidAst.Index) target).base();
            Object container = place(baseE, f, at);
            if (target instanceof RapidAst.Component c) {
                Rec r = (Rec) container;
                int k = field(r, c.component(), at);
                r.f[k] = coerceLike(r.f[k], value, at);
            } else {
                RapidAst.Index x = (RapidAst.Index) target;
                Object[] slot = slot(container, x, f, at);
                int k = (int) (double) (Double) slot[1];
                Object[] items = (Object[]) slot[0];
                items[k] = coerceLike(items[k], value, at);
            }
        }

        List<Integer> dimsOf(Object v) {
            List<Integer> d = new ArrayList<>();
            while (v instanceof Arr a) { d.add(a.items.length); v = a.items.length > 0 ? a.items[0] : null; }
            return d;
        }

        Object coerceLike(Object old, Object value, Object at) {
            if (old instanceof Double && !(value instanceof Double)) throw error(at, "a num is needed, found " + Values.describe(value));
            if (old instanceof Boolean && !(value instanceof Boolean)) throw error(at, "a bool is needed, found " + Values.describe(value));
            if (old instanceof String && !(value instanceof String)) throw error(at, "a string is needed, found " + Values.describe(value));
            if (old instanceof Rec r && r.type != null) return coerce(value instanceof Typed t ? Values.untyped(t.value()) : value, r.type, List.of(), at);
            return Values.copy(value instanceof Typed t ? Values.untyped(t.value()) : value);
        }

        /** The mutable value a component/element target lives in (typed values are taken apart first). */
        Object place(RapidAst.Expr e, Frame f, Object at) {
            if (e instanceof RapidAst.Name n) {
                Var v = variable(n.name(), f, at);
                if (v.constant) throw error(at, n.name() + " is a constant");
                if (v.value instanceof Typed t) v.value = Values.untyped(t.value());
                return v.value;
            }
            if (e instanceof RapidAst.Component c) {
                Object base = place(c.base(), f, at);
                if (!(base instanceof Rec r)) throw error(at, "." + c.component() + " of a " + Values.describe(base));
                int k = field(r, c.component(), at);
                if (r.f[k] instanceof Typed t) r.f[k] = Values.untyped(t.value());
                return r.f[k];
            }
            if (e instanceof RapidAst.Index x) {
                Object[] slot = slot(place(x.base(), f, at), x, f, at);
                Object[] items = (Object[]) slot[0];
                int k = (int) (double) (Double) slot[1];
                return items[k];
            }
            throw error(at, "cannot assign to " + org.robopro.programs.rapid.RapidAstWriter.expr(e));
        }

        /** {items array, 0-based index} of the last index of an element expression. */
        Object[] slot(Object container, RapidAst.Index x, Frame f, Object at) {
            Object cur = container;
            for (int n = 0; n < x.indices().size(); n++) {
                if (!(cur instanceof Arr a)) throw error(at, "index into a " + Values.describe(cur));
                int k = index(eval(x.indices().get(n), f), x.indices().get(n));
                if (k < 1 || k > a.items.length) throw error(at, "index " + k + " outside 1.." + a.items.length);
                if (n == x.indices().size() - 1) return new Object[] {a.items, (double) (k - 1)};
                cur = a.items[k - 1];
            }
            throw error(at, "empty index");
        }

        int field(Rec r, String name, Object at) {
            List<Values.FieldDef> fs = r.type == null ? null : records.get(r.type);
            if (fs != null)
                for (int k = 0; k < fs.size(); k++) if (fs.get(k).name().equalsIgnoreCase(name)) return k;
            throw error(at, (r.type == null ? "an aggregate" : "a " + r.type) + " has no component " + name);
        }

        int index(Object v, Object at) {
            double d = num(v, at);
            if (d != Math.rint(d) || Math.abs(d) > 1e7) throw error(at, "an index must be an integer, found " + fmt(d));
            return (int) d;
        }

        // ------------------------------------------------------------ expressions

        Object eval(RapidAst.Expr e, Frame f) {
            if (e instanceof RapidAst.Num n) return n.value();
            if (e instanceof RapidAst.Bool b) return b.value();
            if (e instanceof RapidAst.Str s) {
                try {
                    return s.value();
                } catch (IllegalArgumentException bad) {
                    throw error(e, bad.getMessage());
                }
            }
            if (e instanceof RapidAst.Name n) {
                Var v = f == null ? null : f.vars.get(Values.lower(n.name()));
                if (v == null) v = globals.get(Values.lower(n.name()));
                if (v != null) {
                    if (v.value instanceof Opaque o) throw error(e, "not simulated: data of type " + o.type() + " ('" + n.name() + "') at " + where(e));
                    return v.value;
                }
                if (n.name().equalsIgnoreCase("pi")) return Math.PI;
                Double sig = signalValues.get(Values.lower(n.name()));
                if (sig != null) return sig;
                RapidValue pre = predefined(n.name());
                if (pre != null) return new Typed(pre);
                if (f != null && f.optionalParams.contains(Values.lower(n.name()))) throw error(e, "optional parameter " + n.name() + " is not present");
                throw error(e, "unknown data '" + n.name() + "'");
            }
            if (e instanceof RapidAst.Component c) {
                Object base = eval(c.base(), f);
                if (base instanceof Typed t) base = Values.untyped(t.value());
                if (!(base instanceof Rec r)) throw error(e, "." + c.component() + " of a " + Values.describe(base));
                return r.f[field(r, c.component(), e)];
            }
            if (e instanceof RapidAst.Index x) {
                Object base = eval(x.base(), f);
                Object[] slot = slot(base, x, f, e);
                return ((Object[]) slot[0])[(int) (double) (Double) slot[1]];
            }
            if (e instanceof RapidAst.Aggregate a) {
                Object[] items = new Object[a.items().size()];
                for (int k = 0; k < items.length; k++) {
                    Object v = eval(a.items().get(k), f);
                    items[k] = v instanceof Typed t ? Values.untyped(t.value()) : Values.copy(v);
                }
                return new Rec(null, items);
            }
            if (e instanceof RapidAst.FuncCall fc) return function(fc, f);
            if (e instanceof RapidAst.Unary u) {
                Object v = eval(u.operand(), f);
                if (u.op().equals("NOT")) return !bool(v, u.operand());
                if (v instanceof Typed t) v = Values.untyped(t.value());
                if (v instanceof Rec r && "pos".equals(r.type) && u.op().equals("-"))
                    return Values.rec("pos", -num(r.f[0], e), -num(r.f[1], e), -num(r.f[2], e));
                double d = num(v, u.operand());
                return u.op().equals("-") ? -d : d;
            }
            RapidAst.Binary b = (RapidAst.Binary) e;
            String op = b.op();
            if (op.equals("AND")) return bool(eval(b.left(), f), b.left()) && bool(eval(b.right(), f), b.right());
            if (op.equals("OR")) return bool(eval(b.left(), f), b.left()) || bool(eval(b.right(), f), b.right());
            Object l = eval(b.left(), f), r = eval(b.right(), f);
            if (op.equals("XOR")) return bool(l, b.left()) ^ bool(r, b.right());
            if (op.equals("=")) return same(l, r);
            if (op.equals("<>")) return !same(l, r);
            if (op.equals("+") && l instanceof String ls && r instanceof String rs) return ls + rs;
            if (l instanceof Typed t) l = Values.untyped(t.value());
            if (r instanceof Typed t) r = Values.untyped(t.value());
            if ((op.equals("+") || op.equals("-")) && l instanceof Rec lr && "pos".equals(lr.type) && r instanceof Rec rr) {
                double sg = op.equals("+") ? 1 : -1;
                return Values.rec("pos", num(lr.f[0], e) + sg * num(rr.f[0], e), num(lr.f[1], e) + sg * num(rr.f[1], e),
                        num(lr.f[2], e) + sg * num(rr.f[2], e));
            }
            double x = num(l, b.left()), y = num(r, b.right());
            return switch (op) {
                case "+" -> x + y;
                case "-" -> x - y;
                case "*" -> x * y;
                case "/" -> {
                    if (y == 0) throw error(e, "division by zero");
                    yield x / y;
                }
                case "DIV", "MOD" -> {
                    if (x != Math.rint(x) || y != Math.rint(y)) throw error(e, op + " needs integers");
                    if (y == 0) throw error(e, "division by zero");
                    yield op.equals("DIV") ? (double) ((long) x / (long) y) : (double) ((long) x % (long) y);
                }
                case "<" -> x < y;
                case ">" -> x > y;
                case "<=" -> x <= y;
                case ">=" -> x >= y;
                default -> throw error(e, "operator " + op);
            };
        }

        boolean same(Object a, Object b) {
            if (a instanceof Typed t) a = Values.untyped(t.value());
            if (b instanceof Typed t) b = Values.untyped(t.value());
            return java.util.Objects.equals(a, b);
        }

        Object function(RapidAst.FuncCall fc, Frame f) {
            Object r = routine(fc.name());
            if (r instanceof RapidAst.Routine rt && rt.kind() == RapidAst.RoutineKind.FUNC) {
                if (depth + 1 > MAX_CALL_DEPTH) throw error(fc, "function calls nested deeper than " + MAX_CALL_DEPTH + " (recursion?)");
                Frame nf = bind(rt, fc.args(), f, fc);
                Object v = runAst(rt, nf, depth + 1);
                return coerce(v, rt.returnType(), List.of(), fc);
            }
            String up = fc.name().toUpperCase(Locale.ROOT);
            if (SIGNAL_READS.contains(up)) {
                if (fc.args().size() != 1 || !(fc.args().get(0).value() instanceof RapidAst.Name n))
                    throw error(fc, fc.name() + " needs one signal name");
                String key = Values.lower(signal(n.name(), null, fc.name(), fc, f == null ? module.name() : f.routine, 0));
                double v = signalValues.getOrDefault(key, 0.0);
                return up.startsWith("TEST") ? (Object) (v == 1) : (Object) v;
            }
            List<Object> pos = new ArrayList<>();
            Map<String, Object> opt = new HashMap<>();
            if (!up.equals("PRESENT"))
                for (RapidAst.Arg a : fc.args()) {
                    if (a.kind() == RapidAst.ArgKind.POSITIONAL || a.kind() == RapidAst.ArgKind.NAMED) pos.add(eval(a.value(), f));
                    else opt.put(a.name().toUpperCase(Locale.ROOT), a.value() == null ? Boolean.TRUE : eval(a.value(), f));
                }
            switch (up) {
                case "PRESENT" -> {
                    if (fc.args().size() != 1 || !(fc.args().get(0).value() instanceof RapidAst.Name n)) throw error(fc, "Present needs a parameter name");
                    return f != null && f.vars.containsKey(Values.lower(n.name()));
                }
                case "OFFS" -> {
                    need(fc, pos, 4);
                    Rec p = robRec(pos.get(0), fc);
                    Rec t = (Rec) p.f[0];
                    t.f[0] = num(t.f[0], fc) + num(pos.get(1), fc);
                    t.f[1] = num(t.f[1], fc) + num(pos.get(2), fc);
                    t.f[2] = num(t.f[2], fc) + num(pos.get(3), fc);
                    return p;
                }
                case "RELTOOL" -> {
                    need(fc, pos, 4);
                    return relTool(robRec(pos.get(0), fc), num(pos.get(1), fc), num(pos.get(2), fc), num(pos.get(3), fc),
                            opt.containsKey("RX") ? num(opt.get("RX"), fc) : 0, opt.containsKey("RY") ? num(opt.get("RY"), fc) : 0,
                            opt.containsKey("RZ") ? num(opt.get("RZ"), fc) : 0, fc);
                }
                case "CROBT" -> {
                    if (currentRob == null || lastRobTarget == null)
                        throw error(fc, "not simulated: CRobT before any Cartesian move (the position needs the robot's kinematics) at " + where(fc));
                    return Values.untyped(((Typed) currentRob).value());
                }
                case "CJOINTT" -> {
                    if (currentJoint == null || lastJointTarget == null)
                        throw error(fc, "not simulated: CJointT after a Cartesian move or before any move (needs inverse kinematics) at " + where(fc));
                    return Values.untyped(((Typed) currentJoint).value());
                }
                case "ABS" -> { need(fc, pos, 1); return Math.abs(num(pos.get(0), fc)); }
                case "SQRT" -> { need(fc, pos, 1); return Math.sqrt(num(pos.get(0), fc)); }
                case "SIN" -> { need(fc, pos, 1); return Math.sin(Math.toRadians(num(pos.get(0), fc))); }
                case "COS" -> { need(fc, pos, 1); return Math.cos(Math.toRadians(num(pos.get(0), fc))); }
                case "TAN" -> { need(fc, pos, 1); return Math.tan(Math.toRadians(num(pos.get(0), fc))); }
                case "ASIN" -> { need(fc, pos, 1); return Math.toDegrees(Math.asin(num(pos.get(0), fc))); }
                case "ACOS" -> { need(fc, pos, 1); return Math.toDegrees(Math.acos(num(pos.get(0), fc))); }
                case "ATAN" -> { need(fc, pos, 1); return Math.toDegrees(Math.atan(num(pos.get(0), fc))); }
                case "ATAN2" -> { need(fc, pos, 2); return Math.toDegrees(Math.atan2(num(pos.get(0), fc), num(pos.get(1), fc))); }
                case "EXP" -> { need(fc, pos, 1); return Math.exp(num(pos.get(0), fc)); }
                case "POW" -> { need(fc, pos, 2); return Math.pow(num(pos.get(0), fc), num(pos.get(1), fc)); }
                case "ROUND", "TRUNC" -> {
                    need(fc, pos, 1);
                    double s = Math.pow(10, opt.containsKey("DEC") ? num(opt.get("DEC"), fc) : 0);
                    double x = num(pos.get(0), fc) * s;
                    return (up.equals("ROUND") ? Math.round(x) : (x < 0 ? Math.ceil(x) : Math.floor(x))) / s;
                }
                case "NUMTOSTR" -> {
                    need(fc, pos, 2);
                    int dec = index(pos.get(1), fc);
                    return new java.math.BigDecimal(num(pos.get(0), fc)).setScale(Math.max(0, dec), java.math.RoundingMode.HALF_UP).toPlainString();
                }
                case "STRLEN" -> { need(fc, pos, 1); return (double) string(pos.get(0), fc).length(); }
                case "DIM" -> {
                    need(fc, pos, 2);
                    Object v = pos.get(0);
                    for (int k = 1; k < index(pos.get(1), fc); k++) v = v instanceof Arr a && a.items.length > 0 ? a.items[0] : null;
                    if (!(v instanceof Arr a)) throw error(fc, "Dim of a non-array");
                    return (double) a.items.length;
                }
                default -> throw error(fc, "not simulated: function " + fc.name() + " at " + where(fc) + " (no such FUNC in the module)");
            }
        }

        void need(RapidAst.FuncCall fc, List<Object> pos, int n) {
            if (pos.size() != n) throw error(fc, fc.name() + " takes " + n + " arguments, found " + pos.size());
        }

        Rec robRec(Object v, Object at) {
            if (v instanceof Typed t) v = Values.untyped(t.value());
            else v = Values.copy(v);
            if (!(v instanceof Rec r) || !(r.type == null || r.type.equals("robtarget")) || r.f.length != 4) throw error(at, "a robtarget is needed, found " + Values.describe(v));
            return (Rec) coerce(r, "robtarget", List.of(), at);
        }

        /**
         * RelTool: displacement (dx, dy, dz) mm in the tool frame, then rotations Rx, Ry, Rz (deg)
         * about the tool's x, y, z axes, in that order (ABB RAPID reference, RelTool).
         */
        Rec relTool(Rec p, double dx, double dy, double dz, double rx, double ry, double rz, Object at) {
            Rec t = (Rec) p.f[0], o = (Rec) p.f[1];
            double w = num(o.f[0], at), x = num(o.f[1], at), y = num(o.f[2], at), z = num(o.f[3], at);
            double[] d = rotate(w, x, y, z, dx, dy, dz);
            t.f[0] = num(t.f[0], at) + d[0];
            t.f[1] = num(t.f[1], at) + d[1];
            t.f[2] = num(t.f[2], at) + d[2];
            double[] q = {w, x, y, z};
            q = mul(q, axis(rx, 0));
            q = mul(q, axis(ry, 1));
            q = mul(q, axis(rz, 2));
            p.f[1] = Values.rec("orient", q[0], q[1], q[2], q[3]);
            return p;
        }

        double[] axis(double deg, int k) {
            double h = Math.toRadians(deg) / 2;
            double[] q = {Math.cos(h), 0, 0, 0};
            q[k + 1] = Math.sin(h);
            return q;
        }

        double[] mul(double[] a, double[] b) {
            return new double[] {a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3], a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
                    a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1], a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]};
        }

        double[] rotate(double w, double x, double y, double z, double vx, double vy, double vz) {
            double[] r = mul(mul(new double[] {w, x, y, z}, new double[] {0, vx, vy, vz}), new double[] {w, -x, -y, -z});
            return new double[] {r[1], r[2], r[3]};
        }

        double num(Object v, Object at) {
            if (v instanceof Typed t && t.value() instanceof RapidValue.Num n) return n.value();
            if (v instanceof Double d) return d;
            throw error(at, "a num is needed, found " + Values.describe(v));
        }

        boolean bool(Object v, Object at) {
            if (v instanceof Typed t && t.value() instanceof RapidValue.Bool b) return b.value();
            if (v instanceof Boolean b) return b;
            throw error(at, "a bool is needed, found " + Values.describe(v));
        }

        String string(Object v, Object at) {
            if (v instanceof Typed t && t.value() instanceof RapidValue.Str s) return s.value();
            if (v instanceof String s) return s;
            throw error(at, "a string is needed, found " + Values.describe(v));
        }

        Optional<SourcePos> source(Object at) { return Optional.ofNullable(pos(at)); }
    }

    private static String fmt(double d) { return d == Math.rint(d) && Math.abs(d) < 1e15 ? String.valueOf((long) d) : String.valueOf(d); }

    private static RapidValue predefined(String name) {
        String k = name.toLowerCase(Locale.ROOT);
        if (k.equals("tool0")) return ToolData.TOOL0;
        if (k.equals("wobj0")) return WObjData.WOBJ0;
        if (k.equals("load0")) return org.robopro.programs.LoadData.LOAD0;
        Optional<SpeedData> s = SpeedData.predefined(k);
        if (s.isPresent()) return s.get();
        return ZoneData.predefined(k).orElse(null);
    }

    private SourcePos pos(Object at) {
        if (at == null) return null;
        for (ParsedAst a : asts) {
            SourcePos p = a.position(at).orElse(null);
            if (p != null) return p;
        }
        return null;
    }

    private String where(Object at) {
        SourcePos p = pos(at);
        return p == null ? "(no position)" : p.line() + ":" + p.column();
    }

    private InputException error(Object at, String problem) {
        SourcePos p = pos(at);
        return p == null ? new InputException(file, 0, 0, null, problem) : new InputException(p.file(), p.line(), p.column(), null, problem);
    }
}
