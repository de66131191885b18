package org.robopro.world;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/** The truth record of a trial: what was concealed, in mm and degrees (SI where a key says so). */
final class Truth {
    private Truth() { }

    /** The truth of a scenario's robot, and of its campaign when one is given (else null). */
    static String json(Scenario scenario, long seed, WorldRobot w, Campaign.Result campaign) {
        Map<String, Object> root = new LinkedHashMap<>();
        root.put("scenario", scenario.name());
        root.put("family", scenario.family());
        root.put("robot", w.robotName());
        root.put("seed", seed);
        Map<String, Object> exp = new LinkedHashMap<>();
        exp.put("verdict", scenario.expected().verdict().name().toLowerCase(java.util.Locale.ROOT));
        List<Map<String, Object>> claims = new ArrayList<>();
        for (Expected.Claim c : scenario.expected().claims()) {
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("family", c.family().words);
            m.put("diagnosis_names", c.family().diagnosisNames.stream().sorted().toList());
            m.put("joints", c.joints());
            claims.add(m);
        }
        exp.put("claims", claims);
        root.put("expected", exp);
        if (campaign != null) {
            Campaign.Plan p = campaign.plan();
            root.put("campaign_seed", p.seed());
            root.put("sigma_mm", p.sigmaM() * 1e3);
            root.put("sigma_rot_deg", p.sixD() ? Math.toDegrees(p.sigmaRotRad()) : 0);
            root.put("poses", p.poses());
            root.put("validate_poses", p.validatePoses());
            root.put("order", p.order().name().toLowerCase(java.util.Locale.ROOT));
            root.put("start", p.start().name().toLowerCase(java.util.Locale.ROOT));
            if (p.approach() != null) {
                Campaign.Approach a = p.approach();
                root.put("approach", Map.of("side", Arrays.stream(a.side()).boxed().toList(), "min_deg", Math.toDegrees(a.minRad()),
                        "max_deg", Math.toDegrees(a.maxRad()), "other_side_share", a.otherSide()));
            }
            root.put("frame", campaign.frame());
            root.put("outlier_poses", campaign.rows().stream().filter(Campaign.Row::outlier).map(Campaign.Row::id).toList());
            Campaign.Warmup wu = campaign.warmup();
            root.put("warmup", Map.of("ambient_c", wu.ambientC(), "rise_k", wu.riseK(), "tau_s", wu.tauS()));
        }
        root.put("instrument_from_base", rigid(w.instrumentFromBase()));
        root.put("flange_to_target", rigid(w.flangeToTool()));
        root.put("zero_offsets_deg", Arrays.stream(w.zeroOffsets()).map(Math::toDegrees).boxed().toList());
        List<Map<String, Object>> joints = new ArrayList<>();
        Arm a = w.arm();
        for (int i = 0; i < a.dof(); i++)
            joints.add(Map.of("point_mm", mm(a.points()[i]), "axis", List.of(a.axes()[i][0], a.axes()[i][1], a.axes()[i][2])));
        root.put("joints", joints);
        root.put("flange_at_zero", rigid(a.flange()));
        List<List<Double>> c = new ArrayList<>();
        for (double[] row : w.coupling()) c.add(Arrays.stream(row).boxed().toList());
        root.put("coupling", c);
        List<Map<String, Object>> errors = new ArrayList<>();
        for (JointError e : w.errors()) errors.add(error(e));
        root.put("drive_errors", errors);
        if (w.thermal() != null) {
            WorldRobot.Thermal th = w.thermal();
            root.put("thermal", Map.of("ref_c", th.refC(), "link_alpha_per_k", Arrays.stream(th.linkAlpha()).boxed().toList(),
                    "holder_alpha_per_k", th.holderAlpha(),
                    "instrument_drift_mm_per_k", mm(th.driftPerK()), "instrument_drift_mm_per_s", mm(th.driftPerS())));
        }
        if (w.compliance() != null) {
            WorldRobot.Compliance co = w.compliance();
            List<Map<String, Object>> masses = new ArrayList<>();
            for (WorldRobot.Mass m : co.masses())
                masses.add(Map.of("joint", m.joint() + 1, "mass_kg", m.kg(), "centre_mm", mm(m.centre())));
            List<Object> k = new ArrayList<>();
            for (double s : co.stiffness()) k.add(Double.isInfinite(s) ? "rigid" : s);
            Map<String, Object> cm = new LinkedHashMap<>();
            cm.put("stiffness_nm_per_rad", k);
            cm.put("springs", co.springsInJoints() ? "in the joints' own angles: dtheta_i = tau_theta_i / k_i"
                    : "in the drives: dq_j = (C^T tau_theta)_j / k_j");
            cm.put("masses", masses);
            if (Arrays.stream(co.hardening()).anyMatch(Double::isFinite)) {
                List<Object> h = new ArrayList<>();
                for (double d : co.hardening()) h.add(Double.isInfinite(d) ? "linear" : Math.toDegrees(d));
                cm.put("hardening_deg", h);
                cm.put("hardening_form", "tau = k dq (1 + (dq/dh)^2): tangent stiffness k (1 + 3 (dq/dh)^2)");
            }
            root.put("compliance", cm);
        }
        if (w.tracker() != null) {
            WorldRobot.Tracker t = w.tracker();
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("form", "range' = range (1 + scale) + a sin(2 pi range / period + phase); az' = az + sum a_k sin(k az + phi_k); el' likewise; "
                    + "in the instrument's frame, azimuth about its own z");
            m.put("cyclic_um", t.cyclicM() * 1e6);
            m.put("cyclic_period_mm", t.periodM() * 1e3);
            m.put("cyclic_phase_rad", t.cyclicPhase());
            if (t.cyclicOverM().length > 0) {
                m.put("cyclic_overtones_um", Arrays.stream(t.cyclicOverM()).map(v -> v * 1e6).boxed().toList());
                m.put("cyclic_overtone_phases_rad", Arrays.stream(t.cyclicOverPhase()).boxed().toList());
            }
            m.put("range_scale", t.rangeScale());
            m.put("azimuth_cycles_per_turn", Arrays.stream(t.azK()).boxed().toList());
            m.put("azimuth_amplitude_arcsec", Arrays.stream(t.azAmp()).map(v -> Math.toDegrees(v) * 3600).boxed().toList());
            m.put("azimuth_phase_rad", Arrays.stream(t.azPhase()).boxed().toList());
            m.put("elevation_cycles_per_turn", Arrays.stream(t.elK()).boxed().toList());
            m.put("elevation_amplitude_arcsec", Arrays.stream(t.elAmp()).map(v -> Math.toDegrees(v) * 3600).boxed().toList());
            m.put("elevation_phase_rad", Arrays.stream(t.elPhase()).boxed().toList());
            if (t.airWarmK() != 0) {
                m.put("air_form", "range' = range (1 - 0.93e-6 warm (1 - exp(-t / tau))): the beam's air warms against the weather station's reading");
                m.put("air_warm_k", t.airWarmK());
                m.put("air_tau_s", t.airTauS());
            }
            if (t.resetS().length > 0) {
                m.put("beam_break_form", "range' = range + offset_i from beam break i on: the distance taken again from the absolute distance meter");
                m.put("beam_break_s", Arrays.stream(t.resetS()).boxed().toList());
                m.put("beam_break_offset_um", Arrays.stream(t.resetM()).map(v -> v * 1e6).boxed().toList());
            }
            root.put("tracker", m);
        }
        if (w.floorTilt() != null) {
            WorldRobot.FloorTilt f = w.floorTilt();
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("form", "the robot turns about a horizontal axis through a floor point by max (1 - exp(-t / tau))");
            m.put("axis_azimuth_deg", Math.toDegrees(f.azimuth()));
            m.put("pivot_mm", mm(f.pivot()));
            m.put("max_urad", f.maxRad() * 1e6);
            m.put("tau_s", f.tauS());
            root.put("floor_tilt", m);
        }
        if (w.dispensing() != null)
            root.put("dispensing", Map.of("form", "the flange carries kg(t), piecewise linear in time, whatever payload_kg records (outside)",
                    "times_s", Arrays.stream(w.dispensing().timesS()).boxed().toList(), "kg", Arrays.stream(w.dispensing().kg()).boxed().toList()));
        if (w.retractor() != null)
            root.put("retractor", Map.of("form", "a steady pull of force_n on the measured target toward the anchor, each drive yielding "
                    + "by its torque over its stiffness (outside)", "anchor_m", Arrays.stream(w.retractor().anchor()).boxed().toList(),
                    "force_n", w.retractor().forceN(), "stiffness_nm_per_rad", Arrays.stream(w.retractor().stiffness()).boxed().toList()));
        if (w.network() != null)
            root.put("network", Map.of("form", "poses whose target faces the second station better read from it, misregistered by a turn "
                    + "about it and a shift (outside)", "second_station_m", Arrays.stream(w.network().secondBase()).boxed().toList(),
                    "omega_urad", Arrays.stream(w.network().omegaRad()).map(x -> x * 1e6).boxed().toList(),
                    "shift_um", Arrays.stream(w.network().shiftM()).map(x -> x * 1e6).boxed().toList()));
        if (w.machine() != null) {
            WorldRobot.Machine m = w.machine();
            root.put("machine", Map.of("form", "the instrument a measuring machine reporting its scales' readings: p = (1+sx) u x + (1+sy) v y' "
                    + "+ w z' + (0, bow_y, bow_z) xi^2, y' = unit(-gxy, 1, 0), z' = unit(-gxz, -gyz, 1) (outside)",
                    "squareness_urad", List.of(m.gxy() * 1e6, m.gxz() * 1e6, m.gyz() * 1e6), "scale_ppm", List.of(m.sx() * 1e6, m.sy() * 1e6),
                    "bow_um", List.of(m.bowY() * 1e6, m.bowZ() * 1e6), "x_centre_m", m.centreM(), "x_half_travel_m", m.halfM()));
        }
        if (w.shaftTilt() != null)
            root.put("shaft_tilt", Map.of("form", "drive joint's output shaft turned by rad_per_nm (tau d + |tau| tan(pressure angle) n) about its "
                    + "bearing's centre, tau the drive's gravity torque (outside)", "joint", w.shaftTilt().joint() + 1,
                    "rad_per_nm", w.shaftTilt().radPerNm(), "pressure_angle_deg", Math.toDegrees(w.shaftTilt().pressureAngle()),
                    "phase_deg", Math.toDegrees(w.shaftTilt().phase()), "offset_mm", w.shaftTilt().offsetM() * 1e3));
        if (w.refraction() != null)
            root.put("refraction", Map.of("form", "the line of sight turned up by kappa L / 2 in its vertical plane, kappa = (n - 1) / T dT/dz / n, "
                    + "n - 1 = 2.7e-4 (outside)", "times_s", Arrays.stream(w.refraction().timesS()).boxed().toList(),
                    "gradient_k_per_m", Arrays.stream(w.refraction().kPerM()).boxed().toList()));
        if (w.twist() != null) {
            WorldRobot.Twist t = w.twist();
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("form", "everything beyond the upper arm turns about its axis (joint 2's point, toward joint 3's across joint 2's axis) "
                    + "by T / stiffness, T the moment about that axis of the weights beyond it and the payload");
            m.put("stiffness_nm_per_rad", t.stiffnessNmPerRad());
            m.put("payload_centre_mm", mm(t.payloadCentre()));
            List<Map<String, Object>> masses = new ArrayList<>();
            for (WorldRobot.Mass ms : t.masses()) masses.add(Map.of("joint", ms.joint() + 1, "mass_kg", ms.kg(), "centre_mm", mm(ms.centre())));
            m.put("masses", masses);
            root.put("upper_arm_twist", m);
        }
        if (w.rocking() != null) {
            WorldRobot.Rocking ro = w.rocking();
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("form", "square foot in z = -depth on the base axes; about the foot edge with the largest overturning moment M of the "
                    + "arm's weight and payload: tilt = (M - hold) / stiffness when M > hold, else none");
            m.put("half_width_mm", ro.halfWidthM() * 1e3);
            m.put("foot_depth_mm", ro.footDepthM() * 1e3);
            m.put("hold_moment_nm", ro.holdMomentNm());
            m.put("stiffness_nm_per_rad", ro.stiffnessNmPerRad());
            List<Map<String, Object>> masses = new ArrayList<>();
            for (WorldRobot.Mass ms : ro.masses()) masses.add(Map.of("joint", ms.joint() + 1, "mass_kg", ms.kg(), "centre_mm", mm(ms.centre())));
            m.put("masses", masses);
            root.put("rocking", m);
        }
        if (w.dressPack() != null) {
            WorldRobot.DressPack d = w.dressPack();
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("form", "s = r sqrt((theta4 + theta6)^2 + (bend (theta5 - centre))^2); T = k_hose (s - r slack) when taut; "
                    + "tau_j = -T ds/dtheta_j; each wrist drive yields tau_q / k");
            m.put("radius_mm", d.radiusM() * 1e3);
            m.put("slack_deg", Math.toDegrees(d.slackRad()));
            m.put("bend", d.bend());
            m.put("bend_centre_deg", Math.toDegrees(d.bendCentreRad()));
            m.put("hose_stiffness_n_per_m", d.hoseStiffnessNPerM());
            m.put("wrist_stiffness_nm_per_rad", Arrays.stream(d.wristStiffness()).boxed().toList());
            root.put("dress_pack", m);
        }
        if (w.targetPlay() != null)
            root.put("target_play", Map.of("clearance_mm", w.targetPlay().clearanceM() * 1e3, "friction_deg", Math.toDegrees(w.targetPlay().frictionRad()),
                    "form", "the target moved in the flange's frame by clearance * min(1, |g_xy| / sin(friction)) * g_xy / |g_xy|, g gravity seen from the flange"));
        if (!w.wobbles().isEmpty()) {
            List<Map<String, Object>> ws = new ArrayList<>();
            for (WorldRobot.Wobble wb : w.wobbles()) {
                Map<String, Object> m = new LinkedHashMap<>();
                m.put("joint", wb.joint() + 1);
                m.put("tilt_deg", Math.toDegrees(wb.tiltRad()));
                m.put("ratio", wb.ratio());
                m.put("phase_rad", wb.phase());
                if (wb.axialM() != 0) {
                    m.put("axial_mm", wb.axialM() * 1e3);
                    m.put("lobes", wb.lobes());
                    m.put("axial_phase_rad", wb.axialPhase());
                    m.put("axial_form", "everything outboard moved along w by axial cos(lobes theta + axial_phase), after the tilt");
                }
                m.put("form", "the axis w (joint's true axis at zero) tilted by tilt about d = cos(ratio theta + phase) u + sin(ratio theta + phase) v "
                        + "through its axis point; u = w x (the base axis least along w), normalised; v = w x u; theta the model angle");
                ws.add(m);
            }
            root.put("bearing_wobbles", ws);
        }
        if (w.sag() != null)
            root.put("sag", Map.of("size_mm", w.sag().sizeM() * 1e3, "per_kg_mm", w.sag().perKgM() * 1e3, "ref_reach_m", w.sag().refReachM()));
        if (w.toolBump() != null && Double.isFinite(w.toolBump().atS()))
            root.put("tool_bump", Map.of("at_s", w.toolBump().atS(), "shift_mm", mm(w.toolBump().shiftM()),
                    "turn_deg", Arrays.stream(w.toolBump().turnRad()).map(Math::toDegrees).boxed().toList()));
        if (w.toolBump() != null && w.toolBump().spindle() != null) {
            var sp = w.toolBump().spindle();
            root.put("spindle", Map.of("type", "tool growing along the flange's axis as its spindle runs (outside)",
                    "on_s", Arrays.stream(sp.onS()).boxed().toList(), "off_s", Arrays.stream(sp.offS()).boxed().toList(),
                    "peak_mm", sp.peakM() * 1e3, "tau_s", sp.tauS()));
        }
        try {
            return new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT).writeValueAsString(root);
        } catch (JsonProcessingException e) {
            throw new IllegalStateException(e);
        }
    }

    static Map<String, Object> error(JointError e) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("joint", e.joint() + 1);
        if (e instanceof JointError.Harmonics h) {
            m.put("type", "transmission error");
            m.put("cycles_per_turn", Arrays.stream(h.k()).boxed().toList());
            m.put("amplitude_deg", Arrays.stream(h.amplitude()).map(Math::toDegrees).boxed().toList());
            m.put("phase_rad", Arrays.stream(h.phase()).boxed().toList());
        } else if (e instanceof JointError.LostMotion b) {
            m.put("type", "lost motion (output = q - b/2 dir)");
            m.put("width_deg", Math.toDegrees(b.width()));
        } else if (e instanceof JointError.Scale s) {
            m.put("type", "gear-ratio error");
            m.put("eps", s.eps());
        } else if (e instanceof JointError.Coupling c) {
            m.put("type", "cross-coupling");
            m.put("source", c.source() + 1);
            m.put("kappa", c.kappa());
        } else if (e instanceof JointError.LinkageRod l) {
            m.put("type", "parallel-arm rod of another length than the upper arm's pivot distance (outside): four-bar closure");
            m.put("upper_joint", "j" + (l.upper() + 1));
            m.put("ground_mm", l.groundM() * 1e3);
            m.put("crank_mm", l.crankM() * 1e3);
            m.put("lever_mm", l.leverM() * 1e3);
            m.put("rod_mm", l.rodM() * 1e3);
            m.put("psi0_deg", Math.toDegrees(l.psi0()));
        } else if (e instanceof JointError.Bump b) {
            m.put("type", "bump (outside)");
            m.put("centre_deg", Math.toDegrees(b.centre()));
            m.put("width_deg", Math.toDegrees(b.width()));
            m.put("amplitude_deg", Math.toDegrees(b.amplitude()));
        } else if (e instanceof JointError.TwoJoint tj) {
            m.put("type", "two-joint error (outside)");
            m.put("other", tj.other() + 1);
            m.put("amplitude_deg", Math.toDegrees(tj.amplitude()));
        } else if (e instanceof JointError.AsymmetricLostMotion a) {
            m.put("type", "lost motion, unequal flanks (output = q - up/2 after a rise, q + down/2 after a fall)");
            m.put("up_deg", Math.toDegrees(a.up()));
            m.put("down_deg", Math.toDegrees(a.down()));
        } else if (e instanceof JointError.WindUpLostMotion wu) {
            m.put("type", "lost motion building up over the move (output = q - b/2 dir (1 - exp(-|move|/x0)))");
            m.put("width_deg", Math.toDegrees(wu.width()));
            m.put("build_up_deg", Math.toDegrees(wu.buildUp()));
        } else if (e instanceof JointError.GravityHeldLostMotion g) {
            m.put("type", "lost motion held by gravity (output = q - b/2 flank; flank = -sign(tau_q) where |tau_q| > hold, else dir)");
            m.put("width_deg", Math.toDegrees(g.width()));
            m.put("hold_torque_nm", g.holdTorque());
        } else if (e instanceof JointError.LoadedHarmonic lh) {
            m.put("type", "transmission error growing with the load (output = q + (a0 + a1 tau_q/tau_ref) sin(k q + phase)) (outside)");
            m.put("cycles_per_turn", lh.k());
            m.put("unloaded_deg", Math.toDegrees(lh.unloaded()));
            m.put("loaded_deg", Math.toDegrees(lh.loaded()));
            m.put("torque_ref_nm", lh.torqueRef());
            m.put("phase_rad", lh.phase());
        } else if (e instanceof JointError.Slip sl) {
            m.put("type", "encoder slip (outside)");
            m.put("at_s", sl.atS());
            m.put("step_deg", Math.toDegrees(sl.step()));
        } else if (e instanceof JointError.Creep c) {
            m.put("type", "zero creeping with time (outside)");
            m.put("deg_per_hour", Math.toDegrees(c.ratePerS()) * 3600);
        } else if (e instanceof JointError.DriveThermal dt) {
            m.put("type", "drive zero moving with temperature (outside)");
            m.put("deg_per_k", Math.toDegrees(dt.perK()));
            m.put("ref_c", dt.refC());
        } else if (e instanceof JointError.GasSpring gs) {
            m.put("type", "gas-spring balancer bending the drive (outside)");
            m.put("arm_m", gs.rM());
            m.put("anchor_m", gs.lM());
            m.put("phi0_deg", Math.toDegrees(gs.phi0()));
            m.put("force_n", gs.f0N());
            m.put("stiffness_nm_per_rad", gs.stiffness());
        } else if (e instanceof JointError.HoseTwist h) {
            m.put("type", "hose twisted by the joint, stiffer as another joint bends (outside): -c (q - neutral)(1 + beta (1 - cos q_bend))");
            m.put("bend_joint", h.bend() + 1);
            m.put("c", h.c());
            m.put("neutral_deg", Math.toDegrees(h.neutral()));
            m.put("beta", h.beta());
        } else if (e instanceof JointError.WarmSoftening ws) {
            m.put("type", "joint softening as it warms (outside): output += tau_q per_k (T - ref) / k0");
            m.put("stiffness_nm_per_rad", ws.stiffness());
            m.put("per_k", ws.perK());
            m.put("ref_c", ws.refC());
        } else if (e instanceof JointError.LinkHarmonic lh) {
            m.put("type", "error repeating with a link angle (outside): output += a sin(k (q_joint + sign q_other) + phase)");
            m.put("other", lh.other() + 1);
            m.put("sign", lh.sign());
            m.put("cycles_per_turn", lh.k());
            m.put("amplitude_deg", Math.toDegrees(lh.amplitude()));
            m.put("phase_rad", lh.phase());
        } else if (e instanceof JointError.QuadratureGain qg) {
            m.put("type", "encoder channels' gains drifting apart with temperature (outside): q = atan2((1 + g) sin theta, cos theta), g = per_k (T - ref)");
            m.put("gain_per_k", qg.gainPerK());
            m.put("ref_c", qg.refC());
        } else if (e instanceof JointError.OvalSeat os) {
            m.put("type", "drive through an oval bearing seat in another joint's housing (outside): output += e cos 2(q_housing - major) tan(alpha) / r");
            m.put("housing", os.housing() + 1);
            m.put("ovality_um", os.ovality() * 1e6);
            m.put("pressure_angle_deg", Math.toDegrees(os.pressureAngle()));
            m.put("radius_mm", os.radius() * 1e3);
            m.put("major_deg", Math.toDegrees(os.major()));
        } else if (e instanceof JointError.MotorWarm mw) {
            m.put("type", "drive zero moving as its motor warms (outside)");
            m.put("shift_deg", Math.toDegrees(mw.shift()));
            m.put("tau_s", mw.tauS());
        }
        return m;
    }

    static Map<String, Object> rigid(Rigid r) {
        return Map.of("position_mm", mm(r.p()), "quaternion_wxyz", Arrays.stream(r.quaternion()).boxed().toList());
    }

    static List<Double> mm(double[] v) { return List.of(v[0] * 1e3, v[1] * 1e3, v[2] * 1e3); }
}
