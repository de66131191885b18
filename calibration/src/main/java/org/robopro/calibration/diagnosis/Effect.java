package org.robopro.calibration.diagnosis;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.robopro.calibration.JointEffect;
import org.robopro.calibration.PoseConditions;
import org.robopro.calibration.identification.EffectBlock;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.kinematics.KinematicModel;
import org.robopro.models.EffectDescription;
import org.robopro.models.InputException;

/**
 * One candidate non-geometric effect on one joint (docs/diagnosis.md). Every effect is linear in
 * its parameters v: it perturbs the model angle of one target joint, Δθ_target = g(q, c) · v, or
 * (thermal expansion) every length by the strain ε = g(c) · v about the base origin, with g the
 * effect's regressor at controller values q under pose conditions c:
 * <ul>
 * <li>{@code joint-compliance}: g = τ_j(q, payload), the gravity torque ({@link GravityTorques}); v = compliance, rad/(N·m);</li>
 * <li>{@code gear-periodic}: g = (sin q_j, cos q_j, sin 2q_j, cos 2q_j, sin 3q_j, cos 3q_j); v rad. The gear turns
 *     with the axis's own (controller) angle q_j, which differs from θ_j only on coupled axes;</li>
 * <li>{@code backlash}: g = −dir_j / 2; v = lost motion b ≥ 0, rad. A driven output lags its motor-side
 *     encoder: after a motion in direction dir the gear flanks touch on the far side of the play, so
 *     the output angle is q − (b/2)·dir (the standard dead-band / lost-motion model of gear backlash:
 *     Nordin &amp; Gutman, "Controlling mechanical systems with backlash — a survey", Automatica 38 (2002)
 *     1633–1649, the dead-zone/hysteresis output x_out = x_in − (b/2)·sign(ẋ_in) once the play is taken up;
 *     ISO 230-2 calls the same quantity "reversal value"). To reach a target the command must lead by
 *     +(b/2)·dir, which the compensation does by inverting this model;</li>
 * <li>{@code thermal-expansion}: g = T − T0 (v = α, 1/K), or from time as a warm-up proxy
 *     g = 1 − exp(−t/τ) (v = strain at saturation);</li>
 * <li>{@code joint-scale}: g = q_j (θ_j = (1+ε) q_j); v = ε;</li>
 * <li>{@code joint-coupling}: θ_target += κ q_source; g = q_source; v = κ.</li>
 * </ul>
 * The same object is the simulator's truth ({@link #truth}) and the identification's parameter
 * block ({@link #block}). Immutable and thread-safe.
 */
public final class Effect {
    /** The effect vocabulary (the JSON names of docs/diagnosis.md and the robot file). */
    public enum Kind {
        COMPLIANCE("joint-compliance"), PERIODIC("gear-periodic"), BACKLASH("backlash"),
        THERMAL("thermal-expansion"), SCALE("joint-scale"), COUPLING("joint-coupling");

        public final String json;

        Kind(String json) { this.json = json; }

        public static Kind of(String name) {
            for (Kind k : values()) if (k.json.equals(name)) return k;
            return null;
        }
    }

    /** Harmonics of a gear-periodic effect. */
    public static final int HARMONICS = 3;

    private final Kind kind;
    private final int joint, source;        // 0-based; joint = -1 for thermal
    private final GravityTorques gravity;    // compliance only
    private final double t0C, tauS;          // thermal: reference temperature, or time constant (time proxy)

    private Effect(Kind kind, int joint, int source, GravityTorques gravity, double t0C, double tauS) {
        this.kind = kind;
        this.joint = joint;
        this.source = source;
        this.gravity = gravity;
        this.t0C = t0C;
        this.tauS = tauS;
    }

    public static Effect compliance(int joint, GravityTorques g) { return new Effect(Kind.COMPLIANCE, joint, -1, g, Double.NaN, Double.NaN); }
    public static Effect periodic(int joint) { return new Effect(Kind.PERIODIC, joint, -1, null, Double.NaN, Double.NaN); }
    public static Effect backlash(int joint) { return new Effect(Kind.BACKLASH, joint, -1, null, Double.NaN, Double.NaN); }
    public static Effect scale(int joint) { return new Effect(Kind.SCALE, joint, -1, null, Double.NaN, Double.NaN); }
    /** θ_target += κ q_source. */
    public static Effect coupling(int target, int source) { return new Effect(Kind.COUPLING, target, source, null, Double.NaN, Double.NaN); }
    /** ε = α (T − t0C). */
    public static Effect thermal(double t0C) { return new Effect(Kind.THERMAL, -1, -1, null, t0C, Double.NaN); }
    /** ε = s (1 − exp(−t/τ)): time since the start as a proxy for the warm-up. */
    public static Effect thermalFromTime(double tauS) { return new Effect(Kind.THERMAL, -1, -1, null, Double.NaN, tauS); }

    public Kind kind() { return kind; }
    /** Target joint, 0-based (-1 for thermal expansion). */
    public int joint() { return joint; }
    /** Source joint of a coupling, 0-based (-1 otherwise). */
    public int source() { return source; }
    public boolean isStrain() { return kind == Kind.THERMAL; }
    public boolean usesTimeProxy() { return kind == Kind.THERMAL && Double.isNaN(t0C); }
    public double t0C() { return t0C; }
    public double tauS() { return tauS; }
    public GravityTorques gravity() { return gravity; }

    /** Joints in the JSON sense (1-based): target, then source for a coupling; empty for thermal expansion. */
    public List<Integer> joints1() {
        if (kind == Kind.THERMAL) return List.of();
        if (kind == Kind.COUPLING) return List.of(joint + 1, source + 1);
        return List.of(joint + 1);
    }

    public int size() { return kind == Kind.PERIODIC ? 2 * HARMONICS : 1; }

    public List<String> parameterNames() {
        return switch (kind) {
            case COMPLIANCE -> List.of("c");
            case PERIODIC -> List.of("a1", "b1", "a2", "b2", "a3", "b3");
            case BACKLASH -> List.of("b");
            case THERMAL -> List.of(usesTimeProxy() ? "strain" : "alpha");
            case SCALE -> List.of("eps");
            case COUPLING -> List.of("kappa");
        };
    }

    public List<String> units() {
        return switch (kind) {
            case COMPLIANCE -> List.of("rad/(N·m)");
            case PERIODIC -> List.of("rad", "rad", "rad", "rad", "rad", "rad");
            case BACKLASH -> List.of("rad");
            case THERMAL -> List.of(usesTimeProxy() ? "1" : "1/K");
            case SCALE, COUPLING -> List.of("1");
        };
    }

    /** A short label: "backlash j2", "joint-coupling j3<-j2", "thermal-expansion". */
    public String label() {
        return switch (kind) {
            case THERMAL -> kind.json + (usesTimeProxy() ? String.format(Locale.ROOT, " (time proxy, tau %.0f s)", tauS) : "");
            case COUPLING -> kind.json + " j" + (joint + 1) + "<-j" + (source + 1);
            default -> kind.json + " j" + (joint + 1);
        };
    }

    /** Block / parameter prefix without spaces. */
    public String id() { return label().replace(' ', '.').replace("<-", "from").replace("(", "").replace(")", "").replace(",", ""); }

    /** Whether the conditions this effect needs are present on every row. */
    public boolean testableOn(List<Measurement> rows) {
        for (Measurement m : rows) {
            switch (kind) {
                case BACKLASH -> { if (m.directions() == null) return false; }
                case THERMAL -> { if (Double.isNaN(usesTimeProxy() ? m.timeS() : m.tempC())) return false; }
                default -> { }
            }
        }
        return true;
    }

    /** The regressor g (length {@link #size()}) at controller values q under conditions c. */
    public void regressor(double[] q, PoseConditions c, double[] g) {
        switch (kind) {
            case COMPLIANCE -> g[0] = gravity.torques(q, c.payloadKg())[joint];
            case PERIODIC -> {
                for (int h = 1; h <= HARMONICS; h++) {
                    g[2 * h - 2] = Math.sin(h * q[joint]);
                    g[2 * h - 1] = Math.cos(h * q[joint]);
                }
            }
            case BACKLASH -> g[0] = -0.5 * c.direction(joint); // the output lags: θ = q − (b/2)·dir
            case THERMAL -> {
                // Unknown conditions (a file without the column) contribute nothing.
                double x = usesTimeProxy() ? 1 - Math.exp(-c.timeS() / tauS) : c.tempC() - t0C;
                g[0] = Double.isFinite(x) ? x : 0;
            }
            case SCALE -> g[0] = q[joint];
            case COUPLING -> g[0] = q[source];
        }
    }

    /** The effect's value (Δθ_target in rad, or the strain) at q, c. */
    public double value(double[] v, double[] q, PoseConditions c) {
        double[] g = new double[size()];
        regressor(q, c, g);
        double s = 0;
        for (int i = 0; i < g.length; i++) s += g[i] * v[i];
        return s;
    }

    /** This effect with fixed values, as the simulator's truth or an extended model's term. */
    public JointEffect truth(double[] values) {
        double[] v = values.clone();
        if (v.length != size()) throw new IllegalArgumentException(label() + " needs " + size() + " values, got " + v.length);
        Effect self = this;
        return new JointEffect() {
            @Override public String name() { return kind.json; }

            @Override public void addDeltaTheta(KinematicModel model, double[] q, PoseConditions c, double[] dThetaOut) {
                if (!isStrain()) dThetaOut[joint] += self.value(v, q, c);
            }

            @Override public double lengthStrain(PoseConditions c) {
                return isStrain() ? self.value(v, null, c) : 0;
            }

            @Override public String toString() { return label() + " " + Arrays.toString(v); }
        };
    }

    /** This effect as an identification parameter block starting at zero. */
    public EffectBlock block() {
        Effect self = this;
        int k = size();
        return new EffectBlock() {
            @Override public String name() { return id(); }
            @Override public List<String> parameterNames() { return self.parameterNames(); }
            @Override public List<String> units() { return self.units(); }
            @Override public double[] initialValues() { return new double[k]; }

            @Override public void jointDelta(double[] values, Measurement row, double[] dTheta, double[] dThetaDv) {
                if (dThetaDv != null) Arrays.fill(dThetaDv, 0);
                if (isStrain()) return;
                double[] g = new double[k];
                regressor(row.q(), PoseConditions.of(row), g);
                double s = 0;
                for (int i = 0; i < k; i++) s += g[i] * values[i];
                dTheta[joint] += s;
                if (dThetaDv != null) System.arraycopy(g, 0, dThetaDv, joint * k, k);
            }

            @Override public void positionDelta(double[] values, Measurement row, double[] pointBase, double[] dp, double[] dpDv,
                                                double[] dpDpoint) {
                if (dpDv != null) Arrays.fill(dpDv, 0);
                if (!isStrain()) return;
                double[] g = new double[1];
                regressor(row.q(), PoseConditions.of(row), g);
                double e = g[0] * values[0];
                if (dpDpoint != null) for (int a = 0; a < 3; a++) dpDpoint[4 * a] += e; // ∂(ε p)/∂p = ε I
                for (int a = 0; a < 3; a++) {
                    dp[a] += e * pointBase[a];
                    if (dpDv != null) dpDv[a] = g[0] * pointBase[a];
                }
            }
        };
    }

    /** The robot-file form (docs/robot-file.md "effects"): parameters SI keyed by name, plus t0_c or tau_s. */
    public EffectDescription describe(double[] values) {
        Map<String, Double> p = new LinkedHashMap<>();
        List<String> names = parameterNames();
        for (int i = 0; i < names.size(); i++) p.put(names.get(i), values[i]);
        if (kind == Kind.THERMAL) {
            if (usesTimeProxy()) p.put("tau_s", tauS);
            else p.put("t0_c", t0C);
        }
        return new EffectDescription(kind.json, joints1(), p);
    }

    /** Reads an effect back from its robot-file form; values in the order of {@link #parameterNames()}. */
    public static Term fromDescription(EffectDescription d, KinematicModel model, GravityTorques gravity, String file) {
        Kind kind = Kind.of(d.effect());
        if (kind == null) throw new InputException(file, 0, 0, "effects.effect", "unknown effect '" + d.effect() + "'");
        List<Integer> js = d.joints();
        int need = switch (kind) { case THERMAL -> 0; case COUPLING -> 2; default -> 1; };
        if (js.size() != need)
            throw new InputException(file, 0, 0, "effects.joints", d.effect() + " needs " + need + " joints, got " + js);
        for (int j : js)
            if (j < 1 || j > model.dof())
                throw new InputException(file, 0, 0, "effects.joints", "joint " + j + " outside 1.." + model.dof());
        Effect e = switch (kind) {
            case COMPLIANCE -> {
                if (gravity == null)
                    throw new InputException(file, 0, 0, "mass_model", "joint-compliance needs the robot's mass_model");
                yield compliance(js.get(0) - 1, gravity);
            }
            case PERIODIC -> periodic(js.get(0) - 1);
            case BACKLASH -> backlash(js.get(0) - 1);
            case SCALE -> scale(js.get(0) - 1);
            case COUPLING -> coupling(js.get(0) - 1, js.get(1) - 1);
            case THERMAL -> d.parameters().containsKey("tau_s") ? thermalFromTime(d.parameters().get("tau_s"))
                    : thermal(require(d, "t0_c", file));
        };
        List<String> names = e.parameterNames();
        double[] v = new double[names.size()];
        for (int i = 0; i < v.length; i++) v[i] = require(d, names.get(i), file);
        return new Term(e, v);
    }

    private static double require(EffectDescription d, String key, String file) {
        Double v = d.parameters().get(key);
        if (v == null || !Double.isFinite(v))
            throw new InputException(file, 0, 0, "effects." + d.effect() + ".parameters_si." + key, "missing or not a finite number");
        return v;
    }

    /** An effect with its parameter values. */
    public record Term(Effect effect, double[] values) {
        public Term { values = values.clone(); }
        @Override public double[] values() { return values.clone(); }
    }

    @Override public String toString() { return label(); }

    /** Every effect to test on a robot: the kinds for each joint (coupling for every ordered pair), thermal once. */
    public static List<Effect> candidates(KinematicModel model, GravityTorques gravity, double t0C, double[] timeTaus) {
        List<Effect> out = new ArrayList<>();
        int n = model.dof();
        for (int j = 0; j < n; j++) {
            if (gravity != null) out.add(compliance(j, gravity));
            out.add(periodic(j));
            out.add(backlash(j));
            out.add(scale(j));
        }
        for (int k = 0; k < n; k++)
            for (int j = 0; j < n; j++) if (j != k) out.add(coupling(k, j));
        if (!Double.isNaN(t0C)) out.add(thermal(t0C));
        if (timeTaus != null) for (double t : timeTaus) out.add(thermalFromTime(t));
        return out;
    }
}
