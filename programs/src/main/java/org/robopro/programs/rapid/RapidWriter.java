package org.robopro.programs.rapid;

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
import org.robopro.programs.AstItem;
import org.robopro.programs.AstStatement;
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
 * Writes a {@link RapidModule} as a RAPID module a controller loads: two-space indentation
 * (rapidchecker's rule), upper-case keywords, no trailing spaces, a final line break. Names are
 * made valid, at most 32 characters and unique ignoring case; every change is reported.
 * Quaternions are written unit (normalised unless already unit at the file's precision, so an
 * imported file's digits survive). Numbers: see {@link RapidNumbers}.
 */
public final class RapidWriter {
    /** Decimals written for mm, degrees, quaternion components and other numbers (kg, kg m^2, s). */
    public record Precision(int mmDecimals, int degDecimals, int quatDecimals, int otherDecimals) {
        public static final Precision DEFAULT = new Precision(6, 6, 10, 9);
    }

    private static final String IND = "  ";
    private final Precision prec;
    private final Map<String, String> names = new HashMap<>(); // lower-case original -> written
    private final List<RapidExport.Rename> renames = new ArrayList<>();

    private RapidWriter(Precision prec) { this.prec = prec; }

    public static RapidExport export(RapidModule module) { return export(module, Precision.DEFAULT); }

    public static RapidExport export(RapidModule module, Precision precision) {
        return new RapidWriter(precision).write(module);
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

    private RapidExport write(RapidModule m) {
        planNames(m);
        StringBuilder b = new StringBuilder();
        String modName = RapidNames.isValid(m.name()) ? m.name() : RapidNames.sanitize(m.name());
        if (!modName.equals(m.name())) renames.add(new RapidExport.Rename("module", m.name(), modName, "not a valid RAPID name"));
        b.append("MODULE ").append(modName);
        if (!m.options().isEmpty()) b.append('(').append(String.join(", ", m.options())).append(')');
        b.append('\n');
        boolean afterDecl = false;
        for (ModuleItem item : m.items()) {
            if (item instanceof Comment c) {
                b.append(IND).append('!').append(stripEnd(c.text())).append('\n');
            } else if (item instanceof Declaration d) {
                b.append(IND).append(declaration(d)).append('\n');
                afterDecl = true;
            } else if (item instanceof Procedure p) {
                if (afterDecl || b.charAt(b.length() - 2) != '\n') b.append('\n');
                procedure(b, p);
                afterDecl = true;
            } else if (item instanceof AstItem a) {
                if (a.item() instanceof RapidAst.Routine && (afterDecl || b.charAt(b.length() - 2) != '\n')) b.append('\n');
                RapidAstWriter.item(b, a.item(), IND);
                afterDecl = !(a.item() instanceof RapidAst.CommentLine);
            }
        }
        b.append("ENDMODULE\n");
        return new RapidExport(b.toString(), renames);
    }

    private void procedure(StringBuilder b, Procedure p) {
        b.append(IND).append(p.local() ? "LOCAL " : "").append("PROC ").append(name(p.name())).append("()\n");
        for (Statement s : p.body()) {
            if (s instanceof AstStatement a) RapidAstWriter.stmt(b, a.stmt(), IND + IND);
            else b.append(IND).append(IND).append(statement(s)).append('\n');
        }
        b.append(IND).append("ENDPROC\n");
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

    // ---------------------------------------------------------------- declarations

    private String declaration(Declaration d) {
        StringBuilder b = new StringBuilder();
        if (d.scope() == Declaration.Scope.LOCAL) b.append("LOCAL ");
        if (d.scope() == Declaration.Scope.TASK) b.append("TASK ");
        b.append(d.storage().name()).append(' ').append(d.rapidType()).append(' ').append(declaredName(d)).append(":=");
        b.append(value(d.value())).append(';');
        return b.toString();
    }

    private final Set<String> written = new HashSet<>();

    private String declaredName(Declaration d) {
        String w = names.get(d.name().toLowerCase(Locale.ROOT));
        if (written.add(w.toLowerCase(Locale.ROOT))) return w;
        // A repeated name: its rename was planned in order; find it.
        for (RapidExport.Rename r : renames)
            if (r.from().equals(d.name()) && r.reason().equals("name used twice") && written.add(r.to().toLowerCase(Locale.ROOT)))
                return r.to();
        throw new IllegalStateException("no name planned for " + d.name());
    }

    /** The RAPID aggregate of a value (RobotStudio's layout: no spaces inside brackets). */
    public String value(RapidValue v) {
        if (v instanceof RobTarget t)
            return "[" + mm(t.trans()) + "," + quat(t.rot()) + ",[" + t.robconf().cf1() + "," + t.robconf().cf4() + ","
                    + t.robconf().cf6() + "," + t.robconf().cfx() + "]," + ext(t.extax()) + "]";
        if (v instanceof JointTarget j) {
            StringBuilder b = new StringBuilder("[[");
            for (int k = 0; k < 6; k++) b.append(k > 0 ? "," : "").append(deg(j.robax(k)));
            return b.append("],").append(ext(j.extax())).append(']').toString();
        }
        if (v instanceof ToolData t) return "[" + bool(t.robhold()) + "," + pose(t.tframe()) + "," + value(t.tload()) + "]";
        if (v instanceof WObjData w)
            return "[" + bool(w.robhold()) + "," + bool(w.ufprog()) + "," + quoted(w.ufmec()) + "," + pose(w.uframe()) + "," + pose(w.oframe()) + "]";
        if (v instanceof LoadData l)
            return "[" + other(l.mass()) + "," + mm(l.cog()) + "," + quat(l.aom()) + "," + other(l.ix()) + "," + other(l.iy()) + "," + other(l.iz()) + "]";
        if (v instanceof SpeedData s)
            return "[" + fmt(Units.mToMm(s.vTcp()), prec.mmDecimals()) + "," + deg(s.vOri()) + "," + fmt(Units.mToMm(s.vLeax()), prec.mmDecimals())
                    + "," + deg(s.vReax()) + "]";
        if (v instanceof ZoneData z)
            return "[" + bool(z.finep()) + "," + mmv(z.pzoneTcp()) + "," + mmv(z.pzoneOri()) + "," + mmv(z.pzoneEax()) + ","
                    + deg(z.zoneOri()) + "," + mmv(z.zoneLeax()) + "," + deg(z.zoneReax()) + "]";
        if (v instanceof RapidPose p) return pose(p);
        if (v instanceof RapidValue.Num n) return RapidNumbers.formatExact(n.value());
        if (v instanceof RapidValue.Bool bo) return bool(bo.value());
        if (v instanceof RapidValue.Str s) return quoted(s.value());
        throw new IllegalArgumentException("cannot write " + v);
    }

    /**
     * A RAPID string literal: backslashes doubled, the quote and control characters as a
     * backslash and two hex digits (RAPID also allows a doubled quote, but rapidchecker 0.1.5
     * rejects it; backslash 22 is the same character and passes both).
     */
    static String quoted(String s) {
        StringBuilder b = new StringBuilder("\"");
        for (char c : s.toCharArray()) {
            if (c == '"') b.append("\\22");
            else if (c == '\\') b.append("\\\\");
            else if (c < ' ' || c > '~') b.append(String.format("\\%02X", (int) (c & 0xFF)));
            else b.append(c);
        }
        return b.append('"').toString();
    }

    private static String bool(boolean b) { return b ? "TRUE" : "FALSE"; }

    private String pose(RapidPose p) { return "[" + mm(p.trans()) + "," + quat(p.rot()) + "]"; }

    private String mm(Vec3 p) { return "[" + mmv(p.x()) + "," + mmv(p.y()) + "," + mmv(p.z()) + "]"; }

    private String mmv(double m) { return fmt(Units.mToMm(m), prec.mmDecimals()); }

    private String deg(double rad) { return fmt(Units.radToDeg(rad), prec.degDecimals()); }

    private String other(double x) { return fmt(x, prec.otherDecimals()); }

    private static String fmt(double x, int decimals) { return RapidNumbers.format(x, decimals); }

    private String quat(Quaternion q) {
        double tol = Math.pow(10, -prec.quatDecimals()) * 10;
        Quaternion u = Math.abs(q.norm() - 1) <= tol ? q : q.normalized();
        return "[" + fmt(u.q1(), prec.quatDecimals()) + "," + fmt(u.q2(), prec.quatDecimals()) + "," + fmt(u.q3(), prec.quatDecimals())
                + "," + fmt(u.q4(), prec.quatDecimals()) + "]";
    }

    private String ext(ExtJoints e) {
        StringBuilder b = new StringBuilder("[");
        for (int k = 0; k < 6; k++) {
            double x = e.get(k);
            b.append(k > 0 ? "," : "").append(x == ExtJoints.UNUSED ? "9E+09" : fmt(x, prec.mmDecimals()));
        }
        return b.append(']').toString();
    }

    // ---------------------------------------------------------------- statements

    private String statement(Statement s) {
        if (s instanceof Comment c) return "!" + stripEnd(c.text());
        if (s instanceof ProcCall p) return name(p.procedure()) + ";";
        if (s instanceof WaitTime w) return "WaitTime " + RapidNumbers.formatExact(w.seconds()) + ";";
        if (s instanceof Move m) return move(m);
        throw new IllegalArgumentException("cannot write " + s);
    }

    private String move(Move m) {
        StringBuilder b = new StringBuilder(m.kind().rapidName()).append(' ');
        if (m.conc()) b.append("\\Conc, ");
        m.circPoint().ifPresent(c -> b.append(ref(c)).append(", "));
        b.append(ref(m.toPoint()));
        if (m.noEOffs()) b.append("\\NoEOffs");
        b.append(", ").append(ref(m.speed()));
        m.v().ifPresent(x -> b.append("\\V:=").append(fmt(Units.mToMm(x), prec.mmDecimals())));
        m.t().ifPresent(x -> b.append("\\T:=").append(fmt(x, prec.otherDecimals())));
        b.append(", ").append(ref(m.zone()));
        m.z().ifPresent(x -> b.append("\\Z:=").append(mmv(x)));
        b.append(", ").append(name(m.tool()));
        m.wobj().ifPresent(w -> b.append("\\WObj:=").append(name(w)));
        return b.append(';').toString();
    }

    private String ref(Ref<?> r) {
        if (r instanceof Ref.Named<?> n) return name(n.name());
        return value(((Ref.Inline<?>) r).value());
    }
}
