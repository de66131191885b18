package org.robopro.world;

/**
 * An error of one drive: the angle its gearbox output really has differs from what the
 * controller reports, q_out = q + delta(q, dir). Applied on the controller's (motor-side) axis
 * values before the coupling theta = C q, as a drive's own error is (a parallel-arm linkage
 * passes it on to the model angles it feeds). Joints 0-based; angles rad.
 */
public sealed interface JointError {
    /** The drive (0-based) this error acts on. */
    int joint();

    /** Whether the error needs the drive's gravity torque ({@link Moment#driveTorque}): the robot's masses. */
    default boolean needsTorque() { return false; }

    /**
     * The error of the drive's output angle, rad.
     *
     * @param q   all controller values (rad or m)
     * @param dir the sign of each drive's last motion before the pose was reached (+1, -1)
     */
    default double delta(double[] q, int[] dir) { return delta(q, new Moment(dir, null, Double.NaN, Double.NaN)); }

    /** The error of the drive's output angle at a moment of a campaign, rad. */
    double delta(double[] q, Moment m);

    /**
     * The play (lost motion) this error puts into its drive at controller values q, rad; 0 for an
     * error without play. A campaign tracks where each drive's output rests within its play from it.
     */
    default double playWidth(double[] q) { return 0; }

    /**
     * What a drive's error may depend on besides the joint values, at the moment a pose is measured.
     *
     * @param dir      the sign of each drive's last motion before the pose was reached (+1, -1)
     * @param lastMove each drive's last motion (rad or m, signed), or null when every move was long
     * @param timeS    seconds since the campaign started (NaN: unknown)
     * @param tempC    the drive's temperature, °C (NaN: unknown)
     * @param driveTorque the gravity torque each drive carries at the pose (N·m, tau_q = C^T tau_theta), or null
     * @param side     where each drive's output rests within its play, from +1 (on the flank a rising move
     *                 leaves it on: lagging) to -1 (after a falling move), or null: on the flank of dir
     */
    record Moment(int[] dir, double[] lastMove, double timeS, double tempC, double[] driveTorque, double[] side) {
        /** A moment without the drives' gravity torques. */
        public Moment(int[] dir, double[] lastMove, double timeS, double tempC) { this(dir, lastMove, timeS, tempC, null, null); }

        /** Where drive j's output rests within its play (+1 lagging after a rise, -1 after a fall). */
        public double side(int j) { return side == null ? dir[j] : side[j]; }
    }

    /**
     * Transmission error of a reducer: a sum of harmonics of the output angle,
     * sum a_i sin(k_i q + phi_i). A single-stage gear gives k = 1 (eccentricity); a multi-stage or
     * cycloidal reducer adds the tooth-meshing and stage harmonics (k up to tens per output turn).
     */
    record Harmonics(int joint, int[] k, double[] amplitude, double[] phase) implements JointError {
        public Harmonics {
            k = k.clone();
            amplitude = amplitude.clone();
            phase = phase.clone();
            if (k.length != amplitude.length || k.length != phase.length) throw new IllegalArgumentException("harmonic arrays differ in length");
        }

        @Override public int[] k() { return k.clone(); }
        @Override public double[] amplitude() { return amplitude.clone(); }
        @Override public double[] phase() { return phase.clone(); }

        @Override public double delta(double[] q, Moment m) {
            double s = 0;
            for (int i = 0; i < k.length; i++) s += amplitude[i] * Math.sin(k[i] * q[joint] + phase[i]);
            return s;
        }
    }

    /**
     * Lost motion (backlash) of width b: the driven output lags its motor-side encoder by half the
     * play in the direction of the last motion, q_out = q - (b/2) dir. (The motor has to take up
     * the play before the output moves, so after a positive move the output sits b/2 short of
     * where the encoder says; after a negative move b/2 beyond. See e.g. Nordin &amp; Gutman,
     * "Controlling mechanical systems with backlash: a survey", Automatica 38 (2002), §2.)
     * A reversal shorter than the play leaves the output where it stood (the play's dead zone, same
     * source): a campaign tracks that in {@link Moment#side}, q_out = q - (b/2) side.
     */
    record LostMotion(int joint, double width) implements JointError {
        @Override public double delta(double[] q, Moment m) { return -0.5 * width * m.side(joint); }

        @Override public double playWidth(double[] q) { return width; }
    }

    /**
     * Lost motion of the last gear pair of a drive whose gears run off their centres: the output gear
     * ({@code gearTeeth}) off its bearing's centre by {@code gearRunoutM}, and the pinion driving it
     * ({@code pinionTeeth}, turning gearTeeth/pinionTeeth times per output turn, the other way) by
     * {@code pinionRunoutM} (either may be 0). Each moves the centre distance by its runout times the
     * cosine of its own angle, and a gear pair's circumferential backlash changes with the centre
     * distance by 2 Δa tan α (α the working pressure angle; ISO/TR 10064-2:1996, "Backlash", j_t from
     * the centre distance; D. W. Dudley, Handbook of Practical Gear Design, §4.3), an angle of the
     * output gear of pitch radius r. The output lags by half the play: q_out = q - (play/2) dir.
     */
    record GearPairLostMotion(int joint, double width, double gearRunoutM, double gearPhase, double pinionRunoutM, double pinionPhase,
                              int gearTeeth, int pinionTeeth, double gearPitchRadiusM, double pressureAngle) implements JointError {
        public GearPairLostMotion {
            if (!(2 * (gearRunoutM + pinionRunoutM) * Math.tan(pressureAngle) / gearPitchRadiusM < width))
                throw new IllegalArgumentException("the play would close: runouts " + gearRunoutM + " + " + pinionRunoutM
                        + " m against width " + width + " rad");
        }

        /** The pinion's angle when the output is at q, rad. */
        public double pinionAngle(double q) { return -q * gearTeeth / pinionTeeth; }

        /** The play at output angle q, rad. */
        public double play(double q) {
            double da = gearRunoutM * Math.cos(q - gearPhase) + pinionRunoutM * Math.cos(pinionAngle(q) - pinionPhase);
            return width + 2 * da * Math.tan(pressureAngle) / gearPitchRadiusM;
        }

        /** The play's change by the pinion's runout alone (amplitude), rad. */
        public double pinionChange() { return 2 * pinionRunoutM * Math.tan(pressureAngle) / gearPitchRadiusM; }

        /** The play's change by the output gear's runout alone (amplitude), rad. */
        public double gearChange() { return 2 * gearRunoutM * Math.tan(pressureAngle) / gearPitchRadiusM; }

        @Override public double delta(double[] q, Moment m) { return -0.5 * play(q[joint]) * m.side(joint); }

        @Override public double playWidth(double[] q) { return play(q[joint]); }
    }

    /** Gear-ratio error: the output turns (1 + eps) times what the controller assumes. */
    record Scale(int joint, double eps) implements JointError {
        @Override public double delta(double[] q, Moment m) { return eps * q[joint]; }
    }

    /** Cross-coupling error: the output of {@code joint} also follows another drive, kappa q_source. */
    record Coupling(int joint, int source, double kappa) implements JointError {
        @Override public double delta(double[] q, Moment m) { return kappa * q[source]; }
    }

    /**
     * Outside every catalogue family: a smooth local bump of the output angle around one joint
     * angle (a damaged stretch of a gear, a cable pulling over part of the range), not periodic:
     * a exp(-((q - centre)/width)^2).
     */
    record Bump(int joint, double centre, double width, double amplitude) implements JointError {
        @Override public double delta(double[] q, Moment m) {
            double u = (q[joint] - centre) / width;
            return amplitude * Math.exp(-u * u);
        }
    }

    /**
     * Outside every catalogue family: a parallel arm whose rod is not as long as the upper arm's
     * pivot distance. Drive {@code joint}'s motor turns a crank of length {@code crankM} at the upper
     * arm's pivot; a rod of length {@code rodM} carries it to a lever of length {@code leverM} on the
     * forearm at the elbow, {@code groundM} along the upper arm from the pivot. With rod = ground and
     * lever = crank the four bars are a parallelogram and the forearm turns with the crank; otherwise
     * the forearm's angle to the upper arm φ is the four-bar's closure at the crank's angle to the
     * upper arm ψ = psi0 + q_joint − q_upper (Norton, Design of Machinery, §4.5, position analysis:
     * the elbow, the crank's end and the lever's end form a triangle of sides d, rod and lever), and
     * the drive's output is off by φ − ψ. To first order −δrod/(crank·sin ψ): large where the crank
     * lies near the upper arm.
     */
    record LinkageRod(int joint, int upper, double groundM, double crankM, double leverM, double rodM, double psi0) implements JointError {
        @Override public double delta(double[] q, Moment m) {
            double psi = psi0 + q[joint] - q[upper];
            return wrap(leverAngle(psi) - psi);
        }

        /** The lever's angle to the upper arm (rad) at the crank's angle psi, on the branch of the parallelogram. */
        public double leverAngle(double psi) {
            double ax = crankM * Math.cos(psi) - groundM, ay = crankM * Math.sin(psi);     // elbow to the crank's end
            double d = Math.hypot(ax, ay);
            double c = (d * d + leverM * leverM - rodM * rodM) / (2 * leverM * d);
            if (!(Math.abs(c) <= 1)) throw new IllegalStateException("the linkage cannot close at a crank angle of " + Math.toDegrees(psi) + " deg");
            double toCrank = Math.atan2(ay, ax), g = Math.acos(c);
            double a = toCrank + g, b = toCrank - g;
            return Math.abs(wrap(a - psi)) < Math.abs(wrap(b - psi)) ? a : b;
        }

        private static double wrap(double x) { return Math.atan2(Math.sin(x), Math.cos(x)); }
    }

    /**
     * Outside every catalogue family: an error depending on two joints at once (a hose package
     * dragging on an axis with a force that depends on another axis): a sin(q_joint) sin(q_other).
     */
    record TwoJoint(int joint, int other, double amplitude) implements JointError {
        @Override public double delta(double[] q, Moment m) {
            return amplitude * Math.sin(q[joint]) * Math.sin(q[other]);
        }
    }

    /**
     * Outside every catalogue family: a hose routed through the wrist to the tool is twisted as
     * joint {@code joint} turns from the angle {@code neutral} where it hangs free, and its restoring
     * torque deflects the drive (a torsion spring, τ = −(GJ/L)·(q − neutral), and the drive yields by
     * τ/k). Bending the wrist at joint {@code bend} draws the hose taut over the wrist's housing, so
     * its free length shortens as L = L₀ / (1 + β(1 − cos q_bend)) and its torsional stiffness GJ/L
     * rises with the bend (Timoshenko &amp; Goodier, Theory of Elasticity, §101: a shaft's twist
     * stiffness is GJ/L). Δq = −c·(q − neutral)·(1 + β(1 − cos q_bend)), c = GJ/(L₀·k): straight, a
     * scale error of the drive about {@code neutral}; bent, a scale that changes with joint
     * {@code bend}'s angle.
     */
    record HoseTwist(int joint, int bend, double c, double neutral, double beta) implements JointError {
        @Override public double delta(double[] q, Moment m) {
            return -c * (q[joint] - neutral) * (1 + beta * (1 - Math.cos(q[bend])));
        }
    }

    /**
     * Lost motion with unequal flanks: gravity (or a spring) presses the gear on one flank, so a
     * move one way leaves the output lagging by the full half-play and a move the other way by
     * less: q_out = q - (up/2) after a positive move, q + (down/2) after a negative one.
     */
    record AsymmetricLostMotion(int joint, double up, double down) implements JointError {
        @Override public double delta(double[] q, Moment m) { return m.dir()[joint] > 0 ? -0.5 * up : 0.5 * down; }
    }

    /**
     * Lost motion held on one flank by gravity: the load's torque on the output presses the gear
     * against one flank of the play wherever it exceeds {@code holdTorque} (the output side's
     * friction, which otherwise keeps the output where the motor's last motion left it). A positive
     * torque pushes the output ahead of the motor: q_out = q - (b/2) flank with flank = -sign(tau)
     * where |tau| &gt; holdTorque, flank = dir (the last motion's side, {@link LostMotion}) elsewhere.
     * So the play shows its dependence on the direction only where the joint's gravity torque is
     * small; elsewhere it is a step with the torque's sign. (Nordin &amp; Gutman, Automatica 38 (2002),
     * §2: a backlash's output stays in contact with one flank while the load torque holds it there.)
     * The torque is the drive's, tau_q = C^T tau_theta, from the moment's {@code driveTorque}.
     */
    record GravityHeldLostMotion(int joint, double width, double holdTorque) implements JointError {
        @Override public boolean needsTorque() { return true; }

        @Override public double delta(double[] q, Moment m) {
            if (m.driveTorque() == null) throw new IllegalStateException("lost motion held by gravity needs the drive's gravity torque");
            double tau = m.driveTorque()[joint];
            int flank = Math.abs(tau) > holdTorque ? (tau > 0 ? -1 : 1) : m.dir()[joint];
            return -0.5 * width * flank;
        }
    }

    /**
     * A gear's transmission error under load: the mesh's stiffness varies over the mesh cycle, so
     * the part of the output's deflection that repeats with the angle grows with the torque the
     * gear carries (the loaded transmission error: J. D. Smith, "Gear Noise and Vibration", 2nd ed.,
     * Marcel Dekker 2003, §2–3). q_out = q + (unloaded + loaded·τ/torqueRef)·sin(k·q + phase), τ the
     * drive's gravity torque from the moment, with its sign (the mesh deflects the other way when
     * the torque turns).
     */
    record LoadedHarmonic(int joint, int k, double unloaded, double loaded, double torqueRef, double phase) implements JointError {
        @Override public double delta(double[] q, Moment m) {
            if (m.driveTorque() == null) throw new IllegalStateException("a loaded transmission error needs the drive's gravity torque");
            return (unloaded + loaded * m.driveTorque()[joint] / torqueRef) * Math.sin(k * q[joint] + phase);
        }

        @Override public boolean needsTorque() { return true; }
    }

    /**
     * Outside every catalogue family: a joint whose stiffness falls as it warms. A reducer's
     * lubricant thins and its elastomer seals and bearings soften with temperature, so the joint
     * gives way more under the same torque: k(T) = k0 / (1 + perK (T − refC)). With the robot's own
     * spring (its compliance, k0) already in the world, this is the rest of the give:
     * τ/k(T) − τ/k0 = τ · perK (T − refC) / k0, in the sense gravity pulls (τ the drive's gravity
     * torque). T is the temperature the campaign reads.
     */
    record WarmSoftening(int joint, double stiffness, double perK, double refC) implements JointError {
        @Override public double delta(double[] q, Moment m) {
            if (m.driveTorque() == null) throw new IllegalStateException("a softening joint needs the drive's gravity torque");
            if (!Double.isFinite(m.tempC())) return 0;
            return m.driveTorque()[joint] * perK * (m.tempC() - refC) / stiffness;
        }

        @Override public boolean needsTorque() { return true; }
    }

    /**
     * Outside every catalogue family: an error of drive {@code joint} that repeats with the angle
     * between its link and another's, ψ = q_joint + sign · q_other over the controller values, not
     * with the drive's own turn: a parallel arm's rod and lever, whose bearings turn with the
     * forearm's angle to the upper arm (q3 − q2 on a controller that reads the forearm against the
     * ground), or a serial arm's counterweight or cable that turns with the forearm's angle to the
     * ground (q2 + q3). amplitude · sin(k ψ + phase).
     */
    record LinkHarmonic(int joint, int other, double sign, int k, double amplitude, double phase) implements JointError {
        @Override public double delta(double[] q, Moment m) {
            return amplitude * Math.sin(k * (q[joint] + sign * q[other]) + phase);
        }
    }

    /**
     * Outside every catalogue family: drive {@code joint}'s last gear stage seated in a bearing bore of
     * the housing that joint {@code housing} turns (the wrist: joint 5's drive runs from its motor in
     * the forearm through joint 4's housing), the bore out of round by {@code ovality} (m, radial,
     * half the difference of its diameters: an uneven bolt-up of a thin section). The seat turns with
     * the housing while the mesh stays with the gear, so the mesh's depth changes by ovality ·
     * cos 2(q_housing − {@code major}); a preloaded mesh at pressure angle α turns the output by the
     * depth · tan α over the pitch radius {@code radius} (m) (involute gearing: a radial shift e of
     * the centre moves the contact along the line of action by e·sin α, the pitch circle by e·tan α;
     * Dudley, Handbook of Practical Gear Design, ch. 2).
     */
    record OvalSeat(int joint, int housing, double ovality, double pressureAngle, double radius, double major) implements JointError {
        @Override public double delta(double[] q, Moment m) {
            double depth = ovality * Math.cos(2 * (q[housing] - major));
            return depth * Math.tan(pressureAngle) / radius;
        }
    }

    /**
     * Lost motion that builds up over the move: the play plus the transmission's friction
     * wind-up, which reaches its full size only after the joint has travelled a distance of the
     * order of {@code buildUp} (Dahl's solid-friction model: the friction force follows
     * F = Fc (1 - exp(-x/x0)) along the travel x; P. R. Dahl, "A solid friction model",
     * Aerospace Corp. TOR-0158(3107-18)-1, 1968). A short move leaves a smaller lag:
     * q_out = q - (width/2) dir (1 - exp(-|last move| / buildUp)).
     */
    record WindUpLostMotion(int joint, double width, double buildUp) implements JointError {
        @Override public double delta(double[] q, Moment m) {
            double f = m.lastMove() == null ? 1 : 1 - Math.exp(-Math.abs(m.lastMove()[joint]) / buildUp);
            return -0.5 * width * m.dir()[joint] * f;
        }
    }

    /**
     * Outside every catalogue family: encoder slip. At {@code atS} seconds into the campaign the
     * joint's zero jumps by {@code step} (a belt or a motor's encoder slipping on its shaft, a
     * resolver re-synchronised) and stays there.
     */
    record Slip(int joint, double atS, double step) implements JointError {
        @Override public double delta(double[] q, Moment m) { return Double.isFinite(m.timeS()) && m.timeS() >= atS ? step : 0; }
    }

    /** Outside every catalogue family: the joint's zero creeps with time at {@code ratePerS} (rad/s), e.g. an encoder's electronics drifting. */
    record Creep(int joint, double ratePerS) implements JointError {
        @Override public double delta(double[] q, Moment m) { return Double.isFinite(m.timeS()) ? ratePerS * m.timeS() : 0; }
    }

    /**
     * Outside every catalogue family: the joint's zero moves with its drive's temperature,
     * {@code perK} (rad/K) times (T - refC): the motor and gearbox warm up and the encoder's
     * mounting or the gear's housing grows (a drive's thermal error, not a link's).
     */
    record DriveThermal(int joint, double perK, double refC) implements JointError {
        @Override public double delta(double[] q, Moment m) { return Double.isFinite(m.tempC()) ? perK * (m.tempC() - refC) : 0; }
    }

    /**
     * Outside every catalogue family: the joint's angle read by an encoder on its output (a magnetic
     * ring, or an optical one read by two heads) from two channels in quadrature, sin θ and cos θ,
     * whose gains drift apart with the temperature: the sine channel's gain is 1 + g relative to the
     * cosine's, g = {@code gainPerK}·(T − {@code refC}), the two matched at refC. The controller takes
     * q = atan2((1 + g) sin θ, cos θ), so the output is θ = atan2(sin q, (1 + g) cos q); to first order
     * q − θ = (g/2) sin 2θ, an error twice a turn whose size follows the temperature (Hoseinnezhad,
     * Bab-Hadiashar &amp; Harding, "Calibration of resolver sensors in electromechanical braking
     * systems", IEEE Trans. Ind. Electron. 53 (2006) 1052: amplitude imbalance gives the second
     * harmonic).
     */
    record QuadratureGain(int joint, double gainPerK, double refC) implements JointError {
        @Override public double delta(double[] q, Moment m) {
            if (!Double.isFinite(m.tempC())) return 0;
            double g = gainPerK * (m.tempC() - refC), qj = q[joint];
            double theta = Math.atan2(Math.sin(qj), (1 + g) * Math.cos(qj));
            return Math.IEEEremainder(theta - qj, 2 * Math.PI);
        }
    }

    /**
     * Outside every catalogue family: the joint's zero moves as its own motor warms, shift times
     * (1 - exp(-t/tau)), t the time since the campaign started. A motor heated at a steady rate
     * and cooled to the air warms as a lumped body (Incropera & DeWitt, Fundamentals of Heat and
     * Mass Transfer, section 5.2); each drive has its own heating and time constant, and neither
     * follows the air temperature near the robot, so the drives of one arm drift each on its own
     * curve. The encoder's mounting or the gear's housing grows with the motor's temperature.
     */
    record MotorWarm(int joint, double shift, double tauS) implements JointError {
        @Override public double delta(double[] q, Moment m) {
            return Double.isFinite(m.timeS()) ? shift * (1 - Math.exp(-m.timeS() / tauS)) : 0;
        }
    }

    /**
     * Outside every catalogue family: a gas-spring balancer on the joint (as on the second axis of
     * many mid-size arms) whose torque bends the drive through its stiffness. The spring joins a
     * point on the link {@code rM} from the joint's axis to a point of the link before it {@code lM}
     * from the axis, at an angle psi = q + phi0 between the two radii, so its length is
     * l = sqrt(r^2 + L^2 - 2 r L cos psi) (law of cosines). Its gas, compressed polytropically as it
     * shortens, pushes with F = f0 ((l0 - dead) / (l - dead))^n, l0 its length at q = 0 and n = 1.3
     * (nitrogen in a fast stroke); its torque about the axis is F dl/dpsi = F r L sin(psi) / l
     * (virtual work), and the drive, of stiffness k, gives way by tau / k. The torque is not the
     * arm's weight: it depends on the joint's own angle alone, non-linearly and without repeating.
     */
    record GasSpring(int joint, double rM, double lM, double phi0, double f0N, double deadM, double n, double stiffness) implements JointError {
        /** The balancer's torque on the joint at controller value q, N·m. */
        public double torque(double q) {
            double psi = q + phi0, l0 = length(phi0), l = length(psi);
            double f = f0N * Math.pow((l0 - deadM) / (l - deadM), n);
            return f * rM * lM * Math.sin(psi) / l;
        }

        private double length(double psi) { return Math.sqrt(rM * rM + lM * lM - 2 * rM * lM * Math.cos(psi)); }

        @Override public double delta(double[] q, Moment m) { return torque(q[joint]) / stiffness; }
    }

    /**
     * Outside every catalogue family: the error follows the product of two joints' angles,
     * k q_a q_b (rad). Where one of them is the drive's own joint, its part linear in the other
     * looks like a cross-coupling, but the coupling's size changes with the drive's own angle.
     */
    record AngleProduct(int joint, int a, int b, double k) implements JointError {
        @Override public double delta(double[] q, Moment m) { return k * q[a] * q[b]; }
    }

    /**
     * An error of the motor's angle sensor, seen at the joint: the servo holds the motor where its
     * resolver reads the commanded angle N·q, so the motor stands off by the sensor's error δ_m and
     * the output (N turns of the motor per output turn) by −δ_m/N. A resolver's error repeats with
     * the motor's angle, once per turn from the rotor's eccentricity and twice per turn from the
     * windings' and the excitation's imbalance (Hanselman, "Resolver signal requirements for high
     * accuracy resolver-to-digital conversion", IEEE Trans. Industrial Electronics 37 (1990) 556):
     * δ_m = Σ_h A_h sin(h N q + φ_h), h = 1, 2, ... So the joint's error repeats N and 2N times per
     * output turn, at a gear ratio N that need not be whole.
     */
    record MotorSensor(int joint, double ratio, double[] amplitude, double[] phase) implements JointError {
        public MotorSensor {
            amplitude = amplitude.clone();
            phase = phase.clone();
            if (amplitude.length != phase.length) throw new IllegalArgumentException("amplitudes and phases differ in length");
        }

        @Override public double[] amplitude() { return amplitude.clone(); }
        @Override public double[] phase() { return phase.clone(); }

        @Override public double delta(double[] q, Moment m) {
            double motor = ratio * q[joint], s = 0;
            for (int h = 0; h < amplitude.length; h++) s += amplitude[h] * Math.sin((h + 1) * motor + phase[h]);
            return -s / ratio;
        }
    }

    /**
     * A joint read as whole counts of its motor's encoder: the controller reports the count, and the
     * joint stands anywhere within it, so the output is off by a uniform error of one count
     * ({@code countRad} at the joint: 2π over the counts per motor turn and the gear ratio) that no
     * recorded variable predicts (quantization noise: Widrow &amp; Kollár, Quantization Noise,
     * Cambridge 2008, ch. 4; Bennett, Bell System Technical Journal 27 (1948) 446). Where within the
     * count a pose falls is drawn from the pose's angles by a hash, so a campaign is the same on every
     * run.
     */
    record Counts(int joint, double countRad) implements JointError {
        @Override public double delta(double[] q, Moment m) {
            long h = joint * 0x9E3779B97F4A7C15L;
            for (double v : q) h = mix(h ^ Double.doubleToLongBits(v));
            return countRad * ((h >>> 11) * 0x1.0p-53 - 0.5);
        }

        /** SplitMix64's finaliser (Steele, Lea &amp; Flood, OOPSLA 2014). */
        static long mix(long z) {
            z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
            z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
            return z ^ (z >>> 31);
        }
    }

    /**
     * Outside every catalogue family: the arm read before it settled. Each move is synchronised and
     * limited by acceleration alone (bang-bang: every joint accelerates for half the move and brakes
     * for the other half, the move lasting as long as the joint that needs longest at its limit
     * {@code accel[k]}, rad/s²: T = max_k 2·√(|Δq_k| / A_k), joint j braking at a_j = 4·Δq_j / T²).
     * While it brakes, the structure of drive j carries the quasi-static deflection a_j/ω² ahead of
     * its motor, and released at the stop it rings as a damped single mode from rest there,
     * x(t) = e^(−ζωt)·(cos ω_d t + ζ/√(1−ζ²)·sin ω_d t), ω_d = ω√(1−ζ²) (the free response of a
     * viscously damped oscillator; W. T. Thomson, Theory of Vibration with Applications, §2.5): the
     * output at the reading, {@code dwellS} after the stop (plus up to {@code jitterS} more, uniform,
     * drawn from the pose: the controller's cycle and the instrument's averaging shift the moment of
     * the reading), is off by (a_j/ω²)·x(t). Nothing before the first move.
     */
    record Settling(int joint, double hz, double zeta, double dwellS, double jitterS, double[] accel) implements JointError {
        public Settling { accel = accel.clone(); }

        @Override public double delta(double[] q, Moment m) {
            if (m.lastMove() == null) return 0;
            double t = 0;
            for (int k = 0; k < m.lastMove().length && k < accel.length; k++) {
                double d = m.lastMove()[k];
                if (!Double.isFinite(d)) return 0;
                t = Math.max(t, 2 * Math.sqrt(Math.abs(d) / accel[k]));
            }
            if (!(t > 0)) return 0;
            double a = 4 * m.lastMove()[joint] / (t * t), w = 2 * Math.PI * hz, wd = w * Math.sqrt(1 - zeta * zeta);
            long h = 0x2545F4914F6CDD1DL;
            for (double v : q) h = Counts.mix(h ^ Double.doubleToLongBits(v));
            double at = dwellS + jitterS * ((h >>> 11) * 0x1.0p-53);
            double x = Math.exp(-zeta * w * at) * (Math.cos(wd * at) + zeta / Math.sqrt(1 - zeta * zeta) * Math.sin(wd * at));
            return a / (w * w) * x;
        }
    }

    /**
     * Outside every catalogue family: an absolute encoder whose reading jumps by {@code step} where
     * the joint passes {@code at} (a code-track defect, a misread bit): the output is off by the
     * step wherever q_joint is beyond that angle, whatever the time or the direction.
     */
    record AngleStep(int joint, double at, double step) implements JointError {
        @Override public double delta(double[] q, Moment m) { return q[joint] > at ? step : 0; }
    }
}
