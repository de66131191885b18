package org.robopro.calibration.diagnosis;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeSet;
import org.robopro.calibration.JointEffect;
import org.robopro.calibration.PoseConditions;
import org.robopro.calibration.identification.EffectBlock;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.EffectDescription;
import org.robopro.models.InputException;
import org.robopro.models.Vec3;

/**
 * One candidate non-geometric effect (docs/diagnosis.md). Every effect is linear in its
 * parameters v and acts in one of three places, with g its regressor at controller values q
 * under pose conditions c:
 * <ul>
 * <li><b>on a drive</b>: the output of drive j differs from what its motor-side encoder (the
 *     controller's value q_j) says, q_out,j = q_j + g(q, c)·v, before the controller's coupling
 *     θ = C q_out (a parallel-arm linkage passes a drive's error on to every model angle it feeds):
 *     <ul>
 *     <li>{@code joint-compliance}: g = (Cᵀτ)_j, the gravity torque on drive j (virtual work through the
 *         linkage; {@link GravityTorques}); v = compliance, rad/(N·m). With the mass model re-estimated, one
 *         column per mass of the robot file (and the payload), each with its own coefficient;</li>
 *     <li>{@code gear-periodic}: g = (sin h q_j, cos h q_j) for each harmonic h of the effect (1–3 for a
 *         single-stage gear, any h the locate scan finds for multi-stage and cycloidal reducers); v rad;</li>
 *     <li>{@code backlash}: g = −dir_j / 2; v = lost motion b ≥ 0, rad. A driven output lags its motor-side
 *         encoder: after a motion in direction dir the gear flanks touch on the far side of the play, so the
 *         output is q − (b/2)·dir (the dead-band / lost-motion model of gear backlash: Nordin &amp; Gutman,
 *         "Controlling mechanical systems with backlash — a survey", Automatica 38 (2002) 1633–1649;
 *         ISO 230-2 calls b the reversal value). To reach a target the command leads by +(b/2)·dir,
 *         which the compensation does by inverting this model;</li>
 *     <li>{@code joint-scale}: g = q_j; v = ε (gear ratio); {@code joint-coupling}: g = q_source; v = κ;</li>
 *     <li>{@code joint-smooth-error}: g = cubic B-spline basis of q_j over the joint's range
 *         ({@link #SMOOTH_BASIS} functions, uniform knots): an angle-dependent error none of the physical
 *         families explains (the honest fallback);</li>
 *     </ul></li>
 * <li><b>on every length</b> ({@code thermal-expansion}): ε = g·v about the base origin, g = T − T0
 *     (v = α, 1/K), or from time as a warm-up proxy g = 1 − exp(−t/τ);</li>
 * <li><b>on the measured point</b>, an additive Δp in base coordinates: {@code thermal-link}, each link
 *     grows by its own α_i, Δp = (T − T0) Σ α_i s_i(q) with s_i the link's vector from one joint frame to
 *     the next (the last to the measured point); {@code instrument-drift}, Δp = x·d with x = T − T0 or
 *     the hours since the start (the instrument, or the base, moves).</li>
 * </ul>
 * The same object is the identification's parameter block ({@link #block}) and an extended
 * model's term ({@link ExtendedModel}). Immutable and thread-safe.
 */
public final class Effect {
    /** The effect vocabulary (JSON names) with a title in words. */
    public enum Kind {
        COMPLIANCE("joint-compliance", "Joint compliance (the joint gives way under gravity)"),
        PERIODIC("gear-periodic", "Periodic transmission error (gear or encoder)"),
        BACKLASH("backlash", "Backlash (lost motion, the output lags the motor)"),
        THERMAL("thermal-expansion", "Thermal expansion (uniform)"),
        THERMAL_LINK("thermal-link", "Thermal growth link by link"),
        DRIFT("instrument-drift", "Drift of the instrument or base"),
        SCALE("joint-scale", "Joint scale error (gear ratio or encoder)"),
        COUPLING("joint-coupling", "Joint coupling"),
        SMOOTH("joint-smooth-error", "Angle-dependent joint error of no known family"),
        GRAVITY_PLAY("joint-gravity-play", "A joint's play taken up by gravity: its output rests on the side the gravity torque "
                + "pushes it to, whatever the last motion (a clearance in the joint's bearing, gear or linkage), of no known family"),
        COMPLIANCE_VARYING("joint-compliance-varying", "A joint's give under gravity that changes through the campaign: with "
                + "temperature (a stiffness that softens as the joint warms) or with time (a carried mass that changes, a dispensing "
                + "tool emptying, while the recorded payload stays), of no known family"),
        LINK_PERIODIC("link-angle-periodic", "A joint's error that repeats with the angle of its link against the link before it "
                + "(or against the ground), or with the angle of a wrist housing its drive passes through, not with its drive's own turn: "
                + "a parallel linkage's rod, lever or bearing, an oval bearing seat or a bevel pair in the wrist, of no known family"),
        WARM_PERIODIC("joint-periodic-warming", "A joint's periodic error whose size changes with the temperature (a magnetic or "
                + "optical encoder whose sine and cosine channels drift apart as it warms, so its error twice per turn grows with the "
                + "temperature), of no known family"),
        LOAD_PERIODIC("joint-load-periodic", "A joint's periodic error whose size follows the gravity torque on the joint (a gear mesh "
                + "deflecting more under load), of no known family"),
        PAIR("joint-pair-error", "Joint error depending on two joints at once, of no known family"),
        POINT_SMOOTH("point-smooth-error", "Displacement of the measured point with its reach, height, time or temperature, of no known family"),
        BASE_TURN("base-turn", "The robot's base or the instrument turning with time or temperature, of no known family"),
        ZERO_DRIFT("joint-zero-drift", "Joint zero that moves with time or temperature, of no known family"),
        ZERO_STEP("joint-zero-step", "Joint zero that jumped at one time during the campaign, of no known family"),
        SETTLING("joint-settling", "A joint's deflection that follows the move made just before the reading (the arm read before "
                + "it settled: a residual vibration after the stop, a servo's following error), of no known family"),
        ANGLE_STEP("joint-angle-step", "Joint reading that jumps where the joint passes one angle, of no known family"),
        BASE_CREEP("base-creep", "The robot's base turning on its floor a little with each large move of joint 1 (its anchor "
                + "bolts slipping under the move's reaction), of no known family"),
        TARGET_DRIFT("target-drift", "Measured point that moves on the flange with time (a tool or holder that grows or creeps as a "
                + "spindle or the tool warms), of no known family"),
        TARGET_STEP("target-step", "Measured point that moved on the flange at one time during the campaign, of no known family"),
        BASE_STEP("base-step", "The measuring instrument and the robot's base that moved against each other at one time during the "
                + "campaign (the instrument knocked, the base slipped), of no known family"),
        SECOND_STATION("second-station", "The poses whose target faces one side, measured from a second instrument station (a second "
                + "tracker, or the one moved), turned and shifted against the rest: the stations' registration into one frame is off, not "
                + "the robot, of no known family"),
        RANGE_STEP("range-step", "The measuring instrument's distances that jumped at one time during the campaign (its distance "
                + "taken again after the beam was broken), not the robot, of no known family"),
        INSTRUMENT("instrument-reading-error", "Error of the measuring instrument's distance or angle readings, not of the robot"),
        REFRACTION("beam-refraction", "The measured points seen higher or lower by the square of their horizontal distance from the "
                + "instrument, changing with time or temperature: the instrument's beam bent by a vertical temperature gradient in the "
                + "air (refraction), not the robot, of no known family"),
        INSTRUMENT_SCALE("instrument-scale", "The measuring instrument's distances scaling with time or temperature (its air "
                + "compensation), not the robot, of no known family"),
        INSTRUMENT_AXES("instrument-axes", "The measuring instrument's axes out of square or scaled one against another (a "
                + "coordinate measuring machine's squareness, a camera system's depth scale), not the robot, of no known family"),
        BASE_TILT("base-tilt", "The robot's base tilting on its foundation under the arm's weight, of no known family"),
        AXIS_WOBBLE("axis-wobble", "A joint's axis tilting as the joint turns (its bearing wobbles), of no known family"),
        AXIAL_RUNOUT("axial-runout", "The arm beyond a joint moving along the joint's axis as it turns (its bearing runs out "
                + "axially), of no known family"),
        TOOL_SAG("tool-sag", "The measured point's holder bending under its own weight, of no known family"),
        TOOL_PLAY("tool-play", "The measured point's holder or the flange tipping within a clearance toward gravity, of no known family"),
        TARGET_INCIDENCE("target-incidence", "Error of the measured point that follows the direction the instrument sees it from, "
                + "in the tool's frame: a reflector seen off its axis, of no known family"),
        LINK_SAG("link-sag", "An arm link bending under gravity as a beam, of no known family"),
        LINK_TWIST("link-twist", "The upper arm twisting about its long axis under the weights beyond it, of no known family"),
        LOAD_TILT("axis-load-tilt", "A joint's axis tilting across itself with the torque its drive carries (the gear mesh's "
                + "tooth and separating forces bending the output shaft on its bearings), of no known family"),
        TOOL_PULL("tool-pull", "A steady pull on the tool from outside the robot (a hose or cable retractor, a balancer, a dress pack "
                + "hung from a boom), each joint yielding to it through its stiffness, of no known family");

        public final String json;
        public final String title;

        Kind(String json, String title) {
            this.json = json;
            this.title = title;
        }

        public static Kind of(String name) {
            for (Kind k : values()) if (k.json.equals(name)) return k;
            return null;
        }
    }

    /** Where an effect acts. */
    public enum Target { DRIVE, STRAIN, POSITION }

    /** The variable of a fallback that follows a scalar: the measured point's reach or height, time, temperature. */
    public enum Along {
        REACH("reach", "reach", "m"), HEIGHT("height", "height", "m"), TIME("time", "time_s", "s"), TEMPERATURE("temperature", "temp_c", "°C"),
        /** The payload times a smooth function of the reach: an arm that bends more with load the farther it reaches. */
        PAYLOAD_REACH("payload and reach", "payload_reach", "m");

        public final String words, key, unit;

        Along(String words, String key, String unit) {
            this.words = words;
            this.key = key;
            this.unit = unit;
        }
    }

    /**
     * What an error of a spherical-coordinate instrument (a laser tracker: a distance meter on a
     * gimbal with two angle encoders) follows: its distance reading to the point, or its azimuth or
     * elevation reading. A distance-meter error moves the point along the line of sight; an angle
     * encoder's error moves it across the line of sight by the distance (horizontal distance for
     * the azimuth) times the angle error (the tracker's own model of its errors: Muralikrishnan et
     * al., "Laser trackers for large-scale dimensional metrology: a review", Precision Engineering
     * 44 (2016) 13, §3; ASME B89.4.19-2006 range and angle tests).
     */
    public enum Sight {
        RANGE("distance", "range_m", "m"), AZIMUTH("azimuth", "azimuth_rad", "rad"), ELEVATION("elevation", "elevation_rad", "rad");

        public final String words, key, unit;

        Sight(String words, String key, String unit) {
            this.words = words;
            this.key = key;
            this.unit = unit;
        }
    }

    /** The payload must vary by this much for a compliance with the masses unknown to be tested, kg. */
    static final double MIN_PAYLOAD_SPAN_KG = 0.1;
    /** Harmonics of a default (single-stage) gear-periodic effect. */
    public static final int HARMONICS = 3;
    private static final int[] LOW = {1, 2, 3};
    /** Basis functions of the smooth fallback (the coarsest resolution; {@link #SMOOTH_RESOLUTIONS}). */
    public static final int SMOOTH_BASIS = 7;
    /**
     * Resolutions (basis functions) of the smooth per-joint fallback: 7 follows a slow drift over the
     * range, 25 a place-bound error about a tenth of the range wide (a bump, a damaged gear stretch).
     */
    static final int[] SMOOTH_RESOLUTIONS = {7, 13, 25};
    /** Poses needed per basis function of a smooth fallback. */
    static final int POSES_PER_BASIS = 6;

    /**
     * Whether {@code poses} support a curve of {@code nb} functions: the coarsest resolution of its
     * kind ({@code coarsest}) always, a finer one with {@link #POSES_PER_BASIS} poses per function.
     */
    static boolean supported(int nb, int coarsest, int poses) { return nb <= coarsest || nb * POSES_PER_BASIS <= poses; }

    /** Basis functions of the point's smooth displacement along reach or height (per axis). */
    public static final int POINT_BASIS = 4;
    /** Gravity's direction in the base frame the tool sag takes: straight down the base's z (a robot standing on the floor). */
    public static final Vec3 DOWN = new Vec3(0, 0, -1);
    /** Links shorter than this do not get their own thermal coefficient, m. */
    static final double MIN_LINK_M = 0.05;

    private final Kind kind;
    private final int joint, source;        // 0-based; -1 when none
    private final GravityTorques gravity;    // compliance only
    private final boolean perMass;           // compliance: one coefficient per mass
    private boolean stiffens;                // compliance: a spring that stiffens with its load, Δq = c·τ + c3·τ³
    private boolean atJoint;                 // compliance: the joint's own angle gives under the torque about its axis, not the drive
    private boolean bowed;                   // instrument axes: its ways bowed as well
    private double[] driveShares;            // the drives a joint's own give moves (C⁻¹ e_j), null for a drive's
    private final double t0C, tauS;          // thermal / drift: reference temperature, or time constant (NaN)
    private final int[] harmonics;           // periodic
    private double[] stages = new double[0]; // periodic: orders that are not whole (an intermediate shaft's turns per output turn)
    private final double lo, hi;             // smooth: range of q_j
    private final KinematicModel model;      // thermal-link: the frames
    private final int[] links;               // thermal-link: frame indices i whose vector s_i (frame i -> i+1) grows
    private final int nBasis;                // smooth, point-smooth, zero-drift: spline functions (per axis)
    private Along along;                     // point-smooth, zero-drift: the variable
    private double buildUp = Double.NaN;     // backlash that builds up over the move: the build-up length (rad); NaN: constant
    private Directions.Moves moves = Directions.Moves.NONE; // that backlash, a settling: each row's last move
    private double[] speeds;                 // a settling: each joint's top speed (rad/s; NaN or null: unknown, taken alike)
    private double approach = Double.NaN;    // that backlash: the approach move before each pose (rad); NaN: none in the program
    private double[] runout = new double[0]; // backlash whose play changes over the turn of its joint (b + Σ b_cos,f cos f q + b_sin,f sin f q): the orders f
    private double preloadNm = Double.NaN;   // backlash held on one flank by gravity: the torque above which it is held (N·m); NaN: free
    private double preloadWidth;             // that backlash: half-width of the hand-over, a share of preloadNm (0: a sharp one)
    private double[] massScales;             // that backlash, a base tilt: the file's masses re-estimated by a factor each (null: as in the file)
    private ThermalLag lag;                  // thermal-link: the campaign's temperature history (null: no lag)
    private double[] lagTaus;                // thermal-link: each column's lag time constant, s (0: none)
    private double[] warmTaus;               // thermal-link: each link's warm-up time constant by its drives, s (null: the air's temperature only)
    private Pauses pauses;                   // that warm-up: when the robot rested during the campaign (null: never, as far as known)
    private Vec3 down;                       // tool sag, link sag and twist: gravity's direction, base frame (unit)
    private boolean sagPayload;              // link sag and twist: columns of the payload's weight
    private boolean playTurns;               // tool play: the flange also tips (its orientation measured), four more columns
    private Sight sight;                     // instrument reading: the reading it follows
    private Pose instrument;                 // instrument reading, target incidence: instrumentTbase, fixed where the geometric fit put it
    private Vec3 sightAxis;                  // target incidence: the mean direction the point is seen from, flange frame (unit)
    private Vec3 sightOrigin;                // target incidence: the instrument's origin, base frame (from instrument)
    private Vec3[] sightAcross;              // target incidence: two unit vectors across sightAxis (acrossAxis)
    private double azimuthRef;               // instrument reading: the azimuth the data's angles are taken about (no wrap inside)
    private double cycle = Double.NaN;       // instrument reading: the period of a cyclic error of the reading (NaN: a spline)
    private double tiltAzimuth, tiltHold;    // base tilt: the azimuth of its axis (rad; NaN: the moment's own), the moment held before it tilts (N·m; −∞: none)
    private int tiltEdges = 1;               // base tilt: 1, one edge; 4, a square foot's edges at the axis azimuth + k·90°
    private double loadRefNm = Double.NaN;   // load-periodic: the torque its load columns are scaled by (N·m)
    private double[] creepTimes, creepSlips;   // base creep: each move's time (s) and its slip's sign (0: a move too small)
    private double sideNm, sideWidthNm;      // gravity play: the torque where the side changes, the hand-over's half-width (0: sharp), N·m
    private boolean loadMagnitude;           // load-periodic: the size follows |τ| (true) or τ with its sign
    private boolean payloadShare;            // varying compliance: the payload's share of the torque alone
    private double[] stepTimes;              // varying compliance in steps: the times (s) its compliance steps at (null: a spline)
    private boolean payloadCentreFree;       // varying payload compliance: the payload's centre estimated with it (four columns a function)
    private double[] linkAngle;              // link-angle periodic: the angle it repeats with, Σ linkAngle[l]·q_l
    private Vec3 attach;                     // tool pull: where the pull acts, flange frame
    private double[] anchor;                 // tool pull: the fixed point it pulls toward, base frame (null: a pull of one direction)
    private GravityTorques fileGravity;      // load tilt: the masses before their scales
    private Vec3 facing;                     // second station: the poses whose flange axis has a positive part along it (base frame, unit)
    private double[] stations;               // second station, by where the stations stand: the first's and the second's origins (base frame), or null

    private Effect(Kind kind, int joint, int source, GravityTorques gravity, boolean perMass, double t0C, double tauS,
                   int[] harmonics, double lo, double hi, KinematicModel model, int[] links) {
        this(kind, joint, source, gravity, perMass, t0C, tauS, harmonics, lo, hi, model, links, 0);
    }

    private Effect(Kind kind, int joint, int source, GravityTorques gravity, boolean perMass, double t0C, double tauS,
                   int[] harmonics, double lo, double hi, KinematicModel model, int[] links, int nBasis) {
        this.nBasis = nBasis;
        this.kind = kind;
        this.joint = joint;
        this.source = source;
        this.gravity = gravity;
        this.perMass = perMass;
        this.t0C = t0C;
        this.tauS = tauS;
        this.harmonics = harmonics;
        this.lo = lo;
        this.hi = hi;
        this.model = model;
        this.links = links;
    }

    private static Effect drive(Kind k, int joint) {
        return new Effect(k, joint, -1, null, false, Double.NaN, Double.NaN, null, Double.NaN, Double.NaN, null, null);
    }

    public static Effect compliance(int joint, GravityTorques g) {
        return new Effect(Kind.COMPLIANCE, joint, -1, g, false, Double.NaN, Double.NaN, null, Double.NaN, Double.NaN, null, null);
    }

    /** Compliance with every mass of the file (and the payload) scaled by its own factor: the mass model re-estimated. */
    public static Effect complianceRemassed(int joint, GravityTorques g) {
        return new Effect(Kind.COMPLIANCE, joint, -1, g, true, Double.NaN, Double.NaN, null, Double.NaN, Double.NaN, null, null);
    }

    /**
     * Compliance of a spring that stiffens with its load: Δq = c·τ + c₃·τ³ on the file's masses, c₃ &lt; 0
     * for a stiffness that rises with the torque. Reducers stiffen so: strain-wave (Harmonic Drive)
     * and cycloidal (RV) gears are catalogued with torsional stiffnesses K1 &lt; K2 &lt; K3 over rising
     * torque ranges (Harmonic Drive AG, CSG/CSD catalogues, "Torsional stiffness"), and Tuttle &amp;
     * Seering, IEEE Trans. Robotics and Automation 12 (1996) 368, measured a stiffness growing with
     * the torque. The cubic is the first odd term of a smooth torque-torsion curve.
     */
    public static Effect complianceStiffening(int joint, GravityTorques g) {
        Effect e = compliance(joint, g);
        e.stiffens = true;
        return e;
    }

    /** Whether this is a compliance that stiffens with its load ({@link #complianceStiffening}). */
    public boolean stiffens() { return stiffens; }

    /**
     * A joint whose own angle gives under the gravity torque about its axis: Δθ_j = c·τ_j (τ_j of
     * everything beyond joint j, {@link GravityTorques#torques}), the spring in the joint (its bearing,
     * its housing, the structure it turns in) rather than in the drive's gear. On a serial arm the two
     * are one; on a parallel arm (θ3 = q3 − q2) the gear of drive 2 feels τ2 − τ3 (virtual work,
     * {@link GravityTorques#driveTorques}) while a give of joint 2's own angle turns the whole arm
     * beyond it, forearm included, by τ2: drives 2 and 3 both move, Δq = C⁻¹ e_j Δθ_j. Serial-chain
     * stiffness models take this form (Dumas, Caro, Garnier &amp; Furet, "Joint stiffness
     * identification of six-revolute industrial serial robots", Robotics and Computer-Integrated
     * Manufacturing 27 (2011) 881; Abele, Weigold &amp; Rothenbücher, CIRP Annals 56 (2007) 387).
     * {@code perMass}: one coefficient per mass, as {@link #complianceRemassed}.
     */
    public static Effect complianceAtJoint(int joint, GravityTorques g, boolean perMass) {
        Effect e = new Effect(Kind.COMPLIANCE, joint, -1, g, perMass, Double.NaN, Double.NaN, null, Double.NaN, Double.NaN, null, null);
        e.atJoint = true;
        e.driveShares = jointsDrives(g.model(), joint);
        return e;
    }

    /** The drives' values that turn joint {@code joint}'s own angle by one and no other joint's: C⁻¹ e_j. */
    private static double[] jointsDrives(KinematicModel model, int joint) {
        double[] unit = new double[model.dof()];
        unit[joint] = 1;
        return model.q(unit);
    }

    /** Whether a joint's own give ({@link #complianceAtJoint}) moves other drives than its own: the coupling makes it differ from the drive's. */
    public static boolean atJointDiffers(KinematicModel model, int joint) {
        double[] d = jointsDrives(model, joint);
        for (int i = 0; i < d.length; i++) if (i != joint && d[i] != 0) return true;
        return false;
    }

    /** Whether this compliance is of the joint's own angle ({@link #complianceAtJoint}). */
    public boolean atJoint() { return atJoint; }

    /** d(residual)/ds of a drive effect's s at one row, from the row's derivatives by drive {@code dq[at..at+dof)}. */
    public double driveDerivative(double[] dq, int at) {
        if (driveShares == null) return dq[at + joint];
        double d = 0;
        for (int i = 0; i < driveShares.length; i++) if (driveShares[i] != 0) d += driveShares[i] * dq[at + i];
        return d;
    }

    /** Adds a drive effect's Δ to the drives' values: to drive {@link #joint()}, or for a joint's own give C⁻¹ e_j times it. */
    public void addToDrives(double delta, double[] q) {
        if (driveShares == null) { q[joint] += delta; return; }
        for (int i = 0; i < driveShares.length; i++) q[i] += driveShares[i] * delta;
    }

    /** The gravity torque this compliance's coefficient multiplies at q: the drive's, or the joint's own ({@link #complianceAtJoint}). */
    public double complianceTorque(double[] q, double payloadKg) {
        return atJoint ? gravity.torques(q, payloadKg)[joint] : gravity.driveTorques(q, payloadKg)[joint];
    }

    /** A stiffening compliance as a linear spring on the same masses (itself when it is not one). */
    public static Effect withoutStiffening(Effect e) { return e.stiffens ? compliance(e.joint, e.gravity) : e; }

    /**
     * A joint's give under gravity that changes through the campaign: Δq = τ·s(x), τ the gravity
     * torque on drive {@code joint} ({@code g}'s masses with the pose's payload) or, with
     * {@code payloadShare}, the payload's share of it alone, and s a cubic B-spline of x (temperature
     * or time, {@code along}) over lo..hi with {@code nBasis} functions. The splines sum to one, so a
     * constant compliance is the case s = c. Two causes give it: a stiffness that falls as the joint
     * warms (a reducer's lubricant thins and its elastomer seals soften: k(T) = k0/(1 + c·(T − T0))
     * makes s linear in T), and a carried mass that changes while the file's payload stays as
     * recorded (a dispensing or gluing tool emptying, a part dropped), whose torque follows the mass.
     * Of no known family: the catalogue's compliance has one stiffness. Without the arm's masses
     * ({@link GravityTorques#massesUnknown}) each mass's torque has its own coefficient at either end
     * of the range, straight between ({@code nBasis} 2), as the compliance has one per mass.
     */
    public static Effect complianceVarying(int joint, GravityTorques g, Along along, double lo, double hi, int nBasis, boolean payloadShare) {
        if (g == null) throw new IllegalArgumentException("a varying compliance needs the arm's masses");
        if (along != Along.TIME && along != Along.TEMPERATURE) throw new IllegalArgumentException("a compliance varies with time or temperature");
        if (!(hi > lo)) throw new IllegalArgumentException("varying compliance range " + lo + ".." + hi);
        if (g.massesUnknown() && !payloadShare && nBasis != 2)
            throw new IllegalArgumentException("without the masses a varying compliance is one per mass, straight between the range's ends (2 functions)");
        Effect e = new Effect(Kind.COMPLIANCE_VARYING, joint, -1, g, false, Double.NaN, Double.NaN, null, lo, hi, null, null, nBasis);
        e.along = along;
        e.payloadShare = payloadShare;
        return e;
    }

    /**
     * The payload's share of drive {@code joint}'s gravity torque times a compliance that steps at
     * each of {@code times} (s, rising) and stays between them: Δq = τ_payload·c_i over the i-th
     * interval. A carried mass that changes at moments while the file records it unchanged (a
     * dispensing tool's shots, a part dropped or added between poses) gives it: the torque follows
     * the mass, which a spline of the time follows only so sharply. Of no known family, as
     * {@link #complianceVarying}.
     */
    public static Effect complianceInSteps(int joint, GravityTorques g, double[] times) {
        if (g == null) throw new IllegalArgumentException("a varying compliance needs the arm's masses");
        if (times.length == 0) throw new IllegalArgumentException("a compliance in steps needs a step");
        for (int i = 0; i < times.length; i++)
            if (!Double.isFinite(times[i]) || i > 0 && !(times[i] > times[i - 1]))
                throw new IllegalArgumentException("step times must be finite and rising: " + Arrays.toString(times));
        Effect e = new Effect(Kind.COMPLIANCE_VARYING, joint, -1, g, false, Double.NaN, Double.NaN, null, times[0],
                times[times.length - 1], null, null, times.length + 1);
        e.along = Along.TIME;
        e.payloadShare = true;
        e.stepTimes = times.clone();
        return e;
    }

    /**
     * The same payload's varying compliance with the payload's centre estimated with it: each time
     * function multiplies the payload's torque at the file's centre and its change with the centre
     * moved along each flange axis ({@link GravityTorques#payloadDriveTorques}), four columns a
     * function. A tool's centre of mass is rarely where the file puts it (a dispensing tool's
     * reservoir hangs off the flange), and a torque of the wrong phase is left where the joint it
     * turns with (joint 5 under a long tool) moves.
     */
    public static Effect withPayloadCentreFree(Effect e) {
        if (e.kind != Kind.COMPLIANCE_VARYING || !e.payloadShare) throw new IllegalArgumentException("not a payload's varying compliance: " + e.label());
        Effect f = e.stepTimes != null ? complianceInSteps(e.joint, e.gravity, e.stepTimes)
                : complianceVarying(e.joint, e.gravity, e.along, e.lo, e.hi, e.nBasis, true);
        f.payloadCentreFree = true;
        return f;
    }

    /** Whether a payload's varying compliance estimates the payload's centre with it ({@link #withPayloadCentreFree}). */
    public boolean payloadCentreFree() { return payloadCentreFree; }

    /** A varying compliance's step times (s), or null where it follows a spline. */
    public double[] stepTimes() { return stepTimes == null ? null : stepTimes.clone(); }

    /**
     * Whether a varying compliance is one per mass, straight between the ends of its range: on a robot
     * file without masses ({@link GravityTorques#massesUnknown}), each mass's torque at each end.
     */
    boolean perMassVarying() { return kind == Kind.COMPLIANCE_VARYING && !payloadShare && gravity.massesUnknown(); }

    /** Whether a varying compliance follows the payload's share of the torque alone (a carried mass that changes). */
    public boolean payloadShare() { return payloadShare; }

    /**
     * The torque (N·m) at which a stiffening compliance with values {@code v} (c, c₃) is twice as stiff as
     * unloaded: the tangent compliance c + 3c₃τ² is half of c where τ² = −c/(6c₃); NaN unless c &gt; 0 &gt; c₃.
     */
    public static double stiffnessDoublesAtNm(double[] v) {
        return v.length > 1 && v[0] > 0 && v[1] < 0 ? Math.sqrt(-v[0] / (6 * v[1])) : Double.NaN;
    }

    /** Harmonics 1–3 of joint {@code joint}'s angle. */
    public static Effect periodic(int joint) { return periodic(joint, LOW); }

    /** The given harmonics (≥ 1, sorted, distinct) of joint {@code joint}'s angle. */
    public static Effect periodic(int joint, int[] harmonics) {
        int[] h = new TreeSet<>(Arrays.stream(harmonics).boxed().toList()).stream().mapToInt(Integer::intValue).toArray();
        if (h.length == 0 || h[0] < 1) throw new IllegalArgumentException("harmonics " + Arrays.toString(harmonics));
        return new Effect(Kind.PERIODIC, joint, -1, null, false, Double.NaN, Double.NaN, h, Double.NaN, Double.NaN, null, null);
    }

    /**
     * The other angle of joint {@code j}'s link where the joint before it turns about a parallel axis
     * (a planar pair: the upper arm and forearm of an articulated arm): the link's angle against the
     * link before it where the controller reads its angle against the ground (a parallel-arm linkage,
     * θ3 = q3 − q2), or against the ground where the controller reads it against the link before it
     * (q2 + q3 on a serial arm). As Σ_l c_l·q_l over the controller values; null where the axes are
     * not parallel. The drive of a parallel arm turns the forearm through a rod and a lever whose own
     * bearings turn with the relative angle; a serial arm's counterweight or cable turns with the
     * forearm's angle to the ground.
     */
    public static double[] linkAngle(KinematicModel model, int j) {
        if (j < 1 || model.isPrismatic(j) || model.isPrismatic(j - 1)) return null;
        var joints = model.description().joints();
        if (joints.get(j).axis().cross(joints.get(j - 1).axis()).norm() > 1e-6) return null;
        double[][] c = model.couplingMatrix();
        double[] rel = c[j].clone(), out = rel.clone();
        boolean unit = true;
        for (int l = 0; l < rel.length; l++) if (Math.abs(rel[l] - (l == j ? 1 : 0)) > 1e-12) unit = false;
        if (unit) {
            // the controller reads the angle against the link before: the link's angle against the ground, θ_{j−1} + θ_j
            double s = joints.get(j).axis().dot(joints.get(j - 1).axis()) > 0 ? 1 : -1;
            for (int l = 0; l < rel.length; l++) out[l] = rel[l] + s * c[j - 1][l];
        }
        return out;
    }

    /**
     * The joints whose housings drive {@code j}'s transmission passes through, turning with them: in a
     * six-axis arm's wrist the drives of joints 5 and 6 run from motors in the forearm through joint
     * 4's housing (and joint 6's through joint 5's), so a bearing seat or a bevel pair in that housing,
     * out of round or eccentric, changes joint {@code j}'s transmission as the housing turns (an oval
     * seat by twice its angle). Revolute joints from the wrist's first to the one before {@code j}
     * whose axes are not parallel to {@code j}'s; empty for the arm's joints.
     */
    public static int[] housingsOf(KinematicModel model, int j) {
        int n = model.dof();
        if (n < 6 || j < n - 2 || model.isPrismatic(j)) return new int[0];
        var joints = model.description().joints();
        return java.util.stream.IntStream.range(n - 3, j).filter(k -> !model.isPrismatic(k)
                && joints.get(k).axis().cross(joints.get(j).axis()).norm() > 1e-6).toArray();
    }

    /** The angle of joint {@code k} alone as a link-angle periodic error's angle (Σ_l c_l·q_l with c = e_k). */
    public static double[] jointAngle(int dof, int k) {
        double[] c = new double[dof];
        c[k] = 1;
        return c;
    }

    /** Whether a link-angle periodic error repeats with one other joint's angle alone (a housing its drive passes through). */
    public boolean followsAnotherJoint() { return isAnotherJointsAngle(linkAngle, joint); }

    /** Whether the angle Σ_l c_l·q_l is one joint's alone, not joint {@code j}'s ({@link #jointAngle}). */
    static boolean isAnotherJointsAngle(double[] c, int j) {
        int nonzero = 0;
        for (double x : c) if (x != 0) nonzero++;
        return nonzero == 1 && c[j] == 0;
    }

    /**
     * Error of drive {@code joint} periodic in the angle ψ = Σ_l angle[l]·q_l ({@link #linkAngle}):
     * Σ_h a_h sin(hψ) + b_h cos(hψ) at the given harmonics. Of no known family: a transmission
     * error repeats with its drive's own turn.
     */
    public static Effect linkPeriodic(int joint, double[] angle, int[] harmonics) {
        int[] h = new TreeSet<>(Arrays.stream(harmonics).boxed().toList()).stream().mapToInt(Integer::intValue).toArray();
        if (h.length == 0 || h[0] < 1) throw new IllegalArgumentException("harmonics " + Arrays.toString(harmonics));
        Effect e = new Effect(Kind.LINK_PERIODIC, joint, -1, null, false, Double.NaN, Double.NaN, h, Double.NaN, Double.NaN, null, null);
        e.linkAngle = angle.clone();
        return e;
    }

    /** A link-angle periodic error's angle, Σ linkAngle[l]·q_l at controller values q (rad). */
    public double linkAngleAt(double[] q) {
        double s = 0;
        for (int l = 0; l < linkAngle.length; l++) s += linkAngle[l] * q[l];
        return s;
    }

    /** A link angle as text: "q3 − q2", "q2 + q3". */
    public static String linkAngleText(double[] c) {
        StringBuilder b = new StringBuilder();
        for (int l = 0; l < c.length; l++) {
            if (c[l] == 0) continue;
            String coef = Math.abs(Math.abs(c[l]) - 1) < 1e-12 ? "" : orderText(Math.abs(c[l])) + "·";
            if (b.length() == 0) b.append(c[l] < 0 ? "−" : "").append(coef).append("q").append(l + 1);
            else b.append(c[l] < 0 ? " − " : " + ").append(coef).append("q").append(l + 1);
        }
        return b.toString();
    }

    /** A link-angle periodic error's angle as text. */
    public String linkAngleText() { return linkAngleText(linkAngle); }

    /** A link-angle periodic error's angle coefficients per controller joint. */
    public double[] linkAngleCoefficients() { return linkAngle.clone(); }

    /**
     * The given whole harmonics and, besides them, stage orders that are not whole (cycles per turn of
     * the joint, > 0): a reducer's intermediate shaft turning 7.1 times per output turn repeats its
     * error 7.1 times per turn of the joint; over the joint's range that is still a function of its
     * angle. Whole orders among {@code stages} join the harmonics.
     */
    public static Effect periodic(int joint, int[] harmonics, double[] stages) {
        java.util.TreeSet<Integer> whole = new java.util.TreeSet<>(Arrays.stream(harmonics).boxed().toList());
        java.util.TreeSet<Double> other = new java.util.TreeSet<>();
        for (double f : stages) {
            if (!(f > 0)) throw new IllegalArgumentException("stage order " + f);
            if (f == Math.rint(f)) whole.add((int) f);
            else other.add(roundOrder(f));
        }
        if (whole.isEmpty() && other.isEmpty() || !whole.isEmpty() && whole.first() < 1)
            throw new IllegalArgumentException("harmonics " + whole + ", stages " + other);
        Effect e = new Effect(Kind.PERIODIC, joint, -1, null, false, Double.NaN, Double.NaN,
                whole.stream().mapToInt(Integer::intValue).toArray(), Double.NaN, Double.NaN, null, null);
        e.stages = other.stream().mapToDouble(Double::doubleValue).toArray();
        return e;
    }

    /**
     * A periodic error of joint {@code joint} at the orders of {@code periodic} whose size follows the
     * gravity torque τ on the joint: Δq = Σ_h (a_h + a'_h x) sin h q + (b_h + b'_h x) cos h q, with
     * x = τ/τ_ref, or |τ|/τ_ref when {@code magnitude}. A gear mesh's error under load is its unloaded
     * error plus the load over the mesh stiffness, and that stiffness varies over the mesh cycle, so
     * the part that repeats with the angle grows with the transmitted torque (the loaded
     * transmission error: J. D. Smith, "Gear Noise and Vibration", 2nd ed., Marcel Dekker 2003, §2–3;
     * W. D. Mark, J. Acoust. Soc. Am. 63 (1978) 1409). Of no known family: located, not named.
     */
    public static Effect loadPeriodic(Effect periodic, GravityTorques g, double refNm, boolean magnitude) {
        if (periodic.kind != Kind.PERIODIC) throw new IllegalArgumentException("a load-periodic error follows a periodic one, not " + periodic.label());
        if (!(refNm > 0) || Double.isInfinite(refNm)) throw new IllegalArgumentException("reference torque " + refNm);
        if (g == null || g.massesUnknown()) throw new IllegalArgumentException("a load-periodic error needs the arm's masses");
        Effect e = new Effect(Kind.LOAD_PERIODIC, periodic.joint, -1, g, false, Double.NaN, Double.NaN, periodic.harmonics.clone(),
                Double.NaN, Double.NaN, null, null);
        e.stages = periodic.stages.clone();
        e.loadRefNm = refNm;
        e.loadMagnitude = magnitude;
        return e;
    }

    /**
     * A periodic error of joint {@code joint} at {@code harmonics} of its own angle whose size changes
     * with the temperature: Δq = Σ_h (a_h + a'_h u) sin h q + (b_h + b'_h u) cos h q, u = (T − lo)/(hi − lo)
     * over the campaign's temperatures lo..hi. An encoder read by two channels in quadrature whose gains
     * drift apart with temperature (g = γ(T − T_c), its amplitude matched at T_c) reads atan2((1 + g) sin q,
     * cos q) = q + (g/2) sin 2q to first order (a gain mismatch's error is twice per turn; an offset's
     * once: Kavanagh, "Shaft encoder characterization via theoretical model of differentiator with
     * both differential and integral nonlinearities", IEEE Trans. Instrum. Meas. 49 (2000) 795; Hoseinnezhad,
     * IEEE Trans. Instrum. Meas. 55 (2006) 1263 on sinusoidal-encoder errors). Of no known family: a
     * transmission error keeps its size.
     */
    public static Effect periodicWarming(int joint, int[] harmonics, double lo, double hi) {
        int[] h = new TreeSet<>(Arrays.stream(harmonics).boxed().toList()).stream().mapToInt(Integer::intValue).toArray();
        if (h.length == 0 || h[0] < 1) throw new IllegalArgumentException("harmonics " + Arrays.toString(harmonics));
        if (!(hi > lo)) throw new IllegalArgumentException("temperature range " + lo + ".." + hi);
        Effect e = new Effect(Kind.WARM_PERIODIC, joint, -1, null, false, Double.NaN, Double.NaN, h, lo, hi, null, null);
        e.along = Along.TEMPERATURE;
        return e;
    }

    /**
     * A play of joint {@code joint} taken up by gravity: Δq = (b/2)·s(τ), τ the gravity torque on the
     * drive ({@code g}'s masses, the pose's payload), s = sign(τ − c) or, with a hand-over half-width
     * w &gt; 0, clamp((τ − c)/w, −1, 1). A clearance held against one side by a load gives way in the
     * load's direction, as a spring does (b &gt; 0 with the torque's sign of a joint compliance,
     * Δq = τ/k), and changes side where the load reverses; it does not follow the last motion, so no
     * motion's direction tells it (a backlash held by gravity with no free zone: Nordin &amp; Gutman,
     * Automatica 38 (2002) 1633, §2). c stands for where the file's masses put the torque's zero
     * against where it is. Of no known family: located, not named.
     */
    public static Effect gravityPlay(int joint, GravityTorques g, double centreNm, double widthNm) {
        if (g == null || g.massesUnknown()) throw new IllegalArgumentException("a gravity play needs the arm's masses");
        if (!Double.isFinite(centreNm) || !(widthNm >= 0) || Double.isInfinite(widthNm))
            throw new IllegalArgumentException("side change at " + centreNm + " N·m, width " + widthNm);
        Effect e = new Effect(Kind.GRAVITY_PLAY, joint, -1, g, false, Double.NaN, Double.NaN, null, Double.NaN, Double.NaN, null, null);
        e.sideNm = centreNm;
        e.sideWidthNm = widthNm;
        return e;
    }

    /** A gravity play's side, −1..1, at gravity torque {@code tauNm} on its drive. */
    public double playSide(double tauNm) {
        double x = tauNm - sideNm;
        return sideWidthNm > 0 ? Math.max(-1, Math.min(1, x / sideWidthNm)) : Math.signum(x);
    }

    /** A gravity play's torque where the side changes, N·m. */
    public double sideNm() { return sideNm; }

    /** A gravity play's hand-over half-width, N·m (0: sharp). */
    public double sideWidthNm() { return sideWidthNm; }

    /** A load-periodic error's load at controller values q with payload {@code payloadKg}: τ/τ_ref or |τ|/τ_ref. */
    /** A warming periodic error's temperature share u = (T − lo)/(hi − lo) under c (0 where no temperature is read). */
    double warmShare(PoseConditions c) {
        return Double.isFinite(c.tempC()) ? (c.tempC() - lo) / (hi - lo) : 0;
    }

    double loadShare(double[] q, double payloadKg) {
        double t = gravity.driveTorques(q, Double.isFinite(payloadKg) ? payloadKg : 0)[joint] / loadRefNm;
        return loadMagnitude ? Math.abs(t) : t;
    }

    /** Whether a load-periodic error's size follows the torque's magnitude (else the torque with its sign). */
    public boolean loadMagnitude() { return loadMagnitude; }

    /** A load-periodic error's reference torque, N·m. */
    public double loadRefNm() { return loadRefNm; }

    /** A stage order kept to 3 decimals (the label and the parameter names carry it). */
    static double roundOrder(double f) { return Math.rint(f * 1000) / 1000; }

    /** An order in words: "81", "7.12". */
    public static String orderText(double f) {
        if (f == Math.rint(f)) return Long.toString((long) f);
        return new java.math.BigDecimal(roundOrder(f)).setScale(3, java.math.RoundingMode.HALF_EVEN).stripTrailingZeros().toPlainString();
    }

    public static Effect backlash(int joint) { return drive(Kind.BACKLASH, joint); }

    /**
     * Lost motion that builds up over the move (friction wind-up): the output lags by
     * (b/2)·dir·(1 − exp(−|last move| / x0)), x0 = {@code buildUpRad}. Solid friction in the
     * transmission winds up along the travel after a reversal and saturates (Dahl's model:
     * F = Fc (1 − exp(−x/x0)); P. R. Dahl, "A solid friction model", Aerospace Corp.
     * TOR-0158(3107-18)-1, 1968; B. Armstrong-Hélouvry, P. Dupont, C. Canudas de Wit, "A survey of
     * models, analysis tools and compensation methods for the control of machines with friction",
     * Automatica 30 (1994) 1083, §2.2 "pre-sliding displacement"), so a short move leaves a smaller
     * lag than a long one. The move of each row comes from {@code moves} (the measuring order); where
     * it is unknown (a compensated program, a row not in the campaign) the full lag of a long move is
     * taken, which is plain backlash. b is the lag after a long move, as for {@link #backlash}.
     */
    public static Effect windUp(int joint, double buildUpRad, Directions.Moves moves) {
        return windUp(joint, buildUpRad, Double.NaN, moves);
    }

    /**
     * Lost motion that builds up over the travel since the drive last turned, each pose taken by an
     * approach move of {@code approachRad} from the side its recorded direction gives (a one-sided
     * approach program: the controller stops short of the pose and moves onto it from a fixed side;
     * the approach's length is in the program, not in the file). The wind-up follows the travel since
     * the motor last reversed (Dahl's model is a function of that travel, Armstrong-Hélouvry et al.
     * 1994 §2.2). Where the last move in the file went the way of the recorded direction and is
     * longer than the approach, the drive went on through the approach pose and the travel is that
     * move (the approach is its last part); where it went the other way, or fell short of the
     * approach pose, the motor turned round at the approach pose and the travel is the approach
     * alone. {@code approachRad} NaN: no approach moves, as {@link #windUp(int, double, Directions.Moves)}.
     */
    public static Effect windUp(int joint, double buildUpRad, double approachRad, Directions.Moves moves) {
        if (!(buildUpRad > 0)) throw new IllegalArgumentException("build-up length " + buildUpRad);
        if (!Double.isNaN(approachRad) && !(approachRad > 0)) throw new IllegalArgumentException("approach length " + approachRad);
        Effect e = drive(Kind.BACKLASH, joint);
        e.buildUp = buildUpRad;
        e.approach = approachRad;
        e.moves = moves == null ? Directions.Moves.NONE : moves;
        return e;
    }

    /**
     * Backlash held on one flank by gravity except where the gravity torque on the joint is small.
     * A load torque on a gear train holds the teeth in contact on the flank it pushes them to, so
     * the play is taken up the same way whatever the direction of the last motion; only where the
     * load torque is too small to overcome the friction of the mesh does the last motion decide,
     * and the output lags as for plain backlash (gear backlash under a biasing load, "anti-backlash
     * by preload": Nordin &amp; Gutman, Automatica 38 (2002) 1633, §2 — a constant external torque
     * keeps the backlash closed; Shigley's Mechanical Engineering Design, gear backlash and
     * preloaded drives; the same reason a vertical axis is calibrated without reversal error).
     * With τ the gravity torque on drive {@code joint} from {@code gravity} (the robot file's
     * masses, {@link GravityTorques#driveTorques}: the torque gravity exerts, positive turning the
     * joint forward, as a compliance's Δq = c·τ), q_out = q + (b/2)·sign τ where |τ| ≥
     * {@code heldAboveNm}, else q − (b/2)·dir. b ≥ 0 is the whole play, as for {@link #backlash}.
     */
    public static Effect heldByGravity(int joint, GravityTorques gravity, double heldAboveNm) {
        return heldByGravity(joint, gravity, heldAboveNm, 0);
    }

    /**
     * {@link #heldByGravity(int, GravityTorques, double)} with a gradual hand-over: the share of
     * the pose held is s = smoothstep of |τ| from (1 − w)·τ0 to (1 + w)·τ0 (w = {@code width}),
     * q_out = q + s·(b/2)·sign τ − (1 − s)·(b/2)·dir. The friction that the load must overcome to
     * close the play varies along the mesh, and the file's masses are not the arm's: near τ0
     * some poses are held and some are not.
     */
    public static Effect heldByGravity(int joint, GravityTorques gravity, double heldAboveNm, double width) {
        return heldByGravity(joint, gravity, heldAboveNm, width, null);
    }

    /**
     * {@link #heldByGravity(int, GravityTorques, double, double)} with the file's mass k scaled by
     * {@code massScales[k]} (null: the file's masses): which flank a pose is held on, and whether
     * it is held, follows the arm's real weight, not the data sheet's.
     */
    public static Effect heldByGravity(int joint, GravityTorques gravity, double heldAboveNm, double width, double[] massScales) {
        if (gravity == null || gravity.massesUnknown()) throw new IllegalArgumentException("backlash held by gravity needs the robot's masses");
        if (!(heldAboveNm >= 0) || Double.isInfinite(heldAboveNm)) throw new IllegalArgumentException("holding torque " + heldAboveNm);
        GravityTorques g = massScales == null ? gravity : gravity.withMassScales(massScales);
        Effect e = new Effect(Kind.BACKLASH, joint, -1, g, false, Double.NaN, Double.NaN, null, Double.NaN, Double.NaN, null, null);
        e.massScales = massScales == null ? null : massScales.clone();
        if (!(width >= 0 && width < 1)) throw new IllegalArgumentException("hand-over width " + width);
        e.preloadNm = heldAboveNm;
        e.preloadWidth = width;
        return e;
    }

    /** Whether this is backlash held on one flank by gravity where the torque is large ({@link #heldByGravity}). */
    public boolean heldByGravity() { return kind == Kind.BACKLASH && Double.isFinite(preloadNm); }

    /** The gravity torque above which a backlash held by gravity stays on one flank, N·m (NaN otherwise). */
    public double heldAboveNm() { return preloadNm; }

    /** The factors of the file's masses of a backlash held by gravity (null: as in the file). */
    public double[] heldMassScales() { return massScales == null ? null : massScales.clone(); }

    /** The half-width of a backlash held by gravity's hand-over, a share of {@link #heldAboveNm()} (0: sharp). */
    public double heldWidth() { return preloadWidth; }

    /** The gravity torque on the drive of a backlash held by gravity or of a gravity play at {@code q} with {@code payloadKg} (NaN: none), N·m. */
    public double holdingTorque(double[] q, double payloadKg) {
        return gravity.driveTorques(q, Double.isFinite(payloadKg) ? payloadKg : 0)[joint];
    }

    /** The share of the play held by gravity at a gravity torque τ (N·m): 0 free, 1 held. */
    double heldShare(double tau) {
        double a = Math.abs(tau);
        if (preloadWidth == 0) return a >= preloadNm ? 1 : 0;
        double t = Math.min(1, Math.max(0, (a - (1 - preloadWidth) * preloadNm) / (2 * preloadWidth * preloadNm)));
        return t * t * (3 - 2 * t);
    }

    /** The lost motion's regressor for one pose: held on the flank gravity pushes it to, or lagging the last motion. */
    private double lostMotion(double[] q, PoseConditions c) {
        if (!heldByGravity()) return -0.5 * c.direction(joint); // the output lags: q_out = q − (b/2)·dir
        double tau = holdingTorque(q, c.payloadKg());
        double s = heldShare(tau);
        return s * 0.5 * Math.signum(tau) - (1 - s) * 0.5 * c.direction(joint);
    }

    /** Whether this is lost motion that builds up over the move ({@link #windUp}). */
    public boolean buildsUp() { return kind == Kind.BACKLASH && Double.isFinite(buildUp); }

    /** The build-up length of a lost motion that builds up over the move, rad (NaN for a constant one). */
    public double buildUpRad() { return buildUp; }

    /**
     * The same lost motion (constant or building up over the move) with a play that changes once per
     * turn of its joint: b(q) = b + b_cos·cos q + b_sin·sin q, the output lagging by b(q)/2. An
     * output gear running off its bearing's centre by e changes its centre distance to the pinion
     * by e·cos(q − φ) over the turn, and a gear pair's circumferential backlash changes with the
     * centre distance by 2·Δa·tan α (α the working pressure angle; ISO/TR 10064-2:1996, backlash
     * from the centre distance), an angle of 2·e·tan α / r at the output of pitch radius r.
     */
    public static Effect withRunout(Effect lostMotion) { return withRunout(lostMotion, 1); }

    /**
     * The same lost motion with a play that changes at each of {@code orders} (times per turn of its
     * joint): b(q) = b + Σ_f (b_cos,f·cos f q + b_sin,f·sin f q). The pinion meshing with the output
     * gear turns z_gear/z_pinion times per output turn (an order that need not be whole); running
     * off its own centre, it changes the centre distance, and with it the play, at that rate (the
     * same 2·Δa·tan α law as {@link #withRunout(Effect)}); the output gear's own runout adds order 1.
     */
    public static Effect withRunout(Effect lostMotion, double... orders) {
        if (lostMotion.kind != Kind.BACKLASH || lostMotion.heldByGravity())
            throw new IllegalArgumentException("a play changing over the turn is a form of free lost motion, not of " + lostMotion.label());
        double[] f = Arrays.stream(orders).map(Effect::roundOrder).distinct().sorted().toArray();
        if (f.length == 0 || !(f[0] >= 1))
            throw new IllegalArgumentException("a play's change over the turn needs orders of at least 1, got " + Arrays.toString(orders));
        Effect e = constantPlay(lostMotion);
        e.runout = f;
        return e;
    }

    /**
     * A play's change over the turn in a label's words: "play changing over the turn", "play changing
     * 4.417 times per turn", "play changing once and 4.417 times per turn".
     */
    private String runoutWords() {
        List<String> f = new ArrayList<>();
        for (double o : runout) f.add(o == 1 ? runout.length == 1 ? "over the turn" : "once" : orderText(o));
        String times = String.join(" and ", f);
        return "play changing " + (runout.length == 1 && runout[0] == 1 ? times : times + " times per turn");
    }

    /** The play b + Σ_f (b_cos,f·cos f q + b_sin,f·sin f q) at joint angle q (rad) of a play changing at {@code orders}, values v (b first). */
    static double play(double[] orders, double[] v, double q) {
        double b = v[0];
        for (int i = 0; i < orders.length; i++) b += v[1 + 2 * i] * Math.cos(orders[i] * q) + v[2 + 2 * i] * Math.sin(orders[i] * q);
        return b;
    }

    /** The orders (times per turn of its joint) at which a play changing over the turn repeats ({@link #withRunout(Effect, double...)}); empty for any other effect. */
    public double[] runoutOrders() { return runout() ? runout.clone() : new double[0]; }

    /** A new lost motion of the same form as {@code lostMotion} (constant or building up), with a constant play. */
    private static Effect constantPlay(Effect lostMotion) {
        return lostMotion.buildsUp() ? windUp(lostMotion.joint, lostMotion.buildUp, lostMotion.approach, lostMotion.moves)
                : backlash(lostMotion.joint);
    }

    /** Whether this is lost motion whose play changes over the turn of its joint ({@link #withRunout}). */
    public boolean runout() { return kind == Kind.BACKLASH && runout.length > 0; }

    /** A lost motion with a play that changes over the turn as the same lost motion with a constant play (itself otherwise). */
    public static Effect withoutRunout(Effect e) {
        return e.runout() ? constantPlay(e) : e;
    }

    /** Whether this is a wind-up of poses taken by an approach move ({@link #windUp(int, double, double, Directions.Moves)}). */
    public boolean approached() { return buildsUp() && Double.isFinite(approach); }

    /** The approach move's length of an approached wind-up, rad (NaN otherwise). */
    public double approachRad() { return approach; }

    /**
     * A wind-up's share of its full lag after row m's travel since its joint last turned, the joint
     * resting on side {@code dir} (1 when the move is unknown).
     */
    double windUpShare(Measurement m, int dir) {
        double x = travel(m, dir);
        return Double.isFinite(x) ? windUpShare(x, buildUp) : 1;
    }

    /**
     * The travel of this effect's joint since it last turned before row m (rad; NaN when unknown),
     * the joint resting on side {@code d}: the last move in the file, or, for an approached wind-up,
     * that move where it went the way of {@code d} and beyond the approach pose, else the approach
     * alone (signed by d).
     */
    double travel(Measurement m, int d) {
        double x = m == null ? Double.NaN : moves.of(m, joint);
        if (!Double.isFinite(x) || !Double.isFinite(approach) || d == 0) return x;
        return Math.signum(x) == d ? d * Math.max(Math.abs(x), approach) : d * approach;
    }

    /**
     * The share of its full lag a lost motion has built up after a move of {@code moveRad} (either
     * sign), with build-up length {@code buildUpRad}: 1 − exp(−|move|/x0) (Dahl's solid friction).
     */
    static double windUpShare(double moveRad, double buildUpRad) { return 1 - Math.exp(-Math.abs(moveRad) / buildUpRad); }


    public static Effect scale(int joint) { return drive(Kind.SCALE, joint); }
    /** q_out,target += κ q_source. */
    public static Effect coupling(int target, int source) {
        return new Effect(Kind.COUPLING, target, source, null, false, Double.NaN, Double.NaN, null, Double.NaN, Double.NaN, null, null);
    }
    /** Smooth error of drive {@code joint} over [lo, hi] (its range), {@link #SMOOTH_BASIS} functions. */
    public static Effect smooth(int joint, double lo, double hi) { return smooth(joint, lo, hi, SMOOTH_BASIS); }

    /** Smooth error of drive {@code joint} over [lo, hi]: a cubic B-spline of {@code n} ≥ 4 functions. */
    public static Effect smooth(int joint, double lo, double hi, int n) { return smoothFollowing(joint, -1, lo, hi, n); }

    /**
     * Smooth error of drive {@code joint} following joint {@code source}'s angle over [lo, hi] (the
     * source's range), a cubic B-spline of {@code n} ≥ 4 functions; {@code source} −1 (or the joint
     * itself): its own angle. The fallback of a coupling that is not in proportion: a cable or hose
     * that tightens as another joint winds up pulls the drive by a stiff, non-linear function of that
     * joint's angle, which a coupling κ·q_source holds only in its linear part.
     */
    public static Effect smoothFollowing(int joint, int source, double lo, double hi, int n) {
        if (!(hi > lo)) throw new IllegalArgumentException("smooth error range " + lo + ".." + hi);
        if (n < 4) throw new IllegalArgumentException("smooth error needs at least 4 functions, got " + n);
        return new Effect(Kind.SMOOTH, joint, source == joint ? -1 : source, null, false, Double.NaN, Double.NaN, null, lo, hi, null, null, n);
    }

    /**
     * The joint whose angle this effect's regressor follows: the source of a coupling or of a smooth
     * error following another joint, else the effect's own joint (−1 for effects on lengths or the point).
     */
    public int angleJoint() { return (kind == Kind.COUPLING || kind == Kind.SMOOTH) && source >= 0 ? source : joint; }

    /**
     * Smooth error of drive {@code joint} following the model angle θ_source = Σ_l C[source][l]·q_l
     * of {@code model}'s controller coupling (on a parallel-arm linkage θ3 = q3 − q2, the forearm's
     * angle to the upper arm): what turns with one joint of the arm itself, whatever the drives did
     * to set it (a bearing's wobble turning with the forearm's own angle moves drive 4's axis by a
     * function of θ3, which no function of q3 alone holds). {@code source} may be the joint itself:
     * a drive's error following its own model angle (a parallel arm's rod or lever of the wrong
     * length turns the forearm by a non-linear function of θ3, the four-bar closure).
     */
    public static Effect smoothFollowingModelAngle(int joint, int source, KinematicModel model, double lo, double hi, int n) {
        Effect e = smoothFollowing(joint, source, lo, hi, n);
        return new Effect(Kind.SMOOTH, joint, e.source, null, false, Double.NaN, Double.NaN, null, lo, hi, model, null, n);
    }

    /** Whether a smooth error follows a model angle θ (the linkage's), not a controller value q. */
    public boolean followsModelAngle() { return kind == Kind.SMOOTH && model != null; }

    /** The variable a smooth error follows at controller values q: q of its joint or source, or the source's model angle. */
    double smoothVariable(double[] q) {
        int k = angleJoint();
        if (model == null) return q[k];
        double[] row = model.couplingMatrix()[k];
        double th = 0;
        for (int l = 0; l < row.length; l++) th += row[l] * q[l];
        return th;
    }

    /**
     * Error of drive {@code joint} that depends on its own angle and joint {@code other}'s together:
     * Δq = v·(sin q_j sin q_k, sin q_j cos q_k, cos q_j sin q_k, cos q_j cos q_k, q_j, q_k, q_j q_k,
     * q_j cos q_k, q_j sin q_k, cos q_k, sin q_k): the first-order products of the sines and cosines,
     * which no function of one joint alone holds; the two angles' Taylor terms to the first
     * interaction (linear in each, and their product), so that a scale error of j and a coupling of j
     * from k are nested in it (each must beat it on held-out error) and an interaction that is not
     * periodic is held too; and a scale of j that changes once per turn of k, with k's own once-per-
     * turn term (a load on drive j growing with its travel from where it is free, made stiffer or
     * softer by joint k's angle: a hose or cable twisted by j and drawn over the housing as k bends),
     * which over more than a turn of j no product of sines holds.
     */
    public static Effect pair(int joint, int other) {
        if (joint == other) throw new IllegalArgumentException("a joint pair needs two joints");
        return new Effect(Kind.PAIR, joint, other, null, false, Double.NaN, Double.NaN, null, Double.NaN, Double.NaN, null, null, PAIR_COLUMNS);
    }

    /** Columns of the two-joint fallback: four products, q_j, q_k and q_j q_k, then j's scale changing with k and k's once-per-turn term. */
    static final int PAIR_COLUMNS = 11;

    /** The two-joint fallback's first columns, the products of the two joints' sines and cosines ({@link #pairProducts}). */
    static final int PAIR_PRODUCTS = 4;

    /** Whether the two-joint fallback's term {@code i} is periodic (a product, or k's own once-per-turn term), not proportional to an angle. */
    static boolean pairTermPeriodic(int i) { return i < PAIR_PRODUCTS || i >= PAIR_COLUMNS - 2; }

    /** The four first-order products of joints j and k's sines and cosines (the two-joint locate probe; the fallback's first columns). */
    static void pairProducts(double[] q, int j, int k, double[] g) {
        double sj = Math.sin(q[j]), cj = Math.cos(q[j]), so = Math.sin(q[k]), co = Math.cos(q[k]);
        g[0] = sj * so;
        g[1] = sj * co;
        g[2] = cj * so;
        g[3] = cj * co;
    }

    /**
     * The measured point moves in base coordinates as a smooth function (cubic B-spline of
     * {@link #POINT_BASIS} functions per axis) of its reach (distance from the base's z axis) or its
     * height, over [lo, hi] m.
     */
    public static Effect pointSmooth(Along along, double lo, double hi) {
        if (!(hi > lo)) throw new IllegalArgumentException("point displacement range " + lo + ".." + hi);
        Effect e = new Effect(Kind.POINT_SMOOTH, -1, -1, null, false, Double.NaN, Double.NaN, null, lo, hi, null, null, POINT_BASIS);
        e.along = along;
        return e;
    }

    /**
     * The robot's base (or the instrument) turns and moves with time or temperature, as a rigid body:
     * Δp = ω(u) × p + d·(u − lo)/(hi − lo), p the measured point in base coordinates, ω a cubic
     * B-spline ({@link #POINT_BASIS} functions per axis) of u (time or temperature) over [lo, hi],
     * and d a drift in proportion to u; the measured frame turns by ω (6-D). A floor slab or a
     * tracker's stand that tilts as it warms turns everything on it about a point of the floor (the
     * turn about the base origin and a move); a drift in proportion to the reading is {@link
     * #driftWithTime()}'s or {@link #driftWithTemperature}'s shape, which this one holds. An
     * unknown time is taken as the end of the campaign, an unknown temperature contributes nothing.
     */
    public static Effect baseTurn(Along along, double lo, double hi) {
        if (along != Along.TIME && along != Along.TEMPERATURE) throw new IllegalArgumentException("a base turns with time or temperature");
        if (!(hi > lo)) throw new IllegalArgumentException("base turn range " + lo + ".." + hi);
        Effect e = new Effect(Kind.BASE_TURN, -1, -1, null, false, Double.NaN, Double.NaN, null, lo, hi, null, null, POINT_BASIS);
        e.along = along;
        return e;
    }

    /**
     * The zero of drive {@code joint} moves with time or temperature: Δq = a cubic B-spline
     * ({@link #POINT_BASIS} functions) of the variable over [lo, hi]. An unknown time is taken as
     * the end of the campaign (the state closest to a program run after it); an unknown
     * temperature contributes nothing.
     */
    public static Effect zeroDrift(int joint, Along along, double lo, double hi) {
        if (along != Along.TIME && along != Along.TEMPERATURE) throw new IllegalArgumentException("a joint zero drifts with time or temperature");
        if (!(hi > lo)) throw new IllegalArgumentException("zero drift range " + lo + ".." + hi);
        Effect e = new Effect(Kind.ZERO_DRIFT, joint, -1, null, false, Double.NaN, Double.NaN, null, lo, hi, null, null, POINT_BASIS);
        e.along = along;
        return e;
    }

    /**
     * Drive {@code joint} deflected at the reading in proportion to its speed in the move made just
     * before it: Δq = c·v_j, v_j = m_j / max_k(|m_k| / s_k) with m_k each joint's last move (rad) and
     * s_k its top speed (the robot file's; 1 rad/s for each when unknown), the speed a synchronised
     * point-to-point move gives joint j when the slowest joint sets its time. A structure stopped by
     * a deceleration a_j springs back and forth after the stop, δ_j = −(a_j/ω²)·e^(−ζωt)·cos(ω_d t)
     * (a damped single-mode oscillator: S. S. Rao, Mechanical Vibrations, §2.6), and in a synchronised
     * move every joint decelerates in proportion to its share of the move, so a reading taken a fixed
     * time t after the stop carries a deflection that follows the move: the arm read before it
     * settled (a servo's following error lags the same way). One parameter c (s). It is not the
     * robot's at rest: a compensated target leaves it out (0 where the move is unknown).
     */
    public static Effect settling(int joint, Directions.Moves moves, double[] speedsRadS) {
        Effect e = new Effect(Kind.SETTLING, joint, -1, null, false, Double.NaN, Double.NaN, null, Double.NaN, Double.NaN, null, null, 1);
        e.moves = moves == null ? Directions.Moves.NONE : moves;
        e.speeds = speedsRadS == null ? null : speedsRadS.clone();
        return e;
    }

    /**
     * A settling's speed of its joint in the move before row m ({@link #settling}), rad/s; 0 when a
     * joint's last move is unknown (the first pose) or nothing moved.
     */
    double settlingSpeed(Measurement m) {
        if (m == null || moves.isEmpty()) return 0;
        double time = 0;
        for (int k = 0; k < m.dof(); k++) {
            double x = moves.of(m, k);
            if (!Double.isFinite(x)) return 0;
            double top = speeds != null && k < speeds.length && speeds[k] > 0 ? speeds[k] : 1;
            time = Math.max(time, Math.abs(x) / top);
        }
        return time > 0 ? moves.of(m, joint) / time : 0;
    }

    /**
     * Drive {@code joint}'s zero jumps by v at time {@code tauS} (s since the start): an encoder slip.
     * Δq = −v before the jump, 0 after it and at an unknown time (the state the campaign ended in).
     */
    public static Effect zeroStep(int joint, double tauS) {
        if (!Double.isFinite(tauS)) throw new IllegalArgumentException("step time " + tauS);
        return new Effect(Kind.ZERO_STEP, joint, -1, null, false, Double.NaN, tauS, null, Double.NaN, Double.NaN, null, null, 1);
    }

    /**
     * Drive {@code joint}'s reading jumps by v where the joint passes {@code atRad}: Δq = v for
     * q_j > atRad, 0 below (an absolute encoder's code track misread over part of the turn).
     */
    public static Effect angleStep(int joint, double atRad) {
        if (!Double.isFinite(atRad)) throw new IllegalArgumentException("step angle " + atRad);
        return new Effect(Kind.ANGLE_STEP, joint, -1, null, false, Double.NaN, Double.NaN, null, atRad, Double.NaN, null, null, 1);
    }

    /**
     * Drive {@code joint}'s reading is off by v while the joint is between {@code fromRad} and
     * {@code toRad}: Δq = v for fromRad &lt; q_j ≤ toRad, 0 outside (a code track or a scale
     * misread over one window of the turn: a step up and a step back down).
     */
    public static Effect angleWindow(int joint, double fromRad, double toRad) {
        if (!(toRad > fromRad)) throw new IllegalArgumentException("window " + fromRad + ".." + toRad);
        return new Effect(Kind.ANGLE_STEP, joint, -1, null, false, Double.NaN, Double.NaN, null, fromRad, toRad, null, null, 1);
    }

    /** Whether this reading step is a window (a step up and back down), not one step. */
    public boolean isWindow() { return kind == Kind.ANGLE_STEP && Double.isFinite(hi); }

    /**
     * The measured point moved on the flange at time {@code tauS} (a target knocked in its nest, a
     * holder that slipped): its offset in the flange frame changed by d there. Δp = −R_flange(q)·d
     * before the move, 0 after it and at an unknown time (the state the campaign ended in, which
     * the tool offset of the geometry holds). {@code model} gives the flange's orientation.
     */
    public static Effect targetStep(KinematicModel model, double tauS) {
        if (!Double.isFinite(tauS)) throw new IllegalArgumentException("step time " + tauS);
        return new Effect(Kind.TARGET_STEP, -1, -1, null, false, Double.NaN, tauS, null, Double.NaN, Double.NaN, model, null, 1);
    }

    /** The number of base creep's columns: a turn about the base's z axis and a shift in x and y per slip. */
    public static final int CREEP_TERMS = 3;

    /**
     * The robot's base creeping on its floor: each move of joint 1 larger than {@code minMoveRad}
     * turns the base a little about a vertical axis, in the move's direction (the reaction of the
     * arm's acceleration on bolts that slip), and the turns add up over the campaign. Δp = n(t)·(ψ ẑ
     * × p + (dx, dy, 0)), n(t) the signed count of such moves up to time t, ψ the turn per slip and
     * (dx, dy) the shift of a pivot off joint 1's axis; the measured frame turns by n(t)·ψ about ẑ.
     * {@code moves}: {@link Directions#movesInTime} of joint 1. At an unknown time, where the
     * campaign ended.
     */
    public static Effect baseCreep(double[][] moves, double minMoveRad) {
        if (moves == null || !(minMoveRad > 0)) throw new IllegalArgumentException("base creep needs joint 1's moves in time and a least move");
        Effect e = new Effect(Kind.BASE_CREEP, -1, -1, null, false, Double.NaN, minMoveRad, null, Double.NaN, Double.NaN, null, null, 1);
        e.creepTimes = moves[0].clone();
        e.creepSlips = new double[moves[1].length];
        for (int i = 0; i < moves[1].length; i++) e.creepSlips[i] = Math.abs(moves[1][i]) > minMoveRad ? Math.signum(moves[1][i]) : 0;
        return e;
    }

    /**
     * A base creep read back from a robot file: where the campaign ended ({@code count} slips), which
     * is all a program run after it needs.
     */
    static Effect baseCreepAtEnd(double minMoveRad, double count) {
        Effect e = baseCreep(new double[][] {{Double.NEGATIVE_INFINITY}, {0}}, minMoveRad);
        e.creepSlips[0] = count;
        return e;
    }

    /** Base creep's signed count of slips up to time {@code timeS} (all of them at an unknown time). */
    double creepCount(double timeS) {
        double n = 0;
        for (int i = 0; i < creepTimes.length; i++) if (!(creepTimes[i] > timeS)) n += creepSlips[i];
        return n;
    }

    /** Base creep's least move of joint 1 that slips, rad. */
    public double creepMoveRad() { return tauS; }

    /** Basis functions per axis of a target's drift on the flange with time ({@link #targetDrift}), tried coarsest first. */
    public static final int[] DRIFT_RESOLUTIONS = {POINT_BASIS, 7, 13, 25};

    /**
     * The measured point moving on the flange with time (a tool that grows as a spindle or the tool
     * itself warms and cools, a holder that creeps): Δp = R_flange(q)·d(t), d a cubic B-spline of the
     * time ({@code nBasis} functions per flange axis) over [lo, hi], s. At an unknown time (a
     * compensated program) it is where the campaign ended. {@code model} gives the flange's
     * orientation. A tool's length grows with its temperature (α·L·ΔT: 11.5 µm/m/K for steel) and its
     * temperature follows the spindle's duty with its own time constant, which no sensor in the file
     * records.
     */
    public static Effect targetDrift(KinematicModel model, double lo, double hi, int nBasis) {
        if (!(hi > lo)) throw new IllegalArgumentException("target drift over " + lo + ".." + hi + " s");
        if (nBasis < POINT_BASIS) throw new IllegalArgumentException("target drift with " + nBasis + " functions");
        Effect e = new Effect(Kind.TARGET_DRIFT, -1, -1, null, false, Double.NaN, Double.NaN, null, lo, hi, model, null, nBasis);
        e.along = Along.TIME;
        return e;
    }

    /**
     * The instrument and the robot's base moved against each other at time {@code tauS}: a
     * tracker's stand knocked or its tripod's foot slipping, the robot's base plate sliding on its
     * anchors. Every measured point moves by one rigid motion there, a translation d and a small
     * turn ω about the base's origin (base axes): Δp = −(d + ω × p) before it, 0 after it and at an
     * unknown time (the state the campaign ended in, which the geometry's instrument pose holds),
     * and a measured frame turns by −ω before it. Not a drift (the instrument's pose changes once,
     * not with time or temperature) nor a move of the target on the flange (the motion is the
     * same in base axes whatever the arm's pose). Six parameters: d (m), then ω (rad).
     */
    public static Effect baseStep(double tauS) {
        if (!Double.isFinite(tauS)) throw new IllegalArgumentException("step time " + tauS);
        return new Effect(Kind.BASE_STEP, -1, -1, null, false, Double.NaN, tauS, null, Double.NaN, Double.NaN, null, null, 1);
    }

    /**
     * The poses whose target faces one side measured from a second instrument station, whose
     * registration into the first's frame is off by a small rigid motion: a tracker sees a reflector
     * only within its acceptance angle, so with two stations (two trackers, or one moved) each pose is
     * read by the one its target faces, and the second's points carry the error of its registration.
     * The second station's poses are those whose flange axis has a positive part along {@code facing}
     * (base frame): Δp = −(d + ω × p) there, as a base step's before its time ({@link #baseStep}), and
     * their measured frames turn by −ω; 0 at the others, whose station the geometry's instrument pose
     * holds. Six parameters: d (m), then ω (rad). An error of the measurement, never applied to the
     * robot.
     */
    public static Effect secondStation(KinematicModel model, Vec3 facing) {
        if (!(facing.norm() > 0)) throw new IllegalArgumentException("no facing direction");
        Effect e = new Effect(Kind.SECOND_STATION, -1, -1, null, false, Double.NaN, Double.NaN, null, Double.NaN, Double.NaN, model, null, 1);
        e.facing = facing.times(1 / facing.norm());
        return e;
    }

    /**
     * The poses read from the station the target faces better, of two standing at {@code first} and
     * {@code second} (base frame): a pose is the second's where its flange axis points more toward the
     * second than toward the first (the unit vectors from the target, at {@code targetInFlange} in the
     * flange's frame, to each), so the split
     * follows the target's place as well as its facing. Otherwise as {@link #secondStation(KinematicModel, Vec3)}.
     */
    public static Effect secondStation(KinematicModel model, Vec3 first, Vec3 second, Vec3 targetInFlange) {
        Effect e = new Effect(Kind.SECOND_STATION, -1, -1, null, false, Double.NaN, Double.NaN, null, Double.NaN, Double.NaN, model, null, 1);
        e.stations = new double[] {first.x(), first.y(), first.z(), second.x(), second.y(), second.z()};
        e.attach = targetInFlange;
        Vec3 d = second.minus(first);
        e.facing = d.norm() > 0 ? d.times(1 / d.norm()) : new Vec3(0, 0, 1);
        return e;
    }

    /** A second station's split: whether the pose at q was read from the second station (its flange axis along the facing). */
    public boolean seenFromSecond(double[] q) { return facingPart(q) > 0; }

    /**
     * A second station's split variable at q: the flange axis's part along the facing direction, or, with
     * the stations' places, along the unit vector to the second less that along the unit vector to the first.
     */
    public double facingPart(double[] q) {
        Pose f = model.flange(q);
        if (stations == null) return f.zAxis().dot(facing);
        Vec3 o = f.apply(attach), z = f.zAxis();
        Vec3 a = new Vec3(stations[0], stations[1], stations[2]).minus(o), b = new Vec3(stations[3], stations[4], stations[5]).minus(o);
        return z.dot(b) / b.norm() - z.dot(a) / a.norm();
    }

    /** A second station split by where the stations stand: their origins (base frame), the first's then the second's; null otherwise. */
    public double[] stations() { return stations == null ? null : stations.clone(); }

    /** A second station's facing direction (base frame, unit); null for other kinds. */
    public Vec3 facing() { return facing; }

    /** The parameters of a base step: the translation's three, then the turn's three. */
    static final int BASE_STEP_TERMS = 6;

    /**
     * The regressors (row-major, 3 x 6, base axes) of a base step before its time, at base point
     * p: g3 moves the point by −(d + ω × p), w3 turns a measured frame by −ω (either may be null).
     */
    static void baseStepRegressor(double[] p, double[] g3, double[] w3) {
        int k = BASE_STEP_TERMS;
        if (g3 != null) {
            Arrays.fill(g3, 0);
            for (int a = 0; a < 3; a++) g3[a * k + a] = -1;
            // −(e_c × p) for the turn about base axis c
            g3[k + 3] = p[2];
            g3[2 * k + 3] = -p[1];
            g3[4] = -p[2];
            g3[2 * k + 4] = p[0];
            g3[5] = p[1];
            g3[k + 5] = -p[0];
        }
        if (w3 != null) {
            Arrays.fill(w3, 0);
            for (int a = 0; a < 3; a++) w3[a * k + 3 + a] = -1;
        }
    }

    /**
     * The instrument's distance reading jumped at time {@code tauS}: a laser tracker's interferometer
     * counts only changes of the distance, and when the beam is broken it takes the distance again
     * from its absolute distance meter, whose error then stays in every distance until the next
     * break (Muralikrishnan et al., Precision Engineering 44 (2016) 13, the IFM and the ADM).
     * Δp = −d·û before the jump, û the line of sight from the instrument to the point, 0 after it and
     * at an unknown time (the state the campaign ended in). Computed through {@code instrumentTbase}
     * (the geometric fit's), as {@link #instrumentReading}.
     */
    public static Effect rangeStep(Pose instrumentTbase, double tauS) {
        if (!Double.isFinite(tauS)) throw new IllegalArgumentException("step time " + tauS);
        Effect e = new Effect(Kind.RANGE_STEP, -1, -1, null, false, Double.NaN, tauS, null, Double.NaN, Double.NaN, null, null, 1);
        e.instrument = instrumentTbase;
        return e;
    }

    /**
     * An error of the instrument's {@code sight} reading: a cubic B-spline of {@code n} functions of
     * that reading over [lo, hi] (m, or rad about {@code azimuthRef} for the azimuth), moving the
     * measured point along the line of sight (distance) or across it by the distance times the
     * angle's error ({@link Sight}). The readings and directions are computed from the predicted
     * point through {@code instrumentTbase} (the geometric fit's; it moves by micro-radians in the
     * joint fit, which changes the regressor by far less than the noise). It is an error of the
     * measurement, not of the robot: an extended model leaves it out of the robot's pose, and with
     * no instrument (a compensated program) it contributes nothing.
     */
    public static Effect instrumentReading(Sight sight, Pose instrumentTbase, double azimuthRef, double lo, double hi, int n) {
        if (!(hi > lo)) throw new IllegalArgumentException("instrument reading range " + lo + ".." + hi);
        if (n < 4) throw new IllegalArgumentException("instrument reading error needs at least 4 functions, got " + n);
        Effect e = new Effect(Kind.INSTRUMENT, -1, -1, null, false, Double.NaN, Double.NaN, null, lo, hi, null, null, n);
        e.sight = sight;
        e.instrument = instrumentTbase;
        e.azimuthRef = sight == Sight.AZIMUTH ? azimuthRef : 0;
        return e;
    }

    /**
     * The instrument's distances scale with time or temperature: the measured point moves along
     * the line of sight by s(u)·r, r its distance from the instrument, s a cubic B-spline
     * ({@link #POINT_BASIS} functions) of u over [lo, hi]. A laser tracker's distance meter turns
     * a count of wavelengths into a length through the air's refractive index, which it computes
     * from a weather station's air temperature, pressure and humidity (Edlén's equation): near
     * room conditions the index falls by about 0.93 ppm per kelvin and rises by about 0.27 ppm per
     * hectopascal (Muralikrishnan et al., Precision Engineering 44 (2016) 13, §3.1; Birch &amp;
     * Downs, Metrologia 30 (1993) 155), so a station that reads the air wrong, or air that changes
     * between the station and the beam, scales every distance. Over a campaign the scale drifts
     * with the hall's air; its constant part is the geometry's (a robot scaled about the
     * instrument is a robot of other lengths). Scaled about the instrument, not the robot's base:
     * the robot growing (a uniform thermal expansion) and the instrument moving toward it hold it
     * together, neither alone. Computed through {@code instrumentTbase} (the geometric fit's), as
     * {@link #instrumentReading}; an unknown time is taken as the end of the campaign, an unknown
     * temperature contributes nothing.
     */
    public static Effect instrumentScale(Along along, Pose instrumentTbase, double lo, double hi) {
        return instrumentScale(along, instrumentTbase, lo, hi, POINT_BASIS);
    }

    /** {@link #instrumentScale(Along, Pose, double, double)} with {@code n} functions of the reading (a campaign long enough to follow the air's changes). */
    public static Effect instrumentScale(Along along, Pose instrumentTbase, double lo, double hi, int n) {
        return instrumentAlong(Kind.INSTRUMENT_SCALE, along, instrumentTbase, lo, hi, n);
    }

    /** Columns of {@link #instrumentAxes}: two scales against the third axis's, three shears. */
    static final int AXES_COLUMNS = 5;

    /**
     * The instrument's axes out of square and scaled one against another: the positions it reports,
     * p_i in its own frame, are off by a constant linear map, Δp_i = S p_i with S symmetric (its
     * antisymmetric part is a turn, the registration's; its trace a uniform scale, the geometry's):
     * S = [[a, g, h], [g, b, k], [h, k, 0]], five columns, a and b the x and y axes' scales against
     * z's, g, h, k half the angles by which x and y, x and z, y and z are out of square. A coordinate
     * measuring machine's squareness errors are among the largest of its 21 geometric errors (ISO
     * 230-1 names them for machine tools; Schwenke et al., CIRP Annals 57 (2008) 660, review their
     * measurement on measuring machines); a photogrammetric
     * or stereo camera system's depth scale differs from its lateral scale where its baseline or
     * focal length is off. Computed through {@code instrumentTbase} (the geometric fit's).
     */
    public static Effect instrumentAxes(Pose instrumentTbase) {
        Effect e = new Effect(Kind.INSTRUMENT_AXES, -1, -1, null, false, Double.NaN, Double.NaN, null, Double.NaN, Double.NaN, null, null);
        e.instrument = instrumentTbase;
        return e;
    }

    /** Columns a machine's bowed ways add to {@link #instrumentAxes}: each axis's square moving the point along the other two. */
    static final int BOW_COLUMNS = 6;

    /**
     * {@link #instrumentAxes} with its ways bowed: a carriage that runs on a way bent in a parabola
     * over its travel moves the point across that axis by c·u², u its reading (the parabola's
     * centre and slope are the registration's and the axes' share), along each of the other two
     * axes, six columns more. Straightness is, with squareness, among a measuring machine's 21
     * geometric errors (Schwenke et al. 2008, above); which of its axes travels farthest the
     * positions do not say, so all three are tried.
     */
    public static Effect instrumentAxesBowed(Pose instrumentTbase) {
        Effect e = instrumentAxes(instrumentTbase);
        e.bowed = true;
        return e;
    }

    /** Whether an instrument's axes' error has its ways bowed ({@link #instrumentAxesBowed}). */
    public boolean bowed() { return bowed; }

    /** An error of the instrument's as a spline of time or temperature over [lo, hi] with {@code n} functions, seen through {@code instrumentTbase}. */
    private static Effect instrumentAlong(Kind kind, Along along, Pose instrumentTbase, double lo, double hi, int n) {
        if (along != Along.TIME && along != Along.TEMPERATURE) throw new IllegalArgumentException(kind.json + " follows time or temperature");
        if (!(hi > lo)) throw new IllegalArgumentException(kind.json + " range " + lo + ".." + hi);
        if (n < POINT_BASIS) throw new IllegalArgumentException(kind.json + " with " + n + " functions");
        Effect e = new Effect(kind, -1, -1, null, false, Double.NaN, Double.NaN, null, lo, hi, null, null, n);
        e.along = along;
        e.instrument = instrumentTbase;
        return e;
    }

    /**
     * The instrument's line of sight bent by the air: every measured point is seen moved vertically
     * (along the base's z, the robot and the instrument levelled alike) by k(u)·d², d its horizontal
     * distance from the instrument's origin and k a cubic B-spline of u (time or temperature) over
     * [lo, hi] with {@code n} functions. Light bends toward the denser air: a vertical temperature
     * gradient dT/dz gives the index a gradient dn/dz = −(n − 1)/T·dT/dz (n − 1 ≈ 2.7·10⁻⁴ in room air),
     * the ray's curvature is κ = −dn/dz, and over a chord d the ray leaves the instrument at κd/2 to
     * the chord, so the point is placed κd²/2 off it: higher with warm air above cool (the ray
     * concave down), lower with cool air above (the refraction coefficient of trigonometric heighting;
     * Muralikrishnan et al., Precision Engineering 44 (2016) 13, on a tracker's environment). k = κ/2,
     * 1/m; a gradient of 1 K/m gives about 0.5 µm at 1 m and 0.05 mm at 10 m. A hall's stratification
     * builds up as it warms and changes when the ventilation does, so k follows time. Its constant
     * part the geometry holds only in part (d² is no rigid motion). Computed through
     * {@code instrumentTbase} (the geometric fit's); an unknown time is taken as the end of the
     * campaign, an unknown temperature contributes nothing. Not the robot's: left out of compensation.
     */
    public static Effect refraction(Along along, Pose instrumentTbase, double lo, double hi, int n) {
        return instrumentAlong(Kind.REFRACTION, along, instrumentTbase, lo, hi, n);
    }

    /**
     * A cyclic error of the instrument's {@code sight} reading, a·sin(2πu/period) + b·cos(2πu/period)
     * of the reading u (a distance meter that measures a phase repeats its error with the distance:
     * the cyclic, or periodic, error of phase-measuring distance meters; Muralikrishnan et al. 2016,
     * §3.1), acting as {@link #instrumentReading}; [lo, hi] is the range of the reading seen.
     */
    public static Effect instrumentCyclic(Sight sight, Pose instrumentTbase, double azimuthRef, double lo, double hi, double period) {
        return instrumentCyclic(sight, instrumentTbase, azimuthRef, lo, hi, period, 1);
    }

    /**
     * {@link #instrumentCyclic(Sight, Pose, double, double, double, double)} with its harmonics
     * 1..{@code orders}: a_h·sin(2πhu/period) + b_h·cos(2πhu/period). A phase meter's error repeats
     * at the phase's cycle and at its harmonics (the mixing of the signals' leakage and a
     * non-linear detection add twice and more the cycle; Heydemann, Applied Optics 20 (1981) 3382,
     * for an interferometer's first- and second-order periodic errors), so a meter that measures
     * on several modulation frequencies shows a cycle and its halves and quarters.
     */
    public static Effect instrumentCyclic(Sight sight, Pose instrumentTbase, double azimuthRef, double lo, double hi, double period, int orders) {
        if (!(period > 0) || Double.isInfinite(period)) throw new IllegalArgumentException("cycle " + period);
        if (!(hi > lo)) throw new IllegalArgumentException("instrument reading range " + lo + ".." + hi);
        if (orders < 1) throw new IllegalArgumentException("cyclic error with " + orders + " harmonics");
        Effect c = new Effect(Kind.INSTRUMENT, -1, -1, null, false, Double.NaN, Double.NaN, null, lo, hi, null, null, 2 * orders);
        c.sight = sight;
        c.instrument = instrumentTbase;
        c.azimuthRef = sight == Sight.AZIMUTH ? azimuthRef : 0;
        c.cycle = period;
        return c;
    }

    /** The period of a cyclic instrument-reading error (m, or rad), NaN otherwise. */
    public double cycle() { return cycle; }

    /** The harmonics of the period a cyclic instrument-reading error holds (1..this), 0 otherwise. */
    public int cycleOrders() { return Double.isFinite(cycle) ? nBasis / 2 : 0; }

    /** The basis of a cyclic reading error at reading u: sin and cos of 2πhu/cycle for h = 1..orders. */
    private void cyclicBasis(double u, double[] b) {
        for (int h = 1; h <= nBasis / 2; h++) {
            b[2 * h - 2] = Math.sin(2 * Math.PI * h * u / cycle);
            b[2 * h - 1] = Math.cos(2 * Math.PI * h * u / cycle);
        }
    }

    /**
     * The robot's base tilting on its foundation about a horizontal edge: with e the unit horizontal
     * axis at azimuth {@code axisAzimuth} and M the moment of the arm's weight and payload about the
     * base origin ({@link GravityTorques#baseMoment}), the excess x = M·e − h tips the base by
     * φ = a·x about the edge where x &gt; 0 (a foot held by bolts or its own weight up to h rocks over
     * its edge beyond it; statics of tipping, e.g. Meriam &amp; Kraige, Engineering Mechanics: Statics,
     * §6/2), or by a·(M·e) both ways without a hold (an elastic foundation). A point p moves by
     * φ·e × (p − P0), P0 on the edge or axis it rocks about. Written P0 = s·(ẑ × e) − d·ẑ (s its
     * distance across from the axis of joint 1, d its depth below the base origin), e × P0 = s·ẑ − d·(e × ẑ)
     * (e × (ẑ × e) = ẑ), so Δp = a·x·(e × p) + b·x·ẑ + c·x·(e × ẑ) with b = −a·s (the lift) and c = a·d (the
     * slide: a robot on a pedestal, a riser or a soft slab rocks about a point below its base plate, and
     * its base slides toward the lean by the tilt times that depth). Three parameters a, b, c.
     * <p>
     * With {@code axisAzimuth} NaN the foot rocks toward whichever side the arm leans (every anchor
     * slack, a round or square foot on a soft pad): e is the horizontal moment's own direction
     * M_h/|M_h| at each pose and x = |M_h| − h (h ≥ 0; 0: an isotropic elastic foundation, φ ∝ M_h).
     * A square foot ({@link #squareFootTilt}) rocks over whichever of its four edges the moment
     * pushes it past.
     */
    public static Effect baseTilt(GravityTorques gravity, double axisAzimuth, double holdNm) {
        return baseTilt(gravity, axisAzimuth, holdNm, null);
    }

    /**
     * {@link #baseTilt(GravityTorques, double, double)} with the file's mass k scaled by
     * {@code massScales[k]} (null: the file's masses): the moment that tips the base is the arm's
     * real weight's, and a data sheet's link masses are rarely better than ±30 %.
     */
    public static Effect baseTilt(GravityTorques gravity, double axisAzimuth, double holdNm, double[] massScales) {
        if (gravity == null) throw new IllegalArgumentException("a base tilt needs the arm's masses");
        if (Double.isNaN(axisAzimuth) && !(holdNm >= 0)) throw new IllegalArgumentException("a tilt toward the lean holds a moment >= 0, not " + holdNm);
        GravityTorques g = massScales == null ? gravity : gravity.withMassScales(massScales);
        Effect e = new Effect(Kind.BASE_TILT, -1, -1, g, false, Double.NaN, Double.NaN, null, Double.NaN, Double.NaN, null, null, TILT_COLUMNS);
        e.tiltAzimuth = axisAzimuth;
        e.tiltHold = holdNm;
        e.massScales = massScales == null ? null : massScales.clone();
        return e;
    }

    /**
     * A square foot held down along its four edges (a robot's base plate bolted at its corners): it
     * rocks over the edge whose axis, at {@code edgeAzimuth} + k·90°, the arm's moment exceeds the hold
     * most (Meriam &amp; Kraige §6/2 for each edge), so as the arm swings around joint 1 the base tips
     * over one edge, then the next; h ≥ 0.
     */
    public static Effect squareFootTilt(GravityTorques gravity, double edgeAzimuth, double holdNm, double[] massScales) {
        if (!(holdNm >= 0) || Double.isInfinite(holdNm)) throw new IllegalArgumentException("a square foot holds a moment >= 0, not " + holdNm);
        Effect e = baseTilt(gravity, edgeAzimuth, holdNm, massScales);
        e.tiltEdges = 4;
        return e;
    }

    /**
     * The bearing of revolute joint {@code joint} wobbling: the joint's axis tilts across itself as
     * the joint turns, by a pattern that repeats {@code orders} times per turn in the fixed (stator)
     * part's frame (a race's waviness or runout, a worn or unloaded cross-roller bearing: the
     * rotating ring tilts on the rolling elements as they pass the high spots; Harris &amp; Kotzalas,
     * Rolling Bearing Analysis, on raceway waviness). Everything beyond the joint turns by a small
     * rotation ω about a point of the axis, ω across the axis:
     * ω = Σ_h (x_c cos hθ + x_s sin hθ) x̂ + (y_c cos hθ + y_s sin hθ) ŷ, θ the joint's own turn
     * (its model angle: a drive coupled to another reads more than it), x̂, ŷ the stator frame's
     * axes across the joint (the tilt error motion of ISO 230-7:2015). The measured point moves by
     * ω × (p − o), o the model's point of the axis (frame j's origin); the measured frame turns by
     * ω. Four parameters per order (rad). A tilt that is constant in the stator's or the rotor's
     * frame is the geometry's (order 0, and the half of order 1 that turns with the link; the other
     * half, turning against it, is a wobble). The bearing's radial error motion (a shift across the
     * axis, which a tilt about another point of the axis also brings) is left out: across a wrist
     * joint it is the next drive's error of that joint's angle, so it would stand in for the wrist's
     * couplings and two-joint errors.
     */
    public static Effect axisWobble(KinematicModel model, int joint, int[] orders) {
        if (model.isPrismatic(joint)) throw new IllegalArgumentException("joint " + (joint + 1) + " is prismatic: no bearing axis to wobble");
        for (int h : orders) if (h < 1) throw new IllegalArgumentException("a wobble's order is >= 1, not " + h);
        return new Effect(Kind.AXIS_WOBBLE, joint, -1, null, false, Double.NaN, Double.NaN, orders.clone(), Double.NaN, Double.NaN, model, null);
    }

    /**
     * A joint's bearing running out along its axis (outside every family): the rotating ring follows
     * the axial waviness of its race, or a race's face runs out, so everything beyond the joint moves
     * along the joint's axis as it turns, δ(θ) = Σ_h (z_c cos hθ + z_s sin hθ) (the axial error
     * motion of ISO 230-7:2015; Harris &amp; Kotzalas, Rolling Bearing Analysis, on raceway waviness),
     * θ the joint's own turn (its model angle). The measured point moves by δ(θ) ẑ, ẑ the axis in
     * base coordinates; the measured frame does not turn. Two parameters per order (m). No error of a
     * joint's angle moves a point along that joint's own axis, and a tilt of the axis moves it in
     * proportion to its distance from the axis, so the shift is its own structure. A constant shift
     * (order 0) is the geometry's.
     */
    public static Effect axialRunout(KinematicModel model, int joint, int[] orders) {
        if (model.isPrismatic(joint)) throw new IllegalArgumentException("joint " + (joint + 1) + " is prismatic: no bearing to run out");
        for (int h : orders) if (h < 1) throw new IllegalArgumentException("an axial runout's order is >= 1, not " + h);
        return new Effect(Kind.AXIAL_RUNOUT, joint, -1, null, false, Double.NaN, Double.NaN, orders.clone(), Double.NaN, Double.NaN, model, null);
    }

    /** The joint's axis in base coordinates at q, into {@code z}; returns the joint's own turn (its model angle). */
    private double runoutFrame(double[] q, double[] z) {
        Pose rotor = model.linkFrames(q)[joint + 1]; // z on the joint's axis
        for (int a = 0; a < 3; a++) z[a] = rotor.rot(a, 2);
        return model.theta(q)[joint];
    }

    /**
     * An axis wobble's columns at q (3 x size, row-major, base frame): the distal bodies' rotation
     * per unit of each parameter; and a point {@code o} of the joint's axis.
     */
    private void wobble(double[] q, double[] w, double[] o) {
        int k = size();
        double th = model.theta(q)[joint];
        double[] xs = new double[3], ys = new double[3];
        statorAxes(q, xs, ys, o);
        // the pattern follows the joint's own turn, its model angle (a drive coupled to another joint reads more than its turn)
        for (int i = 0; i < harmonics.length; i++) {
            double c = Math.cos(harmonics[i] * th), s = Math.sin(harmonics[i] * th);
            for (int a = 0; a < 3; a++) {
                w[a * k + 4 * i] = c * xs[a];
                w[a * k + 4 * i + 1] = s * xs[a];
                w[a * k + 4 * i + 2] = c * ys[a];
                w[a * k + 4 * i + 3] = s * ys[a];
            }
        }
    }

    /**
     * The stator's axes across this effect's joint at q (base frame): the rotor frame's x and y turned back
     * by the joint's model angle; and {@code o}, the model's point of the axis (the rotor frame's origin).
     */
    private void statorAxes(double[] q, double[] xs, double[] ys, double[] o) {
        Pose rotor = model.linkFrames(q)[joint + 1]; // z on the joint's axis, origin on it, turned by the joint
        double th = model.theta(q)[joint], ct = Math.cos(th), st = Math.sin(th);
        for (int a = 0; a < 3; a++) {
            double xr = rotor.rot(a, 0), yr = rotor.rot(a, 1);
            xs[a] = ct * xr - st * yr;
            ys[a] = st * xr + ct * yr;
        }
        o[0] = rotor.x();
        o[1] = rotor.y();
        o[2] = rotor.z();
    }

    /**
     * A joint's axis tilting across itself with the torque its drive carries (outside every family): the
     * final stage's tooth force τ/r and its separating force |τ|·tan α/r (α the pressure angle), acting on
     * an overhung output gear, bend the output shaft on its bearings, so everything beyond the joint turns
     * about a point of the axis by ω = (x_t τ + x_s |τ|) x̂ + (y_t τ + y_s |τ|) ŷ, τ/τ_ref the drive's gravity
     * torque over its largest on the poses, x̂, ŷ the stator frame's axes across the joint (fixed to the
     * housing that holds the mesh; Budynas &amp; Nisbett, Shigley's Mechanical Engineering Design, 10th ed.,
     * §13-14, the forces on a spur gear's teeth, and ch. 4, a shaft's deflection under them). The measured
     * point moves by ω × (p − o), o the model's point of the axis; the measured frame turns by ω. Four
     * parameters, rad at the reference torque: the tilt that follows the torque's sign (the tooth force)
     * and the one that follows its size (the separating force). A joint's angle error under the same torque
     * is its compliance; a tilt under it, no error of the angle.
     */
    public static Effect loadTilt(KinematicModel model, int joint, GravityTorques g, double refNm) { return loadTilt(model, joint, g, refNm, null); }

    /** {@link #loadTilt} with the masses of {@code g} each scaled by {@code massScales} (null: as they are). */
    public static Effect loadTilt(KinematicModel model, int joint, GravityTorques g, double refNm, double[] massScales) {
        if (model.isPrismatic(joint)) throw new IllegalArgumentException("joint " + (joint + 1) + " is prismatic: no shaft to tilt");
        if (!(refNm > 0) || Double.isInfinite(refNm)) throw new IllegalArgumentException("reference torque " + refNm);
        GravityTorques scaled = massScales == null ? g : g.withMassScales(massScales);
        Effect e = new Effect(Kind.LOAD_TILT, joint, -1, scaled, false, Double.NaN, Double.NaN, null, Double.NaN, Double.NaN, model, null);
        e.loadRefNm = refNm;
        e.massScales = massScales == null ? null : massScales.clone();
        e.fileGravity = g;
        return e;
    }

    /** A load tilt with the masses as they were before any scales (itself when it has none). */
    public Effect withFileMasses() { return massScales == null ? this : loadTilt(model, joint, fileGravity, loadRefNm, null); }

    /** A load tilt's four tilt columns (3 x 4, row-major, base axes) at q under c, and the model's point of the axis o. */
    private void loadTilt(double[] q, PoseConditions c, double[] w, double[] o) {
        int k = size();
        double[] xs = new double[3], ys = new double[3];
        statorAxes(q, xs, ys, o);
        double tau = gravity.driveTorques(q, Double.isFinite(c.payloadKg()) ? c.payloadKg() : 0)[joint] / loadRefNm;
        for (int a = 0; a < 3; a++) {
            w[a * k] = tau * xs[a];
            w[a * k + 1] = Math.abs(tau) * xs[a];
            w[a * k + 2] = tau * ys[a];
            w[a * k + 3] = Math.abs(tau) * ys[a];
        }
    }

    /**
     * The measured point's holder (an extension bar, a nest, a tool) bending under its own weight:
     * a cantilever's tip deflects in proportion to the part of its weight across it (Euler-Bernoulli,
     * δ = wL⁴/8EI + PL³/3EI; Gere &amp; Goodno, Mechanics of Materials, table G-1), so in the flange's
     * frame the point moves by a fixed linear map of gravity's direction seen from the flange,
     * Δp_f = A·ĝ_f, a compliance matrix times the weight (its two bending directions and their
     * stiffnesses unknown). In base axes Δp = R·A·Rᵀ·ĝ, R the flange's orientation: nine parameters
     * (m), A row-major; A's isotropic part is a constant shift, the geometry's.
     */
    public static Effect toolSag(KinematicModel model, Vec3 down) {
        if (!(down.norm() > 0)) throw new IllegalArgumentException("no gravity direction");
        Effect e = new Effect(Kind.TOOL_SAG, -1, -1, null, false, Double.NaN, Double.NaN, null, Double.NaN, Double.NaN, model, null);
        e.down = down.times(1 / down.norm());
        return e;
    }

    /**
     * The measured point's holder, or the flange on its bearing, tipping within a clearance toward
     * gravity (outside every family): a loose target nest or tool mount, or the radial clearance of
     * the flange's bearing pair, is taken up to the side the tool's weight pulls it across its axis,
     * by about the same amount whichever way that is once the pull is more than the friction holds
     * (a play taken up by a load; Nordin &amp; Gutman 2002 for a play, Harris &amp; Kotzalas for a
     * bearing's clearance). With ĝ_f gravity's direction in the flange's frame (z the tool's axis),
     * the side it pulls to is u = (ĝ_x, ĝ_y) / √(ĝ_x² + ĝ_y² + {@link #PLAY_TAKE_UP}²), a unit vector
     * across the axis once the axis leans, fading where it hangs straight down or up; the point moves
     * by Δp_f = B·u (B 3 x 2: the play's sizes and directions unknown), Δp = R·B·u in base axes. A
     * holder that bends (tool-sag) moves in proportion to the pull instead. Six parameters (m).
     * With {@code turns} (the flange's orientation measured) the flange also tips across its axis,
     * Δω_f = (C·u, 0) with C 2 x 2 (rad), Δω = R·Δω_f: four more parameters. The point's share of
     * that tip (Δω_f × its offset) is again linear in u, held by B.
     */
    public static Effect toolPlay(KinematicModel model, Vec3 down, boolean turns) {
        if (!(down.norm() > 0)) throw new IllegalArgumentException("no gravity direction");
        Effect e = new Effect(Kind.TOOL_PLAY, -1, -1, null, false, Double.NaN, Double.NaN, null, Double.NaN, Double.NaN, model, null);
        e.down = down.times(1 / down.norm());
        e.playTurns = turns;
        return e;
    }

    /** The tool-play columns that move the point ({@link #toolPlay}): six. */
    static final int PLAY_SHIFTS = 6;

    /** The tool-play columns that tip the flange ({@link #toolPlay} with its turns): four. */
    static final int PLAY_TIPS = 4;

    /** The lean of the tool's axis (as the part of gravity across it) over which a play is taken up: about 9 deg. */
    static final double PLAY_TAKE_UP = 0.15;

    /**
     * The regressor (row-major, base axes, 3 x k from column {@code from}) of {@link #toolPlay} at
     * flange pose {@code f}: its point shifts B·u, or with {@code tips} its flange's tips C·u.
     */
    static void toolPlayRegressor(Pose f, Vec3 down, boolean tips, double[] g3, int k, int from) {
        double gx = f.rot(0, 0) * down.x() + f.rot(1, 0) * down.y() + f.rot(2, 0) * down.z();
        double gy = f.rot(0, 1) * down.x() + f.rot(1, 1) * down.y() + f.rot(2, 1) * down.z();
        double n = Math.sqrt(gx * gx + gy * gy + PLAY_TAKE_UP * PLAY_TAKE_UP);
        double[] u = {gx / n, gy / n};
        int across = tips ? 2 : 3; // a tip turns about the flange's x and y only
        for (int axis = 0; axis < 3; axis++)
            for (int a = 0; a < across; a++)
                for (int b = 0; b < 2; b++) g3[axis * k + from + 2 * a + b] = f.rot(axis, a) * u[b];
    }

    /** The kinematic model an effect on the measured point works with (thermal growth per link, a step of the target, a wobble, a tool sag); null otherwise. */
    public KinematicModel model() { return model; }

    /** Gravity's direction (base frame, unit) of a tool sag; null for other kinds. */
    public Vec3 down() { return down; }

    /** The angle of flange pose {@code f}'s z axis from gravity's direction {@code down} (deg): 0 pointing straight down. */
    static double angleFromDown(Pose f, Vec3 down) {
        return Math.toDegrees(Math.acos(Math.max(-1, Math.min(1, f.rot(0, 2) * down.x() + f.rot(1, 2) * down.y() + f.rot(2, 2) * down.z()))));
    }

    /**
     * An error of the measured point that follows the direction the instrument sees it from, in the
     * tool's frame: a glass-prism reflector seen off its axis refracts the beam (Snell's law in the
     * glass), so its apparent centre moves with the incidence angle, across the line of sight with
     * odd powers of it and along it with even ones (by symmetry about the prism's axis), and the
     * tracker's reflector constant holds only at normal incidence; a reflector's errors are reviewed
     * by Muralikrishnan et al., Precision Engineering 44 (2016). With u the unit vector
     * from the instrument to the point in flange axes, and s, t its components across {@code axis}
     * (the mean direction the point is seen from), the point moves in flange axes by a polynomial of
     * degrees 1–3 in s, t along each axis ({@link #INCIDENCE_ACROSS}) and one of degree 4 along the
     * axis ({@link #INCIDENCE_ALONG}); the constant is the tool offset, the geometry's. It is an
     * error of the measurement, not of the robot: the extended model leaves it out of the robot's pose.
     */
    public static Effect targetIncidence(KinematicModel model, Pose instrumentTbase, Vec3 axis) {
        if (!(axis.norm() > 0)) throw new IllegalArgumentException("no sight axis");
        Effect e = new Effect(Kind.TARGET_INCIDENCE, -1, -1, null, false, Double.NaN, Double.NaN, null, Double.NaN, Double.NaN, model, null);
        e.instrument = instrumentTbase;
        e.sightAxis = axis.times(1 / axis.norm());
        e.sightOrigin = instrumentOrigin(instrumentTbase);
        e.sightAcross = acrossAxis(e.sightAxis);
        return e;
    }

    /** A target incidence's monomials of s, t across the axis (each times a flange axis), and of degree 4 along the axis. */
    static final String[] INCIDENCE_ACROSS = {"s", "t", "ss", "st", "tt", "sss", "sst", "stt", "ttt"},
            INCIDENCE_ALONG = {"ssss", "ssst", "sstt", "sttt", "tttt"};
    /** A target incidence's parameters: each flange axis times the monomials across, and the axis times those along. */
    static final int INCIDENCE_TERMS = 3 * INCIDENCE_ACROSS.length + INCIDENCE_ALONG.length;

    /** The degree in s, t of a target incidence's parameter {@code i}. */
    static int incidenceDegree(int i) {
        int na = INCIDENCE_ACROSS.length;
        return i >= 3 * na ? INCIDENCE_ALONG[i - 3 * na].length() : INCIDENCE_ACROSS[i % na].length();
    }

    /** The instrument's origin in base axes, from instrumentTbase. */
    static Vec3 instrumentOrigin(Pose instrumentTbase) { return instrumentTbase.inverse().position(); }

    /**
     * The direction the point at {@code pointBase} is seen from, in flange axes at flange pose f: the
     * unit vector from the instrument's origin {@code origin} to it.
     */
    static Vec3 sightInFlange(Pose f, Vec3 origin, double[] pointBase) {
        double ux = pointBase[0] - origin.x(), uy = pointBase[1] - origin.y(), uz = pointBase[2] - origin.z();
        double n = Math.sqrt(ux * ux + uy * uy + uz * uz);
        if (!(n > 0)) return new Vec3(0, 0, 0);
        return new Vec3((f.rot(0, 0) * ux + f.rot(1, 0) * uy + f.rot(2, 0) * uz) / n, (f.rot(0, 1) * ux + f.rot(1, 1) * uy + f.rot(2, 1) * uz) / n,
                (f.rot(0, 2) * ux + f.rot(1, 2) * uy + f.rot(2, 2) * uz) / n);
    }

    /** Two unit vectors across the unit vector {@code axis}, right-handed with it. */
    static Vec3[] acrossAxis(Vec3 axis) {
        Vec3 ref = Math.abs(axis.x()) < 0.9 ? new Vec3(1, 0, 0) : new Vec3(0, 1, 0);
        Vec3 e1 = axis.cross(ref);
        e1 = e1.times(1 / e1.norm());
        return new Vec3[] {e1, axis.cross(e1)};
    }

    /** A target incidence's angle between the direction the point at {@code pointBase} is seen from at joints q and its sight axis, deg. */
    double incidenceAngle(double[] q, double[] pointBase) {
        return incidenceAngle(sightInFlange(model.flange(q), sightOrigin, pointBase), sightAxis);
    }

    /** The angle between the direction {@code sight} the point is seen from (flange frame, unit) and the sight axis, deg. */
    static double incidenceAngle(Vec3 sight, Vec3 axis) { return Math.toDegrees(Math.acos(Math.max(-1, Math.min(1, sight.dot(axis))))); }

    /**
     * A target incidence's regressor (3 x {@link #INCIDENCE_TERMS}, row-major, base axes) at flange pose f, the instrument at
     * {@code origin} (base frame), the sight axis and two unit vectors across it ({@link #acrossAxis}).
     */
    static void incidenceRegressor(Pose f, Vec3 origin, Vec3 axis, Vec3[] perp, double[] pointBase, double[] g3) {
        Vec3 u = sightInFlange(f, origin, pointBase);
        double a = u.dot(perp[0]), b = u.dot(perp[1]);
        double[] across = {a, b, a * a, a * b, b * b, a * a * a, a * a * b, a * b * b, b * b * b};
        double[] along = {a * a * a * a, a * a * a * b, a * a * b * b, a * b * b * b, b * b * b * b};
        int k = INCIDENCE_TERMS, na = across.length;
        // the along-axis direction in base axes: R·axis
        double[] ab = new double[3];
        for (int r = 0; r < 3; r++) ab[r] = f.rot(r, 0) * axis.x() + f.rot(r, 1) * axis.y() + f.rot(r, 2) * axis.z();
        for (int r = 0; r < 3; r++) {
            for (int fa = 0; fa < 3; fa++) for (int m = 0; m < na; m++) g3[r * k + fa * na + m] = f.rot(r, fa) * across[m];
            for (int m = 0; m < along.length; m++) g3[r * k + 3 * na + m] = ab[r] * along[m];
        }
    }

    /** The instrument pose of an effect's robot-file form (its translation and rotation vector). */
    private static void putInstrument(Map<String, Double> p, Pose instrument) {
        Vec3 w = instrument.rotationVector();
        p.put("instrument_x", instrument.x());
        p.put("instrument_y", instrument.y());
        p.put("instrument_z", instrument.z());
        p.put("instrument_rx", w.x());
        p.put("instrument_ry", w.y());
        p.put("instrument_rz", w.z());
    }

    /** The instrument pose an effect's robot-file form holds. */
    private static Pose instrumentOf(EffectDescription d, String file) {
        Vec3 w0 = new Vec3(require(d, "instrument_rx", file), require(d, "instrument_ry", file), require(d, "instrument_rz", file));
        return Pose.translation(require(d, "instrument_x", file), require(d, "instrument_y", file), require(d, "instrument_z", file))
                .times(w0.norm() > 0 ? Pose.rotAxis(w0.times(1 / w0.norm()), w0.norm()) : Pose.IDENTITY);
    }

    /** A tool sag's regressor (3 x 9, row-major) at flange pose f: column 3a + b moves the point by R[:, a]·(Rᵀĝ)_b. */
    static void toolSagRegressor(Pose f, Vec3 down, double[] g3) {
        double[] gf = {f.rot(0, 0) * down.x() + f.rot(1, 0) * down.y() + f.rot(2, 0) * down.z(),
                f.rot(0, 1) * down.x() + f.rot(1, 1) * down.y() + f.rot(2, 1) * down.z(),
                f.rot(0, 2) * down.x() + f.rot(1, 2) * down.y() + f.rot(2, 2) * down.z()};
        for (int axis = 0; axis < 3; axis++)
            for (int a = 0; a < 3; a++)
                for (int b = 0; b < 3; b++) g3[axis * 9 + 3 * a + b] = f.rot(axis, a) * gf[b];
    }

    /**
     * An arm link bending under gravity as a beam, in the plane its joint turns it in: the upper
     * arm from joint 2's axis to joint 3's, or the forearm from joint 3's axis to the wrist's centre
     * (on joint 5's axis), is a cantilever held at its joint. The part of gravity across it, g_n = ĝ·n̂
     * (n̂ = ẑ × ê across the link in that plane, ê along it, ẑ the joint's axis), loads it with its
     * own weight and with the weight it carries at its far end. A beam's far end moves across it by
     * δ and turns by θ about ẑ in proportion to each load (Euler-Bernoulli: δ = wL⁴/8EI and
     * θ = wL³/6EI for its own weight, PL³/3EI and PL²/2EI for a force at its far end; Gere &amp;
     * Goodno, Mechanics of Materials, table G-1): everything beyond moves by δ n̂ + θ ẑ × (p − e)
     * (e the far end) and turns by θ ẑ. Columns: δ and θ per unit g_n (the two loads' mix unknown,
     * so their ratio free); with {@code payloadColumns}, θ per kg of payload times g_n with
     * δ = θ·2L/3 (a force at the far end). A moment passed on at the far end is left out: on a
     * parallel-link arm the forearm's moment goes down the link rod to its drive, not through the
     * upper arm, and with it the bending and the next joint's spring together held the spring of
     * the link's own joint (δ = L·θ for all of its torque). That spring's part from the weight across
     * the link is in the bending's span, the part from the bodies beyond (the next drive's torque)
     * is not.
     */
    public static Effect linkSag(KinematicModel model, int joint, boolean payloadColumns) {
        if (joint < 1 || joint + 1 >= model.dof() || model.isPrismatic(joint))
            throw new IllegalArgumentException("link sag is of the upper arm or the forearm (revolute joints 2 or 3), not joint " + (joint + 1));
        Effect e = new Effect(Kind.LINK_SAG, joint, -1, null, false, Double.NaN, Double.NaN, null, Double.NaN, Double.NaN, model, null);
        e.sagPayload = payloadColumns;
        e.down = DOWN;
        return e;
    }

    /** A link sag's share of gravity across its link at q (g_n, between −1 and 1; 0 for a link too short). */
    public double sagAcross(double[] q) {
        Bend b = bend(q);
        return b == null ? 0 : down.dot(b.across);
    }

    /**
     * A bending or twisting link at q: its joint's axis ẑ and point o, its far end, the unit vectors
     * along it ê (across ẑ) and across it n̂ = ẑ × ê, its length across ẑ.
     */
    private record Bend(Vec3 axis, Vec3 root, Vec3 end, Vec3 along, Vec3 across, double length) { }

    /** The link sag's or twist's link at q; null where it is shorter than {@link #MIN_LINK_M} across its joint's axis. */
    private Bend bend(double[] q) { return bend(model.linkFrames(q)); }

    /** {@link #bend(double[])} with the link frames {@code f} at q. */
    private Bend bend(Pose[] f) {
        Pose root = f[joint + 1];
        // the far end: the next joint's axis for the upper arm, the wrist's centre (joint 5's axis, which joints 4 and 6 meet)
        // for the forearm, whose own axis runs along joint 4's
        Vec3 z = new Vec3(root.rot(0, 2), root.rot(1, 2), root.rot(2, 2)), end = f[Math.min(joint == 2 ? 5 : joint + 2, f.length - 1)].position();
        Vec3 l = end.minus(root.position());
        l = l.minus(z.times(l.dot(z)));
        double len = l.norm();
        if (len < MIN_LINK_M) return null;
        Vec3 along = l.times(1 / len);
        return new Bend(z, root.position(), end, along, z.cross(along), len);
    }

    /**
     * Whether this fallback holds part of named effect {@code e}'s shape in its span: a link's
     * bending holds the part of its joint's spring that the weight across the link drives (δ = L·θ);
     * a load-periodic error holds the whole of the transmission error it was made from ({@link #nests}).
     */
    public boolean holdsPartOf(Effect e) {
        if (kind == Kind.BASE_TURN && e.kind == Kind.DRIFT) return e.usesTimeProxy() == (along == Along.TIME);
        if (nests(e)) return true;
        return (kind == Kind.LINK_SAG || kind == Kind.COMPLIANCE_VARYING) && e.kind == Kind.COMPLIANCE && e.joint == joint;
    }

    /**
     * Whether this fallback holds all of named effect {@code e}'s columns and more: a load-periodic
     * error and the transmission error of its joint at its orders. What it finds beside {@code e} is
     * then {@code e}'s own shape changing (its size with the load), not another structure.
     */
    public boolean nests(Effect e) {
        // a varying compliance on the whole torque holds its joint's linear compliance (the splines sum to one), one per mass
        // where the masses are unknown
        if (kind == Kind.COMPLIANCE_VARYING && !payloadShare && e.kind == Kind.COMPLIANCE && e.joint == joint && !e.stiffens
                && e.gravity == gravity && e.perMass == gravity.massesUnknown()) return true;
        return (kind == Kind.LOAD_PERIODIC || kind == Kind.WARM_PERIODIC) && e.kind == Kind.PERIODIC && e.joint == joint
                && Arrays.equals(e.orders(), orders());
    }

    /** Whether a link sag has the columns of the payload's weight at its far end. */
    public boolean sagPayload() { return sagPayload; }

    /**
     * A link sag's columns at q under c: the point's move (3 x size, row-major) for a point at
     * {@code pointBase}, or the frame's turn; either may be null. Zero where the link is shorter
     * than {@link #MIN_LINK_M} across its axis.
     */
    private void linkSagColumns(double[] q, PoseConditions c, double[] pointBase, double[] g3, double[] w3) {
        int k = size();
        if (g3 != null) Arrays.fill(g3, 0);
        if (w3 != null) Arrays.fill(w3, 0);
        Bend b = bend(q);
        if (b == null) return;
        Vec3 z = b.axis, end = b.end, n = b.across;
        double len = b.length, gn = down.dot(n);
        double payload = Double.isFinite(c.payloadKg()) ? c.payloadKg() : 0;
        Vec3 turn = pointBase == null ? null : z.cross(new Vec3(pointBase[0], pointBase[1], pointBase[2]).minus(end));
        // each column: the far end's move across the link per unit (along n̂) and its turn about ẑ per unit
        double[] across = new double[k], turns = new double[k];
        across[0] = gn;
        turns[1] = gn;
        if (sagPayload) { across[2] = payload * gn * 2 * len / 3; turns[2] = payload * gn; }
        for (int i = 0; i < k; i++) {
            if (g3 != null) {
                g3[i] = across[i] * n.x() + (turn == null ? 0 : turns[i] * turn.x());
                g3[k + i] = across[i] * n.y() + (turn == null ? 0 : turns[i] * turn.y());
                g3[2 * k + i] = across[i] * n.z() + (turn == null ? 0 : turns[i] * turn.z());
            }
            if (w3 != null) {
                w3[i] = turns[i] * z.x();
                w3[k + i] = turns[i] * z.y();
                w3[2 * k + i] = turns[i] * z.z();
            }
        }
    }

    /**
     * The upper arm twisting about its own long axis under the torque of the weights beyond it: a
     * bar under a torque T about its axis turns its far end by φ = T L / (G J) in the sense of T
     * (Saint-Venant torsion, Timoshenko &amp; Goodier, Theory of Elasticity, ch. 10; Gere &amp;
     * Goodno, Mechanics of Materials, §3.3). The axis ê runs from joint 2's axis to joint 3's,
     * across joint 2's axis; everything beyond turns by φ ê about joint 2's point: Δp = φ ê × (p − o).
     * The weights' torque about ê through o is T = g Σ m (c − o)·(ĝ × ê) (ĝ the unit of gravity):
     * only weight beside the arm's plane twists it, the forearm's centre off the plane and the
     * tool's and the payload's, which the wrist swings about. With their masses and centres unknown
     * it is linear in each body's mass and first moments: for the forearm, which turns with joint 3
     * about an axis parallel to joint 2's, only the part across the plane counts, u·z₃ (u = ĝ × ê);
     * for the wrist's two bodies, whose masses sit at the wrist's centre (their masses' part is the
     * forearm's), their first moments along their own axes, u·x₄, u·y₄, u·z₄ and u·x₅, u·y₅, u·z₅;
     * for the body on the flange (the hand, the tool) its mass at the flange's origin, u·(o_f − o),
     * and its first moments along the flange's axes, u·x_f, u·y_f, u·z_f. With {@code
     * payloadColumns}, the payload's four again, times its mass. Columns: φ per unit of each (the
     * coefficients g m / k and g m c / k, k = G J / L); a lever that is no more than rounding at a
     * pose (an axis that stays in the arm's plane) is taken as zero there.
     * The forearm's own twist about its long axis is joint 4's turn, a spring of that drive.
     */
    public static Effect linkTwist(KinematicModel model, boolean payloadColumns) {
        if (model.dof() < 6 || model.isPrismatic(1) || model.isPrismatic(2))
            throw new IllegalArgumentException("link twist is of a six-axis arm's upper arm between revolute joints 2 and 3");
        Effect e = new Effect(Kind.LINK_TWIST, 1, -1, null, false, Double.NaN, Double.NaN, null, Double.NaN, Double.NaN, model, null);
        e.sagPayload = payloadColumns;
        e.down = DOWN;
        return e;
    }

    /** Columns of a link twist before the payload's: the forearm's weight across the arm's plane, the wrist's two bodies' first moments, the hand's mass and first moments. */
    static final int TWIST_ARM_TERMS = 11;
    /** A link twist's lever below this (m, or a unit vector's component) is rounding of one that is zero. */
    private static final double TWIST_LEVER_ZERO = 1e-9;

    /**
     * A link twist's lever columns at q under c (its size; the twist φ = Σ v_i x_i), and the upper arm
     * whose axis ê it turns about ({@link Bend#along}, through {@link Bend#root}); null, with the
     * columns zero, where the upper arm is shorter than {@link #MIN_LINK_M} across joint 2's axis.
     */
    private Bend twistLevers(double[] q, PoseConditions c, double[] x) {
        Arrays.fill(x, 0);
        Pose[] f = model.linkFrames(q);
        Bend b = bend(f);
        if (b == null) return null;
        Vec3 o = b.root(), u = down.cross(b.along());
        Pose fl = f[f.length - 1];
        double[] arm = {u.dot(f[3].zAxis()), u.dot(f[4].xAxis()), u.dot(f[4].yAxis()), u.dot(f[4].zAxis()),
                u.dot(f[5].xAxis()), u.dot(f[5].yAxis()), u.dot(f[5].zAxis()),
                u.dot(fl.position().minus(o)), u.dot(fl.xAxis()), u.dot(fl.yAxis()), u.dot(fl.zAxis())};
        for (int i = 0; i < arm.length; i++) if (Math.abs(arm[i]) < TWIST_LEVER_ZERO) arm[i] = 0;
        System.arraycopy(arm, 0, x, 0, TWIST_ARM_TERMS);
        if (sagPayload) {
            double payload = c != null && Double.isFinite(c.payloadKg()) ? c.payloadKg() : 0;
            for (int i = 0; i < HAND_TERMS; i++) x[TWIST_ARM_TERMS + i] = payload * arm[TWIST_ARM_TERMS - HAND_TERMS + i];
        }
        return b;
    }

    /** A link twist's columns at q under c: the point's move (3 x size) for a point at {@code pointBase}, or the frame's turn. */
    private void linkTwistColumns(double[] q, PoseConditions c, double[] pointBase, double[] g3, double[] w3) {
        int k = size();
        if (g3 != null) Arrays.fill(g3, 0);
        if (w3 != null) Arrays.fill(w3, 0);
        double[] x = new double[k];
        Bend b = twistLevers(q, c, x);
        if (b == null) return;
        Vec3 e = b.along();
        Vec3 move = pointBase == null ? null : e.cross(new Vec3(pointBase[0], pointBase[1], pointBase[2]).minus(b.root()));
        for (int i = 0; i < k; i++) {
            if (g3 != null && move != null) {
                g3[i] = x[i] * move.x();
                g3[k + i] = x[i] * move.y();
                g3[2 * k + i] = x[i] * move.z();
            }
            if (w3 != null) {
                w3[i] = x[i] * e.x();
                w3[k + i] = x[i] * e.y();
                w3[2 * k + i] = x[i] * e.z();
            }
        }
    }

    /** A link twist's lateral lever of the flange at q: u·(o_f − o), m (the plot's variable). */
    public double twistLever(double[] q) {
        double[] x = new double[size()];
        return twistLevers(q, null, x) == null ? 0 : x[TWIST_ARM_TERMS - HAND_TERMS];
    }

    /** A link twist's columns of the body on the flange (and of the payload): its mass, then its three first moments. */
    static final int HAND_TERMS = 4;

    /** A base tilt's excess moment about its axis at q with a payload (N·m, ≥ 0 with a hold). */
    double tiltExcess(double[] q, double payloadKg) { return tilt(q, payloadKg)[2]; }

    /** Whether a base tilt rocks toward whichever side the arm leans (its axis the moment's own), not about one edge. */
    public boolean towardLean() { return kind == Kind.BASE_TILT && Double.isNaN(tiltAzimuth); }

    /** Whether a base tilt is a square foot's ({@link #squareFootTilt}). */
    public boolean squareFoot() { return kind == Kind.BASE_TILT && tiltEdges == 4; }

    /** A base tilt at q with a payload: its axis (cos, sin; {0, 0} where a lean-following tilt has no moment) and excess moment x (N·m). */
    private double[] tilt(double[] q, double payloadKg) {
        Vec3 m = gravity.baseMoment(q, payloadKg);
        double[] t = tiltAt(m.x(), m.y(), tiltAzimuth, tiltEdges);
        if (!Double.isInfinite(tiltHold)) t[2] = Math.max(0, t[2] - tiltHold);
        return t;
    }

    /**
     * The axis (cos, sin) and the moment about it (N·m, before any hold) of a tilt under the horizontal
     * moment (mx, my): about the axis at {@code azimuth} (one edge), about the most loaded of the four at
     * {@code azimuth} + k·90° ({@code edges} 4), or about the moment's own direction ({@code azimuth} NaN).
     */
    static double[] tiltAt(double mx, double my, double azimuth, int edges) {
        if (Double.isNaN(azimuth)) {
            double h = Math.hypot(mx, my);
            return h > 0 ? new double[] {mx / h, my / h, h} : new double[3];
        }
        double c = Math.cos(azimuth), s = Math.sin(azimuth);
        double[] best = {c, s, mx * c + my * s};
        for (int k = 1; k < edges; k++) {
            double ck = Math.cos(azimuth + k * Math.PI / 2), sk = Math.sin(azimuth + k * Math.PI / 2), x = mx * ck + my * sk;
            if (x > best[2]) { best[0] = ck; best[1] = sk; best[2] = x; }
        }
        return best;
    }

    /** A base tilt's parameters and regressor columns: the tilt, the lift and the slide ({@link #baseTilt}). */
    static final int TILT_COLUMNS = 3;

    /**
     * A base tilt's regressor (3 x {@link #TILT_COLUMNS}, row-major) at excess moment {@code x} about the unit axis
     * (ex, ey, 0) for a point at {@code p}: the tilt's x·(e × p) = x·(ey p_z, −ex p_z, ex p_y − ey p_x),
     * the lift x·ẑ and the slide x·(e × ẑ) = x·(ey, −ex, 0).
     */
    static void tiltRegressor(double x, double ex, double ey, double[] p, double[] g3) {
        g3[0] = x * ey * p[2];
        g3[1] = 0;
        g3[2] = x * ey;
        g3[3] = -x * ex * p[2];
        g3[4] = 0;
        g3[5] = -x * ex;
        g3[6] = x * (ex * p[1] - ey * p[0]);
        g3[7] = x;
        g3[8] = 0;
    }

    /** A base tilt's axis azimuth (rad) and hold (N·m; −∞ for none). */
    public double tiltAzimuth() { return tiltAzimuth; }
    public double tiltHold() { return tiltHold; }

    /** An instrument-reading error's instrumentTbase (null for other kinds). */
    public Pose instrumentPose() { return instrument; }

    /** An instrument-reading error's reading (null for other kinds). */
    public Sight sight() { return sight; }

    /** The azimuth an instrument's azimuth readings are taken about, rad (0 for other readings). */
    public double azimuthRef() { return azimuthRef; }

    /**
     * An instrument's reading of a point at {@code pInstrument} (instrument frame, m): its distance,
     * or its azimuth (about {@code azimuthRef}, in [−π, π)) or elevation, rad.
     */
    public static double sightReading(Sight sight, double azimuthRef, double[] pInstrument) {
        double x = pInstrument[0], y = pInstrument[1], z = pInstrument[2];
        return switch (sight) {
            case RANGE -> Math.sqrt(x * x + y * y + z * z);
            case AZIMUTH -> Math.IEEEremainder(Math.atan2(y, x) - azimuthRef, 2 * Math.PI);
            case ELEVATION -> Math.atan2(z, Math.hypot(x, y));
        };
    }

    /**
     * The point's displacement (instrument frame) per unit error of the {@code sight} reading at
     * {@code pInstrument}: the line of sight for the distance, r_h times the horizontal tangent for
     * the azimuth, r times the vertical tangent for the elevation.
     */
    public static double[] sightDirection(Sight sight, double[] pInstrument) {
        double x = pInstrument[0], y = pInstrument[1], z = pInstrument[2];
        double rh = Math.hypot(x, y), r = Math.sqrt(x * x + y * y + z * z);
        if (!(r > 0)) return new double[3];
        return switch (sight) {
            case RANGE -> new double[] {x / r, y / r, z / r};
            case AZIMUTH -> new double[] {-y, x, 0};
            case ELEVATION -> rh > 0 ? new double[] {-x * z / rh, -y * z / rh, rh} : new double[3];
        };
    }

    /**
     * A steady pull on the tool from outside the robot, the joints yielding to it ({@code tool-pull}):
     * a force F acting at {@code attach} (flange frame) loads each drive j with τ_j = J_jᵀ F, J_j the
     * point's linear Jacobian column of drive j (virtual work, e.g. Siciliano et al., "Robotics:
     * Modelling, Planning and Control", 2009, §3.8.2), and the drive yields by Δq_j = c_j τ_j, which
     * moves the measured point by its own column times Δq_j and turns the measured frame about the
     * joint's axis. With {@code anchor} null the force keeps one direction over the campaign (a
     * weight on a pulley, a balancer far overhead): three columns per revolute joint, the products
     * c_j F_x, c_j F_y, c_j F_z (rad/m). With an anchor (base frame), a pull of steady size toward
     * that point (a cable retractor on a boom): one column per revolute joint, c_j |F|, the force
     * along the unit vector from the attach point to the anchor at each pose. A compliance's payload
     * column is this form's vertical pull with the payload's weight as the force.
     */
    public static Effect toolPull(KinematicModel model, Vec3 attachInFlange, double[] anchorBase) {
        if (!hasRevolute(model)) throw new IllegalArgumentException("a tool pull needs a revolute joint to yield");
        Effect e = new Effect(Kind.TOOL_PULL, -1, -1, null, false, Double.NaN, Double.NaN, null, Double.NaN, Double.NaN, model, null);
        e.attach = attachInFlange;
        e.anchor = anchorBase == null ? null : anchorBase.clone();
        return e;
    }

    /** Whether the model has a revolute joint (one that can yield to a pull). */
    static boolean hasRevolute(KinematicModel model) {
        for (int j = 0; j < model.dof(); j++) if (!model.isPrismatic(j)) return true;
        return false;
    }

    /** A tool pull's yielding joints (0-based): the model's revolute ones. */
    int[] pullJoints() {
        return java.util.stream.IntStream.range(0, model.dof()).filter(j -> !model.isPrismatic(j)).toArray();
    }

    /** A tool pull's point of action, flange frame (null for other kinds). */
    public Vec3 pullAttach() { return attach; }

    /** A tool pull's anchor, base frame (null: a pull of one direction, or another kind). */
    public double[] pullAnchor() { return anchor == null ? null : anchor.clone(); }

    /**
     * A tool pull's drive torque per unit of each column at the pose with Jacobian {@code jac}
     * ({@link KinematicModel#geometricJacobian}) and flange {@code f}: the attach point's velocity per unit
     * of the column's drive, v + ω × (a − o_flange), dotted with the column's force direction.
     */
    private double[] pullTorques(double[][] jac, Pose f) {
        Vec3 fo = f.position(), a = f.apply(attach);
        double ax = a.x() - fo.x(), ay = a.y() - fo.y(), az = a.z() - fo.z();
        double[] u = null;
        if (anchor != null) {
            double dx = anchor[0] - a.x(), dy = anchor[1] - a.y(), dz = anchor[2] - a.z(), d = Math.sqrt(dx * dx + dy * dy + dz * dz);
            u = d > 0 ? new double[] {dx / d, dy / d, dz / d} : new double[3];
        }
        double[] out = new double[size()];
        int col = 0;
        for (int j : pullJoints()) {
            double wx = jac[3][j], wy = jac[4][j], wz = jac[5][j];
            double[] lever = {jac[0][j] + wy * az - wz * ay, jac[1][j] + wz * ax - wx * az, jac[2][j] + wx * ay - wy * ax};
            if (u == null) for (int c = 0; c < 3; c++) out[col++] = lever[c];
            else out[col++] = lever[0] * u[0] + lever[1] * u[1] + lever[2] * u[2];
        }
        return out;
    }

    /**
     * A tool pull's columns at q: the move of a point at {@code pointBase} (3 x size, row-major) and the
     * measured frame's turn, for a unit coefficient of each column ({@link #toolPull}).
     */
    private void toolPullColumns(double[] q, double[] pointBase, double[] g3, double[] w3) {
        int k = size();
        if (g3 != null) Arrays.fill(g3, 0);
        if (w3 != null) Arrays.fill(w3, 0);
        double[][] jac = model.geometricJacobian(q);
        Pose f = model.flange(q);
        Vec3 fo = f.position();
        double[] tau = pullTorques(jac, f);
        int[] js = pullJoints();
        int per = k / js.length;
        for (int i = 0; i < js.length; i++) {
            int j = js[i];
            double vx = jac[0][j], vy = jac[1][j], vz = jac[2][j], wx = jac[3][j], wy = jac[4][j], wz = jac[5][j];
            double[] move = null;
            if (g3 != null && pointBase != null) {
                double px = pointBase[0] - fo.x(), py = pointBase[1] - fo.y(), pz = pointBase[2] - fo.z();
                move = new double[] {vx + wy * pz - wz * py, vy + wz * px - wx * pz, vz + wx * py - wy * px};
            }
            for (int c = 0; c < per; c++) {
                int col = i * per + c;
                double dq = tau[col];
                if (move != null) for (int r = 0; r < 3; r++) g3[r * k + col] = move[r] * dq;
                if (w3 != null) { w3[col] = wx * dq; w3[k + col] = wy * dq; w3[2 * k + col] = wz * dq; }
            }
        }
    }

    /** A tool pull's plotting variable at q: the azimuth of its point of action about axis 1 (deg). */
    public double pullAzimuthDeg(double[] q) {
        Vec3 a = model.flange(q).apply(attach);
        return Math.toDegrees(Math.atan2(a.y(), a.x()));
    }

    /** A tool pull's drive deflections (rad) at q for coefficients v; zero on prismatic joints. */
    public double[] pullDeflections(double[] q, double[] v) {
        double[] out = new double[model.dof()], tau = pullTorques(model.geometricJacobian(q), model.flange(q));
        int[] js = pullJoints();
        int per = tau.length / js.length;
        for (int i = 0; i < js.length; i++) for (int c = 0; c < per; c++) out[js[i]] += v[i * per + c] * tau[i * per + c];
        return out;
    }

    /** Whether this effect is a step at one time (s): of a joint's zero, the target on the flange, the instrument against the base, the distances. */
    public boolean stepInTime() {
        return kind == Kind.ZERO_STEP || kind == Kind.TARGET_STEP || kind == Kind.BASE_STEP || kind == Kind.RANGE_STEP;
    }

    /** Whether this effect is a fallback (a located structure modelled without a physical family). */
    public boolean isFallback() {
        return shaftOrders() || stepInTime() || kind == Kind.SMOOTH || kind == Kind.LOAD_PERIODIC || kind == Kind.WARM_PERIODIC || kind == Kind.COMPLIANCE_VARYING || kind == Kind.LINK_PERIODIC || kind == Kind.GRAVITY_PLAY || kind == Kind.TARGET_DRIFT || kind == Kind.BASE_CREEP || kind == Kind.PAIR || kind == Kind.POINT_SMOOTH || kind == Kind.BASE_TURN
                || kind == Kind.ZERO_DRIFT || kind == Kind.ANGLE_STEP || kind == Kind.SETTLING || kind == Kind.INSTRUMENT || kind == Kind.INSTRUMENT_SCALE || kind == Kind.INSTRUMENT_AXES || kind == Kind.REFRACTION
                || kind == Kind.BASE_TILT || kind == Kind.AXIS_WOBBLE || kind == Kind.AXIAL_RUNOUT || kind == Kind.TOOL_SAG || kind == Kind.TOOL_PLAY || kind == Kind.LINK_SAG || kind == Kind.LINK_TWIST || kind == Kind.TARGET_INCIDENCE || kind == Kind.TOOL_PULL || kind == Kind.LOAD_TILT || kind == Kind.SECOND_STATION;
    }

    /**
     * Whether this is a periodic error of a joint at orders above {@link #SHAFT_ORDER} only: the turn
     * of a shaft that turns many times per output turn. At the joint's gear ratio that shaft is the
     * motor, whose angle sensor (a resolver's or an encoder's once- and twice-per-turn error) and the
     * reducer's input stage repeat their errors alike, and the output's measurements cannot tell the
     * two; an intermediate shaft gives such an order too, whole or not (over part of a turn a line's
     * order is known to a cycle or two). So it is located and modelled, a shape of known period, not
     * named as a gear's error.
     */
    public boolean shaftOrders() {
        if (kind != Kind.PERIODIC) return false;
        for (double f : orders()) if (!(f > SHAFT_ORDER)) return false;
        return true;
    }

    /** The name of a shaft's periodic error in reports and robot files ({@link #shaftOrders}). */
    public static final String SHAFT_JSON = "shaft-periodic";

    /** This effect's name in reports and robot files: its kind's, or {@link #SHAFT_JSON} for a shaft's orders. */
    public String json() { return shaftOrders() ? SHAFT_JSON : kind.json; }

    /** This effect's title in words (the workbench's list): its kind's, or a shaft's for {@link #shaftOrders}. */
    public String title() { return shaftOrders() ? "Periodic error at a shaft's turn (motor sensor or input stage)" : kind.title; }

    /**
     * Orders of a joint's error (cycles per turn) above which it is a shaft's ({@link #shaftOrders}):
     * the output's own gear features (an output gear's eccentricity and its teeth's pattern, a
     * cycloidal disc's lobes, 39-40 on a robot's RV stage) repeat at most this often per turn, the
     * motor and the input stage at the total ratio (60-200 on an industrial arm's joint).
     */
    public static final double SHAFT_ORDER = 40;

    /** An instrument-reading error's reading of a predicted point (base frame, m): m, or rad for an angle; NaN for other kinds. */
    public double sightReadingOf(double[] pointBase) {
        if (kind != Kind.INSTRUMENT) return Double.NaN;
        return sightReading(sight, azimuthRef, instrument.apply(new Vec3(pointBase[0], pointBase[1], pointBase[2])).toArray());
    }

    /** The measured point's distance from the instrument's origin (m), for an effect seen through the instrument's frame. */
    public double instrumentDistanceOf(double[] pointBase) {
        return instrument == null ? Double.NaN : instrument.apply(new Vec3(pointBase[0], pointBase[1], pointBase[2])).norm();
    }

    /** Whether this effect is an error of the measuring instrument, not of the robot (compensation leaves it out). */
    public boolean ofInstrument() {
        return kind == Kind.INSTRUMENT || kind == Kind.INSTRUMENT_SCALE || kind == Kind.INSTRUMENT_AXES || kind == Kind.REFRACTION
                || kind == Kind.RANGE_STEP || kind == Kind.BASE_STEP
                || kind == Kind.SECOND_STATION
                || kind == Kind.TARGET_INCIDENCE;
    }

    /** Spline functions of a smooth or point-smooth effect (per axis), 0 otherwise. */
    public int basisCount() { return nBasis; }

    /** A point-smooth or zero-drift effect's variable (null for other kinds). */
    public Along along() { return along; }
    /** ε = α (T − t0C). */
    public static Effect thermal(double t0C) {
        return new Effect(Kind.THERMAL, -1, -1, null, false, t0C, Double.NaN, null, Double.NaN, Double.NaN, null, null);
    }
    /** ε = s (1 − exp(−t/τ)): time since the start as a proxy for the warm-up. */
    public static Effect thermalFromTime(double tauS) {
        return new Effect(Kind.THERMAL, -1, -1, null, false, Double.NaN, tauS, null, Double.NaN, Double.NaN, null, null);
    }
    /**
     * {@link #thermalFromTime(double)} with the arm warmed by its drives, so cooling toward the air
     * while the robot rests in {@code pauses} ({@link Pauses#share}); the plain form when there are none.
     */
    public static Effect thermalFromTime(double tauS, Pauses pauses) { return thermalFromTime(tauS).restingIn(pauses); }
    /** Each link of {@code model} at least {@link #MIN_LINK_M} long (and the flange-to-point vector) grows by its own α (T − t0C). */
    public static Effect thermalLinks(KinematicModel model, double t0C) {
        Pose[] f = model.linkFrames(new double[model.dof()]);
        List<Integer> ls = new ArrayList<>();
        for (int i = 0; i + 1 < f.length; i++) if (f[i + 1].position().minus(f[i].position()).norm() >= MIN_LINK_M) ls.add(i);
        ls.add(f.length - 1); // flange to measured point
        return new Effect(Kind.THERMAL_LINK, -1, -1, null, false, t0C, Double.NaN, null, Double.NaN, Double.NaN, model,
                ls.stream().mapToInt(Integer::intValue).toArray());
    }
    /**
     * {@link #thermalLinks(KinematicModel, double)} with each link's temperature lagging the
     * reading: column i grows with {@link ThermalLag#at} at {@code taus[i]} (0: the reading itself).
     * Where the lag cannot be computed (no history, a time outside the campaign) the link is taken
     * at the reading's temperature.
     */
    public static Effect thermalLinks(KinematicModel model, double t0C, ThermalLag lag, double[] taus) {
        Effect e = thermalLinks(model, t0C);
        if (taus.length != e.links.length) throw new IllegalArgumentException("lags " + taus.length + " for " + e.links.length + " links");
        for (double x : taus) if (!(x >= 0)) throw new IllegalArgumentException("lag time constant " + x);
        e.lag = lag;
        e.lagTaus = taus.clone();
        return e;
    }

    /**
     * {@code growth} (a thermal-link effect) with each link also warmed by the drives as the robot
     * works: besides α_i·(T_i − T0) each link grows by β_i·(1 − exp(−t/τ_w)), t the time since the
     * campaign started. A link's temperature is the air's (lagged) plus what its motors and gears put
     * into it, which rises with the time the robot has run and levels off (the warm-up of industrial
     * robots: ISO 9283 §6.2 asks for a warmed-up robot for this reason; a lumped body heated at a
     * constant rate and cooled to the air rises as 1 − exp(−t/τ), Incropera &amp; DeWitt §5.2).
     * β_i = α_i·ΔT_i is the growth per link when warmed through. An unknown time (a compensated
     * program) is taken warmed through.
     */
    public static Effect withWarmUp(Effect growth, double warmTauS) {
        if (growth.kind != Kind.THERMAL_LINK) throw new IllegalArgumentException("a warm-up belongs to thermal-link, not " + growth.label());
        double[] taus = new double[growth.links.length];
        Arrays.fill(taus, warmTauS);
        return withWarmUp(growth, taus);
    }

    /** {@link #withWarmUp(Effect, double)} with each link's own warm-up time constant (a heavy casting slowly, a thin tube quickly). */
    public static Effect withWarmUp(Effect growth, double[] warmTausS) {
        if (growth.kind != Kind.THERMAL_LINK) throw new IllegalArgumentException("a warm-up belongs to thermal-link, not " + growth.label());
        if (warmTausS.length != growth.links.length) throw new IllegalArgumentException("warm-ups " + warmTausS.length + " for " + growth.links.length + " links");
        for (double x : warmTausS) if (!(x > 0) || Double.isInfinite(x)) throw new IllegalArgumentException("warm-up time constant " + x);
        return growthWith(growth, warmTausS.clone());
    }

    /**
     * {@link #withWarmUp(Effect, double)} where the robot rested in {@code pauses} (null: it worked
     * throughout): the links cool toward the air while it rests ({@link Pauses#share}).
     */
    public static Effect withWarmUp(Effect growth, double warmTauS, Pauses pauses) { return withWarmUp(growth, warmTauS).restingIn(pauses); }

    /** This warm-up cooling through {@code pauses} (none when null or without a pause). */
    private Effect restingIn(Pauses pauses) {
        this.pauses = pauses != null && pauses.any() ? pauses : null;
        return this;
    }

    /** {@code growth} without the drives' warm-up (itself when it has none). */
    public static Effect withoutWarmUp(Effect growth) { return growth.warms() ? growthWith(growth, null) : growth; }

    /** A copy of thermal growth {@code growth} (its links, reference and lags) with the warm-ups {@code warmTaus} (null: none). */
    private static Effect growthWith(Effect growth, double[] warmTaus) {
        Effect e = new Effect(Kind.THERMAL_LINK, -1, -1, null, false, growth.t0C, Double.NaN, null, Double.NaN, Double.NaN, growth.model, growth.links);
        e.lag = growth.lag;
        e.lagTaus = growth.lagTaus == null ? null : growth.lagTaus.clone();
        e.warmTaus = warmTaus;
        e.pauses = warmTaus == null ? null : growth.pauses;
        return e;
    }

    /** {@code growth} with the links at the reading's temperature, its warm-up kept. */
    public static Effect withoutLags(Effect growth) {
        Effect e = thermalLinks(growth.model, growth.t0C);
        if (!growth.warms()) return e;
        Effect warmed = withWarmUp(e, growth.warmTaus);
        warmed.pauses = growth.pauses;
        return warmed;
    }

    /** Whether a thermal growth's links are also warmed by the drives ({@link #withWarmUp}). */
    public boolean warms() { return kind == Kind.THERMAL_LINK && warmTaus != null; }

    /** Each link's warm-up time constant of a thermal growth, s (null: none). */
    public double[] warmTausS() { return warmTaus == null ? null : warmTaus.clone(); }

    /** The warm-up time constants in words: "1200 s", or link by link "2400, 600, 600, … s". */
    public String warmWords() {
        if (warmTaus == null) return "";
        if (Arrays.stream(warmTaus).distinct().count() == 1) return String.format(Locale.ROOT, "%.0f s", warmTaus[0]);
        return String.join(", ", Arrays.stream(warmTaus).mapToObj(x -> String.format(Locale.ROOT, "%.0f", x)).toList()) + " s";
    }

    /** Link {@code col}'s warm-up share at time t: 1 − exp(−t/τ_w), cooling through the pauses; warmed through (1) at an unknown time. */
    private double warmX(PoseConditions c, int col) {
        double t = c.timeS();
        if (pauses != null) return pauses.share(warmTaus[col], t);
        return Double.isFinite(t) ? 1 - Math.exp(-Math.max(0, t) / warmTaus[col]) : 1;
    }

    /** Whether a thermal growth's warm-up cools through pauses in the campaign. */
    public boolean coolsInPauses() { return pauses != null; }

    /** The campaign's pauses a thermal growth's warm-up cools through, in words ("from 1830 s to 3342 s"), or "". */
    public String pauseWords() {
        if (pauses == null) return "";
        return String.join(", ", pauses.pauses().stream().map(g -> String.format(Locale.ROOT, "from %.0f s to %.0f s", g[0], g[1])).toList());
    }

    /** Whether some link of a thermal growth lags the reading. */
    public boolean lags() { return lagTaus != null && Arrays.stream(lagTaus).anyMatch(x -> x > 0); }

    /** Each link's lag time constant of a thermal growth, s (0: none); null for other kinds. */
    public double[] lagTaus() {
        if (kind != Kind.THERMAL_LINK) return null;
        return lagTaus == null ? new double[links.length] : lagTaus.clone();
    }

    /** The thermal growth's temperature history (null without a lag). */
    ThermalLag lag() { return lag; }

    /** Δp = (T − t0C) d, base coordinates (the instrument or the base moves with temperature). */
    public static Effect driftWithTemperature(double t0C) {
        return new Effect(Kind.DRIFT, -1, -1, null, false, t0C, Double.NaN, null, Double.NaN, Double.NaN, null, null);
    }
    /** Δp = (t / 1 h) d, base coordinates (the instrument or the base moves with time). */
    public static Effect driftWithTime() {
        return new Effect(Kind.DRIFT, -1, -1, null, false, Double.NaN, 3600, null, Double.NaN, Double.NaN, null, null);
    }

    public Kind kind() { return kind; }
    public Target target() {
        return switch (kind) {
            case THERMAL -> Target.STRAIN;
            case THERMAL_LINK, DRIFT, POINT_SMOOTH, BASE_TURN, TARGET_STEP, TARGET_DRIFT, BASE_CREEP, BASE_STEP, RANGE_STEP, INSTRUMENT, INSTRUMENT_SCALE, INSTRUMENT_AXES, REFRACTION, BASE_TILT, AXIS_WOBBLE, AXIAL_RUNOUT,
                 TOOL_SAG, TOOL_PLAY, LINK_SAG, LINK_TWIST, TARGET_INCIDENCE, TOOL_PULL, LOAD_TILT, SECOND_STATION -> Target.POSITION;
            default -> Target.DRIVE;
        };
    }
    /** Target joint (drive), 0-based (-1 for effects on lengths or the point). */
    public int joint() { return joint; }
    /** Source joint of a coupling, the second joint of a pair error, or the joint a smooth error follows when not its own; 0-based (-1 otherwise). */
    public int source() { return source; }
    public boolean isStrain() { return target() == Target.STRAIN; }
    public boolean usesTimeProxy() { return (kind == Kind.THERMAL || kind == Kind.DRIFT) && Double.isNaN(t0C); }
    public double t0C() { return t0C; }
    public double tauS() { return tauS; }
    public GravityTorques gravity() { return gravity; }
    public boolean perMass() { return perMass; }
    public int[] harmonics() { return harmonics == null ? null : harmonics.clone(); }
    /** A periodic effect's stage orders that are not whole (cycles per turn), in its columns after the harmonics. */
    public double[] stages() { return stages.clone(); }
    /** Every order of a periodic effect, cycles per turn: the harmonics, then the stage orders not whole. */
    public double[] orders() {
        double[] out = new double[harmonics.length + stages.length];
        for (int i = 0; i < harmonics.length; i++) out[i] = harmonics[i];
        System.arraycopy(stages, 0, out, harmonics.length, stages.length);
        return out;
    }
    public double rangeLo() { return lo; }
    public double rangeHi() { return hi; }
    /** Whether this is the default harmonics 1-3 periodic effect. */
    public boolean lowHarmonics() { return kind == Kind.PERIODIC && Arrays.equals(harmonics, LOW) && stages.length == 0; }

    /** Joints in the JSON sense (1-based): target, then source for a coupling; empty for effects on lengths or the point. */
    public List<Integer> joints1() {
        if (joint < 0) return List.of();
        if (kind == Kind.COUPLING || kind == Kind.PAIR || kind == Kind.SMOOTH && source >= 0) return List.of(joint + 1, source + 1);
        return List.of(joint + 1);
    }

    public int size() {
        return switch (kind) {
            case PERIODIC -> 2 * (harmonics.length + stages.length);
            case LINK_PERIODIC -> 2 * harmonics.length;
            case LOAD_PERIODIC, WARM_PERIODIC -> 4 * (harmonics.length + stages.length);
            case COMPLIANCE -> perMass ? gravity.massCount() : stiffens ? 2 : 1;
            case BACKLASH -> 1 + 2 * runout.length;
            case SMOOTH, PAIR, ZERO_DRIFT, INSTRUMENT, INSTRUMENT_SCALE, REFRACTION, BASE_TILT -> nBasis;
            case COMPLIANCE_VARYING -> perMassVarying() ? gravity.massCount() * nBasis : payloadCentreFree ? 4 * nBasis : nBasis;
            case AXIS_WOBBLE -> 4 * harmonics.length;
            case LOAD_TILT -> 8;
            case INSTRUMENT_AXES -> AXES_COLUMNS + (bowed ? BOW_COLUMNS : 0);
            case AXIAL_RUNOUT -> 2 * harmonics.length;
            case TOOL_SAG -> 9;
            case TOOL_PLAY -> PLAY_SHIFTS + (playTurns ? PLAY_TIPS : 0);
            case TARGET_INCIDENCE -> INCIDENCE_TERMS;
            case TOOL_PULL -> pullJoints().length * (anchor == null ? 3 : 1);
            case LINK_SAG -> 2 + (sagPayload ? 1 : 0);
            case LINK_TWIST -> TWIST_ARM_TERMS + (sagPayload ? HAND_TERMS : 0);
            case POINT_SMOOTH, TARGET_DRIFT -> 3 * nBasis;
            case BASE_TURN -> 3 * nBasis + 3;
            case THERMAL_LINK -> links.length * (warms() ? 2 : 1);
            case DRIFT, TARGET_STEP -> 3;
            case BASE_CREEP -> CREEP_TERMS;
            case BASE_STEP, SECOND_STATION -> BASE_STEP_TERMS;
            default -> 1;
        };
    }

    public List<String> parameterNames() {
        List<String> out = new ArrayList<>();
        switch (kind) {
            case COMPLIANCE -> {
                if (!perMass) {
                    out.add("c");
                    if (stiffens) out.add("c3");
                } else for (int k = 0; k < gravity.massCount(); k++) out.add("c_" + gravity.massName(k));
            }
            case PERIODIC -> { for (double h : orders()) { out.add("a" + orderText(h)); out.add("b" + orderText(h)); } }
            case LINK_PERIODIC -> { for (int h : harmonics) { out.add("a" + h); out.add("b" + h); } }
            case LOAD_PERIODIC -> {
                for (double h : orders()) { out.add("a" + orderText(h)); out.add("b" + orderText(h)); }
                for (double h : orders()) { out.add("la" + orderText(h)); out.add("lb" + orderText(h)); }
            }
            case WARM_PERIODIC -> {
                for (double h : orders()) { out.add("a" + orderText(h)); out.add("b" + orderText(h)); }
                for (double h : orders()) { out.add("ta" + orderText(h)); out.add("tb" + orderText(h)); }
            }
            case GRAVITY_PLAY -> out.add("b");
            case BACKLASH -> {
                out.add("b");
                for (double f : runout) {
                    String o = f == 1 ? "" : "_" + orderText(f);
                    out.add("b_cos" + o);
                    out.add("b_sin" + o);
                }
            }
            case THERMAL -> out.add(usesTimeProxy() ? "strain" : "alpha");
            case THERMAL_LINK -> {
                for (int i : links) out.add("alpha_" + linkName(i));
                if (warms()) for (int i : links) out.add("warm_" + linkName(i));
            }
            case DRIFT -> { out.add("dx"); out.add("dy"); out.add("dz"); }
            case SCALE -> out.add("eps");
            case COUPLING -> out.add("kappa");
            case SMOOTH -> { for (int k = 1; k <= nBasis; k++) out.add("s" + k); }
            case PAIR -> {
                for (String n : new String[] {"ss", "sc", "cs", "cc", "lin_j", "lin_k", "lin_jk", "lin_j_ck", "lin_j_sk", "ck", "sk"}) out.add(n);
            }
            case POINT_SMOOTH, TARGET_DRIFT -> { for (String a : new String[] {"x", "y", "z"}) for (int k = 1; k <= nBasis; k++) out.add("d" + a + k); }
            case BASE_TURN -> {
                for (String a : new String[] {"x", "y", "z"}) for (int k = 1; k <= nBasis; k++) out.add("r" + a + k);
                out.add("dx"); out.add("dy"); out.add("dz");
            }
            case ZERO_DRIFT -> { for (int k = 1; k <= nBasis; k++) out.add("z" + k); }
            case COMPLIANCE_VARYING -> { for (int k = 1; k <= size(); k++) out.add("c" + k); }
            case INSTRUMENT_SCALE -> { for (int k = 1; k <= nBasis; k++) out.add("s" + k); }
            case INSTRUMENT_AXES -> {
                out.addAll(List.of("scale_x", "scale_y", "square_xy", "square_xz", "square_yz"));
                if (bowed) out.addAll(List.of("bow_x_y", "bow_x_z", "bow_y_x", "bow_y_z", "bow_z_x", "bow_z_y"));
            }
            case REFRACTION -> { for (int k = 1; k <= nBasis; k++) out.add("k" + k); }
            case ZERO_STEP, ANGLE_STEP -> out.add("step");
            case SETTLING -> out.add("per_speed");
            case TARGET_STEP -> { out.add("dx"); out.add("dy"); out.add("dz"); }
            case BASE_CREEP -> { out.add("turn"); out.add("dx"); out.add("dy"); }
            case BASE_STEP, SECOND_STATION -> out.addAll(List.of("dx", "dy", "dz", "wx", "wy", "wz"));
            case RANGE_STEP -> out.add("d");
            case BASE_TILT -> { out.add("tilt"); out.add("lift"); out.add("slide"); }
            case AXIS_WOBBLE -> {
                for (int h : harmonics) { out.add("xc" + h); out.add("xs" + h); out.add("yc" + h); out.add("ys" + h); }
            }
            case AXIAL_RUNOUT -> { for (int h : harmonics) { out.add("zc" + h); out.add("zs" + h); } }
            case LOAD_TILT -> out.addAll(List.of("x_torque", "x_size", "y_torque", "y_size", "sx_torque", "sx_size", "sy_torque", "sy_size"));
            case LINK_SAG -> {
                out.add("d_weight");
                out.add("t_weight");
                if (sagPayload) out.add("t_payload");
            }
            case LINK_TWIST -> {
                out.addAll(List.of("t_forearm", "t_wrist4_x", "t_wrist4_y", "t_wrist4_z", "t_wrist5_x", "t_wrist5_y", "t_wrist5_z",
                        "t_hand_o", "t_hand_x", "t_hand_y", "t_hand_z"));
                if (sagPayload) out.addAll(List.of("t_payload_o", "t_payload_x", "t_payload_y", "t_payload_z"));
            }
            case TOOL_SAG -> { for (String a : new String[] {"x", "y", "z"}) for (String b : new String[] {"x", "y", "z"}) out.add("a" + a + b); }
            case TOOL_PULL -> {
                for (int j : pullJoints()) {
                    if (anchor != null) out.add("c_j" + (j + 1));
                    else for (String a : new String[] {"x", "y", "z"}) out.add("c_j" + (j + 1) + "_f" + a);
                }
            }
            case TOOL_PLAY -> {
                for (String a : new String[] {"x", "y", "z"}) for (String b : new String[] {"x", "y"}) out.add("p" + a + b);
                if (playTurns) for (String a : new String[] {"x", "y"}) for (String b : new String[] {"x", "y"}) out.add("r" + a + b);
            }
            case TARGET_INCIDENCE -> {
                for (String a : new String[] {"x", "y", "z"}) for (String m : INCIDENCE_ACROSS) out.add(a + "_" + m);
                for (String m : INCIDENCE_ALONG) out.add("r_" + m);
            }
            case INSTRUMENT -> {
                if (Double.isFinite(cycle))
                    for (int h = 1; h <= nBasis / 2; h++) { out.add(h == 1 ? "a" : "a" + h); out.add(h == 1 ? "b" : "b" + h); }
                else for (int k = 1; k <= nBasis; k++) out.add("e" + k);
            }
        }
        return out;
    }

    /** " (lag 600 s)", " (lags 2400, 600, 600, 300 s)" by link, or "" without a lag. */
    private String lagWords() {
        if (!lags()) return "";
        if (Arrays.stream(lagTaus).distinct().count() == 1) return String.format(Locale.ROOT, " (lag %.0f s)", lagTaus[0]);
        return " (lags " + String.join(", ", Arrays.stream(lagTaus).mapToObj(x -> String.format(Locale.ROOT, "%.0f", x)).toList()) + " s)";
    }

    /** The temperature excess of thermal-link column {@code col} under c (0 when unknown). */
    private double linkX(PoseConditions c, int col) {
        if (lagTaus == null || lagTaus[col] == 0 || lag == null) return conditionX(c);
        double x = lag.at(lagTaus[col], c.timeS(), c.tempC()) - t0C;
        return Double.isFinite(x) ? x : 0;
    }

    private String linkName(int i) { return i == model.dof() + 1 ? "tool" : "link" + i; }

    /** The link of a thermal-link parameter in words. */
    String linkWords(int col) {
        int i = links[col];
        return col == links.length - 1 ? "flange to measured point" : i == 0 ? "base to joint 1" : "link " + i + " (joint " + i + " to " + (i + 1 > model.dof() ? "flange" : "joint " + (i + 1)) + ")";
    }

    public List<String> units() {
        String u = switch (kind) {
            case COMPLIANCE, COMPLIANCE_VARYING -> "rad/(N·m)";
            case PERIODIC, LOAD_PERIODIC, WARM_PERIODIC, LINK_PERIODIC, GRAVITY_PLAY, BACKLASH, SMOOTH, PAIR, ZERO_DRIFT, ZERO_STEP, ANGLE_STEP -> "rad";
            case SETTLING -> "s";
            case POINT_SMOOTH, TARGET_STEP, TARGET_DRIFT, BASE_STEP, RANGE_STEP, TOOL_SAG, TOOL_PLAY, TARGET_INCIDENCE, SECOND_STATION -> "m";
            case BASE_TURN, BASE_CREEP -> "rad";
            case INSTRUMENT -> sight.unit;
            case INSTRUMENT_SCALE -> "1";
            case INSTRUMENT_AXES -> "1";
            case REFRACTION -> "1/m";
            case BASE_TILT -> "rad/(N·m)";
            case AXIS_WOBBLE, LOAD_TILT -> "rad";
            case AXIAL_RUNOUT -> "m";
            case LINK_SAG -> "m";
            case LINK_TWIST -> "rad";
            case TOOL_PULL -> "rad/m";
            case THERMAL -> usesTimeProxy() ? "1" : "1/K";
            case THERMAL_LINK -> "1/K";
            case DRIFT -> usesTimeProxy() ? "m/h" : "m/K";
            case SCALE, COUPLING -> "1";
        };
        if (warms()) { // the warm-up's coefficients are strains (the growth when warmed through)
            List<String> out = new ArrayList<>(java.util.Collections.nCopies(links.length, u));
            out.addAll(java.util.Collections.nCopies(links.length, "1"));
            return out;
        }
        if (stiffens) return List.of(u, "rad/(N·m)^3");
        if (kind == Kind.BASE_TILT) return List.of(u, "m/(N·m)", "m/(N·m)"); // the lift and the slide: the tilt times a distance
        if (kind == Kind.BASE_STEP || kind == Kind.SECOND_STATION) return List.of("m", "m", "m", "rad", "rad", "rad");
        if (kind == Kind.BASE_CREEP) return List.of("rad", "m", "m");
        if (kind == Kind.INSTRUMENT_AXES && bowed) { // the scales and squareness, then the ways' bows per metre squared
            List<String> out = new ArrayList<>(java.util.Collections.nCopies(AXES_COLUMNS, u));
            out.addAll(java.util.Collections.nCopies(BOW_COLUMNS, "1/m"));
            return out;
        }
        if (kind == Kind.TOOL_PLAY && playTurns) { // the point's shifts, then the flange's tips
            List<String> out = new ArrayList<>(java.util.Collections.nCopies(PLAY_SHIFTS, u));
            out.addAll(java.util.Collections.nCopies(PLAY_TIPS, "rad"));
            return out;
        }
        if (kind == Kind.BASE_TURN) { // the turns, then the drift over the whole range
            List<String> out = new ArrayList<>(java.util.Collections.nCopies(3 * nBasis, u));
            out.addAll(List.of("m", "m", "m"));
            return out;
        }
        if (kind == Kind.LINK_TWIST) { // per unit of each lever: the forearm's and the first moments' unitless, the masses' in m
            List<String> out = new ArrayList<>(java.util.Collections.nCopies(TWIST_ARM_TERMS, "rad"));
            out.set(TWIST_ARM_TERMS - HAND_TERMS, "rad/m");
            if (sagPayload) out.addAll(List.of("rad/(kg·m)", "rad/kg", "rad/kg", "rad/kg"));
            return out;
        }
        if (kind == Kind.LOAD_TILT) { // the tilts, then the shifts across the axis (each at the reference torque)
            List<String> out = new ArrayList<>(java.util.Collections.nCopies(4, "rad"));
            out.addAll(java.util.Collections.nCopies(4, "m"));
            return out;
        }
        if (kind == Kind.LINK_SAG) {
            List<String> out = new ArrayList<>(List.of(u, "rad")); // the far end's deflection, then its turns
            if (sagPayload) out.add("rad/kg");
            return out;
        }
        return java.util.Collections.nCopies(size(), u);
    }

    /** A short label: "backlash j2", "joint-coupling j3<-j2", "gear-periodic j1 (h 1,7,23)", "thermal-expansion". */
    public String label() {
        return switch (kind) {
            case THERMAL -> kind.json + (usesTimeProxy() ? String.format(Locale.ROOT, " (time proxy, tau %.0f s%s)", tauS,
                    pauses != null ? ", cooling in pauses" : "") : "");
            case DRIFT -> kind.json + (usesTimeProxy() ? " (with time)" : " (with temperature)");
            case THERMAL_LINK -> kind.json + lagWords() + (warms() ? " (warm-up " + warmWords() + ")" : "");
            case COUPLING -> kind.json + " j" + (joint + 1) + "<-j" + (source + 1);
            case PERIODIC -> shaftOrders() ? SHAFT_JSON + " j" + (joint + 1) + " (" + String.join(",",
                    Arrays.stream(orders()).mapToObj(Effect::orderText).toList()) + " per turn)"
                    : kind.json + " j" + (joint + 1) + (lowHarmonics() ? "" : " (h " + String.join(",",
                    Arrays.stream(orders()).mapToObj(Effect::orderText).toList()) + ")");
            case GRAVITY_PLAY -> kind.json + " j" + (joint + 1) + String.format(Locale.ROOT, " (side changing at %.1f N·m%s)", sideNm,
                    sideWidthNm > 0 ? String.format(Locale.ROOT, " ± %.1f", sideWidthNm) : "");
            case WARM_PERIODIC -> kind.json + " j" + (joint + 1) + " (h " + String.join(",", Arrays.stream(harmonics).mapToObj(String::valueOf).toList()) + ")";
            case LOAD_PERIODIC -> kind.json + " j" + (joint + 1) + " (h " + String.join(",", Arrays.stream(orders()).mapToObj(Effect::orderText).toList())
                    + (loadMagnitude ? ", with the torque's size)" : ", with the torque)");
            case COMPLIANCE -> kind.json + " j" + (joint + 1) + (atJoint ? " (at the joint)" : "")
                    + (gravity.massesUnknown() ? " (masses estimated)" : perMass ? " (masses re-estimated)" : stiffens ? " (stiffening)" : "");
            case SMOOTH -> kind.json + " j" + (joint + 1) + (source >= 0 || model != null ? " (following " + (model != null ? "theta" : "j")
                    + (angleJoint() + 1) + ")" : "")
                    + (nBasis == SMOOTH_BASIS ? "" : " (" + nBasis + " functions)");
            case BACKLASH -> kind.json + " j" + (joint + 1) + (buildsUp() ? String.format(Locale.ROOT, " (building up over %.1f deg%s%s)",
                    Math.toDegrees(buildUp), approached() ? String.format(Locale.ROOT, ", approached by %.1f deg", Math.toDegrees(approach)) : "",
                    runout() ? ", " + runoutWords() : "") : runout() ? " (" + runoutWords() + ")" : heldByGravity() ? String.format(Locale.ROOT, " (held by gravity above %.1f N·m%s%s)", preloadNm,
                    preloadWidth > 0 ? String.format(Locale.ROOT, " ± %.0f %%", 100 * preloadWidth) : "", gravity.fromLengths() ? ", masses from the link lengths"
                    + (massScales != null ? ", re-estimated" : "") : massScales != null ? ", masses re-estimated" : "") : "");
            case PAIR -> kind.json + " j" + (joint + 1) + " (with j" + (source + 1) + ")";
            case POINT_SMOOTH, BASE_TURN -> kind.json + " (" + along.words + ")";
            case INSTRUMENT_SCALE, REFRACTION -> kind.json + " (" + along.words + (nBasis == POINT_BASIS ? "" : ", " + nBasis + " functions") + ")";
            case INSTRUMENT_AXES -> kind.json + (bowed ? " (out of square, ways bowed)" : " (out of square)");
            case ZERO_DRIFT -> kind.json + " j" + (joint + 1) + " (" + along.words + ")";
            case LINK_PERIODIC -> kind.json + " j" + (joint + 1) + " (" + linkAngleText() + ", h " + String.join(",",
                    Arrays.stream(harmonics).mapToObj(String::valueOf).toList()) + ")";
            case COMPLIANCE_VARYING -> kind.json + " j" + (joint + 1) + " (" + (payloadShare ? "payload, " : "")
                    + (stepTimes != null ? "in steps at " + String.join(", ", Arrays.stream(stepTimes)
                            .mapToObj(t -> String.format(Locale.ROOT, "%.0f s", t)).toList())
                    : "with " + along.words + (nBasis == POINT_BASIS ? "" : ", " + nBasis + " functions"))
                    + (payloadCentreFree ? ", its centre estimated" : "") + (gravity.massesUnknown() ? ", masses estimated" : "") + ")";
            case ZERO_STEP -> kind.json + " j" + (joint + 1) + String.format(Locale.ROOT, " (at %.0f s)", tauS);
            case SETTLING -> kind.json + " j" + (joint + 1);
            case ANGLE_STEP -> kind.json + " j" + (joint + 1) + (isWindow()
                    ? String.format(Locale.ROOT, " (from %.1f to %.1f deg)", Math.toDegrees(lo), Math.toDegrees(hi))
                    : String.format(Locale.ROOT, " (at %.1f deg)", Math.toDegrees(lo)));
            case TARGET_STEP, BASE_STEP, RANGE_STEP -> kind.json + String.format(Locale.ROOT, " (at %.0f s)", tauS);
            case SECOND_STATION -> kind.json + (stations != null ? String.format(Locale.ROOT, " (at %.2f, %.2f, %.2f m)", stations[3], stations[4], stations[5])
                    : String.format(Locale.ROOT, " (target facing %.2f, %.2f, %.2f)", facing.x(), facing.y(), facing.z()));
            case BASE_CREEP -> kind.json + String.format(Locale.ROOT, " (moves of joint 1 over %.0f deg)", Math.toDegrees(tauS));
            case TARGET_DRIFT -> kind.json + " (time" + (nBasis == DRIFT_RESOLUTIONS[0] ? "" : ", " + nBasis + " functions") + ")";
            case BASE_TILT -> kind.json + (towardLean() ? " (toward the lean" + (tiltHold > 0 ? String.format(Locale.ROOT, " above %.0f N·m", tiltHold) : "") + ")"
                    : squareFoot() ? String.format(Locale.ROOT, " (square foot, edges at %.0f deg, above %.0f N·m)",
                    (Math.toDegrees(tiltAzimuth) % 90 + 90) % 90, tiltHold)
                    : String.format(Locale.ROOT, " (about %.0f deg%s)", Math.toDegrees(tiltAzimuth),
                    Double.isInfinite(tiltHold) ? "" : String.format(Locale.ROOT, " above %.0f N·m", tiltHold)))
                    + (massScales != null ? " (masses re-estimated)" : "");
            case TOOL_SAG, TOOL_PLAY, TARGET_INCIDENCE -> kind.json;
            case LOAD_TILT -> kind.json + " j" + (joint + 1) + (gravity.fromLengths() ? " (masses from the link lengths" + (massScales != null ? ", re-estimated)" : ")")
                    : massScales != null ? " (masses re-estimated)" : "");
            case TOOL_PULL -> kind.json + (anchor == null ? " (one direction)"
                    : String.format(Locale.ROOT, " (toward %.2f, %.2f, %.2f m)", anchor[0], anchor[1], anchor[2]));
            case LINK_TWIST -> kind.json + " j2 (upper arm)";
            case LINK_SAG -> kind.json + " j" + (joint + 1) + (joint == 1 ? " (upper arm)" : joint == 2 ? " (forearm)" : "");
            case AXIS_WOBBLE, AXIAL_RUNOUT -> kind.json + " j" + (joint + 1) + " (" + (harmonics.length > 1 ? "orders "
                    + String.join(",", Arrays.stream(harmonics).mapToObj(Integer::toString).toList()) : harmonics[0] == 1 ? "once"
                    : harmonics[0] + " times") + " per turn)";
            case INSTRUMENT -> kind.json + " (" + sight.words + (Double.isFinite(cycle)
                    ? String.format(Locale.ROOT, ", cyclic %.0f %s%s", sight == Sight.RANGE ? cycle * 1e3 : Math.toDegrees(cycle), sight == Sight.RANGE ? "mm" : "deg",
                            nBasis > 2 ? ", harmonics 1-" + nBasis / 2 : "")
                    : nBasis == POINT_BASIS ? "" : ", " + nBasis + " functions") + ")";
            default -> kind.json + " j" + (joint + 1);
        };
    }

    /** Block / parameter prefix without spaces. */
    public String id() {
        return label().replace(' ', '.').replace("<-", "from").replace("(", "").replace(")", "").replace(",", "_").replace("·", "");
    }

    /** Whether the conditions this effect needs are present on every row. */
    public boolean testableOn(List<Measurement> rows) {
        if (kind == Kind.COMPLIANCE && gravity.massesUnknown()) {
            // with the masses unknown only the payload's torque tells a compliance from them: the payload must vary
            double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
            for (Measurement m : rows) { lo = Math.min(lo, m.payloadKg()); hi = Math.max(hi, m.payloadKg()); }
            if (!(hi - lo >= MIN_PAYLOAD_SPAN_KG)) return false;
        }
        for (Measurement m : rows) {
            switch (kind) {
                case BACKLASH -> { if (m.directions() == null) return false; }
                case THERMAL, THERMAL_LINK, DRIFT -> { if (Double.isNaN(usesTimeProxy() ? m.timeS() : m.tempC())) return false; }
                default -> { }
            }
        }
        return true;
    }

    /** The condition variable x of a thermal or drift effect (0 when unknown: unknown conditions contribute nothing). */
    private double conditionX(PoseConditions c) {
        double x = switch (kind) {
            case THERMAL -> !usesTimeProxy() ? c.tempC() - t0C
                    : pauses != null && Double.isFinite(c.timeS()) ? pauses.share(tauS, c.timeS()) : 1 - Math.exp(-c.timeS() / tauS);
            case DRIFT -> usesTimeProxy() ? c.timeS() / tauS : c.tempC() - t0C;
            default -> c.tempC() - t0C;
        };
        return Double.isFinite(x) ? x : 0;
    }

    /**
     * The regressor of a drive or strain effect at a measured row under conditions c: as
     * {@link #regressor(double[], PoseConditions, double[])} at the row's joint values, with the
     * row's last move for a lost motion that builds up over the move.
     */
    public void regressor(Measurement row, PoseConditions c, double[] g) {
        regressor(row.q(), c, g);
        if (kind == Kind.SETTLING) g[0] = settlingSpeed(row);
        if (buildsUp()) {
            double share = windUpShare(row, c.direction(joint));
            for (int i = 0; i < g.length; i++) g[i] *= share;
        }
    }

    /** The drive or strain value at a measured row ({@link #regressor(Measurement, PoseConditions, double[])}). */
    public double valueAt(double[] v, Measurement row, PoseConditions c) {
        double[] g = new double[size()];
        regressor(row, c, g);
        double s = 0;
        for (int i = 0; i < g.length; i++) s += g[i] * v[i];
        return s;
    }

    /**
     * The regressor g (length {@link #size()}) of a drive or strain effect at controller values q
     * under conditions c: Δq_joint = g·v, or ε = g·v. (A lost motion that builds up over the move
     * is taken at its full size here: the move is not known from q and c.)
     */
    public void regressor(double[] q, PoseConditions c, double[] g) {
        switch (kind) {
            case COMPLIANCE -> {
                if (!perMass) {
                    g[0] = complianceTorque(q, c.payloadKg());
                    if (stiffens) g[1] = g[0] * g[0] * g[0];
                } else if (atJoint) gravity.jointTorquesByMass(q, c.payloadKg(), joint, g);
                else gravity.driveTorquesByMass(q, c.payloadKg(), joint, g);
            }
            case PERIODIC -> {
                for (int i = 0; i < harmonics.length; i++) {
                    g[2 * i] = Math.sin(harmonics[i] * q[joint]);
                    g[2 * i + 1] = Math.cos(harmonics[i] * q[joint]);
                }
                for (int i = 0, o = 2 * harmonics.length; i < stages.length; i++) {
                    g[o + 2 * i] = Math.sin(stages[i] * q[joint]);
                    g[o + 2 * i + 1] = Math.cos(stages[i] * q[joint]);
                }
            }
            case LINK_PERIODIC -> {
                double psi = linkAngleAt(q);
                for (int i = 0; i < harmonics.length; i++) {
                    g[2 * i] = Math.sin(harmonics[i] * psi);
                    g[2 * i + 1] = Math.cos(harmonics[i] * psi);
                }
            }
            case GRAVITY_PLAY -> g[0] = 0.5 * playSide(gravity.driveTorques(q, Double.isFinite(c.payloadKg()) ? c.payloadKg() : 0)[joint]);
            case LOAD_PERIODIC, WARM_PERIODIC -> {
                double[] hs = orders();
                double x = kind == Kind.WARM_PERIODIC ? warmShare(c) : loadShare(q, c.payloadKg());
                for (int i = 0, n = hs.length; i < n; i++) {
                    g[2 * i] = Math.sin(hs[i] * q[joint]);
                    g[2 * i + 1] = Math.cos(hs[i] * q[joint]);
                    g[2 * n + 2 * i] = x * g[2 * i];
                    g[2 * n + 2 * i + 1] = x * g[2 * i + 1];
                }
            }
            case BACKLASH -> {
                g[0] = lostMotion(q, c);
                for (int i = 0; i < runout.length; i++) {
                    g[1 + 2 * i] = g[0] * Math.cos(runout[i] * q[joint]);
                    g[2 + 2 * i] = g[0] * Math.sin(runout[i] * q[joint]);
                }
            }
            case THERMAL -> g[0] = conditionX(c);
            case SCALE -> g[0] = q[joint];
            case COUPLING -> g[0] = q[source];
            case SMOOTH -> bspline(smoothVariable(q), lo, hi, g);
            case PAIR -> {
                pairProducts(q, joint, source, g);
                double co = Math.cos(q[source]), so = Math.sin(q[source]);
                g[4] = q[joint];
                g[5] = q[source];
                g[6] = q[joint] * q[source];
                g[7] = q[joint] * co;
                g[8] = q[joint] * so;
                g[9] = co;
                g[10] = so;
            }
            // before the jump the zero was v lower; after it (and at an unknown time: the state the campaign ended in) nothing
            case ZERO_STEP -> g[0] = c.timeS() <= tauS ? -1 : 0;
            // the move before the reading is not known from q and c: the arm at rest
            case SETTLING -> g[0] = 0;
            case ANGLE_STEP -> g[0] = q[joint] > lo && !(q[joint] > hi) ? 1 : 0;
            case ZERO_DRIFT -> {
                double x = reading(c);
                if (Double.isFinite(x)) bspline(x, lo, hi, g);
                else Arrays.fill(g, 0);
            }
            case COMPLIANCE_VARYING -> {
                double x = reading(c), p = Double.isFinite(c.payloadKg()) ? c.payloadKg() : 0;
                if (!Double.isFinite(x)) {
                    Arrays.fill(g, 0);
                } else if (perMassVarying()) {
                    // each mass's torque (their sizes unknown) at either end of the range, straight between
                    double[] t = new double[gravity.massCount()];
                    gravity.driveTorquesByMass(q, p, joint, t);
                    double u = Math.max(0, Math.min(1, (x - lo) / (hi - lo)));
                    for (int k = 0; k < t.length; k++) { g[2 * k] = t[k] * (1 - u); g[2 * k + 1] = t[k] * u; }
                } else {
                    double[] b = payloadCentreFree ? new double[nBasis] : g;
                    if (stepTimes != null) {
                        Arrays.fill(b, 0);
                        int i = 0;
                        while (i < stepTimes.length && x >= stepTimes[i]) i++;
                        b[i] = 1;
                    } else bspline(x, lo, hi, b);
                    if (payloadCentreFree) {
                        double[] t = new double[4];
                        gravity.payloadDriveTorques(q, p, joint, t);
                        for (int i = 0; i < nBasis; i++) for (int k = 0; k < 4; k++) g[4 * i + k] = b[i] * t[k];
                    } else {
                        double tau = gravity.driveTorques(q, p)[joint] - (payloadShare ? gravity.driveTorques(q, 0)[joint] : 0);
                        for (int i = 0; i < g.length; i++) g[i] *= tau;
                    }
                }
            }
            case THERMAL_LINK, DRIFT, POINT_SMOOTH, BASE_TURN, TARGET_STEP, TARGET_DRIFT, BASE_CREEP, BASE_STEP, RANGE_STEP, INSTRUMENT, INSTRUMENT_SCALE, REFRACTION, BASE_TILT, AXIS_WOBBLE, AXIAL_RUNOUT,
                 TOOL_SAG, TOOL_PLAY, LINK_SAG, LINK_TWIST, TARGET_INCIDENCE, TOOL_PULL, LOAD_TILT, SECOND_STATION -> throw new IllegalStateException(label() + " acts on the measured point");
        }
    }

    /**
     * The regressor of an effect on the measured point: Δp (base, m) = G v with G 3 x size,
     * row-major, at q under c with the predicted point {@code pointBase}.
     */
    public void positionRegressor(double[] q, PoseConditions c, double[] pointBase, double[] g3) {
        double x = conditionX(c);
        Arrays.fill(g3, 0);
        int k = size();
        switch (kind) {
            case DRIFT -> { for (int a = 0; a < 3; a++) g3[a * k + a] = x; }
            case BASE_TILT -> {
                double[] t = tilt(q, c.payloadKg());
                tiltRegressor(t[2], t[0], t[1], pointBase, g3);
            }
            case TOOL_SAG -> toolSagRegressor(model.flange(q), down, g3);
            case TOOL_PLAY -> toolPlayRegressor(model.flange(q), down, false, g3, k, 0);
            case TARGET_INCIDENCE -> incidenceRegressor(model.flange(q), sightOrigin, sightAxis, sightAcross, pointBase, g3);
            case LINK_SAG -> linkSagColumns(q, c, pointBase, g3, null);
            case LINK_TWIST -> linkTwistColumns(q, c, pointBase, g3, null);
            case TOOL_PULL -> toolPullColumns(q, pointBase, g3, null);
            case AXIAL_RUNOUT -> {
                // the distal bodies move along the joint's axis: Δp = δ(θ) ẑ, whatever the point
                double[] z = new double[3];
                double th = runoutFrame(q, z);
                for (int i = 0; i < harmonics.length; i++) {
                    double cs = Math.cos(harmonics[i] * th), sn = Math.sin(harmonics[i] * th);
                    for (int a = 0; a < 3; a++) {
                        g3[a * k + 2 * i] = cs * z[a];
                        g3[a * k + 2 * i + 1] = sn * z[a];
                    }
                }
            }
            case AXIS_WOBBLE, LOAD_TILT -> {
                // the distal bodies turn by ω about the model's point of the axis: Δp = ω × (p − o)
                double[] w = new double[3 * k], o = new double[3];
                if (kind == Kind.LOAD_TILT) loadTilt(q, c, w, o);
                else wobble(q, w, o);
                double rx = pointBase[0] - o[0], ry = pointBase[1] - o[1], rz = pointBase[2] - o[2];
                int turns = kind == Kind.LOAD_TILT ? 4 : k;
                for (int col = 0; col < turns; col++) {
                    double wx = w[col], wy = w[k + col], wz = w[2 * k + col];
                    g3[col] = wy * rz - wz * ry;
                    g3[k + col] = wz * rx - wx * rz;
                    g3[2 * k + col] = wx * ry - wy * rx;
                }
                // a load tilt's shifts across the axis (its turn about another point of the axis): the tilt's directions
                for (int col = turns; col < k; col++) for (int a = 0; a < 3; a++) g3[a * k + col] = w[a * k + col - 4];
            }
            case INSTRUMENT -> {
                // the instrument's reading of the predicted point, and the point's move per unit error of it, back in base axes
                double[] pi = instrument.apply(new Vec3(pointBase[0], pointBase[1], pointBase[2])).toArray();
                double[] d = sightDirection(sight, pi), b = new double[nBasis];
                double u = sightReading(sight, azimuthRef, pi);
                if (Double.isFinite(cycle)) cyclicBasis(u, b);
                else bspline(u, lo, hi, b);
                for (int a = 0; a < 3; a++) {
                    double da = instrument.rot(0, a) * d[0] + instrument.rot(1, a) * d[1] + instrument.rot(2, a) * d[2];
                    for (int i = 0; i < nBasis; i++) g3[a * k + i] = da * b[i];
                }
            }
            case REFRACTION -> {
                // Δp = k(u) d² along the base's z, d the point's horizontal distance from the instrument's origin o = −R_ibᵀ t_ib
                double[] b = readingBasis(c);
                if (b == null) break; // an unknown temperature contributes nothing
                Vec3 o = instrument.inverse().position();
                double dx = pointBase[0] - o.x(), dy = pointBase[1] - o.y(), d2 = dx * dx + dy * dy;
                for (int i = 0; i < nBasis; i++) g3[2 * k + i] = d2 * b[i];
            }
            case INSTRUMENT_AXES -> {
                // Δp_i = S p_i in the instrument's axes, turned into the base's: R_ibᵀ (E_k p_i) per column
                double[] pi = instrument.apply(new Vec3(pointBase[0], pointBase[1], pointBase[2])).toArray();
                double xi = pi[0], yi = pi[1], zi = pi[2];
                // column c moves the point by (cx[c], cy[c], cz[c]) in the instrument's axes: the scales, shears, then the bows
                double[] cx = {xi, 0, yi, zi, 0, 0, 0, yi * yi, 0, zi * zi, 0};
                double[] cy = {0, yi, xi, 0, zi, xi * xi, 0, 0, 0, 0, zi * zi};
                double[] cz = {0, 0, 0, xi, yi, 0, xi * xi, 0, yi * yi, 0, 0};
                for (int col = 0; col < k; col++)
                    for (int a = 0; a < 3; a++)
                        g3[a * k + col] = instrument.rot(0, a) * cx[col] + instrument.rot(1, a) * cy[col] + instrument.rot(2, a) * cz[col];
            }
            case INSTRUMENT_SCALE -> {
                // Δp = s(u) (p − o), o the instrument's origin: in base axes R_ibᵀ (s p_i) with p_i = R_ib p + t_ib
                double[] b = readingBasis(c);
                if (b == null) break; // an unknown temperature contributes nothing
                double[] pi = instrument.apply(new Vec3(pointBase[0], pointBase[1], pointBase[2])).toArray();
                for (int a = 0; a < 3; a++) {
                    double ra = instrument.rot(0, a) * pi[0] + instrument.rot(1, a) * pi[1] + instrument.rot(2, a) * pi[2];
                    for (int i = 0; i < nBasis; i++) g3[a * k + i] = ra * b[i];
                }
            }
            case BASE_CREEP -> {
                double n = creepCount(Double.isFinite(c.timeS()) ? c.timeS() : Double.POSITIVE_INFINITY);
                g3[0] = -n * pointBase[1];
                g3[k] = n * pointBase[0];
                g3[1] = n;
                g3[k + 2] = n;
            }
            case TARGET_DRIFT -> {
                // d(t) in the flange's axes, turned into the base's
                double[] b = new double[nBasis];
                bspline(reading(c), lo, hi, b);
                Pose f = model.flange(q);
                for (int a = 0; a < 3; a++)
                    for (int axis = 0; axis < 3; axis++) {
                        double r = f.rot(a, axis);
                        for (int i = 0; i < nBasis; i++) g3[a * k + axis * nBasis + i] = r * b[i];
                    }
            }
            case TARGET_STEP -> {
                // before the move the point sat −d (flange frame) from where it ended; an unknown time: where it ended
                if (!(c.timeS() <= tauS)) break;
                Pose f = model.flange(q);
                for (int a = 0; a < 3; a++) for (int col = 0; col < 3; col++) g3[a * k + col] = -f.rot(a, col);
            }
            case BASE_STEP -> { if (c.timeS() <= tauS) baseStepRegressor(pointBase, g3, null); }
            case SECOND_STATION -> { if (seenFromSecond(q)) baseStepRegressor(pointBase, g3, null); }
            case RANGE_STEP -> {
                // before the jump every distance read d less than at the end: −d along the line of sight, in base axes
                // R_ibᵀ p_i/|p_i| with p_i = R_ib p + t_ib (its change with the point itself, d/|p_i|, is left out: 10⁻⁵ of d)
                if (!(c.timeS() <= tauS)) break;
                double[] pi = instrument.apply(new Vec3(pointBase[0], pointBase[1], pointBase[2])).toArray();
                double rho = Math.sqrt(pi[0] * pi[0] + pi[1] * pi[1] + pi[2] * pi[2]);
                if (!(rho > 0)) break;
                for (int a = 0; a < 3; a++)
                    g3[a * k] = -(instrument.rot(0, a) * pi[0] + instrument.rot(1, a) * pi[1] + instrument.rot(2, a) * pi[2]) / rho;
            }
            case BASE_TURN -> {
                double[] b = readingBasis(c);
                if (b == null) break; // an unknown temperature contributes nothing
                double px = pointBase[0], py = pointBase[1], pz = pointBase[2];
                for (int i = 0; i < nBasis; i++) {
                    // ω = e_a b_i: e_x × p = (0, −z, y), e_y × p = (z, 0, −x), e_z × p = (−y, x, 0)
                    g3[k + i] = -pz * b[i];
                    g3[2 * k + i] = py * b[i];
                    g3[nBasis + i] = pz * b[i];
                    g3[2 * k + nBasis + i] = -px * b[i];
                    g3[2 * nBasis + i] = -py * b[i];
                    g3[k + 2 * nBasis + i] = px * b[i];
                }
                double share = (reading(c) - lo) / (hi - lo);
                for (int a = 0; a < 3; a++) g3[a * k + 3 * nBasis + a] = share;
            }
            case POINT_SMOOTH -> {
                double[] b = new double[nBasis];
                double u = switch (along) {
                    case TIME, TEMPERATURE -> reading(c);
                    default -> pointVariable(pointBase);
                };
                if (!Double.isFinite(u)) break; // unknown conditions contribute nothing
                bspline(u, lo, hi, b);
                if (along == Along.PAYLOAD_REACH) {
                    double load = Double.isFinite(c.payloadKg()) ? c.payloadKg() : 0;
                    for (int i = 0; i < nBasis; i++) b[i] *= load;
                }
                for (int a = 0; a < 3; a++) System.arraycopy(b, 0, g3, a * k + a * nBasis, nBasis);
            }
            case THERMAL_LINK -> {
                Pose[] f = model.linkFrames(q);
                int nl = links.length;
                for (int col = 0; col < k; col++) {
                    int i = links[col % nl];
                    Vec3 from = f[i].position();
                    Vec3 to = i + 1 < f.length ? f[i + 1].position() : new Vec3(pointBase[0], pointBase[1], pointBase[2]);
                    Vec3 s = to.minus(from);
                    x = col < nl ? linkX(c, col) : warmX(c, col - nl);
                    g3[col] = x * s.x();
                    g3[k + col] = x * s.y();
                    g3[2 * k + col] = x * s.z();
                }
            }
            default -> throw new IllegalStateException(label() + " does not act on the measured point");
        }
    }

    /** A point-smooth effect's geometric variable at a point (base frame, m): its reach or its height (NaN for time, temperature). */
    public double pointVariable(double[] pointBase) {
        return along == Along.HEIGHT ? pointBase[2]
                : along == Along.REACH || along == Along.PAYLOAD_REACH ? Math.hypot(pointBase[0], pointBase[1]) : Double.NaN;
    }

    /** Uniform cubic B-spline basis (n = g.length functions) on [lo, hi] at x (clamped to the range). */
    static void bspline(double x, double lo, double hi, double[] g) {
        int n = g.length;
        double h = (hi - lo) / (n - 3);
        double xc = Math.min(hi, Math.max(lo, x));
        for (int i = 0; i < n; i++) {
            double u = (xc - (lo + (i - 3) * h)) / h;
            double v;
            if (u < 0 || u >= 4) v = 0;
            else if (u < 1) v = u * u * u / 6;
            else if (u < 2) v = (-3 * u * u * u + 12 * u * u - 12 * u + 4) / 6;
            else if (u < 3) v = (3 * u * u * u - 24 * u * u + 60 * u - 44) / 6;
            else v = (4 - u) * (4 - u) * (4 - u) / 6;
            g[i] = v;
        }
        if (xc == hi) { Arrays.fill(g, 0); g[n - 3] = 1 / 6.0; g[n - 2] = 4 / 6.0; g[n - 1] = 1 / 6.0; }
    }

    /** The drive or strain value (Δq_joint in rad, or the strain) at q, c. */
    public double value(double[] v, double[] q, PoseConditions c) {
        double[] g = new double[size()];
        regressor(q, c, g);
        double s = 0;
        for (int i = 0; i < g.length; i++) s += g[i] * v[i];
        return s;
    }

    /**
     * The time or temperature an effect along one of them reads under c: an unknown time is the
     * state the campaign ended in (the range's end), an unknown temperature NaN.
     */
    private double reading(PoseConditions c) {
        if (along == Along.TEMPERATURE) return c.tempC();
        return Double.isFinite(c.timeS()) ? c.timeS() : hi;
    }

    /**
     * The effect's B-spline of its variable at {@code u} (time, s, or temperature, °C: a base turn's
     * or an instrument scale's) with the coefficients {@code v[from]} .. {@code v[from + basisCount)}.
     */
    public double splineAt(double[] v, int from, double u) {
        double[] b = new double[nBasis];
        bspline(u, lo, hi, b);
        double s = 0;
        for (int i = 0; i < nBasis; i++) s += b[i] * v[from + i];
        return s;
    }

    /** The spline functions of an effect along time or temperature at c's reading; null at an unknown temperature. */
    private double[] readingBasis(PoseConditions c) {
        double u = reading(c);
        if (!Double.isFinite(u)) return null;
        double[] b = new double[nBasis];
        bspline(u, lo, hi, b);
        return b;
    }

    /** Whether this effect also turns the measured frame (a base tilt turns everything the robot carries). */
    public boolean turnsFrame() { return kind == Kind.BASE_TILT || kind == Kind.AXIS_WOBBLE || kind == Kind.LINK_SAG || kind == Kind.LINK_TWIST || kind == Kind.TOOL_PULL
            || kind == Kind.LOAD_TILT || kind == Kind.BASE_TURN || kind == Kind.BASE_STEP || kind == Kind.SECOND_STATION || kind == Kind.TOOL_PLAY && playTurns; }

    /**
     * The rotation of the measured frame (base coordinates, rad): Δω = G v with G 3 x size,
     * row-major, at q under c; zero unless {@link #turnsFrame()}. A base tilt turns the frame by
     * a·x·e (its tilt parameter; the lift and the slide turn nothing).
     */
    public void rotationRegressor(double[] q, PoseConditions c, double[] g3) {
        Arrays.fill(g3, 0);
        if (kind == Kind.AXIS_WOBBLE) { wobble(q, g3, new double[3]); return; }
        if (kind == Kind.LOAD_TILT) { loadTilt(q, c, g3, new double[3]); return; }
        if (kind == Kind.LINK_SAG) { linkSagColumns(q, c, null, null, g3); return; }
        if (kind == Kind.LINK_TWIST) { linkTwistColumns(q, c, null, null, g3); return; }
        if (kind == Kind.TOOL_PULL) { toolPullColumns(q, null, null, g3); return; }
        if (kind == Kind.TOOL_PLAY) { if (playTurns) toolPlayRegressor(model.flange(q), down, true, g3, size(), PLAY_SHIFTS); return; }
        if (kind == Kind.BASE_STEP) { if (c.timeS() <= tauS) baseStepRegressor(null, null, g3); return; }
        if (kind == Kind.SECOND_STATION) { if (seenFromSecond(q)) baseStepRegressor(null, null, g3); return; }
        if (kind == Kind.BASE_CREEP) { g3[2 * size()] = creepCount(Double.isFinite(c.timeS()) ? c.timeS() : Double.POSITIVE_INFINITY); return; }
        if (kind == Kind.BASE_TURN) {
            double[] b = readingBasis(c);
            if (b == null) return;
            int k = size();
            for (int a = 0; a < 3; a++) System.arraycopy(b, 0, g3, a * k + a * nBasis, nBasis);
            return;
        }
        if (kind != Kind.BASE_TILT) return;
        double[] t = tilt(q, c.payloadKg());
        g3[0] = t[2] * t[0];
        g3[3] = t[2] * t[1];
    }

    /** The rotation (base, rotation vector, rad) of the measured frame by an effect that turns it (zero otherwise). */
    public Vec3 rotation(double[] v, double[] q, PoseConditions c) {
        int k = size();
        double[] g = new double[3 * k];
        rotationRegressor(q, c, g);
        double[] d = new double[3];
        for (int a = 0; a < 3; a++) for (int i = 0; i < k; i++) d[a] += g[a * k + i] * v[i];
        return new Vec3(d[0], d[1], d[2]);
    }

    /** The point displacement (base, m) of an effect on the measured point. */
    public Vec3 displacement(double[] v, double[] q, PoseConditions c, Vec3 pointBase) {
        int k = size();
        double[] g = new double[3 * k];
        positionRegressor(q, c, new double[] {pointBase.x(), pointBase.y(), pointBase.z()}, g);
        double[] d = new double[3];
        for (int a = 0; a < 3; a++) for (int i = 0; i < k; i++) d[a] += g[a * k + i] * v[i];
        return new Vec3(d[0], d[1], d[2]);
    }

    /**
     * This effect with fixed values for the campaign simulator's true robot (drive and strain
     * effects; that simulator has no effects on the measured point).
     */
    public JointEffect truth(double[] values) {
        double[] v = values.clone();
        if (v.length != size()) throw new IllegalArgumentException(label() + " needs " + size() + " values, got " + v.length);
        if (target() == Target.POSITION) throw new UnsupportedOperationException(label() + ": the campaign simulator has no point effects");
        Effect self = this;
        return new JointEffect() {
            @Override public String name() { return kind.json; }

            @Override public void addDeltaTheta(KinematicModel m, double[] q, PoseConditions c, double[] dThetaOut) {
                if (isStrain()) return;
                double dq = self.value(v, q, c);
                double[][] cm = m.couplingMatrix();
                for (int i = 0; i < dThetaOut.length; i++) dThetaOut[i] += cm[i][joint] * dq; // θ = C q_out
            }

            @Override public double lengthStrain(PoseConditions c) {
                return isStrain() ? self.value(v, null, c) : 0;
            }

            @Override public String toString() { return label() + " " + Arrays.toString(v); }
        };
    }

    /**
     * Whether drive {@code target}'s output can follow drive {@code source}'s angle. A drive train
     * runs from its motor to its joint, so it can be turned only by the joints it passes: joints
     * before its own in the chain, between the link its motor rides on and its own joint. A linkage
     * the controller couples (a parallel arm's rod, θ3 = q3 − q2) ties the pair both ways. A joint
     * beyond the target has no path to it: its drive turns only what lies beyond itself.
     * <p>
     * On a six-axis arm the motors sit where the industrial arms put them (Craig, <i>Introduction to
     * Robotics</i>, 3rd ed., §8.5 and the PUMA 560's wrist coupling; the ABB IRB and KUKA product
     * manuals' motor layouts): axes 1 and 2 on the base and the turret, axis 3 on the turret or the
     * lower arm (a rod or a belt along the lower arm passes axis 2), axes 4–6 at the upper arm's rear,
     * their shafts through axes 4 and 5 to the hand. So joint 3 may follow joint 2, a wrist joint the
     * wrist joints before it, and nothing else: no shaft of the wrist passes axes 1–3. Other arms keep
     * the general rule (any joint before the target).
     */
    static boolean canCouple(KinematicModel model, int target, int source) {
        if (target == source) return false;
        double[][] c = model.couplingMatrix();
        if (c[target][source] != 0 || c[source][target] != 0) return true;
        if (source > target) return false;
        if (model.dof() != 6) return true;
        return target == 2 && source == 1 || source >= 3;
    }

    /** This effect as an identification parameter block on {@code m} (its coupling matrix), starting at zero. */
    public EffectBlock block(KinematicModel m) {
        Effect self = this;
        int k = size();
        int dof = m.dof();
        double[] cCol = new double[dof];
        if (atJoint) cCol[joint] = 1; // the joint's own angle: C (C⁻¹ e_j) = e_j
        else if (joint >= 0) { double[][] cm = m.couplingMatrix(); for (int i = 0; i < dof; i++) cCol[i] = cm[i][joint]; }
        Target t = target();
        return new EffectBlock() {
            @Override public String name() { return id(); }
            @Override public List<String> parameterNames() { return self.parameterNames(); }
            @Override public List<String> units() { return self.units(); }
            @Override public double[] initialValues() { return new double[k]; }

            @Override public void jointDelta(double[] values, Measurement row, double[] dTheta, double[] dThetaDv) {
                if (dThetaDv != null) Arrays.fill(dThetaDv, 0);
                if (t != Target.DRIVE) return;
                double[] g = new double[k];
                regressor(row, PoseConditions.of(row), g);
                double s = 0;
                for (int i = 0; i < k; i++) s += g[i] * values[i];
                for (int i = 0; i < dof; i++) {
                    if (cCol[i] == 0) continue;
                    dTheta[i] += cCol[i] * s;
                    if (dThetaDv != null) for (int col = 0; col < k; col++) dThetaDv[i * k + col] = cCol[i] * g[col];
                }
            }

            @Override public void positionDelta(double[] values, Measurement row, double[] pointBase, double[] dp, double[] dpDv,
                                                double[] dpDpoint) {
                if (dpDv != null) Arrays.fill(dpDv, 0);
                if (t == Target.DRIVE) return;
                PoseConditions c = PoseConditions.of(row);
                if (t == Target.STRAIN) {
                    double[] g = new double[1];
                    regressor(row.q(), c, g);
                    double e = g[0] * values[0];
                    if (dpDpoint != null) for (int a = 0; a < 3; a++) dpDpoint[4 * a] += e; // ∂(ε p)/∂p = ε I
                    for (int a = 0; a < 3; a++) {
                        dp[a] += e * pointBase[a];
                        if (dpDv != null) dpDv[a] = g[0] * pointBase[a];
                    }
                    return;
                }
                double[] g3 = new double[3 * k];
                positionRegressor(row.q(), c, pointBase, g3);
                for (int a = 0; a < 3; a++)
                    for (int col = 0; col < k; col++) {
                        dp[a] += g3[a * k + col] * values[col];
                        if (dpDv != null) dpDv[a * k + col] = g3[a * k + col];
                    }
                double[] sb = kind == Kind.INSTRUMENT_SCALE && dpDpoint != null ? readingBasis(c) : null;
                if (sb != null) { // ∂(s (p − o))/∂p = s I
                    double sc = 0;
                    for (int col = 0; col < k; col++) sc += sb[col] * values[col];
                    for (int a = 0; a < 3; a++) dpDpoint[4 * a] += sc;
                }
                if (kind == Kind.THERMAL_LINK && dpDpoint != null) {
                    // the last vector ends at the point: ∂/∂p of x α_tool (p − o_flange) = x α_tool I
                    int nl = links.length;
                    double x = linkX(c, nl - 1) * values[nl - 1] + (warms() ? warmX(c, nl - 1) * values[2 * nl - 1] : 0);
                    for (int a = 0; a < 3; a++) dpDpoint[4 * a] += x;
                }
            }

            @Override public void rotationDelta(double[] values, Measurement row, double[] pointBase, double[] dw, double[] dwDv) {
                if (dwDv != null) Arrays.fill(dwDv, 0);
                if (!turnsFrame()) return;
                double[] g3 = new double[3 * k];
                rotationRegressor(row.q(), PoseConditions.of(row), g3);
                for (int a = 0; a < 3; a++)
                    for (int col = 0; col < k; col++) {
                        dw[a] += g3[a * k + col] * values[col];
                        if (dwDv != null) dwDv[a * k + col] = g3[a * k + col];
                    }
            }
        };
    }

    /** The robot-file form (docs/robot-file.md "effects"): parameters SI keyed by name, plus the effect's constants. */
    public EffectDescription describe(double[] values) {
        Map<String, Double> p = new LinkedHashMap<>();
        List<String> names = parameterNames();
        for (int i = 0; i < names.size(); i++) p.put(names.get(i), values[i]);
        switch (kind) {
            case THERMAL, DRIFT -> { if (usesTimeProxy()) p.put("tau_s", tauS); else p.put("t0_c", t0C); }
            case THERMAL_LINK -> {
                p.put("t0_c", t0C);
                if (lags()) for (int col = 0; col < links.length; col++) p.put("lag_s_" + linkName(links[col]), lagTaus[col]);
                if (warms()) for (int col = 0; col < links.length; col++) p.put("warm_tau_s_" + linkName(links[col]), warmTaus[col]);
            }
            case SMOOTH -> {
                p.put("q_min", lo);
                p.put("q_max", hi);
                if (model != null) p.put("model_angle", 1.0);
            }
            case POINT_SMOOTH, ZERO_DRIFT, BASE_TURN, TARGET_DRIFT -> { p.put(along.key + "_min", lo); p.put(along.key + "_max", hi); }
            case COMPLIANCE_VARYING -> {
                p.put(along.key + "_min", lo);
                p.put(along.key + "_max", hi);
                if (payloadShare) p.put("payload_share", 1.0);
                if (stepTimes != null) for (int i = 0; i < stepTimes.length; i++) p.put("time_s_step_" + (i + 1), stepTimes[i]);
                if (payloadCentreFree) p.put("payload_centre_free", 1.0);
                if (gravity.fromLengths()) p.put("varying_masses_from_lengths", 1.0);
            }
            case INSTRUMENT_SCALE, REFRACTION -> { p.put(along.key + "_min", lo); p.put(along.key + "_max", hi); putInstrument(p, instrument); }
            case INSTRUMENT_AXES -> putInstrument(p, instrument); // (the bows' keys tell the bowed form)
            case ZERO_STEP, TARGET_STEP, BASE_STEP -> p.put("time_s_step", tauS);
            case SECOND_STATION -> {
                if (stations == null) { p.put("facing_x", facing.x()); p.put("facing_y", facing.y()); p.put("facing_z", facing.z()); }
                else {
                    for (int i = 0; i < 6; i++) p.put((i < 3 ? "first_" : "second_") + "xyz".charAt(i % 3), stations[i]);
                    p.put("target_x", attach.x());
                    p.put("target_y", attach.y());
                    p.put("target_z", attach.z());
                }
            }
            case BASE_CREEP -> { p.put("creep_move_rad", tauS); p.put("creep_count_end", creepCount(Double.POSITIVE_INFINITY)); }
            case RANGE_STEP -> { p.put("time_s_step", tauS); putInstrument(p, instrument); }
            case AXIS_WOBBLE, AXIAL_RUNOUT -> { }
            case LOAD_TILT -> {
                p.put("load_ref_nm", loadRefNm);
                if (gravity.fromLengths()) p.put("load_masses_from_lengths", 1.0);
                if (massScales != null) putMassScales(p, "load_mass_scale_");
            }
            case TOOL_SAG, TOOL_PLAY -> { p.put("down_x", down.x()); p.put("down_y", down.y()); p.put("down_z", down.z()); }
            case COMPLIANCE -> { if (atJoint) p.put("at_joint", 1.0); }
            case TARGET_INCIDENCE -> {
                p.put("axis_x", sightAxis.x());
                p.put("axis_y", sightAxis.y());
                p.put("axis_z", sightAxis.z());
                putInstrument(p, instrument);
            }
            case LINK_SAG, LINK_TWIST -> { }
            case TOOL_PULL -> {
                p.put("attach_x", attach.x());
                p.put("attach_y", attach.y());
                p.put("attach_z", attach.z());
                if (anchor != null) { p.put("anchor_x", anchor[0]); p.put("anchor_y", anchor[1]); p.put("anchor_z", anchor[2]); }
            }
            case BASE_TILT -> {
                if (!towardLean()) p.put("axis_azimuth_rad", tiltAzimuth);
                if (squareFoot()) p.put("foot_edges", 4.0);
                if (!Double.isInfinite(tiltHold)) p.put("hold_nm", tiltHold);
                if (massScales != null) putMassScales(p, "tilt_mass_scale_");
            }
            case INSTRUMENT -> {
                p.put(sight.key + "_min", lo);
                p.put(sight.key + "_max", hi);
                if (sight == Sight.AZIMUTH) p.put("azimuth_ref_rad", azimuthRef);
                if (Double.isFinite(cycle)) p.put(sight.key + "_cycle", cycle);
                putInstrument(p, instrument);
            }
            case ANGLE_STEP -> { p.put("q_step", lo); if (isWindow()) p.put("q_step_back", hi); }
            case GRAVITY_PLAY -> {
                p.put("side_nm", sideNm);
                p.put("side_width_nm", sideWidthNm);
                if (gravity.fromLengths()) p.put("play_masses_from_lengths", 1.0);
            }
            case LINK_PERIODIC -> { for (int l = 0; l < linkAngle.length; l++) p.put("angle_q" + (l + 1), linkAngle[l]); }
            case WARM_PERIODIC -> { p.put("temp_c_min", lo); p.put("temp_c_max", hi); }
            case LOAD_PERIODIC -> {
                p.put("load_ref_nm", loadRefNm);
                if (loadMagnitude) p.put("load_magnitude", 1.0);
                if (gravity.fromLengths()) p.put("load_masses_from_lengths", 1.0);
            }
            case BACKLASH -> {
                if (buildsUp()) p.put("build_up_rad", buildUp);
                if (approached()) p.put("approach_rad", approach);
                if (heldByGravity()) {
                    p.put("held_above_nm", preloadNm);
                    p.put("held_width", preloadWidth);
                    if (gravity.fromLengths()) p.put("held_masses_from_lengths", 1.0);
                    if (massScales != null)
                        putMassScales(p, "held_mass_scale_");
                }
            }
            default -> { }
        }
        return new EffectDescription(json(), joints1(), p);
    }

    /** The whole harmonics a1, a2, ... an effect's parameters name (their b's beside them); refused when there is none. */
    private static int[] wholeHarmonics(EffectDescription d, String file) {
        int[] hs = d.parameters().keySet().stream().filter(key -> key.matches("a\\d+")).mapToInt(key -> Integer.parseInt(key.substring(1))).toArray();
        if (hs.length == 0) throw d.error(file, "parameters_si", "no harmonic a1, a2, ...");
        return hs;
    }

    /** The periodic error of drive {@code joint} at the orders its description's a-parameters name (a7: whole, a7.1: a stage). */
    private static Effect periodicOf(EffectDescription d, int joint, String file) {
        List<Integer> hs = new ArrayList<>();
        List<Double> st = new ArrayList<>();
        for (String key : d.parameters().keySet())
            if (key.matches("a\\d+")) hs.add(Integer.parseInt(key.substring(1)));
            else if (key.matches("a\\d+\\.\\d+")) st.add(Double.parseDouble(key.substring(1)));
        if (hs.isEmpty() && st.isEmpty())
            throw d.error(file, "parameters_si", "no harmonic a1, a2, ... or stage order a7.1, ...");
        return periodic(joint, hs.stream().mapToInt(Integer::intValue).toArray(), st.stream().mapToDouble(Double::doubleValue).toArray());
    }

    /** Reads an effect back from its robot-file form; values in the order of {@link #parameterNames()}. */
    public static Term fromDescription(EffectDescription d, KinematicModel model, GravityTorques gravity, String file) {
        Kind kind = SHAFT_JSON.equals(d.effect()) ? Kind.PERIODIC : Kind.of(d.effect());
        if (kind == null) throw d.error(file, "effect", "unknown effect '" + d.effect() + "'");
        List<Integer> js = d.joints();
        int need = switch (kind) {
            case THERMAL, THERMAL_LINK, DRIFT, POINT_SMOOTH, BASE_TURN, TARGET_STEP, TARGET_DRIFT, BASE_CREEP, BASE_STEP, RANGE_STEP, INSTRUMENT, INSTRUMENT_SCALE, INSTRUMENT_AXES, REFRACTION, BASE_TILT,
                 TOOL_SAG, TOOL_PLAY, TARGET_INCIDENCE, TOOL_PULL, SECOND_STATION -> 0;
            case COUPLING, PAIR -> 2;
            case SMOOTH -> js.size() == 2 ? 2 : 1; // its own angle, or another joint's (target, then source)
            default -> 1;
        };
        Along along = null;
        for (Along a : Along.values()) if (d.parameters().containsKey(a.key + "_min")) along = a;
        if ((kind == Kind.POINT_SMOOTH || kind == Kind.ZERO_DRIFT || kind == Kind.BASE_TURN || kind == Kind.INSTRUMENT_SCALE || kind == Kind.REFRACTION
                || kind == Kind.TARGET_DRIFT
                || kind == Kind.COMPLIANCE_VARYING)
                && along == null)
            throw d.error(file, "parameters_si", "needs the variable's range, e.g. time_s_min and time_s_max");
        if (js.size() != need)
            throw d.error(file, "joints", d.effect() + " needs " + need + " joints, got " + js);
        for (int j : js)
            if (j < 1 || j > model.dof())
                throw d.error(file, "joints", "joint " + j + " outside 1.." + model.dof());
        Map<String, Double> ps = d.parameters();
        Effect e = switch (kind) {
            case COMPLIANCE -> {
                // a compliance "c" is a stiffness on the file's masses; without them only the remassed form means anything
                if (gravity == null || gravity.massesUnknown() && ps.containsKey("c"))
                    throw needsMassModel(d, file, "joint-compliance");
                if (ps.containsKey("at_joint")) yield complianceAtJoint(js.get(0) - 1, gravity, !ps.containsKey("c"));
                yield ps.containsKey("c3") ? complianceStiffening(js.get(0) - 1, gravity)
                        : ps.containsKey("c") ? compliance(js.get(0) - 1, gravity) : complianceRemassed(js.get(0) - 1, gravity);
            }
            case PERIODIC -> periodicOf(d, js.get(0) - 1, file);
            case LINK_PERIODIC -> {
                double[] c = new double[model.dof()];
                boolean any = false;
                for (int l = 0; l < c.length; l++) {
                    Double v = ps.get("angle_q" + (l + 1));
                    if (v != null) { c[l] = v; any |= v != 0; }
                }
                if (!any) throw d.error(file, "parameters_si", "needs the angle's coefficients angle_q1..angle_q" + model.dof());
                int[] hs = wholeHarmonics(d, file);
                yield linkPeriodic(js.get(0) - 1, c, hs);
            }
            case GRAVITY_PLAY -> {
                GravityTorques g = ps.containsKey("play_masses_from_lengths") ? GravityTorques.fromLengths(model) : gravity;
                if (g == null || g.massesUnknown()) throw needsMassModel(d, file, "joint-gravity-play");
                double wd = ps.containsKey("side_width_nm") ? require(d, "side_width_nm", file) : 0;
                if (!(wd >= 0) || Double.isInfinite(wd)) throw d.error(file, "parameters_si.side_width_nm", "must be >= 0, got " + wd);
                yield gravityPlay(js.get(0) - 1, g, require(d, "side_nm", file), wd);
            }
            case WARM_PERIODIC -> {
                int[] hs = wholeHarmonics(d, file);
                double lo = require(d, "temp_c_min", file), hi = require(d, "temp_c_max", file);
                if (!(hi > lo)) throw d.error(file, "parameters_si.temp_c_max", "must be above temp_c_min, got " + hi);
                yield periodicWarming(js.get(0) - 1, hs, lo, hi);
            }
            case LOAD_PERIODIC -> {
                GravityTorques g = ps.containsKey("load_masses_from_lengths") ? GravityTorques.fromLengths(model) : gravity;
                if (g == null || g.massesUnknown()) throw needsMassModel(d, file, "joint-load-periodic");
                double ref = require(d, "load_ref_nm", file);
                if (!(ref > 0) || Double.isInfinite(ref)) throw d.error(file, "parameters_si.load_ref_nm", "must be > 0, got " + ref);
                yield loadPeriodic(periodicOf(d, js.get(0) - 1, file), g, ref, ps.containsKey("load_magnitude"));
            }
            case BACKLASH -> {
                if (ps.containsKey("held_above_nm")) {
                    double t = require(d, "held_above_nm", file);
                    // the masses it was fitted with: the robot file's, or estimated from the link lengths when the file had none
                    GravityTorques g = ps.containsKey("held_masses_from_lengths") ? GravityTorques.fromLengths(model) : gravity;
                    if (g == null || g.massesUnknown())
                        throw needsMassModel(d, file, "backlash held by gravity");
                    if (!(t >= 0)) throw d.error(file, "parameters_si.held_above_nm", "must be >= 0, got " + t);
                    double wd = ps.containsKey("held_width") ? require(d, "held_width", file) : 0;
                    if (!(wd >= 0 && wd < 1)) throw d.error(file, "parameters_si.held_width", "must be in [0, 1), got " + wd);
                    yield heldByGravity(js.get(0) - 1, g, t, wd, massScales(d, g, "held_mass_scale_", file));
                }
                Effect form = backlash(js.get(0) - 1);
                if (ps.containsKey("build_up_rad")) {
                    double x0 = require(d, "build_up_rad", file);
                    if (!(x0 > 0)) throw d.error(file, "parameters_si.build_up_rad", "must be > 0, got " + x0);
                    double a = Double.NaN;
                    if (ps.containsKey("approach_rad")) {
                        a = require(d, "approach_rad", file);
                        if (!(a > 0)) throw d.error(file, "parameters_si.approach_rad", "must be > 0, got " + a);
                    }
                    form = windUp(js.get(0) - 1, x0, a, null);
                }
                // the play's orders from its parameters' names: b_cos (once per turn), b_cos_4.417 (4.417 times per turn)
                List<Double> orders = new ArrayList<>();
                for (String key : ps.keySet()) {
                    if (key.equals("b_cos")) orders.add(1.0);
                    else if (key.startsWith("b_cos_")) {
                        double f;
                        try { f = Double.parseDouble(key.substring(6)); } catch (NumberFormatException x) { f = Double.NaN; }
                        if (!(f >= 1)) throw d.error(file, "parameters_si." + key,
                                "the play's order after b_cos_ must be a number >= 1 (times per turn)");
                        orders.add(f);
                    }
                }
                yield orders.isEmpty() ? form : withRunout(form, orders.stream().mapToDouble(Double::doubleValue).toArray());
            }
            case SCALE -> scale(js.get(0) - 1);
            case COUPLING -> coupling(js.get(0) - 1, js.get(1) - 1);
            case SMOOTH -> {
                int n = (int) ps.keySet().stream().filter(key -> key.matches("s\\d+")).count();
                if (n < 4) throw d.error(file, "parameters_si", "needs s1..sN, N >= 4");
                if (js.size() == 2 && js.get(0).equals(js.get(1)))
                    throw d.error(file, "joints", "joint-smooth-error following another joint needs two different joints");
                if (ps.containsKey("model_angle"))
                    yield smoothFollowingModelAngle(js.get(0) - 1, js.get(js.size() - 1) - 1, model, require(d, "q_min", file),
                            require(d, "q_max", file), n);
                yield smoothFollowing(js.get(0) - 1, js.size() == 2 ? js.get(1) - 1 : -1, require(d, "q_min", file), require(d, "q_max", file), n);
            }
            case PAIR -> {
                if (js.get(0).equals(js.get(1))) throw d.error(file, "joints", "joint-pair-error needs two different joints");
                yield pair(js.get(0) - 1, js.get(1) - 1);
            }
            case POINT_SMOOTH -> pointSmooth(along, require(d, along.key + "_min", file), require(d, along.key + "_max", file));
            case BASE_TURN -> {
                if (along != Along.TIME && along != Along.TEMPERATURE)
                    throw d.error(file, "parameters_si", "needs time_s_min and time_s_max or temp_c_min and temp_c_max");
                yield baseTurn(along, require(d, along.key + "_min", file), require(d, along.key + "_max", file));
            }
            case INSTRUMENT_AXES -> d.parameters().containsKey("bow_x_y") ? instrumentAxesBowed(instrumentOf(d, file)) : instrumentAxes(instrumentOf(d, file));
            case INSTRUMENT_SCALE, REFRACTION -> {
                if (along != Along.TIME && along != Along.TEMPERATURE)
                    throw d.error(file, "parameters_si", "needs time_s_min and time_s_max or temp_c_min and temp_c_max");
                String c = kind == Kind.INSTRUMENT_SCALE ? "s" : "k"; // the coefficients' letter (parameterNames)
                int n = (int) d.parameters().keySet().stream().filter(key -> key.matches(c + "\\d+")).count();
                if (n < POINT_BASIS) throw d.error(file, "parameters_si", "needs " + c + "1.." + c + "N, N >= " + POINT_BASIS);
                yield instrumentAlong(kind, along, instrumentOf(d, file), require(d, along.key + "_min", file), require(d, along.key + "_max", file), n);
            }
            case ZERO_STEP -> zeroStep(js.get(0) - 1, require(d, "time_s_step", file));
            case SETTLING -> settling(js.get(0) - 1, Directions.Moves.NONE, null);
            case ANGLE_STEP -> d.parameters().containsKey("q_step_back") ? angleWindow(js.get(0) - 1, require(d, "q_step", file),
                    require(d, "q_step_back", file)) : angleStep(js.get(0) - 1, require(d, "q_step", file));
            case TARGET_STEP -> targetStep(model, require(d, "time_s_step", file));
            case BASE_CREEP -> {
                double move = require(d, "creep_move_rad", file), n = require(d, "creep_count_end", file);
                if (!(move > 0)) throw d.error(file, "parameters_si.creep_move_rad", "must be > 0, got " + move);
                yield baseCreepAtEnd(move, n);
            }
            case TARGET_DRIFT -> {
                if (along != Along.TIME) throw d.error(file, "parameters_si", "needs time_s_min and time_s_max");
                int n = (int) d.parameters().keySet().stream().filter(key -> key.matches("dx\\d+")).count();
                if (n < POINT_BASIS) throw d.error(file, "parameters_si", "needs dx1..dxN, N >= " + POINT_BASIS);
                yield targetDrift(model, require(d, "time_s_min", file), require(d, "time_s_max", file), n);
            }
            case BASE_STEP -> baseStep(require(d, "time_s_step", file));
            case SECOND_STATION -> {
                if (ps.containsKey("second_x"))
                    yield secondStation(model, new Vec3(require(d, "first_x", file), require(d, "first_y", file), require(d, "first_z", file)),
                            new Vec3(require(d, "second_x", file), require(d, "second_y", file), require(d, "second_z", file)),
                            new Vec3(require(d, "target_x", file), require(d, "target_y", file), require(d, "target_z", file)));
                Vec3 f = new Vec3(require(d, "facing_x", file), require(d, "facing_y", file), require(d, "facing_z", file));
                if (!(f.norm() > 0)) throw d.error(file, "parameters_si.facing_x", "the facing direction must not be zero");
                yield secondStation(model, f);
            }
            case RANGE_STEP -> rangeStep(instrumentOf(d, file), require(d, "time_s_step", file));
            case LINK_SAG -> {
                if (js.get(0) < 2 || js.get(0) > 3)
                    throw d.error(file, "joints", "link-sag is of the upper arm (joint 2) or the forearm (joint 3), got " + js.get(0));
                if (js.get(0) >= model.dof() || model.isPrismatic(js.get(0) - 1))
                    throw d.error(file, "joints", "link-sag needs joint " + js.get(0) + " revolute with a joint "
                            + "beyond it; this robot's joint " + js.get(0) + (js.get(0) > model.dof() ? " does not exist"
                            : js.get(0) == model.dof() ? " is its last" : " is prismatic"));
                yield linkSag(model, js.get(0) - 1, ps.containsKey("t_payload"));
            }
            case LINK_TWIST -> {
                if (js.get(0) != 2)
                    throw d.error(file, "joints", "link-twist is of the upper arm (joint 2), got " + js.get(0));
                if (model.dof() < 6 || model.isPrismatic(1) || model.isPrismatic(2))
                    throw d.error(file, "", "link-twist needs a six-axis arm whose joints 2 and 3 "
                            + "are revolute; this robot has " + model.dof() + " joints");
                yield linkTwist(model, ps.containsKey("t_payload_o"));
            }
            case TOOL_SAG -> toolSag(model, new Vec3(require(d, "down_x", file), require(d, "down_y", file), require(d, "down_z", file)));
            case TOOL_PULL -> {
                if (!hasRevolute(model))
                    throw d.error(file, "", "tool-pull needs a revolute joint to yield; this robot has none");
                Vec3 at = new Vec3(require(d, "attach_x", file), require(d, "attach_y", file), require(d, "attach_z", file));
                double[] a = ps.containsKey("anchor_x") ? new double[] {require(d, "anchor_x", file), require(d, "anchor_y", file),
                        require(d, "anchor_z", file)} : null;
                yield toolPull(model, at, a);
            }
            case TOOL_PLAY -> toolPlay(model, new Vec3(require(d, "down_x", file), require(d, "down_y", file), require(d, "down_z", file)),
                    ps.containsKey("rxx"));
            case TARGET_INCIDENCE -> {
                Vec3 axis = new Vec3(require(d, "axis_x", file), require(d, "axis_y", file), require(d, "axis_z", file));
                if (!(axis.norm() > 0))
                    throw d.error(file, "parameters_si.axis_x", "the sight axis must not be zero");
                yield targetIncidence(model, instrumentOf(d, file), axis);
            }
            case AXIAL_RUNOUT -> axialRunout(model, revolute(d, model, file), bearingOrders(d, "zc", "zc1, zs1", file));
            case LOAD_TILT -> {
                GravityTorques g = ps.containsKey("load_masses_from_lengths") ? GravityTorques.fromLengths(model) : gravity;
                if (g == null || g.massesUnknown()) throw needsMassModel(d, file, "axis-load-tilt");
                double ref = require(d, "load_ref_nm", file);
                if (!(ref > 0) || Double.isInfinite(ref)) throw d.error(file, "parameters_si.load_ref_nm", "must be > 0, got " + ref);
                yield loadTilt(model, revolute(d, model, file), g, ref, massScales(d, g, "load_mass_scale_", file));
            }
            case AXIS_WOBBLE -> axisWobble(model, revolute(d, model, file), bearingOrders(d, "xc", "xc1, xs1, yc1, ys1", file));
            case BASE_TILT -> {
                if (gravity == null || gravity.massesUnknown())
                    throw needsMassModel(d, file, "base-tilt");
                if (ps.containsKey("foot_edges")) {
                    if (require(d, "foot_edges", file) != 4)
                        throw d.error(file, "parameters_si.foot_edges", "must be 4 (a square foot)");
                    yield squareFootTilt(gravity, require(d, "axis_azimuth_rad", file), require(d, "hold_nm", file),
                            massScales(d, gravity, "tilt_mass_scale_", file));
                }
                yield baseTilt(gravity, ps.containsKey("axis_azimuth_rad") ? require(d, "axis_azimuth_rad", file) : Double.NaN,
                        ps.containsKey("hold_nm") ? require(d, "hold_nm", file) : ps.containsKey("axis_azimuth_rad") ? Double.NEGATIVE_INFINITY : 0,
                        massScales(d, gravity, "tilt_mass_scale_", file));
            }
            case INSTRUMENT -> {
                Sight sg = null;
                for (Sight x : Sight.values()) if (ps.containsKey(x.key + "_min")) sg = x;
                if (sg == null)
                    throw d.error(file, "parameters_si", "needs the reading's range, e.g. range_m_min and range_m_max");
                int n = (int) ps.keySet().stream().filter(key -> key.matches("e\\d+")).count();
                Pose inst0 = instrumentOf(d, file);
                double ref = sg == Sight.AZIMUTH ? require(d, "azimuth_ref_rad", file) : 0;
                if (ps.containsKey(sg.key + "_cycle")) {
                    double cyc = require(d, sg.key + "_cycle", file);
                    if (!(cyc > 0)) throw d.error(file, "parameters_si." + sg.key + "_cycle", "must be > 0, got " + cyc);
                    int orders = 1 + (int) ps.keySet().stream().filter(key -> key.matches("a\\d+")).count();
                    yield instrumentCyclic(sg, inst0, ref, require(d, sg.key + "_min", file), require(d, sg.key + "_max", file), cyc, orders);
                }
                if (n < 4) throw d.error(file, "parameters_si", "needs e1..eN, N >= 4");
                yield instrumentReading(sg, inst0, ref, require(d, sg.key + "_min", file), require(d, sg.key + "_max", file), n);
            }
            case COMPLIANCE_VARYING -> {
                if (along != Along.TIME && along != Along.TEMPERATURE)
                    throw d.error(file, "parameters_si", "a compliance varies with time_s or temp_c");
                GravityTorques g = ps.containsKey("varying_masses_from_lengths") ? GravityTorques.fromLengths(model) : gravity;
                boolean share = ps.containsKey("payload_share");
                if (g == null) throw needsMassModel(d, file, "joint-compliance-varying");
                int n = (int) ps.keySet().stream().filter(key -> key.matches("c\\d+")).count();
                int steps = (int) ps.keySet().stream().filter(key -> key.matches("time_s_step_\\d+")).count();
                boolean centre = ps.containsKey("payload_centre_free");
                if (centre) {
                    if (!share) throw d.error(file, "parameters_si.payload_centre_free", "only a payload's varying compliance estimates its centre");
                    if (n % 4 != 0) throw d.error(file, "parameters_si", "needs four of c1..cN a function with the payload's centre estimated");
                    n /= 4;
                }
                if (steps > 0) {
                    if (!share || along != Along.TIME) throw d.error(file, "parameters_si", "steps of a compliance are the payload's, in time_s");
                    if (n != steps + 1) throw d.error(file, "parameters_si", "needs " + (steps + 1) + " functions (one more than its steps)");
                    double[] times = new double[steps];
                    for (int i = 0; i < steps; i++) times[i] = require(d, "time_s_step_" + (i + 1), file);
                    for (int i = 1; i < steps; i++)
                        if (!(times[i] > times[i - 1])) throw d.error(file, "parameters_si.time_s_step_" + (i + 1), "must be after time_s_step_" + i);
                    Effect stepped = complianceInSteps(js.get(0) - 1, g, times);
                    yield centre ? withPayloadCentreFree(stepped) : stepped;
                }
                if (centre) {
                    if (n < 4) throw d.error(file, "parameters_si", "needs c1..cN, N >= 16");
                    yield withPayloadCentreFree(complianceVarying(js.get(0) - 1, g, along, require(d, along.key + "_min", file),
                            require(d, along.key + "_max", file), n, true));
                }
                if (g.massesUnknown() && !share) {
                    if (n != 2 * g.massCount()) throw d.error(file, "parameters_si", "needs c1..c" + 2 * g.massCount() + " (two per mass)");
                    n = 2;
                } else if (n < 4) throw d.error(file, "parameters_si", "needs c1..cN, N >= 4");
                yield complianceVarying(js.get(0) - 1, g, along, require(d, along.key + "_min", file), require(d, along.key + "_max", file), n, share);
            }
            case ZERO_DRIFT -> {
                if (along != Along.TIME && along != Along.TEMPERATURE)
                    throw d.error(file, "parameters_si", "a joint zero drifts with time_s or temp_c");
                yield zeroDrift(js.get(0) - 1, along, require(d, along.key + "_min", file), require(d, along.key + "_max", file));
            }
            case THERMAL -> ps.containsKey("tau_s") ? thermalFromTime(ps.get("tau_s")) : thermal(require(d, "t0_c", file));
            case THERMAL_LINK -> {
                // the lags are kept; without the campaign's history each link is taken at the reading (in equilibrium)
                Effect plain = thermalLinks(model, require(d, "t0_c", file));
                double[] warm = null;
                if (ps.keySet().stream().anyMatch(key -> key.startsWith("warm_tau_s_"))) {
                    warm = new double[plain.links.length];
                    for (int col = 0; col < warm.length; col++) {
                        String key = "warm_tau_s_" + plain.linkName(plain.links[col]);
                        warm[col] = require(d, key, file);
                        if (!(warm[col] > 0) || Double.isInfinite(warm[col]))
                            throw d.error(file, "parameters_si." + key, "must be > 0, got " + warm[col]);
                    }
                }
                if (ps.keySet().stream().noneMatch(key -> key.startsWith("lag_s_"))) yield warm == null ? plain : withWarmUp(plain, warm);
                double[] taus = new double[plain.links.length];
                for (int col = 0; col < taus.length; col++) {
                    taus[col] = require(d, "lag_s_" + plain.linkName(plain.links[col]), file);
                    if (!(taus[col] >= 0)) throw d.error(file, "parameters_si.lag_s_"
                            + plain.linkName(plain.links[col]), "must be >= 0, got " + taus[col]);
                }
                Effect lagged = thermalLinks(model, plain.t0C, null, taus);
                yield warm == null ? lagged : withWarmUp(lagged, warm);
            }
            case DRIFT -> ps.containsKey("tau_s") ? driftWithTime() : driftWithTemperature(require(d, "t0_c", file));
        };
        List<String> names = e.parameterNames();
        double[] v = new double[names.size()];
        for (int i = 0; i < v.length; i++)
            // a two-joint error written before it had its Taylor terms or its changing scale has none, a base tilt before its slide none
            v[i] = (kind == Kind.PAIR && i >= PAIR_PRODUCTS || kind == Kind.BASE_TILT && names.get(i).equals("slide"))
                    && !d.parameters().containsKey(names.get(i)) ? 0
                    : require(d, names.get(i), file);
        return new Term(e, v);
    }

    /** The orders of a bearing's error motion in a file: those of its keys {@code prefix}N (N >= 1). */
    private static int[] bearingOrders(EffectDescription d, String prefix, String keys, String file) {
        java.util.TreeSet<Integer> hs = new java.util.TreeSet<>();
        for (String key : d.parameters().keySet())
            if (key.matches(prefix + "\\d+")) hs.add(Integer.parseInt(key.substring(prefix.length())));
        if (hs.isEmpty() || hs.first() < 1) throw d.error(file, "parameters_si", "needs " + keys + " (or another order >= 1)");
        return hs.stream().mapToInt(Integer::intValue).toArray();
    }

    /** The effect's one joint (0-based), which must be revolute (a bearing's error motion). */
    private static int revolute(EffectDescription d, KinematicModel model, String file) {
        int j = d.joints().get(0);
        if (model.isPrismatic(j - 1)) throw d.error(file, "joints", d.effect() + " needs a revolute joint, joint " + j + " is prismatic");
        return j - 1;
    }

    /**
     * An effect that needs the robot's masses in a file without {@code mass_model}: reported at the
     * effect (the field the file lacks has no place of its own), or as the field {@code mass_model}
     * for an effect made in code.
     */
    private static InputException needsMassModel(EffectDescription d, String file, String what) {
        return d.source() == null ? new InputException(file, 0, 0, "mass_model", what + " needs the robot's mass_model")
                : d.error(file, "", what + " needs the robot's mass_model, which the file does not have");
    }

    /** Each re-estimated mass's factor as {@code prefix + name} (a factor of 1 is left out). */
    private void putMassScales(Map<String, Double> p, String prefix) {
        for (int k = 0; k < massScales.length; k++) if (massScales[k] != 1) p.put(prefix + gravity.massName(k), massScales[k]);
    }

    /** The factors {@code prefix + name} of the file's masses, each > 0 (1 where absent); null when none is given. */
    private static double[] massScales(EffectDescription d, GravityTorques gravity, String prefix, String file) {
        double[] sc = new double[gravity.massCount()];
        boolean scaled = false;
        for (int k = 0; k < sc.length; k++) {
            String key = prefix + gravity.massName(k);
            sc[k] = d.parameters().containsKey(key) ? require(d, key, file) : 1;
            if (!(sc[k] > 0)) throw d.error(file, "parameters_si." + key, "must be > 0, got " + sc[k]);
            scaled |= d.parameters().containsKey(key);
        }
        return scaled ? sc : null;
    }

    private static double require(EffectDescription d, String key, String file) {
        Double v = d.parameters().get(key);
        if (v == null || !Double.isFinite(v))
            throw d.error(file, "parameters_si." + key, "missing or not a finite number");
        return v;
    }

    /** An effect with its parameter values. */
    public record Term(Effect effect, double[] values) {
        public Term { values = values.clone(); }
        @Override public double[] values() { return values.clone(); }
    }

    @Override public String toString() { return label(); }

    /**
     * The catalogue's candidates on a robot: the kinds for each joint (a coupling for every ordered
     * pair: one a drive train cannot make is searched but never claimed, {@link #canCouple}), thermal once.
     */
    public static List<Effect> candidates(KinematicModel model, GravityTorques gravity, double t0C, double[] timeTaus) {
        return candidates(model, gravity, t0C, timeTaus, null);
    }

    /**
     * As above; with {@code pauses} in the campaign, each time proxy of the warm-up also in the form
     * that cools while the robot rests (the arm warmed by its drives, not by the air).
     */
    public static List<Effect> candidates(KinematicModel model, GravityTorques gravity, double t0C, double[] timeTaus, Pauses pauses) {
        List<Effect> out = new ArrayList<>();
        int n = model.dof();
        for (int j = 0; j < n; j++) {
            if (gravity != null && !gravity.massesUnknown()) {
                out.add(compliance(j, gravity));
                out.add(complianceStiffening(j, gravity));
                if (atJointDiffers(model, j)) out.add(complianceAtJoint(j, gravity, false));
            }
            out.add(periodic(j));
            out.add(backlash(j));
            out.add(scale(j));
        }
        for (int k = 0; k < n; k++)
            for (int j = 0; j < n; j++) if (j != k) out.add(coupling(k, j));
        if (!Double.isNaN(t0C)) out.add(thermal(t0C));
        if (timeTaus != null) for (double t : timeTaus) out.add(thermalFromTime(t));
        if (timeTaus != null && pauses != null && pauses.any()) for (double t : timeTaus) out.add(thermalFromTime(t, pauses));
        return out;
    }
}
