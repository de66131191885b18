package org.robopro.world;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.robopro.models.LinkMass;
import org.robopro.models.MassModel;
import org.robopro.models.RobotDescription;

/**
 * "The real robot": what a calibration campaign measures, with everything the robot file does
 * not know. From controller values q and the conditions of the moment to the pose of the measured
 * target in the instrument's frame:
 * <ol>
 * <li>each drive: q_out = q + zero offset + the sum of its {@link JointError}s (motor side);</li>
 * <li>coupling as the controller applies it: theta = C q_out, with the robot's true C;</li>
 * <li>joint elasticity: the gravity torques of the true masses (and payload) on the model angles,
 *     tau_theta, reach the drives as tau_q = C^T tau_theta (virtual work), each drive yields
 *     dq = tau_q / k, so theta += C dq;</li>
 * <li>each link grown by its own thermal strain, {@link Arm#grown}, and the target holder by its own;</li>
 * <li>product of exponentials to the flange, then the tool (measured target);</li>
 * <li>an optional position-dependent error of the measured point ({@link Sag});</li>
 * <li>the measured target may be knocked on the flange mid-campaign ({@link ToolBump});</li>
 * <li>the instrument's frame, which may drift with temperature and time.</li>
 * </ol>
 * Noise is added by the campaign, not here. SI units, angles rad. Immutable.
 *
 * @param robotName          the robot file's name
 * @param arm                true geometry
 * @param coupling           true coupling matrix C (theta = C q)
 * @param zeroOffsets        per drive, rad (or m)
 * @param errors             drive errors
 * @param flangeToTool       the measured target (and its frame, for 6-D) in flange coordinates
 * @param instrumentFromBase x_instrument = T x_base (identity when the instrument measures in base)
 * @param thermal            thermal growth and instrument drift, or null
 * @param compliance         joint elasticity, or null
 * @param sag                position-dependent error of the measured point, or null
 * @param toolBump           the measured target knocked to another place on the flange during the campaign, or null
 */
public record WorldRobot(String robotName, Arm arm, double[][] coupling, double[] zeroOffsets, List<JointError> errors,
                         Rigid flangeToTool, Rigid instrumentFromBase, Thermal thermal, Compliance compliance, Sag sag,
                         ToolBump toolBump) {
    public WorldRobot {
        coupling = copy(coupling);
        zeroOffsets = zeroOffsets.clone();
        errors = List.copyOf(errors);
    }

    @Override public double[][] coupling() { return copy(coupling); }

    @Override public double[] zeroOffsets() { return zeroOffsets.clone(); }

    /**
     * Thermal growth: the structure's temperature is the recorded one; link i (pedestal = 0, last
     * link to the flange = n) grows by alpha_i (T - refC) (linear expansion, e.g. steel about
     * 11.5e-6/K, aluminium cast about 23e-6/K: CRC Handbook of Chemistry and Physics, "Thermal
     * expansion of metals"); the target holder, the part bolted to the flange that carries the
     * measured target, grows by holderAlpha (T - refC) along the flange-to-target offset; the
     * instrument's view of the base drifts by driftPerK (T - refC) + driftPerS t (a tracker on a
     * stand on a warming floor), in instrument coordinates.
     */
    public record Thermal(double refC, double[] linkAlpha, double[] driftPerK, double[] driftPerS, double holderAlpha) {
        public Thermal {
            linkAlpha = linkAlpha.clone();
            driftPerK = driftPerK.clone();
            driftPerS = driftPerS.clone();
        }

        /** Links and instrument only: the target holder does not grow. */
        public Thermal(double refC, double[] linkAlpha, double[] driftPerK, double[] driftPerS) {
            this(refC, linkAlpha, driftPerK, driftPerS, 0);
        }

        /**
         * An aluminium target holder: 23·10⁻⁶/K, the linear expansion of aluminium near room
         * temperature (23.1·10⁻⁶/K at 25 °C: CRC Handbook of Chemistry and Physics, "Thermal
         * expansion of metals"; laser-tracker reflector nests and adapter plates are commonly
         * machined from aluminium alloy).
         */
        public static final double ALUMINIUM_HOLDER_ALPHA = 23e-6;

        /** The same growth with the target holder growing by {@code alpha} per kelvin. */
        public Thermal withHolderAlpha(double alpha) { return new Thermal(refC, linkAlpha, driftPerK, driftPerS, alpha); }

        @Override public double[] linkAlpha() { return linkAlpha.clone(); }
        @Override public double[] driftPerK() { return driftPerK.clone(); }
        @Override public double[] driftPerS() { return driftPerS.clone(); }
    }

    /** A point mass carried by the link of {@code joint} (0-based), centre at zero position, base coordinates (m). */
    public record Mass(int joint, double kg, double[] centre) {
        public Mass { centre = centre.clone(); }

        @Override public double[] centre() { return centre.clone(); }
    }

    /**
     * Joint elasticity: each drive's stiffness k (N·m/rad, infinite: rigid), the true link masses,
     * the payload's centre of mass in flange coordinates and gravity (m/s^2, base coordinates).
     */
    public record Compliance(double[] stiffness, List<Mass> masses, double[] payloadCentre, double[] gravity) {
        public Compliance {
            stiffness = stiffness.clone();
            masses = List.copyOf(masses);
            payloadCentre = payloadCentre.clone();
            gravity = gravity.clone();
        }

        @Override public double[] stiffness() { return stiffness.clone(); }
        @Override public double[] payloadCentre() { return payloadCentre.clone(); }
        @Override public double[] gravity() { return gravity.clone(); }

        /**
         * The true masses of a robot file's mass model, each off by a factor drawn uniformly in
         * 1 ± maxError (a data sheet's masses are rarely better than ±30 %), and its centre moved by
         * N(0, 20 mm); stiffness infinite except where given.
         */
        public static Compliance fromFile(MassModel m, int dof, double maxError, Random rng) {
            List<Mass> ms = new ArrayList<>();
            for (LinkMass l : m.links()) {
                double f = 1 + maxError * (2 * rng.nextDouble() - 1);
                ms.add(new Mass(l.joint() - 1, l.massKg() * f, Rigid.plus(l.centreOfMass().toArray(), Arm.gauss(rng, 0.02))));
            }
            double[] k = new double[dof];
            java.util.Arrays.fill(k, Double.POSITIVE_INFINITY);
            double[] g = m.gravity() != null ? m.gravity().toArray() : new double[] {0, 0, -9.80665};
            double[] pc = m.payloadCentreOfMass() != null ? m.payloadCentreOfMass().toArray() : new double[3];
            return new Compliance(k, ms, pc, g);
        }

        public Compliance withStiffness(int joint, double k) {
            double[] s = stiffness.clone();
            s[joint] = k;
            return new Compliance(s, masses, payloadCentre, gravity);
        }
    }

    /**
     * Outside every catalogue family: the measured point sags with reach like the tip of a
     * cantilever under its own load (deflection grows with the cube of the length: Gere &amp;
     * Goodno, Mechanics of Materials, cantilever with end load, delta = P L^3 / 3EI):
     * dz = -size (r / refReach)^3 with r the point's distance from the first joint's axis line.
     */
    public record Sag(double sizeM, double refReachM, double perKgM) {
        /** A sag under the arm's own weight only. */
        public Sag(double sizeM, double refReachM) { this(sizeM, refReachM, 0); }

        /** The downward deflection, m, at reach r (m) carrying {@code payloadKg}: (size + perKg payload) (r / refReach)^3. */
        public double at(double reachM, double payloadKg) { return (sizeM + perKgM * payloadKg) * Math.pow(reachM / refReachM, 3); }
    }

    /**
     * The measured target knocked on the flange at {@code atS} seconds into the campaign (a
     * reflector nest bumped by a cable or a hand): from then on it sits {@code shiftM} (flange
     * coordinates) from where it was and is turned by the rotation vector {@code turnRad}.
     */
    public record ToolBump(double atS, double[] shiftM, double[] turnRad) {
        public ToolBump {
            shiftM = shiftM.clone();
            turnRad = turnRad.clone();
        }

        @Override public double[] shiftM() { return shiftM.clone(); }
        @Override public double[] turnRad() { return turnRad.clone(); }

        /** The flange-to-target transform after the bump. */
        Rigid apply(Rigid tool) {
            double a = Rigid.norm(turnRad);
            Rigid turn = a > 0 ? Rigid.rotation(Rigid.unit(turnRad), a, new double[3]) : Rigid.IDENTITY;
            return Rigid.translation(shiftM[0], shiftM[1], shiftM[2]).times(tool).times(turn);
        }
    }

    /** The nominal robot of a file, as the world sees it: no errors, instrument = base. */
    public static WorldRobot nominal(RobotDescription robot, double[] targetInFlangeM) {
        int n = robot.dof();
        return new WorldRobot(robot.name(), Arm.of(robot), robot.couplingMatrix(), new double[n], List.of(),
                Rigid.translation(targetInFlangeM[0], targetInFlangeM[1], targetInFlangeM[2]), Rigid.IDENTITY, null, null, null, null);
    }

    public int dof() { return zeroOffsets.length; }

    /** Whether the temperature changes what is measured (thermal growth, instrument drift with temperature, a drive's thermal error). */
    public boolean temperatureMatters() {
        return thermal != null || errors.stream().anyMatch(e -> e instanceof JointError.DriveThermal);
    }

    /**
     * The pose of the measured target in the instrument frame (origin = the measured point).
     *
     * @param q       controller values
     * @param dir     sign of each drive's last motion (+1/-1)
     * @param tempC   structure temperature, °C (ignored without thermal growth)
     * @param timeS   seconds since the campaign started
     * @param payload kg at the flange
     */
    public Rigid target(double[] q, int[] dir, double tempC, double timeS, double payload) {
        return target(q, dir, null, tempC, timeS, payload);
    }

    /**
     * {@link #target(double[], int[], double, double, double)} knowing each drive's last move
     * (signed, rad or m; null: every move was long).
     */
    public Rigid target(double[] q, int[] dir, double[] lastMove, double tempC, double timeS, double payload) {
        int n = dof();
        double[] qo = q.clone();
        for (int i = 0; i < n; i++) qo[i] += zeroOffsets[i];
        JointError.Moment moment = new JointError.Moment(dir, lastMove, timeS, tempC);
        for (JointError e : errors) qo[e.joint()] += e.delta(q, moment);
        double[] theta = times(coupling, qo);
        Arm a = arm;
        if (thermal != null && Double.isFinite(tempC)) {
            double[] strain = thermal.linkAlpha.clone();
            for (int i = 0; i < strain.length; i++) strain[i] *= tempC - thermal.refC;
            a = arm.grown(strain);
        }
        if (compliance != null) {
            double[] tau = gravityTorques(a, theta, payload);
            double[] tauQ = new double[n];
            for (int j = 0; j < n; j++) for (int i = 0; i < n; i++) tauQ[j] += coupling[i][j] * tau[i];
            double[] dq = new double[n];
            for (int j = 0; j < n; j++) dq[j] = tauQ[j] / compliance.stiffness[j];
            double[] dTheta = times(coupling, dq);
            for (int i = 0; i < n; i++) theta[i] += dTheta[i];
        }
        Rigid onFlange = toolBump != null && Double.isFinite(timeS) && timeS >= toolBump.atS() ? toolBump.apply(flangeToTool) : flangeToTool;
        if (thermal != null && thermal.holderAlpha != 0 && Double.isFinite(tempC))
            onFlange = new Rigid(onFlange.r(), Rigid.scale(onFlange.p(), 1 + thermal.holderAlpha * (tempC - thermal.refC)));
        Rigid tool = a.flange(theta).times(onFlange);
        if (sag != null) {
            double[] p = tool.p();
            double[] w = a.axes()[0], p0 = a.points()[0];
            double[] d = Rigid.minus(p, p0);
            double r = Rigid.norm(Rigid.minus(d, Rigid.scale(w, Rigid.dot(d, w))));
            p[2] -= sag.at(r, payload);
            tool = new Rigid(tool.r(), p);
        }
        Rigid inst = instrumentFromBase;
        if (thermal != null) {
            double[] drift = new double[3];
            for (int i = 0; i < 3; i++)
                drift[i] = (Double.isFinite(tempC) ? thermal.driftPerK[i] * (tempC - thermal.refC) : 0)
                        + (Double.isFinite(timeS) ? thermal.driftPerS[i] * timeS : 0);
            inst = new Rigid(inst.r(), Rigid.plus(inst.p(), drift));
        }
        return inst.times(tool);
    }

    /**
     * Gravity torque about each model joint axis at theta (N·m; force along the axis, N, for a
     * prismatic joint): tau_i = sum over the masses outboard of joint i of
     * w_i · ((c - p_i) × m g), with w_i, p_i the joint's current axis and point and c the mass's
     * current centre (the gravity vector of the Lagrangian equations, e.g. Siciliano et al.,
     * "Robotics: Modelling, Planning and Control", 2009, §7.1.3 and §7.2, written as moments).
     * It is the torque gravity puts on the joint; an elastic joint yields in its direction.
     */
    public double[] gravityTorques(Arm a, double[] theta, double payload) {
        int n = dof();
        Rigid[] body = a.bodies(theta);
        double[][] pts = a.points(), axes = a.axes();
        boolean[] prismatic = a.prismatic();
        List<Mass> all = new ArrayList<>(compliance.masses);
        if (payload > 0) {
            double[] c = a.flange().apply(compliance.payloadCentre); // flange coordinates -> zero-position base coordinates
            all.add(new Mass(n - 1, payload, c));
        }
        double[] tau = new double[n];
        for (int i = 0; i < n; i++) {
            Rigid before = i == 0 ? Rigid.IDENTITY : body[i - 1];
            double[] w = before.rotate(axes[i]), p = before.apply(pts[i]);
            for (Mass m : all) {
                if (m.joint < i) continue;
                double[] c = body[m.joint].apply(m.centre);
                double[] f = Rigid.scale(compliance.gravity, m.kg);
                tau[i] += prismatic[i] ? Rigid.dot(w, f) : Rigid.dot(w, Rigid.cross(Rigid.minus(c, p), f));
            }
        }
        return tau;
    }

    public WorldRobot withErrors(List<JointError> e) {
        return new WorldRobot(robotName, arm, coupling, zeroOffsets, e, flangeToTool, instrumentFromBase, thermal, compliance, sag, toolBump);
    }

    public WorldRobot withThermal(Thermal t) {
        return new WorldRobot(robotName, arm, coupling, zeroOffsets, errors, flangeToTool, instrumentFromBase, t, compliance, sag, toolBump);
    }

    public WorldRobot withCompliance(Compliance c) {
        return new WorldRobot(robotName, arm, coupling, zeroOffsets, errors, flangeToTool, instrumentFromBase, thermal, c, sag, toolBump);
    }

    public WorldRobot withSag(Sag s) {
        return new WorldRobot(robotName, arm, coupling, zeroOffsets, errors, flangeToTool, instrumentFromBase, thermal, compliance, s, toolBump);
    }

    public WorldRobot withToolBump(ToolBump b) {
        return new WorldRobot(robotName, arm, coupling, zeroOffsets, errors, flangeToTool, instrumentFromBase, thermal, compliance, sag, b);
    }

    /** The same robot with the measured target (and its frame) at {@code flangeToTool} in flange coordinates. */
    public WorldRobot withTool(Rigid flangeToTool) {
        return new WorldRobot(robotName, arm, coupling, zeroOffsets, errors, flangeToTool, instrumentFromBase, thermal, compliance, sag, toolBump);
    }

    public WorldRobot withInstrument(Rigid instrumentFromBase) {
        return new WorldRobot(robotName, arm, coupling, zeroOffsets, errors, flangeToTool, instrumentFromBase, thermal, compliance, sag, toolBump);
    }

    public WorldRobot withCoupling(double[][] c) {
        return new WorldRobot(robotName, arm, c, zeroOffsets, errors, flangeToTool, instrumentFromBase, thermal, compliance, sag, toolBump);
    }

    static double[] times(double[][] m, double[] v) {
        double[] out = new double[m.length];
        for (int i = 0; i < m.length; i++) for (int j = 0; j < v.length; j++) out[i] += m[i][j] * v[j];
        return out;
    }

    static double[][] copy(double[][] a) {
        double[][] out = new double[a.length][];
        for (int i = 0; i < a.length; i++) out[i] = a[i].clone();
        return out;
    }
}
