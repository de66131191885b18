package org.robopro.calibration.diagnosis;

import java.util.ArrayList;
import java.util.List;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.JointType;
import org.robopro.models.LinkMass;
import org.robopro.models.MassModel;
import org.robopro.models.Vec3;

/**
 * Gravity torque about every joint axis from a robot's mass model (links plus a payload at the
 * flange): τ_j = Σ_{k downstream of j} ((c_k − o_j) × m_k g) · z_j, with o_j, z_j a point on and
 * the direction of joint axis j and c_k the centre of mass of link k, all at the pose q
 * ({@link KinematicModel#linkFrames}). This is −∂V/∂θ_j of the potential V = −Σ m_k g·c_k; a
 * prismatic joint gets the force m g · z_j instead. Immutable and thread-safe.
 */
public final class GravityTorques {
    private final KinematicModel model;
    private final int[] frameIndex; // frame a mass rides on (1..dof = link of joint k, dof+1 = flange)
    private final double[] mass;
    private final Vec3[] local;     // centre of mass in that frame
    private final Vec3 gravity;
    private final int payloadSlot;  // index of the payload entry (mass set per pose)
    private final String[] names;   // the unknown-mass form's column names; null for a file's mass model
    private final String[] massNames; // masses estimated from the link lengths ({@link #fromLengths}): their names; null otherwise

    /** Links (1-based frames) whose unknown first moments stand for the arm's weight when the file has no mass model. */
    static final int UNKNOWN_MASS_LINKS = 3;
    /** Lever of the unit point masses that span a link's first moments, m. */
    static final double UNKNOWN_MASS_LEVER_M = 0.5;

    private GravityTorques(KinematicModel model, int[] frameIndex, double[] mass, Vec3[] local, Vec3 gravity, int payloadSlot,
                           String[] names, String[] massNames) {
        this.massNames = massNames;
        this.model = model;
        this.frameIndex = frameIndex;
        this.mass = mass;
        this.local = local;
        this.gravity = gravity;
        this.payloadSlot = payloadSlot;
        this.names = names;
    }

    /** The robot file's mass model, or, without one, {@link #massesUnknown(KinematicModel)}. */
    public static GravityTorques of(KinematicModel model, org.robopro.models.RobotDescription robot) {
        return robot.massModel().map(mm -> new GravityTorques(model, mm)).orElseGet(() -> massesUnknown(model));
    }

    /**
     * Gravity torques of an arm whose masses are not known (a robot file without a mass model): the
     * payload at the flange (its mass given per pose), and for each of links 1..3 four unit point
     * masses, at the link frame's origin and {@link #UNKNOWN_MASS_LEVER_M} along each of its axes.
     * A link's weight torque, −g·(m (p + R c) − o) × z, is linear in its mass m and first moments
     * m·c, so these four span every mass and centre the link can have; the wrist's masses are
     * taken at the wrist centre, which rides on link 3 (a spherical wrist). Only with the masses
     * re-estimated (one coefficient each) does this mean anything, and only the payload's
     * coefficient is a compliance: the arm's own weight alone cannot separate a compliance from
     * the unknown masses.
     */
    public static GravityTorques massesUnknown(KinematicModel model) {
        int n = model.dof(), links = Math.min(UNKNOWN_MASS_LINKS, n);
        int count = 4 * links + 1;
        int[] fi = new int[count];
        double[] m = new double[count];
        Vec3[] loc = new Vec3[count];
        String[] names = new String[count];
        // the payload first: its coefficient is the compliance itself, and is kept before any of the arm's columns
        fi[0] = n + 1;
        loc[0] = Vec3.ZERO;
        names[0] = "payload";
        String[] axis = {"o", "x", "y", "z"};
        Vec3[] offs = {Vec3.ZERO, new Vec3(UNKNOWN_MASS_LEVER_M, 0, 0), new Vec3(0, UNKNOWN_MASS_LEVER_M, 0), new Vec3(0, 0, UNKNOWN_MASS_LEVER_M)};
        for (int i = 1; i <= links; i++)
            for (int a = 0; a < 4; a++) {
                int k = 1 + 4 * (i - 1) + a;
                fi[k] = i;
                m[k] = 1;
                loc[k] = offs[a];
                names[k] = "link" + i + "_" + axis[a];
            }
        return new GravityTorques(model, fi, m, loc, new Vec3(0, 0, -9.80665), 0, names, null);
    }

    /** Whether the masses are unknown ({@link #massesUnknown(KinematicModel)}): only the payload's coefficient is a compliance. */
    public boolean massesUnknown() { return names != null; }

    /** Index of the payload among the masses. */
    public int payloadIndex() { return payloadSlot; }

    public GravityTorques(KinematicModel model, MassModel masses) {
        this(model, masses, null);
    }

    /** Linear density of a link taken as a uniform beam when the masses are estimated from the lengths, kg/m. */
    static final double LINK_KG_PER_M = 50;
    /** Mass taken at the last joint's point for the wrist and hand when the masses are estimated from the lengths, kg. */
    static final double HAND_KG = 5;
    /** Distance either side of a beam's centre at which its two halves are put when the masses are estimated from the lengths, m. */
    static final double HALF_OFFSET_M = 0.1;

    /**
     * A rough mass model from the arm's geometry alone, for a robot file without one: each link a
     * uniform beam from its joint's point (the robot file's point on the axis) to the next joint's
     * (to the flange for the last), {@link #LINK_KG_PER_M} per metre, and {@link #HAND_KG} at the
     * last joint's point for the wrist and hand. A cast arm of an industrial robot weighs some tens
     * of kilograms per metre of reach. Each beam's weight is split in two halves {@link
     * #HALF_OFFSET_M} either side of its centre, across the beam in the plane the shoulder's pitch
     * axis (joint 2's) turns it in: re-estimating the halves' sizes ({@link #withMassScales}) moves
     * the link's centre off the line between its joints (a forearm's wrist motors sit behind the
     * elbow, an upper arm's casting bulges forward), which sets where each joint's gravity torque
     * changes sign. The torques stated are this model's, an estimate.
     */
    public static GravityTorques fromLengths(KinematicModel model) {
        var joints = model.description().joints();
        int n = joints.size();
        Vec3 pitch = n >= 2 ? joints.get(1).axis() : null;
        List<LinkMass> links = new ArrayList<>();
        for (int k = 0; k < n; k++) {
            Vec3 a = joints.get(k).point(), b = k + 1 < n ? joints.get(k + 1).point() : model.description().flange().origin();
            Vec3 along = b.minus(a);
            double len = along.norm();
            if (len < 0.01) continue;
            Vec3 mid = a.plus(b).times(0.5), across = pitch == null ? Vec3.ZERO : along.cross(pitch);
            double kg = LINK_KG_PER_M * len;
            if (across.norm() < 1e-6 * len) {
                links.add(new LinkMass(k + 1, "link" + (k + 1), kg, mid));
                continue;
            }
            Vec3 off = across.times(HALF_OFFSET_M / across.norm());
            links.add(new LinkMass(k + 1, "link" + (k + 1) + "_a", kg / 2, mid.plus(off)));
            links.add(new LinkMass(k + 1, "link" + (k + 1) + "_b", kg / 2, mid.minus(off)));
        }
        links.add(new LinkMass(n, "hand", HAND_KG, joints.get(n - 1).point()));
        return new GravityTorques(model, new MassModel(links, 0, Vec3.ZERO, null), links.stream().map(LinkMass::name).toArray(String[]::new));
    }

    /** Whether the masses are {@link #fromLengths(KinematicModel)}'s estimate, not a robot file's. */
    public boolean fromLengths() { return massNames != null; }

    private GravityTorques(KinematicModel model, MassModel masses, String[] lengthNames) {
        this.massNames = lengthNames == null ? null : java.util.Arrays.copyOf(lengthNames, lengthNames.length + 1);
        if (massNames != null) massNames[lengthNames.length] = "payload";
        this.names = null;
        this.model = model;
        int n = model.dof();
        Pose[] zero = model.linkFrames(new double[n]);
        List<Integer> fi = new ArrayList<>();
        List<Double> m = new ArrayList<>();
        List<Vec3> loc = new ArrayList<>();
        for (LinkMass l : masses.links()) {
            if (l.joint() < 1 || l.joint() > n)
                throw new IllegalArgumentException("mass of link " + l.joint() + " but the robot has " + n + " joints");
            fi.add(l.joint());
            m.add(l.massKg());
            loc.add(zero[l.joint()].inverse().apply(l.centreOfMass()));
        }
        payloadSlot = fi.size();
        fi.add(n + 1);
        m.add(0.0);
        loc.add(masses.payloadCentreOfMass() == null ? Vec3.ZERO : masses.payloadCentreOfMass());
        frameIndex = fi.stream().mapToInt(Integer::intValue).toArray();
        mass = m.stream().mapToDouble(Double::doubleValue).toArray();
        local = loc.toArray(new Vec3[0]);
        gravity = masses.gravity() == null ? new Vec3(0, 0, -9.80665) : masses.gravity();
    }

    public KinematicModel model() { return model; }

    /** Potential energy V = −Σ m_k g·c_k (J) at q with a payload (kg; NaN = 0); τ = −∂V/∂θ. */
    public double potentialEnergy(double[] q, double payloadKg) {
        Pose[] f = model.linkFrames(q);
        double v = 0;
        for (int k = 0; k < mass.length; k++) {
            double mk = k == payloadSlot ? (Double.isNaN(payloadKg) ? 0 : payloadKg) : mass[k];
            v -= mk * gravity.dot(f[frameIndex[k]].apply(local[k]));
        }
        return v;
    }

    /** Gravity torque (N·m; N for prismatic joints) about each joint at controller values q with a payload (kg; NaN = 0). */
    public double[] torques(double[] q, double payloadKg) {
        int n = model.dof();
        Pose[] f = model.linkFrames(q);
        Vec3[] c = new Vec3[mass.length];
        double[] m = mass.clone();
        m[payloadSlot] = Double.isNaN(payloadKg) ? 0 : payloadKg;
        for (int k = 0; k < c.length; k++) c[k] = f[frameIndex[k]].apply(local[k]);
        double[] tau = new double[n];
        for (int j = 0; j < n; j++) {
            Vec3 o = f[j + 1].position(), z = f[j + 1].zAxis();
            boolean prismatic = model.description().joints().get(j).type() == JointType.PRISMATIC;
            double s = 0;
            for (int k = 0; k < c.length; k++) {
                if (frameIndex[k] < j + 1 || m[k] == 0) continue; // upstream of joint j
                Vec3 force = gravity.times(m[k]);
                s += prismatic ? force.dot(z) : c[k].minus(o).cross(force).dot(z);
            }
            tau[j] = s;
        }
        return tau;
    }

    /**
     * Gravity torque on each drive: τ_q = Cᵀ τ_θ with C the coupling (θ = C q), by virtual work
     * (δW = τ_θ·δθ = τ_θ·C δq), the torque a drive's gear and its stiffness see.
     */
    public double[] driveTorques(double[] q, double payloadKg) {
        return toDrive(torques(q, payloadKg));
    }

    private double[] toDrive(double[] tauTheta) {
        double[][] c = model.couplingMatrix();
        int n = tauTheta.length;
        double[] out = new double[n];
        for (int j = 0; j < n; j++) for (int i = 0; i < n; i++) out[j] += c[i][j] * tauTheta[i];
        return out;
    }

    /**
     * The same arm with mass k scaled by {@code scale[k]} (centres unchanged; the payload stays as
     * given per pose): the file's masses re-estimated by a factor each.
     */
    public GravityTorques withMassScales(double[] scale) {
        if (scale.length != mass.length) throw new IllegalArgumentException(mass.length + " scales needed, got " + scale.length);
        double[] m = mass.clone();
        for (int k = 0; k < m.length; k++) if (k != payloadSlot) m[k] *= scale[k];
        return new GravityTorques(model, frameIndex, m, local, gravity, payloadSlot, names, massNames);
    }

    /** The number of masses (the file's links, then the payload). */
    public int massCount() { return mass.length; }

    /** Name of mass k: "link3" (the mass the file puts on joint 3's link), "payload"; {@link #fromLengths}'s as it names them ("link2_a", "hand"). */
    public String massName(int k) {
        return names != null ? names[k] : massNames != null ? massNames[k] : k == payloadSlot ? "payload" : "link" + frameIndex[k];
    }

    /** The file's value of mass k, kg (0 for the payload, which is given per pose). */
    public double massKg(int k) { return mass[k]; }

    /** Drive {@code joint}'s gravity torque split by mass: out[k] = the torque of mass k alone (file mass, payload as given). */
    public void driveTorquesByMass(double[] q, double payloadKg, int joint, double[] out) {
        torquesByMass(q, payloadKg, joint, false, out);
    }

    /** Joint {@code joint}'s gravity torque about its own axis ({@link #torques}) split by mass, as {@link #driveTorquesByMass}. */
    public void jointTorquesByMass(double[] q, double payloadKg, int joint, double[] out) {
        torquesByMass(q, payloadKg, joint, true, out);
    }

    private void torquesByMass(double[] q, double payloadKg, int joint, boolean atJoint, double[] out) {
        Pose[] f = model.linkFrames(q);
        double[] m = mass.clone();
        m[payloadSlot] = Double.isNaN(payloadKg) ? 0 : payloadKg;
        for (int k = 0; k < mass.length; k++) out[k] = pointTorque(f, f[frameIndex[k]].apply(local[k]), m[k], frameIndex[k], joint, atJoint);
    }

    /** Lever (m) of the payload's centre shifts in {@link #payloadDriveTorques}: a centre 0.1 m off along a flange axis is one unit. */
    static final double PAYLOAD_SHIFT_M = 0.1;

    /**
     * Drive {@code joint}'s torque of the payload ({@code payloadKg}) at its centre, out[0], and how it
     * changes with that centre moved by {@link #PAYLOAD_SHIFT_M} along the x, y and z axes of the frame
     * it rides on (the flange), out[1..3]. The torque is linear in the centre's place, so out[0] + Σ
     * (d_k / PAYLOAD_SHIFT_M)·out[k] is the torque of the payload at its centre moved by d: the
     * payload's centre can be estimated with the compliance that multiplies it.
     */
    public void payloadDriveTorques(double[] q, double payloadKg, int joint, double[] out) {
        double m = Double.isNaN(payloadKg) ? 0 : payloadKg;
        Pose[] f = model.linkFrames(q);
        Pose at = f[frameIndex[payloadSlot]];
        Vec3 c0 = local[payloadSlot];
        Vec3[] shifts = {Vec3.ZERO, new Vec3(PAYLOAD_SHIFT_M, 0, 0), new Vec3(0, PAYLOAD_SHIFT_M, 0), new Vec3(0, 0, PAYLOAD_SHIFT_M)};
        for (int s = 0; s < 4; s++) {
            double t = pointTorque(f, at.apply(c0.plus(shifts[s])), m, frameIndex[payloadSlot], joint, false);
            out[s] = s == 0 ? t : t - out[0];
        }
    }

    /**
     * Drive {@code joint}'s torque of a point mass m (kg) at {@code point} (base frame) riding on frame
     * {@code frame}, or with {@code atJoint} the torque about the joint's own axis (coupling aside).
     */
    private double pointTorque(Pose[] f, Vec3 point, double m, int frame, int joint, boolean atJoint) {
        int n = model.dof();
        double[][] cm = model.couplingMatrix();
        Vec3 force = gravity.times(m);
        double s = 0;
        for (int i = 0; i < n; i++) {
            double w = atJoint ? (i == joint ? 1 : 0) : cm[i][joint];
            if (w == 0 || frame < i + 1 || m == 0) continue;
            Vec3 o = f[i + 1].position(), z = f[i + 1].zAxis();
            boolean prismatic = model.description().joints().get(i).type() == JointType.PRISMATIC;
            s += w * (prismatic ? force.dot(z) : point.minus(o).cross(force).dot(z));
        }
        return s;
    }

    /**
     * The moment of the arm's weight and the payload about the base origin, M = Σ c_k × m_k g (N·m,
     * base frame): what the foundation and its bolts must hold against (its horizontal part tips the
     * robot over an edge of its foot).
     */
    public Vec3 baseMoment(double[] q, double payloadKg) {
        Pose[] f = model.linkFrames(q);
        Vec3 sum = Vec3.ZERO;
        for (int k = 0; k < mass.length; k++) {
            double mk = k == payloadSlot ? (Double.isNaN(payloadKg) ? 0 : payloadKg) : mass[k];
            if (mk == 0) continue;
            sum = sum.plus(f[frameIndex[k]].apply(local[k]).cross(gravity.times(mk)));
        }
        return sum;
    }
}
