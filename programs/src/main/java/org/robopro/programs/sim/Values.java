package org.robopro.programs.sim;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.robopro.kinematics.Units;
import org.robopro.models.Vec3;
import org.robopro.programs.ExtJoints;
import org.robopro.programs.JointTarget;
import org.robopro.programs.LoadData;
import org.robopro.programs.Quaternion;
import org.robopro.programs.RapidPose;
import org.robopro.programs.RapidValue;
import org.robopro.programs.RobTarget;
import org.robopro.programs.SpeedData;
import org.robopro.programs.ToolData;
import org.robopro.programs.WObjData;
import org.robopro.programs.ZoneData;
import org.robopro.programs.rapid.RapidAst;

/**
 * Run-time values of the interpreter, in RAPID units (mm, degrees): Double (num), Boolean,
 * String, {@link Rec} (record, components in declaration order), {@link Arr} (1-based array),
 * {@link Typed} (a typed model value not yet taken apart, kept exact) and {@link Opaque}
 * (data of types robopro does not simulate, such as signals and sockets).
 */
final class Values {
    private Values() { }

    /** A record value; type null for an aggregate not yet given a type. */
    static final class Rec {
        String type;
        final Object[] f;
        Rec(String type, Object[] f) { this.type = type; this.f = f; }
        @Override public boolean equals(Object o) { return o instanceof Rec r && Arrays.deepEquals(f, r.f); }
        @Override public int hashCode() { return Arrays.deepHashCode(f); }
    }

    static final class Arr {
        final Object[] items;
        Arr(Object[] items) { this.items = items; }
        @Override public boolean equals(Object o) { return o instanceof Arr a && Arrays.deepEquals(items, a.items); }
        @Override public int hashCode() { return Arrays.deepHashCode(items); }
    }

    record Typed(RapidValue value) { }

    record Opaque(String type) { }

    record FieldDef(String name, String type) { }

    static final Map<String, List<FieldDef>> BUILTIN = new HashMap<>();

    private static void def(String type, String... nameType) {
        List<FieldDef> l = new ArrayList<>();
        for (int k = 0; k < nameType.length; k += 2) l.add(new FieldDef(nameType[k], nameType[k + 1]));
        BUILTIN.put(type, List.copyOf(l));
    }

    static {
        def("pos", "x", "num", "y", "num", "z", "num");
        def("orient", "q1", "num", "q2", "num", "q3", "num", "q4", "num");
        def("confdata", "cf1", "num", "cf4", "num", "cf6", "num", "cfx", "num");
        def("extjoint", "eax_a", "num", "eax_b", "num", "eax_c", "num", "eax_d", "num", "eax_e", "num", "eax_f", "num");
        def("robjoint", "rax_1", "num", "rax_2", "num", "rax_3", "num", "rax_4", "num", "rax_5", "num", "rax_6", "num");
        def("robtarget", "trans", "pos", "rot", "orient", "robconf", "confdata", "extax", "extjoint");
        def("jointtarget", "robax", "robjoint", "extax", "extjoint");
        def("pose", "trans", "pos", "rot", "orient");
        def("loaddata", "mass", "num", "cog", "pos", "aom", "orient", "ix", "num", "iy", "num", "iz", "num");
        def("tooldata", "robhold", "bool", "tframe", "pose", "tload", "loaddata");
        def("wobjdata", "robhold", "bool", "ufprog", "bool", "ufmec", "string", "uframe", "pose", "oframe", "pose");
        def("speeddata", "v_tcp", "num", "v_ori", "num", "v_leax", "num", "v_reax", "num");
        def("zonedata", "finep", "bool", "pzone_tcp", "num", "pzone_ori", "num", "pzone_eax", "num", "zone_ori", "num",
                "zone_leax", "num", "zone_reax", "num");
    }

    /** Types that are num under another name (RAPID aliases of num). */
    static final java.util.Set<String> NUM_ALIASES = java.util.Set.of("num", "dnum", "errnum", "intnum", "dionum", "byte",
            "tpnum", "iounit_state", "signalorigin", "opnum", "handler_type", "event_type", "errdomain", "errtype",
            "triggmode", "buffersize", "sensorstate", "socketstatus");

    static Object copy(Object v) {
        if (v instanceof Rec r) {
            Object[] f = new Object[r.f.length];
            for (int k = 0; k < f.length; k++) f[k] = copy(r.f[k]);
            return new Rec(r.type, f);
        }
        if (v instanceof Arr a) {
            Object[] f = new Object[a.items.length];
            for (int k = 0; k < f.length; k++) f[k] = copy(a.items[k]);
            return new Arr(f);
        }
        return v;
    }

    static Rec rec(String type, Object... f) { return new Rec(type, f); }

    private static Rec pos(Vec3 m) { return rec("pos", Units.mToMm(m.x()), Units.mToMm(m.y()), Units.mToMm(m.z())); }

    private static Rec orient(Quaternion q) { return rec("orient", q.q1(), q.q2(), q.q3(), q.q4()); }

    private static Rec pose(RapidPose p) { return rec("pose", pos(p.trans()), orient(p.rot())); }

    private static Rec ext(ExtJoints e) {
        Object[] f = new Object[6];
        for (int k = 0; k < 6; k++) f[k] = e.get(k);
        return new Rec("extjoint", f);
    }

    /** A typed model value taken apart into RAPID units. */
    static Object untyped(RapidValue v) {
        if (v instanceof RapidValue.Num n) return n.value();
        if (v instanceof RapidValue.Bool b) return b.value();
        if (v instanceof RapidValue.Str s) return s.value();
        if (v instanceof RobTarget t)
            return rec("robtarget", pos(t.trans()), orient(t.rot()), rec("confdata", (double) t.robconf().cf1(), (double) t.robconf().cf4(),
                    (double) t.robconf().cf6(), (double) t.robconf().cfx()), ext(t.extax()));
        if (v instanceof JointTarget j) {
            Object[] f = new Object[6];
            for (int k = 0; k < 6; k++) f[k] = Units.radToDeg(j.robax(k));
            return rec("jointtarget", new Rec("robjoint", f), ext(j.extax()));
        }
        if (v instanceof RapidPose p) return pose(p);
        if (v instanceof LoadData l) return rec("loaddata", l.mass(), pos(l.cog()), orient(l.aom()), l.ix(), l.iy(), l.iz());
        if (v instanceof ToolData t) return rec("tooldata", t.robhold(), pose(t.tframe()), untyped(t.tload()));
        if (v instanceof WObjData w) return rec("wobjdata", w.robhold(), w.ufprog(), w.ufmec(), pose(w.uframe()), pose(w.oframe()));
        if (v instanceof SpeedData s)
            return rec("speeddata", Units.mToMm(s.vTcp()), Units.radToDeg(s.vOri()), Units.mToMm(s.vLeax()), Units.radToDeg(s.vReax()));
        if (v instanceof ZoneData z)
            return rec("zonedata", z.finep(), Units.mToMm(z.pzoneTcp()), Units.mToMm(z.pzoneOri()), Units.mToMm(z.pzoneEax()),
                    Units.radToDeg(z.zoneOri()), Units.mToMm(z.zoneLeax()), Units.radToDeg(z.zoneReax()));
        throw new IllegalArgumentException("cannot take apart " + v);
    }

    /** A run-time value as a RAPID literal (for the typed conversion of the parser). */
    static RapidAst.Expr literal(Object v) {
        if (v instanceof Typed t) v = untyped(t.value());
        if (v instanceof Double d) {
            if (!Double.isFinite(d)) throw new IllegalArgumentException("not a finite number: " + d);
            return d < 0 || (d == 0 && 1 / d < 0) ? new RapidAst.Unary("-", RapidAst.Num.of(-d)) : RapidAst.Num.of(d);
        }
        if (v instanceof Boolean b) return new RapidAst.Bool(b);
        if (v instanceof String s) return RapidAst.Str.of(s);
        Object[] items = v instanceof Rec r ? r.f : v instanceof Arr a ? a.items : null;
        if (items == null) throw new IllegalArgumentException("no literal for " + describe(v));
        List<RapidAst.Expr> l = new ArrayList<>();
        for (Object o : items) l.add(literal(o));
        return new RapidAst.Aggregate(l);
    }

    static String describe(Object v) {
        if (v instanceof Double) return "num";
        if (v instanceof Boolean) return "bool";
        if (v instanceof String) return "string";
        if (v instanceof Rec r) return r.type == null ? "aggregate" : r.type;
        if (v instanceof Arr) return "array";
        if (v instanceof Typed t) return t.value().rapidType();
        if (v instanceof Opaque o) return o.type();
        return String.valueOf(v);
    }

    static String lower(String s) { return s.toLowerCase(Locale.ROOT); }
}
