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

    public GravityTorques(KinematicModel model, MassModel masses) {
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

    /** The number of masses (the file's links, then the payload). */
    public int massCount() { return mass.length; }

    /** Name of mass k: "link3" (the mass the file puts on joint 3's link) or "payload". */
    public String massName(int k) { return k == payloadSlot ? "payload" : "link" + frameIndex[k]; }

    /** The file's value of mass k, kg (0 for the payload, which is given per pose). */
    public double massKg(int k) { return mass[k]; }

    /** Drive {@code joint}'s gravity torque split by mass: out[k] = the torque of mass k alone (file mass, payload as given). */
    public void driveTorquesByMass(double[] q, double payloadKg, int joint, double[] out) {
        int n = model.dof();
        Pose[] f = model.linkFrames(q);
        double[] m = mass.clone();
        m[payloadSlot] = Double.isNaN(payloadKg) ? 0 : payloadKg;
        double[][] cm = model.couplingMatrix();
        for (int k = 0; k < mass.length; k++) {
            Vec3 ck = f[frameIndex[k]].apply(local[k]);
            Vec3 force = gravity.times(m[k]);
            double s = 0;
            for (int i = 0; i < n; i++) {
                if (cm[i][joint] == 0 || frameIndex[k] < i + 1 || m[k] == 0) continue;
                Vec3 o = f[i + 1].position(), z = f[i + 1].zAxis();
                boolean prismatic = model.description().joints().get(i).type() == JointType.PRISMATIC;
                s += cm[i][joint] * (prismatic ? force.dot(z) : ck.minus(o).cross(force).dot(z));
            }
            out[k] = s;
        }
    }
}
