package org.robopro.programs;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import org.robopro.kinematics.Units;
import org.robopro.models.Vec3;
import org.robopro.programs.rapid.RapidAst.Arg;
import org.robopro.programs.rapid.RapidAst.Expr;
import org.robopro.programs.rapid.RapidAst;
import org.robopro.programs.rapid.RapidAstWriter;
import org.robopro.programs.rapid.RapidExport;
import org.robopro.programs.rapid.RapidNames;
import org.robopro.programs.rapid.RapidNumbers;

/**
 * Writes a {@link RapidModule} as a RAPID module a controller loads: the module's typed view is
 * written as a syntax tree at the file's precision with valid unique names ({@link #tree}),
 * which {@link RapidAstWriter} writes (two-space
 * indentation, rapidchecker's rule; upper-case keywords; no trailing spaces; a final line
 * break). Names are made valid, at most 32 characters and unique ignoring case; every change is
 * reported. Quaternions are written unit (normalised unless already unit at the file's
 * precision, so an imported file's digits survive). Numbers: see {@link RapidNumbers}.
 */
public final class RapidWriter {
    /** Decimals written for mm, degrees, quaternion components and other numbers (kg, kg m^2, s). */
    public record Precision(int mmDecimals, int degDecimals, int quatDecimals, int otherDecimals) {
        public static final Precision DEFAULT = new Precision(6, 6, 10, 9);
    }

    private final Precision prec;
    /** Names as given and numbers as the shortest literals that read back exactly (no precision, no renames). */
    private final boolean exact;
    private final Map<String, String> names = new HashMap<>(); // lower-case original -> written
    private final List<RapidExport.Rename> renames = new ArrayList<>();

    private RapidWriter(Precision prec, boolean exact) {
        this.prec = prec;
        this.exact = exact;
    }

    public static RapidExport export(RapidModule module) { return export(module, Precision.DEFAULT); }

    public static RapidExport export(RapidModule module, Precision precision) {
        RapidWriter w = new RapidWriter(precision, false);
        RapidAst.Module tree = w.module(module);
        return new RapidExport(RapidAstWriter.write(tree), w.renames);
    }

    /**
     * The syntax tree {@code module} is exported as (names made valid and unique, values as the
     * literals written at {@code precision}): what {@link #export} writes and what a controller
     * (or the interpreter) reads back.
     */
    public static RapidAst.Module tree(RapidModule module, Precision precision) {
        return new RapidWriter(precision, false).module(module);
    }

    /**
     * The syntax tree of one typed item with its names as given and every number a literal that
     * reads back as the very same value (how {@link RapidModule} turns typed items into its tree,
     * so its poses are not rounded to a file's precision). Statements found in {@code nodes}
     * (typed statements read from a tree, to the node they were read from) keep that node.
     */
    static RapidAst.Item exactItem(ModuleItem item, Map<Object, Object> nodes) {
        return new RapidWriter(Precision.DEFAULT, true).item(item, nodes);
    }

    /** Names every module may use without declaring them. */
    private static final Set<String> PREDEFINED = predefinedNames();

    private static Set<String> predefinedNames() {
        Set<String> s = new HashSet<>();
        SpeedData.predefinedAll().keySet().forEach(k -> s.add(k.toLowerCase(Locale.ROOT)));
        ZoneData.predefinedAll().keySet().forEach(k -> s.add(k.toLowerCase(Locale.ROOT)));
        s.add("tool0");
        s.add("wobj0");
        s.add("load0");
        return s;
    }

    private RapidAst.Module module(RapidModule m) {
        if (!exact) planNames(m);
        String modName = exact || RapidNames.isValid(m.name()) ? m.name() : RapidNames.sanitize(m.name());
        if (!modName.equals(m.name())) renames.add(new RapidExport.Rename("module", m.name(), modName, "not a valid RAPID name"));
        List<RapidAst.Item> items = new ArrayList<>();
        for (ModuleItem item : m.items()) items.add(item(item, Map.of()));
        return new RapidAst.Module(modName, m.options(), items);
    }

    private RapidAst.Item item(ModuleItem item, Map<Object, Object> nodes) {
        if (item instanceof Comment c) return new RapidAst.CommentLine(stripEnd(c.text()));
        if (item instanceof Declaration d)
            return new RapidAst.DataDecl(d.scope(), d.storage(), d.rapidType(), declaredName(d), List.of(), value(d.value()));
        if (item instanceof Procedure p) return procedure(p, nodes);
        return ((AstItem) item).item();
    }

    private RapidAst.Routine procedure(Procedure p, Map<Object, Object> nodes) {
        List<RapidAst.Stmt> body = new ArrayList<>();
        for (Statement s : p.body()) body.add(nodes.get(s) instanceof RapidAst.Stmt kept ? kept : statement(s));
        return new RapidAst.Routine(p.local(), RapidAst.RoutineKind.PROC, null, name(p.name()), List.of(), body, null, null, null, null);
    }

    private static String stripEnd(String s) {
        int e = s.length();
        while (e > 0 && Character.isWhitespace(s.charAt(e - 1))) e--;
        return s.substring(0, e);
    }

    // ---------------------------------------------------------------- names

    /**
     * Declared data and procedures get valid unique names first (in file order); names only
     * referenced (data of other modules) are kept when valid, sanitised otherwise.
     */
    private void planNames(RapidModule m) {
        Set<String> used = new HashSet<>(PREDEFINED);
        Map<String, String> declared = new LinkedHashMap<>();
        for (ModuleItem it : m.items()) {
            String n = it instanceof Declaration d ? d.name() : it instanceof Procedure p ? p.name() : null;
            if (it instanceof AstItem a && a.name() != null) {
                // Written as read: its name and the names inside it are kept.
                used.add(a.name().toLowerCase(Locale.ROOT));
                declared.putIfAbsent(a.name().toLowerCase(Locale.ROOT), a.name());
            }
            if (n == null) continue;
            String key = n.toLowerCase(Locale.ROOT);
            if (declared.containsKey(key)) {
                // Same name twice: the second becomes name_2 and references keep meaning the first.
                String w = unique(RapidNames.sanitize(n), used);
                renames.add(new RapidExport.Rename(it instanceof Declaration ? "data" : "procedure", n, w, "name used twice"));
                continue;
            }
            String reason = null;
            String w = n;
            if (!RapidNames.isValid(n)) { w = RapidNames.sanitize(n); reason = "not a valid RAPID name"; }
            if (used.contains(w.toLowerCase(Locale.ROOT))) {
                w = unique(w, used);
                reason = PREDEFINED.contains(key) ? "clashes with predefined data" : "clashes with another name";
            }
            used.add(w.toLowerCase(Locale.ROOT));
            declared.put(key, w);
            if (reason != null) renames.add(new RapidExport.Rename(it instanceof Declaration ? "data" : "procedure", n, w, reason));
        }
        names.putAll(declared);
        usedNames = used;
    }

    private Set<String> usedNames;

    private String unique(String base, Set<String> used) {
        for (int k = 2; ; k++) {
            String suffix = "_" + k;
            String stem = base.length() + suffix.length() > RapidNames.MAX_LENGTH ? base.substring(0, RapidNames.MAX_LENGTH - suffix.length()) : base;
            String c = stem + suffix;
            if (!used.contains(c.toLowerCase(Locale.ROOT))) {
                used.add(c.toLowerCase(Locale.ROOT));
                return c;
            }
        }
    }

    private String name(String n) {
        if (exact) return n;
        String key = n.toLowerCase(Locale.ROOT);
        String w = names.get(key);
        if (w != null) return w;
        if (PREDEFINED.contains(key) || RapidNames.isValid(n)) {
            names.put(key, n);
            return n;
        }
        w = unique(RapidNames.sanitize(n), usedNames);
        renames.add(new RapidExport.Rename("reference", n, w, "not a valid RAPID name"));
        names.put(key, w);
        return w;
    }

    private final Set<String> written = new HashSet<>();

    private String declaredName(Declaration d) {
        if (exact) return d.name();
        String w = names.get(d.name().toLowerCase(Locale.ROOT));
        if (written.add(w.toLowerCase(Locale.ROOT))) return w;
        // A repeated name: its rename was planned in order; find it.
        for (RapidExport.Rename r : renames)
            if (r.from().equals(d.name()) && r.reason().equals("name used twice") && written.add(r.to().toLowerCase(Locale.ROOT)))
                return r.to();
        throw new IllegalStateException("no name planned for " + d.name());
    }

    // ---------------------------------------------------------------- values

    /** The RAPID aggregate of a value (RobotStudio's layout: no spaces inside brackets), in RAPID units. */
    private Expr value(RapidValue v) {
        if (v instanceof RobTarget t)
            return agg(mm(t.trans()), quat(t.rot()), agg(integer(t.robconf().cf1()), integer(t.robconf().cf4()),
                    integer(t.robconf().cf6()), integer(t.robconf().cfx())), ext(t.extax()));
        if (v instanceof JointTarget j) {
            Expr[] q = new Expr[6];
            for (int k = 0; k < 6; k++) q[k] = deg(j.robax(k));
            return agg(agg(q), ext(j.extax()));
        }
        if (v instanceof ToolData t) return agg(bool(t.robhold()), pose(t.tframe()), value(t.tload()));
        if (v instanceof WObjData w) return agg(bool(w.robhold()), bool(w.ufprog()), quoted(w.ufmec()), pose(w.uframe()), pose(w.oframe()));
        if (v instanceof LoadData l) return agg(other(l.mass()), mm(l.cog()), quat(l.aom()), other(l.ix()), other(l.iy()), other(l.iz()));
        if (v instanceof SpeedData s)
            return agg(num(fmt(Units.mToMm(s.vTcp()), prec.mmDecimals())), deg(s.vOri()), num(fmt(Units.mToMm(s.vLeax()), prec.mmDecimals())),
                    deg(s.vReax()));
        if (v instanceof ZoneData z)
            return agg(bool(z.finep()), mmv(z.pzoneTcp()), mmv(z.pzoneOri()), mmv(z.pzoneEax()), deg(z.zoneOri()), mmv(z.zoneLeax()),
                    deg(z.zoneReax()));
        if (v instanceof RapidPose p) return pose(p);
        if (v instanceof RapidValue.Num n) return num(RapidNumbers.formatExact(n.value()));
        if (v instanceof RapidValue.Bool bo) return bool(bo.value());
        if (v instanceof RapidValue.Str s) return quoted(s.value());
        throw new IllegalArgumentException("cannot write " + v);
    }

    /** A number literal from its text; a leading minus is RAPID's sign operator. */
    private static Expr num(String text) {
        return text.startsWith("-") ? new RapidAst.Unary("-", new RapidAst.Num(text.substring(1))) : new RapidAst.Num(text);
    }

    private static Expr integer(int k) { return num(Integer.toString(k)); }

    private static Expr agg(Expr... items) { return new RapidAst.Aggregate(List.of(items)); }

    private static Expr quoted(String s) { return RapidAst.Str.of(s); }

    private static Expr bool(boolean b) { return new RapidAst.Bool(b); }

    private Expr pose(RapidPose p) { return agg(mm(p.trans()), quat(p.rot())); }

    private Expr mm(Vec3 p) { return agg(mmv(p.x()), mmv(p.y()), mmv(p.z())); }

    private Expr mmv(double m) { return num(fmt(Units.mToMm(m), prec.mmDecimals())); }

    private Expr deg(double rad) { return num(fmt(Units.radToDeg(rad), prec.degDecimals())); }

    private Expr other(double x) { return num(fmt(x, prec.otherDecimals())); }

    /**
     * A number's literal: at {@code decimals}, or in an exact tree a text that reads back as the
     * very same double (a whole number without decimals, otherwise Java's own text: it costs far
     * less than the shortest decimal, and an export writes the file's precision anyway).
     */
    private String fmt(double x, int decimals) {
        if (!exact) return RapidNumbers.format(x, decimals);
        if (x == RapidNumbers.UNUSED_AXIS) return "9E+09";
        if (x == Math.rint(x) && Math.abs(x) < 1e15) return Long.toString((long) x);
        return Double.toString(x);
    }

    private Expr quat(Quaternion q) {
        double tol = Math.pow(10, -prec.quatDecimals()) * 10;
        Quaternion u = exact || Math.abs(q.norm() - 1) <= tol ? q : q.normalized();
        int d = prec.quatDecimals();
        return agg(num(fmt(u.q1(), d)), num(fmt(u.q2(), d)), num(fmt(u.q3(), d)), num(fmt(u.q4(), d)));
    }

    private Expr ext(ExtJoints e) {
        Expr[] x = new Expr[6];
        for (int k = 0; k < 6; k++) x[k] = num(fmt(e.get(k), prec.mmDecimals()));
        return agg(x);
    }

    // ---------------------------------------------------------------- statements

    private RapidAst.Stmt statement(Statement s) {
        if (s instanceof Comment c) return new RapidAst.CommentLine(stripEnd(c.text()));
        if (s instanceof ProcCall p) return new RapidAst.Call(name(p.procedure()), null, List.of());
        if (s instanceof WaitTime w) return call("WaitTime", List.of(Arg.positional(num(RapidNumbers.formatExact(w.seconds())))));
        if (s instanceof Move m) return move(m);
        if (s instanceof AstStatement a) return a.stmt();
        throw new IllegalArgumentException("cannot write " + s);
    }

    private static RapidAst.Call call(String name, List<Arg> args) { return new RapidAst.Call(name, null, args); }

    private RapidAst.Call move(Move m) {
        List<Arg> a = new ArrayList<>();
        if (m.conc()) a.add(new Arg(RapidAst.ArgKind.SWITCH, "Conc", null));
        m.circPoint().ifPresent(c -> a.add(Arg.positional(ref(c))));
        a.add(Arg.positional(ref(m.toPoint())));
        if (m.noEOffs()) a.add(new Arg(RapidAst.ArgKind.SWITCH, "NoEOffs", null));
        a.add(Arg.positional(ref(m.speed())));
        m.v().ifPresent(x -> a.add(new Arg(RapidAst.ArgKind.OPTIONAL, "V", num(fmt(Units.mToMm(x), prec.mmDecimals())))));
        m.t().ifPresent(x -> a.add(new Arg(RapidAst.ArgKind.OPTIONAL, "T", num(fmt(x, prec.otherDecimals())))));
        a.add(Arg.positional(ref(m.zone())));
        m.z().ifPresent(x -> a.add(new Arg(RapidAst.ArgKind.OPTIONAL, "Z", mmv(x))));
        a.add(Arg.positional(new RapidAst.Name(name(m.tool()))));
        m.wobj().ifPresent(w -> a.add(new Arg(RapidAst.ArgKind.OPTIONAL, "WObj", new RapidAst.Name(name(w)))));
        return call(m.kind().rapidName(), a);
    }

    private Expr ref(Ref<?> r) {
        if (r instanceof Ref.Named<?> n) return new RapidAst.Name(name(n.name()));
        return value(((Ref.Inline<?>) r).value());
    }
}
