package org.robopro.calibration.diagnosis;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.robopro.calibration.PoseConditions;
import org.robopro.calibration.measurement.Measurement;

/** Evidence plot data for a finding (see {@link Diagnosis.Plot}). */
final class Plots {
    private Plots() { }

    /**
     * Partial residuals: per pose, the effect's own value plus the final residual resolved along
     * the effect's signature, y_i = g_i·v − d_iᵀ r_i / ‖d_i‖² (r = predicted − measured) (d_i: the pose's residual rows'
     * sensitivity to the effect's Δθ or strain). Poses where the measured point barely moves
     * with the effect (‖d_i‖ below 0.3 x the median) are left out: they carry no information.
     * Angles in millidegrees, strains in ppm.
     */
    static Diagnosis.Plot partialResidual(Diagnoser.Tester t, Effect e, double[] v) {
        if (e.kind() == Effect.Kind.BASE_TURN && t.ends == 1) return turn(t, e, v);
        if (e.kind() == Effect.Kind.INSTRUMENT_SCALE && t.ends == 1) return scale(t, e, v);
        if (e.target() == Effect.Target.POSITION) return alongDisplacement(t, e, v);
        int rpp = t.rpp, poses = t.m / rpp, dof = t.dof;
        // A distance between two poses is put at the pose that carries more of the effect's change
        // of it (its own sensitivity times the effect's value there); the other pose's share is noise.
        int[] end = new int[poses];
        for (int i = 0; t.ends > 1 && i < poses; i++) {
            double best = -1;
            for (int k = 0; k < t.ends; k++) {
                double d = e.isStrain() ? t.endDStrain[k][i] : e.driveDerivative(t.endDQ[k], i * dof);
                double c = Math.abs(d * e.valueAt(v, t.endRows.get(k).get(i), t.endConditions.get(k).get(i)));
                if (c > best) { best = c; end[i] = k; }
            }
        }
        double[] dn = new double[poses];
        for (int i = 0; i < poses; i++) {
            double s = 0;
            for (int a = 0; a < t.posRows; a++) {
                double d = e.isStrain() ? t.endDStrain[end[i]][i * rpp + a] : e.driveDerivative(t.endDQ[end[i]], (i * rpp + a) * dof);
                s += d * d;
            }
            dn[i] = s;
        }
        double[] sorted = dn.clone();
        Arrays.sort(sorted);
        double cut = 0.09 * sorted[poses / 2];
        double unit = e.isStrain() ? 1e6 : Math.toDegrees(1) * 1e3;
        List<double[]> pts = new ArrayList<>();
        for (int i = 0; i < poses; i++) {
            if (!(dn[i] > cut) || dn[i] == 0) continue;
            Measurement row = t.endRows.get(end[i]).get(i);
            PoseConditions c = t.endConditions.get(end[i]).get(i);
            double proj = 0;
            for (int a = 0; a < t.posRows; a++) {
                double d = e.isStrain() ? t.endDStrain[end[i]][i * rpp + a] : e.driveDerivative(t.endDQ[end[i]], (i * rpp + a) * dof);
                proj += d * t.fit.r[i * rpp + a];
            }
            double y = e.valueAt(v, row, c) - proj / dn[i]; // residual is predicted - measured
            double x = xOf(e, row, c);
            if (e.runout()) {
                // the play at this pose: the lag −(b(q)/2)·dir·share over its direction and built-up share
                int dir = c.direction(e.joint());
                double share = e.buildsUp() ? e.windUpShare(row, dir) : 1;
                if (dir == 0 || share < 0.5) continue;
                y = -2 * y / (dir * share);
            } else if (e.kind() == Effect.Kind.BACKLASH && !e.buildsUp() && !e.heldByGravity())
                x += 0.3 * (((i * 0.6180339887) % 1) - 0.5); // spread the two columns of points
            pts.add(new double[] {x, y * unit});
        }
        double[] x = new double[pts.size()], y = new double[pts.size()];
        for (int i = 0; i < x.length; i++) { x[i] = pts.get(i)[0]; y[i] = pts.get(i)[1]; }
        double lo = Arrays.stream(x).min().orElse(0), hi = Arrays.stream(x).max().orElse(1);
        int nc = e.kind() == Effect.Kind.PERIODIC || e.kind() == Effect.Kind.LINK_PERIODIC || e.kind() == Effect.Kind.SMOOTH || e.buildsUp() || e.heldByGravity() || e.stiffens()
                || e.runout() ? 400 : 2;
        // a high stage order: enough curve points for about 16 per cycle over the range
        if (e.kind() == Effect.Kind.PERIODIC) nc = (int) Math.max(nc, Math.min(20000, 16 * maxOrder(e) * (hi - lo) / 360));
        double[] cx = new double[nc], cy = new double[nc];
        for (int i = 0; i < nc; i++) {
            cx[i] = lo + (hi - lo) * i / (nc - 1);
            cy[i] = curve(e, v, cx[i]) * unit;
        }
        if (nc > 0 && Double.isNaN(cy[0])) { cx = new double[0]; cy = new double[0]; } // no curve in this variable
        double[] gram = null;
        if (e.kind() == Effect.Kind.PERIODIC) gram = periodogram(x, y, Math.max(8, (int) Math.ceil(maxOrder(e)) + 2));
        return new Diagnosis.Plot(t.ends > 1 ? xLabel(e) + ", at the pose of the pair that carries more of the change" : xLabel(e), e.isStrain() ? "partial residual strain (ppm)"
                : e.runout() ? "play of joint " + (e.joint() + 1) + " from each pose's partial residual (mdeg)"
                : "partial residual of joint " + (e.joint() + 1) + " angle (mdeg)", x, y, cx, cy, gram);
    }

    private static double maxOrder(Effect e) { return Arrays.stream(e.orders()).max().orElse(1); }

    static String xLabel(Effect e) {
        return switch (e.kind()) {
            case COMPLIANCE -> e.perMass() ? "joint " + (e.joint() + 1) + " angle q" + (e.joint() + 1) + " (deg)"
                    : e.atJoint() ? "gravity torque about joint " + (e.joint() + 1) + "'s own axis (N·m)"
                    : "gravity torque on drive " + (e.joint() + 1) + " (N·m)";
            case PERIODIC, LOAD_PERIODIC, WARM_PERIODIC, SCALE, SMOOTH, PAIR -> "joint " + (e.angleJoint() + 1) + " angle " + (e.followsModelAngle() ? "θ" : "q") + (e.angleJoint() + 1) + " (deg)";
            case POINT_SMOOTH -> switch (e.along()) {
                case REACH -> "reach of the measured point (m)";
                case HEIGHT -> "height of the measured point (m)";
                case TIME -> "time since start (s)";
                case TEMPERATURE -> "temperature (°C)";
                case PAYLOAD_REACH -> "reach of the measured point (m), times the payload";
            };
            case ZERO_STEP, TARGET_STEP, TARGET_DRIFT, BASE_CREEP, BASE_STEP, RANGE_STEP -> "time since start (s)";
            case BASE_TILT -> "moment of the arm's weight about the base's tipping axis (N·m)";
            case AXIS_WOBBLE, AXIAL_RUNOUT -> "joint " + (e.joint() + 1) + " angle q" + (e.joint() + 1) + " (deg)";
            case TOOL_SAG, TOOL_PLAY -> "angle of the flange's axis from straight down (deg)";
            case TARGET_INCIDENCE -> "angle of the line of sight from its mean direction in the tool's frame (deg)";
            case LINK_SAG -> "share of gravity across link " + (e.joint() + 1) + " (g)";
            case LINK_TWIST -> "the flange's lever across the upper arm's plane, times gravity across the arm (m)";
            case TOOL_PULL -> "azimuth of the pull's point on the tool about axis 1 (deg)";
            case LOAD_TILT -> "gravity torque on drive " + (e.joint() + 1) + " (N·m)";
            case SECOND_STATION -> "the flange axis's part along the second station's side (positive: read from it)";
            case INSTRUMENT -> "the instrument's " + e.sight().words + " reading" + (e.sight() == Effect.Sight.RANGE ? " (m)" : " (deg)");
            case INSTRUMENT_AXES -> "distance of the measured point from the instrument's origin (m)";
            case ANGLE_STEP -> "joint " + (e.joint() + 1) + " angle q" + (e.joint() + 1) + " (deg)";
            case ZERO_DRIFT, BASE_TURN, INSTRUMENT_SCALE, REFRACTION -> e.along() == Effect.Along.TIME ? "time since start (s)" : "temperature (°C)";
            case THERMAL_LINK -> "temperature (°C)";
            case DRIFT -> e.usesTimeProxy() ? "time since start (s)" : "temperature (°C)";
            case BACKLASH -> e.runout() ? "joint " + (e.joint() + 1) + " angle q" + (e.joint() + 1) + " (deg)"
                    : e.approached() ? "travel of joint " + (e.joint() + 1) + " since it last turned, approach included, "
                    + "signed by its direction (deg)"
                    : e.buildsUp() ? "last move of joint " + (e.joint() + 1) + " before the pose, signed (deg)"
                    : e.heldByGravity() ? "gravity torque on drive " + (e.joint() + 1) + " (N·m)"
                    : "approach direction dir" + (e.joint() + 1);
            case THERMAL -> e.usesTimeProxy() ? "time since start (s)" : "temperature (°C)";
            case COUPLING -> "joint " + (e.source() + 1) + " angle q" + (e.source() + 1) + " (deg)";
            case SETTLING -> "speed of joint " + (e.joint() + 1) + " in the move before the reading, synchronised (deg/s)";
            case GRAVITY_PLAY -> "gravity torque on drive " + (e.joint() + 1) + " (N·m)";
            case LINK_PERIODIC -> "link angle " + e.linkAngleText() + " (deg)";
            case COMPLIANCE_VARYING -> (e.payloadShare() ? "the payload's gravity torque on drive " : "gravity torque on drive ") + (e.joint() + 1)
                    + " (N·m; the compliance changes with " + e.along().words + ")";
        };
    }

    private static double xOf(Effect e, Measurement row, PoseConditions c) {
        return switch (e.kind()) {
            case COMPLIANCE -> e.perMass() ? Math.toDegrees(row.q(e.joint())) : e.complianceTorque(row.q(), c.payloadKg());
            case PERIODIC, LOAD_PERIODIC, WARM_PERIODIC, SCALE, PAIR -> Math.toDegrees(row.q(e.angleJoint()));
            case SMOOTH -> Math.toDegrees(e.smoothVariable(row.q()));
            case POINT_SMOOTH -> e.along() == Effect.Along.TIME ? c.timeS() : e.along() == Effect.Along.TEMPERATURE ? c.tempC()
                    : Double.NaN; // reach, height: from the predicted point (alongDisplacement)
            case ZERO_DRIFT, BASE_TURN, INSTRUMENT_SCALE, REFRACTION -> e.along() == Effect.Along.TIME ? c.timeS() : c.tempC();
            case ZERO_STEP, TARGET_STEP, TARGET_DRIFT, BASE_CREEP, BASE_STEP, RANGE_STEP -> c.timeS();
            case INSTRUMENT, INSTRUMENT_AXES -> Double.NaN; // from the predicted point (alongDisplacement)
            case BASE_TILT -> e.tiltExcess(row.q(), c.payloadKg()) + (Double.isInfinite(e.tiltHold()) ? 0 : e.tiltHold());
            case ANGLE_STEP, AXIS_WOBBLE, AXIAL_RUNOUT -> Math.toDegrees(row.q(e.joint()));
            case LINK_SAG -> e.sagAcross(row.q());
            case LINK_TWIST -> e.twistLever(row.q());
            case TOOL_PULL -> e.pullAzimuthDeg(row.q());
            case SECOND_STATION -> e.facingPart(row.q());
            case LOAD_TILT -> e.gravity().driveTorques(row.q(), Double.isFinite(c.payloadKg()) ? c.payloadKg() : 0)[e.joint()];
            case TOOL_SAG, TOOL_PLAY -> Effect.angleFromDown(e.model().flange(row.q()), e.down());
            case TARGET_INCIDENCE -> Double.NaN; // from the predicted point (alongDisplacement)
            case THERMAL_LINK -> c.tempC();
            case DRIFT -> e.usesTimeProxy() ? c.timeS() : c.tempC();
            case BACKLASH -> {
                double travel = e.buildsUp() ? e.travel(row, c.direction(e.joint())) : Double.NaN;
                yield e.runout() ? Math.toDegrees(row.q(e.joint()))
                        : Double.isFinite(travel) ? c.direction(e.joint()) * Math.toDegrees(Math.abs(travel))
                        : e.heldByGravity() ? e.holdingTorque(row.q(), c.payloadKg()) : c.direction(e.joint());
            }
            case THERMAL -> e.usesTimeProxy() ? c.timeS() : c.tempC();
            case COUPLING -> Math.toDegrees(row.q(e.source()));
            case SETTLING -> Math.toDegrees(e.settlingSpeed(row));
            case GRAVITY_PLAY -> e.gravity().driveTorques(row.q(), Double.isFinite(c.payloadKg()) ? c.payloadKg() : 0)[e.joint()];
            case LINK_PERIODIC -> Math.toDegrees(e.linkAngleAt(row.q()));
            case COMPLIANCE_VARYING -> {
                double p = Double.isFinite(c.payloadKg()) ? c.payloadKg() : 0;
                yield e.gravity().driveTorques(row.q(), p)[e.joint()] - (e.payloadShare() ? e.gravity().driveTorques(row.q(), 0)[e.joint()] : 0);
            }
        };
    }

    /** The fitted effect (rad or strain) as a function of the plot's x (deg for a joint's angle); NaN where it is no function of it. */
    static double curve(Effect e, double[] v, double x) {
        return switch (e.kind()) {
            case COMPLIANCE -> e.perMass() ? Double.NaN : e.stiffens() ? v[0] * x + v[1] * x * x * x : v[0] * x;
            case PERIODIC -> {
                double q = Math.toRadians(x), s = 0;
                double[] hs = e.orders();
                for (int i = 0; i < hs.length; i++) s += v[2 * i] * Math.sin(hs[i] * q) + v[2 * i + 1] * Math.cos(hs[i] * q);
                yield s;
            }
            case LINK_PERIODIC -> {
                double psi = Math.toRadians(x), s = 0;
                int[] hs = e.harmonics();
                for (int i = 0; i < hs.length; i++) s += v[2 * i] * Math.sin(hs[i] * psi) + v[2 * i + 1] * Math.cos(hs[i] * psi);
                yield s;
            }
            case SMOOTH -> {
                double[] g = new double[e.basisCount()];
                Effect.bspline(Math.toRadians(x), e.rangeLo(), e.rangeHi(), g);
                double s = 0;
                for (int i = 0; i < g.length; i++) s += g[i] * v[i];
                yield s;
            }
            // a load-periodic error is no function of the angle alone: its size follows the load
            case LOAD_PERIODIC, WARM_PERIODIC, COMPLIANCE_VARYING, THERMAL_LINK, DRIFT, POINT_SMOOTH, BASE_TURN, PAIR, INSTRUMENT, INSTRUMENT_SCALE, INSTRUMENT_AXES, REFRACTION, BASE_TILT, AXIS_WOBBLE, AXIAL_RUNOUT, TOOL_SAG, TOOL_PLAY, LINK_SAG, LINK_TWIST, TARGET_INCIDENCE, TOOL_PULL, LOAD_TILT, SECOND_STATION -> Double.NaN;
            case ZERO_STEP -> x <= e.tauS() ? -v[0] : 0;
            case ANGLE_STEP -> Math.toRadians(x) > e.rangeLo() && !(Math.toRadians(x) > e.rangeHi()) ? v[0] : 0;
            case TARGET_STEP, TARGET_DRIFT, BASE_CREEP, BASE_STEP, RANGE_STEP -> Double.NaN;
            case ZERO_DRIFT -> {
                double[] g = new double[e.basisCount()];
                Effect.bspline(x, e.rangeLo(), e.rangeHi(), g);
                double s = 0;
                for (int i = 0; i < g.length; i++) s += g[i] * v[i];
                yield s;
            }
            case BACKLASH -> e.runout() // the play over the turn: b + Σ b_cos,f·cos f q + b_sin,f·sin f q
                    ? Effect.play(e.runoutOrders(), v, Math.toRadians(x))
                    : e.buildsUp() // the lag builds up with the move: −(b/2)·dir·(1 − exp(−|move|/x0))
                    ? -0.5 * v[0] * Math.signum(x) * Effect.windUpShare(Math.toRadians(x), e.buildUpRad())
                    // held on the flank the torque pushes it to; where the torque is small the direction decides (shown at the centre)
                    : e.heldByGravity() ? e.heldShare(x) * 0.5 * v[0] * Math.signum(x)
                    : -0.5 * v[0] * x; // output lags: θ − q = −(b/2)·dir
            case THERMAL -> e.usesTimeProxy() ? v[0] * (1 - Math.exp(-x / e.tauS())) : v[0] * (x - e.t0C());
            case SCALE, COUPLING, SETTLING -> v[0] * Math.toRadians(x);
            case GRAVITY_PLAY -> 0.5 * v[0] * e.playSide(x);
        };
    }

    /**
     * For an effect on the measured point: per measurement (each measured point of a pose, or each
     * distance), the effect's fitted displacement c_i (residual units) and the partial residual
     * along it, ‖c_i‖ − ĉ_i·r_i, in mm, against the effect's variable.
     */
    static Diagnosis.Plot alongDisplacement(Diagnoser.Tester t, Effect e, double[] v) {
        int k = e.size(), n = t.measurements(), d = t.dim;
        double[] s = t.signature(e, t.w.conditions);
        // a step in time moves no pose after it: there the residual is taken along the way the step would have moved the pose
        double[] sBefore = e.stepInTime() ? t.signature(e, t.w.conditions.stream()
                .map(c -> new PoseConditions(c.directions(), e.tauS(), c.tempC(), c.payloadKg())).toList()) : null;
        double[] x = new double[n], y = new double[n], fx = new double[n], fy = new double[n];
        double unit = t.fit.problem.sigmaPos() * 1e3;
        for (int mi = 0; mi < n; mi++) {
            int r0 = t.rowOf(mi), i = t.poseOf(mi);
            double[] c = new double[d], dir = new double[d];
            for (int a = 0; a < d; a++) for (int col = 0; col < k; col++) c[a] += s[(r0 + a) * k + col] * v[col];
            double nc = 0;
            for (double cv : c) nc += cv * cv;
            nc = Math.sqrt(nc);
            if (nc == 0 && sBefore != null) for (int a = 0; a < d; a++) for (int col = 0; col < k; col++) dir[a] += sBefore[(r0 + a) * k + col] * v[col];
            else System.arraycopy(c, 0, dir, 0, d);
            double nd = 0;
            for (double dv : dir) nd += dv * dv;
            nd = Math.sqrt(nd);
            double along = 0;
            if (nd > 0) for (int a = 0; a < d; a++) along += dir[a] / nd * t.fit.r[r0 + a];
            double[] pb = t.pointsBase[i][d == 3 ? (r0 - i * t.rpp) / 3 : 0];
            double pv = e.kind() == Effect.Kind.POINT_SMOOTH ? e.pointVariable(pb)
                    : e.kind() == Effect.Kind.INSTRUMENT ? e.sightReadingOf(pb) * (e.sight() == Effect.Sight.RANGE ? 1 : 180 / Math.PI)
                    : e.kind() == Effect.Kind.TARGET_INCIDENCE ? e.incidenceAngle(t.w.rows.get(i).q(), pb)
                    : e.kind() == Effect.Kind.INSTRUMENT_AXES ? e.instrumentDistanceOf(pb) : Double.NaN;
            x[mi] = Double.isFinite(pv) ? pv : xOf(e, t.w.rows.get(i), t.w.conditions.get(i));
            y[mi] = (nc - along) * unit;
            fx[mi] = x[mi];
            fy[mi] = nc * unit;
        }
        return new Diagnosis.Plot(xLabel(e), d == 1 ? "partial residual of the distance along the effect's change (mm)"
                : "partial residual along the effect's displacement (mm)", x, y, fx, fy, null);
    }

    /**
     * A turn of the base or the instrument ({@link Effect#baseTurn}) as its angle about the fitted
     * turn's main axis â (the leading eigenvector of Σ (ω_i − ω̄)(ω_i − ω̄)ᵀ over the poses, signed so that the
     * turn grows over the range) against time or temperature, from its value at the start of the
     * range (a constant turn is the geometry's): the fitted angle θ(u) = ω(u)·â as the curve, and per
     * pose the partial residual along a further turn about â (the B-spline's functions sum to 1, so
     * that is the sum of the turn's columns weighted by â). The partial residual along the
     * displacement would mix each pose's lever arm into the size; this shows the tilt growing. Millidegrees.
     */
    static Diagnosis.Plot turn(Diagnoser.Tester t, Effect e, double[] v) {
        int k = e.size(), nb = e.basisCount(), poses = t.m / t.rpp;
        double[][] w = new double[poses][];
        double[] mm = new double[9], mean = new double[3];
        for (int i = 0; i < poses; i++) {
            w[i] = e.rotation(v, t.w.rows.get(i).q(), t.w.conditions.get(i)).toArray();
            for (int a = 0; a < 3; a++) mean[a] += w[i][a] / poses;
        }
        // the axis of the turn's change: a constant turn is the geometry's, and the spline's constant part is whatever is left of it
        for (int i = 0; i < poses; i++)
            for (int a = 0; a < 3; a++) for (int b = 0; b < 3; b++) mm[3 * a + b] += (w[i][a] - mean[a]) * (w[i][b] - mean[b]);
        double[] axis = {1, 1, 1};
        for (int it = 0; it < 100; it++) { // power iteration: mm is symmetric and positive semi-definite
            double[] n = new double[3];
            for (int a = 0; a < 3; a++) for (int b = 0; b < 3; b++) n[a] += mm[3 * a + b] * axis[b];
            double len = Math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            if (!(len > 0)) break;
            for (int a = 0; a < 3; a++) axis[a] = n[a] / len;
        }
        // a constant turn is the geometry's (the fit holds it): angles from the start of the range
        if (turnAt(e, v, axis, e.rangeHi()) < turnAt(e, v, axis, e.rangeLo())) for (int a = 0; a < 3; a++) axis[a] = -axis[a];
        double[] cols = new double[k];
        for (int a = 0; a < 3; a++) for (int j = 0; j < nb; j++) cols[a * nb + j] = axis[a];
        return alongReading(t, e, cols, i -> w[i][0] * axis[0] + w[i][1] * axis[1] + w[i][2] * axis[2], u -> turnAt(e, v, axis, u),
                Math.toDegrees(1) * 1e3, String.format(java.util.Locale.ROOT, "turn about (%.2f, %.2f, %.2f), base axes (mdeg)", axis[0], axis[1], axis[2]));
    }

    /**
     * The instrument's distance scale ({@link Effect#instrumentScale}) against time or temperature,
     * from its value at the start of the range (a constant scale is the geometry's): the fitted
     * scale as the curve, and per pose the partial residual along a further scale (the sum of the
     * effect's columns: its B-spline's functions sum to 1). Parts per million.
     */
    static Diagnosis.Plot scale(Diagnoser.Tester t, Effect e, double[] v) {
        double[] cols = new double[e.size()];
        Arrays.fill(cols, 1);
        return alongReading(t, e, cols, i -> e.splineAt(v, 0, xOf(e, t.w.rows.get(i), t.w.conditions.get(i))), u -> e.splineAt(v, 0, u), 1e6,
                "scale of the instrument's distances (ppm)");
    }

    /**
     * A quantity of an effect along time or temperature: per pose its fitted value f_i and the partial
     * residual f_i − d_iᵀ r_i / ‖d_i‖², d_i the pose's residual rows' sensitivity to a further amount of
     * it (the effect's signature columns weighted by {@code cols}); the fitted {@code curve} over the
     * effect's range; both from the curve's value at the start of the range, times {@code unit}. Poses
     * whose point barely moves with it (‖d_i‖ below 0.3 x the median) or whose reading is unknown are left out.
     */
    private static Diagnosis.Plot alongReading(Diagnoser.Tester t, Effect e, double[] cols, java.util.function.IntToDoubleFunction fitted,
                                               java.util.function.DoubleUnaryOperator curve, double unit, String yLabel) {
        int k = e.size(), poses = t.m / t.rpp, rpp = t.rpp;
        double[] s = t.signature(e, t.w.conditions);
        double[] d = new double[t.m], dn = new double[poses];
        for (int row = 0; row < t.m; row++) {
            for (int c = 0; c < k; c++) d[row] += s[row * k + c] * cols[c];
            dn[row / rpp] += d[row] * d[row];
        }
        double[] sorted = dn.clone();
        Arrays.sort(sorted);
        double cut = 0.09 * sorted[poses / 2], start = curve.applyAsDouble(e.rangeLo());
        List<double[]> pts = new ArrayList<>();
        for (int i = 0; i < poses; i++) {
            double u = xOf(e, t.w.rows.get(i), t.w.conditions.get(i));
            if (!(dn[i] > cut) || !Double.isFinite(u)) continue;
            double proj = 0;
            for (int row = i * rpp; row < (i + 1) * rpp; row++) proj += d[row] * t.fit.r[row];
            pts.add(new double[] {u, (fitted.applyAsDouble(i) - start - proj / dn[i]) * unit});
        }
        double[] x = new double[pts.size()], y = new double[pts.size()];
        for (int i = 0; i < x.length; i++) { x[i] = pts.get(i)[0]; y[i] = pts.get(i)[1]; }
        int nc = 200;
        double[] cx = new double[nc], cy = new double[nc];
        for (int i = 0; i < nc; i++) {
            cx[i] = e.rangeLo() + (e.rangeHi() - e.rangeLo()) * i / (nc - 1);
            cy[i] = (curve.applyAsDouble(cx[i]) - start) * unit;
        }
        return new Diagnosis.Plot(xLabel(e), yLabel, x, y, cx, cy, null);
    }

    /** A base turn's fitted angle about {@code axis} at the reading {@code u} (rad): each axis's turn is its own spline. */
    private static double turnAt(Effect e, double[] v, double[] axis, double u) {
        double s = 0;
        for (int a = 0; a < 3; a++) s += axis[a] * e.splineAt(v, a * e.basisCount(), u);
        return s;
    }

    /** Amplitude of harmonics 1..n of y against the angle x (deg), each fitted alone with a constant. */
    static double[] periodogram(double[] xDeg, double[] y, int n) {
        double[] out = new double[n];
        for (int h = 1; h <= n; h++) {
            double[] a = new double[9], b = new double[3];
            for (int i = 0; i < y.length; i++) {
                double q = Math.toRadians(xDeg[i]);
                double[] f = {Math.sin(h * q), Math.cos(h * q), 1};
                for (int r = 0; r < 3; r++) {
                    b[r] += f[r] * y[i];
                    for (int c = 0; c < 3; c++) a[3 * r + c] += f[r] * f[c];
                }
            }
            out[h - 1] = Diagnoser.solve(a, b, 3) ? Math.hypot(b[0], b[1]) : 0;
        }
        return out;
    }
}
