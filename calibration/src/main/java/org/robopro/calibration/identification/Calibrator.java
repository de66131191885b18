package org.robopro.calibration.identification;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Random;
import java.util.Set;
import java.util.WeakHashMap;
import org.robopro.calibration.Cancellation;
import org.robopro.calibration.Progress;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.InputException;
import org.robopro.models.JointDescription;
import org.robopro.models.Vec3;

/**
 * Calibrates a robot from measurements (seed paper §5):
 * <ol>
 * <li>check the data (joint count, enough poses, an instrument frame the data can determine);</li>
 * <li>start the instrument frame by rigid registration of nominal predictions, then fit only
 *     instrument and tool with the nominal geometry (the "nominal" errors of the report);</li>
 * <li>identifiability: parameters that no pose set can separate for this model and data kind
 *     (structural; from 60 random poses) are fixed by {@link Identifiability}'s rule; if the given
 *     poses cannot separate more, refuse and say what is missing;</li>
 * <li>Levenberg–Marquardt on everything else; with orientations, re-weight by the estimated
 *     position and rotation noise and refit;</li>
 * <li>outliers: a pose whose position residual exceeds {@code outlierK} times the robust noise
 *     (median residual norm / 1.5382, the median of a 3-D Gaussian's norm) is flagged, dropped
 *     from the fit and reported; repeated until no new pose is flagged (at most 5 rounds);</li>
 * <li>σ per parameter from s²(JᵀJ)⁻¹; validation errors on poses the fit did not see.</li>
 * </ol>
 */
public final class Calibrator {
    /** Median of the norm of a 3-D standard normal vector (Maxwell distribution). */
    static final double MAXWELL_MEDIAN = 1.5381722;
    /** Fits at most: the first and up to this many minus one trimmed refits. */
    private static final int MAX_ROUNDS = 8;
    private static final int STRUCTURAL_POSES = 60;

    /**
     * @param initialTool      start of the tool frame (its origin is the measured point), flange coordinates
     * @param outlierK         outlier threshold in robust sigmas
     * @param rejectOutliers   drop flagged poses from the fit (else only report them)
     * @param tolerance        relative singular-value threshold for identifiability
     * @param maxIterations    LM iteration limit per fit
     * @param effects          extra parameter blocks (diagnosis)
     * @param cancel           cancellation token
     * @param progress         progress listener
     * @param knownInstrument  a known instrument pose (instrument_T_base, e.g. a tracker registration) to start
     *                         from instead of the registration of the nominal predictions; null for none
     * @param fixInstrument    keep {@code knownInstrument} fixed (not identified)
     * @param fixTool          keep {@code initialTool} fixed (a known tool, e.g. a hand-eye result)
     */
    public record Options(Pose initialTool, double outlierK, boolean rejectOutliers, double tolerance, int maxIterations,
                          List<EffectBlock> effects, Cancellation cancel, Progress progress, Pose knownInstrument,
                          boolean fixInstrument, boolean fixTool) {
        public Options {
            // Infinity is allowed: "never flag"; NaN would silently turn rejection off.
            if (!(outlierK > 0))
                throw new IllegalArgumentException("the outlier threshold must be a positive number of robust sigmas, got " + outlierK);
            if (!(tolerance > 0 && tolerance < 1))
                throw new IllegalArgumentException("the identifiability tolerance must be in (0, 1), got " + tolerance);
            if (maxIterations < 1) throw new IllegalArgumentException("the iteration limit must be at least 1, got " + maxIterations);
            if (fixInstrument && knownInstrument == null) throw new IllegalArgumentException("a fixed instrument pose needs its value");
        }

        public static Options defaults() {
            return new Options(Pose.IDENTITY, 5.0, true, Identifiability.DEFAULT_TOLERANCE, 100, List.of(),
                    Cancellation.NONE, Progress.NONE, null, false, false);
        }

        public Options withInitialTool(Pose t) { return new Options(t, outlierK, rejectOutliers, tolerance, maxIterations, effects, cancel, progress, knownInstrument, fixInstrument, fixTool); }
        public Options withEffects(List<EffectBlock> e) { return new Options(initialTool, outlierK, rejectOutliers, tolerance, maxIterations, e, cancel, progress, knownInstrument, fixInstrument, fixTool); }
        public Options withCancel(Cancellation c) { return new Options(initialTool, outlierK, rejectOutliers, tolerance, maxIterations, effects, c, progress, knownInstrument, fixInstrument, fixTool); }
        public Options withProgress(Progress p) { return new Options(initialTool, outlierK, rejectOutliers, tolerance, maxIterations, effects, cancel, p, knownInstrument, fixInstrument, fixTool); }
        public Options withOutliers(double k, boolean reject) { return new Options(initialTool, k, reject, tolerance, maxIterations, effects, cancel, progress, knownInstrument, fixInstrument, fixTool); }
        /** Starts from (or, with {@code fix}, keeps) this instrument pose. */
        public Options withInstrument(Pose instrumentTbase, boolean fix) { return new Options(initialTool, outlierK, rejectOutliers, tolerance, maxIterations, effects, cancel, progress, instrumentTbase, fix, fixTool); }
        /** Keeps the tool frame at {@link #initialTool} (not identified). */
        public Options withToolFixed(boolean fix) { return new Options(initialTool, outlierK, rejectOutliers, tolerance, maxIterations, effects, cancel, progress, knownInstrument, fixInstrument, fix); }
    }

    private Calibrator() { }

    public static CalibrationResult calibrate(KinematicModel nominal, MeasurementSet train, MeasurementSet validate) {
        return calibrate(nominal, train, validate, Options.defaults());
    }

    public static CalibrationResult calibrate(KinematicModel nominal, MeasurementSet train, MeasurementSet validate, Options o) {
        long t0 = System.nanoTime();
        checkData(nominal, train);
        if (validate != null) {
            checkData(nominal, validate);
            if (!validate.pointNames().equals(train.pointNames()) || validate.isDistance() != train.isDistance()
                    || validate.isPairs() != train.isPairs())
                throw new InputException(validate.source(), 0, 0, "point", "validation data measure " + shape(validate)
                        + " but the training data " + shape(train) + "; validation needs the same measured points");
            if (!validate.isDistance() && !validate.frame().equalsIgnoreCase(train.frame()))
                throw new InputException(validate.source(), 0, 0, "frame", "validation data are in frame '" + validate.frame()
                        + "' but the training data in '" + train.frame() + "'; validation needs the same instrument set-up");
        }
        boolean sixD = train.hasOrientation();
        boolean distance = train.isDistance();
        boolean instrument = !train.inBaseFrame() && !distance;
        int points = train.pointCount();
        if (points > 1 && o.fixTool())
            throw new InputException(train.source(), 0, 0, "point", "a known tool gives one measured point, but this file measures "
                    + points + " points per pose (" + String.join(", ", train.pointNames()) + "); let the calibration identify them");
        List<EffectBlock> effects = o.effects();
        List<Measurement> rows = train.rows();
        checkMemory(train, nominal, sixD, effects, validate == null ? 0 : validate.size());
        o.progress().update("start", 0);

        // 1. Starting instrument frame and tool. The registration trims poses far from the
        //    nominal prediction, so a wild reading cannot tilt the starting frame.
        Pose tool0 = sixD ? o.initialTool() : Pose.translation(o.initialTool().position());
        List<Vec3> more0 = new ArrayList<>();
        for (int k = 1; k < points; k++) more0.add(tool0.position());
        Pose inst0 = null;
        Vec3 anchor0 = null;
        Set<String> screened = new HashSet<>();
        if (distance) {
            if (o.knownInstrument() != null)
                throw new InputException(train.source(), 0, 0, "anchor", "distance data have no instrument frame to give; "
                        + "write the anchor's position in the file ('# anchor: x, y, z', robot base frame) to keep it fixed");
            if (!train.isPairs())
                anchor0 = train.anchor() != null ? train.anchor() : Registration.multilaterate(nominal, rows, tool0.position(), train.source());
        } else if (instrument) {
            List<Vec3> pred = new ArrayList<>(), meas = new ArrayList<>();
            for (Measurement m : rows) {
                pred.add(nominal.flange(m.q()).times(tool0).position());
                meas.add(m.position());
            }
            double[] spread = Registration.spread(meas);
            if (rows.size() < 3 || spread[1] < 5e-3)
                throw new InputException(train.source(), 0, 0, "frame", String.format(Locale.ROOT,
                        "the measured points lie on a line (spread %.1f mm x %.1f mm), so the instrument frame '%s' "
                                + "cannot be determined; add poses that move the measured point in at least two "
                                + "directions, or write '# frame: base' if the positions are in the robot base frame",
                        spread[0] * 1e3, spread[1] * 1e3, train.frame()));
            boolean[] keep = new boolean[rows.size()];
            inst0 = Registration.trimmed(pred, meas, keep);
            for (int i = 0; i < rows.size(); i++) if (!keep[i]) screened.add(rows.get(i).poseId());
            if (o.knownInstrument() != null) inst0 = o.knownInstrument();
        } else if (o.knownInstrument() != null)
            throw new InputException(train.source(), 0, 0, "frame", "the measurements are in the robot base frame ('# frame: base'), "
                    + "so there is no instrument pose to give");
        if (sixD && !o.fixTool()) tool0 = averageToolRotation(nominal, rows, tool0, inst0);
        if (points > 1) {
            // Each point's place on the flange seen through the starting frame, averaged over the poses.
            List<Vec3> est = Registration.toolPoints(nominal, rows, inst0, screened);
            if (instrument && o.knownInstrument() == null) {
                // The first registration put every point at the start tool point; register again
                // with each point at its estimate, then estimate the points again.
                List<Vec3> pred = new ArrayList<>(), meas = new ArrayList<>();
                for (Measurement m : rows) {
                    if (screened.contains(m.poseId())) continue;
                    Pose f = nominal.flange(m.q());
                    for (int k = 0; k < points; k++) { pred.add(f.apply(est.get(k))); meas.add(m.point(k)); }
                }
                inst0 = Registration.rigid(pred, meas);
                est = Registration.toolPoints(nominal, rows, inst0, screened);
            }
            tool0 = Pose.translation(est.get(0));
            more0 = est.subList(1, points);
        }
        double[] start = IdentificationProblem.startVector(nominal, tool0, more0, sixD, inst0, anchor0, effects);
        if (!o.rejectOutliers()) screened.clear();

        // 2. Nominal fit: geometry fixed, instrument and tool free (on the poses not screened out).
        NominalFit nf = nominalFit(nominal, without(rows, screened), sixD, instrument, effects, start, o, train.anchor() != null);
        IdentificationProblem p1 = nf.problem();
        double[] nominalFull = nf.full();
        o.progress().update("nominal fit", 0.2);

        // 3. Identifiability: structural (any poses) then these poses.
        // A given anchor is fixed before the analysis: in the base frame, it makes the robot's base
        // placement observable, which a free anchor absorbs. (A given instrument pose or tool is
        // fixed after it: the base placement keeps its nominal value, so a wrong registration
        // shows as a poor fit instead of being absorbed by the robot.)
        boolean[] fix = new boolean[p1.fullSize()];
        if (distance && train.anchor() != null) for (int a = 0; a < 3; a++) fix[p1.anchorOffset() + a] = true;
        Identifiability.Result structural = structural(nominal, sixD, instrument, effects, nominalFull, p1, o.tolerance(), fix.clone());
        for (int j : structural.fixed()) fix[j] = true;
        for (int j : known(p1, o, train.anchor() != null)) fix[j] = true;
        int nFree = 0;
        for (boolean b : fix) if (!b) nFree++;
        int eq = rows.size() * p1.rowsPerPose();
        if (eq < nFree) {
            int need = (nFree + p1.rowsPerPose() - 1) / p1.rowsPerPose();
            throw new InputException(train.source(), 0, 0, null, String.format(Locale.ROOT,
                    "%d poses give %d equations but %d parameters are to be identified; measure at least %d poses "
                            + "(3 to 5 times as many give a usable result)", rows.size(), eq, nFree, need));
        }
        IdentificationProblem p2 = new IdentificationProblem(nominal, rows, sixD, instrument, effects, nominalFull);
        p2.setSigmas(p1.sigmaPos(), p1.sigmaRot());
        double[] jFull = new double[eq * p2.fullSize()];
        p2.evaluateFull(nominalFull, new double[eq], jFull);
        Identifiability.Result data = Identifiability.analyze(jFull, eq, p2.fullSize(), p2.names(), p2.fixPriorities(),
                fix, rows.size(), o.tolerance());
        if (data.fixed().length > 0) {
            StringBuilder sb = new StringBuilder();
            for (Identifiability.Direction d : data.directions()) sb.append("\n  ").append(d.describe());
            throw new InputException(train.source(), 0, 0, null, "these " + rows.size()
                    + " poses cannot separate the following parameter combinations:" + sb
                    + "\nadd poses that move the joints involved over a wider part of their ranges");
        }
        o.progress().update("identifiability", 0.3);

        // 4. Full fit, re-weighting for 6-D data, then trimmed refits: the poses flagged at a fit
        //    are left out and the fit is redone from the nominal start (not from the fit they
        //    shaped); every pose is judged again at each fit, so a pose wrongly flagged by a
        //    spoiled fit comes back. Ends when the flagged set no longer changes.
        Set<String> excluded = new HashSet<>(screened);
        List<CalibrationResult.Outlier> outliers = List.of();
        double[] full = nominalFull;
        LevenbergMarquardt.Result fit = null;
        IdentificationProblem p = null;
        for (int round = 0; round < MAX_ROUNDS; round++) {
            List<Measurement> kept = without(rows, excluded);
            if (kept.size() * p1.rowsPerPose() <= nFree)
                throw new InputException(train.source(), 0, 0, null, "after removing " + excluded.size()
                        + " outlier poses too few poses remain to identify " + nFree + " parameters");
            if (round > 0) {
                nf = nominalFit(nominal, kept, sixD, instrument, effects, start, o, train.anchor() != null);
                p1 = nf.problem();
                nominalFull = nf.full();
            }
            p = new IdentificationProblem(nominal, kept, sixD, instrument, effects, nominalFull);
            p.setSigmas(p1.sigmaPos(), p1.sigmaRot());
            p.setFixed(fix);
            fit = new LevenbergMarquardt(p).maxIterations(o.maxIterations()).solve(p.freeOf(nominalFull), o.cancel());
            full = p.fullOf(fit.x());
            if (sixD) {
                double[] sig = estimateSigmas(p, full, p.freeIndices().length);
                p.setSigmas(sig[0], sig[1]);
                fit = new LevenbergMarquardt(p).maxIterations(o.maxIterations()).solve(p.freeOf(full), o.cancel());
                full = p.fullOf(fit.x());
            }
            o.progress().update("fit", Math.min(0.9, 0.4 + 0.1 * round));
            Map<String, CalibrationResult.Outlier> flagged = outliers(p, full, train, excluded, o.outlierK());
            if (!o.rejectOutliers()) {
                outliers = new ArrayList<>(flagged.values());
                break;
            }
            boolean last = flagged.keySet().equals(excluded) || round == MAX_ROUNDS - 1;
            if (last) {
                // Report what the final fit left out, judged at that fit.
                List<CalibrationResult.Outlier> out = new ArrayList<>();
                Map<String, CalibrationResult.Outlier> all = outliers(p, full, train, excluded, 0);
                for (Measurement m : rows) if (excluded.contains(m.poseId())) out.add(all.get(m.poseId()));
                outliers = out;
                break;
            }
            excluded = new HashSet<>(flagged.keySet());
        }
        Set<String> outlierIds = new HashSet<>();
        for (CalibrationResult.Outlier ol : outliers) outlierIds.add(ol.poseId());

        // 5. Uncertainty.
        List<CalibrationResult.Correlation> correlations = new ArrayList<>();
        double[] sigmaFull = covariance(p, fit.x(), correlations);
        double[] sig = estimateSigmas(p, full, p.freeIndices().length);
        KinematicModel calibrated = p.modelOf(full);
        Pose tool = p.toolOf(full);
        Pose inst = instrument ? p.instrumentOf(full) : null;
        List<CalibrationResult.ParameterEstimate> params = new ArrayList<>();
        List<String> names = p.names(), units = p.unitsSi();
        double[] nomStart = start;
        for (int i = 0; i < names.size(); i++) {
            double nomValue = p.blocks().get(i) == IdentificationProblem.Block.GEOMETRY ? nomStart[i] : nominalFull[i];
            params.add(new CalibrationResult.ParameterEstimate(names.get(i), p.blocks().get(i).name().toLowerCase(Locale.ROOT),
                    units.get(i), nomValue, full[i], fix[i] ? Double.NaN : sigmaFull[i], fix[i]));
        }

        // 6. Errors per pose, training and validation.
        List<CalibrationResult.PoseError> trainErr = poseErrors(p, nominal, train, nominalFull, full, outlierIds, effects);
        List<CalibrationResult.PoseError> valErr = validate == null ? List.of()
                : poseErrors(p, nominal, validate, nominalFull, full, Set.of(), effects);
        o.progress().update("done", 1);
        List<Vec3> toolPoints = new ArrayList<>();
        for (int k = 0; k < points; k++) toolPoints.add(p.toolPointOf(full, k));
        return new CalibrationResult(nominal, calibrated, tool, inst, params, structural.directions(),
                data.conditionNumber(), data.observability(), outliers, trainErr, valErr, nf.result(), fit,
                sig[0], sixD ? sig[1] : Double.NaN, sixD, (System.nanoTime() - t0) / 1e6, List.copyOf(correlations),
                train.pointNames(), toolPoints, p.anchorOf(full), distance && train.anchor() != null, train.isPairs());
    }

    /**
     * Refuses, before any work, a campaign whose dense Jacobians (three copies of poses x rows x
     * parameters doubles: the fit, the identifiability analysis, the covariance) would not fit the
     * heap, instead of running out of memory after minutes.
     */
    static void checkMemory(MeasurementSet train, KinematicModel nominal, boolean sixD, List<EffectBlock> effects, int validate) {
        long params = 6L * nominal.dof() + 12 + 3L * (train.pointCount() - 1);
        for (EffectBlock e : effects) params += e.parameterNames().size();
        long need = 3L * (train.size() + validate) * (sixD ? 6 : train.isDistance() ? 1 : 3 * train.pointCount()) * params * Double.BYTES;
        long max = Runtime.getRuntime().maxMemory();
        if (need > 0.7 * max)
            throw new InputException(train.source(), 0, 0, null, String.format(Locale.ROOT,
                    "%d poses need about %d MB for the fit, more than the %d MB of memory available; use fewer poses "
                            + "(a few hundred to a few thousand suffice: the precision grows only with their square root) "
                            + "or give Java more memory (-Xmx)", train.size() + validate, need >> 20, max >> 20));
    }

    static void checkData(KinematicModel model, MeasurementSet set) {
        if (set.size() == 0) throw new InputException(set.source(), 0, 0, null, "no measurements");
        if (set.dof() != model.dof())
            throw new InputException(set.source(), 0, 0, "q" + set.dof(), "the measurements have " + set.dof()
                    + " joint values per pose but robot " + model.description().name() + " has " + model.dof()
                    + " joints; use the robot the data were taken on");
        for (Measurement m : set.rows()) {
            String bad = m.grossField();
            if (bad != null)
                throw new InputException(set.source(), m.line(), 0, bad, "pose '" + m.poseId() + "': "
                        + Measurement.grossReason(bad));
        }
    }

    private static Pose averageToolRotation(KinematicModel nominal, List<Measurement> rows, Pose tool0, Pose inst0) {
        double[] acc = new double[4];
        double[] ref = null;
        for (Measurement m : rows) {
            Pose bf = nominal.flange(m.q());
            Pose meas = Pose.fromQuaternion(m.orientation()[0], m.orientation()[1], m.orientation()[2], m.orientation()[3], 0, 0, 0);
            Pose ib = inst0 == null ? Pose.IDENTITY : inst0;
            double[] qf = ib.times(bf).inverse().times(meas).quaternion(); // flangeTtool rotation seen by this pose
            if (ref == null) ref = qf;
            double s = qf[0] * ref[0] + qf[1] * ref[1] + qf[2] * ref[2] + qf[3] * ref[3] < 0 ? -1 : 1;
            for (int k = 0; k < 4; k++) acc[k] += s * qf[k];
        }
        return Pose.fromQuaternion(acc[0], acc[1], acc[2], acc[3], tool0.x(), tool0.y(), tool0.z());
    }

    /** Position (m) and rotation (rad) noise per axis from the residuals, with the dof correction. */
    static double[] estimateSigmas(IdentificationProblem p, double[] full, int nFree) {
        int m = p.residualCount();
        double[] r = new double[m];
        p.evaluateFull(full, r, null);
        int rpp = p.rowsPerPose();
        double sp = 0, sr = 0;
        int np = 0, nr = 0;
        for (int i = 0; i < m; i++) {
            if (!p.sixD() || i % rpp < 3) { sp += Math.pow(r[i] * p.sigmaPos(), 2); np++; }
            else { sr += Math.pow(r[i] * p.sigmaRot(), 2); nr++; }
        }
        double corr = (double) m / Math.max(1, m - nFree);
        double sigP = Math.sqrt(sp / np * corr), sigR = nr == 0 ? 1e-4 : Math.sqrt(sr / nr * corr);
        return new double[] {Math.max(sigP, 1e-12), Math.max(sigR, 1e-12)};
    }

    /** Pairs of free parameters whose estimates are correlated beyond this |ρ| are kept in the result. */
    static final double CORRELATION_KEPT = 0.9;

    /**
     * σ_j = sqrt(s² [(JᵀJ)⁻¹]_jj), for every full index (NaN where fixed); when {@code correlations} is not null, adds the
     * pairs of free parameters with |ρ_ij| = |C_ij| / sqrt(C_ii C_jj) above {@link #CORRELATION_KEPT}
     * (C = (JᵀJ)⁻¹; the column scaling cancels in ρ).
     */
    static double[] covariance(IdentificationProblem p, double[] x, List<CalibrationResult.Correlation> correlations) {
        int m = p.residualCount(), n = p.parameterCount();
        double[] r = new double[m], j = new double[m * n];
        p.evaluate(x, r, j);
        double[] scale = new double[n];
        for (int c = 0; c < n; c++) {
            double s = 0;
            for (int i = 0; i < m; i++) s += j[i * n + c] * j[i * n + c];
            scale[c] = s > 0 ? Math.sqrt(s) : 1;
        }
        double[] a = new double[n * n];
        Dense.normalMatrix(j, m, n, scale, a);
        double s2 = Dense.dot(r, r, m) / Math.max(1, m - n);
        double[] out = new double[p.fullSize()];
        Arrays.fill(out, Double.NaN);
        if (!Dense.cholesky(a, n)) return out;
        int[] free = p.freeIndices();
        double[] inv = new double[n * n];
        double[] e = new double[n];
        for (int c = 0; c < n; c++) {
            Arrays.fill(e, 0);
            e[c] = 1;
            Dense.choleskySolve(a, n, e);
            System.arraycopy(e, 0, inv, c * n, n);
            out[free[c]] = Math.sqrt(s2 * e[c]) / scale[c];
        }
        if (correlations != null) {
            List<String> names = p.names();
            for (int i = 0; i < n; i++)
                for (int k = i + 1; k < n; k++) {
                    double rho = inv[i * n + k] / Math.sqrt(inv[i * n + i] * inv[k * n + k]);
                    if (Math.abs(rho) > CORRELATION_KEPT)
                        correlations.add(new CalibrationResult.Correlation(names.get(free[i]), names.get(free[k]), rho));
                }
            correlations.sort((u, v) -> Double.compare(Math.abs(v.rho()), Math.abs(u.rho())));
        }
        return out;
    }

    /**
     * The outlier rule: the poses whose residual at this solution ({@code p}'s layout and blocks,
     * evaluated on every row of {@code train}) exceeds {@code k} robust sigmas, by id in file
     * order. The robust sigma (median residual norm / Maxwell median) comes from the poses not in
     * {@code excluded}; every pose is judged, the excluded ones too. {@code k = 0} returns every pose.
     */
    public static Map<String, CalibrationResult.Outlier> outliers(IdentificationProblem p, double[] full,
                                                                 MeasurementSet train, Set<String> excluded, double k) {
        IdentificationProblem all = withRows(p, train.rows(), full);
        int m = all.residualCount(), rpp = all.rowsPerPose();
        double[] r = new double[m];
        all.evaluateFull(full, r, null);
        int n = train.size();
        boolean six = all.sixD(), dist = all.distance();
        int pts = all.measurementsPerPose();
        // Per measured point: the 3-D error norm (a Maxwell variable under Gaussian noise), or the
        // distance error's magnitude (half-normal); a pose is judged by its worst point.
        double[] each = all.measurementErrors(r, all.sigmaPos()), pos = new double[n], rot = new double[n];
        for (int i = 0; i < n; i++) {
            for (int k2 = 0; k2 < pts; k2++) pos[i] = Math.max(pos[i], each[i * pts + k2]);
            if (six) rot[i] = Math.sqrt(sq(r[i * rpp + 3]) + sq(r[i * rpp + 4]) + sq(r[i * rpp + 5])) * all.sigmaRot();
        }
        double sigPos = Math.max(robustSigma(each, pts, train, excluded) * (dist ? MAXWELL_MEDIAN / HALF_NORMAL_MEDIAN : 1), 1e-9);
        double sigRot = six ? Math.max(robustSigma(rot, 1, train, excluded), 1e-9) : 0;
        String what = dist ? "distance" : pts > 1 ? "largest point" : "position";
        Map<String, CalibrationResult.Outlier> out = new java.util.LinkedHashMap<>();
        for (int i = 0; i < n; i++) {
            String id = train.rows().get(i).poseId();
            if (pos[i] > k * sigPos)
                out.put(id, new CalibrationResult.Outlier(id, pos[i], sigPos, String.format(Locale.ROOT,
                        "%s residual %.4f mm > %.1f x robust sigma %.4f mm", what, pos[i] * 1e3, k == 0 ? pos[i] / sigPos : k, sigPos * 1e3)));
            else if (six && rot[i] > k * sigRot)
                out.put(id, new CalibrationResult.Outlier(id, pos[i], sigPos, String.format(Locale.ROOT,
                        "rotation residual %.5f deg > %.1f x robust sigma %.5f deg", Math.toDegrees(rot[i]), k, Math.toDegrees(sigRot))));
        }
        return out;
    }

    /** Median of |N(0, 1)|: the robust scale of a one-dimensional residual. */
    static final double HALF_NORMAL_MEDIAN = 0.6744898;

    /** Median norm / Maxwell median over the {@code per} values of each pose not in {@code known}. */
    private static double robustSigma(double[] norms, int per, MeasurementSet train, Set<String> known) {
        double[] v = new double[norms.length];
        int c = 0;
        for (int i = 0; i < norms.length; i++) if (!known.contains(train.rows().get(i / per).poseId())) v[c++] = norms[i];
        v = Arrays.copyOf(v, c);
        Arrays.sort(v);
        double med = c % 2 == 1 ? v[c / 2] : 0.5 * (v[c / 2 - 1] + v[c / 2]);
        return med / MAXWELL_MEDIAN;
    }

    /** The rows whose id is not in {@code ids}, in order. */
    private static List<Measurement> without(List<Measurement> rows, Set<String> ids) {
        if (ids.isEmpty()) return rows;
        List<Measurement> kept = new ArrayList<>();
        for (Measurement m : rows) if (!ids.contains(m.poseId())) kept.add(m);
        return kept;
    }

    /** Nominal fit (geometry and effects fixed, instrument and tool free) from {@code start}; 6-D sigmas set. */
    private static NominalFit nominalFit(KinematicModel nominal, List<Measurement> rows, boolean sixD, boolean instrument,
                                         List<EffectBlock> effects, double[] start, Options o, boolean anchorGiven) {
        IdentificationProblem p1 = new IdentificationProblem(nominal, rows, sixD, instrument, effects, start);
        boolean[] geoFixed = new boolean[p1.fullSize()];
        for (int i = 0; i < p1.fullSize(); i++)
            geoFixed[i] = p1.blocks().get(i) == IdentificationProblem.Block.GEOMETRY
                    || p1.blocks().get(i) == IdentificationProblem.Block.EFFECT;
        for (int j : known(p1, o, anchorGiven)) geoFixed[j] = true;
        p1.setFixed(geoFixed);
        LevenbergMarquardt.Result r;
        if (p1.parameterCount() == 0) {
            // Instrument and tool both given and kept: nothing to fit with the nominal geometry.
            double[] res = new double[p1.residualCount()];
            p1.evaluateFull(start, res, null);
            double cost = 0.5 * Dense.dot(res, res, res.length);
            r = new LevenbergMarquardt.Result(new double[0], cost, 0, 1, new double[] {cost}, LevenbergMarquardt.Reason.COST_CONVERGED);
        } else r = new LevenbergMarquardt(p1).maxIterations(o.maxIterations()).solve(p1.freeOf(start), o.cancel());
        double[] full = p1.fullOf(r.x());
        if (sixD) {
            double[] sig = estimateSigmas(p1, full, p1.freeIndices().length);
            p1.setSigmas(sig[0], sig[1]);
        }
        return new NominalFit(p1, r, full);
    }

    /** Full indices of the parameters kept at known values: instrument and tool by the options, an anchor the file gives. */
    private static List<Integer> known(IdentificationProblem p, Options o, boolean anchorGiven) {
        List<Integer> out = new ArrayList<>();
        for (int i = 0; i < p.fullSize(); i++) {
            IdentificationProblem.Block b = p.blocks().get(i);
            if (o.fixInstrument() && b == IdentificationProblem.Block.INSTRUMENT || o.fixTool() && b == IdentificationProblem.Block.TOOL) out.add(i);
        }
        if (p.distance() && anchorGiven) for (int a = 0; a < 3; a++) out.add(p.anchorOffset() + a);
        return out;
    }

    /** "points A, B, C" / "one point" / "distances", for messages. */
    static String shape(MeasurementSet s) {
        if (s.isPairs()) return "distances between pairs of poses";
        if (s.isDistance()) return "distances";
        return s.pointNames().isEmpty() ? "one point per pose" : "points " + String.join(", ", s.pointNames());
    }

    /** The nominal-fit problem (its sigmas), the solver result and the full parameter vector. */
    private record NominalFit(IdentificationProblem problem, LevenbergMarquardt.Result result, double[] full) { }

    private static double sq(double v) { return v * v; }

    /** A problem of the same layout on other rows; orientation rows only when every row has one. */
    private static IdentificationProblem withRows(IdentificationProblem p, List<Measurement> rows, double[] full) {
        IdentificationProblem q = new IdentificationProblem(p.model(), rows, p.sixD(), p.hasInstrument(), effectsOf(p), full);
        q.setSigmas(p.sigmaPos(), p.sigmaRot());
        return q;
    }

    private static List<EffectBlock> effectsOf(IdentificationProblem p) { return p.effects(); }

    private static List<CalibrationResult.PoseError> poseErrors(IdentificationProblem p, KinematicModel nominal, MeasurementSet set,
                                                               double[] nominalFull, double[] full, Set<String> outliers,
                                                               List<EffectBlock> effects) {
        boolean sixD = p.sixD() && set.hasOrientation();
        IdentificationProblem src = p;
        IdentificationProblem q = new IdentificationProblem(nominal, set.rows(), sixD, p.hasInstrument(), effects,
                remap(src, sixD, nominalFull));
        q.setSigmas(1, 1);
        int rpp = q.rowsPerPose(), m = q.residualCount();
        double[] rn = new double[m], rc = new double[m];
        q.evaluateFull(remap(src, sixD, nominalFull), rn, null);
        q.evaluateFull(remap(src, sixD, full), rc, null);
        List<CalibrationResult.PoseError> out = new ArrayList<>();
        if (q.distance()) {
            for (int i = 0; i < set.size(); i++) {
                String id = set.rows().get(i).poseId();
                out.add(new CalibrationResult.PoseError(id, Math.abs(rn[i]), Math.abs(rc[i]), Double.NaN, Double.NaN, outliers.contains(id),
                        null, null, -rc[i]));
            }
            return out;
        }
        if (q.pointCount() > 1) {
            for (int i = 0; i < set.size(); i++) {
                String id = set.rows().get(i).poseId();
                for (int k = 0; k < q.pointCount(); k++) {
                    int b = i * rpp + 3 * k;
                    out.add(new CalibrationResult.PoseError(id, Math.sqrt(sq(rn[b]) + sq(rn[b + 1]) + sq(rn[b + 2])),
                            Math.sqrt(sq(rc[b]) + sq(rc[b + 1]) + sq(rc[b + 2])), Double.NaN, Double.NaN, outliers.contains(id),
                            new Vec3(-rc[b], -rc[b + 1], -rc[b + 2]), set.pointNames().get(k), Double.NaN));
                }
            }
            return out;
        }
        for (int i = 0; i < set.size(); i++) {
            int b = i * rpp;
            double en = Math.sqrt(sq(rn[b]) + sq(rn[b + 1]) + sq(rn[b + 2]));
            double ec = Math.sqrt(sq(rc[b]) + sq(rc[b + 1]) + sq(rc[b + 2]));
            double rnRot = Double.NaN, rcRot = Double.NaN;
            if (rpp == 6) {
                rnRot = Math.sqrt(sq(rn[b + 3]) + sq(rn[b + 4]) + sq(rn[b + 5]));
                rcRot = Math.sqrt(sq(rc[b + 3]) + sq(rc[b + 4]) + sq(rc[b + 5]));
            }
            String id = set.rows().get(i).poseId();
            out.add(new CalibrationResult.PoseError(id, en, ec, rnRot, rcRot, outliers.contains(id), new Vec3(-rc[b], -rc[b + 1], -rc[b + 2])));
        }
        return out;
    }

    /** A full vector of a 6-D layout turned into the position-only layout (tool rotation dropped), or as is. */
    private static double[] remap(IdentificationProblem from, boolean sixDTo, double[] full) {
        if (from.sixD() == sixDTo) return full;
        int t = from.toolOffset();
        double[] out = new double[full.length - 3];
        System.arraycopy(full, 0, out, 0, t + 3);
        System.arraycopy(full, t + 6, out, t + 3, full.length - t - 6);
        return out;
    }

    // ------------------------------------------------------------------ structural identifiability

    private static final Map<KinematicModel, Map<String, Identifiability.Result>> STRUCTURAL = new WeakHashMap<>();

    /**
     * Identifiability of the model and data kind, independent of the measured poses: the
     * analysis on {@value #STRUCTURAL_POSES} random poses inside the joint limits. Cached per model.
     */
    static Identifiability.Result structural(KinematicModel nominal, boolean sixD, boolean instrument, List<EffectBlock> effects,
                                             double[] start, IdentificationProblem like, double tol, boolean[] known) {
        StringBuilder key = new StringBuilder().append(sixD).append('/').append(instrument).append('/').append(tol)
                .append('/').append(like.pointCount()).append('/').append(like.distance()).append('/').append(like.pairs())
                .append('/').append(Arrays.toString(known));
        for (EffectBlock e : effects) key.append('/').append(e.name()).append(e.parameterNames());
        synchronized (STRUCTURAL) {
            Identifiability.Result r = STRUCTURAL.getOrDefault(nominal, Map.of()).get(key.toString());
            if (r != null) return r;
        }
        Random rng = new Random(20261121L);
        List<Measurement> rows = new ArrayList<>();
        List<JointDescription> js = nominal.description().joints();
        double[] prev = null;
        for (int i = like.pairs() ? -1 : 0; i < STRUCTURAL_POSES; i++) {
            double[] q = new double[js.size()];
            for (int k = 0; k < q.length; k++) {
                double lo = js.get(k).min(), hi = js.get(k).max();
                if (lo == hi && Double.isFinite(lo)) { q[k] = lo; continue; } // a locked joint
                if (!(hi > lo) || !Double.isFinite(lo) || !Double.isFinite(hi) || hi - lo > 2 * Math.PI) {
                    double mid = Double.isFinite(lo + hi) ? 0.5 * (lo + hi) : 0;
                    lo = mid - Math.PI; hi = mid + Math.PI;
                }
                q[k] = lo + (hi - lo) * rng.nextDouble();
            }
            if (like.pairs()) {
                // each pose measured from the one before: random pairs
                if (prev != null) rows.add(Measurement.ofPair("s" + i, prev, q, 1));
                prev = q;
            } else if (like.distance()) rows.add(Measurement.ofDistance("s" + i, q, 1));
            else if (like.pointCount() > 1) rows.add(Measurement.ofPoints("s" + i, q, java.util.Collections.nCopies(like.pointCount(), Vec3.ZERO)));
            else rows.add(new Measurement("s" + i, q, Vec3.ZERO, sixD ? new double[] {1, 0, 0, 0} : null,
                    null, Double.NaN, Double.NaN, Double.NaN, null, 0));
        }
        IdentificationProblem p = new IdentificationProblem(nominal, rows, sixD, instrument, effects, start);
        p.setSigmas(like.sigmaPos(), like.sigmaRot());
        int m = p.residualCount(), n = p.fullSize();
        double[] j = new double[m * n];
        p.evaluateFull(start, new double[m], j);
        boolean any = false;
        for (boolean b : known) any |= b;
        Identifiability.Result r = Identifiability.analyze(j, m, n, p.names(), p.fixPriorities(), any ? known : null, rows.size(), tol);
        synchronized (STRUCTURAL) {
            STRUCTURAL.computeIfAbsent(nominal, k -> new HashMap<>()).put(key.toString(), r);
        }
        return r;
    }
}
