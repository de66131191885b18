package org.robopro.calibration.diagnosis;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Random;
import org.robopro.kinematics.KinematicModel;

/**
 * A non-geometric effect to inject into a simulated robot, as a user writes it on a command line
 * ({@code robopro simulate --effect}, {@code robopro controller-sim --effect}) and the
 * concealed-effect benchmark lists its cases:
 * {@code NAME[:JOINT[<-SOURCE]][=VALUE[,VALUE...]]}, joints 1-based, for example
 * {@code backlash:2}, {@code gear-periodic:1}, {@code joint-compliance:2=1e6},
 * {@code thermal-expansion}, {@code joint-scale:1=-2e-4}, {@code joint-coupling:3<-2}.
 *
 * <p>Without a joint the controller simulator's defaults apply: gear-periodic 1, joint-scale and
 * joint-coupling 3 (coupling from the joint before), backlash and joint-compliance 2.
 * Without a value the size is drawn from the realistic ranges in the table below with the caller's random
 * generator ({@link #draw}); a VALUE is in the units a user thinks in:
 * <table>
 * <caption>values</caption>
 * <tr><th>effect</th><th>VALUE</th><th>drawn from the range</th></tr>
 * <tr><td>backlash</td><td>lost motion, deg (the full play; ± half of it by direction)</td><td>0.02–0.05°</td></tr>
 * <tr><td>gear-periodic</td><td>amplitude of each of harmonics 1–3, deg (phases drawn), or six values
 *     a1,b1,a2,b2,a3,b3 in deg (Δθ = Σ a_h sin hq + b_h cos hq)</td>
 *     <td>0.004–0.01° per harmonic (0.02–0.05° on wrist axes 4–6), random phase</td></tr>
 * <tr><td>joint-compliance</td><td>joint stiffness, N·m/rad (deflection = torque / stiffness)</td><td>0.5–2·10⁶ N·m/rad</td></tr>
 * <tr><td>thermal-expansion</td><td>expansion coefficient α, 1/K (reference 20 °C)</td><td>12–23·10⁻⁶/K</td></tr>
 * <tr><td>joint-scale</td><td>scale error ε (θ = (1+ε) q)</td><td>±(1–3)·10⁻⁴</td></tr>
 * <tr><td>joint-coupling</td><td>coupling κ (θ_target += κ q_source)</td><td>±(3–10)·10⁻⁴</td></tr>
 * </table>
 * Immutable.
 *
 * @param kind   the effect
 * @param joint  target joint, 1-based (0 for thermal expansion)
 * @param source source joint of a coupling, 1-based (0 otherwise)
 * @param value  the VALUE numbers as written, or null: drawn
 */
public record EffectSpec(Effect.Kind kind, int joint, int source, double[] value) {
    /** The kinds this simulator can inject. */
    public static final java.util.Set<Effect.Kind> INJECTABLE = java.util.EnumSet.of(Effect.Kind.COMPLIANCE, Effect.Kind.PERIODIC,
            Effect.Kind.BACKLASH, Effect.Kind.THERMAL, Effect.Kind.SCALE, Effect.Kind.COUPLING);

    /** Reference temperature of a simulated thermal expansion, °C (the warm-up starts there). */
    public static final double AMBIENT_C = 20;

    public EffectSpec {
        if (kind == null) throw new IllegalArgumentException("effect kind is null");
        if (!INJECTABLE.contains(kind))
            throw new IllegalArgumentException(kind.json + " cannot be injected by this simulator (the world module simulates it)");
        value = value == null ? null : value.clone();
        if (kind == Effect.Kind.THERMAL ? joint != 0 : joint < 1)
            throw new IllegalArgumentException(kind.json + ": joint " + joint + (kind == Effect.Kind.THERMAL ? " (takes none)" : " (1-based)"));
        if ((kind == Effect.Kind.COUPLING) != (source > 0) || (kind == Effect.Kind.COUPLING && source == joint))
            throw new IllegalArgumentException(kind.json + ": source joint " + source);
        if (value != null) {
            int n = value.length;
            if (!(n == 1 || (kind == Effect.Kind.PERIODIC && n == 2 * Effect.HARMONICS)))
                throw new IllegalArgumentException(kind.json + " takes one value" + (kind == Effect.Kind.PERIODIC ? " or six" : "") + ", got " + n);
            for (double v : value) if (!Double.isFinite(v)) throw new IllegalArgumentException(kind.json + ": value " + v + " is not finite");
            if (kind == Effect.Kind.BACKLASH && !(value[0] >= 0)) throw new IllegalArgumentException("backlash: lost motion must be >= 0 deg");
            if (kind == Effect.Kind.COMPLIANCE && !(value[0] > 0)) throw new IllegalArgumentException("joint-compliance: stiffness must be > 0 N·m/rad");
        }
    }

    @Override public double[] value() { return value == null ? null : value.clone(); }

    @Override public boolean equals(Object o) {
        return o instanceof EffectSpec e && e.kind == kind && e.joint == joint && e.source == source && Arrays.equals(e.value, value);
    }

    @Override public int hashCode() { return (kind.hashCode() * 31 + joint) * 31 + source + 7 * Arrays.hashCode(value); }

    /** The spec with a drawn size (no VALUE). */
    public static EffectSpec of(Effect.Kind kind, int joint) {
        return new EffectSpec(kind, kind == Effect.Kind.THERMAL ? 0 : joint, 0, null);
    }

    /** The spec of an effect (no VALUE); {@code of(e).withSize(values)} writes a term back as text. */
    public static EffectSpec of(Effect e) {
        return new EffectSpec(e.kind(), e.joint() + 1, e.kind() == Effect.Kind.COUPLING ? e.source() + 1 : 0, null);
    }

    public static EffectSpec coupling(int target, int source) { return new EffectSpec(Effect.Kind.COUPLING, target, source, null); }

    public static EffectSpec thermal() { return new EffectSpec(Effect.Kind.THERMAL, 0, 0, null); }

    /** This spec with an explicit VALUE (units as in the class comment). */
    public EffectSpec withValue(double... v) { return new EffectSpec(kind, joint, source, v); }

    /**
     * Parses {@code NAME[:JOINT[<-SOURCE]][=VALUE[,VALUE...]]}; the names of the diagnosis
     * vocabulary, case-insensitive. {@code joint-coupling:J} means J from J−1.
     *
     * @throws IllegalArgumentException naming the spec and what is wrong
     */
    public static EffectSpec parse(String text) {
        String s = text.strip().toLowerCase(Locale.ROOT);
        String valuePart = null;
        int eq = s.indexOf('=');
        if (eq >= 0) {
            valuePart = s.substring(eq + 1).strip();
            s = s.substring(0, eq).strip();
        }
        int colon = s.indexOf(':');
        String name = (colon < 0 ? s : s.substring(0, colon)).strip();
        Effect.Kind kind = Effect.Kind.of(name);
        if (kind == null || !INJECTABLE.contains(kind)) throw new IllegalArgumentException("effect '" + text + "': unknown effect '" + name + "'; known: " + names()
                + " (NAME[:JOINT[<-SOURCE]][=VALUE])");
        int joint = switch (kind) {
            case THERMAL -> 0;
            case PERIODIC -> 1;
            case SCALE, COUPLING -> 3;
            default -> 2;
        };
        int source = 0;
        if (colon >= 0) {
            if (kind == Effect.Kind.THERMAL) throw new IllegalArgumentException("effect '" + text + "': thermal-expansion takes no joint");
            String js = s.substring(colon + 1).strip();
            int arrow = js.indexOf("<-");
            if (arrow >= 0) {
                if (kind != Effect.Kind.COUPLING)
                    throw new IllegalArgumentException("effect '" + text + "': only joint-coupling takes TARGET<-SOURCE");
                source = integer(text, js.substring(arrow + 2).strip());
                js = js.substring(0, arrow).strip();
            }
            joint = integer(text, js);
        }
        if (kind == Effect.Kind.COUPLING && source == 0) source = joint - 1;
        if (kind != Effect.Kind.THERMAL && joint < 1) throw new IllegalArgumentException("effect '" + text + "': joint " + joint + " must be >= 1");
        if (kind == Effect.Kind.COUPLING && (source < 1 || source == joint))
            throw new IllegalArgumentException("effect '" + text + "': coupling source joint " + source + " must be >= 1 and differ from the target");
        double[] value = null;
        if (valuePart != null) {
            String[] parts = valuePart.split(",");
            value = new double[parts.length];
            for (int i = 0; i < parts.length; i++) {
                try {
                    value[i] = Double.parseDouble(parts[i].strip());
                } catch (NumberFormatException e) {
                    throw new IllegalArgumentException("effect '" + text + "': value '" + parts[i].strip() + "' is not a number");
                }
            }
        }
        try {
            return new EffectSpec(kind, joint, source, value);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("effect '" + text + "': " + e.getMessage());
        }
    }

    public static List<EffectSpec> parseAll(List<String> texts) {
        List<EffectSpec> out = new ArrayList<>();
        for (String t : texts) out.add(parse(t));
        return out;
    }

    private static int integer(String text, String s) {
        try {
            return Integer.parseInt(s);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("effect '" + text + "': joint '" + s + "' is not a number");
        }
    }

    /** The effect names, comma separated. */
    public static String names() {
        return String.join(", ", INJECTABLE.stream().map(k -> k.json).toList());
    }

    /** Canonical text, parseable by {@link #parse}: "joint-coupling:3<-2", "backlash:2=0.03". */
    @Override public String toString() {
        StringBuilder sb = new StringBuilder(kind.json);
        if (kind != Effect.Kind.THERMAL) sb.append(':').append(joint);
        if (kind == Effect.Kind.COUPLING) sb.append("<-").append(source);
        if (value != null) {
            sb.append('=');
            for (int i = 0; i < value.length; i++) sb.append(i > 0 ? "," : "").append(value[i]);
        }
        return sb.toString();
    }

    /**
     * The effect on {@code model}; {@code gravity} (the robot's mass model) is needed for
     * joint-compliance only.
     *
     * @throws IllegalArgumentException if a joint is outside the robot or compliance has no mass model
     */
    public Effect effect(KinematicModel model, GravityTorques gravity) {
        int dof = model.dof();
        if (joint > dof || source > dof)
            throw new IllegalArgumentException("effect '" + this + "': joint outside 1.." + dof + " of " + model.description().name());
        return switch (kind) {
            case COMPLIANCE -> {
                if (gravity == null)
                    throw new IllegalArgumentException("effect '" + this + "': " + model.description().name() + " has no mass_model for gravity torques");
                yield Effect.compliance(joint - 1, gravity);
            }
            case PERIODIC -> Effect.periodic(joint - 1);
            case BACKLASH -> Effect.backlash(joint - 1);
            case THERMAL -> Effect.thermal(AMBIENT_C);
            case SCALE -> Effect.scale(joint - 1);
            case COUPLING -> Effect.coupling(joint - 1, source - 1);
            default -> throw new IllegalArgumentException(kind.json + " cannot be injected");
        };
    }

    /**
     * The effect with its values (SI, in the order of {@link Effect#parameterNames()}): the VALUE
     * converted, or drawn from the ranges of the class table with {@code rng} (the draw takes the same numbers
     * from {@code rng} whatever the robot, so a seed gives the same sizes).
     */
    public Effect.Term draw(KinematicModel model, GravityTorques gravity, Random rng) {
        Effect e = effect(model, gravity);
        double[] v = switch (kind) {
            case COMPLIANCE -> new double[] {1 / (value != null ? value[0] : uniform(rng, 0.5e6, 2e6))};
            case PERIODIC -> periodicValues(rng);
            case BACKLASH -> new double[] {Math.toRadians(value != null ? value[0] : uniform(rng, 0.02, 0.05))};
            case THERMAL -> new double[] {value != null ? value[0] : uniform(rng, 12e-6, 23e-6)};
            case SCALE -> new double[] {value != null ? value[0] : signed(rng, 1e-4, 3e-4)};
            case COUPLING -> new double[] {value != null ? value[0] : signed(rng, 3e-4, 10e-4)};
            default -> throw new IllegalArgumentException(kind.json + " cannot be injected");
        };
        return new Effect.Term(e, v);
    }

    private double[] periodicValues(Random rng) {
        double[] v = new double[2 * Effect.HARMONICS];
        if (value != null && value.length == v.length) {
            for (int i = 0; i < v.length; i++) v[i] = Math.toRadians(value[i]);
            return v;
        }
        boolean wrist = joint >= 4; // the table: a larger range on wrist axes 4-6
        for (int h = 0; h < Effect.HARMONICS; h++) {
            double a = Math.toRadians(value != null ? value[0] : wrist ? uniform(rng, 0.02, 0.05) : uniform(rng, 0.004, 0.01));
            double ph = 2 * Math.PI * rng.nextDouble();
            v[2 * h] = a * Math.cos(ph);
            v[2 * h + 1] = a * Math.sin(ph);
        }
        return v;
    }

    /**
     * What a simulation's truth file records for an injected effect: the spec, the effect and its
     * joints (1-based), the parameters in SI and the size in the VALUE's units.
     */
    public static Map<String, Object> truthEntry(EffectSpec spec, Effect.Term t) {
        Map<String, Object> m = new LinkedHashMap<>();
        Effect e = t.effect();
        double[] v = t.values();
        m.put("spec", spec.withSize(v).toString());
        m.put("effect", e.kind().json);
        m.put("joints", e.joints1());
        Map<String, Object> p = new LinkedHashMap<>();
        List<String> names = e.parameterNames();
        for (int i = 0; i < names.size(); i++) p.put(names.get(i), v[i]);
        if (e.kind() == Effect.Kind.THERMAL) p.put("t0_c", e.t0C());
        m.put("parameters_si", p);
        m.put("units_si", e.units());
        m.put("value", spec.withSize(v).value);
        m.put("value_unit", valueUnit(e.kind()));
        return m;
    }

    /** The spec with the VALUE of these SI values (so that its text reproduces them exactly). */
    public EffectSpec withSize(double[] si) {
        return switch (kind) {
            case COMPLIANCE -> withValue(1 / si[0]);
            case BACKLASH -> withValue(Math.toDegrees(si[0]));
            case PERIODIC -> withValue(Arrays.stream(si).map(Math::toDegrees).toArray());
            default -> withValue(si[0]);
        };
    }

    /** The unit of a VALUE of this kind. */
    public static String valueUnit(Effect.Kind kind) {
        return switch (kind) {
            case COMPLIANCE -> "N·m/rad (stiffness)";
            case BACKLASH -> "deg (lost motion)";
            case PERIODIC -> "deg";
            case THERMAL -> "1/K";
            case SCALE, COUPLING -> "1";
            default -> "";
        };
    }

    static double uniform(Random r, double lo, double hi) { return lo + (hi - lo) * r.nextDouble(); }

    static double signed(Random r, double lo, double hi) { return (r.nextBoolean() ? 1 : -1) * uniform(r, lo, hi); }
}
