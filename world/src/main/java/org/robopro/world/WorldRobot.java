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
 * <li>the instrument's frame, which may drift with temperature and time;</li>
 * <li>the instrument's own reading errors ({@link Tracker}).</li>
 * </ol>
 * Besides: a joint's bearing may wobble ({@link Wobble}, in the chain), the wrist's drives may
 * yield to a dress pack's pull ({@link DressPack}, with the gravity yield), and the whole robot
 * may rock on its foundation ({@link Rocking}, about a foot edge, after the chain), and the upper
 * arm may twist about its long axis under the weights beyond it ({@link Twist}, after the chain).
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
 * @param tracker            the laser tracker's own reading errors (distance meter, angle encoders), or null
 * @param rocking            the base rocking on its foundation above an overturning moment, or null
 * @param dressPack          the dress pack (cable hose) pulling on the wrist, or null
 * @param wobbles            bearing wobbles: joint axes tilting about a direction that turns with the joint
 * @param floorTilt          the floor under the robot tilting as it warms, or null
 * @param twist              the upper arm twisting under the weights beyond it, or null
 * @param targetPlay         the measured target shifting within its nest's clearance toward gravity, or null
 * @param knock              the instrument knocked (or the base slipping) once during the campaign, or null
 * @param dispensing         what the flange really carries over the campaign, whatever the file records, or null
 * @param refraction         the air's temperature gradient bending the instrument's beam, or null
 * @param retractor          a cable retractor pulling the tool toward a fixed anchor, or null
 * @param shaftTilt          a drive's output shaft tilting under its gear mesh's forces, or null
 * @param network            a second instrument station reading the poses whose target faces it better, or null
 * @param machine            the instrument a measuring machine whose axes are out of square and whose x-way is bowed, or null
 */
public record WorldRobot(String robotName, Arm arm, double[][] coupling, double[] zeroOffsets, List<JointError> errors,
                         Rigid flangeToTool, Rigid instrumentFromBase, Thermal thermal, Compliance compliance, Sag sag,
                         ToolBump toolBump, Tracker tracker, Rocking rocking, DressPack dressPack, List<Wobble> wobbles,
                         FloorTilt floorTilt, Twist twist, TargetPlay targetPlay, Knock knock, Dispensing dispensing,
                         Refraction refraction, Retractor retractor, ShaftTilt shaftTilt, Network network, Machine machine) {
    /** A world robot whose carried mass is as recorded and whose instrument sees through still air. */
    public WorldRobot(String robotName, Arm arm, double[][] coupling, double[] zeroOffsets, List<JointError> errors,
                      Rigid flangeToTool, Rigid instrumentFromBase, Thermal thermal, Compliance compliance, Sag sag,
                      ToolBump toolBump, Tracker tracker, Rocking rocking, DressPack dressPack, List<Wobble> wobbles,
                      FloorTilt floorTilt, Twist twist, TargetPlay targetPlay, Knock knock) {
        this(robotName, arm, coupling, zeroOffsets, errors, flangeToTool, instrumentFromBase, thermal, compliance, sag, toolBump, tracker,
                rocking, dressPack, wobbles, floorTilt, twist, targetPlay, knock, null, null, null, null, null, null);
    }

    /** A world robot whose instrument is never knocked. */
    public WorldRobot(String robotName, Arm arm, double[][] coupling, double[] zeroOffsets, List<JointError> errors,
                      Rigid flangeToTool, Rigid instrumentFromBase, Thermal thermal, Compliance compliance, Sag sag,
                      ToolBump toolBump, Tracker tracker, Rocking rocking, DressPack dressPack, List<Wobble> wobbles,
                      FloorTilt floorTilt, Twist twist, TargetPlay targetPlay) {
        this(robotName, arm, coupling, zeroOffsets, errors, flangeToTool, instrumentFromBase, thermal, compliance, sag, toolBump, tracker,
                rocking, dressPack, wobbles, floorTilt, twist, targetPlay, null);
    }

    public WorldRobot {
        coupling = copy(coupling);
        zeroOffsets = zeroOffsets.clone();
        errors = List.copyOf(errors);
        wobbles = wobbles == null ? List.of() : List.copyOf(wobbles);
    }

    /** A robot without tracker errors, rocking, dress pack or bearing wobble. */
    public WorldRobot(String robotName, Arm arm, double[][] coupling, double[] zeroOffsets, List<JointError> errors,
                      Rigid flangeToTool, Rigid instrumentFromBase, Thermal thermal, Compliance compliance, Sag sag, ToolBump toolBump) {
        this(robotName, arm, coupling, zeroOffsets, errors, flangeToTool, instrumentFromBase, thermal, compliance, sag, toolBump,
                null, null, null, List.of(), null, null, null);
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
     * A drive may stiffen with its load ({@code hardening}, rad; infinite: a linear spring): a
     * cubic-hardening spring tau = k dq (1 + (dq/dh)^2), whose tangent stiffness k (1 + 3 (dq/dh)^2)
     * rises with the deflection. Reducers stiffen so: the torque-torsion curves of strain-wave
     * (Harmonic Drive) and cycloidal (RV) gears are catalogued as stiffnesses K1 &lt; K2 &lt; K3 over
     * rising torque ranges (e.g. Harmonic Drive AG, CSG/CSD catalogues, "Torsional stiffness"), and
     * Tuttle &amp; Seering, "A nonlinear model of a harmonic drive gear transmission", IEEE Trans.
     * Robotics and Automation 12 (1996) 368-374, measured a stiffness that grows with the torque;
     * the cubic is a smooth form of those piecewise curves.
     */
    public record Compliance(double[] stiffness, List<Mass> masses, double[] payloadCentre, double[] gravity, double[] hardening,
                             boolean springsInJoints) {
        public Compliance {
            stiffness = stiffness.clone();
            masses = List.copyOf(masses);
            payloadCentre = payloadCentre.clone();
            gravity = gravity.clone();
            if (hardening == null) {
                hardening = new double[stiffness.length];
                java.util.Arrays.fill(hardening, Double.POSITIVE_INFINITY);
            } else {
                hardening = hardening.clone();
            }
        }

        /** Linear springs. */
        public Compliance(double[] stiffness, List<Mass> masses, double[] payloadCentre, double[] gravity) {
            this(stiffness, masses, payloadCentre, gravity, null);
        }

        /** Springs in the drives' gears. */
        public Compliance(double[] stiffness, List<Mass> masses, double[] payloadCentre, double[] gravity, double[] hardening) {
            this(stiffness, masses, payloadCentre, gravity, hardening, false);
        }

        /**
         * The same springs in the joints themselves: joint i's own angle gives by the gravity torque
         * about its axis over its stiffness, Δθ_i = τ_θ,i / k_i, whatever drives it (a serial chain's
         * joint stiffness; on a parallel arm the forearm turns with the upper arm's give).
         */
        public Compliance inJoints() {
            return new Compliance(stiffness, masses, payloadCentre, gravity, hardening, true);
        }

        @Override public double[] stiffness() { return stiffness.clone(); }
        @Override public double[] payloadCentre() { return payloadCentre.clone(); }
        @Override public double[] gravity() { return gravity.clone(); }
        @Override public double[] hardening() { return hardening.clone(); }

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
            return new Compliance(s, masses, payloadCentre, gravity, hardening, springsInJoints);
        }

        /** The same with drive {@code joint} a cubic-hardening spring (its tangent stiffness doubles at dq = dh / sqrt(3)). */
        public Compliance withHardening(int joint, double dhRad) {
            double[] h = hardening.clone();
            h[joint] = dhRad;
            return new Compliance(stiffness, masses, payloadCentre, gravity, h, springsInJoints);
        }

        /**
         * The deflection of drive {@code joint} under torque tau: tau / k for a linear spring; for a
         * hardening one the real root of k dq + (k / dh^2) dq^3 = tau (Cardano: the cubic
         * dq^3 + p dq - r = 0 with p = dh^2 &gt; 0 has one real root).
         */
        public double deflection(int joint, double tau) {
            double k = stiffness[joint], dh = hardening[joint];
            if (Double.isInfinite(k)) return 0;
            if (Double.isInfinite(dh)) return tau / k;
            double p = dh * dh, r = tau * dh * dh / k;
            double d = Math.sqrt(r * r / 4 + p * p * p / 27);
            return Math.cbrt(r / 2 + d) + Math.cbrt(r / 2 - d);
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
    /**
     * The measured target (a reflector's ball) sitting in a nest with a radial clearance: the ball
     * rolls to the low side of the clearance, by {@code clearanceM} toward the part of gravity across
     * the tool's axis (flange z) once the axis leans more than the friction angle {@code frictionRad}
     * (tan φ = μ: Coulomb, the ball rolls when the slope beats the friction), and in proportion below
     * it (the ball resting part of the way, where the last lean left it being unknown).
     * <p>
     * With {@code tiltRad} the mount itself also gives: a flange on a worn bearing pair (radial
     * clearance c over a span s tips it by up to c/s; Harris &amp; Kotzalas, Rolling Bearing
     * Analysis, misalignment of shaft-bearing systems) tips by {@code tiltRad} in the same
     * proportion, about the point {@code pivotM} inside the flange on its axis, so that the tool's
     * axis turns toward gravity.
     */
    public record TargetPlay(double clearanceM, double frictionRad, double tiltRad, double pivotM) {
        /** A ball rolling in its nest, the mount rigid. */
        public TargetPlay(double clearanceM, double frictionRad) { this(clearanceM, frictionRad, 0, 0); }

        /** The share (0..1) of the play taken up, times the unit direction across the tool's axis; null when straight along it. */
        private double[] takeUp(double[] gFlange) {
            double across = Math.hypot(gFlange[0], gFlange[1]), hold = Math.sin(frictionRad);
            if (across == 0) return null;
            double f = Math.min(1, across / hold) / across;
            return new double[] {f * gFlange[0], f * gFlange[1]};
        }

        /** The ball's shift in flange coordinates for gravity {@code gFlange} (unit) seen from the flange. */
        public double[] shift(double[] gFlange) {
            double[] u = takeUp(gFlange);
            return u == null ? new double[3] : new double[] {clearanceM * u[0], clearanceM * u[1], 0};
        }

        /**
         * The mount's tip as a rigid motion in flange coordinates: a turn by tiltRad·|u| about
         * z × u (which brings the tool's axis z toward u), about the point (0, 0, −pivotM).
         */
        public Rigid tip(double[] gFlange) {
            double[] u = takeUp(gFlange);
            if (u == null) return Rigid.IDENTITY;
            double share = Math.hypot(u[0], u[1]);
            if (tiltRad == 0 || share == 0) return Rigid.IDENTITY;
            // Rodrigues: the turn about n = z × û takes z to z cos a + û sin a
            return Rigid.rotation(new double[] {-u[1] / share, u[0] / share, 0}, tiltRad * share, new double[] {0, 0, -pivotM});
        }
    }

    /**
     * The instrument knocked once during the campaign (a tracker's stand bumped by a cart or a
     * person, a tripod's foot slipping on the floor): from {@code atS} seconds on it stands
     * turned by the rotation vector {@code turnRad} about its own origin and shifted by
     * {@code shiftM} (base axes), and sees every point, and every measured frame, from there.
     */
    public record Knock(double atS, double[] shiftM, double[] turnRad) {
        public Knock {
            shiftM = shiftM.clone();
            turnRad = turnRad.clone();
        }

        @Override public double[] shiftM() { return shiftM.clone(); }
        @Override public double[] turnRad() { return turnRad.clone(); }

        /** The instrument's motion in base coordinates: the turn about its origin {@code o} (base), then the shift. */
        public Rigid motion(double[] o) {
            double a = Rigid.norm(turnRad);
            Rigid turn = a == 0 ? Rigid.IDENTITY : Rigid.rotation(Rigid.scale(turnRad, 1 / a), a, o);
            return Rigid.translation(shiftM[0], shiftM[1], shiftM[2]).times(turn);
        }
    }

    /**
     * The measured target moving on the flange during the campaign: knocked to another place at
     * {@code atS} (shift and turn, flange frame), and, where {@code spindle} is given, pushed along the
     * flange's axis by a tool that grows as its spindle runs and shrinks as it rests.
     */
    public record ToolBump(double atS, double[] shiftM, double[] turnRad, Spindle spindle) {
        public ToolBump {
            shiftM = shiftM.clone();
            turnRad = turnRad.clone();
        }

        /** A knock alone. */
        public ToolBump(double atS, double[] shiftM, double[] turnRad) { this(atS, shiftM, turnRad, null); }

        /** A spindle's growth alone (no knock). */
        public static ToolBump growing(Spindle spindle) { return new ToolBump(Double.POSITIVE_INFINITY, new double[3], new double[3], spindle); }

        /** The flange-to-target transform at {@code timeS} (NaN: the campaign's end state is not known, the tool cold and unknocked). */
        Rigid at(Rigid tool, double timeS) {
            Rigid t = Double.isFinite(timeS) && timeS >= atS ? apply(tool) : tool;
            if (spindle == null || !Double.isFinite(timeS)) return t;
            return Rigid.translation(0, 0, spindle.growthM(timeS)).times(t);
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

    /**
     * A spindle on the tool that runs from each {@code onS[i]} to {@code offS[i]} (s, in order): the
     * tool's length grows toward {@code peakM} while it runs and shrinks back while it rests, a body
     * heated at a constant rate and cooled to the air (Newton's law of cooling, lumped capacitance:
     * F. P. Incropera, D. P. DeWitt, "Fundamentals of Heat and Mass Transfer", §5.1–5.2), with time
     * constant {@code tauS}. A steel tool 200 mm long grows 2.3 µm per kelvin (11.5·10⁻⁶/K), so tens
     * of kelvin of spindle heat are tens of micrometres. The file records no spindle.
     */
    public record Spindle(double[] onS, double[] offS, double peakM, double tauS) {
        public Spindle {
            onS = onS.clone();
            offS = offS.clone();
        }

        /** The tool's growth at {@code timeS}, m: the exact first-order response to the on-off schedule from cold at 0 s. */
        public double growthM(double timeS) {
            double g = 0, t = 0;
            for (int i = 0; i < onS.length && t < timeS; i++) {
                double rest = Math.min(onS[i], timeS) - t;
                if (rest > 0) { g *= Math.exp(-rest / tauS); t += rest; }
                double run = Math.min(offS[i], timeS) - t;
                if (run > 0) { g = peakM + (g - peakM) * Math.exp(-run / tauS); t += run; }
            }
            if (timeS > t) g *= Math.exp(-(timeS - t) / tauS);
            return g;
        }

        @Override public double[] onS() { return onS.clone(); }
        @Override public double[] offS() { return offS.clone(); }
    }

    /**
     * The laser tracker's own reading errors, in its frame (x_instrument = instrumentFromBase x_base):
     * its standing axis is its own z, the azimuth az = atan2(y, x) is read about it, the elevation
     * el = atan2(z, sqrt(x^2 + y^2)) above its xy plane, the range rho = |x| from its gimbal point.
     * <ul>
     * <li>distance meter: rho' = rho (1 + rangeScale) + cyclic sin(2 pi rho / period + cyclicPhase).
     *     A phase-measuring distance meter's cyclic error repeats with half its fine modulation
     *     wavelength (crosstalk between the transmitter and the receiver adds a signal of fixed
     *     phase to the measured one): J. M. Rüeger, "Electronic Distance Measurement", 4th ed.,
     *     Springer 1996, the chapter on cyclic errors; the error is along the line of sight;</li>
     * <li>angle encoders: az' = az + sum azAmp_i sin(azK_i az + azPhase_i), el' likewise in el. An
     *     encoder disc mounted off its axis reads a once-per-turn error, a disc out of round a
     *     twice-per-turn one; the tracker's error models carry them as the first Fourier terms of
     *     each encoder (B. Muralikrishnan et al., "ASME B89.4.19 performance evaluation tests and
     *     geometric misalignments in laser trackers", J. Res. NIST 114 (2009) 21-35, encoder
     *     eccentricity parameters; "Laser trackers for large-scale dimensional metrology: a review",
     *     Precision Engineering 44 (2016) 13-28). The point moves tangentially by rho times the
     *     angle error.</li>
     * <li>air compensation: the distance meter counts wavelengths in air and turns them into a
     *     length with the air's refractive index, which it computes from its weather station; a
     *     station that lags the hall's air as the hall warms scales every distance by the index's
     *     error. The group index of air falls by about 0.93·10⁻⁶ per kelvin near 20 °C and 1013 hPa
     *     (Edlén's equation as revised by K. P. Birch and M. J. Downs, Metrologia 30 (1993) 155-162
     *     and 31 (1994) 315-316). Here the air the beam crosses warms by {@code airWarmK}
     *     (1 − exp(−t / {@code airTauS})) over the campaign while the station reads the start's, so
     *     the index it assumes is too high by 0.93·10⁻⁶ · that warming. The meter counts N = n D / λ₀
     *     wavelengths over a true distance D and reports N λ₀ / n_assumed = D n / n_assumed:
     *     rho' = rho (1 + rangeScale − 0.93·10⁻⁶ · that warming), the distance comes out short.</li>
     * <li>beam breaks: the interferometer counts only changes of the distance, so when the arm
     *     crosses the beam the count is lost; the tracker takes the distance again from its
     *     absolute distance meter, whose error at that moment (its accuracy, a few micrometres)
     *     then stays in every distance until the next break: rho' = rho + offset_i from break time
     *     {@code resetS[i]} on (B. Muralikrishnan et al., Precision Engineering 44 (2016) 13-28,
     *     the IFM and ADM; ASME B89.4.19-2006, ranging tests). Which moves break the beam is
     *     drawn, not worked out from the arm's shape.</li>
     * </ul>
     * Orientation (6-D) is read by other means and is left as it is. Angles rad, lengths m.
     */
    public record Tracker(double cyclicM, double periodM, double cyclicPhase, double rangeScale,
                          int[] azK, double[] azAmp, double[] azPhase, int[] elK, double[] elAmp, double[] elPhase,
                          double airWarmK, double airTauS, double[] resetS, double[] resetM, double[] cyclicOverM, double[] cyclicOverPhase) {
        /** The refractive index of air against its temperature near 20 °C and 1013 hPa, 1/K (Birch and Downs 1993). */
        public static final double INDEX_PER_K = -0.93e-6;

        /** A tracker whose air compensation holds (no warming of the air against its station). */
        public Tracker(double cyclicM, double periodM, double cyclicPhase, double rangeScale,
                       int[] azK, double[] azAmp, double[] azPhase, int[] elK, double[] elAmp, double[] elPhase) {
            this(cyclicM, periodM, cyclicPhase, rangeScale, azK, azAmp, azPhase, elK, elAmp, elPhase, 0, 1, new double[0], new double[0],
                    new double[0], new double[0]);
        }

        /** This tracker with the air the beam crosses warming by {@code warmK} with time constant {@code tauS} against its station. */
        public Tracker withAirWarming(double warmK, double tauS) {
            return new Tracker(cyclicM, periodM, cyclicPhase, rangeScale, azK, azAmp, azPhase, elK, elAmp, elPhase, warmK, tauS, resetS, resetM,
                    cyclicOverM, cyclicOverPhase);
        }

        /** This tracker with its distance taken again at beam breaks at {@code timesS} (ascending), each with its offset, m. */
        public Tracker withBeamBreaks(double[] timesS, double[] offsetsM) {
            return new Tracker(cyclicM, periodM, cyclicPhase, rangeScale, azK, azAmp, azPhase, elK, elAmp, elPhase, airWarmK, airTauS,
                    timesS, offsetsM, cyclicOverM, cyclicOverPhase);
        }

        /**
         * This tracker with its distance meter's cyclic error also at the overtones of its period:
         * {@code ampM[i]} sin(2π(i + 2)ρ/period + {@code phase[i]}). A meter that resolves the phase
         * on a fine and a coarse modulation, or whose crosstalk is detected non-linearly, repeats
         * its error at half, a third or a quarter of the fine period as well (Rüeger, Electronic
         * Distance Measurement, cyclic errors of the second and higher orders).
         */
        public Tracker withCyclicOvertones(double[] ampM, double[] phase) {
            return new Tracker(cyclicM, periodM, cyclicPhase, rangeScale, azK, azAmp, azPhase, elK, elAmp, elPhase, airWarmK, airTauS,
                    resetS, resetM, ampM, phase);
        }

        public Tracker {
            azK = azK.clone();
            azAmp = azAmp.clone();
            azPhase = azPhase.clone();
            elK = elK.clone();
            elAmp = elAmp.clone();
            elPhase = elPhase.clone();
            resetS = resetS.clone();
            resetM = resetM.clone();
            cyclicOverM = cyclicOverM.clone();
            cyclicOverPhase = cyclicOverPhase.clone();
            if (cyclicOverM.length != cyclicOverPhase.length) throw new IllegalArgumentException("overtone amplitudes and phases differ in length");
            if (resetS.length != resetM.length) throw new IllegalArgumentException("beam break times and offsets differ in length");
            for (int i = 1; i < resetS.length; i++)
                if (!(resetS[i] > resetS[i - 1])) throw new IllegalArgumentException("beam break times must ascend");
            if (azK.length != azAmp.length || azK.length != azPhase.length || elK.length != elAmp.length || elK.length != elPhase.length)
                throw new IllegalArgumentException("encoder harmonic arrays differ in length");
        }

        @Override public int[] azK() { return azK.clone(); }
        @Override public double[] azAmp() { return azAmp.clone(); }
        @Override public double[] azPhase() { return azPhase.clone(); }
        @Override public int[] elK() { return elK.clone(); }
        @Override public double[] elAmp() { return elAmp.clone(); }
        @Override public double[] elPhase() { return elPhase.clone(); }
        @Override public double[] resetS() { return resetS.clone(); }
        @Override public double[] resetM() { return resetM.clone(); }
        @Override public double[] cyclicOverM() { return cyclicOverM.clone(); }
        @Override public double[] cyclicOverPhase() { return cyclicOverPhase.clone(); }

        /** The absolute distance meter's offset in the distance at {@code timeS} (unknown: the start): that of the last beam break before it. */
        public double resetOffset(double timeS) {
            double at = Double.isFinite(timeS) ? timeS : 0, off = 0;
            for (int i = 0; i < resetS.length && resetS[i] <= at; i++) off = resetM[i];
            return off;
        }

        /** The range reading of a true range rho, m, with the air as the station reads it. */
        public double range(double rho) {
            double r = rho * (1 + rangeScale) + cyclicM * Math.sin(2 * Math.PI * rho / periodM + cyclicPhase);
            for (int i = 0; i < cyclicOverM.length; i++) r += cyclicOverM[i] * Math.sin(2 * Math.PI * (i + 2) * rho / periodM + cyclicOverPhase[i]);
            return r;
        }

        /**
         * The range reading of a true range rho at {@code timeS} (unknown: the station's air, and no
         * beam break yet): the index the station computes exceeds the true one by the warming times
         * |dn/dT|, so the wavelength in air it assumes is that much too short, and the distance, the
         * wavelengths counted times it, too; the offset of the last beam break adds to it.
         */
        public double range(double rho, double timeS) {
            double warm = Double.isFinite(timeS) && airWarmK != 0 ? airWarmK * (1 - Math.exp(-timeS / airTauS)) : 0;
            return range(rho) + rho * INDEX_PER_K * warm + resetOffset(timeS);
        }

        /** The azimuth reading of a true azimuth, rad. */
        public double azimuth(double az) { return az + series(azK, azAmp, azPhase, az); }

        /** The elevation reading of a true elevation, rad. */
        public double elevation(double el) { return el + series(elK, elAmp, elPhase, el); }

        /** The position the tracker reports for a true position x (its frame, m). */
        public double[] read(double[] x) { return read(x, Double.NaN); }

        /** The position the tracker reports for a true position x (its frame, m) at {@code timeS}. */
        public double[] read(double[] x, double timeS) {
            double h = Math.hypot(x[0], x[1]), rho = Rigid.norm(x);
            double az = azimuth(Math.atan2(x[1], x[0])), el = elevation(Math.atan2(x[2], h)), r = range(rho, timeS);
            return new double[] {r * Math.cos(el) * Math.cos(az), r * Math.cos(el) * Math.sin(az), r * Math.sin(el)};
        }

        private static double series(int[] k, double[] a, double[] ph, double x) {
            double s = 0;
            for (int i = 0; i < k.length; i++) s += a[i] * Math.sin(k[i] * x + ph[i]);
            return s;
        }
    }

    /**
     * The robot's base rocking on its foundation: the foot plate, a square of half-width
     * {@code halfWidthM} centred under the base origin in the plane z = −{@code footDepthM} (0: the
     * robot's own base plate; deeper: the foot of a rigid pedestal or riser the robot is bolted on)
     * with its edges along the base x and y axes, is held down by anchor bolts. The arm's weight (these masses, and the payload at
     * the flange) has a moment about each foot edge, M = e · sum (c - p_edge) × m g, with e the edge's
     * direction taken so that M &gt; 0 tips the robot over that edge (statics of a rigid body on a
     * support line: e.g. Meriam &amp; Kraige, "Engineering Mechanics: Statics", tipping about an edge).
     * Below {@code holdMomentNm} (the bolts' preload and the pedestal's own weight) the base stays down;
     * above it the plate lifts off the far side and the whole robot turns about the edge by
     * (M - hold) / stiffness (the bolts' stretch: a rotational spring). Of the four edges the one with
     * the largest excess acts. Gravity's change of direction in the tilted base is second order and left
     * out.
     */
    public record Rocking(double halfWidthM, double holdMomentNm, double stiffnessNmPerRad, List<Mass> masses, double[] payloadCentre,
                          double[] gravity, double footDepthM) {
        public Rocking {
            masses = List.copyOf(masses);
            payloadCentre = payloadCentre.clone();
            gravity = gravity.clone();
        }

        /** The robot's own base plate rocking (its foot in z = 0). */
        public Rocking(double halfWidthM, double holdMomentNm, double stiffnessNmPerRad, List<Mass> masses, double[] payloadCentre,
                       double[] gravity) {
            this(halfWidthM, holdMomentNm, stiffnessNmPerRad, masses, payloadCentre, gravity, 0);
        }

        /** A point of foot edge {@code e}: its outward normal times the half-width, at the foot's depth. */
        private double[] edgePoint(int e) {
            double[] p = Rigid.scale(NORMALS[e], halfWidthM);
            p[2] = -footDepthM;
            return p;
        }

        @Override public double[] payloadCentre() { return payloadCentre.clone(); }
        @Override public double[] gravity() { return gravity.clone(); }

        /** The foot edges' outward normals (base x, -x, y, -y). */
        static final double[][] NORMALS = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}};

        /** The overturning moment about each foot edge (N·m, positive: tips over it) with the masses' centres {@code centres} (base, m). */
        public double[] moments(List<double[]> centres, List<Double> kg) {
            double[] out = new double[4];
            for (int e = 0; e < 4; e++) {
                double[] n = NORMALS[e], p = edgePoint(e), axis = Rigid.cross(new double[] {0, 0, 1}, n);
                for (int i = 0; i < centres.size(); i++)
                    out[e] += Rigid.dot(axis, Rigid.cross(Rigid.minus(centres.get(i), p), Rigid.scale(gravity, kg.get(i))));
            }
            return out;
        }

        /** The base's turn (identity below the hold moment) for the edge moments {@code m}. */
        public Rigid tilt(double[] m) {
            int best = 0;
            for (int e = 1; e < 4; e++) if (m[e] > m[best]) best = e;
            if (!(m[best] > holdMomentNm)) return Rigid.IDENTITY;
            double[] n = NORMALS[best];
            return Rigid.rotation(Rigid.cross(new double[] {0, 0, 1}, n), (m[best] - holdMomentNm) / stiffnessNmPerRad, edgePoint(best));
        }
    }

    /**
     * A drive whose output shaft tilts under its gear mesh's forces: the last stage's tooth force τ/r
     * (τ the drive's torque, here its gravity torque; r the output gear's pitch radius) and the separating
     * force |τ| tan α / r (α the pressure angle) push the overhung gear across the axis, and the shaft turns
     * on its bearings by an angle proportional to each, about axes across the joint fixed in the housing
     * that holds the pinion (Budynas &amp; Nisbett, Shigley's Mechanical Engineering Design, §13-14 for the
     * forces, ch. 4 for the shaft's slope under them): ω = κ (τ d̂ + |τ| tan α n̂), d̂ and n̂ across the axis,
     * d̂ at {@code phase} in the zero position's frame, the turn about the bearing's centre, {@code offsetM}
     * along the axis from the arm's axis point.
     *
     * @param radPerNm the shaft's slope per N·m of the drive's torque, κ (rad/(N·m))
     */
    public record ShaftTilt(int joint, double radPerNm, double pressureAngle, double phase, double offsetM) {
        /** The tilt at drive torque tau (N·m) of the joint whose zero-position axis and point are given. */
        public Rigid tilt(double[] axis, double[] point, double tau) {
            double[] u = Wobble.perpendicular(axis), v = Rigid.cross(axis, u);
            double[] d = Rigid.plus(Rigid.scale(u, Math.cos(phase)), Rigid.scale(v, Math.sin(phase)));
            double[] nn = Rigid.cross(axis, d);
            double[] w = Rigid.plus(Rigid.scale(d, radPerNm * tau), Rigid.scale(nn, radPerNm * Math.abs(tau) * Math.tan(pressureAngle)));
            double angle = Rigid.norm(w);
            if (!(angle > 0)) return Rigid.IDENTITY;
            return Rigid.rotation(Rigid.unit(w), angle, Rigid.plus(point, Rigid.scale(axis, offsetM)));
        }
    }

    /**
     * Two instrument stations (two laser trackers, or one moved) in one network: a tracker reads a
     * reflector only within its acceptance angle, so each pose is read by the station its target faces
     * better, the one whose direction from the target makes the smaller angle with the target's axis (the
     * tool frame's z). The first station is the instrument; the second stands at {@code secondBase} (base
     * frame, m) and its registration into the first's frame is off by a small turn {@code omegaRad} about
     * the second station and a shift {@code shiftM} (both in the first's frame): its points land at
     * p + ω × (p − s₂) + δ and their frames turn by ω (a network's registration off by its residual;
     * Muralikrishnan et al., "Laser trackers for large-scale dimensional metrology: a review", Precision
     * Engineering 44 (2016) 13, on networks of trackers).
     */
    public record Network(double[] secondBase, double[] omegaRad, double[] shiftM) {
        public Network { secondBase = secondBase.clone(); omegaRad = omegaRad.clone(); shiftM = shiftM.clone(); }

        @Override public double[] secondBase() { return secondBase.clone(); }

        @Override public double[] omegaRad() { return omegaRad.clone(); }

        @Override public double[] shiftM() { return shiftM.clone(); }

        /** Whether the target at {@code tool} (base frame) is read from the second station, {@code inst} the first's instrumentFromBase. */
        boolean readsSecond(Rigid tool, Rigid inst) {
            double[] r = tool.r(), p = tool.p(), z = {r[2], r[5], r[8]};
            double[] to1 = Rigid.unit(Rigid.minus(inst.inverse().p(), p)), to2 = Rigid.unit(Rigid.minus(secondBase, p));
            return Rigid.dot(z, to2) > Rigid.dot(z, to1);
        }

        /** The reading {@code seen} (the first station's frame) as the misregistered second station gives it. */
        Rigid misregistered(Rigid seen, Rigid inst) {
            double angle = Rigid.norm(omegaRad);
            Rigid turn = angle > 0 ? Rigid.rotation(Rigid.unit(omegaRad), angle, inst.apply(secondBase)) : Rigid.IDENTITY;
            return Rigid.translation(shiftM[0], shiftM[1], shiftM[2]).times(turn).times(seen);
        }
    }

    /**
     * A cable retractor (a spring balancer or hose reel) hung from a boom beside the cell, its cable
     * hooked to the tool: it pulls the measured target with a steady force {@code forceN} toward the
     * fixed {@code anchor} (base frame, m), a spring reel's tension nearly the same over its travel.
     * Each model joint i feels the force's moment about its current axis line, τ_i = w_i · ((p − p_i)
     * × F) (a force at a point through the Jacobian transpose: Siciliano et al., "Robotics: Modelling,
     * Planning and Control", 2009, §3.8.2, written as moments about the axes), carried to the drives
     * by virtual work, τ_q = Cᵀ τ_θ, and drive j yields by τ_q,j / {@code stiffness[j]} (N·m/rad;
     * infinite: rigid), θ += C Δq.
     */
    public record Retractor(double[] anchor, double forceN, double[] stiffness) {
        public Retractor { anchor = anchor.clone(); stiffness = stiffness.clone(); }

        @Override public double[] anchor() { return anchor.clone(); }

        @Override public double[] stiffness() { return stiffness.clone(); }

        /** The pull's moment about each model joint's axis line (N·m; N along the axis for a prismatic joint), bodies at {@code body}, pulled at {@code at}. */
        double[] torques(Arm a, Rigid[] body, double[] at) {
            double[] d = Rigid.minus(anchor, at);
            double[] f = Rigid.scale(d, forceN / Rigid.norm(d));
            int n = a.dof();
            double[][] pts = a.points(), axes = a.axes();
            boolean[] prismatic = a.prismatic();
            double[] tau = new double[n];
            for (int i = 0; i < n; i++) {
                Rigid before = i == 0 ? Rigid.IDENTITY : body[i - 1];
                double[] w = before.rotate(axes[i]), p = before.apply(pts[i]);
                tau[i] = prismatic[i] ? Rigid.dot(w, f) : Rigid.dot(w, Rigid.cross(Rigid.minus(at, p), f));
            }
            return tau;
        }

        /** Drive j's yield under torque tau (rad). */
        double yieldOf(int j, double tau) { return Double.isInfinite(stiffness[j]) ? 0 : tau / stiffness[j]; }
    }

    /**
     * A dress pack (cable and hose package) on the wrist, held by a spring retractor on the forearm:
     * between its clamps on the forearm and on the tool the hose runs around the wrist at radius
     * {@code radiusM}; winding the wrist (u = theta4 + theta6: with joint 5 straight, joints 4 and 6
     * turn about one line and the hose twists by their sum) and bending it (theta5) draw hose out, a
     * path length s = r sqrt(u^2 + (bend (theta5 - bendCentre))^2). Up to the slack s0 = r slackRad the
     * hose hangs loose; beyond it the retractor's spring pulls with T = hoseStiffness (s - s0). By
     * virtual work (the hose's tension does work -T ds) each wrist joint feels tau_j = -T ds/dtheta_j
     * (e.g. Siciliano et al., "Robotics: Modelling, Planning and Control", 2009, §3.8.2, forces and
     * torques through a Jacobian transpose), which its drive yields to through its own stiffness,
     * as the gravity torques do: tau_q = C^T tau_theta, dq = tau_q / k, theta += C dq.
     *
     * @param wristStiffness drives 4, 5, 6 (N·m/rad)
     */
    public record DressPack(double radiusM, double slackRad, double bend, double bendCentreRad, double hoseStiffnessNPerM,
                            double[] wristStiffness) {
        public DressPack { wristStiffness = wristStiffness.clone(); }

        @Override public double[] wristStiffness() { return wristStiffness.clone(); }

        /** The hose's pull on model joints 4, 5, 6 (N·m) at the wrist's model angles. */
        public double[] torques(double t4, double t5, double t6) {
            double u = t4 + t6, v = bend * (t5 - bendCentreRad);
            double s = radiusM * Math.hypot(u, v), slack = radiusM * slackRad;
            if (!(s > slack)) return new double[3];
            double tension = hoseStiffnessNPerM * (s - slack);
            double r2s = radiusM * radiusM / s;
            return new double[] {-tension * r2s * u, -tension * r2s * v * bend, -tension * r2s * u};
        }
    }

    /**
     * A joint's bearing wobbling: its axis tilts by {@code tiltRad} about a direction perpendicular
     * to it that turns at {@code ratio} times the joint's angle, d = cos(ratio theta + phase) u +
     * sin(ratio theta + phase) v (u, v perpendicular to the axis, fixed to the link before the joint).
     * Everything outboard turns with the tilt about the axis point (the bearing's centre): an axis
     * tilt, not an angle error. Ratio 1 would be a tilt fixed to the rotor (geometry); 2, a bearing
     * seat out of round; about 0.4, the cage of a rolling bearing, which turns at the fundamental
     * train frequency (1/2)(1 - (d/D) cos alpha) of the shaft's speed (d the rolling elements'
     * diameter, D the pitch diameter, alpha the contact angle; d/D 0.2-0.25 gives 0.38-0.40: T. A.
     * Harris &amp; M. N. Kotzalas, "Rolling Bearing Analysis", 5th ed., 2007, Vol. 1, the kinematics of
     * rolling bearings), so a rolling element set with one large element or a cage out of round tilts
     * the axis at that ratio.
     */
    public record Wobble(int joint, double tiltRad, double ratio, double phase, double axialM, int lobes, double axialPhase) {
        /** A bearing that tilts only. */
        public Wobble(int joint, double tiltRad, double ratio, double phase) { this(joint, tiltRad, ratio, phase, 0, 0, 0); }

        /**
         * A bearing whose rotating race was ground with {@code lobes} lobes on its face (a three-jaw
         * chuck leaves three, a ring clamped out of round two): everything outboard rides up and down
         * along the axis by axialM·cos(lobes·θ + axialPhase) as the joint turns (the axial error motion
         * of ISO 230-7:2015), without a tilt.
         */
        public static Wobble axial(int joint, double axialM, int lobes, double axialPhase) {
            return new Wobble(joint, 0, 1, 0, axialM, lobes, axialPhase);
        }

        /** The transform of the tilt (and the axial shift) at model angle theta of the joint, given the arm's axis and point (zero position). */
        public Rigid tilt(double[] axis, double[] point, double theta) {
            double[] u = perpendicular(axis), v = Rigid.cross(axis, u);
            double a = ratio * theta + phase;
            double[] d = Rigid.plus(Rigid.scale(u, Math.cos(a)), Rigid.scale(v, Math.sin(a)));
            Rigid t = Rigid.rotation(Rigid.unit(d), tiltRad, point);
            if (axialM == 0) return t;
            double[] z = Rigid.scale(axis, axialM * Math.cos(lobes * theta + axialPhase));
            return Rigid.translation(z[0], z[1], z[2]).times(t);
        }

        /** A unit vector perpendicular to w: w × the base axis least along w, normalised. */
        static double[] perpendicular(double[] w) {
            double ax = Math.abs(w[0]), ay = Math.abs(w[1]), az = Math.abs(w[2]);
            double[] e = ax <= ay && ax <= az ? new double[] {1, 0, 0} : ay <= az ? new double[] {0, 1, 0} : new double[] {0, 0, 1};
            return Rigid.unit(Rigid.cross(w, e));
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

    /** The play (lost motion) of drive {@code joint} at controller values q, rad: the sum of its errors' plays. */
    public double playWidth(int joint, double[] q) {
        double w = 0;
        for (JointError e : errors) if (e.joint() == joint) w += e.playWidth(q);
        return w;
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
        return target(q, dir, null, lastMove, tempC, timeS, payload);
    }

    /**
     * {@link #target(double[], int[], double[], double, double, double)} knowing where each drive's
     * output rests within its play ({@link JointError.Moment#side}; null: on the flank of dir).
     */
    public Rigid target(double[] q, int[] dir, double[] side, double[] lastMove, double tempC, double timeS, double recordedPayload) {
        int n = dof();
        // what the flange really carries: the recorded mass, or a dispensing tool's at this time
        double payload = dispensing != null && Double.isFinite(timeS) ? dispensing.at(timeS) : recordedPayload;
        double[] qo = q.clone();
        for (int i = 0; i < n; i++) qo[i] += zeroOffsets[i];
        Arm a = arm;
        if (thermal != null && Double.isFinite(tempC)) {
            double[] strain = thermal.linkAlpha.clone();
            for (int i = 0; i < strain.length; i++) strain[i] *= tempC - thermal.refC;
            a = arm.grown(strain);
        }
        double[] driveTorque = null;
        if (errors.stream().anyMatch(JointError::needsTorque)) {
            if (compliance == null) throw new IllegalStateException("an error that follows the gravity torque needs the masses (a compliance)");
            driveTorque = driveSide(gravityTorques(a, times(coupling, qo), payload));
        }
        JointError.Moment moment = new JointError.Moment(dir, lastMove, timeS, tempC, driveTorque, side);
        for (JointError e : errors) qo[e.joint()] += e.delta(q, moment);
        double[] theta = times(coupling, qo);
        double[] hose = dressPack != null && n >= 6 ? dressPack.torques(theta[3], theta[4], theta[5]) : null;
        if (compliance != null && compliance.springsInJoints) {
            double[] tau = gravityTorques(a, theta, payload);
            for (int i = 0; i < n; i++) theta[i] += compliance.deflection(i, tau[i]);
        } else if (compliance != null) {
            double[] tauQ = driveSide(gravityTorques(a, theta, payload));
            double[] dq = new double[n];
            for (int j = 0; j < n; j++) dq[j] = compliance.deflection(j, tauQ[j]);
            double[] dTheta = times(coupling, dq);
            for (int i = 0; i < n; i++) theta[i] += dTheta[i];
        }
        if (hose != null) {
            double[] tau = new double[n];
            for (int j = 0; j < 3; j++) tau[3 + j] = hose[j];
            double[] tauQ = driveSide(tau);
            double[] dq = new double[n];
            for (int j = 0; j < 3; j++) dq[3 + j] = tauQ[3 + j] / dressPack.wristStiffness[j];
            double[] dTheta = times(coupling, dq);
            for (int i = 0; i < n; i++) theta[i] += dTheta[i];
        }
        if (retractor != null) {
            // the cable pulls at the measured target, at its place before the joints yield (a deflection of a few tenths of a
            // millimetre turns a pull from an anchor metres away by well under a milliradian)
            Rigid[] body = a.bodies(theta);
            double[] at = a.flange(theta).apply(flangeToTool.p());
            double[] tau = retractor.torques(a, body, at);
            double[] tauQ = driveSide(tau);
            double[] dq = new double[n];
            for (int j = 0; j < n; j++) dq[j] = retractor.yieldOf(j, tauQ[j]);
            double[] dTheta = times(coupling, dq);
            for (int i = 0; i < n; i++) theta[i] += dTheta[i];
        }
        Rigid onFlange = toolBump != null ? toolBump.at(flangeToTool, timeS) : flangeToTool;
        if (thermal != null && thermal.holderAlpha != 0 && Double.isFinite(tempC))
            onFlange = new Rigid(onFlange.r(), Rigid.scale(onFlange.p(), 1 + thermal.holderAlpha * (tempC - thermal.refC)));
        Rigid flangeNow;
        if (wobbles.isEmpty() && shaftTilt == null) {
            flangeNow = a.flange(theta);
        } else {
            Rigid[] pre = new Rigid[n];
            double[][] axes = a.axes(), pts = a.points();
            for (Wobble wb : wobbles) {
                Rigid t = wb.tilt(axes[wb.joint()], pts[wb.joint()], theta[wb.joint()]);
                pre[wb.joint()] = pre[wb.joint()] == null ? t : pre[wb.joint()].times(t);
            }
            if (shaftTilt != null) {
                if (compliance == null) throw new IllegalStateException("a shaft tilting under its drive's torque needs the masses (a compliance)");
                int j = shaftTilt.joint();
                double tau = driveSide(gravityTorques(a, theta, payload))[j];
                Rigid t = shaftTilt.tilt(axes[j], pts[j], tau);
                pre[j] = pre[j] == null ? t : pre[j].times(t);
            }
            flangeNow = a.flange(theta, pre);
        }
        if (targetPlay != null) {
            // gravity (straight down the base's z) seen from the flange
            double[] g = flangeNow.inverse().rotate(new double[] {0, 0, -1});
            double[] d = targetPlay.shift(g);
            onFlange = targetPlay.tip(g).times(new Rigid(onFlange.r(), Rigid.plus(onFlange.p(), d)));
        }
        Rigid tool = flangeNow.times(onFlange);
        if (sag != null) {
            double[] p = tool.p();
            double[] w = a.axes()[0], p0 = a.points()[0];
            double[] d = Rigid.minus(p, p0);
            double r = Rigid.norm(Rigid.minus(d, Rigid.scale(w, Rigid.dot(d, w))));
            p[2] -= sag.at(r, payload);
            tool = new Rigid(tool.r(), p);
        }
        if (twist != null) tool = twist.turn(a, theta, payload).times(tool);
        if (rocking != null) tool = rocking.tilt(overturningMoments(a, theta, payload)).times(tool);
        if (floorTilt != null && Double.isFinite(timeS)) tool = floorTilt.at(timeS).times(tool);
        Rigid inst = instrumentFromBase;
        if (thermal != null) {
            double[] drift = new double[3];
            for (int i = 0; i < 3; i++)
                drift[i] = (Double.isFinite(tempC) ? thermal.driftPerK[i] * (tempC - thermal.refC) : 0)
                        + (Double.isFinite(timeS) ? thermal.driftPerS[i] * timeS : 0);
            inst = new Rigid(inst.r(), Rigid.plus(inst.p(), drift));
        }
        // knocked: the instrument's pose in base coordinates moved by K, so it maps base points by inst · K⁻¹
        if (knock != null && Double.isFinite(timeS) && timeS >= knock.atS()) inst = inst.times(knock.motion(inst.inverse().p()).inverse());
        if (refraction != null) tool = new Rigid(tool.r(), refraction.seen(tool.p(), inst.inverse().p(), timeS, tempC));
        Rigid seen = inst.times(tool);
        if (network != null && network.readsSecond(tool, inst)) seen = network.misregistered(seen, inst);
        if (machine != null) seen = new Rigid(seen.r(), machine.read(seen.p()));
        return tracker == null ? seen : new Rigid(seen.r(), tracker.read(seen.p(), timeS));
    }

    /**
     * The instrument is a coordinate measuring machine whose three scales' readings (u, v, w) it
     * reports as the point's coordinates, while its axes are not square and its x carriage runs on a
     * bowed way: the point the readings reach is p = (1 + sx) u x̂ + (1 + sy) v ŷ' + w ẑ' + b(u), with
     * ŷ' = unit(−gxy, 1, 0) and ẑ' = unit(−gxz, −gyz, 1) (y out of square with x by gxy, z with x and y
     * by gxz, gyz, rad; x and y scales off z's by sx, sy), and the carriage's straightness deviation
     * b(u) = (0, bowY ξ², bowZ ξ²), ξ = (u − centre)/half, along the x travel. Squareness and
     * straightness are among a machine's 21 geometric errors (ISO 230-1; Schwenke et al., CIRP
     * Annals 57 (2008) 660). Lengths m.
     */
    public record Machine(double gxy, double gxz, double gyz, double sx, double sy, double bowY, double bowZ, double centreM, double halfM) {
        /**
         * The readings the machine reports for the point p (its own frame): the reading (u, v, w) whose
         * chain reaches p. The chain is triangular (ẑ' alone has a z part, ŷ' none along z): w from z,
         * then v from y, then u from x; the bow, a function of u, by a few rounds of that.
         */
        public double[] read(double[] p) {
            double[] y = Rigid.unit(new double[] {-gxy, 1, 0}), z = Rigid.unit(new double[] {-gxz, -gyz, 1});
            double u = p[0], v = 0, w = 0;
            for (int it = 0; it < 8; it++) {
                double xi = (u - centreM) / halfM;
                w = (p[2] - bowZ * xi * xi) / z[2];
                v = (p[1] - bowY * xi * xi - w * z[1]) / ((1 + sy) * y[1]);
                u = (p[0] - (1 + sy) * v * y[0] - w * z[0]) / (1 + sx);
            }
            return new double[] {u, v, w};
        }
    }

    /** The same robot measured by a machine whose axes are out of square ({@link Machine}). */
    public WorldRobot withMachine(Machine m) {
        return edit(it -> it.machine = m);
    }

    /**
     * Outside every catalogue family: the floor under the robot tilts as it warms (a slab heated on
     * one side by the sun through a window, by a furnace or by the hall's heating; a slab's
     * temperature difference through its depth bows it, Timoshenko &amp; Goodier, Theory of
     * Elasticity, thermal stresses in plates). The robot turns with it by theta(t) = maxRad (1 -
     * exp(-t / tauS)) about a horizontal axis at {@code azimuth} from the base's x axis through the
     * floor point {@code pivot} (base coordinates, m): the slab's temperature follows the heating
     * as a lumped body (Incropera &amp; DeWitt, section 5.2). The instrument stands elsewhere and
     * does not turn.
     */
    public record FloorTilt(double azimuth, double[] pivot, double maxRad, double tauS) {
        public FloorTilt { pivot = pivot.clone(); }

        @Override public double[] pivot() { return pivot.clone(); }

        /** The floor's turn at {@code timeS} seconds into the campaign, in base coordinates. */
        public Rigid at(double timeS) {
            double[] axis = {Math.cos(azimuth), Math.sin(azimuth), 0};
            return Rigid.rotation(axis, maxRad * (1 - Math.exp(-timeS / tauS)), pivot);
        }
    }

    /**
     * Outside every catalogue family: the upper arm (from joint 2's axis to joint 3's) twisting about
     * its own long axis. A bar under a torque T about its axis turns its far end by phi = T L / (G J)
     * in the sense of T (Saint-Venant torsion: Gere &amp; Goodno, "Mechanics of Materials", 7th ed.,
     * 2009, §3.3; Timoshenko &amp; Goodier, "Theory of Elasticity", ch. 10); here phi = T / k with
     * k = G J / L. The torque is the moment about the arm's axis of every weight beyond it, the
     * forearm's, the wrist's and the payload's: T = e · sum (c - p) × m g, with e the unit vector from
     * joint 2's axis to joint 3's point across joint 2's axis and p joint 2's point, at the pose (statics
     * of the bodies beyond a section: Meriam &amp; Kraige, "Engineering Mechanics: Statics", moments
     * about an axis). Only weight beside the arm's plane gives it: a tool or payload whose centre
     * sits off the flange's axis, swung to one side or the other by the wrist. Everything beyond the
     * arm turns by phi about the line (p, e).
     *
     * @param masses         the bodies beyond joint 2 that load it (their joints 2.. count; others are ignored)
     * @param payloadCentre  the payload's centre in flange coordinates, m
     */
    public record Twist(double stiffnessNmPerRad, List<Mass> masses, double[] payloadCentre, double[] gravity) {
        public Twist {
            masses = List.copyOf(masses);
            payloadCentre = payloadCentre.clone();
            gravity = gravity.clone();
        }

        @Override public double[] payloadCentre() { return payloadCentre.clone(); }
        @Override public double[] gravity() { return gravity.clone(); }

        /** The torque about the upper arm's axis (N·m) at model angles theta with {@code payload} kg. */
        public double torque(Arm a, double[] theta, double payload) {
            Rigid[] body = a.bodies(theta);
            return torque(a, body, axis(a, body), payload);
        }

        /** The turn of everything beyond the upper arm at model angles theta with {@code payload} kg. */
        public Rigid turn(Arm a, double[] theta, double payload) {
            Rigid[] body = a.bodies(theta);
            double[][] axis = axis(a, body);
            return Rigid.rotation(axis[0], torque(a, body, axis, payload) / stiffnessNmPerRad, axis[1]);
        }

        /** The moment about the arm's {@code axis} of the bodies beyond it (joints 3..) and the payload, N·m. */
        private double torque(Arm a, Rigid[] body, double[][] axis, double payload) {
            return moment(body, withPayload(a, masses, payloadCentre, payload), 2, axis[0], axis[1], gravity);
        }

        /** The upper arm's axis with the bodies at {@code body}: {unit direction from joint 2's axis to joint 3's point, joint 2's point}. */
        private static double[][] axis(Arm a, Rigid[] body) {
            double[] w = body[0].rotate(a.axes()[1]), p = body[0].apply(a.points()[1]), p3 = body[1].apply(a.points()[2]);
            double[] l = Rigid.minus(p3, p);
            l = Rigid.minus(l, Rigid.scale(w, Rigid.dot(l, w)));
            return new double[][] {Rigid.unit(l), p};
        }
    }

    /** Torques on the model joints carried to the drives by virtual work: tau_q = C^T tau_theta. */
    double[] driveSide(double[] tauTheta) {
        int n = dof();
        double[] tauQ = new double[n];
        for (int j = 0; j < n; j++) for (int i = 0; i < n; i++) tauQ[j] += coupling[i][j] * tauTheta[i];
        return tauQ;
    }

    /** The arm's overturning moments about the base's four foot edges at model angles theta ({@link Rocking#moments}). */
    public double[] overturningMoments(Arm a, double[] theta, double payload) {
        Rigid[] body = a.bodies(theta);
        List<double[]> c = new ArrayList<>();
        List<Double> kg = new ArrayList<>();
        for (Mass m : rocking.masses()) {
            c.add(body[m.joint].apply(m.centre));
            kg.add(m.kg);
        }
        if (payload > 0) {
            c.add(body[dof() - 1].apply(a.flange().apply(rocking.payloadCentre)));
            kg.add(payload);
        }
        return rocking.moments(c, kg);
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
        List<Mass> all = withPayload(a, compliance.masses, compliance.payloadCentre, payload);
        double[] tau = new double[n];
        for (int i = 0; i < n; i++) {
            Rigid before = i == 0 ? Rigid.IDENTITY : body[i - 1];
            double[] w = before.rotate(axes[i]), p = before.apply(pts[i]);
            if (!prismatic[i]) {
                tau[i] = moment(body, all, i, w, p, compliance.gravity);
                continue;
            }
            for (Mass m : all) if (m.joint >= i) tau[i] += Rigid.dot(w, Rigid.scale(compliance.gravity, m.kg));
        }
        return tau;
    }

    /**
     * The masses, and the payload ({@code payload} kg above 0) at its centre in flange coordinates as
     * a mass of the last body, in zero-position base coordinates.
     */
    static List<Mass> withPayload(Arm a, List<Mass> masses, double[] payloadCentre, double payload) {
        List<Mass> all = new ArrayList<>(masses);
        if (payload > 0) all.add(new Mass(a.dof() - 1, payload, a.flange().apply(payloadCentre)));
        return all;
    }

    /**
     * The moment about the line through {@code p} along unit {@code w} of the weights of the masses
     * riding on body {@code from} and beyond, with the bodies at {@code body}: Σ w · ((c − p) × m g)
     * (N·m), c each mass's centre at the pose.
     */
    static double moment(Rigid[] body, List<Mass> all, int from, double[] w, double[] p, double[] gravity) {
        double t = 0;
        for (Mass m : all) {
            if (m.joint < from) continue;
            t += Rigid.dot(w, Rigid.cross(Rigid.minus(body[m.joint].apply(m.centre), p), Rigid.scale(gravity, m.kg)));
        }
        return t;
    }

    public WorldRobot withErrors(List<JointError> e) {
        return edit(it -> it.errors = e);
    }

    public WorldRobot withThermal(Thermal t) {
        return edit(it -> it.thermal = t);
    }

    public WorldRobot withCompliance(Compliance c) {
        return edit(it -> it.compliance = c);
    }

    public WorldRobot withSag(Sag s) {
        return edit(it -> it.sag = s);
    }

    public WorldRobot withToolBump(ToolBump b) {
        return edit(it -> it.toolBump = b);
    }

    /** The same robot with the measured target (and its frame) at {@code flangeToTool} in flange coordinates. */
    public WorldRobot withTool(Rigid flangeToTool) {
        return edit(it -> it.flangeToTool = flangeToTool);
    }

    public WorldRobot withInstrument(Rigid instrumentFromBase) {
        return edit(it -> it.instrumentFromBase = instrumentFromBase);
    }

    public WorldRobot withTracker(Tracker t) {
        return edit(it -> it.tracker = t);
    }

    public WorldRobot withRocking(Rocking r) {
        return edit(it -> it.rocking = r);
    }

    public WorldRobot withDressPack(DressPack d) {
        return edit(it -> it.dressPack = d);
    }

    public WorldRobot withKnock(Knock k) {
        return edit(it -> it.knock = k);
    }

    public WorldRobot withTargetPlay(TargetPlay p) {
        return edit(it -> it.targetPlay = p);
    }

    public WorldRobot withWobbles(List<Wobble> w) {
        return edit(it -> it.wobbles = w);
    }

    public WorldRobot withFloorTilt(FloorTilt f) {
        return edit(it -> it.floorTilt = f);
    }

    public WorldRobot withTwist(Twist t) {
        return edit(it -> it.twist = t);
    }

    /** The same robot carrying a mass that changes with time as {@code d} says, whatever the campaign records. */
    public WorldRobot withDispensing(Dispensing d) {
        return edit(it -> it.dispensing = d);
    }

    /** The same robot with a cable retractor pulling its tool toward the retractor's anchor. */
    public WorldRobot withRetractor(Retractor r) {
        return edit(it -> it.retractor = r);
    }

    public WorldRobot withShaftTilt(ShaftTilt t) {
        return edit(it -> it.shaftTilt = t);
    }

    public WorldRobot withNetwork(Network x) {
        return edit(it -> it.network = x);
    }

    /** The same robot seen through air whose vertical temperature gradient is {@code r}'s. */
    public WorldRobot withRefraction(Refraction r) {
        return edit(it -> it.refraction = r);
    }

    /**
     * Outside every catalogue family: a tool that dispenses what it carries (glue, sealant, a part
     * set down), so the mass at the flange falls with time while the campaign records the full tool's
     * mass. The carried mass is piecewise linear between ({@code timesS}, {@code kg}) and constant
     * beyond them; a step is two points a moment apart.
     */
    public record Dispensing(double[] timesS, double[] kg) {
        public Dispensing {
            requireSeries(timesS, kg);
            timesS = timesS.clone();
            kg = kg.clone();
        }

        /** The mass carried at time t (s). */
        public double at(double t) { return piecewise(timesS, kg, t); }
    }

    /** A series of values at times for {@link #piecewise}: as many of each, at least one, the times in order. */
    static void requireSeries(double[] timesS, double[] values) {
        if (timesS.length != values.length || timesS.length == 0) throw new IllegalArgumentException("times and values in pairs");
        for (int i = 1; i < timesS.length; i++) if (!(timesS[i] >= timesS[i - 1])) throw new IllegalArgumentException("times in order");
    }

    /** The piecewise linear function through (x[i], y[i]) at u, constant beyond its ends (x ascending; equal x: a step). */
    static double piecewise(double[] x, double[] y, double u) {
        if (u <= x[0]) return y[0];
        for (int i = 1; i < x.length; i++)
            if (u <= x[i]) {
                double span = x[i] - x[i - 1];
                return span > 0 ? y[i - 1] + (y[i] - y[i - 1]) * (u - x[i - 1]) / span : y[i];
            }
        return y[y.length - 1];
    }

    /**
     * Outside every catalogue family: the instrument's line of sight bent by the air. A vertical
     * temperature gradient dT/dz makes the air's refractive index change with height,
     * dn/dz = −(n − 1)/T · dT/dz (the refractivity of air scales with its density, which at constant
     * pressure goes as 1/T; n − 1 = 2.7e-4 near 20 °C, Edlén), and a ray bends toward the higher
     * index with curvature κ = −(dn/dz)/n. Over a chord of length L the ray leaves the instrument
     * at κL/2 above the chord (a circular arc's tangent–chord angle), and the instrument places the
     * point along its line of departure: the point is seen with its line of sight turned up by κL/2
     * in the vertical plane through it, at the same distance (warm air over cool: κ &gt; 0, seen
     * higher; the refraction coefficient of trigonometric levelling). The gradient is piecewise
     * linear between ({@code timesS}, {@code kPerM}), constant beyond.
     */
    public record Refraction(double[] timesS, double[] kPerM) {
        static final double REFRACTIVITY = 2.7e-4;

        public Refraction {
            requireSeries(timesS, kPerM);
            timesS = timesS.clone();
            kPerM = kPerM.clone();
        }

        /** The vertical temperature gradient at time t, K/m. */
        public double gradient(double t) { return piecewise(timesS, kPerM, t); }

        /**
         * The point {@code pBase} as an instrument at {@code originBase} sees it at time t with the air at
         * {@code tempC} (20 °C when unknown), base coordinates (z up).
         */
        double[] seen(double[] pBase, double[] originBase, double t, double tempC) {
            double kelvin = (Double.isFinite(tempC) ? tempC : 20) + 273.15;
            double dndz = -REFRACTIVITY / kelvin * gradient(Double.isFinite(t) ? t : timesS[timesS.length - 1]);
            double kappa = -dndz / (1 + REFRACTIVITY);
            double[] los = Rigid.minus(pBase, originBase);
            double len = Rigid.norm(los);
            double[] across = Rigid.cross(los, new double[] {0, 0, 1});
            if (!(Rigid.norm(across) > 1e-9 * len)) return pBase.clone(); // looking straight up or down: no bend across the sight
            // turning the sight up by κL/2 in its vertical plane: about the horizontal axis ẑ × los (right-handed, up for κ > 0)
            double[] axis = Rigid.unit(Rigid.cross(new double[] {0, 0, 1}, los));
            double[] turned = Rigid.rotation(axis, -kappa * len / 2, new double[3]).rotate(los);
            return Rigid.plus(originBase, turned);
        }
    }

    public WorldRobot withCoupling(double[][] c) {
        return edit(it -> it.coupling = c);
    }

    /** This robot with what {@code change} sets changed: the one place every {@code with...} copies the rest. */
    private WorldRobot edit(java.util.function.Consumer<Edit> change) {
        Edit e = new Edit(this);
        change.accept(e);
        return new WorldRobot(e.robotName, e.arm, e.coupling, e.zeroOffsets, e.errors, e.flangeToTool, e.instrumentFromBase, e.thermal, e.compliance, e.sag, e.toolBump, e.tracker, e.rocking, e.dressPack, e.wobbles, e.floorTilt, e.twist, e.targetPlay, e.knock, e.dispensing, e.refraction, e.retractor, e.shaftTilt, e.network, e.machine);
    }

    /** The components of a robot being copied with one of them changed. */
    private static final class Edit {
        String robotName;
        Arm arm;
        double[][] coupling;
        double[] zeroOffsets;
        List<JointError> errors;
        Rigid flangeToTool;
        Rigid instrumentFromBase;
        Thermal thermal;
        Compliance compliance;
        Sag sag;
        ToolBump toolBump;
        Tracker tracker;
        Rocking rocking;
        DressPack dressPack;
        List<Wobble> wobbles;
        FloorTilt floorTilt;
        Twist twist;
        TargetPlay targetPlay;
        Knock knock;
        Dispensing dispensing;
        Refraction refraction;
        Retractor retractor;
        ShaftTilt shaftTilt;
        Network network;
        Machine machine;

        Edit(WorldRobot w) {
            robotName = w.robotName;
            arm = w.arm;
            coupling = w.coupling;
            zeroOffsets = w.zeroOffsets;
            errors = w.errors;
            flangeToTool = w.flangeToTool;
            instrumentFromBase = w.instrumentFromBase;
            thermal = w.thermal;
            compliance = w.compliance;
            sag = w.sag;
            toolBump = w.toolBump;
            tracker = w.tracker;
            rocking = w.rocking;
            dressPack = w.dressPack;
            wobbles = w.wobbles;
            floorTilt = w.floorTilt;
            twist = w.twist;
            targetPlay = w.targetPlay;
            knock = w.knock;
            dispensing = w.dispensing;
            refraction = w.refraction;
            retractor = w.retractor;
            shaftTilt = w.shaftTilt;
            network = w.network;
            machine = w.machine;
        }
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
