package org.robopro.calibration.diagnosis;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import org.ejml.data.DMatrixRMaj;
import org.ejml.dense.row.CommonOps_DDRM;
import org.ejml.dense.row.factory.DecompositionFactory_DDRM;
import org.ejml.interfaces.decomposition.QRDecomposition;
import org.ejml.interfaces.decomposition.SingularValueDecomposition_F64;
import org.robopro.calibration.Cancellation;
import org.robopro.calibration.PoseConditions;
import org.robopro.calibration.Progress;
import org.robopro.calibration.identification.CalibrationResult;
import org.robopro.calibration.identification.Calibrator;
import org.robopro.calibration.identification.EffectBlock;
import org.robopro.calibration.identification.IdentificationProblem;
import org.robopro.calibration.identification.LevenbergMarquardt;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.calibration.workflow.CalibrationWorkflow;
import org.robopro.kinematics.KinematicModel;
import org.robopro.models.RobotDescription;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Finds the physics a geometric model left out (method in docs/diagnosis.md):
 * <ol>
 * <li>geometric calibration ({@link Calibrator}): identifiability, outliers by its rule (reported,
 *     excluded), noise estimate;</li>
 * <li>for every candidate effect × joint ({@link Effect#candidates}), its signature S = (∂p/∂θ_j) g
 *     (3 rows per pose), and the part the model cannot absorb, P⊥S, with P⊥ the projector onto
 *     the orthogonal complement of the span of the current model's Jacobian (geometry, tool,
 *     instrument and effects already selected; thin SVD of the column-scaled Jacobian). Columns
 *     with ‖P⊥s‖/‖s‖ below {@link Options#absorbedRatio} are absorbed; a candidate with no column
 *     left is reported as not identifiable;</li>
 * <li>nested F-test per candidate, Holm–Bonferroni over the family (forward step s uses α/(N−s)),
 *     AND a smaller leave-one-pose-out prediction error (PRESS from the hat matrix), AND the
 *     physical plausibility of the estimate; among the candidates that pass, the one with the
 *     lowest BIC is added (stepwise forward selection);</li>
 * <li>after each addition, joint non-linear re-identification (Levenberg–Marquardt) of geometry,
 *     tool, instrument and the selected effects; the tests are repeated on the new residuals.</li>
 * </ol>
 * Missing columns turn into advice: reversal-like residuals with directions inferred from the
 * pose order ask for dir columns, a drift in pose order asks for temp_c or time_s.
 */
public final class Diagnoser {
    /**
     * @param alpha          family-wise false-positive rate
     * @param absorbedRatio  ‖P⊥s‖/‖s‖ below which a column counts as absorbed by the geometry
     * @param maxEffects     at most this many effects are selected
     * @param timeTaus       warm-up time constants (s) tried when only time_s stands for temperature
     * @param cancel         cancellation token
     * @param progress       progress listener
     */
    public record Options(double alpha, double absorbedRatio, int maxEffects, double[] timeTaus, Cancellation cancel,
                          Progress progress, int folds) {
        public static Options defaults() {
            return new Options(1e-3, 0.05, 4, new double[] {600, 1200, 2400, 4800}, Cancellation.NONE, Progress.NONE, 5);
        }

        public Options withAlpha(double a) { return new Options(a, absorbedRatio, maxEffects, timeTaus, cancel, progress, folds); }
        public Options withProgress(Progress p) { return new Options(alpha, absorbedRatio, maxEffects, timeTaus, cancel, p, folds); }
        public Options withCancel(Cancellation c) { return new Options(alpha, absorbedRatio, maxEffects, timeTaus, c, progress, folds); }
        /** Folds of the cross-validation that judges the claims when no validation poses are given (below 2: none). */
        public Options withFolds(int k) { return new Options(alpha, absorbedRatio, maxEffects, timeTaus, cancel, progress, k); }
    }

    // Physical plausibility bounds: what real joints and gears can have.
    static final double MIN_STIFFNESS = 1e4, MAX_STIFFNESS = 1e8;        // N·m/rad
    static final double MAX_PERIODIC_RAD = Math.toRadians(0.1);
    static final double MAX_BACKLASH_RAD = Math.toRadians(0.5);
    static final double MAX_SCALE = 1e-2, MAX_COUPLING = 1e-2;
    /** Largest plausible tilt of a robot's base on its foundation per N·m of the arm's moment, rad/(N·m): a loose base indeed. */
    static final double MAX_TILT_PER_NM = 1e-5;
    /** A bearing's tilt across its axis beyond this (about 3.5 arc-minutes RMS) would be a failed bearing, not a wobble, rad. */
    static final double MAX_WOBBLE_RAD = 1e-3;
    /** Nor a shift of a bearing along its axis beyond this, RMS over a turn (a large slewing ring's axial runout is 0.05-0.3 mm), m. */
    static final double MAX_RUNOUT_M = 1e-3;
    /** Nor a holder that bends more than this under its own weight (it would be seen bending), m. */
    static final double MAX_TOOL_SAG_M = 2e-3;
    /** Largest plausible turn of the base or the instrument with time or temperature, rad (2 mm at 2 m). */
    static final double MAX_BASE_TURN_RAD = 1e-3;
    /**
     * Largest move of the measured target on the flange between two readings taken as one campaign's
     * (a reflector's nest knocked, a tool slipping in its clamp), m; beyond it the tool was changed.
     * Also the bound on a displacement of the measured point with its reach, height or time.
     */
    static final double MAX_TARGET_STEP_M = 10e-3;
    /**
     * The largest jump of the instrument's distances taken for its absolute distance meter's error
     * after a broken beam: a tracker's ADM states ±10-25 µm (Muralikrishnan et al., Precision
     * Engineering 44 (2016) 13), so half a millimetre is a fault, not a re-set.
     */
    static final double MAX_RANGE_STEP_M = 0.5e-3;
    /**
     * Largest move of the point by one term of a reflector's error with the direction it is seen
     * from, half a radian off the mean line of sight (about a reflector's acceptance), m: a glass
     * prism's refraction there is a fraction of a millimetre.
     */
    static final double MAX_INCIDENCE_M = 2e-3;
    /**
     * Nor a link whose far end turns more than this as it bends (a beam's far end turns by about
     * 1.5 δ/L: 2 mm on a 0.6 m link), rad.
     */
    static final double MAX_LINK_TURN_RAD = 5e-3;
    /**
     * A pose whose flange axis points toward two instrument stations within this much alike (the difference of
     * the cosines, {@link Effect#facingPart}) may have been read by either.
     */
    static final double STATION_AMBIGUOUS = 0.05;

    /** Whether the pose at q faces the two stations of a selected second station nearly alike ({@link #STATION_AMBIGUOUS}). */
    static boolean atStationSplit(List<Effect> selected, double[] q) {
        return selected.stream().anyMatch(e -> e.kind() == Effect.Kind.SECOND_STATION && Math.abs(e.facingPart(q)) < STATION_AMBIGUOUS);
    }
    /** A second instrument station's registration error at most, m and rad. */
    static final double MAX_STATION_SHIFT_M = 2e-3, MAX_STATION_TURN_RAD = 2e-3;
    /** A joint's largest turn per metre of lever across a pull on the tool, rad/m: 200 N on a wrist drive of 5000 N·m/rad. */
    static final double MAX_PULL_TURN_PER_M = 0.04;
    /**
     * Largest plausible RMS error of an instrument's distance reading (m) and of its angle readings
     * (rad, 50 arc-seconds): a laser tracker's specified distance error is tens of micrometres and its
     * angle error a few arc-seconds; far beyond that the instrument is broken, not erring.
     */
    static final double MAX_INSTRUMENT_RANGE_M = 0.5e-3, MAX_INSTRUMENT_ANGLE_RAD = 50 / 3600.0 * Math.PI / 180;
    /**
     * Nor an instrument whose distances change their scale by more than this over a campaign: 50 ppm
     * is the air's index after a 50 K or a 180 hPa change (Edlén; see {@link Effect#instrumentScale}).
     */
    static final double MAX_INSTRUMENT_SCALE = 50e-6;
    /** Largest scale or half-squareness of an instrument's axes ({@link Effect#instrumentAxes}) taken as the instrument's. */
    static final double MAX_INSTRUMENT_AXES = 1e-3;
    /** Largest bow of an instrument's way ({@link Effect#instrumentAxesBowed}), per metre squared of its travel, taken as the instrument's. */
    static final double MAX_INSTRUMENT_BOW = 1e-3;

    /**
     * Largest change of the air's vertical temperature gradient a campaign's refraction may imply,
     * K/m: a hall stratified by 10 K between floor and a 3 m ceiling, against one mixed, is 3 K/m,
     * near a heater or a sunlit wall more.
     */
    static final double MAX_GRADIENT_CHANGE = 10;
    static final double MAX_ALPHA = 5e-5;                                 // 1/K: steel 12e-6, aluminium 23e-6
    /**
     * Bound of one link's growth per kelvin of the reading, 1/K: a link near its drives warms more
     * than the air the sensor reads (motor and gear losses conduct into it), up to about four times
     * the air's rise for an aluminium link (4 × 23e-6).
     */
    static final double MAX_LINK_ALPHA = 1e-4;
    static final double MAX_STRAIN = 2e-3;
    static final double MAX_DRIFT_PER_K = 1e-4, MAX_DRIFT_PER_H = 1e-3; // m/K, m/h

    /** The stepwise search's candidates and decisions, at debug level (off by default). */
    private static final Logger LOG = LoggerFactory.getLogger(Diagnoser.class);
    /** Stage times at debug level. */
    static final class Timer {
        private long t = System.nanoTime();

        void mark(String what) {
            long n = System.nanoTime();
            if (LOG.isDebugEnabled()) LOG.debug(String.format(Locale.ROOT, "%s %.0f ms", what, (n - t) / 1e6));
            t = n;
        }
    }

    private Diagnoser() { }

    /** Logs a step's candidates with the lowest BIC: six, or as many as the system property robopro.debugTop says. */
    private static void debug(int step, List<Candidate> cs) {
        List<Candidate> sorted = new ArrayList<>(cs);
        sorted.sort((x, y) -> Double.compare(x.bic, y.bic));
        for (int i = 0; i < Math.min(Integer.getInteger("robopro.debugTop", 6), sorted.size()); i++) {
            Candidate c = sorted.get(i);
            LOG.debug(String.format(Locale.ROOT, "step %d %-30s F %.2f p %.2e bic %.1f press %.1f/%.1f ratio %.3f %s %s est %s sd %s", step,
                    c.effect.label(), c.f, c.p, c.bic, c.pressBefore, c.pressAfter, c.ratio, c.plausible, c.plausibility,
                    Arrays.toString(c.estimate), Arrays.toString(c.sd)));
        }
    }

    public static Diagnosis diagnose(RobotDescription robot, MeasurementSet train, MeasurementSet validate) {
        return diagnose(robot, train, validate, Options.defaults());
    }

    public static Diagnosis diagnose(RobotDescription robot, MeasurementSet train, MeasurementSet validate, Options o) {
        long t0 = System.nanoTime();
        // Pairs of poses: the directions of both poses are the file's, never inferred from the row order
        // (the first pose of a row is not the row before it).
        Directions.Prepared dirs = train.isPairs() && !train.hasDirections()
                ? new Directions.Prepared(train, validate, Directions.Source.NONE) : Directions.prepare(train, validate);
        train = dirs.train();
        validate = dirs.validate();
        Diagnosis d = prepared(robot, train, validate, o, t0, dirs.source(), Set.of());
        List<String> flankNotes = new ArrayList<>(dirs.notes());
        if (dirs.source().inferred()) {
            MeasurementSet[] flipped = startFlanks(d, train, validate, flankNotes);
            if (flipped != null) {
                train = flipped[0];
                validate = flipped[1];
                d = prepared(robot, train, validate, o, t0, dirs.source(), Set.of());
            }
        }
        if (dirs.source() != Directions.Source.NONE) {
            MeasurementSet[] kept = inPlay(d, train, validate, dirs.source().inferred(), false, flankNotes);
            if (kept != null) {
                train = kept[0];
                validate = kept[1];
                d = prepared(robot, train, validate, o, t0, dirs.source(), Set.of());
            } else if (validate != null && validate.size() > 0) {
                // A lost motion named as building up over the move lags less after a short move, as a play's dead zone
                // does: the play's dead zone (no further parameter) takes its place when the validation poses say so.
                List<String> trial = new ArrayList<>();
                MeasurementSet[] alt = inPlay(d, train, validate, dirs.source().inferred(), true, trial);
                Diagnosis d2 = alt == null ? null : prepared(robot, alt[0], alt[1], o, t0, dirs.source(), Set.of());
                if (d2 != null && d2.effects().stream().noneMatch(f -> f.effect().buildsUp()) && namedKeys(d2).equals(namedKeys(d))
                        && d2.finalValidateRmsM() < d.finalValidateRmsM() && d2.outliers().size() <= d.outliers().size()) {
                    String windUp = d.effects().stream().filter(f -> f.effect().buildsUp()).map(f -> f.effect().label()).findFirst().orElse("");
                    for (String t : trial)
                        flankNotes.add(String.format(Locale.ROOT, "%s; %s first stood for it, and the play's dead zone predicts the "
                                + "validation poses better (RMS %.4f mm against %.4f mm)", t, windUp, d2.finalValidateRmsM() * 1e3,
                                d.finalValidateRmsM() * 1e3));
                    train = alt[0];
                    validate = alt[1];
                    d = d2;
                }
            }
        }
        if (!(validate != null && validate.size() > 0 || o.folds() < 2 || namedKeys(d).isEmpty()))
            d = crossValidated(robot, train, o, t0, dirs.source(), d);
        if (flankNotes.isEmpty()) return d;
        List<String> notes = new ArrayList<>(d.notes());
        notes.addAll(flankNotes);
        return with(d, d.outliers(), notes);
    }

    /**
     * With inferred directions, the flank of a joint with lost motion at the first poses of the
     * measuring order (before that joint's first move) rests on the campaign starting at the zero
     * position. When the robot started elsewhere (where the last program left it) that flank may be
     * the other one, and the pose then misses by the whole play, which looks like a bad measurement.
     * For each joint with lost motion named, the flank those poses share is taken from their
     * residuals under the diagnosis' model: the other flank is taken when it lowers their sum of
     * squared residuals by more than a pose's expected noise (3σ²). Returns the sets with those
     * directions changed (null when none is), and says so in {@code notes}.
     */
    static MeasurementSet[] startFlanks(Diagnosis d, MeasurementSet train, MeasurementSet validate, List<String> notes) {
        Map<String, int[]> flips = new LinkedHashMap<>();
        double s2 = d.sigmaM() * d.sigmaM();
        for (Diagnosis.Finding f : d.effects()) {
            if (f.effect().kind() != Effect.Kind.BACKLASH) continue;
            int j = f.effect().joint();
            List<Measurement> start = Directions.fromStart(train, validate, j);
            if (start.isEmpty() || start.stream().anyMatch(m -> m.isDistance() || m.points().size() > 1 || m.directions() == null)) continue;
            int assumed = start.get(0).directions()[j];
            double[] ss = new double[3];
            for (int flank = -1; flank <= 1; flank += 2)
                for (Measurement m : start) {
                    int[] dir = m.directions();
                    dir[j] = flank;
                    PoseConditions c = new PoseConditions(dir, m.timeS(), m.tempC(), m.payloadKg());
                    ss[flank + 1] += missed2(d, m, c);
                }
            int other = assumed > 0 ? -1 : 1;
            double ssAssumed = assumed == 0 ? Math.min(ss[0], ss[2]) + 3 * s2 * start.size() : ss[assumed + 1];
            if (!(ss[other + 1] + 3 * s2 * start.size() < ssAssumed)) continue;
            for (Measurement m : start) flips.computeIfAbsent(m.poseId() + "|" + m.set(), k -> m.directions())[j] = other;
            List<String> ids = start.stream().map(Measurement::poseId).toList();
            notes.add(String.format(Locale.ROOT, "%s direction on joint %d taken from %s residual%s: the campaign seems to start away "
                    + "from the zero position (a first move from zero gives %s, the residual%s support%s %s: RMS %.4f mm against "
                    + "%.4f mm per pose); record dir1..dir%d, or start the measuring program at the zero position, to be sure",
                    ids.size() == 1 ? "pose " + ids.get(0) + "'s" : "poses " + String.join(", ", ids) + "'", j + 1,
                    ids.size() == 1 ? "its" : "their", ids.size() == 1 ? "" : "s", assumed > 0 ? "+" : assumed < 0 ? "-" : "no direction",
                    ids.size() == 1 ? "" : "s", ids.size() == 1 ? "s" : "", other > 0 ? "+" : "-",
                    Math.sqrt(ss[other + 1] / start.size()) * 1e3, Math.sqrt(ssAssumed / start.size()) * 1e3, d.model().geometry().dof()));
        }
        if (flips.isEmpty()) return null;
        java.util.function.UnaryOperator<Measurement> flip = m -> {
            int[] dir = flips.get(m.poseId() + "|" + m.set());
            return dir == null ? m : m.withConditions(dir, m.timeS(), m.tempC(), m.payloadKg());
        };
        return new MeasurementSet[] {train.map(flip), validate == null ? null : validate.map(flip)};
    }

    /**
     * For each joint with lost motion named that does not build up over the move (play b), the poses
     * at which its output, moved through the play by the joint values of the measuring order, rests
     * inside the play or on the other flank than its direction gives ({@link Directions#inPlay}): a
     * reversal shorter than the play leaves the output where it stood. Such a pose misses by up to
     * the whole play under the flank model, and would be reported as a bad reading. Taken, for every
     * such pose of the file, only when the training poses among them say so under the diagnosis'
     * model: the output's place within the play lowers their sum of squared residuals by more than a
     * pose's expected noise (3σ²) each. (A measuring program that approaches every pose through a
     * pose the file does not hold crosses the play on moves the file cannot show; its residuals then
     * keep the flanks.) The place is given to the model as the joint's value moved by −(b/2)(s − dir),
     * so that the flank model's −(b/2)·dir makes the output's −(b/2)·s. Returns the sets with those
     * joint values (null when none changes), and says so in {@code notes}.
     */
    static MeasurementSet[] inPlay(Diagnosis d, MeasurementSet train, MeasurementSet validate, boolean inferred, boolean windUps,
                                   List<String> notes) {
        Map<Measurement, double[]> moved = new java.util.IdentityHashMap<>();
        double s2 = d.sigmaM() * d.sigmaM();
        java.util.Set<Measurement> inTrain = java.util.Collections.newSetFromMap(new java.util.IdentityHashMap<>());
        inTrain.addAll(train.rows());
        for (Diagnosis.Finding f : d.effects()) {
            Effect e = f.effect();
            if (e.kind() != Effect.Kind.BACKLASH || e.buildsUp() != windUps || e.approached() || e.heldByGravity() || f.values().length == 0)
                continue;
            int j = e.joint();
            double[] v = f.values(), orders = e.runoutOrders();
            java.util.function.DoubleUnaryOperator play = q -> Effect.play(orders, v, q);
            List<Directions.InPlay> list = Directions.inPlay(train, validate, j, play);
            if (list.isEmpty() || list.stream().anyMatch(r -> r.row().isDistance() || r.row().points().size() > 1)) continue;
            Map<Measurement, double[]> inPlace = new java.util.IdentityHashMap<>();
            for (Directions.InPlay r : list) inPlace.put(r.row(), inPlayQ(r, play.applyAsDouble(r.row().q(j))));
            double ssGiven = 0, ssInPlay = 0;
            int n = 0;
            for (Directions.InPlay r : list) {
                if (!inTrain.contains(r.row())) continue;
                Measurement m = r.row();
                PoseConditions c = PoseConditions.of(m);
                ssGiven += missed2(d, m, c);
                ssInPlay += missed2(d, m.withQ(inPlace.get(m)), c);
                n++;
            }
            // with inferred directions the flanks already follow the file's moves, and so does the play: validation poses alone take
            // it; a wind-up's residuals are not the flank model's, so the caller judges the dead zone in its place
            if (!windUps && (n == 0 ? !inferred : !(ssInPlay + 3 * s2 * n < ssGiven))) continue;
            for (Directions.InPlay r : list) moved.computeIfAbsent(r.row(), Measurement::q)[j] = inPlace.get(r.row())[j];
            notes.add(String.format(Locale.ROOT, "joint %d moved by less than its play (%.4f deg) against the flank it rested on before "
                    + "pose%s %s, which leaves the output where it stood (a play's dead zone): there the output was taken within the "
                    + "play as the joint values of the measuring order move it, not on the flank of the last motion ("
                    + "%s)", j + 1, Math.toDegrees(v[0]), list.size() == 1 ? "" : "s",
                    String.join(", ", list.stream().map(r -> r.row().poseId()).toList()), windUps ? "in place of its wind-up"
                    : n == 0 ? "validation poses only"
                    : String.format(Locale.ROOT, "training RMS %.4f mm against %.4f mm per pose", Math.sqrt(ssInPlay / n) * 1e3,
                    Math.sqrt(ssGiven / n) * 1e3)));
        }
        if (moved.isEmpty()) return null;
        java.util.function.UnaryOperator<Measurement> toPlace = m -> moved.containsKey(m) ? m.withQ(moved.get(m)) : m;
        return new MeasurementSet[] {train.map(toPlace), validate == null ? null : validate.map(toPlace)};
    }

    /** Pose r's joint values with its joint moved so that the flank model's lag becomes the lag at its place in the play. */
    private static double[] inPlayQ(Directions.InPlay r, double play) {
        double[] q = r.row().q();
        q[r.joint()] -= 0.5 * play * (r.side() - r.row().directions()[r.joint()]);
        return q;
    }

    /** The squared distance between row m's measured point and where the diagnosis' final model puts it under conditions c. */
    private static double missed2(Diagnosis d, Measurement m, PoseConditions c) {
        org.robopro.models.Vec3 p = d.finalInstrumentTbase().times(d.model().tool(m.q(), d.finalFlangeTtool(), c)).position();
        double e = p.minus(m.position()).norm();
        return e * e;
    }

    /** The stepwise selection's state (effects, their absorbed columns, their steps) as it was, to be put back. */
    private record Selection(List<Effect> selected, Map<Effect, boolean[]> absorbed, List<Step> steps) {
        static Selection of(List<Effect> selected, Map<Effect, boolean[]> absorbed, List<Step> steps) {
            return new Selection(new ArrayList<>(selected), new java.util.IdentityHashMap<>(absorbed), new ArrayList<>(steps));
        }

        void restore(List<Effect> selectedNow, Map<Effect, boolean[]> absorbedNow, List<Step> stepsNow) {
            selectedNow.clear();
            selectedNow.addAll(selected);
            absorbedNow.clear();
            absorbedNow.putAll(absorbed);
            stepsNow.clear();
            stepsNow.addAll(steps);
        }
    }

    /** At least this many training poses per fold for the cross-validation of the claims. */
    static final int MIN_POSES_PER_FOLD = 10;

    /** What a named effect claims: its family and joints (a gear's harmonics or a mass model may differ between folds). */
    static String claimKey(Effect e) {
        StringBuilder b = new StringBuilder(e.json());
        for (int j : e.joints1()) b.append(" j").append(j);
        return b.toString();
    }

    private static Set<String> namedKeys(Diagnosis d) { return namedKeys(d.effects().stream().map(Diagnosis.Finding::effect).toList()); }

    private static Set<String> namedKeys(List<Effect> effects) {
        Set<String> out = new java.util.LinkedHashSet<>();
        for (Effect e : effects) if (!e.isFallback()) out.add(claimKey(e));
        return out;
    }

    /**
     * What the cross-validation takes from a fold's diagnosis: the families it names, the poses it
     * left out, its geometric calibration and the held-out fold's error with the geometric model and
     * with the fold's effects.
     */
    record Fold(Set<String> named, List<String> outliers, CalibrationResult geometric, double geometricValidateRmsM,
                double finalValidateRmsM) {
        static Fold of(Diagnosis d) {
            return new Fold(namedKeys(d), d.outliers(), d.geometric(), d.geometricValidateRmsM(), d.finalValidateRmsM());
        }
    }

    /**
     * Without validation poses, the claims are judged by K-fold cross-validation of the whole
     * diagnosis: the training poses are dealt at random into K folds; the diagnosis runs K times,
     * each time on the other folds with the held-out fold as its validation set (so every held-out
     * gate inside it, selection included, sees poses it was not fitted to). Each named family is then
     * judged on its own: it stays named only when all folds but at most one name it on the same joints
     * and the final model without it predicts the folds' held-out poses worse than with it
     * ({@link #perFamilyHeldOut}); otherwise the diagnosis runs again without it (its structure stays
     * located, and a fallback may model it).
     */
    private static Diagnosis crossValidated(RobotDescription robot, MeasurementSet train, Options o, long t0,
                                            Directions.Source dirSource, Diagnosis d) {
        int k = o.folds();
        List<Measurement> rows = train.rows();
        if (rows.size() < MIN_POSES_PER_FOLD * k) {
            List<String> notes = new ArrayList<>(d.notes());
            notes.add(String.format(Locale.ROOT, "no validation poses and only %d training poses: the claims were judged by "
                    + "leave-one-pose-out error, not by %d-fold cross-validation (at least %d poses); measure validation poses to "
                    + "confirm them", rows.size(), k, MIN_POSES_PER_FOLD * k));
            return with(d, d.outliers(), notes);
        }
        int[] fold = MeasurementSet.folds(rows.size(), k, rows.size());
        Options fo = o.withFolds(0).withProgress(Progress.NONE);
        Map<String, Integer> count = new LinkedHashMap<>();
        double[] heldSs = new double[2]; // the held-out sums of squares: geometric model, each fold's effects
        List<Fold> folds = CalibrationWorkflow.crossValidate(train, fold, k, (f, tr, va) -> {
            o.cancel().check();
            o.progress().update("cross-validating the claims (fold " + (f + 1) + " of " + k + ")", (double) f / k);
            Fold df = firstRun(robot, tr, va, fo, t0, dirSource, Set.of()).fold;
            for (String key : df.named()) count.merge(key, 1, Integer::sum);
            heldSs[0] += va.size() * df.geometricValidateRmsM() * df.geometricValidateRmsM();
            heldSs[1] += va.size() * df.finalValidateRmsM() * df.finalValidateRmsM();
            return df;
        });
        double geoCv = Math.sqrt(heldSs[0] / rows.size()), effCv = Math.sqrt(heldSs[1] / rows.size());
        List<String> extra = new ArrayList<>();
        extra.add(String.format(Locale.ROOT, "no validation poses: the claims were judged by %d-fold cross-validation of the whole "
                + "diagnosis; held-out RMS %.4f mm with the geometric model, %.4f mm with each fold's effects", k, geoCv * 1e3, effCv * 1e3));
        Set<String> excluded = new java.util.LinkedHashSet<>();
        Diagnosis out = d;
        // Where the last round's notes on the keys it kept start in extra, and how many: a key kept in
        // several rounds is reported once, by the last round that judged it.
        int namedAt = 0, namedCount = 0;
        for (int round = 0; round < 3; round++) {
            Map<String, double[]> held = perFamilyHeldOut(robot, train, fold, folds, out, o);
            Set<String> failing = new java.util.LinkedHashSet<>();
            extra.subList(namedAt, namedAt + namedCount).clear();
            namedAt = extra.size();
            for (String key : namedKeys(out)) {
                int n = foldCount(count, key, k);
                double[] h = held.get(key);
                boolean helps = h != null && h[0] < h[1];
                if (!foldsAgree(n, k) || !helps) failing.add(key);
                else extra.add(String.format(Locale.ROOT, "%s: named by %d of %d folds; the folds' held-out error %.1f with it, "
                        + "%.1f without it (each residual over its noise)", key, n, k, h[0], h[1]));
            }
            namedCount = extra.size() - namedAt;
            if (failing.isEmpty()) break;
            for (String key : failing) {
                int n = foldCount(count, key, k);
                double[] h = held.get(key);
                extra.add(String.format(Locale.ROOT, "%s is not claimed: %s", key, !foldsAgree(n, k)
                        ? String.format(Locale.ROOT, "only %d of %d cross-validation folds name it (at least %d must)", n, k,
                        foldsNeeded(k))
                        : h == null ? "the folds could not judge it on its own"
                        : String.format(Locale.ROOT, "the final model without it predicts the folds' held-out poses as well or "
                        + "better (error %.1f with it, %.1f without it)", h[0], h[1])));
            }
            excluded.addAll(failing);
            out = prepared(robot, train, null, o, t0, dirSource, excluded);
        }
        List<String> notes = new ArrayList<>(out.notes());
        notes.addAll(extra);
        return with(out, out.outliers(), notes);
    }

    /**
     * Whether {@code n} of {@code k} cross-validation folds naming a family is agreement enough to
     * claim it: every fold but at most one (and a majority). Each fold sees 1 − 1/k of the poses; a
     * family those poses show clearly is found by nearly all of them, and one at the edge of what
     * they show is the kind the held-out gates pass by chance (docs/diagnosis.md, the held-out rule).
     */
    static boolean foldsAgree(int n, int k) { return n >= foldsNeeded(k); }

    /** The folds of {@code k} that must name a family ({@link #foldsAgree}). */
    private static int foldsNeeded(int k) { return Math.max(k / 2 + 1, k - 1); }

    /**
     * How many of the {@code k} folds named claim {@code key}: a growth of the arm with temperature
     * counts the same uniform or link by link (a fold's poses may choose either form, as a gear's
     * harmonic set may differ between folds).
     */
    static int foldCount(Map<String, Integer> count, String key, int k) {
        if (!growth(key)) return count.getOrDefault(key, 0);
        int n = 0;
        for (Map.Entry<String, Integer> c : count.entrySet()) if (growth(c.getKey())) n += c.getValue();
        return Math.min(n, k);
    }

    private static boolean growth(String key) {
        return key.equals(Effect.Kind.THERMAL.json) || key.equals(Effect.Kind.THERMAL_LINK.json);
    }

    /**
     * Each named family of {@code d} judged by the folds on its own: per fold, the final model's
     * effects (families and fallbacks, with the columns the full fit left to the geometry left to it
     * again) are fitted jointly with the geometry to the fold's training poses (without the fold
     * diagnosis' outliers), from the fold's geometric calibration, once with every effect and once
     * without each family; the held-out fold's error (each residual over its noise, orientation
     * included) is summed over the folds. Returns claim key to {error with it, error without it}.
     */
    static Map<String, double[]> perFamilyHeldOut(RobotDescription robot, MeasurementSet train, int[] fold, List<Fold> folds,
                                                  Diagnosis d, Options o) {
        Map<String, double[]> out = new LinkedHashMap<>();
        List<Effect> effects = new ArrayList<>();
        Map<Effect, boolean[]> masks = new java.util.IdentityHashMap<>();
        for (Diagnosis.Finding f : d.effects()) {
            Effect e = f.effect();
            effects.add(e);
            boolean[] m = new boolean[e.size()];
            List<String> names = e.parameterNames();
            for (int i = 0; i < m.length; i++) m[i] = f.evidence().absorbed().contains(names.get(i));
            masks.put(e, m);
        }
        KinematicModel model = KinematicModel.build(robot);
        GravityTorques gravity = GravityTorques.of(model, robot);
        for (int f = 0; f < folds.size(); f++) {
            o.cancel().check();
            Fold df = folds.get(f);
            Set<String> outl = new HashSet<>(df.outliers());
            MeasurementSet.FoldSplit split = train.foldSplit(fold, f);
            Work w = new Work(model, gravity, split.train().filter(m -> !outl.contains(m.poseId())).rows(), df.geometric(), split.heldOut(), o);
            double[] start = Arrays.copyOf(w.geoFull, w.geoFull.length + d.effects().stream().mapToInt(x -> x.effect().size()).sum());
            int off = w.geoFull.length;
            for (Diagnosis.Finding x : d.effects()) for (double v : x.values()) start[off++] = v; // from the full fit's values
            Fit all = w.fit(effects, masks, start, null);
            double with = w.validateError(all);
            for (int i = 0; i < effects.size(); i++) {
                Effect e = effects.get(i);
                if (e.isFallback()) continue;
                double without = w.validateError(w.refitWithout(all, effects, masks, i));
                double[] h = out.computeIfAbsent(claimKey(e), x -> new double[2]);
                h[0] += with;
                h[1] += without;
            }
        }
        return out;
    }

    /** {@code d} with the given outliers and notes, everything else as it is. */
    private static Diagnosis with(Diagnosis d, List<String> outliers, List<String> notes) {
        return new Diagnosis(d.robot(), d.geometric(), d.sigmaM(), d.geometricTrainRmsM(), d.geometricValidateRmsM(), d.effects(),
                d.finalTrainRmsM(), d.finalValidateRmsM(), outliers, d.notIdentifiable(), d.implausible(), d.recommendations(),
                notes, d.model(), d.finalFlangeTtool(), d.finalInstrumentTbase(), d.candidatesTested(), d.alpha(), d.elapsedMs(),
                d.directions(), d.located(), d.warnings());
    }

    /**
     * The first run of a diagnosis: with the geometric fit's outliers left out; but a run of them one
     * after another in time is kept in as a change at one time ({@link #runInTime}), and when no step
     * at that time is found, they are left out after all.
     */
    private static Run firstRun(RobotDescription robot, MeasurementSet train, MeasurementSet validate, Options o, long t0,
                                Directions.Source dirSource, Set<String> excluded) {
        return firstRun(robot, train, validate, o, t0, dirSource, excluded, false);
    }

    /** {@link #firstRun} that may set gross validation readings aside from the start ({@link #run}'s {@code screen}). */
    private static Run firstRun(RobotDescription robot, MeasurementSet train, MeasurementSet validate, Options o, long t0,
                                Directions.Source dirSource, Set<String> excluded, boolean screen) {
        Run r = run(robot, train, validate, o, null, t0, dirSource, excluded, Double.NaN, screen);
        return r.unexplainedRun.isEmpty() ? r : run(robot, train, validate, o, r.unexplainedRun, t0, dirSource, excluded, Double.NaN, screen);
    }

    /**
     * The diagnosis of data whose directions are prepared, with the outlier rule judged under the
     * extended model. A validation pose beyond the same rule (5 robust sigmas of the validation
     * poses under the final model) is a bad measurement too: it would decide the validation gates
     * and dominate the validation error. With a structure left unexplained at the end (the model
     * cannot predict every pose) only a gross reading is, beyond {@link #GROSS_SIGMAS}. It is reported as an outlier, the diagnosis is run again
     * without it, and the notes say so with its error.
     */
    private static Diagnosis prepared(RobotDescription robot, MeasurementSet train, MeasurementSet validate, Options o, long t0,
                                      Directions.Source dirSource, Set<String> excluded) {
        Run r = firstRun(robot, train, validate, o, t0, dirSource, excluded, true);
        // a structure only the poses beyond the rule carry, which the validation poses on its far side show too (see judged)
        Run every = everyPose(r, robot, train, validate, o, t0, dirSource, excluded);
        if (every != null) r = every;
        if (r.validationOutliers().isEmpty() && r.screened.isEmpty())
            return judged(r, robot, train, validate, o, t0, dirSource, excluded, List.of(), new HashSet<>());
        Set<String> bad = new HashSet<>();
        for (CalibrationResult.Outlier ol : r.validationOutliers()) bad.add(ol.poseId());
        MeasurementSet clean = validate.filter(m -> !bad.contains(m.poseId()));
        List<Measurement> beyond = validate.rows().stream().filter(m -> bad.contains(m.poseId())).toList();
        Set<String> inRegion = new HashSet<>();
        // the poses set aside from the start are exactly those the final model puts beyond the rule: that run was the run
        // without them already
        Run clear = bad.equals(new HashSet<>(r.screened)) ? r : firstRun(robot, train, clean, o, t0, dirSource, excluded);
        Diagnosis d = judged(clear, robot, train, clean, o, t0, dirSource, excluded, beyond, inRegion);
        List<String> outliers = new ArrayList<>(d.outliers()), notes = new ArrayList<>(d.notes());
        for (CalibrationResult.Outlier ol : r.validationOutliers()) {
            boolean region = inRegion.contains(ol.poseId());
            if (!region && !outliers.contains(ol.poseId())) outliers.add(ol.poseId());
            notes.add(String.format(Locale.ROOT, "validation pose %s misses by %.4f mm, %.0f robust sigmas (%.4f mm) of the "
                    + "validation poses under the final model: %s left out of the validation error and of every decision taken on "
                    + "the validation poses", ol.poseId(), ol.residualM() * 1e3, Math.floor(ol.residualM() / ol.robustSigmaM()),
                    ol.robustSigmaM() * 1e3, region ? "it lies in the region of the training poses the model does not follow (see "
                    + "above), so it is no bad reading either, but the model's miss; it is" : "it is reported as an outlier and"));
        }
        return with(d, outliers, notes);
    }

    /**
     * Robust sigmas beyond which a pose is reported as a bad reading under a final model that misses
     * the stated floor, or that follows a structure through a fallback's shape: twice the rule's
     * {@link #OUTLIER_K}. On a clean-room campaign of a lost motion beside thermal growth, left 1.3
     * times above its floor, the five bad readings stood at 16-63 robust sigmas and three clean poses
     * at 5.3-7.0; on one of a link bending with drive heat, two clean poses at 5.0-5.3. Under
     * fallbacks at the floor, single clean poses stood at 5.0-6.0 (a pedestal's rocking foot, the
     * upper arm's twist, a dress pack's drag), the world's bad readings of 0.5-3 mm beyond 10.
     */
    static final double SHORT_MODEL_SIGMAS = 10;

    /**
     * Too many training poses beyond the rule to be bad readings, left out all the same (the farthest
     * as gross readings, the rest then few enough) by a run that found nothing in what was left: a
     * structure only they carry (a play whose other side few poses show, a step) is seen only with
     * them in. The run with every pose in, when it models something and leaves fewer poses beyond
     * the rule; else null.
     */
    private static Run everyPose(Run r, RobotDescription robot, MeasurementSet train, MeasurementSet validate, Options o, long t0,
                                 Directions.Source dirSource, Set<String> excluded) {
        if (r.named || !tooManyToBeBad(r.outliers().size(), train.size())) return null;
        Run all = run(robot, train, validate, o, List.of(), t0, dirSource, excluded);
        LOG.debug("nothing found without {} poses beyond the rule; with every pose: named {}, beyond the rule {}", r.outliers().size(),
                all.named, all.outliersUnder);
        return all.named && all.outliersUnder.size() < r.outliers().size() ? all : null;
    }

    /** {@link #prepared}'s outlier rule under the extended model, given the first run. */
    private static Diagnosis judged(Run r, RobotDescription robot, MeasurementSet train, MeasurementSet validate, Options o, long t0,
                                    Directions.Source dirSource, Set<String> excluded, List<Measurement> validationBeyond,
                                    Set<String> validationInRegion) {
        Run underRun = r;
        if (!r.named) {
            Run every = everyPose(r, robot, train, validate, o, t0, dirSource, excluded);
            return every == null ? r.reported() : judged(every, robot, train, validate, o, t0, dirSource, excluded, validationBeyond, validationInRegion);
        }
        // The geometric fit's outlier rule sees an effect's residuals: it flags poses an effect moved
        // most and misses outliers the effect's spread hides. The same rule under the extended model
        // decides; if it differs, diagnose again with its outliers.
        List<String> under = r.outliersUnder;
        // The geometric fit's outliers may be the peak of a structure the effects now model, which a
        // model fitted without them cannot judge: judge them with the effects fitted to every pose
        // (but the gross readings among many, which would bend that fit). When the final model's
        // effects, fitted so, still put every one of them beyond the rule, they are not; else the
        // whole diagnosis is made again with them (the search may take other effects with them in).
        // A gross reading among many stays out of it only while that model still puts it beyond the
        // rule: the peaks of a structure the geometry could not follow look gross to the geometric fit.
        List<String> underEvery = r.outliers().isEmpty() ? List.of() : r.underEveryPose.get();
        if (!r.outliers().isEmpty() && !underEvery.containsAll(r.outliers())) {
            Run all = run(robot, train, validate, o, r.gross.stream().filter(underEvery::contains).toList(), t0, dirSource, excluded);
            if (all.named) {
                List<String> underAll = all.outliersUnder;
                if (underAll.isEmpty()) return all.reported();
                if (underAll.size() < under.size()) {
                    under = underAll;
                    underRun = all;
                }
            }
        }
        // The same poses beyond the rule as the run left out are bad readings, unless all of them lie within one band of a
        // joint's angle: then they are where the model does not follow the arm (a bump of a joint's error narrower than its
        // fallback's features), judged below as any such region. Only that form: its poses were left out by the geometric
        // fit and the final model alike, and a few gross readings can neighbour one another in some joints by chance.
        Region region;
        if (new HashSet<>(under).equals(new HashSet<>(r.outliers()))) {
            region = band(under, train.rows());
            if (region == null || !(region.p() < REGION_ALPHA)) return r.reported();
        } else region = region(under, train.rows());
        if (LOG.isDebugEnabled()) LOG.debug("outliers under the model {} (robust sigmas {}): {}, linked {}", under, r.sigmasUnder,
                region == null ? "-" : region.words(), region == null ? "-" : region.linked());
        if (region != null && region.p() < REGION_ALPHA) {
            // a pose next to none of the region's, beyond twice what its poses typically reach, is a bad reading all the same
            Map<String, Double> sigmas = underRun.sigmasUnder;
            Diagnosis rd = underRun.d();
            double[] zs = region.linked().stream().mapToDouble(id -> sigmas.getOrDefault(id, 0.0)).sorted().toArray();
            double typical = zs.length == 0 ? Double.POSITIVE_INFINITY : Stats.median(zs);
            List<String> beyondRule = under;
            java.util.function.Predicate<String> ofRegion = id -> beyondRule.contains(id) && region.linked().contains(id)
                    && sigmas.getOrDefault(id, 0.0) < REGION_GROSS * typical;
            // the region's poses the run left out of its fit stay out of it (kept in, they would bend the fit where the
            // model holds), but are no more reported than the others
            List<String> keptOut = rd.outliers().stream().filter(ofRegion).toList();
            List<String> bad = new ArrayList<>(rd.outliers().stream().filter(ofRegion.negate()).toList());
            List<String> far = new ArrayList<>();
            for (String id : under)
                if (!region.linked().contains(id) && sigmas.getOrDefault(id, 0.0) >= REGION_GROSS * typical && !bad.contains(id))
                    far.add(id);
            bad.addAll(far);
            List<String> inRegion = under.stream().filter(id -> !bad.contains(id)).toList();
            List<String> forced = new ArrayList<>(rd.outliers());
            forced.addAll(far);
            Diagnosis base = far.isEmpty() ? rd : run(robot, train, validate, o, forced, t0, dirSource, excluded).d();
            for (Measurement m : validationBeyond) if (region.holds(m, train.rows())) validationInRegion.add(m.poseId());
            List<String> notes = new ArrayList<>(base.notes());
            notes.add(String.format(Locale.ROOT, "poses %s lie beyond %.0f robust sigmas of the final model but are not reported as "
                    + "bad measurements: %s, so they are a region where the model does not follow the arm, not bad readings (a bad "
                    + "reading among them cannot be told from them%s%s)", String.join(", ", inRegion), OUTLIER_K, region.words(),
                    keptOut.isEmpty() ? "" : String.format(Locale.ROOT, "; %s %s left out of the fit, which %s would bend where the "
                    + "model holds", String.join(", ", keptOut), keptOut.size() == 1 ? "is" : "are", keptOut.size() == 1 ? "it" : "they"),
                    far.isEmpty() ? "" : String.format(Locale.ROOT, "; %s, next to none of them and beyond %.0f "
                    + "robust sigmas, twice the %.1f its poses typically reach, %s reported", String.join(", ", far),
                    REGION_GROSS * typical, typical, far.size() == 1 ? "is" : "are")));
            return with(base, bad, notes);
        }
        Diagnosis d = r.reported();
        if (tooManyToBeBad(under.size(), train.size())) return grossOnly(d, under, robot, train, validate, o, t0, dirSource, excluded);
        Run without = run(robot, train, validate, o, under, t0, dirSource, excluded);
        List<String> more = appearing(without, under);
        if (more.size() <= 1) {
            // Reported as bad readings, they are left out of the fit: that must predict the validation poses at least as well as
            // the diagnosis with every pose in (the first run's left out ones are not beyond the rule under its model).
            if (validate != null && !validate.rows().isEmpty()) {
                Diagnosis every = d.outliers().isEmpty() ? d : run(robot, train, validate, o, List.of(), t0, dirSource, excluded).d();
                double valWith = every.finalValidateRmsM(), valWithout = without.d().finalValidateRmsM();
                if (valWithout > valWith * (1 + ALIAS_MARGIN)) {
                    List<String> notes = new ArrayList<>(every.notes());
                    notes.add(String.format(Locale.ROOT, "%s %s beyond %.0f robust sigmas of the final model but %s not reported as "
                            + "bad measurements: left out, the diagnosis predicts the validation poses worse (%.4f mm against %.4f mm), "
                            + "so nothing shows they are bad readings rather than a structure the model does not follow",
                            under.size() == 1 ? "pose" : "poses", String.join(", ", under), OUTLIER_K, under.size() == 1 ? "is" : "are",
                            valWithout * 1e3, valWith * 1e3));
                    return with(every, every.outliers(), notes);
                }
            }
            return without.reported();
        }
        List<String> notes = new ArrayList<>(d.notes());
        // those the final model still puts far beyond the rule where it misses the stated floor are reported all the same
        List<String> reportedAnyway = under.stream().filter(d.outliers()::contains).toList();
        notes.add(String.format(Locale.ROOT, "%s %s beyond %.0f robust sigmas of the final model but %s not reported as bad "
                + "measurements: left out, %d more poses come beyond the rule (%s), so they belong to a structure the model does not "
                + "follow, not to bad readings%s", under.size() == 1 ? "pose" : "poses", String.join(", ", under), OUTLIER_K,
                under.size() == 1 ? "is" : "are", more.size(), String.join(", ", more), reportedAnyway.isEmpty() ? ""
                : String.format(Locale.ROOT, " (but %s, beyond %.0f robust sigmas of a model that misses the stated floor, %s "
                + "reported as %s)", String.join(", ", reportedAnyway), SHORT_MODEL_SIGMAS, reportedAnyway.size() == 1 ? "is" : "are",
                reportedAnyway.size() == 1 ? "a bad reading" : "bad readings")));
        return with(d, d.outliers(), notes);
    }

    /**
     * Where the poses {@code ids} lie next to one another: for every set of joints tried (all, the
     * arm's first three, the wrist's last three, each pair), how many of them have another of them as
     * nearest pose (angles over each joint's sampled range), against how many poses picked at random
     * would (each one's nearest is one of the others with chance (g − 1)/(n − 1)); the binomial chance
     * of as many or more, times the sets tried (Bonferroni). Bad readings (a beam broken, a target
     * knocked for one reading) fall on poses at random; poses where the model does not follow the arm
     * share a region of some of its joints. Returns the set with the lowest chance; when that is not
     * below {@link #REGION_ALPHA}, the region at the ends of one angle ({@link #atTheEnds}) if that is
     * (each test at that level); null when there are fewer than three poses.
     */
    static Region region(List<String> ids, List<Measurement> poses) {
        List<Measurement> in = posesOf(ids, poses);
        Set<String> set = idsOf(in);
        int n = poses.size(), g = in.size();
        if (g < 3 || n < 4) return null;
        int dof = poses.get(0).q().length;
        double[] span = spans(poses);
        List<int[]> sets = new ArrayList<>();
        sets.add(java.util.stream.IntStream.range(0, dof).toArray());
        if (dof > 3) { sets.add(new int[] {0, 1, 2}); sets.add(java.util.stream.IntStream.range(3, dof).toArray()); }
        for (int a = 0; a < dof; a++) for (int b = a + 1; b < dof; b++) sets.add(new int[] {a, b});
        sets.removeIf(js -> Arrays.stream(js).noneMatch(j -> span[j] > 0));
        double p0 = (g - 1.0) / (n - 1.0);
        Region best = null;
        for (int[] js : sets) {
            int count = 0;
            Set<String> linked = new HashSet<>();
            for (Measurement mi : in) {
                Measurement nearest = null;
                double bestD = Double.POSITIVE_INFINITY;
                for (Measurement mk : poses) {
                    if (mk == mi) continue;
                    double d = 0;
                    for (int j : js) {
                        if (!(span[j] > 0)) continue;
                        double x = (mi.q(j) - mk.q(j)) / span[j];
                        d += x * x;
                    }
                    if (d < bestD) { bestD = d; nearest = mk; }
                }
                if (nearest != null && set.contains(nearest.poseId())) { count++; linked.add(mi.poseId()); linked.add(nearest.poseId()); }
            }
            double p = Math.min(1, (count == 0 ? 1 : Stats.regularizedBeta(p0, count, g - count + 1)) * sets.size());
            if (best == null || p < best.p) {
                best = new Region(js, count, g, g * p0, p, range(in, js, false), range(in, js, true), linked, null, Double.NaN, Double.NaN, false);
            }
        }
        if (best != null && best.p() < REGION_ALPHA) return best;
        Region ends = atTheEnds(in, poses, span);
        if (ends != null && ends.p() < REGION_ALPHA) return ends;
        Region band = inABand(in, poses, span);
        return band != null && band.p() < REGION_ALPHA ? band : best;
    }

    /**
     * The second form of a region: the poses lie at the ends of the range of one joint's angle, or of
     * the sum or difference of two joints' angles (a linkage's angle: the IRB 2000's forearm is
     * driven through a parallel rod, so its rod's angle is q3 − q2, robots.md), all within the t
     * lowest, the t highest, or the t lowest and t highest of the poses there, t as small as holds
     * them all, and at least half the poses there: a model that does not follow the arm misses most
     * where it reaches its range's ends (a linkage near its dead point, a curve fitted between the
     * ends), and misses most poses there; bad readings fall on poses at random. g poses of n at random
     * all lie within a set of k with chance C(k, g) / C(n, g); that times the variables and sides tried
     * (Bonferroni). Null when no variable is spread or no end holds them so.
     */
    static Region atTheEnds(List<Measurement> in, List<Measurement> poses, double[] span) {
        int n = poses.size(), g = in.size(), dof = span.length;
        List<int[]> vars = new ArrayList<>(); // coefficients of the joints' angles
        for (int a = 0; a < dof; a++) { int[] c = new int[dof]; c[a] = 1; vars.add(c); }
        for (int a = 0; a < dof; a++)
            for (int b = a + 1; b < dof; b++) {
                int[] sum = new int[dof], diff = new int[dof];
                sum[a] = 1; sum[b] = 1; diff[a] = 1; diff[b] = -1;
                vars.add(sum);
                vars.add(diff);
            }
        vars.removeIf(c -> { for (int j = 0; j < dof; j++) if (c[j] != 0 && !(span[j] > 0)) return true; return false; });
        if (vars.isEmpty()) return null;
        int tests = 3 * vars.size();
        Set<String> linked = idsOf(in);
        Region best = null;
        for (int[] c : vars) {
            double[] v = new double[n];
            Integer[] order = new Integer[n];
            int lowT = 0, highT = 0, bothT = 0;
            for (int r : ranks(c, poses, in, v, order)) {
                lowT = Math.max(lowT, r + 1);
                highT = Math.max(highT, n - r);
                bothT = Math.max(bothT, Math.min(r + 1, n - r));
            }
            int[] ks = {lowT, highT, Math.min(n, 2 * bothT)};
            for (int side = 0; side < 3; side++) {
                // a region the model does not follow: most of its poses are beyond the rule, not a few among many followed
                if (ks[side] > 2 * g) continue;
                double p = Math.min(1, chanceWithin(ks[side], n, g) * tests);
                if (best != null && !(p < best.p())) continue;
                int t = side == 0 ? lowT : side == 1 ? highT : bothT;
                double lowCut = side == 1 ? Double.NaN : v[order[t - 1]], highCut = side == 0 ? Double.NaN : v[order[n - t]];
                int[] js = java.util.stream.IntStream.range(0, dof).filter(j -> c[j] != 0).toArray();
                best = new Region(js, side == 2 ? 2 * t : t, g, g * (double) (side == 2 ? 2 * t : t) / n, p, range(in, js, false),
                        range(in, js, true), linked, c, lowCut, highCut, false);
            }
        }
        return best;
    }

    /** Each of joints {@code js}'s lowest (or with {@code high} highest) angle among poses {@code in}, rad (0 with none). */
    private static double[] range(List<Measurement> in, int[] js, boolean high) {
        double[] out = new double[js.length];
        for (int a = 0; a < js.length; a++) {
            int j = js[a];
            java.util.stream.DoubleStream q = in.stream().mapToDouble(m -> m.q(j));
            out[a] = (high ? q.max() : q.min()).orElse(0);
        }
        return out;
    }

    /** {@link #inABand} of the poses {@code ids} among {@code poses}; null when there are fewer than three. */
    static Region band(List<String> ids, List<Measurement> poses) {
        List<Measurement> in = posesOf(ids, poses);
        return in.size() < 3 || poses.size() < 4 ? null : inABand(in, poses, spans(poses));
    }

    /** The poses among {@code poses} whose ids are {@code ids}, in their order. */
    private static List<Measurement> posesOf(List<String> ids, List<Measurement> poses) {
        Set<String> set = new HashSet<>(ids);
        return poses.stream().filter(m -> set.contains(m.poseId())).toList();
    }

    /** The ids of poses {@code in}. */
    private static Set<String> idsOf(List<Measurement> in) {
        Set<String> out = new HashSet<>();
        for (Measurement m : in) out.add(m.poseId());
        return out;
    }

    /** Each joint's range of angles over the poses, rad. */
    private static double[] spans(List<Measurement> poses) {
        int dof = poses.get(0).q().length;
        double[] span = new double[dof];
        for (int j = 0; j < dof; j++) {
            double a = Double.POSITIVE_INFINITY, b = Double.NEGATIVE_INFINITY;
            for (Measurement m : poses) { a = Math.min(a, m.q(j)); b = Math.max(b, m.q(j)); }
            span[j] = b - a;
        }
        return span;
    }

    /**
     * The third form of a region: the poses lie within one band of one joint's angle, the run of poses
     * there, sorted by that angle, as short as holds them all and at most twice their number: a model
     * that does not follow the arm over a narrow range of a joint's angle (a bump of the joint's error
     * narrower than its fallback's features, which lives in that joint's own angle) misses most poses
     * there. The chance that g poses of n picked at random lie within some run of k consecutive ones
     * is the number of g-subsets whose ranks span at most k, Σ_{d=g−1}^{k−1} (n − d)·C(d − 1, g − 2),
     * over C(n, g) (the first and last rank d apart, the rest between them); that times the joints
     * tried (Bonferroni). Null when no joint's angle is spread.
     */
    static Region inABand(List<Measurement> in, List<Measurement> poses, double[] span) {
        int n = poses.size(), g = in.size(), dof = span.length;
        List<int[]> vars = new ArrayList<>();
        for (int a = 0; a < dof; a++) if (span[a] > 0) { int[] c = new int[dof]; c[a] = 1; vars.add(c); }
        if (vars.isEmpty() || g < 3) return null;
        Set<String> linked = idsOf(in);
        Region best = null;
        for (int[] c : vars) {
            double[] v = new double[n];
            Integer[] order = new Integer[n];
            int[] rk = ranks(c, poses, in, v, order);
            if (rk.length == 0) continue;
            int first = rk[0], last = rk[rk.length - 1], k = last - first + 1;
            if (k > 2 * g) continue;
            double p = Math.min(1, chanceInARun(k, n, g) * vars.size());
            if (best != null && !(p < best.p())) continue;
            int[] js = java.util.stream.IntStream.range(0, dof).filter(j -> c[j] != 0).toArray();
            best = new Region(js, k, g, Double.NaN, p, range(in, js, false), range(in, js, true), linked, c, v[order[first]],
                    v[order[last]], true);
        }
        return best;
    }

    /**
     * The ranks, ascending, of the poses {@code in} among {@code poses} sorted by the angle Σ c_j q_j;
     * fills v with each pose's value of it and order with the poses' indices by rank.
     */
    private static int[] ranks(int[] c, List<Measurement> poses, List<Measurement> in, double[] v, Integer[] order) {
        int n = poses.size();
        for (int i = 0; i < n; i++) { v[i] = combination(c, poses.get(i)); order[i] = i; }
        Arrays.sort(order, (x, y) -> Double.compare(v[x], v[y]));
        Set<Measurement> flagged = java.util.Collections.newSetFromMap(new java.util.IdentityHashMap<>());
        flagged.addAll(in);
        return java.util.stream.IntStream.range(0, n).filter(r -> flagged.contains(poses.get(order[r]))).toArray();
    }

    /** The chance that g poses picked at random of n lie within some run of k consecutive ones (see {@link #inABand}). */
    static double chanceInARun(int k, int n, int g) {
        if (k < g) return 0;
        double count = 0;
        for (int d = g - 1; d <= k - 1; d++) count += (n - d) * binomial(d - 1, g - 2);
        return Math.min(1, count / binomial(n, g));
    }

    private static double binomial(int a, int b) {
        if (b < 0 || b > a) return 0;
        double r = 1;
        for (int i = 0; i < b; i++) r = r * (a - i) / (i + 1);
        return r;
    }

    /** The chance that g poses picked at random of n all lie within a given set of k: C(k, g) / C(n, g). */
    private static double chanceWithin(int k, int n, int g) {
        if (k < g) return 0;
        double p = 1;
        for (int i = 0; i < g; i++) p *= (double) (k - i) / (n - i);
        return p;
    }

    /** Σ c_j q_j of a pose, rad. */
    private static double combination(int[] c, Measurement m) {
        double x = 0;
        for (int j = 0; j < c.length; j++) if (c[j] != 0) x += c[j] * m.q(j);
        return x;
    }

    /**
     * The chance below which poses beyond the outlier rule that lie next to one another are taken as
     * a region the model does not follow rather than bad readings: either answer is a claim about the
     * poses (reporting good readings as bad, or leaving bad ones in), so the conventional 1 % level,
     * not the effects' family-wise one.
     */
    static final double REGION_ALPHA = 0.01;

    /**
     * A pose beyond the rule beside such a region but next to none of its poses is a bad reading when
     * it lies this many times farther out than the region's poses typically do (their median, in
     * robust sigmas): a structure's poses spread about its size, a gross reading (a beam broken, a
     * target out of its nest) stands by itself far beyond them.
     */
    static final double REGION_GROSS = 2;

    /**
     * Poses that lie next to one another in joints {@code joints} (0-based): the test's numbers (how
     * many have another of them as nearest pose, of how many, against how many at random, the chance),
     * their angles' ranges (rad), and the poses in such a pair ({@code linked}). With {@code ends} (the
     * coefficients of the joints' angles in one angle, {@link #atTheEnds}) the poses lie at its ends
     * instead: at or below {@code lowCut}, at or above {@code highCut} (rad; NaN: not at that end),
     * {@code count} the poses there, every one of the region's {@code linked}.
     */
    record Region(int[] joints, int count, int poses, double expected, double p, double[] lo, double[] hi, Set<String> linked,
                  int[] ends, double lowCut, double highCut, boolean band) {
        String words() {
            List<String> js = new ArrayList<>(), ranges = new ArrayList<>();
            for (int a = 0; a < joints.length; a++) {
                js.add(String.valueOf(joints[a] + 1));
                ranges.add(String.format(Locale.ROOT, "q%d %.0f..%.0f deg", joints[a] + 1, Math.toDegrees(lo[a]), Math.toDegrees(hi[a])));
            }
            if (ends != null && band)
                return String.format(Locale.ROOT, "they lie within one band of %s (%.1f..%.1f deg, the %d poses there): all %d of "
                        + "them, where as many poses picked at random would fall in a band so narrow with p = %.2g (over the joints "
                        + "tried)", variable(), Math.toDegrees(lowCut), Math.toDegrees(highCut), count, poses, p);
            if (ends != null) {
                String where = Double.isNaN(highCut) ? String.format(Locale.ROOT, "at or below %.1f deg", Math.toDegrees(lowCut))
                        : Double.isNaN(lowCut) ? String.format(Locale.ROOT, "at or above %.1f deg", Math.toDegrees(highCut))
                        : String.format(Locale.ROOT, "at or below %.1f deg or at or above %.1f deg", Math.toDegrees(lowCut),
                        Math.toDegrees(highCut));
                return String.format(Locale.ROOT, "they lie at the %s of the range of %s (%s, the %d poses nearest %s): all %d "
                        + "of them, where as many poses picked at random would put %.1f (p = %.2g over the angles and ends tried)",
                        Double.isNaN(lowCut) || Double.isNaN(highCut) ? "end" : "ends", variable(), where, count,
                        Double.isNaN(lowCut) || Double.isNaN(highCut) ? "it" : "them", poses, expected, p);
            }
            return String.format(Locale.ROOT, "they lie next to one another in joints %s (%s): %d of the %d have another of them "
                    + "as nearest pose there, against %.1f for poses picked at random (p = %.2g over the sets of joints tried)",
                    String.join(", ", js), String.join(", ", ranges), count, poses, expected, p);
        }

        /** The angle whose ends the poses lie at, in words ("q3 − q2"). */
        String variable() {
            StringBuilder b = new StringBuilder();
            for (int j = 0; j < ends.length; j++) {
                if (ends[j] == 0) continue;
                if (b.length() > 0) b.append(ends[j] > 0 ? " + " : " − ");
                else if (ends[j] < 0) b.append("−");
                b.append("q").append(j + 1);
            }
            return b.toString();
        }

        /**
         * Whether pose m (not one of {@code poses}) lies in the region: at the same end(s) of the
         * angle, or with its nearest pose in the region's joints one of the region's.
         */
        boolean holds(Measurement m, List<Measurement> poses) {
            if (ends != null) {
                double x = combination(ends, m);
                if (band) return x >= lowCut && x <= highCut;
                return (!Double.isNaN(lowCut) && x <= lowCut) || (!Double.isNaN(highCut) && x >= highCut);
            }
            double[] span = new double[joints.length];
            for (int a = 0; a < joints.length; a++) {
                int j = joints[a];
                span[a] = poses.stream().mapToDouble(x -> x.q(j)).max().orElse(0) - poses.stream().mapToDouble(x -> x.q(j)).min().orElse(0);
            }
            Measurement nearest = null;
            double bestD = Double.POSITIVE_INFINITY;
            for (Measurement k : poses) {
                double d = 0;
                for (int a = 0; a < joints.length; a++) {
                    if (!(span[a] > 0)) continue;
                    double x = (m.q(joints[a]) - k.q(joints[a])) / span[a];
                    d += x * x;
                }
                if (d < bestD) { bestD = d; nearest = k; }
            }
            return nearest != null && linked.contains(nearest.poseId());
        }
    }

    /**
     * The poses a run with {@code leftOut} left out flags beyond the outlier rule besides them: one
     * is a pose their spread hid; several at once are a structure's poses appearing as others leave
     * (a lost motion's, a bump's, a step the model does not follow), not bad readings.
     */
    private static List<String> appearing(Run without, List<String> leftOut) {
        return without.outliersUnder.stream().filter(id -> !leftOut.contains(id)).toList();
    }

    /**
     * Many poses beyond 5 robust sigmas under the final model are usually a structure the model
     * leaves (reported as located), not bad measurements. They are gross readings all the same when,
     * left out, the model fitted to the other poses still puts every one of them beyond the rule and
     * leaves no structure unexplained: no shape of any variable the scan knows holds them, so they
     * are reported as outliers however many (up to a fifth of the poses; more is not a campaign to
     * judge poses in). A structure's poses fail this: left out, their shape is no longer seen, and
     * kept in, the located fallback explains them. A model fitted without them may show one more
     * beyond the rule that their spread hid (every one of them still beyond it): that one joins them,
     * and the judgement is made again (a few rounds). Several more at once are a structure's poses
     * appearing as others leave (a lost motion's or a bump's), and the judgement stops there.
     */
    private static Diagnosis grossOnly(Diagnosis d, List<String> under, RobotDescription robot, MeasurementSet train,
                                       MeasurementSet validate, Options o, long t0, Directions.Source dirSource, Set<String> excluded) {
        if (d.located().stream().anyMatch(l -> "final".equals(l.stage()))) return d;
        List<String> out = new ArrayList<>(under);
        for (int round = 0; round < 3 && out.size() <= 0.2 * train.size(); round++) {
            Run without = run(robot, train, validate, o, out, t0, dirSource, excluded);
            boolean clean = without.d().located().stream().noneMatch(l -> "final".equals(l.stage()));
            if (!clean || !without.outliersUnder.containsAll(out)) return d;
            if (new HashSet<>(without.outliersUnder).equals(new HashSet<>(out))) return without.d();
            List<String> more = appearing(without, out);
            if (more.size() > 1) return d;
            out.addAll(more);
        }
        return d;
    }

    /**
     * A diagnosis and the poses the calibration's outlier rule flags under its extended model (and
     * how many robust sigmas out each lies), with the rule's verdict on them under the model refitted
     * to every pose.
     */
    private static final class Run {
        private final java.util.function.Supplier<Finished> finish;
        private Finished finished;
        /** Whether the run named any effect (a family or a fallback). */
        final boolean named;
        /** What a cross-validation fold takes from the run, without finishing its report. */
        final Fold fold;
        private final boolean validationFlagged;
        /** Whether the final model misses the instrument's stated noise floor (see {@link #run}). */
        final boolean missesFloor;
        /** The fallbacks of the final model: structures it follows only as far as a shape fitted to them does. */
        final List<String> approximated;
        final List<String> outliersUnder, gross;
        final java.util.function.Supplier<List<String>> underEveryPose;
        final Map<String, Double> sigmasUnder;
        /** Poses beyond the rule one after another in time that the run kept in and no step at their time explains (else empty). */
        List<String> unexplainedRun = List.of();
        /** The validation poses set aside from the start as gross readings under the geometric fit ({@link #grossValidation}). */
        List<String> screened = List.of();
        /** Training poses that face a second instrument station's split nearly alike ({@link #STATION_AMBIGUOUS}). */
        final Set<String> ambiguous = new HashSet<>();

        Run(java.util.function.Supplier<Finished> finish, boolean named, Fold fold, boolean validationFlagged, boolean missesFloor,
            List<String> approximated, List<String> outliersUnder, List<String> gross, java.util.function.Supplier<List<String>> underEveryPose,
            Map<String, Double> sigmasUnder) {
            this.finish = finish;
            this.named = named;
            this.fold = fold;
            this.validationFlagged = validationFlagged;
            this.missesFloor = missesFloor;
            this.approximated = approximated;
            this.outliersUnder = outliersUnder;
            this.gross = gross;
            this.underEveryPose = underEveryPose;
            this.sigmasUnder = sigmasUnder;
        }

        /** The training poses the run left out. */
        List<String> outliers() { return fold.outliers(); }

        /** The report, finished on first use. */
        Diagnosis d() { return finished().d(); }

        /**
         * The report as the outlier judgement gives it: when the final model misses the instrument's
         * stated floor, or follows a structure only through a fallback's shape, the training poses it
         * left out within {@link #SHORT_MODEL_SIGMAS} of it stay out of the fit but are not reported
         * as bad readings (its residuals have heavier tails than the noise, and a pose a few of its
         * robust sigmas out is no sign of a bad reading).
         */
        Diagnosis reported() {
            Diagnosis d = d();
            if (!missesFloor && approximated.isEmpty()) return d;
            List<String> far = new ArrayList<>(), near = new ArrayList<>(), split = new ArrayList<>();
            // a pose the final model does not put beyond the rule at all is within it: near
            for (String id : d.outliers())
                (ambiguous.contains(id) ? split : sigmasUnder.getOrDefault(id, 0.0) > SHORT_MODEL_SIGMAS ? far : near).add(id);
            if (near.isEmpty() && split.isEmpty()) return d;
            List<String> notes = new ArrayList<>(d.notes());
            if (!split.isEmpty())
                notes.add(String.format(Locale.ROOT, "%s %s %s the two instrument stations nearly alike, so which station read %s is "
                        + "uncertain: left out of the fit but not reported as bad readings; record which station reads each pose",
                        split.size() == 1 ? "pose" : "poses", String.join(", ", split), split.size() == 1 ? "faces" : "face",
                        split.size() == 1 ? "it" : "them"));
            if (near.isEmpty()) return with(d, far, notes);
            String why = missesFloor ? "the model misses the instrument's stated floor (it does not follow every pose)"
                    : "the model follows " + String.join(", ", approximated) + " only as far as a shape fitted to "
                    + (approximated.size() == 1 ? "it" : "them") + " does, not by its physics";
            notes.add(String.format(Locale.ROOT, "%s %s %s within %.0f robust sigmas of the final model (the rule flags beyond %.0f), "
                    + "and %s: %s left out of the fit but not reported as bad readings; measure %s again to tell a bad reading from "
                    + "the model's miss", near.size() == 1 ? "pose" : "poses", String.join(", ", near),
                    near.size() == 1 ? "lies" : "lie", SHORT_MODEL_SIGMAS, OUTLIER_K, why, near.size() == 1 ? "it is" : "they are",
                    near.size() == 1 ? "it" : "them"));
            return with(d, far, notes);
        }

        /** The validation poses beyond the outlier rule under the final model (see {@link #run}). */
        List<CalibrationResult.Outlier> validationOutliers() { return validationFlagged ? finished().validationOutliers() : List.of(); }

        private Finished finished() {
            if (finished == null) finished = finish.get();
            return finished;
        }
    }

    /** A run's report and the validation poses beyond the outlier rule under its final model. */
    private record Finished(Diagnosis d, List<CalibrationResult.Outlier> validationOutliers) { }

    /**
     * The validation poses of {@code w} that are gross readings under its geometric fit {@code g} ({@link #grossAmong} of
     * those beyond the outlier rule, their robust sigma the validation poses'), in file order; none with fewer than 10
     * validation poses, or with lengths (a length's gross error is judged with the model that tells it).
     */
    static List<String> grossValidation(Work w, Fit g, CalibrationResult geo) {
        if (w.validate == null || w.validate.size() < 10 || geo.distance() || geo.pairs()) return List.of();
        List<CalibrationResult.Outlier> far = grossAmong(List.copyOf(
                Calibrator.outliers(g.problem, g.full, w.validate, Set.of(), OUTLIER_K).values()), w.validate.size());
        Set<String> ids = new HashSet<>();
        for (CalibrationResult.Outlier ol : far) ids.add(ol.poseId());
        return w.validate.rows().stream().map(Measurement::poseId).filter(ids::contains).toList();
    }

    /**
     * A lost motion is not claimed where its joint's settling ({@link Effect#settling}) in its place
     * predicts left-out poses better, by {@link #ALIAS_MARGIN}: both follow the sign of the move before
     * the reading, and a reading taken before the arm settled (its size following the move's speed,
     * its sign the phase of the ringing at the reading) can lag like a play. A play, the commoner cause
     * and the catalogue's, stays named where the two predict alike (a 30-pose campaign of a real play),
     * except beside another joint's settling in the model: where the arm was read before it settled a
     * play must beat its joint's settling by the margin and by {@link #TELL_Z} standard errors of the
     * pose-by-pose difference. Else the settling models the structure and the notes say how to tell.
     * A settling taken before the play was, and redundant beside it, leaves.
     */
    private static Fit playOrSettling(Work w, Fit fit, List<Effect> selected, Map<Effect, boolean[]> absorbedCols, List<Step> steps,
                                      List<String> notes) {
        if (w.moves.isEmpty()) return fit;
        for (int k = 0; k < selected.size(); k++) {
            Effect e = selected.get(k);
            if (e.kind() != Effect.Kind.BACKLASH) continue;
            Effect settle = Effect.settling(e.joint(), w.moves, w.speeds);
            Tester at = w.tester(fit);
            double own = at.pressFull(), rival = at.pressReplacing(k, settle, w.conditions);
            // beside another joint's settling in the model (the arm was read before it settled) a play must beat its joint's
            // settling, by the margin and by TELL_Z standard errors of the pose-by-pose difference; else it must not lose to it
            boolean ringing = selected.stream().anyMatch(x -> x.kind() == Effect.Kind.SETTLING && x.joint() != e.joint());
            boolean stays = ringing ? own < rival * (1 - ALIAS_MARGIN) && tellsApart(at, k, settle, w) >= TELL_Z
                    : !(rival < own * (1 - ALIAS_MARGIN));
            if (stays) continue;
            LOG.debug("{}: settling predicts left-out poses {} against {}", e.label(), rival, own);
            int before = selected.size();
            fit = replaceEffect(w, fit, selected, absorbedCols, steps, k, settle, true);
            notes.add(String.format(Locale.ROOT, "%s is not claimed: %s, a deflection that follows the speed of the move just made (the "
                    + "arm read before it settled), predicts left-out poses %s (leave-one-pose-out error %.1f against %.1f); both "
                    + "follow the sign of the move before the reading%s. To tell, repeat a few poses approached from each side, reading once "
                    + "right after the stop and once after a wait of a few seconds: a play stays, a settling fades%s", e.label(),
                    settle.label(), rival < own ? "better" : "nearly as well", rival, own, rival < own ? ""
                    : ", and other joints' readings were taken before the arm settled", selected.size() < before ? "; the settling did not lower the held-out error, so nothing "
                    + "models it" : ""));
            k = -1;
        }
        // a settling taken before its joint's lost motion was, that the play (built up over the move) has made redundant
        for (int k = selected.size() - 1; k >= 0; k--) {
            Effect e = selected.get(k);
            if (e.kind() != Effect.Kind.SETTLING
                    || selected.stream().noneMatch(x -> x.kind() == Effect.Kind.BACKLASH && x.joint() == e.joint())) continue;
            Fit without = w.refitWithout(fit, selected, absorbedCols, k);
            Candidate c = w.tester(without).test(e, w.conditions);
            if (c.keptColumns > 0 && c.p < w.o.alpha() && c.pressAfter < c.pressBefore) continue;
            LOG.debug("{} is redundant beside its joint's lost motion (p {})", e.label(), c.p);
            drop(selected, absorbedCols, steps, k);
            fit = without;
            restampLast(w, fit, steps);
        }
        return fit;
    }

    /**
     * Whether settling {@code e} is significant (at the family-wise α, with a smaller leave-one-pose-out
     * error) beside a constant lost motion of its joint added to the model fitted: a deflection that
     * grows with the move's speed, not only the move's sign. True where no lost motion can be tested.
     */
    static boolean followsSpeed(Work w, Fit fit, List<Effect> selected, Map<Effect, boolean[]> absorbedCols, Effect e) {
        // the lost motion that explains most: of a fixed size, or building up over the move (a wind-up's lag follows the
        // move's size as a settling's does)
        Tester at = w.tester(fit);
        Effect play = null;
        Candidate pc = null;
        List<Effect> plays = new ArrayList<>(List.of(Effect.backlash(e.joint())));
        if (!w.moves.isEmpty()) for (double deg : SETTLING_PLAY_BUILD_UPS_DEG) plays.add(Effect.windUp(e.joint(), Math.toRadians(deg), w.moves));
        for (Effect b : plays) {
            if (!b.testableOn(w.rows)) continue;
            Candidate c = at.test(b, w.conditions);
            if (c.keptColumns > 0 && (pc == null || c.drss > pc.drss)) { play = b; pc = c; }
        }
        if (play == null) return true;
        List<Effect> with = new ArrayList<>(selected);
        with.add(play);
        Map<Effect, boolean[]> abs = new java.util.IdentityHashMap<>(absorbedCols);
        abs.put(play, pc.absorbedMask);
        Candidate sc = w.tester(w.fit(with, abs, fit.full, pc)).test(e, w.conditions);
        return sc.keptColumns > 0 && sc.p < w.o.alpha() && sc.pressAfter < sc.pressBefore;
    }

    /** Build-up lengths of a lost motion building up over the move a settling must be significant beside (deg). */
    static final double[] SETTLING_PLAY_BUILD_UPS_DEG = {2, 5, 10, 20};

    /**
     * Each joint's top speed for a settling's synchronised move (rad/s): the robot file's, or where it
     * gives any joint none, the arm's three joints alike and the wrist's {@link #WRIST_OVER_ARM} times
     * as fast (only the ratios matter: the slowest joint sets the move's time).
     */
    static double[] topSpeeds(RobotDescription robot) {
        double[] s = robot.joints().stream().mapToDouble(org.robopro.models.JointDescription::maxSpeed).toArray();
        boolean known = true;
        for (double v : s) known &= v > 0 && Double.isFinite(v);
        if (!known) for (int k = 0; k < s.length; k++) s[k] = k < 3 ? 1 : WRIST_OVER_ARM;
        return s;
    }

    /**
     * How much faster the wrist's joints turn than the arm's when the robot file gives no speeds: the
     * shipped files' IRB 2400 turns its wrist at 360-450 °/s against 150 °/s for the arm, a KUKA
     * KR 16 at 335-647 against 156 (their data sheets).
     */
    static final double WRIST_OVER_ARM = 2.5;

    /**
     * Share of what the final model leaves that the shapes located in it may hold, below which a
     * joint's scatter is still sought ({@link JointScatter}): a structure of a fifth or more is the
     * residual's own, and the scatter test would see it.
     */
    static final double SCATTER_BESIDE_SHARE = 0.2;

    /** Robust sigmas beyond which a pose is an outlier under the extended model (the calibration's default rule). */
    static final double OUTLIER_K = 5;

    /**
     * The calibration's outlier rule ({@link Calibrator#outliers}: a pose whose worst measured
     * point, or distance, exceeds {@link #OUTLIER_K} robust sigmas) under the extended model of a
     * final fit, over every training pose; poses whose backlash side is unknown are not flagged.
     * Each flagged pose (in file order) with its worst residual in robust sigmas.
     */
    static Map<String, Double> outliersUnder(List<Effect> selected, Fit fit, MeasurementSet train) {
        Map<String, Double> out = new LinkedHashMap<>();
        if (train.size() == 0) return out;
        Map<String, Measurement> byId = new LinkedHashMap<>();
        for (Measurement m : train.rows()) byId.put(m.poseId(), m);
        for (CalibrationResult.Outlier ol : Calibrator.outliers(fit.problem, fit.full, train, Set.of(), OUTLIER_K).values())
            if (!unknownBacklashSide(selected, byId.get(ol.poseId()))) out.put(ol.poseId(), ol.residualM() / ol.robustSigmaM());
        return out;
    }

    /**
     * {@link #otherFlankExplains(Work, Fit, List, List)} for a validation pose: with the drive's
     * reading moved so that the model puts its output at one end of the play where it put it
     * elsewhere, its error (each residual over its noise) falls under 4 per residual row.
     */
    static boolean otherFlankExplains(Work w, Fit fit, List<Effect> selected, Measurement pose) {
        if (pose == null || pose.isPair()) return false;
        PoseConditions c = PoseConditions.of(pose);
        for (int k = 0; k < selected.size(); k++) {
            Effect e = selected.get(k);
            if (!sidedByGravity(e) || !nearHandOver(e, pose, w.rows)) continue;
            double[] g = new double[1];
            e.regressor(pose, c, g);
            double b = fit.full[fit.problem.effectOffset(k)];
            int rows = w.sixD && w.validate.hasOrientation() ? fit.problem.rowsPerPose() : fit.problem.positionRowsPerPose();
            for (double flank : FLANKS) {
                if (Math.abs(flank - g[0]) < 1e-9) continue;
                double[] q = pose.q();
                q[e.joint()] += (flank - g[0]) * b;
                if (w.heldOut(fit, List.of(pose.withQ(q)), true) < 4 * rows) {
                    LOG.debug("validation pose {} is explained by the other flank of {}: not an outlier", pose.poseId(), e.label());
                    return true;
                }
            }
        }
        return false;
    }

    /** A lost motion's flank terms at the two ends of its play. */
    private static final double[] FLANKS = {0.5, -0.5};

    /** Whether effect {@code e} puts its drive's output on one side of a play by the gravity torque: a backlash held by gravity, a gravity play. */
    private static boolean sidedByGravity(Effect e) {
        return e.heldByGravity() || e.kind() == Effect.Kind.GRAVITY_PLAY;
    }

    /**
     * Whether the gravity torque on {@code e}'s drive at {@code pose} lies where the side of its play
     * is uncertain. For a backlash held by gravity, within half its holding torque of it (or the
     * hand-over's width, if wider). For a gravity play, within the hand-over's half-width of where the
     * side changes, or within the share of the largest torque on the drive over the training poses
     * {@code rows} that the change's place was searched over ({@link #PLAY_SIDE_SHIFTS}): the file's
     * masses put the torque's zero only roughly.
     */
    private static boolean nearHandOver(Effect e, Measurement pose, List<Measurement> rows) {
        if (e.heldByGravity()) {
            double tau = Math.abs(e.holdingTorque(pose.q(), pose.payloadKg()));
            return Math.abs(tau - e.heldAboveNm()) <= Math.max(0.5, e.heldWidth()) * e.heldAboveNm();
        }
        double max = 0;
        for (Measurement r : rows) max = Math.max(max, Math.abs(e.holdingTorque(r.q(), r.payloadKg())));
        double band = Math.max(e.sideWidthNm(), Arrays.stream(PLAY_SIDE_SHIFTS).map(Math::abs).max().orElse(0) * max);
        return Math.abs(e.holdingTorque(pose.q(), pose.payloadKg()) - e.sideNm()) <= band;
    }

    /**
     * The poses among {@code flagged} that a named backlash held by gravity's other flank explains,
     * or a gravity play's other side: at a pose whose gravity torque is near the holding torque
     * (within half of it, or the hand-over's width if wider) or where the play's side changes
     * ({@link #nearHandOver}), with the output at one end of the play where the model put it
     * elsewhere (its flank term ±1/2 in place of g, a change of (±1/2 − g)·b of the drive's output:
     * the hand-over's share, too, is the model's estimate), the pose's residual falls to the noise
     * (weighted sum of squares under 4 per residual row). Which flank a gear sits on where gravity
     * hands it over the model can only estimate (the file's masses are not the arm's, the mesh's
     * friction varies); such a pose is no bad measurement, and is not reported as one. Elsewhere the
     * flank is known and a pose keeps its verdict (a gross reading that happens to lie along the
     * play's move is still one).
     */
    static List<String> otherFlankExplains(Work w, Fit fit, List<Effect> selected, List<String> flagged) {
        List<Integer> lost = new ArrayList<>();
        for (int k = 0; k < selected.size(); k++) if (sidedByGravity(selected.get(k))) lost.add(k);
        if (lost.isEmpty()) return flagged;
        Tester t = w.tester(fit);
        if (t.ends > 1) return flagged;
        Map<String, Integer> index = new java.util.HashMap<>();
        for (int i = 0; i < w.rows.size(); i++) index.put(w.rows.get(i).poseId(), i);
        List<String> out = new ArrayList<>();
        for (String id : flagged) {
            Integer i = index.get(id);
            boolean explained = false;
            for (int k : lost) {
                if (i == null) break;
                Effect e = selected.get(k);
                if (!nearHandOver(e, w.rows.get(i), w.rows)) continue;
                double b = fit.full[fit.problem.effectOffset(k)];
                double[] g = new double[1];
                e.regressor(w.rows.get(i), w.conditions.get(i), g);
                for (double flank : FLANKS) {
                    if (Math.abs(flank - g[0]) < 1e-9) continue;
                    double dq = (flank - g[0]) * b, ss = 0;
                    for (int a = 0; a < t.rpp; a++) {
                        int row = i * t.rpp + a;
                        double r = fit.r[row] + t.endDQ[0][row * t.dof + e.joint()] * dq;
                        ss += r * r;
                    }
                    if (ss < 4 * t.rpp) explained = true;
                }
                if (explained) break;
            }
            if (explained) LOG.debug("pose {} is explained by the other flank of a lost motion: not an outlier", id);
            else out.add(id);
        }
        return out;
    }

    /**
     * The joints approached from the same side at every pose (a one-sided campaign), in words: there a
     * constant lost motion lags alike at every pose and the zero offset takes it, so the campaign
     * cannot tell it; empty when every joint was approached from both sides.
     */
    static java.util.Optional<String> oneSidedNote(List<Measurement> rows, int dof) {
        List<String> joints = new ArrayList<>();
        for (int j = 0; j < dof; j++) if (oneSided(rows, j)) joints.add(Integer.toString(j + 1));
        if (joints.isEmpty()) return java.util.Optional.empty();
        String which = joints.size() == 1 ? "joint " + joints.get(0) : "joints " + String.join(", ", joints.subList(0, joints.size() - 1))
                + " and " + joints.get(joints.size() - 1);
        return java.util.Optional.of(which + (joints.size() == 1 ? " was" : " were") + " approached from the same side at every pose: "
                + "a lost motion there lags alike at every pose and the zero offset takes it whole, so this campaign cannot tell "
                + "whether there is any (backlash is not identifiable there); a lag that builds up over the move can still vary with "
                + "the motion before each pose. To tell either, approach some poses from the other side");
    }

    /** Whether every row has joint j's recorded direction on the same side (not 0). */
    static boolean oneSided(List<Measurement> rows, int j) {
        if (rows.isEmpty()) return false;
        int first = rows.get(0).directions()[j];
        return first != 0 && rows.stream().allMatch(m -> m.directions()[j] == first);
    }

    /**
     * The joints whose recorded direction disagrees with the last move in the file at
     * {@link #MIN_APPROACHED} rows or more and at a tenth of them: there the pose was taken by a
     * move the file does not hold (an approach from a fixed side), so the travel since the drive
     * last turned is not the last move.
     */
    static boolean[] approachedJoints(List<Measurement> rows, Directions.Moves moves, int dof) {
        boolean[] out = new boolean[dof];
        if (moves.isEmpty()) return out;
        for (int j = 0; j < dof; j++) {
            int against = 0;
            for (Measurement m : rows) {
                double x = moves.of(m, j);
                int d = m.directions() == null ? 0 : m.directions()[j];
                if (d != 0 && Double.isFinite(x) && x != 0 && Math.signum(x) != d) against++;
            }
            out[j] = against >= MIN_APPROACHED && against >= 0.1 * rows.size();
        }
        return out;
    }

    /** Rows whose direction disagrees with their last move before a joint counts as approached ({@link #approachedJoints}). */
    static final int MIN_APPROACHED = 5;

    /**
     * The wind-up an approached, one-sided joint is first tested with (rad): a build-up length of 4°
     * and an approach of 1°, in the middle of the grids {@link #bestWindUp} then searches. Only how
     * the lag differs between poses whose travel came from either side is seen there, and at these
     * lengths that difference is most of the full lag.
     */
    static final double APPROACH_BUILD_UP_RAD = Math.toRadians(4), APPROACH_RAD = Math.toRadians(1);

    /**
     * Whether a pose's direction is unknown (0: the first pose of an inferred measuring order) on a
     * joint with backlash: its lost motion may sit on either side, so its residual is no sign of a
     * bad measurement.
     */
    static boolean unknownBacklashSide(List<Effect> selected, Measurement m) {
        int[] dir = m.directions();
        if (dir == null) return false;
        for (Effect e : selected)
            if (e.kind() == Effect.Kind.BACKLASH && dir[e.joint()] == 0) return true;
        return false;
    }

    /**
     * One diagnosis; {@code forcedOutliers} null uses the calibration's rule, else exactly these poses
     * are left out. Families whose {@link #claimKey} is in {@code excluded} are not candidates.
     */
    private static Run run(RobotDescription robot, MeasurementSet trainAll, MeasurementSet validate, Options o,
                           List<String> forcedOutliers, long t0, Directions.Source dirSource, Set<String> excluded) {
        return run(robot, trainAll, validate, o, forcedOutliers, t0, dirSource, excluded, Double.NaN, false);
    }

    /**
     * A run whose 6-D residuals weigh a rotation against a position by {@code rotOverPos} (rad per m: the ratio of
     * the rotation's noise σ to the position's); NaN: by the geometric fit's estimates of the two. Where the geometry
     * leaves an effect that mostly turns the tool (a wrist's play, a coupling of the wrist's drives) or mostly moves
     * it, that fit's two σ are not the noise's; weighted by them, one kind of row carries almost nothing once the
     * effect is modelled, the F tests count it as noise all the same, and a small structure of the other kind looks
     * significant. So when the model selected leaves the two kinds of row in another ratio, the diagnosis is redone
     * once with the residuals weighted by that ratio (feasible generalised least squares; the position σ, the unit
     * of the weighted residual, is kept).
     */
    private static Run run(RobotDescription robot, MeasurementSet trainAll, MeasurementSet validate, Options o,
                           List<String> forcedOutliers, long t0, Directions.Source dirSource, Set<String> excluded, double rotOverPos,
                           boolean screen) {
        KinematicModel model = KinematicModel.build(robot);
        GravityTorques gravity = GravityTorques.of(model, robot);
        o.progress().update("geometric calibration", 0);
        Set<String> forced = forcedOutliers == null ? Set.of() : new HashSet<>(forcedOutliers);
        MeasurementSet train = forced.isEmpty() ? trainAll : trainAll.filter(m -> !forced.contains(m.poseId()));
        Calibrator.Options co = Calibrator.Options.defaults().withCancel(o.cancel());
        if (forcedOutliers != null) co = co.withOutliers(co.outlierK(), false);
        CalibrationResult geo = Calibrator.calibrate(model, train, validate, co);
        int beyondGeo = geo.outliers().size(); // the geometric fit's poses beyond the rule, every pose in
        boolean manyOutliers = forcedOutliers == null && tooManyToBeBad(beyondGeo, train.size());
        // A run of poses one after another in time (the instrument knocked, the target slipping, a zero jumping, near the campaign's
        // end or start, where the geometry cannot follow the change) is a change at one time, not readings gone bad at random.
        List<String> timeRun = forcedOutliers == null && !manyOutliers ? runInTime(geo.outliers(), train.rows()) : List.of();
        if (!timeRun.isEmpty()) geo = Calibrator.calibrate(model, train, validate, co.withOutliers(co.outlierK(), false));
        if (LOG.isDebugEnabled())
            for (CalibrationResult.Outlier ol : geo.outliers())
                LOG.debug("geometric outlier {}: {} robust sigmas", ol.poseId(), ol.residualM() / ol.robustSigmaM());
        Set<String> gross = new HashSet<>();
        if (manyOutliers) {
            // Many poses beyond the rule are a structure the geometry leaves (to locate), not bad measurements; but a few
            // far beyond it are gross readings among them, and kept they bend the geometric fit the structure is sought in.
            for (CalibrationResult.Outlier ol : grossAmong(geo.outliers(), train.size())) gross.add(ol.poseId());
            MeasurementSet kept = gross.isEmpty() ? train : train.filter(m -> !gross.contains(m.poseId()));
            // without the gross readings the rest may be few enough to be bad readings too, not a structure
            if (!gross.isEmpty()) {
                geo = Calibrator.calibrate(model, kept, validate, co);
                manyOutliers = tooManyToBeBad(geo.outliers().size(), kept.size());
            }
            if (manyOutliers) geo = Calibrator.calibrate(model, kept, validate, co.withOutliers(co.outlierK(), false));
        }
        Set<String> outlierIds = new HashSet<>(forced);
        List<String> outliers = new ArrayList<>(forced.isEmpty() ? List.of() : forcedOutliers);
        for (Measurement m : train.rows()) if (gross.contains(m.poseId()) && outlierIds.add(m.poseId())) outliers.add(m.poseId());
        if (forcedOutliers == null && !manyOutliers && timeRun.isEmpty()) // with many, the calibration only reports them: none is left out
            for (CalibrationResult.Outlier ol : geo.outliers())
                if (outlierIds.add(ol.poseId())) outliers.add(ol.poseId());
        List<Measurement> rows = new ArrayList<>();
        for (Measurement m : train.rows()) if (!outlierIds.contains(m.poseId())) rows.add(m);

        Work allValidation = Double.isNaN(rotOverPos) ? new Work(model, gravity, rows, geo, validate, o)
                : new Work(model, gravity, rows, geo, validate, o, Work.positionSigma(geo), Work.positionSigma(geo) * rotOverPos);
        // Validation poses far beyond the outlier rule under the geometric fit already (gross readings: a beam broken and caught
        // again) are set aside from every decision taken on the validation poses; the final model judges them again with the
        // rest, and when it puts exactly these beyond the rule this run is the run without them (prepared), which judged only
        // at the end would be the whole diagnosis once more.
        // (the geometric model's fit to the training poses, which no validation pose changes: the stepwise search starts from it)
        Fit geoFit = allValidation.fit(List.of(), new java.util.IdentityHashMap<>(), allValidation.geoFull, null);
        List<String> screened = screen ? grossValidation(allValidation, geoFit, geo) : List.of();
        Set<String> setAside = new HashSet<>(screened);
        Work w = screened.isEmpty() ? allValidation : new Work(model, gravity, rows, geo,
                validate.filter(m -> !setAside.contains(m.poseId())), o, allValidation.sigmaPos, allValidation.sigmaRot);
        List<String> notes = new ArrayList<>(), recs = new ArrayList<>();
        // Each pose's last move per joint, in the measuring order of the whole file: a lost motion that builds up over the move.
        Directions.Moves moves = geo.pairs() ? Directions.Moves.NONE : Directions.moves(trainAll, validate);

        // The candidate family, from what the data can support.
        boolean hasTemp = allFinite(rows, Measurement::tempC), hasTime = allFinite(rows, Measurement::timeS);
        boolean hasDirs = rows.stream().allMatch(m -> m.directions() != null);
        boolean hasPayload = allFinite(rows, Measurement::payloadKg);
        double t0C = hasTemp ? rows.stream().mapToDouble(Measurement::tempC).average().orElse(0) : Double.NaN;
        List<Effect> family = new ArrayList<>();
        // when the robot worked and when it rested, from the whole file's reading times in time order
        List<Measurement> history = new ArrayList<>(trainAll.rows());
        if (validate != null) history.addAll(validate.rows());
        w.pauses = hasTime ? Pauses.of(history) : null;
        w.moves = moves;
        w.speeds = topSpeeds(robot);
        for (Effect e : Effect.candidates(model, gravity, t0C, hasTime && !hasTemp ? o.timeTaus() : null, w.pauses))
            if (e.testableOn(rows) && !excluded.contains(claimKey(e))) family.add(e);
        family.addAll(instrumentForms(geo, history, hasTime, hasTemp));
        // A joint taken by an approach move from one side at every pose: a constant lost motion lags alike everywhere
        // (the zero takes it), but a wind-up still differs with the travel before the approach.
        boolean[] approached = hasDirs && dirSource == Directions.Source.RECORDED ? approachedJoints(rows, moves, model.dof())
                : new boolean[model.dof()];
        for (int j = 0; j < model.dof(); j++)
            if (approached[j] && oneSided(rows, j) && !excluded.contains(claimKey(Effect.backlash(j))))
                family.add(Effect.windUp(j, APPROACH_BUILD_UP_RAD, APPROACH_RAD, moves));
        if (!timeRun.isEmpty())
            notes.add(String.format(Locale.ROOT, "poses %s lie beyond 5 robust sigmas of the geometric fit and were measured one after "
                    + "another (no other training pose between them in time): bad readings at random would be so with a chance of "
                    + "%.1g, so none was left out (a change at one time, located below)", String.join(", ", timeRun),
                    runChance(timeRun.size(), train.size())));
        if (manyOutliers)
            notes.add(String.format(Locale.ROOT, "%d poses lie beyond 5 robust sigmas of the geometric fit, more than %s: too many "
                    + "to be bad measurements, so ", beyondGeo, 0.05 * train.size() > MAX_GROSS ? "5 % of them" : "the "
                    + MAX_GROSS + " bad readings a campaign this small may hold") + (gross.isEmpty() ? "none was left out" : "only the " + gross.size() + " beyond "
                    + String.format(Locale.ROOT, "%.0f", GROSS_SIGMAS) + " robust sigmas were left out as gross readings")
                    + " (the structure they show is located below)");
        if (gravity.massesUnknown())
            notes.add(Effect.complianceRemassed(0, gravity).testableOn(rows)
                    ? "the robot file has no mass model: joint compliance (deflection under gravity) was tested through the "
                    + "payload's torque, with the masses of the arm unknown (estimated with it)"
                    : "the robot file has no mass model and the payload does not vary, so joint compliance (deflection under "
                    + "gravity) was not tested: the arm's own weight alone cannot tell a compliance from unknown masses; measure "
                    + "with two or three payloads, or add a mass_model to the robot file");
        if (geo.pairs())
            notes.add(org.robopro.calibration.report.CalibrationReport.distanceWords(geo) + ". For the diagnosis this means: "
                    + "each pair shows an effect only through the change of the length between the point's two places, so a "
                    + "displacement the same at both poses (a drift of the point, an error of joint 1 alone) is not seen at all; an "
                    + "effect the geometry can absorb is reported as not identifiable. The effects are tested at both poses of "
                    + "every pair, each with its own joints and directions, and so is the locate scan's search for structure "
                    + "outside the named families; the evidence plots put each length at the pose of its pair that carries more "
                    + "of the change. Measure positions (x, y, z) to see the direction of an error");
        else if (geo.distance())
            notes.add(org.robopro.calibration.report.CalibrationReport.distanceWords(geo) + ". For the diagnosis this means: "
                    + "each pose shows an effect only through the change of its length to the anchor, so a displacement across the "
                    + "line to the anchor is not seen at that pose; an effect whose length changes the geometry and the anchor can "
                    + "absorb is reported as not identifiable; a drift of the anchor or the instrument cannot be told from the same "
                    + "drift of the measured point the other way; and where an error lives is told by the lengths alone. Measure "
                    + "positions (x, y, z) to see the direction of an error");
        if (!hasDirs) notes.add("no dir1..dir" + model.dof() + " columns: backlash was not tested");
        else if (dirSource.inferred())
            notes.add("no dir1..dir" + model.dof() + " columns: approach directions " + dirSource.words
                    + ", the sign of each joint's last move before the pose was measured; backlash was tested with them");
        if (hasDirs) oneSidedNote(rows, model.dof()).ifPresent(notes::add);
        if (!hasTemp && !hasTime) notes.add("no temp_c or time_s column: thermal expansion was not tested directly");
        else if (!hasTemp) notes.add("no temp_c column: thermal expansion tested with time_s as a warm-up proxy");
        if (!gravity.massesUnknown() && !hasPayload)
            notes.add("no payload_kg column: compliance tested with the arm's own weight only (payload taken as 0 kg)");

        // Stepwise selection: forward by BIC among the candidates that pass, backward when one stops being needed.
        List<Effect> selected = new ArrayList<>();
        Map<Effect, boolean[]> absorbedCols = new java.util.IdentityHashMap<>();
        List<Step> steps = new ArrayList<>();
        Fit fit = geoFit;
        double geoTrain = fit.trainRms, geoVal = w.validateRms(fit);
        // Locate: where does what the geometry leaves live? Structures found bring the families that can fit them.
        Timer timer = new Timer();
        timer.mark("geometric");
        Tester geoTester = w.tester(fit);
        timer.mark("tester");
        List<Locator.Probe> geoProbes = Locator.probes(geoTester, dirSource);
        timer.mark("probes");
        List<StageScan.Stage> stages = StageScan.scan(geoTester, o.alpha());
        geoProbes.addAll(StageScan.probes(geoTester, stages, Locator.harmonicsFor(rows.size())));
        timer.mark("stage scan");
        List<Locator.Found> foundGeo = Locator.scan(geoTester, geoProbes, o.alpha(), MAX_LOCATED);
        timer.mark("scan");
        for (Effect e : fromLocated(foundGeo, model, rows, gravity, t0C, hasTemp, hasTime))
            if (e.isFallback() || !excluded.contains(claimKey(e))) family.add(e);
        // Thermal growth with the links lagging the reading: the time constant (one for every link) that predicts
        // left-out poses best, from the whole file's temperature history in time order; a candidate beside the unlagged form.
        ThermalLag lag = hasTemp && hasTime ? ThermalLag.of(history) : null;
        if (lag != null && !excluded.contains(claimKey(Effect.thermalLinks(model, t0C)))) {
            Effect lagged = commonLag(geoTester, model, t0C, lag, w.conditions);
            if (lagged != null) family.add(lagged);
            // and with the links also warmed by the drives as the robot works (the time constant that predicts best)
            Effect warmed = commonWarmUp(geoTester, lagged != null ? lagged : Effect.thermalLinks(model, t0C), w.conditions);
            if (warmed != null) family.add(warmed);
        }
        Map<String, Effect> rivals = new LinkedHashMap<>();
        for (Effect e : locatedFallbacks(foundGeo, rows, model)) rivals.putIfAbsent(e.label(), e);
        timer.mark("locate");
        int hMax = Locator.harmonicsFor(rows.size());
        Map<String, Diagnosis.NotIdentifiable> notIdent = new LinkedHashMap<>();
        Map<String, Candidate> implausible = new LinkedHashMap<>();
        List<Effect> remaining = new ArrayList<>(family);
        List<String> aliasNotes = new ArrayList<>();
        Tester scanned = null;
        Fit scannedFit = null;
        int aliasRounds = 0;
        int familySize = -1;
        for (int step = 0; step < 2 * o.maxEffects() + 2 && !remaining.isEmpty(); step++) {
            o.cancel().check();
            o.progress().update("testing effects", Math.min(0.9, 0.2 + 0.7 * step / (o.maxEffects() + 1.0)));
            Tester t = scanned != null && scannedFit == fit ? scanned : w.tester(fit);
            if (step > 0 && scannedFit != fit) {
                // Locate again after each accepted effect: what is left may call for other families or harmonics.
                // (the steps of a reading and of the target are looked for in the geometric fit's and the final residuals only;
                // the stage lines again, as a large effect's residual raised the spectrum's continuum over a weak line)
                List<Locator.Probe> again = Locator.probes(t, dirSource, false);
                again.addAll(StageScan.probes(t, StageScan.scan(t, o.alpha()), hMax));
                List<Locator.Found> more = Locator.scan(t, again, o.alpha(), MAX_LOCATED);
                for (Effect e : locatedFallbacks(more, rows, model)) rivals.putIfAbsent(e.label(), e);
                for (Effect e : fromLocated(more, model, rows, null, t0C, false, false)) {
                    Effect merged = e;
                    if (e.kind() == Effect.Kind.PERIODIC && !e.shaftOrders())
                        for (Effect sel : selected)
                            if (sel.kind() == Effect.Kind.PERIODIC && !sel.shaftOrders() && sel.joint() == e.joint()) {
                                java.util.TreeSet<Integer> hs = new java.util.TreeSet<>();
                                for (int h : sel.harmonics()) hs.add(h);
                                for (int h : e.harmonics()) hs.add(h);
                                merged = Effect.periodic(e.joint(), hs.stream().mapToInt(Integer::intValue).toArray(),
                                        java.util.stream.DoubleStream.concat(Arrays.stream(sel.stages()), Arrays.stream(e.stages())).toArray());
                            }
                    String label = merged.label();
                    if (family.stream().noneMatch(f -> f.label().equals(label)) && (merged.isFallback() || !excluded.contains(claimKey(merged)))) {
                        family.add(merged);
                        remaining.add(merged);
                    }
                }
                scanned = t;
                scannedFit = fit;
            }
            // a pull's anchor placed again, and a load tilt's masses estimated again, on what the effects chosen so far leave
            // (placed on the geometric fit's residual, they bent toward what those hold)
            if (step > 0)
                for (int i = 0; i < remaining.size(); i++) {
                    Effect e = remaining.get(i);
                    Effect moved;
                    if (e.kind() == Effect.Kind.TOOL_PULL && e.pullAnchor() != null) moved = Locator.bestPull(t, e.pullAttach(), e.pullAnchor());
                    else if (e.kind() == Effect.Kind.LOAD_TILT) moved = Locator.remassedLoadTilt(t, e.withFileMasses());
                    else continue;
                    remaining.set(i, moved);
                    family.replaceAll(f -> f == e ? moved : f);
                }
            List<Candidate> cs = new ArrayList<>();
            for (Effect e : remaining) {
                Candidate c = t.test(e, w.conditions);
                if (c.keptColumns == 0) {
                    notIdent.putIfAbsent(e.label(), new Diagnosis.NotIdentifiable(e.json(), e.joints1(), e.label(),
                            c.ratio, c.ratio == 0 ? "its regressor is zero on these poses"
                            : "the geometric model absorbs its signature on these poses"));
                } else cs.add(c);
            }
            if (familySize < 0) familySize = cs.size();
            double threshold = o.alpha() / Math.max(1, familySize - selected.size());
            if (LOG.isDebugEnabled()) debug(step, cs);
            Candidate best = null;
            for (boolean again = true; again; ) {
                again = false;
                best = null;
                for (Candidate c : cs) {
                    c.threshold = threshold;
                    if (!(c.p < threshold) || !(c.pressAfter < c.pressBefore)) continue;
                    if (inPlaceOnly(c.effect) || secondForm(c.effect, selected, null)) continue;
                    if (!c.plausible) { implausible.put(c.effect.label(), c); continue; }
                    if (best == null || lowerBic(c.bic, best.bic)) best = c;
                }
                // a settling is taken only where its size follows the move's speed beside a lost motion of the joint: a play's
                // sign is the move's too, and the settling would take it before the family is tried
                if (best != null && best.effect.kind() == Effect.Kind.SETTLING && !followsSpeed(w, fit, selected, absorbedCols, best.effect)) {
                    LOG.debug("{}: nothing beside a lost motion of its joint follows the move's speed", best.effect.label());
                    Effect gone = best.effect;
                    remaining.remove(gone);
                    cs.removeIf(c -> c.effect == gone);
                    again = true;
                }
            }
            if (best == null || selected.size() >= o.maxEffects()) break;
            implausible.clear(); // only those still significant when selection stops are reported
            Effect chosen = best.effect;
            // One form per effect: a second thermal strain, or the same joint's compliance with other masses, is not a second effect.
            remaining.removeIf(e -> e == chosen || (chosen.kind() == Effect.Kind.THERMAL && e.kind() == Effect.Kind.THERMAL)
                    || (chosen.kind() == Effect.Kind.THERMAL_LINK && e.kind() == Effect.Kind.THERMAL_LINK)
                    || (chosen.kind() == Effect.Kind.COMPLIANCE && e.kind() == Effect.Kind.COMPLIANCE && e.joint() == chosen.joint()));
            notIdent.remove(chosen.label());
            int older = -1; // a periodic effect of the same joint whose harmonics the chosen one holds: one effect, not two
            for (int k = 0; k < selected.size(); k++)
                if (chosen.kind() == Effect.Kind.PERIODIC && selected.get(k).kind() == Effect.Kind.PERIODIC
                        && selected.get(k).joint() == chosen.joint() && chosen.shaftOrders() == selected.get(k).shaftOrders()
                        && Arrays.stream(selected.get(k).orders()).allMatch(h -> Arrays.stream(chosen.orders()).anyMatch(x -> x == h)))
                    older = k;
            if (older >= 0) {
                double thr = best.threshold;
                fit = replaceEffect(w, fit, selected, absorbedCols, steps, older, chosen, false);
                if (!selected.contains(chosen)) continue;
                steps.get(steps.size() - 1).candidate.threshold = thr;
            } else {
                selected.add(chosen);
                absorbedCols.put(chosen, best.absorbedMask);
                fit = w.fit(selected, absorbedCols, fit.full, best);
                steps.add(new Step(best, fit.trainRms, w.validateRms(fit)));
            }
            // Backward: an effect made redundant by the new one (aliases), or implausible in the joint fit, leaves.
            if (selected.size() >= 2) {
                int drop = w.weakest(fit, selected, threshold);
                if (drop >= 0) {
                    LOG.debug("backward: dropped {}", selected.get(drop).label());
                    fit = dropAndRefit(w, fit, selected, absorbedCols, steps, drop);
                    restampLast(w, fit, steps);
                }
            }
        }
        timer.mark("stepwise");
        // Held-out rule: a named effect must beat its aliases on the leave-one-pose-out error; when the
        // smooth fallback or another family predicts better, the effect is replaced.
        Set<String> refusedAliases = new HashSet<>();
        Map<String, String> orderNotes = new java.util.HashMap<>(); // a play's form whose pinion order the left-out poses do not fix: why
        for (int k = 0; k < selected.size(); k++) {
            Effect e = selected.get(k);
            Tester at = w.tester(fit);
            double own = at.pressFull();
            Effect best = null;
            double bestPress = own;
            // A selected smooth fallback holds every simpler shape of its joint's angle: a family of that angle that
            // predicts left-out poses as well (within the margin) takes its place, to be judged against the fallback
            // in the claim check (which also asks whether the fallback finds structure the family leaves).
            boolean smooth = e.kind() == Effect.Kind.SMOOTH;
            if (e.kind() == Effect.Kind.BACKLASH && !moves.isEmpty()) {
                // The other form of the same lost motion: constant, or building up over the move (the build-up
                // length that predicts left-out poses best). It takes the place only when clearly better.
                // An approached wind-up is the same form with its two lengths still to choose: the best of them takes
                // its place when it predicts better at all.
                boolean refine = e.approached();
                Effect form = e.buildsUp() && !refine ? Effect.backlash(e.joint()) : null;
                double formPress = form == null ? Double.POSITIVE_INFINITY : at.pressReplacing(k, form, w.conditions);
                if (!e.buildsUp() || refine) {
                    Effect.Term wu = bestWindUp(at, k, e.joint(), moves, w.conditions, approached[e.joint()]);
                    if (wu != null) { form = wu.effect(); formPress = wu.values()[0]; }
                }
                if (form != null && !refusedAliases.contains(form.label()) && formPress < own * (refine ? 1 : 1 - ALIAS_MARGIN)) {
                    best = form;
                    bestPress = formPress;
                }
            }
            if (e.kind() == Effect.Kind.BACKLASH && !e.heldByGravity() && (!e.runout() || onceOnly(e))) {
                // The same lost motion (in the form just chosen) with a play that changes over the turn of its joint: once
                // per turn (the output gear), or at the order the lag's spectrum shows (a pinion of the last stage). The
                // pinion's line is looked for again beside the output gear's runout once that is in the model: the larger
                // once-per-turn change, not yet modelled, can hide it.
                Effect form = best != null ? best : e;
                List<Effect> forms = new ArrayList<>(List.of(Effect.withRunout(form)));
                StageScan.PlayLine line = StageScan.playOrder(at, e, o.alpha());
                if (line != null) {
                    // the order the left-out poses choose within the line's main lobe (a pinion's ratio is seldom whole): over
                    // part of a turn the spectrum places a line only to about one cycle over the sampled range, 1/span cycles
                    // per turn (the grid step times the oversampling), and a once-per-turn change fitted beside it, or a pinion
                    // turning slower than the scan's least order (3.3 times per output turn), moves its peak within that. A grid
                    // of half steps over the lobe, then a golden section about the best point; no lower than twice per turn,
                    // where a change over part of a turn is the output gear's once-per-turn shape. Alone, and beside the output
                    // gear's runout (once per turn), each form judged against the better before it.
                    double f0 = line.stage().refined(), lobe = StageScan.OVERSAMPLE * line.step();
                    double lo = Math.max(MIN_PINION_ORDER, f0 - lobe), hi = f0 + lobe;
                    int kk = k;
                    for (boolean once : new boolean[] {false, true}) {
                        java.util.function.DoubleFunction<Effect> withOrder = f -> once ? Effect.withRunout(form, 1, f) : Effect.withRunout(form, f);
                        java.util.function.DoubleUnaryOperator press = f -> at.pressReplacing(kk, withOrder.apply(f), w.conditions);
                        double f = line.stage().order(), pf = press.applyAsDouble(f);
                        List<double[]> grid = new ArrayList<>();
                        for (double g = lo; g <= hi + 1e-9; g += line.step() / 2) {
                            double pg = press.applyAsDouble(g);
                            grid.add(new double[] {g, pg});
                            if (pg < pf) { f = g; pf = pg; }
                        }
                        double a = Math.max(MIN_PINION_ORDER, f - line.step() / 2), b = f + line.step() / 2;
                        if (b > a) {
                            double[] r = goldenLog(l -> press.applyAsDouble(Math.exp(l)), a, b);
                            if (r[1] < pf) { f = Math.exp(r[0]); pf = r[1]; }
                        }
                        Effect chosen = withOrder.apply(f);
                        forms.add(chosen);
                        // the orders that predict as well: spread over the whole lobe, the poses do not fix the pinion's ratio
                        double fLo = f, fHi = f;
                        for (double[] gp : grid)
                            if (gp[1] <= pf * (1 + ALIAS_MARGIN)) { fLo = Math.min(fLo, gp[0]); fHi = Math.max(fHi, gp[0]); }
                        if (fHi - fLo >= lobe)
                            orderNotes.put(chosen.label(), String.format(Locale.ROOT, "the order at which joint %d's play changes "
                                    + "(%s times per turn in %s) is not fixed by these poses: every order from %.1f to %.1f times per "
                                    + "turn predicts left-out poses within %.0f %% as well, though over the %.0f deg of joint %d "
                                    + "measured they differ by a cycle or more%s. To tell the pinion's ratio, count the last gear "
                                    + "pair's teeth (z_gear / z_pinion) or measure over more of joint %d's range", e.joint() + 1,
                                    Effect.orderText(f), chosen.label(), fLo, fHi, 100 * ALIAS_MARGIN,
                                    Math.toDegrees(2 * Math.PI / lobe), e.joint() + 1,
                                    once ? " (the once-per-turn change fitted beside them takes up the difference)" : "", e.joint() + 1));
                    }
                }
                if (LOG.isDebugEnabled()) LOG.debug("play of {}: line {}", e.label(), line == null ? "none" : line.stage());
                for (Effect ro : forms) {
                    double pr = at.pressReplacing(k, ro, w.conditions);
                    LOG.debug("alias: {} PRESS {} against {} (best {})", ro.label(), pr, own, bestPress);
                    if (!refusedAliases.contains(ro.label()) && pr < bestPress * (1 - ALIAS_MARGIN)) {
                        best = ro;
                        bestPress = pr;
                    }
                }
            }
            if (e.kind() == Effect.Kind.THERMAL_LINK && lag != null) {
                // The lags of the growth, re-chosen with the rest in place: one for every link, then each link its own
                // where that predicts left-out poses better.
                LagSearch form = bestLags(at, k, e, model, t0C, lag, w.conditions);
                if (form != null && !refusedAliases.contains(form.effect().label()) && form.press() < own * (1 - ALIAS_MARGIN)) {
                    best = form.effect();
                    bestPress = form.press();
                }
            }
            for (Effect a : aliases(e, family, selected)) {
                if (refusedAliases.contains(a.label())) continue;
                if (smooth && (a.isFallback() || !checkedAgainstFallbacks(a) || a.target() != Effect.Target.DRIVE)) continue;
                double pa = at.pressReplacing(k, a, w.conditions);
                if (smooth ? pa <= bestPress * (1 + ALIAS_MARGIN) && (best == null || pa < bestPress)
                        : pa < bestPress * (1 - ALIAS_MARGIN) && !richerWithoutCause(at, e, a, w)) { bestPress = pa; best = a; }
            }
            if (best == null) continue;
            LOG.debug("alias: {} replaced by {} (PRESS {} -> {})", e.label(), best.label(), own, bestPress);
            fit = replaceEffect(w, fit, selected, absorbedCols, steps, k, best, false);
            if (smooth && selected.contains(best)) {
                // The linearised estimate must hold once the family is re-identified with the rest; else the fallback stays.
                double refitted = w.tester(fit).pressFull();
                if (refitted > own * (1 + ALIAS_MARGIN)) {
                    LOG.debug("alias: {} back in place of {} (PRESS refitted {} against {})", e.label(), best.label(), refitted, own);
                    refusedAliases.add(best.label());
                    fit = replaceEffect(w, fit, selected, absorbedCols, steps, selected.indexOf(best), e, false);
                } else
                    aliasNotes.add(String.format(Locale.ROOT, "%s was replaced by %s, the physical form of the same joint "
                            + "angle's error, which predicts left-out poses as well (leave-one-pose-out error %.1f against %.1f)",
                            e.label(), best.label(), refitted, own));
            } else if (selected.contains(best)) {
                aliasNotes.add(String.format(Locale.ROOT, "%s was replaced by %s, which predicts left-out poses better "
                        + "(leave-one-pose-out error %.1f against %.1f)", e.label(), best.label(), bestPress, own));
                // what other effects held of a play changing over the turn before it had that form is now its own
                if (orderNotes.containsKey(best.label())) aliasNotes.add(orderNotes.get(best.label()));
                if (best.runout()) fit = noLongerNeeded(w, fit, selected, absorbedCols, steps, familySize, best, aliasNotes);
            } else {
                refusedAliases.add(best.label());
                aliasNotes.add(String.format(Locale.ROOT, "%s predicts left-out poses better than %s (leave-one-pose-out "
                        + "error %.1f against %.1f), but its estimate leaves the physical bounds once fitted with the rest, "
                        + "so %s stays", best.label(), e.label(), bestPress, own, e.label()));
            }
            k = -1; // re-check from the start with the new set
            if (++aliasRounds > 4) break;
        }
        // Where the smooth fallback was needed on a joint, the angle-dependent error there is not one
        // family's: another family's claim on the same drive's angle is withdrawn (the fallback models it).
        for (int k = selected.size() - 1; k >= 0; k--) {
            Effect e = selected.get(k);
            boolean angleFamily = e.target() == Effect.Target.DRIVE && e.kind() != Effect.Kind.BACKLASH && e.kind() != Effect.Kind.SMOOTH
                    && e.kind() != Effect.Kind.ANGLE_STEP;
            // a smooth curve of the drive's own angle takes any family of the drive; one following another joint, that joint's coupling
            // and a wobble of the joint's axis at orders of its angle takes a gear's error of the same angle
            if (!angleFamily || selected.stream().noneMatch(x -> ((x.kind() == Effect.Kind.SMOOTH || x.kind() == Effect.Kind.ANGLE_STEP)
                    && (x.angleJoint() == x.joint() || e.kind() == Effect.Kind.COUPLING && e.source() == x.angleJoint())
                    || x.kind() == Effect.Kind.AXIS_WOBBLE && e.kind() == Effect.Kind.PERIODIC) && x.joint() == e.joint()))
                continue;
            aliasNotes.add(e.label() + " is not claimed: the angle-dependent error of joint " + (e.joint() + 1)
                    + " needed a fallback of its angle (a smooth curve, a step, or a wobble of its axis) as well, so it is not that family's alone");
            fit = dropAndRefit(w, fit, selected, absorbedCols, steps, k);
        }
        fit = pairNeeded(w, fit, selected, absorbedCols, steps, aliasNotes);
        fit = heldByGravity(w, fit, selected, absorbedCols, steps, gravity, rows, aliasNotes, recs);
        List<Effect> beforeGravity = selected.stream().filter(e -> !e.isFallback()).toList();
        fit = gravityAliases(w, fit, selected, absorbedCols, steps, model, rows, aliasNotes);
        // a transmission error the gravity alias withdrew: what it held may be another shape of its drive's (a zero that moves)
        List<Effect> gravityGone = beforeGravity.stream().filter(e -> !selected.contains(e)).toList();
        fit = jointContest(w, fit, selected, absorbedCols, steps, rivals.values(), aliasNotes);
        for (Effect e : family) if (e.isFallback()) rivals.putIfAbsent(e.label(), e);
        List<Effect> claimed = new ArrayList<>(selected.stream().filter(e -> !e.isFallback()).toList());
        claimed.addAll(gravityGone);
        fit = claimCheck(w, fit, selected, absorbedCols, steps, new ArrayList<>(rivals.values()), family, rows, gravity, aliasNotes);
        // (a two-joint fallback the claim check put in a withdrawn family's place)
        fit = pairNeeded(w, fit, selected, absorbedCols, steps, aliasNotes);
        fit = playOrSettling(w, fit, selected, absorbedCols, steps, aliasNotes);
        // What the withdrawn families held and the one fallback in each one's place does not: their own fallbacks and the
        // located structures' of the same variables, added while they hold on held-out data.
        // (a family a two-joint fallback so added holds leaves in turn, and its own fallbacks are tried for it)
        for (int again = 0; again < 2 && claimed.stream().anyMatch(e -> !selected.contains(e)); again++) {
            List<Effect> gone = claimed.stream().filter(e -> !selected.contains(e)).toList();
            Map<String, Effect> leftFor = new LinkedHashMap<>();
            for (Effect e : gone) for (Effect f : ownFallbacks(e, rows, model)) leftFor.putIfAbsent(f.label(), f);
            for (Effect f : rivals.values()) if (gone.stream().anyMatch(e -> sameVariable(e, f))) leftFor.putIfAbsent(f.label(), f);
            int before = selected.size();
            fit = fallbacksForWhatIsLeft(w, fit, selected, absorbedCols, steps, leftFor.values(), aliasNotes, true);
            if (selected.size() == before) break;
            // the families still named are judged again beside what was added
            int families = (int) selected.stream().filter(e -> !e.isFallback()).count();
            fit = claimCheck(w, fit, selected, absorbedCols, steps, new ArrayList<>(rivals.values()), family, rows, gravity, aliasNotes);
            fit = pairNeeded(w, fit, selected, absorbedCols, steps, aliasNotes);
            if (selected.stream().filter(e -> !e.isFallback()).count() == families) break;
        }
        for (Effect e : gravityGone) {
            // what to measure to tell a deflection under the arm's weight from a gear's error; not asked where a zero that moves
            // with time or temperature holds what the gear's error was taken for and no shape of the angle is left
            int j = e.joint();
            boolean zero = selected.stream().anyMatch(x -> x.joint() == j && (x.kind() == Effect.Kind.ZERO_DRIFT || x.kind() == Effect.Kind.ZERO_STEP));
            boolean angle = selected.stream().anyMatch(x -> x.joint() == j && x.target() == Effect.Target.DRIVE
                    && x.kind() != Effect.Kind.ZERO_DRIFT && x.kind() != Effect.Kind.ZERO_STEP && x.kind() != Effect.Kind.BACKLASH);
            if (!zero || angle)
                recs.add(String.format(Locale.ROOT, "Joint %d's error follows its angle the way a deflection under the arm's weight "
                        + "would: measure the same poses with two or three payloads (record payload_kg) to tell a compliance from a "
                        + "transmission error, or give the robot file a mass_model.", j + 1));
        }
        if (selected.stream().anyMatch(e -> e.kind() == Effect.Kind.ANGLE_STEP && !e.isWindow())) {
            // a step of a joint's reading that took a withdrawn family's place may be a play held by gravity, as above
            List<String> before = selected.stream().map(Effect::label).toList();
            fit = heldByGravity(w, fit, selected, absorbedCols, steps, gravity, rows, aliasNotes, recs);
            if (!selected.stream().map(Effect::label).toList().equals(before))
                fit = claimCheck(w, fit, selected, absorbedCols, steps, new ArrayList<>(rivals.values()), family, rows, gravity, aliasNotes);
        }
        if (selected.isEmpty() && !foundGeo.isEmpty()) {
            // nothing named, nor put in a withdrawn family's place, though the geometric fit left structure: the located
            // structures' own fallbacks, one at a time while each holds on held-out data
            fit = fallbacksForWhatIsLeft(w, fit, selected, absorbedCols, steps, rivals.values(), aliasNotes, false);
        }
        fit = stillSignificant(w, fit, selected, absorbedCols, steps, familySize, aliasNotes);
        fit = instrumentAxesHeld(w, fit, selected, absorbedCols, steps, aliasNotes);
        // With validation data, an effect is kept only when the final model predicts the validation poses better with
        // it than refitted without it (position and orientation, each over its noise).
        for (int k = selected.size() - 1; k >= 0 && w.hasValidation(); k--) {
            Fit without = w.refitWithout(fit, selected, absorbedCols, k);
            double with = w.validateError(fit), wo = w.validateError(without);
            if (with < wo) continue;
            Effect gone = selected.get(k);
            LOG.debug("validation: dropped {} ({} with, {} without)", gone.label(), with, wo);
            drop(selected, absorbedCols, steps, k);
            aliasNotes.add(gone.label() + " was significant on the training poses but did not lower the validation error, "
                    + (gone.isFallback() ? "so it is not used (the structure stays reported as located)" : "so it is not claimed"));
            fit = without;
            restampLast(w, fit, steps);
        }
        // With validation data, a lost motion that builds up over the move is claimed only when it predicts the
        // validation poses better than the constant lost motion of the same joint in its place.
        // Whether the swap took is read from the list itself (the constant play is in it), not from its last entry:
        // when the constant play is not identifiable or not plausible, the wind-up stays as it was.
        for (int k = 0; k < selected.size() && w.hasValidation(); k++) {
            Effect e = selected.get(k);
            if (!e.buildsUp()) continue;
            double with = w.validateError(fit);
            Selection saved = Selection.of(selected, absorbedCols, steps);
            Effect constant = Effect.backlash(e.joint());
            Fit plain = replaceEffect(w, fit, selected, absorbedCols, steps, k, constant, false);
            int at = selected.indexOf(constant);
            if (at < 0) {
                saved.restore(selected, absorbedCols, steps);
                aliasNotes.add(String.format(Locale.ROOT, "%s could not be compared with a constant lost motion of joint %d on the "
                        + "validation poses (in its place a constant lost motion is not identifiable or not plausible), so it stays",
                        e.label(), e.joint() + 1));
                continue;
            }
            double wo = w.validateError(plain);
            if (!(with < wo)) {
                aliasNotes.add(String.format(Locale.ROOT, "%s predicted the left-out training poses better than a constant lost "
                        + "motion but not the validation poses (weighted error %.1f against %.1f), so the lost motion is taken as "
                        + "constant", e.label(), with, wo));
                fit = plain;
                k--; // the effect after it now stands at k
                continue;
            }
            fit = replaceEffect(w, plain, selected, absorbedCols, steps, at, e, false);
            aliasNotes.add(String.format(Locale.ROOT, "%s predicts the validation poses better than a constant lost motion of "
                    + "joint %d (weighted error %.1f against %.1f)", e.label(), e.joint() + 1, w.validateError(fit), wo));
            break;
        }
        // With validation data, a growth whose links lag the temperature reading keeps its lags only when it predicts
        // the validation poses better than the links at the reading's temperature in its place; likewise the drives' warm-up.
        fit = validatedForm(w, fit, selected, absorbedCols, steps, e -> e.kind() == Effect.Kind.THERMAL_LINK && e.lags(), Effect::withoutLags,
                (e, v) -> String.format(Locale.ROOT, "%s predicted the left-out training poses better than the links at the "
                        + "reading's temperature but not the validation poses (weighted error %.1f against %.1f), so no lag is "
                        + "taken", e.label(), v[0], v[1]), null, aliasNotes);
        fit = validatedForm(w, fit, selected, absorbedCols, steps, Effect::warms, Effect::withoutWarmUp,
                (e, v) -> String.format(Locale.ROOT, "%s predicted the left-out training poses better than the links at the "
                        + "air's temperature alone but not the validation poses (weighted error %.1f against %.1f), so no warm-up by "
                        + "the drives is taken", e.label(), v[0], v[1]),
                (e, v) -> String.format(Locale.ROOT, "%s: the links also grow as the drives warm them while the robot works (time "
                        + "constant %s), beside the air's temperature; the validation poses confirm it (weighted error %.1f against %.1f "
                        + "without). Compensation takes the robot warmed through", e.label(), e.warmWords(), v[0], v[1]), aliasNotes);
        // With validation data, a play that changes over the turn is claimed only when it predicts the validation poses better
        // than the same lost motion with a constant play.
        fit = validatedForm(w, fit, selected, absorbedCols, steps, Effect::runout, Effect::withoutRunout,
                (e, v) -> String.format(Locale.ROOT, "%s predicted the left-out training poses better than a constant play but not "
                        + "the validation poses (weighted error %.1f against %.1f), so the play is taken as constant", e.label(), v[0], v[1]),
                (e, v) -> String.format(Locale.ROOT, "%s predicts the validation poses better than the same lost motion with a "
                        + "constant play (weighted error %.1f against %.1f)", e.label(), v[0], v[1]), aliasNotes);
        // With validation data, a stiffening spring is claimed only when it predicts the validation poses better than a linear one.
        fit = validatedForm(w, fit, selected, absorbedCols, steps, Effect::stiffens, Effect::withoutStiffening,
                (e, v) -> String.format(Locale.ROOT, "%s predicted the left-out training poses better than a linear spring but not "
                        + "the validation poses (weighted error %.1f against %.1f), so the spring is taken as linear", e.label(), v[0], v[1]),
                null, aliasNotes);
        if (lag != null)
            for (int k = 0; k < selected.size(); k++)
                if (selected.get(k).kind() == Effect.Kind.THERMAL_LINK) {
                    String words = lagWords(w.tester(fit), k, selected.get(k), model, t0C, lag, w.conditions);
                    if (words != null) notes.add(words);
                }
        // A gear's error of a few harmonics named on a joint sampled over less than a turn: say why the data tell it.
        for (int k = 0; k < selected.size(); k++) {
            Effect e = selected.get(k);
            if (!periodicityUntested(e, rows)) continue;
            int turns = turningPoints(e, fit.effectValues(k), rows);
            if (turns >= REPEAT_TURNS)
                notes.add(String.format(Locale.ROOT, "%s is named though joint %d was sampled over %.0f deg, less than a turn: its error "
                        + "turns %d times within that range (maxima and minima), and a torque that follows the angle without repeating "
                        + "(the arm's weight, a balancer's spring, a cable's pull) turns it at most twice; sampling the joint over a whole turn would "
                        + "show the error repeat", e.label(), e.joint() + 1, Math.toDegrees(spans(rows)[e.joint()]), turns));
        }
        timer.mark("aliases");
        if (w.sixD && Double.isNaN(rotOverPos) && !selected.isEmpty()) {
            double[] sd = w.rowSigmas(fit);
            double used = w.sigmaRot / w.sigmaPos, left = sd[1] / sd[0];
            if (left > used * REWEIGHT || left < used / REWEIGHT) {
                LOG.debug("reweight: the model leaves rotation against position σ {} rad/m, weighted with {}: diagnosis redone", left, used);
                return run(robot, trainAll, validate, o, forcedOutliers, t0, dirSource, excluded, left, screen);
            }
        }
        // Candidates selected later are not "not identifiable" even if an earlier basis absorbed them.
        for (Effect e : selected) notIdent.remove(e.label());

        // The instrument's stated noise, and its floor per kind of measurement as the diagnosis sets it: √3·σ for points, σ for a
        // length (the missing columns' advice and the report's warnings ask whether the final model reaches it).
        double stated = statedSigmaM(trainAll);
        Measured kind = fit.problem.pairs() ? Measured.PAIRS : fit.problem.distance() ? Measured.ANCHOR : Measured.POINTS;

        // Advice for columns that are missing.
        Tester finalTester = w.tester(fit);
        List<Object[]> probes = new ArrayList<>();
        // A drift with the measuring order is asked only of a model short of the instrument's stated floor: on one that reaches
        // it nothing is left to drift, and the order follows the poses' places in the workspace.
        List<PoseConditions> order = poseOrder(rows);
        if (!hasTemp && !hasTime && rows.size() > 1 && shortOfFloor(fit.trainRms, stated, kind, perfectShare(fit, false))) {
            int n = rows.size();
            for (double f : new double[] {0.25, 0.5, 1, 3}) probes.add(new Object[] {Effect.thermalFromTime(f * n), order, "time"});
            // any smooth drift (the point moving, or the base or instrument turning)
            probes.add(new Object[] {Effect.pointSmooth(Effect.Along.TIME, 0, n - 1), order, "order"});
            probes.add(new Object[] {Effect.baseTurn(Effect.Along.TIME, 0, n - 1), order, "order"});
        }
        int nProbes = probes.size();
        boolean askedTime = false;
        double smoothPress = Double.POSITIVE_INFINITY;
        for (Object[] pr : probes) {
            @SuppressWarnings("unchecked") List<PoseConditions> cond = (List<PoseConditions>) pr[1];
            Candidate c = finalTester.test((Effect) pr[0], cond);
            if (c.keptColumns > 0) smoothPress = Math.min(smoothPress, c.pressAfter);
            if (c.keptColumns == 0 || !(c.p < o.alpha() / nProbes) || !(c.pressAfter < c.pressBefore)) continue;
            if (pr[2].equals("time") && !askedTime) {
                askedTime = true;
                recs.add(String.format(Locale.ROOT, "The residuals drift with the pose order (F = %.1f, p = %.1e), as a warm-up "
                        + "of the arm would make them: record temp_c (temperature near the robot) or at least time_s for "
                        + "every pose so thermal expansion can be identified.", c.f, c.p));
            } else if (pr[2].equals("order") && !askedTime) {
                askedTime = true;
                recs.add(String.format(Locale.ROOT, "The residuals change smoothly with the pose order (F = %.1f, p = %.1e): "
                        + "something changed while the poses were measured (a warm-up, the instrument drifting, a heat source or the "
                        + "sun warming one side of the arm), or the error follows the poses' place in the workspace, which the "
                        + "measuring order follows. Record time_s (and temp_c) for every pose so a drift can be located, and "
                        + "measure a few poses again at the end.", c.f, c.p));
            }
        }
        // and one step of the target on the flange between two poses of the order (a nest knocked, a holder slipping), at
        // every twentieth of the poses: its own family of probes, the best of them judged against their number
        Candidate bestStep = null;
        int stepAt = -1, nSteps = 0, grid = rows.size() / 20;
        if (nProbes > 0 && grid >= 1 && !geo.pairs() && !geo.distance()) {
            for (int k = grid; k < rows.size() - grid; k += grid) {
                Candidate c = finalTester.test(Effect.targetStep(model, k - 0.5), order);
                nSteps++;
                if (c.keptColumns > 0 && (bestStep == null || c.p < bestStep.p)) { bestStep = c; stepAt = k; }
            }
        }
        // a smooth drift a step only approximates (a warm-up, a floor tilting) is left to the smooth probes' advice
        if (bestStep != null && bestStep.p < o.alpha() / nSteps && bestStep.pressAfter < Math.min(bestStep.pressBefore, smoothPress)) {
            // placed between the grid's neighbours of the best, pose by pose
            int coarse = stepAt;
            for (int k = coarse - grid + 1; k < coarse + grid; k++) {
                if (k == coarse) continue;
                Candidate c = finalTester.test(Effect.targetStep(model, k - 0.5), order);
                if (c.keptColumns > 0 && c.p < bestStep.p) { bestStep = c; stepAt = k; }
            }
            recs.add(String.format(Locale.ROOT, "The residuals jump once along the pose order, between poses %s and %s (F = %.1f, "
                    + "p = %.1e), as a target that moved on the flange would make them (a reflector's nest knocked, a holder slipping "
                    + "in its clamp): check the target's seat, record time_s for every pose so such a step can be located, and measure "
                    + "a few of the first poses again at the end.", rows.get(stepAt - 1).poseId(), rows.get(stepAt).poseId(),
                    bestStep.f, bestStep.p));
        }
        if (dirSource.inferred() && selected.stream().anyMatch(e -> e.kind() == Effect.Kind.BACKLASH))
            recs.add("Backlash was identified with approach directions " + dirSource.words + ": record the approach direction "
                    + "of every joint (columns dir1..dir" + model.dof() + ") to confirm it, and approach each pose from a "
                    + "known side when compensating.");
        for (Effect e : selected) {
            if (e.kind() == Effect.Kind.COMPLIANCE && !hasPayload)
                recs.add("Joint compliance was found with the arm's own weight only: record payload_kg and measure with "
                        + "two or three payloads so the deflection is separated from the geometry more firmly.");
            if (e.usesTimeProxy())
                recs.add("Thermal expansion was inferred from time_s as a warm-up proxy: record temp_c to confirm it.");
        }

        // Final joint identification: values, sigmas, words, plots.
        double[] sig = w.effectSigmas(fit);
        Tester plotTester = selected.isEmpty() ? null : w.tester(fit);
        List<Diagnosis.Finding> findings = new ArrayList<>();
        List<Effect.Term> terms = new ArrayList<>();
        for (int k = 0; k < selected.size(); k++) {
            Effect e = selected.get(k);
            int off = fit.problem.effectOffset(k) - fit.problem.effectOffset(0);
            double[] v = Arrays.copyOfRange(fit.effectValues(), off, off + e.size());
            double[] s = Arrays.copyOfRange(sig, off, off + e.size());
            Step st = steps.get(k);
            Diagnosis.Evidence ev = st.candidate.evidence();
            // (for pairs of poses, the partial residuals of joint and strain effects; none for an effect on the measured point)
            Diagnosis.Plot plot = fit.problem.pairs() && e.target() == Effect.Target.POSITION ? null : Plots.partialResidual(plotTester, e, v);
            findings.add(new Diagnosis.Finding(e, v, s, st.trainRms, st.validateRms, ev, plot,
                    Words.finding(e, v, s, ev, k == 0 ? geoTrain : steps.get(k - 1).trainRms, st.trainRms,
                            k == 0 ? geoVal : steps.get(k - 1).validateRms, st.validateRms, dirSource,
                            e.kind() == Effect.Kind.BACKLASH && !fit.problem.pairs() ? halfPlaySizeM(plotTester, e.joint(), v[0]) : Double.NaN,
                            e.kind() == Effect.Kind.LINK_SAG ? springAlike(plotTester, k, e, family, selected, w, notes) : null)));
            terms.add(new Effect.Term(e, v));
        }
        List<Diagnosis.Finding> implausibleFindings = new ArrayList<>();
        for (Candidate c : implausible.values())
            implausibleFindings.add(new Diagnosis.Finding(c.effect, c.estimate, new double[c.effect.size()], Double.NaN,
                    Double.NaN, c.evidence(), null, Words.implausible(c.effect, c.estimate, c.evidence())));
        ExtendedModel ext = new ExtendedModel(fit.problem.modelOf(fit.full), terms);
        notes.addAll(aliasNotes);

        timer.mark("final fit");
        // What only the report needs (the final locate, the warnings, the validation poses' outliers) is made when the report
        // is asked for: a diagnosis the judgement of the outliers replaces by another run is never finished.
        Fit fin = fit;
        CalibrationResult geoFin = geo;
        int tested = Math.max(familySize, 0);
        double valFinal = w.validateRms(fit);
        double heldOutRms = Double.isFinite(valFinal) ? valFinal : fit.trainRms;
        boolean onValidation = Double.isFinite(valFinal);
        double perfect = perfectShare(fit, onValidation);
        // (with nothing named, the geometric model's own: a pose it left out is a bad reading only as far out as under any model)
        Map<String, Double> beyond = selected.isEmpty() && outliers.isEmpty() ? Map.of() : outliersUnder(selected, fit, trainAll);
        List<String> under = new ArrayList<>(beyond.keySet());
        if (!under.isEmpty()) under = otherFlankExplains(w, fit, selected, under);
        // The final model short of the instrument's stated floor does not follow every pose, so a pose a few of its robust
        // sigmas out is no sign of a bad reading (only a far one is) — unless the poses beyond the rule are what keeps it
        // short: refitted without them, it must still miss the floor.
        boolean aboveFloor = shortOfFloor(heldOutRms, stated, kind, perfect);
        boolean missesFloor = aboveFloor && (under.isEmpty() || shortWithout(w, fit, selected, absorbedCols, under, geo, stated, kind));
        // A fallback follows a structure by a shape fitted to it, not by its physics: where the shape and the structure part,
        // a clean pose may lie a few robust sigmas out.
        List<String> approximated = selected.stream().filter(Effect::isFallback).map(Effect::label).toList();
        // (every validation pose, those set aside from the start too)
        List<CalibrationResult.Outlier> valBeyond = validate == null || validate.size() < 10 ? List.of()
                : List.copyOf(Calibrator.outliers(fit.problem, fit.full, validate, Set.of(), OUTLIER_K).values());
        java.util.function.Supplier<Finished> finish = () -> {
            // Locate what is left, and report every structure found (named or not).
            Tester lastTester = plotTester != null ? plotTester : geoTester;
            List<Locator.Found> scannedFinal = selected.isEmpty() ? foundGeo
                    : Locator.scan(lastTester, Locator.probes(lastTester, dirSource), o.alpha(), MAX_LOCATED);
            // Beside a named family, a structure left is a claim the user reads: with validation poses it must hold there too.
            List<Locator.Found> weak = weakLeads(w, fin, selected, absorbedCols, lastTester, scannedFinal, rows, model, notes);
            List<Locator.Found> foundFinal = scannedFinal.stream().filter(f -> !weak.contains(f)).toList();
            List<Diagnosis.Located> located = new ArrayList<>();
            for (Locator.Found f : foundGeo) {
                if (weak.stream().anyMatch(g -> sameStructure(f, g))) continue; // said in the notes as a weak lead
                boolean left = foundFinal.stream().anyMatch(g -> sameStructure(f, g));
                Effect named = left ? null : explainer(f, selected);
                String by = named != null ? named.label() : left ? null : takenBy(f, geoTester, selected);
                located.add(located(f, geoTester, "geometric", by, named == null && by != null, left));
            }
            if (!selected.isEmpty())
                for (Locator.Found f : foundFinal) located.add(located(f, lastTester, "final", null, false, true));
            // a model short of the instrument's floor with no shape left to follow (or shapes that hold little of what is left:
            // a ringing arm's deflection, its phase at the reading as good as random, leaves a chance harmonic or two beside its
            // scatter), and none followed through a fallback (whose misfit is left in the residual too): a joint whose angle
            // scatters (a coarse encoder's counts, a joint not settled) moves the point along its own motion only
            double shapesLeft = lastTester.rss0 > 0 ? foundFinal.stream().mapToDouble(f -> f.c.drss).sum() / lastTester.rss0 : 1;
            if (aboveFloor && shapesLeft < SCATTER_BESIDE_SHARE && approximated.isEmpty())
                for (JointScatter.Found f : JointScatter.scan(lastTester, o.alpha())) located.add(JointScatter.located(f));
            // The noise floor without every structure still located; above 1.2x it the report says so first.
            double rssLeft = lastTester.rss0;
            int dfLeft = lastTester.m - lastTester.rank;
            for (Locator.Found f : foundFinal) { rssLeft -= f.c.drss; dfLeft -= f.c.df1; }
            timer.mark("final locate");
            if (!foundFinal.isEmpty() && !outliers.isEmpty())
                notes.add("the outlier test is not reliable on these poses: a structure no named effect explains is left (see "
                        + "located), and poses on it can look like bad measurements; check the poses reported as outliers against it");
            double statedTrainFloor = Double.isFinite(stated) ? noiseFloor(stated, kind.components) * perfectShare(fin, false) : Double.NaN;
            List<String> warnings = warnings(foundFinal, selected, fin, w, rssLeft, dfLeft, rows.size(), model.dof(), statedTrainFloor);
            // What the training fit predicts for new poses: its RMS inflated by the parameters it estimated.
            double predicted = fin.trainRms * Math.sqrt((double) fin.m / Math.max(1, fin.m - fin.nf)) * Math.sqrt(1 + (double) fin.nf / fin.m);
            String carryOver = null, floorWarning = null;
            if (Double.isFinite(valFinal) && valFinal > 1.2 * predicted) {
                carryOver = String.format(Locale.ROOT, "The validation poses miss by %.4f mm RMS, %.1f x what the training fit "
                        + "predicts (%.4f mm): the model does not carry over to new poses. Something the scan cannot resolve on "
                        + "these poses is left (a harmonic above %d cycles per turn, an error that depends on two joints at once, "
                        + "or a change between the measuring sessions). Measure more poses, spread over every joint's range, and "
                        + "repeat some poses at the end to see a drift.", valFinal * 1e3, valFinal / predicted, predicted * 1e3, hMax);
                warnings.add(0, carryOver);
            }
            if (aboveFloor) {
                floorWarning = aboveStatedFloor(heldOutRms, onValidation, stated, kind, perfect, fin.nf, selected, foundFinal.isEmpty());
                warnings.add(0, floorWarning);
            }
            // the validation poses beyond the range a fallback was fitted over (predicted by extrapolation): for the warnings and the
            // validation poses' outliers
            Map<String, Effect> beyondFitted = onValidation && (carryOver != null || floorWarning != null || !valBeyond.isEmpty())
                    ? beyondFitted(selected, validate.rows(), ext, fin.problem.toolOf(fin.full)) : Map.of();
            if (onValidation && (carryOver != null || floorWarning != null))
                sayWhereValidationMisses(w, fin, selected, beyondFitted, rows, warnings, carryOver, floorWarning, valFinal, predicted, hMax);
            o.progress().update("done", 1);
            // σ per position axis, or per distance: from the position (distance) rows only, degrees of freedom corrected.
            int rppF = fin.problem.rowsPerPose(), posRows = fin.problem.positionRowsPerPose();
            double posSq = 0;
            for (int i = 0; i < fin.m; i++) if (i % rppF < posRows) posSq += fin.r[i] * fin.r[i];
            double sigmaFinal = Math.sqrt(posSq / Math.max(1, (double) fin.m / rppF * posRows * (fin.m - fin.nf) / fin.m)) * w.sigmaPos;
            // Validation poses beyond the outlier rule under the final model (their own robust sigma; at least 10 of them); with a
            // structure located and left, a few gross readings only; with the model short of the instrument's stated floor, or
            // resting on a fallback's shape, only those beyond SHORT_MODEL_SIGMAS.
            List<CalibrationResult.Outlier> valOut = new ArrayList<>(valBeyond);
            if (!foundFinal.isEmpty() && !valOut.isEmpty()) valOut = grossAmong(valOut, validate.size());
            else if ((missesFloor || !approximated.isEmpty()) && !valOut.isEmpty()) valOut.removeIf(ol -> !(ol.residualM() / ol.robustSigmaM() > SHORT_MODEL_SIGMAS));
            if (!valOut.isEmpty()) {
                // A pose beyond the range a fallback was fitted over is predicted by extrapolation, not judged.
                Map<String, Measurement> byId = new LinkedHashMap<>();
                for (Measurement m : validate.rows()) byId.put(m.poseId(), m);
                Map<CalibrationResult.Outlier, Effect> extrapolated = new LinkedHashMap<>();
                for (CalibrationResult.Outlier ol : valOut) {
                    Effect e = beyondFitted.get(ol.poseId());
                    if (e != null) extrapolated.put(ol, e);
                }
                valOut.removeIf(ol -> extrapolated.containsKey(ol) || inStepGap(selected, byId.get(ol.poseId()), rows));
                // nor one facing two instrument stations nearly alike: which of them read it is uncertain
                List<String> twoStations = valOut.stream().map(CalibrationResult.Outlier::poseId)
                        .filter(id -> atStationSplit(selected, byId.get(id).q())).toList();
                if (!twoStations.isEmpty()) {
                    valOut.removeIf(ol -> twoStations.contains(ol.poseId()));
                    notes.add(String.format(Locale.ROOT, "validation %s %s %s the two instrument stations nearly alike, so which station "
                            + "read %s is uncertain: not reported as %s; record which station reads each pose",
                            twoStations.size() == 1 ? "pose" : "poses", String.join(", ", twoStations), twoStations.size() == 1 ? "faces" : "face",
                            twoStations.size() == 1 ? "it" : "them", twoStations.size() == 1 ? "an outlier" : "outliers"));
                }
                extrapolated.forEach((ol, e) -> notes.add(String.format(Locale.ROOT, "validation pose %s lies beyond the range %s was "
                        + "fitted over on the training poses and misses by %.4f mm, %.0f robust sigmas: the model's extrapolation there, not a "
                        + "bad reading, so it is not reported as an outlier and stays in the validation error; measure training poses over "
                        + "that range too", ol.poseId(), e.label(), ol.residualM() * 1e3, ol.residualM() / ol.robustSigmaM())));
                // nor is one the play's other flank explains where gravity hands the gear over: the model's miss, said as such
                Fit at = fin;
                List<String> handedOver = valOut.stream().map(CalibrationResult.Outlier::poseId)
                        .filter(id -> otherFlankExplains(w, at, selected, byId.get(id))).toList();
                if (!handedOver.isEmpty()) {
                    valOut.removeIf(ol -> handedOver.contains(ol.poseId()));
                    List<Measurement> rest = w.validate.rows().stream().filter(m -> !handedOver.contains(m.poseId())).toList();
                    boolean one = handedOver.size() == 1;
                    notes.add(String.format(Locale.ROOT, "validation %s %s %s where the gravity torque hands the gear of a play held by "
                            + "gravity from one flank to the other: which flank it sits on there the model cannot tell (the masses are "
                            + "estimates, the mesh's friction varies), and %s by about the play. %s no bad %s and %s in the validation error "
                            + "(%.4f mm; %.4f mm without %s)", one ? "pose" : "poses", String.join(", ", handedOver), one ? "lies" : "lie",
                            one ? "it misses" : "they miss", one ? "It is" : "They are", one ? "reading" : "readings", one ? "stays" : "stay",
                            valFinal * 1e3, rest.isEmpty() ? Double.NaN : w.heldOut(fin, rest, false) * 1e3, one ? "it" : "them"));
                }
            }
            Diagnosis result = new Diagnosis(robot.name(), geoFin, sigmaFinal, geoTrain, geoVal, findings, fin.trainRms, valFinal,
                    outliers, new ArrayList<>(notIdent.values()), implausibleFindings, recs, notes, ext,
                    fin.problem.toolOf(fin.full), w.instrument ? fin.problem.instrumentOf(fin.full) : org.robopro.kinematics.Pose.IDENTITY,
                    tested, o.alpha(), (System.nanoTime() - t0) / 1e6, dirSource, located, warnings);
            return new Finished(result, valOut);
        };
        if (LOG.isDebugEnabled())
            LOG.debug("run: left out {}, model {}, outliers under it {}", outliers, selected.stream().map(Effect::label).toList(), under);
        java.util.function.Supplier<List<String>> underEveryPose = () -> {
            // the final model's effects and geometry fitted again to every training pose but the gross readings among many
            List<Measurement> every = trainAll.rows().stream().filter(m -> !gross.contains(m.poseId())).toList();
            Work wa = new Work(model, gravity, every, geoFin, validate, o, w.sigmaPos, w.sigmaRot);
            Fit fa = wa.fit(selected, absorbedCols, fin.full, null);
            List<String> u = new ArrayList<>(outliersUnder(selected, fa, trainAll).keySet());
            return u.isEmpty() ? u : otherFlankExplains(wa, fa, selected, u);
        };
        Fold fold = new Fold(namedKeys(selected), List.copyOf(outliers), geo, geoVal, valFinal);
        // the validation poses' outliers need the finished report only when the rule flags any
        Run made = new Run(finish, !selected.isEmpty(), fold, !valBeyond.isEmpty(), missesFloor, approximated, under, List.copyOf(gross),
                underEveryPose, beyond);
        made.screened = screened;
        // the poses that face two instrument stations nearly alike: which of them read such a pose is uncertain
        for (Measurement m : trainAll.rows()) if (atStationSplit(selected, m.q())) made.ambiguous.add(m.poseId());
        // a run of poses kept in as a change at one time must be what a step at that time explains; else they are bad readings
        made.unexplainedRun = timeRun.isEmpty() || stepAtRun(selected, timeRun, trainAll.rows()) ? List.of() : timeRun;
        return made;
    }

    /**
     * Whether a selected step in time (of the instrument against the base, the target, a zero, the
     * distances) lies at the run of poses {@code run} (ids in time order): after the training pose
     * before its first, and no later than its last.
     */
    static boolean stepAtRun(List<Effect> selected, List<String> run, List<Measurement> rows) {
        Map<String, Double> time = new java.util.HashMap<>();
        for (Measurement m : rows) time.put(m.poseId(), m.timeS());
        double first = time.get(run.get(0)), last = time.get(run.get(run.size() - 1));
        double before = rows.stream().mapToDouble(Measurement::timeS).filter(t -> t < first).max().orElse(Double.NEGATIVE_INFINITY);
        return selected.stream().anyMatch(e -> e.stepInTime() && e.tauS() > before && e.tauS() <= last);
    }

    /**
     * Whether a pose lies between the two training poses a selected step was placed between (in time
     * for a step of a joint's zero or of the target, in the joint's angle for a step of its reading):
     * the training poses put the step anywhere in that gap, so which side of it the pose lies on,
     * and so its prediction, is not known.
     */
    static boolean inStepGap(List<Effect> selected, Measurement m, List<Measurement> rows) {
        return stepAround(selected, m, rows) != null;
    }

    /** The selected step whose gap between two training poses pose {@code m} lies in ({@link #inStepGap}), or null. */
    private static Effect stepAround(List<Effect> selected, Measurement m, List<Measurement> rows) {
        if (m == null) return null;
        for (Effect e : selected) {
            java.util.function.ToDoubleFunction<Measurement> x = e.stepInTime() ? Measurement::timeS
                    : e.kind() == Effect.Kind.ANGLE_STEP ? r -> r.q(e.joint()) : null;
            if (x == null) continue;
            double[] places = e.kind() == Effect.Kind.ANGLE_STEP
                    ? (e.isWindow() ? new double[] {e.rangeLo(), e.rangeHi()} : new double[] {e.rangeLo()}) : new double[] {e.tauS()};
            double xm = x.applyAsDouble(m);
            for (double place : places) {
                double below = Double.NEGATIVE_INFINITY, above = Double.POSITIVE_INFINITY;
                for (Measurement r : rows) {
                    double xr = x.applyAsDouble(r);
                    if (xr <= place) below = Math.max(below, xr);
                    else above = Math.min(above, xr);
                }
                if (xm > below && xm < above) return e;
            }
        }
        return null;
    }

    /**
     * Where the final model misses the validation poses, when it does (the warnings {@code carryOver}
     * and {@code floorWarning}, either null): poses beyond the range a fallback was fitted over are
     * predicted by extrapolation, and a pose between the two training poses either side of a step
     * may lie on either side of it. When some are, the warnings say how many and why, and what the
     * others miss by: whether the model carries over to the poses it can predict.
     */
    private static void sayWhereValidationMisses(Work w, Fit fin, List<Effect> selected, Map<String, Effect> beyondFitted,
                                                 List<Measurement> rows, List<String> warnings, String carryOver, String floorWarning,
                                                 double valFinal, double predicted, int hMax) {
        Map<Measurement, Effect> beyond = new LinkedHashMap<>(), inGap = new LinkedHashMap<>();
        for (Measurement m : w.validate.rows()) {
            Effect e = beyondFitted.get(m.poseId());
            if (e != null) beyond.put(m, e);
            else if ((e = stepAround(selected, m, rows)) != null) inGap.put(m, e);
        }
        List<Measurement> rest = w.validate.rows().stream().filter(m -> !beyond.containsKey(m) && !inGap.containsKey(m)).toList();
        if (beyond.isEmpty() && inGap.isEmpty() || rest.isEmpty()) return;
        double valRest = w.heldOut(fin, rest, false);
        List<String> why = new ArrayList<>(), measure = new ArrayList<>();
        if (!beyond.isEmpty()) {
            String fallbacks = String.join(", ", new java.util.TreeSet<>(beyond.values().stream().map(Effect::label).toList()));
            why.add(String.format(Locale.ROOT, "%s beyond the range %s was fitted over on the training poses (extrapolated there)",
                    posesLie(beyond.keySet()), fallbacks));
            measure.add(String.format(Locale.ROOT, "measure training poses over the range the model is to be used in: the shape %s "
                    + "follows is fitted, not known, beyond the training poses", fallbacks));
        }
        if (!inGap.isEmpty()) {
            String steps = String.join(", ", new java.util.TreeSet<>(inGap.values().stream().map(Effect::label).toList()));
            why.add(String.format(Locale.ROOT, "%s between the two training poses either side of %s (on either side of the step, "
                    + "which the training poses do not tell)", posesLie(inGap.keySet()), steps));
            measure.add("a step's place is known only to the gap between two training poses: measure a few poses there again");
        }
        String reasons = String.join(", and ", why);
        String advice = " " + Character.toUpperCase(measure.get(0).charAt(0)) + String.join("; ", measure).substring(1) + ".";
        if (carryOver != null)
            warnings.set(warnings.indexOf(carryOver), String.format(Locale.ROOT, "The validation poses miss by %.4f mm RMS, %.1f x what "
                    + "the training fit predicts (%.4f mm), but %s; the other %d miss by %.4f mm (%.1f x): %s", valFinal * 1e3,
                    valFinal / predicted, predicted * 1e3, reasons, rest.size(), valRest * 1e3, valRest / predicted,
                    (valRest <= 1.2 * predicted ? "the model carries over to the poses it can predict."
                            : String.format(Locale.ROOT, "the model does not carry over even to those; something the scan cannot "
                            + "resolve on these poses is left (a harmonic above %d cycles per turn, an error that depends on two joints "
                            + "at once, or a change between the measuring sessions).", hMax)) + advice));
        if (floorWarning != null)
            warnings.set(warnings.indexOf(floorWarning), floorWarning + String.format(Locale.ROOT, " %s; the other %d validation poses "
                    + "miss by %.4f mm.", Character.toUpperCase(reasons.charAt(0)) + reasons.substring(1), rest.size(), valRest * 1e3));
    }

    /** "validation pose 12 lies" or "28 validation poses lie". */
    private static String posesLie(java.util.Set<Measurement> poses) {
        return poses.size() == 1 ? "validation pose " + poses.iterator().next().poseId() + " lies" : poses.size() + " validation poses lie";
    }

    /** Each pose of {@code poses} that lies beyond the fitted range of a selected fallback ({@link #outsideFitted}), by id, with it. */
    private static Map<String, Effect> beyondFitted(List<Effect> selected, List<Measurement> poses, ExtendedModel ext,
                                                    org.robopro.kinematics.Pose tool) {
        Map<String, Effect> out = new LinkedHashMap<>();
        for (Measurement m : poses) {
            Effect e = outsideFitted(selected, m, ext, tool);
            if (e != null) out.put(m.poseId(), e);
        }
        return out;
    }

    /** The selected fallback whose variable a pose lies beyond the fitted range of (its prediction there is an extrapolation), or null. */
    private static Effect outsideFitted(List<Effect> selected, Measurement m, ExtendedModel ext, org.robopro.kinematics.Pose tool) {
        if (m == null) return null;
        PoseConditions c = PoseConditions.of(m);
        for (Effect e : selected) {
            double x = switch (e.kind()) {
                case SMOOTH -> e.smoothVariable(m.q());
                case ZERO_DRIFT, INSTRUMENT_SCALE, BASE_TURN -> e.along() == Effect.Along.TIME ? c.timeS() : c.tempC();
                // an instrument's reading error as a smooth curve of the reading (not a cyclic one)
                case INSTRUMENT -> Double.isFinite(e.cycle()) ? Double.NaN : e.sightReadingOf(ext.tool(m.q(), tool, c).position().toArray());
                case POINT_SMOOTH -> switch (e.along()) {
                    case TIME -> c.timeS();
                    case TEMPERATURE -> c.tempC();
                    default -> {
                        var p = ext.tool(m.q(), tool, c).position();
                        yield e.pointVariable(new double[] {p.x(), p.y(), p.z()});
                    }
                };
                default -> Double.NaN;
            };
            double span = e.rangeHi() - e.rangeLo();
            if (Double.isFinite(x) && (x < e.rangeLo() - 0.01 * span || x > e.rangeHi() + 0.01 * span)) return e;
        }
        return null;
    }

    /**
     * Takes selected effect {@code k} out and, when {@code by} is given and identifiable on what is
     * left, puts it in its place. With {@code heldOut}, {@code by} stays only when it lowers the
     * leave-one-pose-out error of the model without the effect (and the validation error, when
     * there are validation poses). Returns the new fit.
     */
    private static Fit replaceEffect(Work w, Fit fit, List<Effect> selected, Map<Effect, boolean[]> absorbedCols, List<Step> steps,
                                     int k, Effect by, boolean heldOut) {
        Effect e = selected.get(k);
        Step old = steps.get(k);
        Fit without = dropAndRefit(w, fit, selected, absorbedCols, steps, k);
        // a second form of what the model holds already: that form stands for it
        if (by == null || secondForm(by, selected, e)) return without;
        Tester wt = w.tester(without);
        Candidate bc = wt.test(by, w.conditions);
        if (bc.keptColumns == 0 || heldOut && !(bc.pressAfter < bc.pressBefore)) return without;
        selected.add(by);
        absorbedCols.put(by, bc.absorbedMask);
        Fit f = w.fit(selected, absorbedCols, without.full, bc);
        boolean worseHeldOut = heldOut && w.hasValidation() && !(w.validateError(f) < w.validateError(without));
        // A family whose estimate leaves physical bounds once fitted jointly with the rest does not take the place.
        boolean implausible = !by.isFallback() && !w.plausibleIn(f, selected, selected.size() - 1);
        if (worseHeldOut || implausible) {
            selected.remove(selected.size() - 1);
            absorbedCols.remove(by);
            if (heldOut) return without;
            // An alias that fails keeps the effect it was to replace.
            Candidate ec = wt.test(e, w.conditions);
            if (ec.keptColumns == 0) return without;
            selected.add(e);
            absorbedCols.put(e, ec.absorbedMask);
            Fit back = w.fit(selected, absorbedCols, without.full, ec);
            steps.add(new Step(old.candidate, back.trainRms, w.validateRms(back)));
            return back;
        }
        bc.threshold = old.candidate.threshold;
        steps.add(new Step(bc, f.trainRms, w.validateRms(f)));
        return f;
    }

    /**
     * The displacement of the measured point by a lost motion of {@code b} on drive {@code joint} at
     * its full half-play, RMS over the poses, m (position rows only).
     */
    static double halfPlaySizeM(Tester t, int joint, double b) {
        double[] s = t.signature(Effect.backlash(joint), t.w.conditions);
        double ss = 0;
        int poses = t.m / t.rpp;
        for (int i = 0; i < poses; i++)
            for (int a = 0; a < t.posRows; a++) { double d = s[i * t.rpp + a] * b; ss += d * d; }
        return Math.sqrt(ss / Math.max(1, poses * t.perPose)) * t.fit.problem.sigmaPos();
    }

    /** Build-up lengths of the wind-up grid, rad: 0.5° to 40° in steps of 25 %, refined between the neighbours of the best. */
    static final double WINDUP_MIN_RAD = Math.toRadians(0.5), WINDUP_MAX_RAD = Math.toRadians(40), WINDUP_STEP = 1.25;

    /**
     * Approach lengths of the approached wind-up's grid, rad: 0.25° to 16° in doublings, then refined
     * in log length between the best one's neighbours at the best build-up length.
     */
    static final double[] APPROACH_GRID_RAD = {Math.toRadians(0.25), Math.toRadians(0.5), Math.toRadians(1), Math.toRadians(2),
            Math.toRadians(4), Math.toRadians(8), Math.toRadians(16)};

    /**
     * The lost motion of {@code joint} that builds up over the move, with the build-up length that
     * predicts left-out poses best in place of selected effect {@code k}: a grid of lengths (b is
     * linear at each), then a golden-section search in log length between the best one's
     * neighbours. Returned as a term whose value is that leave-one-pose-out error; null when no
     * length is testable.
     * With {@code approached} (the joint's poses were taken by approach moves the file does not
     * hold) the approach's length is searched too: the build-up grid at every approach length of
     * {@link #APPROACH_GRID_RAD}, then a golden-section search of each length in turn between the
     * best one's neighbours.
     */
    static Effect.Term bestWindUp(Tester at, int k, int joint, Directions.Moves moves, List<PoseConditions> conds, boolean approached) {
        List<Double> grid = new ArrayList<>();
        for (double x = WINDUP_MIN_RAD; x <= WINDUP_MAX_RAD * 1.0001; x *= WINDUP_STEP) grid.add(x);
        double[] approaches = approached ? APPROACH_GRID_RAD : new double[] {Double.NaN};
        int best = -1, bestA = -1;
        double pBest = Double.POSITIVE_INFINITY;
        for (int ia = 0; ia < approaches.length; ia++)
            for (int i = 0; i < grid.size(); i++) {
                double p = at.pressReplacing(k, Effect.windUp(joint, grid.get(i), approaches[ia], moves), conds);
                if (Double.isFinite(p) && p < pBest) { pBest = p; best = i; bestA = ia; }
            }
        if (best < 0) return null;
        double[] x = {grid.get(best), approaches[bestA]};
        java.util.function.DoubleUnaryOperator byBuildUp = l -> at.pressReplacing(k, Effect.windUp(joint, Math.exp(l), x[1], moves), conds);
        double[] r = goldenLog(byBuildUp, grid.get(Math.max(0, best - 1)), grid.get(Math.min(grid.size() - 1, best + 1)));
        if (r[1] < pBest) { pBest = r[1]; x[0] = Math.exp(r[0]); }
        if (approached) {
            java.util.function.DoubleUnaryOperator byApproach = l -> at.pressReplacing(k, Effect.windUp(joint, x[0], Math.exp(l), moves), conds);
            r = goldenLog(byApproach, approaches[Math.max(0, bestA - 1)], approaches[Math.min(approaches.length - 1, bestA + 1)]);
            if (r[1] < pBest) { pBest = r[1]; x[1] = Math.exp(r[0]); }
        }
        return new Effect.Term(Effect.windUp(joint, x[0], x[1], moves), new double[] {pBest});
    }

    /**
     * A golden-section search of {@code f} over log lengths between {@code lo} and {@code hi} (rad),
     * eight steps: {log length, value} of the better of its last two points.
     */
    private static double[] goldenLog(java.util.function.DoubleUnaryOperator f, double lo, double hi) {
        double a = Math.log(lo), b = Math.log(hi);
        double g = (Math.sqrt(5) - 1) / 2;
        double c = b - g * (b - a), d = a + g * (b - a);
        double pc = f.applyAsDouble(c), pd = f.applyAsDouble(d);
        for (int it = 0; it < 8; it++) {
            if (pc < pd) { b = d; d = c; pd = pc; c = b - g * (b - a); pc = f.applyAsDouble(c); }
            else { a = c; c = d; pc = pd; d = a + g * (b - a); pd = f.applyAsDouble(d); }
        }
        return pc < pd ? new double[] {c, pc} : new double[] {d, pd};
    }

    /**
     * The thermal growth link by link with every link lagging the reading by one time constant from
     * {@link ThermalLag#TAUS} (above 0), the one whose test against {@code t} predicts left-out poses
     * best; null when none is testable.
     */
    static Effect commonLag(Tester t, KinematicModel model, double t0C, ThermalLag lag, List<PoseConditions> conds) {
        int n = Effect.thermalLinks(model, t0C).size();
        Effect best = null;
        double bestPress = Double.POSITIVE_INFINITY;
        for (double tau : ThermalLag.TAUS) {
            if (tau == 0) continue;
            double[] taus = new double[n];
            Arrays.fill(taus, tau);
            Effect e = Effect.thermalLinks(model, t0C, lag, taus);
            Candidate c = t.test(e, conds);
            if (c.keptColumns > 0 && c.pressAfter < bestPress) { bestPress = c.pressAfter; best = e; }
        }
        return best;
    }

    /**
     * With validation data, the first selected effect of a richer form ({@code richer}: lagged growth,
     * a warm-up) is kept only when the final model predicts the validation poses better with it than
     * with {@code simpler} of it in its place (each residual over its noise); otherwise the simpler
     * form stays. {@code rejected} and {@code kept} (null: no note) word the outcome from the effect
     * and {with, without}.
     */
    private static Fit validatedForm(Work w, Fit fit, List<Effect> selected, Map<Effect, boolean[]> absorbedCols, List<Step> steps,
                                     java.util.function.Predicate<Effect> richer, java.util.function.UnaryOperator<Effect> simpler,
                                     java.util.function.BiFunction<Effect, double[], String> rejected,
                                     java.util.function.BiFunction<Effect, double[], String> kept, List<String> notes) {
        for (int k = 0; k < selected.size() && w.hasValidation(); k++) {
            Effect e = selected.get(k);
            if (!richer.test(e)) continue;
            double with = w.validateError(fit);
            Selection saved = Selection.of(selected, absorbedCols, steps);
            Effect plainForm = simpler.apply(e);
            Fit plain = replaceEffect(w, fit, selected, absorbedCols, steps, k, plainForm, false);
            int at = selected.indexOf(plainForm);
            if (at < 0) {
                saved.restore(selected, absorbedCols, steps);
                continue;
            }
            double wo = w.validateError(plain);
            if (!(with < wo)) {
                notes.add(rejected.apply(e, new double[] {with, wo}));
                fit = plain;
                k--; // the effect after it now stands at k
                continue;
            }
            fit = replaceEffect(w, plain, selected, absorbedCols, steps, at, e, false);
            if (kept != null) notes.add(kept.apply(e, new double[] {with, wo}));
            break;
        }
        return fit;
    }

    /** Time constants tried for the drives' warm-up of a thermal growth link by link, s. */
    static final double[] WARM_TAUS = {600, 1200, 2400, 4800};
    /** Largest plausible rise of a link's temperature above the air from its drives, K. */
    static final double MAX_WARM_K = 30;

    /**
     * {@code growth} with the drives' warm-up at the time constant from {@link #WARM_TAUS} whose test
     * against {@code t} predicts left-out poses best; null when none is testable.
     */
    static Effect commonWarmUp(Tester t, Effect growth, List<PoseConditions> conds) {
        Effect best = null;
        double bestPress = Double.POSITIVE_INFINITY;
        for (double tw : WARM_TAUS) {
            Effect e = Effect.withWarmUp(growth, tw, t.w.pauses);
            Candidate c = t.test(e, conds);
            if (c.keptColumns > 0 && c.pressAfter < bestPress) { bestPress = c.pressAfter; best = e; }
        }
        return best;
    }

    /** A link's own lag replaces the common one only when it lowers the leave-one-pose-out error by this fraction. */
    static final double LINK_LAG_MARGIN = 0.01;

    /**
     * A search of a thermal growth's lags: the best form and its leave-one-pose-out error, that error
     * with no lag, and the best single lag for every link with its error.
     */
    record LagSearch(Effect effect, double press, double pressNone, double commonTau, double pressCommon) {
        /** Whether the links' own lags predict better than one for all. */
        boolean perLink() { return Arrays.stream(effect.lagTaus()).distinct().count() > 1; }
    }

    /**
     * The lags of selected thermal growth {@code k} that predict left-out poses best in its place: one
     * time constant for every link (from {@link ThermalLag#TAUS}, 0 the unlagged form), then, link by
     * link, its own time constant where that lowers the leave-one-pose-out error by more than
     * {@link #LINK_LAG_MARGIN} (two rounds); null when none is testable.
     */
    static LagSearch bestLags(Tester at, int k, Effect growth, KinematicModel model, double t0C, ThermalLag lag,
                                List<PoseConditions> conds) {
        int n = growth.lagTaus().length, nt = ThermalLag.TAUS.length;
        // A link's column depends on its own lag alone: the columns of the common lags, projected once, make up every mix.
        double[][][] cols = new double[nt][][];
        double[][] n0 = new double[nt][];
        int[] pick = null;
        double best = Double.POSITIVE_INFINITY, none = Double.NaN;
        for (int ti = 0; ti < nt; ti++) {
            double[] ts = new double[n];
            Arrays.fill(ts, ThermalLag.TAUS[ti]);
            Effect e = Effect.thermalLinks(model, t0C, lag, ts);
            Tester.Projected pr = at.projectedReplacing(k, at.signature(e, conds), e.size());
            cols[ti] = pr.cols();
            n0[ti] = pr.n0();
            double p = at.pressReplacingProjected(k, cols[ti], n0[ti]);
            if (ThermalLag.TAUS[ti] == 0) none = p;
            if (p < best) { best = p; pick = new int[n]; Arrays.fill(pick, ti); }
        }
        if (pick == null) return null;
        double common = ThermalLag.TAUS[pick[0]], pressCommon = best;
        double[][] mixCols = new double[n][];
        double[] mixN0 = new double[n];
        for (int round = 0; round < 2; round++) {
            boolean moved = false;
            for (int col = 0; col < n; col++)
                for (int ti = 0; ti < nt; ti++) {
                    if (ti == pick[col]) continue;
                    for (int c = 0; c < n; c++) {
                        int from = c == col ? ti : pick[c];
                        mixCols[c] = cols[from][c];
                        mixN0[c] = n0[from][c];
                    }
                    double p = at.pressReplacingProjected(k, mixCols, mixN0);
                    if (p < best * (1 - LINK_LAG_MARGIN)) { best = p; pick = pick.clone(); pick[col] = ti; moved = true; }
                }
            if (!moved) break;
        }
        double[] taus = new double[n];
        for (int c = 0; c < n; c++) taus[c] = ThermalLag.TAUS[pick[c]];
        // the drives' warm-up beside the air's temperature, where it predicts left-out poses clearly better
        Effect form = Effect.thermalLinks(model, t0C, lag, taus);
        Effect warmed = null;
        for (double tw : WARM_TAUS) {
            Effect e = Effect.withWarmUp(form, tw, at.w.pauses);
            double p = at.pressReplacing(k, e, conds);
            if (p < best * (1 - ALIAS_MARGIN)) { best = p; warmed = e; }
        }

        return new LagSearch(warmed != null ? warmed : form, best, none, common, pressCommon);
    }

    /** "600 s: base to joint 1, link 2 (joint 2 to joint 3); 300 s: link 3 (joint 3 to joint 4)". */
    private static String linkLags(Effect growth) {
        Map<Double, List<String>> by = new java.util.TreeMap<>(java.util.Comparator.reverseOrder());
        double[] taus = growth.lagTaus();
        for (int col = 0; col < taus.length; col++) by.computeIfAbsent(taus[col], x -> new ArrayList<>()).add(growth.linkWords(col));
        List<String> out = new ArrayList<>();
        by.forEach((tau, ls) -> out.add(String.format(Locale.ROOT, "%.0f s for %s", tau, String.join(", ", ls))));
        return String.join("; ", out);
    }

    /**
     * What the data tell of the lag of named thermal growth {@code k} (docs/diagnosis.md): the lag
     * found, its leave-one-pose-out error against none, and whether the links' own lags could be
     * told apart; null when nothing can be said.
     */
    static String lagWords(Tester at, int k, Effect growth, KinematicModel model, double t0C, ThermalLag lag,
                           List<PoseConditions> conds) {
        LagSearch s = bestLags(at, k, growth, model, t0C, lag, conds);
        if (s == null) return null;
        if (!growth.lags())
            return String.format(Locale.ROOT, "thermal growth: no lag of the links behind the temperature reading is seen (the "
                    + "best single lag, %.0f s, predicts left-out poses no better: leave-one-pose-out error %.1f against %.1f at the "
                    + "reading's temperature); the links are taken at the reading", s.commonTau(), s.pressCommon(), s.pressNone());
        String which = growth.lags() && Arrays.stream(growth.lagTaus()).distinct().count() > 1
                ? String.format(Locale.ROOT, "each link its own lag: %s (one lag of %.0f s for every link predicts worse: %.1f)",
                        linkLags(growth), s.commonTau(), s.pressCommon())
                : String.format(Locale.ROOT, "one lag of %.0f s for every link: the data do not tell the links' own lags apart "
                        + "(no link's own lag lowers the leave-one-pose-out error by %.0f %%)", growth.lagTaus()[0], 100 * LINK_LAG_MARGIN);
        return String.format(Locale.ROOT, "thermal growth: the links follow the temperature reading with a lag (a first-order "
                + "lag, time constant τ = m·c/(h·A) of each link), %s; leave-one-pose-out error %.1f against %.1f with the links at "
                + "the reading's temperature. Time constants tried: %s s; record temperatures on the arm's links to measure them",
                which, s.press(), s.pressNone(), String.join(", ", Arrays.stream(ThermalLag.TAUS).skip(1)
                        .mapToObj(x -> String.format(Locale.ROOT, "%.0f", x)).toList()));
    }

    /**
     * The instrument's errors of the stepwise search, where the positions are measured in its frame
     * (points, not distances): its distances scaling with time and with temperature
     * ({@link Effect#instrumentScale}, over the readings of the whole file, where the reading is known
     * on every pose), and its axes out of square, with and without its ways bowed
     * ({@link Effect#instrumentAxes}, {@link Effect#instrumentAxesBowed}).
     */
    static List<Effect> instrumentForms(CalibrationResult geo, List<Measurement> history, boolean hasTime, boolean hasTemp) {
        List<Effect> out = new ArrayList<>();
        if (geo.instrumentTbase() == null || geo.pairs() || geo.distance()) return out;
        for (Effect.Along a : new Effect.Along[] {Effect.Along.TIME, Effect.Along.TEMPERATURE}) {
            if (a == Effect.Along.TIME ? !hasTime : !hasTemp) continue;
            double[] r = readingRange(history, a);
            if (r[1] > r[0]) out.add(Effect.instrumentScale(a, geo.instrumentTbase(), r[0], r[1]));
        }
        out.add(Effect.instrumentAxes(geo.instrumentTbase()));
        out.add(Effect.instrumentAxesBowed(geo.instrumentTbase()));
        return out;
    }

    /** The lowest and highest time (s) or temperature (°C) read on {@code rows}, unknown readings left out (±∞ with none). */
    static double[] readingRange(List<Measurement> rows, Effect.Along a) {
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
        for (Measurement m : rows) {
            double u = a == Effect.Along.TIME ? m.timeS() : m.tempC();
            if (Double.isFinite(u)) { lo = Math.min(lo, u); hi = Math.max(hi, u); }
        }
        return new double[] {lo, hi};
    }

    /** Families whose claim rests on a shape in a joint angle, the gravity torque, time or temperature: they must beat the fallbacks. */
    private static boolean checkedAgainstFallbacks(Effect e) {
        return switch (e.kind()) {
            case PERIODIC, SCALE, COUPLING, COMPLIANCE, THERMAL, THERMAL_LINK, DRIFT -> true;
            default -> false;
        };
    }

    /**
     * The rivals of a named compliance {@code e}, or of a growth or a drift with temperature or time
     * beside a named compliance, that let the joint's give change through the campaign
     * ({@link Effect#complianceVarying}): with temperature (where it varies by 0.5 K or more), with
     * time, and the payload's share of the torque alone with time where a payload is recorded (a
     * carried mass that changes, at the resolutions of a drift in time the poses support). For a
     * compliance, its own joint; for the others, each joint with a compliance in {@code selected},
     * or with none, each joint the arm's weight loads (the whole torque's give with temperature only,
     * the payload's share with time).
     */
    static List<Effect> varyingCompliances(Effect e, List<Effect> selected, Work w) {
        Map<Integer, GravityTorques> joints = new java.util.TreeMap<>();
        double[] temp = tempSpan(w.conditions), span = timeSpan(w.conditions);
        boolean withTime = true, payload = w.conditions.stream().anyMatch(c -> c.payloadKg() > 0);
        switch (e.kind()) {
            case COMPLIANCE -> joints.put(e.joint(), e.gravity());
            case THERMAL, THERMAL_LINK, DRIFT -> {
                for (Effect x : selected) if (x.kind() == Effect.Kind.COMPLIANCE) joints.put(x.joint(), x.gravity());
                // with no compliance named, each joint the arm's weight loads (a curve of its angle may hold its static give), its
                // whole give with the temperature read only (with time a growth's warm-up and a joint's give that changes with time
                // are too alike to take one for the other on a claim's held-out error), and a recorded payload's share with time
                if (joints.isEmpty() && w.gravity != null && (temp != null || payload && span != null)) {
                    for (int j = 0; j < w.model.dof(); j++) if (loaded(w.gravity, j, w.rows)) joints.put(j, w.gravity);
                    withTime = false;
                }
            }
            default -> { }
        }
        if (joints.isEmpty()) return List.of();
        boolean wholeWithTime = withTime;
        double[] time = span;
        List<Effect> out = new ArrayList<>();
        joints.forEach((j, g) -> {
            int nb = g.massesUnknown() ? 2 : Effect.POINT_BASIS;
            if (temp != null) out.add(Effect.complianceVarying(j, g, Effect.Along.TEMPERATURE, temp[0], temp[1], nb, false));
            if (time == null) return;
            if (wholeWithTime) out.add(Effect.complianceVarying(j, g, Effect.Along.TIME, time[0], time[1], nb, false));
            // a recorded payload whose carried mass changes: its share of the torque following the time
            if (payload)
                for (int r : Effect.DRIFT_RESOLUTIONS)
                    if (r < Effect.DRIFT_RESOLUTIONS[Effect.DRIFT_RESOLUTIONS.length - 1] && Effect.supported(r, Effect.POINT_BASIS, w.rows.size()))
                        out.add(Effect.complianceVarying(j, g, Effect.Along.TIME, time[0], time[1], r, true));
        });
        return out;
    }

    /** The farthest a payload's centre estimated with its varying compliance may lie from where the file puts it, m. */
    static final double MAX_PAYLOAD_SHIFT_M = 0.5;

    /** Gravity torque (N·m) below which a joint counts as not loaded by the arm's weight over the poses. */
    static final double LOADED_NM = 1;

    /** Whether the arm's weight loads drive {@code j} at some pose of {@code rows} by more than {@link #LOADED_NM}. */
    static boolean loaded(GravityTorques g, int j, List<Measurement> rows) {
        double[] t = new double[g.massCount()];
        for (Measurement r : rows) {
            double p = Double.isFinite(r.payloadKg()) ? r.payloadKg() : 0;
            if (g.massesUnknown()) {
                g.driveTorquesByMass(r.q(), p, j, t);
                for (double x : t) if (Math.abs(x) > LOADED_NM) return true;
            } else if (Math.abs(g.driveTorques(r.q(), p)[j]) > LOADED_NM) return true;
        }
        return false;
    }

    /** The lowest and highest temperature of the poses' conditions, or null unless they span 0.5 K or more. */
    static double[] tempSpan(List<PoseConditions> conditions) {
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
        for (PoseConditions c : conditions) if (Double.isFinite(c.tempC())) { lo = Math.min(lo, c.tempC()); hi = Math.max(hi, c.tempC()); }
        return hi - lo >= 0.5 ? new double[] {lo, hi} : null;
    }

    /**
     * The rivals of a named transmission error {@code e} whose size follows the gravity torque on its
     * joint ({@link Effect#loadPeriodic}): with the torque's sign and with its size. The torque is the
     * robot file's masses', or without them an estimate from the link lengths; its reference the
     * largest on the rows. None for a shaft's orders, or where the joint bears no torque.
     */
    static List<Effect> loadPeriodics(Effect e, GravityTorques gravity, List<Measurement> rows, KinematicModel model) {
        if (e.kind() != Effect.Kind.PERIODIC || e.shaftOrders() || gravity == null || rows.isEmpty()) return List.of();
        GravityTorques g = gravity.massesUnknown() ? GravityTorques.fromLengths(model) : gravity;
        double ref = 0;
        for (Measurement r : rows)
            ref = Math.max(ref, Math.abs(g.driveTorques(r.q(), Double.isFinite(r.payloadKg()) ? r.payloadKg() : 0)[e.joint()]));
        if (!(ref > 0) || Double.isInfinite(ref)) return List.of();
        return List.of(Effect.loadPeriodic(e, g, ref, false), Effect.loadPeriodic(e, g, ref, true));
    }

    /**
     * The rival of a named transmission error {@code e} whose size changes with the temperature
     * ({@link Effect#periodicWarming}) at its whole orders, over the poses' temperatures; none without
     * a temperature that changes, or for a shaft's orders.
     */
    static List<Effect> warmPeriodics(Effect e, List<PoseConditions> conditions) {
        double[] span = tempSpan(conditions);
        if (e.kind() != Effect.Kind.PERIODIC || e.shaftOrders() || e.harmonics().length == 0 || span == null) return List.of();
        return List.of(Effect.periodicWarming(e.joint(), e.harmonics(), span[0], span[1]));
    }

    /** Whether a coupling matrix row is joint k's own value alone (θ_k = q_k). */
    private static boolean isUnitRow(double[] row, int k) {
        for (int l = 0; l < row.length; l++) if (row[l] != (l == k ? 1 : 0)) return false;
        return true;
    }

    /**
     * The generic fallbacks of the variables a family explains: a per-joint smooth spline (at every
     * resolution the poses support) for a one-joint angle family, and for a scale error of joint j
     * also the two-joint fallback of j with every other joint that moves; for a coupling j←k the
     * two-joint fallback, a smooth curve of q_k on drive j, and, where {@code model}'s linkage couples joint k, a
     * smooth curve of its model angle θ_k. Thermal growth and drift have none of their own (growth
     * follows the arm's links; the point moving with time or temperature in any shape is what a drift
     * is); they must beat the located ones that are not the point's own displacement.
     */
    static List<Effect> ownFallbacks(Effect e, List<Measurement> rows, KinematicModel model) {
        List<Effect> out = new ArrayList<>();
        int j = e.joint(), k = e.source();
        switch (e.kind()) {
            case PERIODIC -> smoothCurves(out, rows, q -> q[j], (lo, hi, nb) -> Effect.smooth(j, lo, hi, nb));
            case SCALE -> {
                smoothCurves(out, rows, q -> q[j], (lo, hi, nb) -> Effect.smooth(j, lo, hi, nb));
                // a scale that changes with another joint's angle (a hose twisted by j, stiffer as k bends): the two-joint
                // fallback nests the scale and holds that change, which no function of j alone does
                for (int o = 0; o < (rows.isEmpty() ? 0 : rows.get(0).q().length); o++)
                    if (o != j && (model == null || !model.isPrismatic(o)) && moves(rows, o)) out.add(Effect.pair(j, o));
            }
            case DRIFT -> {
                // the base or the instrument turning as well as moving with the same reading (a floor or a stand that tilts)
                Effect.Along a = e.usesTimeProxy() ? Effect.Along.TIME : Effect.Along.TEMPERATURE;
                double[] r = readingRange(rows, a);
                if (r[1] > r[0]) out.add(Effect.baseTurn(a, r[0], r[1]));
            }
            case COUPLING -> {
                out.add(Effect.pair(j, k));
                // a pull that follows the source's angle but not in proportion (a cable tightening as it winds up)
                smoothCurves(out, rows, q -> q[k], (lo, hi, nb) -> Effect.smoothFollowing(j, k, lo, hi, nb));
                // on a linkage, the source joint's own angle in the arm (θ3 = q3 − q2 on a parallel arm)
                if (model != null && !isUnitRow(model.couplingMatrix()[k], k))
                    smoothCurves(out, rows, Effect.smoothFollowingModelAngle(j, k, model, 0, 1, Effect.SMOOTH_BASIS)::smoothVariable,
                            (lo, hi, nb) -> Effect.smoothFollowingModelAngle(j, k, model, lo, hi, nb));
            }
            default -> { }
        }
        return out;
    }

    /**
     * A smooth error of drive j following its own model angle θ_j over the poses' range, when
     * {@code model}'s linkage makes θ_j of q_j and q_other; null otherwise.
     */
    static Effect ownModelAngleSmooth(int j, int other, KinematicModel model, List<Measurement> rows) {
        double[] row = model.couplingMatrix()[j];
        if (isUnitRow(row, j) || row[other] == 0) return null;
        Effect angle = Effect.smoothFollowingModelAngle(j, j, model, 0, 1, Effect.SMOOTH_BASIS);
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
        for (Measurement r : rows) {
            double th = angle.smoothVariable(r.q());
            lo = Math.min(lo, th);
            hi = Math.max(hi, th);
        }
        return hi > lo ? Effect.smoothFollowingModelAngle(j, j, model, lo, hi, Effect.SMOOTH_BASIS) : null;
    }

    /** Whether joint {@code j} takes more than one value over the poses. */
    private static boolean moves(List<Measurement> rows, int j) {
        for (Measurement r : rows) if (Math.abs(r.q()[j] - rows.get(0).q()[j]) > 1e-6) return true;
        return false;
    }

    /** A smooth curve over [lo, hi] with nb functions. */
    private interface SmoothOf { Effect at(double lo, double hi, int nb); }

    /** The smooth curves of {@code variable} at every resolution the poses support, over its sampled range (none when it does not vary). */
    private static void smoothCurves(List<Effect> out, List<Measurement> rows, java.util.function.ToDoubleFunction<double[]> variable, SmoothOf make) {
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
        for (Measurement r : rows) {
            double v = variable.applyAsDouble(r.q());
            lo = Math.min(lo, v);
            hi = Math.max(hi, v);
        }
        if (hi > lo)
            for (int nb : Effect.SMOOTH_RESOLUTIONS)
                if (Effect.supported(nb, Effect.SMOOTH_BASIS, rows.size())) out.add(make.at(lo, hi, nb));
    }

    /**
     * Without payload steps a drive's gravity torque is a function of the arm's pose alone, and on
     * a parallel-linkage arm a low-harmonic function of the drive's own angle: a compliance with
     * the arm's masses unknown and a transmission error of one cycle per turn can then be near
     * exact aliases. A named transmission error whose place that compliance (every link's mass and
     * centre unknown, {@link GravityTorques#massesUnknown}) takes predicting left-out poses as well
     * (within {@link #ALIAS_MARGIN}) is not claimed: neither is named as physics, the joint's smooth
     * fallback models the shape where it holds on held-out data, and the report says to measure
     * with payload steps, which separate the two.
     */
    private static Fit gravityAliases(Work w, Fit fit, List<Effect> selected, Map<Effect, boolean[]> absorbedCols, List<Step> steps,
                                      KinematicModel model, List<Measurement> rows, List<String> notes) {
        double pLo = Double.POSITIVE_INFINITY, pHi = Double.NEGATIVE_INFINITY;
        for (Measurement r : rows) {
            double p = Double.isFinite(r.payloadKg()) ? r.payloadKg() : 0;
            pLo = Math.min(pLo, p);
            pHi = Math.max(pHi, p);
        }
        if (pHi - pLo >= Effect.MIN_PAYLOAD_SPAN_KG) return fit;
        GravityTorques unknown = GravityTorques.massesUnknown(model);
        for (int k = 0; k < selected.size(); k++) {
            Effect e = selected.get(k);
            if (e.kind() != Effect.Kind.PERIODIC) continue;
            Tester at = w.tester(fit);
            double own = at.pressFull(), grav = at.pressReplacing(k, Effect.complianceRemassed(e.joint(), unknown), w.conditions);
            LOG.debug("gravity alias of {}: press own {} compliance (masses unknown) {}", e.label(), own, grav);
            if (!(grav <= own * (1 + ALIAS_MARGIN))) continue;
            int j = e.joint();
            double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
            for (Measurement r : rows) { lo = Math.min(lo, r.q(j)); hi = Math.max(hi, r.q(j)); }
            int before = selected.size();
            fit = replaceEffect(w, fit, selected, absorbedCols, steps, k, hi > lo ? Effect.smooth(j, lo, hi) : null, true);
            notes.add(String.format(Locale.ROOT, "%s is not claimed: joint %d giving way under the arm's own weight (a compliance, "
                    + "with the masses unknown) predicts left-out poses as well (leave-one-pose-out error %.1f against %.1f); "
                    + "without payload steps a transmission error of one cycle per turn and a deflection under gravity cannot "
                    + "be told apart on these poses%s", e.label(), j + 1, grav, own, selected.size() == before
                    ? ", so the joint's smooth fallback models the shape instead" : ", and nothing models it"));
            k = -1;
        }
        return fit;
    }

    /**
     * Fallbacks the stepwise search does not choose, though they are tested with the families: a
     * drive's error following two joints and a step of a joint's reading take a gear's or a coupling's
     * place before that family is tried (a two-joint error holds a coupling and a scale error, a few
     * steps follow any curve). They enter in a withdrawn family's place, beside what it left, or when
     * nothing else models what the geometric fit left.
     */
    static boolean inPlaceOnly(Effect e) { return e.kind() == Effect.Kind.PAIR || e.kind() == Effect.Kind.ANGLE_STEP; }

    /** Shares of the poses left free (gravity torque below the holding torque) tried for a backlash held by gravity. */
    static final double[] HELD_FREE_SHARES = {0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.35, 0.4, 0.45, 0.5, 0.55, 0.6, 0.7, 0.8};
    /** Half-widths of the hand-over between free and held tried, a share of the holding torque (0: sharp). */
    static final double[] HELD_WIDTHS = {0, 0.25, 0.5};
    /** Factors of a file mass tried when re-estimating the masses of a backlash held by gravity. */
    static final double[] HELD_MASS_SCALES = {0.6, 0.7, 0.8, 0.9, 1.0, 1.1, 1.2, 1.3, 1.4};
    /**
     * The same for masses estimated from the link lengths ({@link GravityTorques#fromLengths}), which
     * may be off by several times (a forearm's wrist motors sit behind its axis, not along it).
     */
    static final double[] HELD_LENGTH_MASS_SCALES = {0.25, 0.35, 0.5, 0.7, 1.0, 1.4, 2.0, 2.8, 4.0};

    /** The holding torque that leaves {@code share} of the poses (|τ| given) free: halfway between two poses' torques. */
    static double heldTorqueAt(double[] absTau, double share) {
        double[] sorted = absTau.clone();
        Arrays.sort(sorted);
        int at = (int) Math.floor(share * (sorted.length - 1));
        return at + 1 < sorted.length ? 0.5 * (sorted[at] + sorted[at + 1]) : sorted[at];
    }

    /**
     * Leave-one-pose-out error with a backlash held by gravity of joint {@code j} in the place of
     * selected effect {@code k}: masses scaled by {@code scales} (null: the file's), holding torque
     * leaving {@code share} of the poses free, hand-over half-width {@code width}.
     */
    private static double heldPress(Tester t, int k, int j, GravityTorques gravity, double[] scales, double share, double width,
                                    List<Measurement> rows, List<PoseConditions> conds) {
        double nm = heldTorqueAt(heldTorques(gravity, scales, rows, j), share);
        if (!(nm > 0)) return Double.POSITIVE_INFINITY;
        return t.pressReplacing(k, Effect.heldByGravity(j, gravity, nm, width, scales), conds);
    }

    /** |τ| of drive {@code j} at every row, the masses scaled by {@code scales} (null: as given). */
    private static double[] heldTorques(GravityTorques gravity, double[] scales, List<Measurement> rows, int j) {
        GravityTorques g = scales == null ? gravity : gravity.withMassScales(scales);
        double[] tau = new double[rows.size()];
        for (int i = 0; i < tau.length; i++) tau[i] = Math.abs(g.driveTorques(rows.get(i).q(), rows.get(i).payloadKg())[j]);
        return tau;
    }

    /**
     * Whether the gravity torque on drive {@code j} (the file's masses, the rows' payloads) changes
     * sign near the reading step at {@code atRad}: among the poses within a tenth of the joint's
     * sampled range either side of it, at least a fifth push each way (a gear held by gravity
     * changes flank where the torque changes sign, and with a free zone about it the step is
     * placed at one of the zone's edges).
     */
    static boolean gravityChangesSignNear(GravityTorques gravity, List<Measurement> rows, int j, double atRad) {
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
        for (Measurement r : rows) { lo = Math.min(lo, r.q(j)); hi = Math.max(hi, r.q(j)); }
        double band = 0.1 * (hi - lo);
        int pos = 0, neg = 0;
        for (Measurement r : rows) {
            if (Math.abs(r.q(j) - atRad) > band) continue;
            double tau = gravity.driveTorques(r.q(), Double.isFinite(r.payloadKg()) ? r.payloadKg() : 0)[j];
            if (tau > 0) pos++;
            else if (tau < 0) neg++;
        }
        return Math.min(pos, neg) >= 0.2 * (pos + neg) && pos + neg > 0;
    }

    /**
     * Backlash held on one flank by gravity ({@link Effect#heldByGravity}): where the gravity torque
     * on a joint is large its gear sits on the flank the torque pushes it to whatever the last
     * motion, and only where the torque is small does the direction decide. Fitted as plain
     * backlash that form leaves a step with the sign of the torque, which a compliance of the same
     * joint (a deflection proportional to the torque) takes in part, so the pair "compliance +
     * backlash" is named for what is one lost motion. For each joint with a constant backlash
     * named (and the robot file's masses known), the held form with the holding torque that
     * predicts left-out poses best (a grid of torque quantiles) is put in the place of the backlash
     * and of the same joint's compliance together. It takes their place when its leave-one-pose-out
     * error is lower by {@link #ALIAS_MARGIN} (and the validation error too, when given); within
     * the margin of a named compliance + backlash the data cannot tell the two apart: the held
     * form (one effect, one play) is named, and the notes say so and what to measure.
     */
    private static Fit heldByGravity(Work w, Fit fit, List<Effect> selected, Map<Effect, boolean[]> absorbedCols, List<Step> steps,
                                     GravityTorques fileGravity, List<Measurement> rows, List<String> notes, List<String> recs) {
        if (fileGravity == null) return fit;
        // without the file's masses, where the arm's weight acts is estimated from its lengths (the holding torque's size
        // is then only that estimate's; which flank, and where the hand-over lies, is re-estimated from the data)
        GravityTorques gravity = fileGravity.massesUnknown() ? GravityTorques.fromLengths(w.model) : fileGravity;
        for (int j = 0; j < w.model.dof(); j++) {
            final int jj = j;
            // (a lost motion that builds up over the move may stand in for it: the wind-up's shorter lags after short
            // moves take up part of what the held flank leaves)
            Effect plain = selected.stream().filter(e -> e.kind() == Effect.Kind.BACKLASH && e.joint() == jj
                    && !e.heldByGravity()).findFirst().orElse(null);
            // A gear held by gravity with a narrow free zone is a step of the joint's reading where the torque on it
            // changes sign (the flank changes there, whatever the last motion): a located step of its reading stands in
            // for the backlash the stepwise search did not name.
            if (plain == null) plain = selected.stream().filter(e -> e.kind() == Effect.Kind.ANGLE_STEP && e.joint() == jj && !e.isWindow()
                    && gravityChangesSignNear(gravity, rows, jj, e.rangeLo())).findFirst().orElse(null);
            if (plain == null) continue;
            Effect comp = selected.stream().filter(e -> e.kind() == Effect.Kind.COMPLIANCE && e.joint() == jj).findFirst().orElse(null);
            Selection saved = Selection.of(selected, absorbedCols, steps);
            double own = w.tester(fit).pressFull(), ownVal = w.validateError(fit);
            double thr = steps.get(selected.indexOf(plain)).candidate.threshold;
            Fit base = comp == null ? fit : dropAndRefit(w, fit, selected, absorbedCols, steps, selected.indexOf(comp));
            Tester bt = w.tester(base);
            int k = selected.indexOf(plain);
            // the holding torque as a share of the poses left free, the hand-over's width, then the masses that bear on the joint
            double[] best = {Double.POSITIVE_INFINITY, HELD_FREE_SHARES[0], 0}; // press, share, width
            double[] scales = null;
            for (int wi = 0; wi < HELD_WIDTHS.length; wi++) {
                double[] bw = {Double.POSITIVE_INFINITY, 0, HELD_WIDTHS[wi]};
                for (double share : HELD_FREE_SHARES) {
                    double pr = heldPress(bt, k, j, gravity, null, share, HELD_WIDTHS[wi], rows, w.conditions);
                    if (pr < bw[0]) { bw[0] = pr; bw[1] = share; }
                }
                // the sharpest hand-over unless a gradual one predicts left-out poses clearly better
                if (wi == 0 || bw[0] < best[0] * (1 - ALIAS_MARGIN)) best = bw;
            }
            if (Double.isFinite(best[0])) {
                // Each mass that bears on the joint scaled in turn (the data sheet's masses are rarely better than ±30 %);
                // re-estimated masses are kept only when they predict left-out poses clearly better than the file's.
                double[] sc = new double[gravity.massCount()];
                Arrays.fill(sc, 1);
                boolean[] bears = new boolean[sc.length]; // masses whose weight reaches the joint on some pose
                double[] byMass = new double[sc.length];
                for (Measurement r : rows) {
                    gravity.driveTorquesByMass(r.q(), r.payloadKg(), j, byMass);
                    for (int m = 0; m < sc.length; m++) bears[m] |= byMass[m] != 0;
                }
                double pr0 = best[0], pr = pr0;
                for (int round = 0; round < 2; round++)
                    for (int m = 0; m < sc.length; m++) {
                        if (m == gravity.payloadIndex() || gravity.massKg(m) == 0 || !bears[m]) continue;
                        double keep = sc[m];
                        double bestF = keep;
                        for (double f : gravity.fromLengths() ? HELD_LENGTH_MASS_SCALES : HELD_MASS_SCALES) {
                            sc[m] = f;
                            double p = heldPress(bt, k, j, gravity, sc, best[1], best[2], rows, w.conditions);
                            if (p < pr) { pr = p; bestF = f; }
                        }
                        sc[m] = bestF;
                    }
                if (pr < pr0 * (1 - ALIAS_MARGIN)) {
                    scales = sc;
                    for (double share : HELD_FREE_SHARES) { // the holding torque again, with the masses re-estimated
                        double p = heldPress(bt, k, j, gravity, sc, share, best[2], rows, w.conditions);
                        if (p < pr) { pr = p; best[1] = share; }
                    }
                    best[0] = pr;
                }
            }
            double bestPress = best[0], bestWidth = best[2];
            double[] tau = heldTorques(gravity, scales, rows, j);
            double bestNm = heldTorqueAt(tau, best[1]);
            LOG.debug("held by gravity j{}: above {} N·m ± {}, masses {}: PRESS {} against {}", j + 1, bestNm, bestWidth,
                    scales == null ? "file" : Arrays.toString(scales), bestPress, own);
            if (!Double.isFinite(bestNm) || !(bestNm > 0) || !(bestPress < own * (1 + ALIAS_MARGIN)) || comp == null && !(bestPress < own * (1 - ALIAS_MARGIN))) {
                saved.restore(selected, absorbedCols, steps);
                continue;
            }
            Effect held = Effect.heldByGravity(j, gravity, bestNm, bestWidth, scales);
            Fit f = replaceEffect(w, base, selected, absorbedCols, steps, k, held, false);
            double pressHeld = w.tester(f).pressFull();
            boolean valWorse = w.hasValidation() && !(w.validateError(f) < ownVal * (1 + ALIAS_MARGIN));
            if (!selected.contains(held) || valWorse || !(pressHeld < own * (1 + ALIAS_MARGIN))) {
                saved.restore(selected, absorbedCols, steps);
                continue;
            }
            steps.get(selected.indexOf(held)).candidate.threshold = thr;
            double free = 0;
            for (double t : tau) if (t < bestNm) free++;
            String was = comp == null ? plain.label() : comp.label() + " and " + plain.label();
            if (pressHeld < own * (1 - ALIAS_MARGIN))
                notes.add(String.format(Locale.ROOT, "%s %s replaced by %s: joint %d's lost motion shows only where the gravity "
                        + "torque on it is below %.1f N·m (%.0f %% of the poses); elsewhere gravity holds the gear on one flank. "
                        + "It predicts left-out poses better (leave-one-pose-out error %.1f against %.1f)", was,
                        comp == null ? "was" : "were", held.label(), j + 1, bestNm, 100 * free / tau.length, pressHeld, own));
            else {
                notes.add(String.format(Locale.ROOT, "%s cannot be told from %s on these poses (leave-one-pose-out error %.1f "
                        + "against %.1f): a gear held on one flank by gravity leaves a step with the sign of the torque, which a "
                        + "deflection proportional to the torque mimics. One lost motion is named, not a compliance beside it",
                        held.label(), was, pressHeld, own));
                recs.add(String.format(Locale.ROOT, "To tell joint %d's backlash held by gravity from a compliance beside it, "
                        + "measure some poses where the gravity torque on joint %d is large with two or three payloads (record "
                        + "payload_kg): a compliance moves with the load, a gear held on one flank does not.", j + 1, j + 1));
            }
            fit = f;
            // What the stepwise search added on the same drive to take up the misfit of the wrong form (harmonics of its
            // angle, a scale error) leaves when it no longer lowers the leave-one-pose-out error or is no longer significant.
            for (boolean again = true; again; ) {
                again = false;
                Tester ft = w.tester(fit);
                double full = ft.pressFull();
                for (int i = 0; i < selected.size() && !again; i++) {
                    Effect o = selected.get(i);
                    if (o == held || o.isFallback() && o.kind() != Effect.Kind.ANGLE_STEP || o.joint() != j || o.target() != Effect.Target.DRIVE) continue;
                    double without = ft.pressReplacing(i, null, w.conditions);
                    double[] pv = new double[1];
                    boolean weak = w.weakest(fit, selected, thr, x -> x == o, pv) >= 0;
                    if (!weak && without > full * (1 + ALIAS_MARGIN)) continue;
                    notes.add(String.format(Locale.ROOT, "%s is not claimed: beside %s it no longer lowers the leave-one-pose-out "
                            + "error clearly (%.1f without it against %.1f) or is no longer significant", o.label(), held.label(), without, full));
                    fit = dropAndRefit(w, fit, selected, absorbedCols, steps, i);
                    restampLast(w, fit, steps);
                    again = true;
                }
            }
        }
        return fit;
    }

    /**
     * Several families on one joint's angle (harmonic sets, a scale error) can together mimic a
     * shape located on that angle that none of them holds alone (a step of the reading: a Fourier
     * series of it), and each then beats that shape's fallback when judged one at a time. Where two
     * or more families share a joint's angle, the located fallbacks of that angle (a step of the
     * reading, a smooth curve) are put in the place of all of them together; one that predicts
     * left-out poses better (and, with validation poses, those too) takes their place, and the notes
     * say so.
     */
    private static Fit jointContest(Work w, Fit fit, List<Effect> selected, Map<Effect, boolean[]> absorbedCols, List<Step> steps,
                                    java.util.Collection<Effect> rivals, List<String> notes) {
        for (int j = 0; j < w.model.dof(); j++) {
            final int jj = j;
            List<Effect> fams = selected.stream().filter(e -> !e.isFallback() && e.joint() == jj
                    && (e.kind() == Effect.Kind.PERIODIC || e.kind() == Effect.Kind.SCALE)).toList();
            if (fams.size() < 2) continue;
            List<Effect> eligible = rivals.stream().filter(r -> r.joint() == jj && r.angleJoint() == jj
                    && (r.kind() == Effect.Kind.ANGLE_STEP || r.kind() == Effect.Kind.SMOOTH)
                    && selected.stream().noneMatch(x -> x.label().equals(r.label()))).toList();
            if (eligible.isEmpty()) continue;
            double own = w.tester(fit).pressFull(), ownVal = w.validateError(fit);
            boolean hasVal = w.hasValidation();
            Selection saved = Selection.of(selected, absorbedCols, steps);
            double thr = steps.get(selected.indexOf(fams.get(0))).candidate.threshold;
            // The joint's families taken out once: the model every rival is tested on and added to.
            Fit f = fit;
            for (Effect e : fams) f = dropAndRefit(w, f, selected, absorbedCols, steps, selected.indexOf(e));
            Tester ft = w.tester(f);
            List<Effect> selF = new ArrayList<>(selected);
            Map<Effect, boolean[]> absF = new java.util.IdentityHashMap<>(absorbedCols);
            List<Step> stepsF = new ArrayList<>(steps);
            boolean taken = false;
            for (Effect r : eligible) {
                selected.clear();
                selected.addAll(selF);
                absorbedCols.clear();
                absorbedCols.putAll(absF);
                steps.clear();
                steps.addAll(stepsF);
                Candidate bc = ft.test(r, w.conditions);
                if (bc.keptColumns > 0 && bc.pressAfter < bc.pressBefore) {
                    selected.add(r);
                    absorbedCols.put(r, bc.absorbedMask);
                    Fit g = w.fit(selected, absorbedCols, f.full, bc);
                    double pr = w.tester(g).pressFull();
                    LOG.debug("joint contest j{}: {} against {} (PRESS {} -> {})", j + 1, r.label(), fams, own, pr);
                    if (pr < own && (!hasVal || w.validateError(g) < ownVal)) {
                        bc.threshold = thr;
                        steps.add(new Step(bc, g.trainRms, w.validateRms(g)));
                        notes.add(String.format(Locale.ROOT, "%s are not claimed: together they mimic a shape located on joint %d's "
                                + "angle, and %s in their place predicts left-out poses better (leave-one-pose-out error %.1f against %.1f)",
                                String.join(", ", fams.stream().map(Effect::label).toList()), j + 1, r.label(), pr, own));
                        fit = g;
                        taken = true;
                        break;
                    }
                }
            }
            if (!taken) {
                saved.restore(selected, absorbedCols, steps);
            }
        }
        return fit;
    }

    /**
     * Never a wrong claim: a physical family stays named only when (a) with it fitted, its own
     * variables' fallbacks find no significant structure left (Holm over them, and a smaller
     * leave-one-pose-out error), and (b) it predicts left-out poses better than every fallback put
     * in its place: its own variables' fallbacks and those of every structure located (per-joint
     * smooth, two-joint, reach or height). A family that fails is withdrawn; the best fallback takes
     * its place only when that lowers the held-out error (leave-one-pose-out, and validation when
     * given) — reported as an unexplained located structure, not as physics.
     */
    private static Fit claimCheck(Work w, Fit fit, List<Effect> selected, Map<Effect, boolean[]> absorbedCols, List<Step> steps,
                                  List<Effect> located, List<Effect> family, List<Measurement> rows, GravityTorques gravity,
                                  List<String> notes) {
        int refinements = 0;
        Set<String> withdrawn = new HashSet<>();
        List<Effect> instrument = null;               // the instrument's rivals, made when a family is first checked
        Map<String, Effect> tilts = new java.util.HashMap<>();  // each family's best base tilt, searched once
        for (int round = 0; round < 2 * MAX_LOCATED; round++) {
            boolean changed = false;
            for (int k = 0; k < selected.size() && !changed; k++) {
                Effect e = selected.get(k);
                if (!checkedAgainstFallbacks(e)) continue;
                Tester at = w.tester(fit);
                List<Effect> own = ownFallbacks(e, rows, w.model);
                own.addAll(loadPeriodics(e, gravity, rows, w.model));
                own.addAll(warmPeriodics(e, w.conditions));
                own.addAll(varyingCompliances(e, selected, w));
                Map<String, Effect> rivals = new LinkedHashMap<>();
                for (Effect f : own) rivals.put(f.label(), f);
                for (Effect f : located) rivals.putIfAbsent(f.label(), f);
                for (Effect f : readingSteps(e, fit, k, rows, w.conditions)) rivals.putIfAbsent(f.label(), f);
                if (instrument == null) instrument = instrumentRivals(at, w.conditions);
                for (Effect f : instrument) rivals.putIfAbsent(f.label(), f);
                Effect tilt = tilts.computeIfAbsent(e.label(), x -> bestBaseTilt(at, selected.indexOf(e), e, gravity, rows, w.conditions));
                if (tilt != null) rivals.putIfAbsent(tilt.label(), tilt);
                for (Effect s : selected) rivals.remove(s.label());
                // a fallback that holds part of the family's shape stands against it only for what it finds beside it
                // and, when the family explains nearly all it does, what it finds beside it is another structure, left to be located
                // (unless it nests the family: then what it finds is the family's own shape changing)
                Set<String> besideFamily = new HashSet<>();
                int fam = k;
                rivals.values().removeIf(f -> {
                    if (!f.holdsPartOf(e)) return false;
                    if (!significantBeside(at, f, w)) return true;
                    if (f.nests(e) || !mostlyFamily(at, fam, e, f, w)) return false;
                    besideFamily.add(f.label());
                    return true;
                });
                if (e.kind() == Effect.Kind.DRIFT)
                    rivals.values().removeIf(f -> f.kind() == Effect.Kind.POINT_SMOOTH
                            && (f.along() == Effect.Along.TIME || f.along() == Effect.Along.TEMPERATURE));
                double pressOwn = at.pressFull();
                Effect best = null;
                double bestPress = Double.POSITIVE_INFINITY;
                for (Effect f : rivals.values()) {
                    double pf = at.pressReplacing(k, f, w.conditions);
                    if (pf < bestPress) { bestPress = pf; best = f; }
                }
                String why = null;
                String local; // whether the family's joint error is one local bump, asked only when the checks before it pass
                double pressWithout = at.pressReplacing(k, null, null);
                if (LOG.isDebugEnabled())
                    LOG.debug(String.format(Locale.ROOT, "claim check %s: press own %.1f without %.1f best rival %s %.1f", e.label(),
                            pressOwn, pressWithout, best == null ? "-" : best.label(), bestPress)
                            + (e.kind() == Effect.Kind.PERIODIC ? ", turning points " + turningPoints(e, fit.effectValues(k), rows) : ""));
                if (!(pressOwn < pressWithout)) {
                    why = String.format(Locale.ROOT, "%s is not claimed: with the rest of the model it does not lower the "
                            + "leave-one-pose-out error (%.1f against %.1f without it)", e.label(), pressOwn, pressWithout);
                    best = null;
                } else if (e.kind() == Effect.Kind.COUPLING && !Effect.canCouple(w.model, e.joint(), e.source())) {
                    // searched as a shape of joint j's error following joint k, never physics: the fallback that predicts
                    // left-out poses best models it (its own, held part of the family's shape or not, or a located one)
                    for (Effect f : own) {
                        if (selected.stream().anyMatch(x -> x.label().equals(f.label()))) continue;
                        double pf = at.pressReplacing(k, f, w.conditions);
                        if (pf < bestPress) { bestPress = pf; best = f; }
                    }
                    why = String.format(Locale.ROOT, "%s is not claimed: joint %d's drive train does not pass joint %d (a drive is "
                            + "turned only by the joints between its motor and its own joint; a wrist's motors ride on the upper arm), "
                            + "so joint %d's angle has no path to it; the structure is an error of joint %d that follows joint %d",
                            e.label(), e.joint() + 1, e.source() + 1, e.source() + 1, e.joint() + 1, e.source() + 1);
                } else if (best != null && !(pressOwn < bestPress) && !nestedTie(best, own, pressOwn, bestPress)
                        || best != null && besideAnother(e, selected)
                        && nestedTie(best, own, pressOwn, bestPress) && pressOwn >= bestPress * (1 - ALIAS_MARGIN)
                        || best != null && !turnsOften(e, fit.effectValues(k), rows) && sharedWithAnotherDrive(e, selected, located, at, w)
                        && nestedTie(best, own, pressOwn, bestPress) && pressOwn >= bestPress * (1 - SHARED_MARGIN))
                    why = String.format(Locale.ROOT, "%s is not claimed: the located structure's own fallback %s predicts "
                            + "left-out poses as well or better (leave-one-pose-out error %.1f against %.1f)", e.label(), best.label(),
                            bestPress, pressOwn) + (e.kind() == Effect.Kind.COMPLIANCE && !payloadVaries(rows)
                            ? "; with one payload a deflection under the arm's own weight and an error of the joint's angle cannot "
                            + "be told apart on these poses: measure with two or three payloads to tell" : "");
                else if (best != null && e.kind() == Effect.Kind.DRIFT && best.kind() == Effect.Kind.REFRACTION
                        && pressOwn >= bestPress * (1 - ALIAS_MARGIN))
                    why = String.format(Locale.ROOT, "%s is not claimed: %s predicts left-out poses nearly as well (leave-one-pose-out "
                            + "error %.1f against %.1f: to be told apart, %.0f %% lower): seen from far, the instrument drifting and its "
                            + "beam bent by the air's changing temperature gradient move the points alike; record the air's temperature "
                            + "at two heights along the beam, or measure a fixed reference target now and then to tell",
                            e.label(), best.label(), pressOwn, bestPress, 100 * ALIAS_MARGIN);
                else if (best != null && best.isFallback() && periodicityUntested(e, rows)
                        && !turnsOften(e, fit.effectValues(k), rows)
                        && (pressOwn > bestPress * (1 - ALIAS_MARGIN) || tellsApart(at, k, best, w) < TELL_Z))
                    why = String.format(Locale.ROOT, "%s is not claimed: %s, a shape of no known physics, predicts left-out poses "
                            + "nearly as well (leave-one-pose-out error %.1f against %.1f: to be told apart, %.0f %% lower and by "
                            + "%.0f standard errors of the pose-by-pose difference), so these poses cannot tell the physics from a "
                            + "shape; %s", e.label(), best.label(), pressOwn, bestPress, 100 * ALIAS_MARGIN, TELL_Z, toTell(e));
                else if ((local = localized(e, fit, selected, rows)) != null) why = e.label() + " is not claimed: " + local;
                else {
                    double thr = w.o.alpha() / Math.max(1, own.size());
                    for (Effect f : own) {
                        if (selected.stream().anyMatch(s -> s.label().equals(f.label()))) continue;
                        if (besideFamily.contains(f.label())) continue;
                        Candidate c = at.test(f, w.conditions);
                        if (c.keptColumns == 0 || !(c.p < thr) || !(c.pressAfter < c.pressBefore)) continue;
                        // what it finds beside a family that explains nearly all it does in the family's place (or more) is
                        // another structure, left to be located: a gear's pin order the fallback's curve cannot follow, and a
                        // trace of the noise's in the same joint
                        if (!f.nests(e) && mostlyFamily(at, k, e, f, w)) continue;
                        why = String.format(Locale.ROOT, "%s is not claimed: with it fitted, %s still finds significant structure "
                                + "in the same variable (F = %.1f, p = %.2g), so the family does not explain what was located",
                                e.label(), f.label(), c.f, c.p);
                        double pf = at.pressReplacing(k, f, w.conditions);
                        if (best == null || pf < bestPress) { best = f; bestPress = pf; }
                        break;
                    }
                }
                if (why == null) continue;
                LOG.debug(why);
                withdrawn.add(e.label());
                if (best != null) {
                    // Another family of the same structure that predicts better than the fallback takes its place (and is checked in turn).
                    Effect alias = null;
                    double aliasPress = bestPress;
                    for (Effect a : aliases(e, family, selected)) {
                        if (withdrawn.contains(a.label()) || !checkedAgainstFallbacks(a)) continue;
                        double pa = at.pressReplacing(k, a, w.conditions);
                        if (pa < aliasPress) { aliasPress = pa; alias = a; }
                    }
                    if (alias != null) {
                        int before = selected.size();
                        fit = replaceEffect(w, fit, selected, absorbedCols, steps, k, alias, true);
                        notes.add(e.label() + " was replaced by " + alias.label() + ", which predicts left-out poses better than "
                                + "both it and the located structure's fallback" + (selected.size() == before ? "" : " (but did not hold on held-out data)"));
                        changed = true;
                        continue;
                    }
                }
                int before = selected.size();
                fit = replaceEffect(w, fit, selected, absorbedCols, steps, k, best, true);
                notes.add(why + (selected.size() == before ? "; " + best.label() + " models the structure instead (held-out error lower)"
                        : "; no fallback lowers the held-out error, so nothing models it"));
                changed = true;
            }
            if (!changed) break;
        }
        // A smooth fallback takes the resolution that predicts left-out poses best (a bump needs finer knots than a drift),
        // a zero step the time between two poses that does, a joint's curve or step the play taken up by gravity that does.
        for (int k = 0; k < selected.size(); k++) {
            Effect e = selected.get(k);
            List<Effect> variants = refinements(e, w, rows, selected);
            if (variants.isEmpty()) continue;
            Tester at = w.tester(fit);
            double pressOwn = at.pressFull();
            Effect best = null;
            double bestPress = pressOwn;
            // its own kind's variants first (a curve's resolution, a step's time); another shape only once they are settled
            for (boolean own : new boolean[] {true, false}) {
                for (Effect f : variants) {
                    if ((f.kind() == e.kind()) != own) continue;
                    // another shape the model holds already (a drift of the target beside one of its steps) is not made twice
                    if (!own && selected.stream().anyMatch(x -> x.kind() == f.kind() && x.joint() == f.joint())) continue;
                    if (secondForm(f, selected, e)) continue;
                    double pf = at.pressReplacing(k, f, w.conditions);
                    if (pf < bestPress) { bestPress = pf; best = f; }
                }
                if (best != null) break;
            }
            if (best == null) continue;
            int before = selected.size();
            Selection saved = Selection.of(selected, absorbedCols, steps);
            Fit refined = replaceEffect(w, fit, selected, absorbedCols, steps, k, best, true);
            // another shape in its place (a play taken up by gravity for a curve of the joint's angle) must not predict the
            // validation poses worse
            if (best.kind() != e.kind() && selected.contains(best) && w.hasValidation()
                    && !(w.validateError(refined) < w.validateError(fit) * (1 + ALIAS_MARGIN))) {
                LOG.debug("{} not in place of {}: validation error {} against {}", best.label(), e.label(), w.validateError(refined),
                        w.validateError(fit));
                saved.restore(selected, absorbedCols, steps);
                continue;
            }
            if (selected.size() < before) { // the finer curve did not hold on held-out data: keep the one fitted
                Candidate c = w.tester(refined).test(e, w.conditions);
                selected.add(e);
                absorbedCols.put(e, c.absorbedMask);
                refined = w.fit(selected, absorbedCols, refined.full, c.keptColumns > 0 ? c : null);
                steps.add(new Step(c, refined.trainRms, w.validateRms(refined)));
            }
            fit = refined;
            k = -1;
            if (++refinements > 2 * MAX_LOCATED) break;
        }
        fit = driftForSteps(w, fit, selected, absorbedCols, steps);
        fit = tuneCycles(w, fit, selected, absorbedCols, steps, rows);
        // A jump of the instrument's distances taken while a smooth change of them with the same time was held back (outside
        // its bounds then, taken later) must still hold beside the final model: at the threshold it was taken at, and with a
        // lower leave-one-pose-out error. A smooth drift the scale's spline does not quite follow is no broken beam.
        for (int k = selected.size() - 1; k >= 0; k--) {
            Effect e = selected.get(k);
            if (e.kind() != Effect.Kind.RANGE_STEP) continue;
            // nor is a change of the air along the beam (a smooth scale of the distances with time, of 4 or 7 functions) that
            // predicts left-out poses as well: the air is the commoner cause, and a jump must beat it
            Effect smooth = smoothRangeRival(w, fit, selected, k, rows);
            if (smooth != null) {
                fit = replaceEffect(w, fit, selected, absorbedCols, steps, k, selected.contains(smooth) ? null : smooth, true);
                notes.add(String.format(Locale.ROOT, "%s is not kept: %s predicts left-out poses as well, so the distances "
                        + "changed smoothly (the air along the beam), not at a broken beam", e.label(), smooth.label()));
                continue;
            }
            double threshold = steps.get(k).candidate.threshold;
            Fit without = w.refitWithout(fit, selected, absorbedCols, k);
            Candidate c = w.tester(without).test(e, w.conditions);
            if (c.keptColumns > 0 && c.p < threshold && c.pressAfter < c.pressBefore) continue;
            LOG.debug("{} does not hold beside the final model (p {} against {})", e.label(), c.p, threshold);
            drop(selected, absorbedCols, steps, k);
            fit = without;
            notes.add(String.format(Locale.ROOT, "%s is not kept: beside the rest of the model it is no longer significant (p = %.2g), "
                    + "so the distances changed smoothly, not at a broken beam", e.label(), c.p));
        }
        return fit;
    }

    /**
     * A named effect must still be needed in the model finally fitted: the fallbacks that took the
     * place of withdrawn families may carry the structure it was selected for, leaving it a share
     * of the noise that happens to lower the leave-one-pose-out error by a hair. Each named effect
     * is tested once more against the whole final model (its partial F-test at the backward
     * step's Holm threshold, and its physical plausibility); the weakest that fails leaves, until
     * every one passes.
     */
    private static Fit stillSignificant(Work w, Fit fit, List<Effect> selected, Map<Effect, boolean[]> absorbedCols,
                                        List<Step> steps, int familySize, List<String> notes) {
        return backward(w, fit, selected, absorbedCols, steps, familySize, e -> !e.isFallback(), (gone, p) -> String.format(Locale.ROOT,
                "%s is not claimed: in the final model, beside the structures located, it is no longer significant (p = %.2g against "
                + "the threshold %.2g) or no longer plausible", gone.label(), p[0], p[1]), notes);
    }

    /**
     * The instrument's axes out of square ({@link Effect#instrumentAxes}) are kept only where the
     * final model predicts left-out poses better with them by {@link #ALIAS_MARGIN}: a linear and
     * quadratic field of the instrument's coordinates takes a share of any structure the rest of the
     * model leaves (a world campaign with three joints' zeros drifting, none of the instrument's, had
     * it at 8-29 ppm, significant by its F-test, lowering that error by 1.7 %).
     */
    private static Fit instrumentAxesHeld(Work w, Fit fit, List<Effect> selected, Map<Effect, boolean[]> absorbedCols, List<Step> steps,
                                          List<String> notes) {
        for (int k = selected.size() - 1; k >= 0; k--) {
            Effect e = selected.get(k);
            if (e.kind() != Effect.Kind.INSTRUMENT_AXES) continue;
            Tester at = w.tester(fit);
            double own = at.pressFull(), without = at.pressReplacing(k, null, null);
            if (without > (1 + ALIAS_MARGIN) * own) continue;
            notes.add(String.format(Locale.ROOT, "%s is not kept: beside the rest of the model it lowers the leave-one-pose-out "
                    + "error by less than %.0f %% (%.1f against %.1f without it), too little to tell the instrument's axes from the "
                    + "rest of what is left", e.label(), 100 * ALIAS_MARGIN, own, without));
            fit = dropAndRefit(w, fit, selected, absorbedCols, steps, k);
            restampLast(w, fit, steps);
        }
        return fit;
    }

    /**
     * After {@code kept} took a richer form: the backward step of the stepwise selection once more
     * (partial F-test at its Holm threshold, and plausibility), over every other selected effect,
     * fallbacks included; the weakest that fails leaves, until every one passes.
     */
    private static Fit noLongerNeeded(Work w, Fit fit, List<Effect> selected, Map<Effect, boolean[]> absorbedCols, List<Step> steps,
                                      int familySize, Effect kept, List<String> notes) {
        return backward(w, fit, selected, absorbedCols, steps, familySize, e -> e != kept, (gone, p) -> String.format(Locale.ROOT,
                "%s left the model: beside %s it is no longer significant (p = %.2g against the threshold %.2g) or no longer plausible",
                gone.label(), kept.label(), p[0], p[1]), notes);
    }

    /**
     * The backward step over the selected effects {@code which} accepts, at the Holm threshold of the
     * family's size: the weakest that fails its partial F-test or its bounds leaves (said by
     * {@code note} from it and {p, threshold}), until every one passes.
     */
    private static Fit backward(Work w, Fit fit, List<Effect> selected, Map<Effect, boolean[]> absorbedCols, List<Step> steps,
                                int familySize, java.util.function.Predicate<Effect> which,
                                java.util.function.BiFunction<Effect, double[], String> note, List<String> notes) {
        while (selected.stream().anyMatch(which)) {
            double threshold = w.o.alpha() / Math.max(1, familySize - selected.size() + 1);
            double[] p = new double[1];
            int drop = w.weakest(fit, selected, threshold, which, p);
            if (drop < 0) break;
            Effect gone = selected.get(drop);
            LOG.debug("backward: dropped {} (p {})", gone.label(), p[0]);
            notes.add(note.apply(gone, new double[] {p[0], threshold}));
            fit = dropAndRefit(w, fit, selected, absorbedCols, steps, drop);
            restampLast(w, fit, steps);
        }
        return fit;
    }

    private static List<Effect> withoutOne(List<Effect> es, int k) {
        List<Effect> out = new ArrayList<>(es);
        out.remove(k);
        return out;
    }

    /** Takes selected effect {@code k} out of the selection: the effect, its absorbed columns and its step. */
    private static void drop(List<Effect> selected, Map<Effect, boolean[]> absorbedCols, List<Step> steps, int k) {
        absorbedCols.remove(selected.remove(k));
        steps.remove(k);
    }

    /**
     * A smooth scale of the instrument's distances with time (the air along the beam) that predicts
     * left-out poses as well as jump {@code k} of the distances, or better, in its place (or, when
     * one is already in the model, the model without the jump does): the best such, or null when the
     * jump beats every one. Its bounds are not asked: a scale spline's coefficients are poorly
     * determined on a campaign of a few hours, and the jump is a fallback too.
     */
    private static Effect smoothRangeRival(Work w, Fit fit, List<Effect> selected, int k, List<Measurement> rows) {
        Effect jump = selected.get(k);
        double[] t = w.conditions.stream().mapToDouble(PoseConditions::timeS).filter(Double::isFinite).toArray();
        if (t.length < 2) return null;
        double lo = Arrays.stream(t).min().getAsDouble(), hi = Arrays.stream(t).max().getAsDouble();
        if (!(hi > lo)) return null;
        Tester at = w.tester(fit);
        double own = at.pressFull(), best = own;
        Effect out = null;
        for (Effect s : selected) if (s.kind() == Effect.Kind.INSTRUMENT_SCALE && s.along() == Effect.Along.TIME) out = s;
        if (out != null) return at.pressReplacing(k, null, null) <= own ? out : null;
        List<Effect> rivals = new ArrayList<>();
        for (int nb : INSTRUMENT_SCALE_RESOLUTIONS)
            if (Effect.supported(nb, Effect.POINT_BASIS, rows.size()))
                rivals.add(Effect.instrumentScale(Effect.Along.TIME, jump.instrumentPose(), lo, hi, nb));
        for (Effect r : rivals) {
            double pr = at.pressReplacing(k, r, w.conditions);
            if (pr <= best) { best = pr; out = r; }
        }
        return out;
    }

    /**
     * The resolutions of a scale of the instrument's distances (functions of time or temperature):
     * a hall's air changes over tens of minutes (its heating's and its doors' cycles, the weather's
     * pressure), so seven functions follow a campaign of hours; a finer curve would follow the jumps
     * of a distance taken again at a broken beam instead.
     */
    static final int[] INSTRUMENT_SCALE_RESOLUTIONS = {Effect.POINT_BASIS, 7};

    /** Takes selected effect {@code k} out ({@link #drop}) and refits the rest from {@code fit}'s values. */
    private static Fit dropAndRefit(Work w, Fit fit, List<Effect> selected, Map<Effect, boolean[]> absorbedCols, List<Step> steps,
                                    int k) {
        Fit without = w.refitWithout(fit, selected, absorbedCols, k);
        drop(selected, absorbedCols, steps, k);
        return without;
    }

    /** The last step's RMS figures made those of {@code fit}, the model once an effect before it has left. */
    private static void restampLast(Work w, Fit fit, List<Step> steps) {
        if (steps.isEmpty()) return;
        Step last = steps.remove(steps.size() - 1);
        steps.add(new Step(last.candidate, fit.trainRms, w.validateRms(fit)));
    }

    /**
     * Whether the rival that predicts left-out poses as well is one of the family's own fallbacks
     * (a smooth curve of the same joint angle, which holds the family's simpler shape) and within
     * {@link #ALIAS_MARGIN} of it: then the two cannot be told apart by the held-out error, and the
     * simpler physical form is kept only if the fallback finds no significant structure it leaves
     * (the claim check's next test).
     */
    private static boolean nestedTie(Effect rival, List<Effect> own, double pressOwn, double pressRival) {
        return own.stream().anyMatch(f -> f.label().equals(rival.label())) && pressOwn <= pressRival * (1 + ALIAS_MARGIN);
    }

    /** The least order a pinion's change of the play is refined to, times per output turn ({@link StageScan#playOrder} finds it from 4). */
    static final double MIN_PINION_ORDER = 2;

    /** Whether lost motion {@code e}'s play changes once per turn only (an output gear's runout, no pinion's order). */
    static boolean onceOnly(Effect e) {
        double[] f = e.runoutOrders();
        return f.length == 1 && f[0] == 1;
    }

    /** The largest harmonic of a transmission error whose periodicity needs a sampled turn to be seen. */
    static final int LOW_HARMONIC = 3;
    /** A joint sampled over less than this share of a turn shows no repeat of a once-per-turn error. */
    static final double TURN_SHARE = 5.0 / 6;

    /**
     * Whether transmission error {@code e} holds only harmonics up to {@link #LOW_HARMONIC} of a joint
     * sampled over less than {@link #TURN_SHARE} of a turn: there its few sines and cosines are one
     * smooth curve among many, and nothing in the data shows them repeat (an error of the angle that
     * does not repeat, such as a deflection under a balancer's or a spring's torque, follows the same
     * curve). Such a claim must then beat the smooth shape clearly ({@link #TELL_Z}).
     */
    static boolean periodicityUntested(Effect e, List<Measurement> rows) {
        if (e.kind() != Effect.Kind.PERIODIC || e.stages().length > 0 || rows.isEmpty()) return false;
        for (int h : e.harmonics()) if (h > LOW_HARMONIC) return false;
        return spans(rows)[e.joint()] < TURN_SHARE * 2 * Math.PI;
    }

    /**
     * Turning points a fitted error of one joint's angle must show within the sampled range before
     * it is taken as a gear's repeating error though the range holds less than a turn. The torques
     * that follow one joint's angle without repeating turn the error at most twice over a joint's
     * range: an arm's weight about a joint, sin(q + φ) summed over links, is one sinusoid of q with
     * one period per turn (two turning points in 300°); a spring or gas-strut balancer's moment,
     * F(q)·r(q) with the stroke a smooth function of q, rises to one maximum and falls (Kolarski et
     * al., "Dynamic balancing of robots", Robotics and Autonomous Systems 11 (1993) 215; Arakelian,
     * "Gravity compensation in robotics", Advanced Robotics 30 (2016) 79); a cable or hose winding
     * with the joint pulls back monotonically. An error with three maxima and minima within the
     * range is none of them.
     */
    static final int REPEAT_TURNS = 3;

    /**
     * Whether transmission error {@code e} (fitted amplitudes {@code v}) turns at least
     * {@link #REPEAT_TURNS} times over the sampled range of its joint: a shape that no torque of a
     * weight, a spring, a cable or a dress pack across the joints gives.
     */
    static boolean turnsOften(Effect e, double[] v, List<Measurement> rows) {
        return e.kind() == Effect.Kind.PERIODIC && !rows.isEmpty() && turningPoints(e, v, rows) >= REPEAT_TURNS;
    }

    /**
     * The turning points of transmission error {@code e}, with fitted sine and cosine amplitudes
     * {@code v}, over the range of its joint's angle the poses sample: extrema whose rise or fall to
     * the next one is at least a fifth of the curve's whole range (a ripple smaller than that is no
     * turn of the shape).
     */
    static int turningPoints(Effect e, double[] v, List<Measurement> rows) {
        int j = e.joint();
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
        for (Measurement m : rows) { lo = Math.min(lo, m.q(j)); hi = Math.max(hi, m.q(j)); }
        int n = 2001;
        double[] y = new double[n];
        double min = Double.POSITIVE_INFINITY, max = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < n; i++) {
            double s = Plots.curve(e, v, Math.toDegrees(lo + (hi - lo) * i / (n - 1)));
            y[i] = s;
            min = Math.min(min, s);
            max = Math.max(max, s);
        }
        double band = (max - min) / 5;
        if (!(band > 0)) return 0;
        // zig-zag: a turn counts once the curve has gone back from its running extreme by the band
        int turns = 0, dir = 0;
        double ext = y[0];
        for (int i = 1; i < n; i++) {
            if (dir == 0) {
                if (Math.abs(y[i] - y[0]) >= band) { dir = y[i] > y[0] ? 1 : -1; ext = y[i]; }
            } else if (dir * (y[i] - ext) > 0) ext = y[i];
            else if (dir * (ext - y[i]) >= band) { turns++; dir = -dir; ext = y[i]; }
        }
        return turns;
    }

    /**
     * A family is told apart from the fallback that predicts left-out poses best only when its
     * leave-one-pose-out error is lower by {@link #ALIAS_MARGIN} of it and by this many standard
     * errors of the pose-by-pose difference: the first asks for a difference worth a claim (two
     * nearly equal fits differ by little but consistently), the second for one that is not a few
     * poses' doing.
     */
    static final double TELL_Z = 2;

    /**
     * How clearly selected family {@code k} predicts left-out poses better than fallback {@code f} in
     * its place: the sum over poses of the difference of their left-out squared errors, over its
     * standard error (√n times the differences' standard deviation). Two models that are not nested
     * are compared by the pose-by-pose differences of what they predict, not by their totals alone
     * (Vuong, "Likelihood ratio tests for model selection and non-nested hypotheses", Econometrica 57
     * (1989) 307; Diebold & Mariano, J. Business & Economic Statistics 13 (1995) 253): a total lower
     * by a hair may come from a few poses, as a smooth curve and a few harmonics of a joint's angle
     * follow a deflection of a joint over part of its turn alike.
     */
    static double tellsApart(Tester at, int k, Effect f, Work w) {
        double[] own = at.pressFullPerPose(), rival = at.pressReplacingPerPose(k, f, w.conditions);
        int n = own.length;
        if (n < 2) return Double.POSITIVE_INFINITY;
        double sum = 0;
        for (int i = 0; i < n; i++) sum += rival[i] - own[i];
        if (!Double.isFinite(sum)) return sum > 0 || Double.isNaN(sum) ? Double.POSITIVE_INFINITY : Double.NEGATIVE_INFINITY;
        double mean = sum / n, ss = 0;
        for (int i = 0; i < n; i++) { double d = rival[i] - own[i] - mean; ss += d * d; }
        double se = Math.sqrt(n * ss / (n - 1));
        double z = se > 0 ? sum / se : sum > 0 ? Double.POSITIVE_INFINITY : 0;
        LOG.debug("selected effect {} against {}: left-out errors {} standard errors apart", k, f.label(), z);
        return z;
    }

    /** What to measure so that a transmission error of a few harmonics can be told from a smooth error of its joint's angle. */
    static String toTell(Effect e) {
        return String.format(Locale.ROOT, "a gear's error repeats at every turn of joint %d, which these poses do not sample, and "
                + "a smooth error of its angle (a balancer's or a spring's torque, a cable's pull) follows the same curve: sample the "
                + "joint over a whole turn where its range allows, or measure the reducer's transmission error on the drive (an "
                + "encoder on the output side)", e.joint() + 1);
    }

    /**
     * A link's bending holds the part of its own joint's spring that the weight across the link drives
     * (δ = L·θ), and the two differ only in how far the link's far end moves for its turn (L·θ for the
     * spring, 2/3 to 3/4 of it for a beam; Gere &amp; Goodno, Mechanics of Materials, table G-1). Where a
     * spring of the joint, in the place of selected bending {@code k}, predicts left-out poses within
     * {@link #ALIAS_MARGIN} of it, the poses cannot tell which gives: returns the words that say so (and
     * adds a note), or null when the bending is told apart from every spring of its joint.
     */
    static String springAlike(Tester at, int k, Effect sag, List<Effect> family, List<Effect> selected, Work w, List<String> notes) {
        double own = at.pressFull(), best = Double.POSITIVE_INFINITY;
        Effect spring = null;
        for (Effect a : family) {
            if (a.kind() != Effect.Kind.COMPLIANCE || a.joint() != sag.joint() || selected.contains(a)) continue;
            double pa = at.pressReplacing(k, a, w.conditions);
            if (pa <= own * (1 + ALIAS_MARGIN) && pa < best) { best = pa; spring = a; }
        }
        if (spring == null) return null;
        notes.add(String.format(Locale.ROOT, "%s and %s predict left-out poses alike (leave-one-pose-out error %.1f against %.1f): "
                + "neither is claimed; the bending models what they share", sag.label(), spring.label(), own, best));
        return Words.springAlike(sag, spring, best, own, w.sixD);
    }

    /** The share of a joint's sampled range within which half of a local error lies, at most. */
    static final double LOCAL_SHARE = 0.1;

    /**
     * Whether named transmission error {@code k} (a sum of harmonics of its joint's angle) is part of
     * one local error rather than of one repeating over the turn: the joint's whole error in its own
     * angle as fitted (every transmission error, smooth curve and step of its reading on that joint)
     * has half of its variation about its mean over the joint's sampled range (the integral of its
     * square) within {@link #LOCAL_SHARE} of that range, away from both ends, and the transmission
     * errors in it have three harmonics or more. A gear's periodic error (an eccentric wheel, tooth
     * meshing, a cycloidal stage) repeats at every period of its harmonics, so no window shorter than
     * one period holds half of it over a range of several periods; harmonics fit one bump of a
     * joint's angle only by phasing many of them to add up there (alone or beside a second series or a
     * fallback), and the bump has local causes as likely as a gear (a cable or hose that pulls at one
     * angle, a dent in a bearing race). Returns the words of why the family is not claimed, or null.
     */
    static String localized(Effect e, Fit fit, List<Effect> selected, List<Measurement> rows) {
        if (e.kind() != Effect.Kind.PERIODIC || rows.isEmpty()) return null;
        int j = e.joint();
        List<Effect> terms = new ArrayList<>();
        List<double[]> values = new ArrayList<>();
        int harmonics = 0;
        double maxOrder = 1;
        for (int k = 0; k < selected.size(); k++) {
            Effect s = selected.get(k);
            if (s.joint() != j || s.target() != Effect.Target.DRIVE) continue;
            boolean own = s.kind() == Effect.Kind.PERIODIC
                    || s.kind() == Effect.Kind.SMOOTH && s.source() < 0 && !s.followsModelAngle() || s.kind() == Effect.Kind.ANGLE_STEP;
            if (!own) continue;
            terms.add(s);
            values.add(fit.effectValues(k));
            if (s.kind() == Effect.Kind.PERIODIC) {
                harmonics += s.orders().length;
                maxOrder = Math.max(maxOrder, Arrays.stream(s.orders()).max().orElse(1));
            }
        }
        if (harmonics < 3) return null;
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
        for (Measurement r : rows) { lo = Math.min(lo, r.q(j)); hi = Math.max(hi, r.q(j)); }
        if (!(hi > lo)) return null;
        // the joint's error on a grid fine enough for its highest harmonic (16 points a cycle, at least 1000)
        int n = (int) Math.min(20000, Math.max(1000, 16 * maxOrder * (hi - lo) / (2 * Math.PI)));
        double[] f = new double[n];
        double mean = 0;
        for (int i = 0; i < n; i++) {
            double qDeg = Math.toDegrees(lo + (hi - lo) * i / (n - 1)), y = 0;
            for (int t = 0; t < terms.size(); t++) y += Plots.curve(terms.get(t), values.get(t), qDeg);
            f[i] = y;
            mean += y / n;
        }
        double total = 0;
        for (int i = 0; i < n; i++) { f[i] = (f[i] - mean) * (f[i] - mean); total += f[i]; }
        if (!(total > 0)) return null;
        // the shortest run of grid points holding half of it
        int width = n + 1, from = 0;
        double in = 0;
        for (int a = 0, b = 0; b < n; b++) {
            in += f[b];
            while (in - f[a] >= 0.5 * total) in -= f[a++];
            if (in >= 0.5 * total && b - a + 1 < width) { width = b - a + 1; from = a; }
        }
        if (width > LOCAL_SHARE * n || from == 0 || from + width >= n) return null;
        double step = (hi - lo) / (n - 1), at = lo + (from + 0.5 * (width - 1)) * step;
        return String.format(Locale.ROOT, "joint %d's error in its angle as fitted%s adds up to one local error about %.1f deg "
                + "(half of it within %.1f deg of the %.0f deg sampled), not to an error that repeats over the turn as a gear's "
                + "meshing or eccentricity does; a local cause at that angle (a damaged tooth of the output wheel, a cable or hose "
                + "pulling there, a dent in a bearing race) fits it as well. To map it, measure more poses with joint %d within "
                + "%.0f deg of %.0f deg", j + 1, terms.size() > 1 ? " (" + String.join(", ", terms.stream().map(Effect::label).toList())
                + ")" : "", Math.toDegrees(at), Math.toDegrees(width * step), Math.toDegrees(hi - lo), j + 1,
                Math.toDegrees(2 * width * step), Math.toDegrees(at));
    }

    /**
     * The step and the window of a joint's reading nearest to what a named transmission error on that
     * joint fitted: least squares of the family's fitted error at the poses by a constant plus v times
     * the indicator of q_j above one place (a step) or between two places (a window), places midway
     * between neighbouring poses, at least two poses on each side. A reading that is off over one
     * window of the turn (an encoder's code track) is a Fourier series of many harmonics, which the
     * harmonic scan finds one by one; these shapes are then the rivals the claim check puts in the
     * family's place, and the held-out error decides. Empty for other families.
     */
    static List<Effect> readingSteps(Effect e, Fit fit, int k, List<Measurement> rows, List<PoseConditions> conds) {
        if (e.kind() != Effect.Kind.PERIODIC || rows.size() < 8) return List.of();
        int n = rows.size(), j = e.joint();
        double[] v = fit.effectValues(k);
        Integer[] order = new Integer[n];
        for (int i = 0; i < n; i++) order[i] = i;
        Arrays.sort(order, (a, b) -> Double.compare(rows.get(a).q(j), rows.get(b).q(j)));
        double[] q = new double[n], pre = new double[n + 1];
        for (int i = 0; i < n; i++) {
            q[i] = rows.get(order[i]).q(j);
            pre[i + 1] = pre[i] + e.valueAt(v, rows.get(order[i]), conds.get(order[i]));
        }
        // sum of squares a window [a, b) of the sorted poses explains about the mean: n_in n_out / n (mean_in − mean_out)²
        double bestStep = 0, bestWin = 0;
        int sa = -1, wa = -1, wb = -1;
        for (int a = 2; a <= n - 2; a++) {
            if (!(q[a] > q[a - 1])) continue;
            for (int b = a + 2; b <= n; b++) {
                if (b < n && (!(q[b] > q[b - 1]) || b > n - 2)) continue;
                int in = b - a, out = n - in;
                double mIn = (pre[b] - pre[a]) / in, mOut = (pre[n] - (pre[b] - pre[a])) / out;
                double ss = (double) in * out / n * (mIn - mOut) * (mIn - mOut);
                if (b == n) { if (ss > bestStep) { bestStep = ss; sa = a; } }
                else if (ss > bestWin) { bestWin = ss; wa = a; wb = b; }
            }
        }
        List<Effect> out = new ArrayList<>();
        if (sa > 0) out.add(Effect.angleStep(j, 0.5 * (q[sa - 1] + q[sa])));
        if (wa > 0) out.add(Effect.angleWindow(j, 0.5 * (q[wa - 1] + q[wa]), 0.5 * (q[wb - 1] + q[wb])));
        return out;
    }

    /**
     * Whether {@code e} would be a second form of a structure the selected effects (but {@code replaced},
     * the one {@code e} would stand in place of; null: none) hold already, so that it is not a second
     * effect and the forms stand against each other in the selected one's place:
     * <ul>
     * <li>a payload's varying compliance of a joint that has one: one carried mass changes one way (steps
     * beside a spline, another centre);</li>
     * <li>a joint's give under gravity (a compliance, fixed or varying) and its error growing with the
     * temperature at its own angle's orders ({@link Effect#periodicWarming}), either way round: on a
     * joint the weight loads, the give changing through a warm-up is the compliance's own rival (a
     * varying compliance), and a warming error beside the compliance would hold that change so that the
     * rival finds nothing beside the claim;</li>
     * <li>a second pull on the tool (another anchor is the same pull placed elsewhere), a second station's split
     * beside one (another side is the same station's poses split elsewhere).</li>
     * </ul>
     */
    static boolean secondForm(Effect e, List<Effect> selected, Effect replaced) {
        boolean mass = e.kind() == Effect.Kind.COMPLIANCE_VARYING && e.payloadShare();
        boolean give = e.kind() == Effect.Kind.COMPLIANCE || e.kind() == Effect.Kind.COMPLIANCE_VARYING;
        boolean warm = e.kind() == Effect.Kind.WARM_PERIODIC;
        if (e.kind() == Effect.Kind.TOOL_PULL || e.kind() == Effect.Kind.SECOND_STATION)
            return selected.stream().anyMatch(x -> x != e && x != replaced && x.kind() == e.kind());
        if (!mass && !give && !warm) return false;
        for (Effect x : selected) {
            if (x == e || x == replaced || x.joint() != e.joint()) continue;
            if (mass && x.kind() == Effect.Kind.COMPLIANCE_VARYING && x.payloadShare()) return true;
            if (give && x.kind() == Effect.Kind.WARM_PERIODIC) return true;
            if (warm && (x.kind() == Effect.Kind.COMPLIANCE || x.kind() == Effect.Kind.COMPLIANCE_VARYING)) return true;
        }
        return false;
    }

    /**
     * Whether a transmission error shares its drive with another named family (a lost motion, a
     * compliance, a scale error of the same joint). What such a family's form leaves of the true
     * physics (a lag that winds up in a way the model does not hold, a stiffness that is not
     * constant) is a smooth function of the same angle, and a harmonic or two fitted to it predict
     * left-out poses as well as the joint's smooth fallback: with the held-out error unable to tell
     * them apart, the gear is then not claimed, and the fallback models the shape.
     */
    static boolean besideAnother(Effect e, List<Effect> selected) {
        return e.kind() == Effect.Kind.PERIODIC
                && selected.stream().anyMatch(x -> x != e && !x.isFallback() && x.joint() == e.joint() && x.kind() != Effect.Kind.PERIODIC);
    }

    /**
     * Whether fallback {@code f} is a shape of what family {@code e} acts through: for a family of a
     * drive, that joint's own error or another drive's that follows its angle; for one of the
     * measured point (thermal growth, a drift), a displacement of the point.
     */
    static boolean sameVariable(Effect e, Effect f) {
        int j = e.joint();
        if (j < 0) return f.joint() < 0 && f.kind() != Effect.Kind.INSTRUMENT;
        return f.joint() == j || f.angleJoint() == j || f.kind() == Effect.Kind.PAIR && f.source() == j;
    }

    /**
     * Fallbacks added one at a time, the one that lowers the leave-one-pose-out error most, while it
     * is significant (Bonferroni over the candidates tried, at the search's α), lowers that error by
     * more than {@link #ALIAS_MARGIN} and, with validation poses, lowers their error too. Once the
     * claim check has withdrawn families, the one fallback put in each one's place may leave part
     * of what it held (a load across two joints: a shape of each); these model it. None is a claim.
     */
    private static Fit fallbacksForWhatIsLeft(Work w, Fit fit, List<Effect> selected, Map<Effect, boolean[]> absorbedCols,
                                              List<Step> steps, java.util.Collection<Effect> candidates, List<String> notes, boolean withdrawn) {
        for (int round = 0; round < MAX_LOCATED; round++) {
            Tester t = w.tester(fit);
            double press = t.pressFull();
            List<Candidate> cs = new ArrayList<>();
            for (Effect f : candidates) {
                if (!f.isFallback() || secondForm(f, selected, null) || selected.stream().anyMatch(x -> x.label().equals(f.label()))) continue;
                Candidate c = t.test(f, w.conditions);
                if (c.keptColumns > 0) cs.add(c);
            }
            Candidate best = null;
            for (Candidate c : cs) {
                c.threshold = w.o.alpha() / Math.max(1, cs.size());
                if (c.p < c.threshold && c.pressAfter < press * (1 - ALIAS_MARGIN) && (best == null || c.pressAfter < best.pressAfter)) best = c;
            }
            if (best == null) break;
            double valBefore = w.validateError(fit);
            selected.add(best.effect);
            absorbedCols.put(best.effect, best.absorbedMask);
            Fit g = w.fit(selected, absorbedCols, fit.full, best);
            if (w.hasValidation() && !(w.validateError(g) < valBefore)) {
                absorbedCols.remove(selected.remove(selected.size() - 1));
                break;
            }
            steps.add(new Step(best, g.trainRms, w.validateRms(g)));
            LOG.debug("left by the withdrawn families: {} (PRESS {} -> {})", best.effect.label(), press, best.pressAfter);
            notes.add(String.format(Locale.ROOT, "%s models what %s (leave-one-pose-out error %.1f against %.1f)", best.effect.label(),
                    withdrawn ? "the withdrawn families' fallbacks left" : "the geometric fit left where it was located", best.pressAfter, press));
            fit = g;
        }
        return fit;
    }

    /**
     * Where the two-joint fallback of drive j with joint k was needed: joint j's error depends on two
     * joints, and the fallback holds j's scale error and the coupling of j from k (its linear terms),
     * so a claim of j's own angle (scale, harmonics) or of k's is not that family's alone; the
     * fallback is then re-tested so that its terms, left to the family while it was there, are its
     * own again.
     */
    private static Fit pairNeeded(Work w, Fit fit, List<Effect> selected, Map<Effect, boolean[]> absorbedCols, List<Step> steps,
                                  List<String> aliasNotes) {
        for (int k = selected.size() - 1; k >= 0; k--) {
            Effect e = selected.get(k);
            Effect pair = selected.stream().filter(x -> x.kind() == Effect.Kind.PAIR && x.joint() == e.joint()
                    && (e.kind() == Effect.Kind.SCALE || e.kind() == Effect.Kind.PERIODIC
                    || e.kind() == Effect.Kind.COUPLING && e.source() == x.source())).findFirst().orElse(null);
            if (pair == null) continue;
            aliasNotes.add(e.label() + " is not claimed: joint " + (e.joint() + 1) + "'s error needed the two-joint fallback "
                    + pair.label() + " as well, which holds this family's shape, so it is not that family's alone");
            fit = dropAndRefit(w, fit, selected, absorbedCols, steps, k);
            fit = replaceEffect(w, fit, selected, absorbedCols, steps, selected.indexOf(pair), pair, false);
            k = selected.size();
        }
        return fit;
    }

    /**
     * Whether a family of drive j sits beside a structure of another drive i that follows joint j's
     * angle and that no named coupling of i from j explains: a two-joint error of drive i with
     * joint j, or drive i's smooth error following joint j, located or in the model. One load across
     * the joints makes both (a dress pack's tension, winding and bending twist every wrist drive
     * through its compliance: a spring bending over joint 5 alone gives joint 5 an error linear in
     * its angle, a scale error's form), so the family is not claimed unless it predicts left-out poses
     * better than its own fallback by {@link #SHARED_MARGIN}; else the fallback models the shape. The
     * structure must be there beside the model fitted in {@code at}: one in the model lowers its
     * leave-one-pose-out error by more than {@link #ALIAS_MARGIN}, one located is significant beside it.
     * (The claim check does not ask it of a transmission error that turns often over its range,
     * {@link #turnsOften}: such a load's torque is smooth in the joints' angles.)
     */
    static boolean sharedWithAnotherDrive(Effect e, List<Effect> selected, List<Effect> located, Tester at, Work w) {
        if (e.target() != Effect.Target.DRIVE || e.joint() < 0 || e.kind() == Effect.Kind.COUPLING) return false;
        int j = e.joint();
        double full = Double.NaN;
        for (Effect f : java.util.stream.Stream.concat(selected.stream(), located.stream()).toList()) {
            boolean follows = f.joint() != j && (f.kind() == Effect.Kind.PAIR && f.source() == j
                    || f.kind() == Effect.Kind.SMOOTH && f.angleJoint() == j);
            if (!follows || selected.stream().anyMatch(x -> x.kind() == Effect.Kind.COUPLING && x.joint() == f.joint() && x.source() == j))
                continue;
            int k = selected.indexOf(f);
            if (k >= 0) {
                if (Double.isNaN(full)) full = at.pressFull();
                if (at.pressReplacing(k, null, null) > full * (1 + ALIAS_MARGIN)) return true;
            } else if (selected.stream().noneMatch(x -> x.label().equals(f.label())) && significantBeside(at, f, w)) return true;
        }
        return false;
    }

    /** The variants of a fallback to try: a smooth error's other resolutions, a zero step's neighbouring times. */
    private static List<Effect> refinements(Effect e, Work w, List<Measurement> rows, List<Effect> selected) {
        List<Effect> out = new ArrayList<>();
        if (e.kind() == Effect.Kind.INSTRUMENT && Double.isFinite(e.cycle())) {
            // the period between the scan's grid points (a quarter and a half of its step either side): the phase
            // error over the readings' span is what a period off the grid leaves
            double f0 = 1 / e.cycle(), step = 1 / (3 * (e.rangeHi() - e.rangeLo()));
            for (int i = -2; i <= 2; i++)
                if (i != 0 && f0 + i * step / 4 > 0)
                    out.add(Effect.instrumentCyclic(e.sight(), e.instrumentPose(), e.azimuthRef(), e.rangeLo(), e.rangeHi(), 1 / (f0 + i * step / 4),
                            e.cycleOrders()));
            // and with more of its harmonics (a phase meter's error repeats at its cycle's harmonics too; one may be missing), as
            // far as the poses support them
            for (int h = e.cycleOrders() + 1; h <= MAX_CYCLE_ORDERS; h++)
                if (Effect.supported(2 * h, 2, rows.size()))
                    out.add(Effect.instrumentCyclic(e.sight(), e.instrumentPose(), e.azimuthRef(), e.rangeLo(), e.rangeHi(), e.cycle(), h));
        } else if (e.kind() == Effect.Kind.INSTRUMENT_SCALE) {
            // a long campaign's air warms and cools and its pressure drifts: a finer curve of the same reading
            for (int nb : INSTRUMENT_SCALE_RESOLUTIONS)
                if (nb != e.basisCount() && Effect.supported(nb, Effect.POINT_BASIS, rows.size()))
                    out.add(Effect.instrumentScale(e.along(), e.instrumentPose(), e.rangeLo(), e.rangeHi(), nb));
        } else if (e.kind() == Effect.Kind.REFRACTION) {
            // the hall's stratification builds up and changes with its ventilation: a finer curve of the same reading
            for (int nb : INSTRUMENT_SCALE_RESOLUTIONS)
                if (nb != e.basisCount() && Effect.supported(nb, Effect.POINT_BASIS, rows.size()))
                    out.add(Effect.refraction(e.along(), e.instrumentPose(), e.rangeLo(), e.rangeHi(), nb));
        } else if (e.kind() == Effect.Kind.BASE_CREEP) {
            // the least move that slips the base (the bolts' hold against the reaction of the move)
            List<Measurement> all = new ArrayList<>(w.rows);
            if (w.validate != null) all.addAll(w.validate.rows());
            double[][] moves = Directions.movesInTime(all, 0);
            if (moves != null)
                for (double deg : CREEP_MOVES_DEG)
                    if (Math.toRadians(deg) != e.creepMoveRad()) out.add(Effect.baseCreep(moves, Math.toRadians(deg)));
        } else if (e.kind() == Effect.Kind.TARGET_DRIFT) {
            for (int nb : Effect.DRIFT_RESOLUTIONS)
                if (nb != e.basisCount() && Effect.supported(nb, Effect.POINT_BASIS, rows.size()))
                    out.add(Effect.targetDrift(w.model, e.rangeLo(), e.rangeHi(), nb));
        } else if (e.kind() == Effect.Kind.INSTRUMENT) {
            for (int nb : e.sight() == Effect.Sight.RANGE ? Locator.RANGE_RESOLUTIONS : Locator.ANGLE_RESOLUTIONS)
                if (nb != e.basisCount() && Effect.supported(nb, Effect.POINT_BASIS, rows.size()))
                    out.add(Effect.instrumentReading(e.sight(), e.instrumentPose(), e.azimuthRef(), e.rangeLo(), e.rangeHi(), nb));
        } else if (e.kind() == Effect.Kind.ZERO_DRIFT && w.gravity != null && loaded(w.gravity, e.joint(), rows)) {
            // a zero that moves with time or temperature may be the joint's give under gravity changing: a joint that softens as
            // it warms, a carried mass that changes while the file records one
            out.add(Effect.complianceVarying(e.joint(), w.gravity, e.along(), e.rangeLo(), e.rangeHi(),
                    w.gravity.massesUnknown() ? 2 : Effect.POINT_BASIS, false));
            if (e.along() == Effect.Along.TIME && rows.stream().anyMatch(r -> r.payloadKg() > 0))
                for (Effect f : payloadSplines(e.joint(), w.gravity, e.rangeLo(), e.rangeHi(), rows)) withPayloadCentre(f, rows, out);
        }
        if (e.kind() == Effect.Kind.WARM_PERIODIC && w.gravity != null && loaded(w.gravity, e.joint(), rows)) {
            // on a joint the arm's weight loads, an error of its angle changing through the warm-up may be its give under gravity
            // changing: the joint softening as it warms, a carried mass changing while the file records one
            double[] temp = tempSpan(w.conditions), time = timeSpan(w.conditions);
            if (temp != null)
                out.add(Effect.complianceVarying(e.joint(), w.gravity, Effect.Along.TEMPERATURE, temp[0], temp[1],
                        w.gravity.massesUnknown() ? 2 : Effect.POINT_BASIS, false));
            if (time != null && rows.stream().anyMatch(r -> r.payloadKg() > 0))
                for (Effect f : payloadSplines(e.joint(), w.gravity, time[0], time[1], rows)) withPayloadCentre(f, rows, out);
        }
        if (e.kind() == Effect.Kind.COMPLIANCE_VARYING && e.payloadShare()) {
            // one carried mass: its shape in time and its centre, each varied with the other kept
            List<Effect> shapes = new ArrayList<>();
            boolean free = e.payloadCentreFree();
            if (e.stepTimes() != null) {
                // each step moved to the places near it (the others kept)
                double[] t = w.conditions.stream().mapToDouble(PoseConditions::timeS).filter(Double::isFinite).toArray();
                double[] steps = e.stepTimes();
                for (int i = 0; i < steps.length; i++)
                    for (double tau : Locator.placesNear(t, steps[i])) {
                        double[] moved = steps.clone();
                        moved[i] = tau;
                        Arrays.sort(moved);
                        if (java.util.stream.IntStream.range(1, moved.length).allMatch(k -> moved[k] > moved[k - 1]))
                            shapes.add(Effect.complianceInSteps(e.joint(), e.gravity(), moved));
                    }
                // one carried mass changes at the same moments for every joint it loads: another joint's steps
                for (Effect x : selected)
                    if (x != e && x.kind() == Effect.Kind.COMPLIANCE_VARYING && x.stepTimes() != null && !Arrays.equals(x.stepTimes(), steps))
                        shapes.add(Effect.complianceInSteps(e.joint(), e.gravity(), x.stepTimes()));
                // and the mass changing steadily instead (a spline of the time over the campaign)
                double[] span = timeSpan(w.conditions);
                if (span != null) shapes.addAll(payloadSplines(e.joint(), e.gravity(), span[0], span[1], rows));
            }
            for (Effect f : shapes) {
                Effect g = free ? Effect.withPayloadCentreFree(f) : f;
                if (Effect.supported(g.size(), 1, rows.size())) out.add(g);
            }
            // the payload's centre off the file's (a tool's reservoir hanging off the flange) estimated with the compliance, or
            // where the file puts it
            Effect same = e.stepTimes() != null ? Effect.complianceInSteps(e.joint(), e.gravity(), e.stepTimes())
                    : Effect.complianceVarying(e.joint(), e.gravity(), e.along(), e.rangeLo(), e.rangeHi(), e.basisCount(), true);
            Effect other = free ? same : Effect.withPayloadCentreFree(same);
            if (Effect.supported(other.size(), 1, rows.size())) out.add(other);
        } else if (e.kind() == Effect.Kind.COMPLIANCE_VARYING && !e.payloadShare()) {
            // the same change of the joint as its zero's drift with the same variable (a motor warming shifts its zero the way a
            // softening joint gives way where the torque changes little), and the give following the other variable
            out.add(Effect.zeroDrift(e.joint(), e.along(), e.rangeLo(), e.rangeHi()));
            Effect.Along other = e.along() == Effect.Along.TIME ? Effect.Along.TEMPERATURE : Effect.Along.TIME;
            double[] span = other == Effect.Along.TIME ? timeSpan(w.conditions) : tempSpan(w.conditions);
            if (span != null) out.add(Effect.complianceVarying(e.joint(), e.gravity(), other, span[0], span[1], e.basisCount(), false));
        } else if (e.kind() == Effect.Kind.GRAVITY_PLAY) {
            // where the side changes (the file's masses put the torque's zero only roughly) and how sharply
            for (Effect f : gravityPlays(e.joint(), e.gravity(), rows, w.model, PLAY_SIDE_SHIFTS, PLAY_SIDE_WIDTHS))
                if (f.sideNm() != e.sideNm() || f.sideWidthNm() != e.sideWidthNm()) out.add(f);
        } else if (e.kind() == Effect.Kind.SMOOTH) {
            // a curve of the joint's angle may stand for its play taken up by gravity (the torque's sign follows the angle closely)
            if (e.angleJoint() == e.joint()) out.addAll(gravityPlays(e.joint(), w.gravity, rows, w.model, PLAY_SIDE_SHIFTS, PLAY_SIDE_WIDTHS));
            for (int nb : Effect.SMOOTH_RESOLUTIONS)
                if (nb != e.basisCount() && Effect.supported(nb, Effect.SMOOTH_BASIS, rows.size()))
                    out.add(e.followsModelAngle() ? Effect.smoothFollowingModelAngle(e.joint(), e.angleJoint(), w.model, e.rangeLo(), e.rangeHi(), nb)
                            : Effect.smoothFollowing(e.joint(), e.angleJoint(), e.rangeLo(), e.rangeHi(), nb));
        } else if (e.stepInTime() || e.kind() == Effect.Kind.ANGLE_STEP && !e.isWindow()) {
            boolean angle = e.kind() == Effect.Kind.ANGLE_STEP;
            // a step of the reading at one angle may stand for a play taken up by gravity, whose side changes with the torque
            if (angle) out.addAll(gravityPlays(e.joint(), w.gravity, rows, w.model, PLAY_SIDE_SHIFTS, PLAY_SIDE_WIDTHS));
            Locator.Var var = angle ? Locator.Var.ANGLE_STEP : e.kind() == Effect.Kind.TARGET_STEP ? Locator.Var.TARGET_STEP
                    : e.kind() == Effect.Kind.BASE_STEP ? Locator.Var.BASE_STEP : Locator.Var.TIME_STEP;
            double[] t = angle ? rows.stream().mapToDouble(r -> r.q(e.joint())).toArray()
                    : w.conditions.stream().mapToDouble(PoseConditions::timeS).filter(Double::isFinite).toArray();
            // the midpoints between the poses within a twentieth of the campaign (of the joint's poses) either side
            for (double tau : Locator.placesNear(t, angle ? e.rangeLo() : e.tauS()))
                out.add(e.kind() == Effect.Kind.RANGE_STEP ? Effect.rangeStep(e.instrumentPose(), tau) : stepEffect(var, e.joint(), tau, w.model));
        }
        return out;
    }

    /**
     * Joint {@code j}'s plays taken up by gravity ({@link Effect#gravityPlay}) with their side changing
     * at each of {@code shifts} (a share of the largest torque on the drive over {@code rows}) and
     * each hand-over half-width of {@code widths}; the masses the robot file's, or estimated from the
     * link lengths. None where fewer than {@link Locator#MIN_PLAY_SIDE} poses lie on either side of
     * the torque's zero.
     */
    static List<Effect> gravityPlays(int j, GravityTorques g0, List<Measurement> rows, KinematicModel model, double[] shifts, double[] widths) {
        if (g0 == null || model.isPrismatic(j)) return List.of();
        GravityTorques g = g0.massesUnknown() ? GravityTorques.fromLengths(model) : g0;
        double max = 0;
        int pos = 0, neg = 0;
        for (Measurement r : rows) {
            double t = g.driveTorques(r.q(), Double.isFinite(r.payloadKg()) ? r.payloadKg() : 0)[j];
            max = Math.max(max, Math.abs(t));
            if (t > 0) pos++;
            else if (t < 0) neg++;
        }
        if (Math.min(pos, neg) < Locator.MIN_PLAY_SIDE || !(max > 0)) return List.of();
        List<Effect> out = new ArrayList<>();
        for (double c : shifts) for (double wd : widths) out.add(Effect.gravityPlay(j, g, c * max, wd * max));
        return out;
    }

    /**
     * Moves of the measured point on the flange at one time or several (target steps, with a drift of
     * it or not) are one drift of it with time when a smooth curve of the time predicts left-out
     * poses better than they do together: a tool that grows and shrinks as its spindle runs and rests
     * moves the point back and forth, which steps follow one at a time. Each resolution of
     * {@link Effect#DRIFT_RESOLUTIONS} the poses support is tried in their place; the best stays when
     * its leave-one-pose-out error is lower and it predicts the validation poses no worse.
     */
    private static Fit driftForSteps(Work w, Fit fit, List<Effect> selected, Map<Effect, boolean[]> absorbedCols, List<Step> steps) {
        List<Effect> moves = selected.stream().filter(e -> e.kind() == Effect.Kind.TARGET_STEP || e.kind() == Effect.Kind.TARGET_DRIFT).toList();
        double[] span = timeSpan(w.conditions);
        if (span == null || moves.stream().noneMatch(e -> e.kind() == Effect.Kind.TARGET_STEP)) return fit;
        Selection saved = Selection.of(selected, absorbedCols, steps);
        double own = w.tester(fit).pressFull(), ownVal = w.validateError(fit);
        // the model without the moves, and each resolution's leave-one-pose-out error beside it
        Fit base = fit;
        for (int k = selected.size() - 1; k >= 0; k--)
            if (moves.contains(selected.get(k)) && selected.get(k) != moves.get(0)) base = dropAndRefit(w, base, selected, absorbedCols, steps, k);
        base = dropAndRefit(w, base, selected, absorbedCols, steps, selected.indexOf(moves.get(0)));
        Tester bt = w.tester(base);
        Effect best = null;
        double bestPress = own;
        for (int nb : Effect.DRIFT_RESOLUTIONS) {
            if (!Effect.supported(nb, Effect.POINT_BASIS, w.rows.size())) continue;
            Effect drift = Effect.targetDrift(w.model, span[0], span[1], nb);
            Candidate c = bt.test(drift, w.conditions);
            LOG.debug("{} in place of {}: PRESS {} against {}", drift.label(), moves.stream().map(Effect::label).toList(), c.pressAfter, own);
            if (c.keptColumns > 0 && c.pressAfter < bestPress) { bestPress = c.pressAfter; best = drift; }
        }
        saved.restore(selected, absorbedCols, steps);
        if (best == null) return fit;
        Fit f = fit;
        for (int k = selected.size() - 1; k >= 0; k--)
            if (moves.contains(selected.get(k)) && selected.get(k) != moves.get(0)) f = dropAndRefit(w, f, selected, absorbedCols, steps, k);
        f = replaceEffect(w, f, selected, absorbedCols, steps, selected.indexOf(moves.get(0)), best, true);
        boolean valWorse = w.hasValidation() && !(w.validateError(f) < ownVal * (1 + ALIAS_MARGIN));
        if (!selected.contains(best) || valWorse || !(w.tester(f).pressFull() < own)) {
            saved.restore(selected, absorbedCols, steps);
            return fit;
        }
        return f;
    }

    /** The least moves of joint 1 (deg) tried for a base creep once it is found. */
    static final double[] CREEP_MOVES_DEG = {5, 10, 15, 20, 30, 45, 60, 90};

    /** The first and last time (s) of the poses' conditions, or null unless they span some time. */
    static double[] timeSpan(List<PoseConditions> conditions) {
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
        for (PoseConditions c : conditions) if (Double.isFinite(c.timeS())) { lo = Math.min(lo, c.timeS()); hi = Math.max(hi, c.timeS()); }
        return hi > lo ? new double[] {lo, hi} : null;
    }

    /** Where a gravity play's side changes, tried when it is refined: a share of the largest torque on its drive either side of zero. */
    static final double[] PLAY_SIDE_SHIFTS = {-0.1, -0.05, -0.02, 0, 0.02, 0.05, 0.1};
    /** The hand-over's half-widths tried, a share of the largest torque (0: sharp). */
    static final double[] PLAY_SIDE_WIDTHS = {0, 0.05, 0.1, 0.2};

    /**
     * A distance meter's cycle in the model, its period tuned and its overtones taken in. A period a
     * fraction of the scan's grid step off leaves a phase error that grows with the harmonic (over
     * a span of metres, a quarter cycle at the fourth where the cycle itself is followed), and what
     * the cycle then misses was taken by a second cycle at a half or a quarter of its period, or
     * one near it. Each cycle, the longest first, is refitted with as many harmonics as the poses
     * support (up to {@link #MAX_CYCLE_ORDERS}) at the period that predicts left-out poses best,
     * searched over half the scan's step either side of its period and a step either side of half
     * its period (a sixteenth of a step apart, then by golden section), the other cycles at its
     * overtones' periods taken out; it stays when the model predicts left-out poses at least as well.
     */
    private static Fit tuneCycles(Work w, Fit fit, List<Effect> selected, Map<Effect, boolean[]> absorbedCols, List<Step> steps,
                                  List<Measurement> rows) {
        List<Effect> cycles = selected.stream().filter(e -> e.kind() == Effect.Kind.INSTRUMENT && Double.isFinite(e.cycle()))
                .sorted((x, y) -> Double.compare(y.cycle(), x.cycle())).toList();
        for (Effect ea : cycles) {
            if (!selected.contains(ea)) continue;
            double fa = 1 / ea.cycle(), step = 1 / (3 * (ea.rangeHi() - ea.rangeLo()));
            int orders = ea.cycleOrders();
            while (orders < MAX_CYCLE_ORDERS && Effect.supported(2 * (orders + 1), 2, rows.size())) orders++;
            List<Effect> overtones = new ArrayList<>();
            for (Effect eb : selected) {
                if (eb == ea || eb.kind() != Effect.Kind.INSTRUMENT || !Double.isFinite(eb.cycle()) || eb.sight() != ea.sight()) continue;
                long m = Math.round(ea.cycle() / eb.cycle());
                if (m >= 1 && m <= orders && Math.abs(1 / eb.cycle() - m * fa) <= m * step) overtones.add(eb);
            }
            double before = w.tester(fit).pressFull();
            Selection saved = Selection.of(selected, absorbedCols, steps);
            Fit without = fit;
            for (Effect eb : overtones) without = dropAndRefit(w, without, selected, absorbedCols, steps, selected.indexOf(eb));
            int ka = selected.indexOf(ea);
            Tester at = w.tester(without);
            int h = orders;
            java.util.function.DoubleUnaryOperator press = f -> at.pressReplacing(ka, Effect.instrumentCyclic(ea.sight(), ea.instrumentPose(),
                    ea.azimuthRef(), ea.rangeLo(), ea.rangeHi(), 1 / f, h), w.conditions);
            // (and at twice its frequency: a scan's probe with harmonics holds the cycle's own harmonics at half its period too, and
            // the one at half the period, with its own harmonics, holds a fourth overtone the longer one's four harmonics miss)
            double bestF = fa, bestP = Double.POSITIVE_INFINITY, d = step / 16;
            for (int mult = 1; mult <= 2; mult++)
                for (int i = -8 * mult; i <= 8 * mult; i++) {
                    double f = mult * fa + i * d, pf = f > 0 ? press.applyAsDouble(f) : Double.POSITIVE_INFINITY;
                    if (pf < bestP) { bestP = pf; bestF = f; }
                }
            // golden section within a grid point either side of the best
            double lo = bestF - d, hi = bestF + d, g = (Math.sqrt(5) - 1) / 2;
            double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo), p1 = press.applyAsDouble(x1), p2 = press.applyAsDouble(x2);
            for (int it = 0; it < 8; it++) {
                if (p1 < p2) { hi = x2; x2 = x1; p2 = p1; x1 = hi - g * (hi - lo); p1 = press.applyAsDouble(x1); }
                else { lo = x1; x1 = x2; p1 = p2; x2 = lo + g * (hi - lo); p2 = press.applyAsDouble(x2); }
            }
            if (Math.min(p1, p2) < bestP) { bestP = Math.min(p1, p2); bestF = p1 < p2 ? x1 : x2; }
            Effect tuned = Effect.instrumentCyclic(ea.sight(), ea.instrumentPose(), ea.azimuthRef(), ea.rangeLo(), ea.rangeHi(), 1 / bestF, h);
            int n = selected.size();
            Fit one = bestP <= before ? replaceEffect(w, without, selected, absorbedCols, steps, ka, tuned, false) : null;
            if (one != null && selected.size() == n && w.tester(one).pressFull() <= before) {
                LOG.debug("{} tuned to {}, taking {}", ea.label(), tuned.label(), overtones.stream().map(Effect::label).toList());
                fit = one;
                continue;
            }
            saved.restore(selected, absorbedCols, steps);
        }
        return fit;
    }

    /**
     * What took a structure found after the geometric fit that the final model no longer leaves,
     * though no effect of its own variable was named: the selected effect with which, added to the
     * geometric model, the structure is no longer significant at its own threshold (the one that
     * leaves it least significant), else the selected effects together if they do; null when the
     * structure holds even beside all of them. What the geometric fit leaves of a warm-up, for one,
     * has a step in time among its nearest shapes (a joint's zero jumping, the target moving on the
     * flange): once the thermal growth is fitted the step is gone; it was the growth's.
     */
    static String takenBy(Locator.Found f, Tester geo, List<Effect> selected) {
        double thr = f.c.threshold;
        Effect best = null;
        double bestP = 0;
        List<double[]> cols = new ArrayList<>(); // every selected effect's columns, orthonormal, out of the geometric span
        for (Effect e : selected) {
            Candidate c = geo.test(e, geo.w.conditions);
            if (c.keptColumns == 0) continue;
            Candidate s = Locator.test(geo, f.probe, c.basis, c.keptColumns, thr);
            double p = s == null ? 1 : s.p;
            LOG.debug("located {}: p {} beside {} (threshold {})", f.probe.shape, p, e.label(), thr);
            if (!(p < thr) && p > bestP) { bestP = p; best = e; }
            for (int t = 0; t < c.keptColumns; t++) {
                double[] x = new double[geo.m];
                for (int i = 0; i < geo.m; i++) x[i] = c.basis[i * c.keptColumns + t];
                cols.add(x);
            }
        }
        if (best != null) return best.label();
        if (selected.size() < 2 || cols.isEmpty()) return null;
        List<double[]> qs = orthonormal(cols, null, geo.m);
        int nq = qs.size();
        double[] q = new double[geo.m * nq];
        for (int t = 0; t < nq; t++) for (int i = 0; i < geo.m; i++) q[i * nq + t] = qs.get(t)[i];
        Candidate s = Locator.test(geo, f.probe, q, nq, thr);
        return s == null || !(s.p < thr) ? String.join(" and ", selected.stream().map(Effect::label).toList()) + " together" : null;
    }

    /**
     * An orthonormal basis of the span of {@code cols} (each m long), Gram–Schmidt twice: a column
     * whose squared norm left is within the rank tolerance (1e-20) of {@code n0[c]} (its squared norm
     * before any projection the caller made; null: its own) is dropped.
     */
    static List<double[]> orthonormal(List<double[]> cols, double[] n0s, int m) { return orthonormal(cols, n0s, m, 1e-20); }

    /** As above, a column kept only when what is left of it is above {@code tol} times its squared norm before the projection. */
    static List<double[]> orthonormal(List<double[]> cols, double[] n0s, int m, double tol) {
        List<double[]> qs = new ArrayList<>();
        for (int c = 0; c < cols.size(); c++) {
            double[] x = cols.get(c).clone();
            double n0 = 0;
            if (n0s != null) n0 = n0s[c];
            else for (double v : x) n0 += v * v;
            for (int pass = 0; pass < 2; pass++)
                for (double[] qv : qs) {
                    double d = 0;
                    for (int i = 0; i < m; i++) d += qv[i] * x[i];
                    for (int i = 0; i < m; i++) x[i] -= d * qv[i];
                }
            double n1 = 0;
            for (double v : x) n1 += v * v;
            if (n0 == 0 || n1 < tol * n0) continue;
            double nn = Math.sqrt(n1);
            for (int i = 0; i < m; i++) x[i] /= nn;
            qs.add(x);
        }
        return qs;
    }

    /** Whether two structures found are the same: the same variable and shape. */
    private static boolean sameStructure(Locator.Found a, Locator.Found b) {
        return a.probe.variable.equals(b.probe.variable) && a.probe.shape.equals(b.probe.shape);
    }

    /**
     * The structures the final scan finds beside a named family that the validation poses do not
     * confirm: the structure's own fallback (or its family, for a harmonic or a direction), fitted
     * jointly with the final model, does not lower the validation error (each residual over its
     * noise). Each is said in {@code notes} as a weak lead with what to measure, not reported as
     * located. Without validation poses, without a named family (only fallbacks: what is located
     * then is the finding), or for a structure without a fallback, none.
     */
    private static List<Locator.Found> weakLeads(Work w, Fit fit, List<Effect> selected, Map<Effect, boolean[]> absorbedCols,
                                                 Tester t, List<Locator.Found> found, List<Measurement> rows, KinematicModel model,
                                                 List<String> notes) {
        List<Locator.Found> out = new ArrayList<>();
        if (!w.hasValidation() || selected.stream().allMatch(Effect::isFallback)) return out;
        double without = w.validateError(fit);
        for (Locator.Found f : found) {
            Effect lead = switch (f.probe.var) {
                case ANGLE_PERIODIC -> Effect.periodic(f.probe.joint, new int[] {f.probe.harmonic});
                case DIRECTION -> Effect.backlash(f.probe.joint);
                default -> locatedFallbacks(List.of(f), rows, model).stream().findFirst().orElse(null);
            };
            if (lead == null || selected.stream().anyMatch(e -> e.label().equals(lead.label()))) continue;
            Candidate c = t.test(lead, w.conditions);
            if (c.keptColumns == 0) continue;
            List<Effect> with = new ArrayList<>(selected);
            with.add(lead);
            Map<Effect, boolean[]> abs = new java.util.IdentityHashMap<>(absorbedCols);
            abs.put(lead, c.absorbedMask);
            double withLead = w.validateError(w.fit(with, abs, fit.full, c));
            LOG.debug("lead {}: validation error {} with {}, {} without", f.probe.shape, withLead, lead.label(), without);
            if (withLead < without) continue;
            out.add(f);
            notes.add(String.format(Locale.ROOT, "A weak lead, not a finding: what the final model leaves on the training poses "
                    + "also shows a structure (%s: %.4f mm RMS %s, F = %.1f, p %s), but modelled (as %s) beside the named effects it does not "
                    + "lower the validation poses' error (%.1f against %.1f, each residual over its noise), so these data do not "
                    + "confirm it. To settle it, %s", f.probe.shape, f.sizeM * 1e3, t.where(), f.c.f, Words.p(f.c.p), lead.label(),
                    withLead, without, nextMeasurement(f, rows.size())));
        }
        return out;
    }

    /** The selected effect that explains a structure found after the geometric fit, or null. */
    static Effect explainer(Locator.Found f, List<Effect> selected) {
        if (f.probe.var == Locator.Var.RANGE_STEP) {
            // the jump of the distances nearest in time, else a drift or a scale of the instrument with time
            Effect near = null;
            for (Effect e : selected)
                if (e.kind() == Effect.Kind.RANGE_STEP && (near == null || Math.abs(e.tauS() - f.probe.lo) < Math.abs(near.tauS() - f.probe.lo)))
                    near = e;
            if (near != null) return near;
        }
        for (Effect e : selected) {
            Effect.Kind k = e.kind();
            boolean thermal = k == Effect.Kind.THERMAL || k == Effect.Kind.THERMAL_LINK || k == Effect.Kind.DRIFT;
            switch (f.probe.var) {
                case ANGLE_PERIODIC, ANGLE_SMOOTH, ANGLE_STEP, LINK_PERIODIC -> {
                    if (e.target() == Effect.Target.DRIVE && k != Effect.Kind.BACKLASH
                            && (e.joint() == f.probe.joint || (k == Effect.Kind.COUPLING && e.source() == f.probe.joint))) return e;
                }
                case JOINT_PAIR -> {
                    // the two joints' error, on either drive (a parallel linkage passes a drive's error on to the other's angle)
                    if (e.target() == Effect.Target.DRIVE && k != Effect.Kind.BACKLASH
                            && (e.joint() == f.probe.joint || e.joint() == f.probe.other)
                            && (k != Effect.Kind.PAIR && k != Effect.Kind.COUPLING || e.source() == f.probe.joint || e.source() == f.probe.other))
                        return e;
                }
                case DIRECTION -> { if ((k == Effect.Kind.BACKLASH || k == Effect.Kind.SETTLING) && e.joint() == f.probe.joint) return e; }
                case SETTLING -> { if (k == Effect.Kind.SETTLING && e.joint() == f.probe.joint) return e; }
                case TIME, TEMPERATURE -> {
                    if (thermal || (k == Effect.Kind.POINT_SMOOTH || k == Effect.Kind.INSTRUMENT_SCALE) && f.probe.joint < 0) return e;
                    if ((k == Effect.Kind.ZERO_DRIFT || k == Effect.Kind.ZERO_STEP) && e.joint() == f.probe.joint) return e;
                }
                case TIME_STEP -> {
                    if ((k == Effect.Kind.ZERO_DRIFT || k == Effect.Kind.ZERO_STEP) && e.joint() == f.probe.joint) return e;
                }
                // the target moved on the flange: at one time, or drifting
                case TARGET_STEP, TARGET_DRIFT -> { if (k == Effect.Kind.TARGET_STEP || k == Effect.Kind.TARGET_DRIFT) return e; }
                // the base turning: in steps with joint 1's moves, at one time, with time; or joint 1's zero moving with time
                case BASE_CREEP -> {
                    if (k == Effect.Kind.BASE_CREEP || k == Effect.Kind.BASE_STEP || k == Effect.Kind.BASE_TURN
                            || (k == Effect.Kind.ZERO_DRIFT || k == Effect.Kind.ZERO_STEP) && e.joint() == 0) return e;
                }
                // the instrument's pose changed: a drift of it, or a turn of the base, with time follows part of a step
                case BASE_STEP -> { if (k == Effect.Kind.BASE_STEP || k == Effect.Kind.DRIFT || k == Effect.Kind.BASE_TURN) return e; }
                case RANGE_STEP -> { if (k == Effect.Kind.DRIFT || k == Effect.Kind.INSTRUMENT_SCALE) return e; }
                case STATION -> { if (k == Effect.Kind.SECOND_STATION) return e; }
                case PAYLOAD_REACH -> { if (k == Effect.Kind.COMPLIANCE || k == Effect.Kind.POINT_SMOOTH) return e; }
                case PAYLOAD -> { if (k == Effect.Kind.COMPLIANCE && e.joint() == f.probe.joint) return e; }
                case REACH, HEIGHT -> { return e; }
                case SIGHT -> { if (k == Effect.Kind.INSTRUMENT && e.sight() == f.probe.sight) return e; }
                // the base's tilt, or a drive of the arm's first joints giving way under the same weight
                case BASE_MOMENT -> { if (k == Effect.Kind.BASE_TILT || k == Effect.Kind.COMPLIANCE && e.joint() <= 2) return e; }
                case AXIS_WOBBLE -> { if (k == Effect.Kind.AXIS_WOBBLE && e.joint() == f.probe.joint) return e; }
                // the axis tilting with its drive's torque, or the joint's spring or its link's bending under the same weight
                case LOAD_TILT -> {
                    if ((k == Effect.Kind.LOAD_TILT || k == Effect.Kind.COMPLIANCE || k == Effect.Kind.LINK_SAG) && e.joint() == f.probe.joint) return e;
                }
                case AXIAL_RUNOUT -> { if (k == Effect.Kind.AXIAL_RUNOUT && e.joint() == f.probe.joint) return e; }
                // the holder's sag, or a wrist drive giving way under the tool's weight
                case TOOL_GRAVITY -> { if (k == Effect.Kind.TOOL_SAG || k == Effect.Kind.COMPLIANCE && e.joint() >= 3) return e; }
                case TOOL_PLAY -> { if (k == Effect.Kind.TOOL_PLAY || k == Effect.Kind.COMPLIANCE && e.joint() >= 3) return e; }
                case TARGET_SIGHT -> { if (k == Effect.Kind.TARGET_INCIDENCE || k == Effect.Kind.INSTRUMENT) return e; }
                // the link's bending, or its joint's spring (a beam's special case)
                case LINK_BEND -> { if ((k == Effect.Kind.LINK_SAG || k == Effect.Kind.COMPLIANCE) && e.joint() == f.probe.joint) return e; }
                case LINK_TWIST -> { if (k == Effect.Kind.LINK_TWIST) return e; }
                // a pull on the tool, or the joints' springs under a weight (one that pulls straight down)
                case TOOL_PULL -> {
                    if (k == Effect.Kind.TOOL_PULL || k == Effect.Kind.COMPLIANCE || k == Effect.Kind.COMPLIANCE_VARYING
                            || k == Effect.Kind.TOOL_SAG || k == Effect.Kind.LINK_SAG || k == Effect.Kind.LINK_TWIST) return e;
                }
                // the joint's play taken up by gravity, a lost motion held by it, or its spring under the same torque
                case GRAVITY_PLAY -> {
                    if ((k == Effect.Kind.GRAVITY_PLAY || k == Effect.Kind.BACKLASH || k == Effect.Kind.COMPLIANCE) && e.joint() == f.probe.joint)
                        return e;
                }
            }
        }
        return null;
    }

    static Diagnosis.Located located(Locator.Found f, Tester t, String stage, String by, boolean taken, boolean left) {
        String words = String.format(Locale.ROOT, "%s: %.4f mm RMS %s, %.0f %% of the %s sum of squares "
                + "(F = %.1f on %d degrees of freedom, p %s below the corrected threshold %.2g)", capital(f.probe.shape),
                f.sizeM * 1e3, t.where(), 100 * share(f, t), stage.equals("geometric") ? "geometric fit's unexplained" : "remaining",
                f.c.f, f.c.df1, Words.p(f.c.p), f.c.threshold);
        if (taken) words += "; explained by " + by + ": with it fitted the structure is no longer significant, so it is "
                + "that effect's seen through the geometric fit, not a structure of its own.";
        else if (by != null) words += "; explained by " + by + ".";
        else if (left) words += "; no named effect explains it.";
        words += Locator.placement(f);
        return new Diagnosis.Located(f.probe.variable, f.probe.shape, f.sizeM, share(f, t), f.c.f, f.c.df1, f.c.p, f.c.threshold,
                stage, by, words, Locator.plot(t, f));
    }

    /** Share of the scanned fit's unexplained sum of squares a structure removes. */
    private static double share(Locator.Found f, Tester t) { return t.rss0 > 0 ? Math.min(1, f.c.drss / t.rss0) : 0; }

    /** {@code s} with its first letter upper-case. */
    static String capital(String s) { return s.isEmpty() ? s : Character.toUpperCase(s.charAt(0)) + s.substring(1); }

    /** Above this multiple of the floor the instrument's stated noise gives, the report says first that error is left. */
    static final double STATED_FLOOR_MARGIN = 1.2;

    private static final java.util.regex.Pattern STATED_SIGMA =
            java.util.regex.Pattern.compile("sigma\\s*[=:]?\\s*([0-9]*\\.?[0-9]+(?:e[-+]?[0-9]+)?)\\s*(mm|um|µm|m)(?![a-z])");

    /**
     * The instrument's noise per axis as the measurement file states it (metadata
     * {@code # instrument: laser tracker, sigma 0.03 mm}), m; NaN when it is not stated. It is the
     * user's statement of the instrument, not an estimate from the residuals: a residual-based
     * floor grows with whatever structure the model leaves and cannot show it.
     */
    static double statedSigmaM(MeasurementSet s) {
        String v = s.metadata() == null ? null : s.metadata().get("instrument");
        if (v == null) return Double.NaN;
        java.util.regex.Matcher m = STATED_SIGMA.matcher(v.toLowerCase(Locale.ROOT));
        if (!m.find()) return Double.NaN;
        double x = Double.parseDouble(m.group(1));
        double scale = switch (m.group(2)) {
            case "mm" -> 1e-3;
            case "m" -> 1;
            default -> 1e-6;
        };
        return x > 0 ? x * scale : Double.NaN;
    }

    /** What the file measures, for the stated floor: points (3 components each) or lengths (one). */
    enum Measured {
        POINTS(3), ANCHOR(1), PAIRS(1);
        final int components;
        Measured(int components) { this.components = components; }
    }

    /** The first warning when the error left exceeds the instrument's stated floor: how much, and what to measure (measured points). */
    static String aboveStatedFloor(double rms, boolean validation, double sigma, List<Effect> selected, boolean nothingLocated) {
        return aboveStatedFloor(rms, validation, sigma, Measured.POINTS, 1, 0, selected, nothingLocated);
    }

    /**
     * The first warning when the error left exceeds what the instrument's stated sigma leaves a
     * model without error: the floor (√3·σ for points, σ for a length) times {@code perfect}, the
     * factor of the {@code parameters} fitted (√(1 ± p/n), training or new poses); how much, and
     * what to measure.
     */
    static String aboveStatedFloor(double rms, boolean validation, double sigma, Measured kind, double perfect, int parameters,
                                   List<Effect> selected, boolean nothingLocated) {
        double floor = noiseFloor(sigma, kind.components) * perfect;
        String stated = kind == Measured.POINTS ? String.format(Locale.ROOT, "%.4f mm per axis", sigma * 1e3)
                : String.format(Locale.ROOT, "%.4f mm per length", sigma * 1e3);
        StringBuilder b = new StringBuilder(String.format(Locale.ROOT, "The final model misses the %s poses by %.4f mm RMS%s, "
                + "%.1f x the noise floor of the instrument's stated sigma (%.4f mm, from %s%s): error is left that the model "
                + "does not hold", validation ? "validation" : "training", rms * 1e3,
                switch (kind) {
                    case POINTS -> "";
                    case ANCHOR -> " in the lengths to the anchor";
                    case PAIRS -> " in the lengths between pairs of poses";
                }, rms / floor, floor * 1e3, stated,
                parameters > 0 ? String.format(Locale.ROOT, " and the %d parameters fitted", parameters) : ""));
        b.append(nothingLocated ? ", and the scan locates no structure in it." : " (where it lives is said below).");
        for (Effect e : selected)
            if (e.kind() == Effect.Kind.BACKLASH) {
                int j = e.joint() + 1;
                b.append(e.buildsUp()
                        ? String.format(Locale.ROOT, " Lost motion of joint %d is modelled as building up over the move (build-up "
                        + "length %.1f deg, from the last move before each pose); if it builds up over the travel since the last "
                        + "reversal rather than the last move, differs between the two flanks, or changes with the speed of the "
                        + "move (not in the file), that model leaves this. To tell: approach a few poses of joint %d from each side "
                        + "after moves of several sizes (0.5, 2, 10 and 30 degrees), once in one step and once in several, once "
                        + "slowly and once fast, and compare the lag.", j, Math.toDegrees(e.buildUpRad()), j)
                        : String.format(Locale.ROOT, " Lost motion of joint %d is modelled as a constant half-play; if the lag "
                        + "grows with the size of the move before each pose (friction winding up), differs between the two "
                        + "flanks or changes with the speed of the move (not in the file), a constant play leaves this. To tell: "
                        + "approach a few poses of joint %d from each side after moves of several sizes (0.5, 2, 10 and 30 "
                        + "degrees), slowly and fast, and compare the lag.", j, j));
            }
        if (selected.stream().noneMatch(e -> e.kind() == Effect.Kind.BACKLASH))
            b.append(kind == Measured.PAIRS
                    ? " Re-measure a few pairs several times to check the instrument's noise, and measure more pairs spread over "
                    + "every joint's range."
                    : " Re-measure a few poses several times to check the instrument's noise, and measure more poses spread "
                    + "over every joint's range.");
        // A length sees an error only along one line (to the anchor, or between the pair's two places).
        if (kind == Measured.ANCHOR)
            b.append(" A length to the anchor shows only the part of an error along the line to the anchor: measure the "
                    + "positions (x, y, z) of some poses, or the same poses from a second anchor, to see where the rest lives.");
        else if (kind == Measured.PAIRS)
            b.append(" A length between two poses shows only the change of an error along the line between the two places "
                    + "(what is the same at both poses is not seen): measure the positions (x, y, z) of some poses to see "
                    + "where the rest lives.");
        return b.toString();
    }

    /**
     * What the report says first when the model leaves error above the noise: what, where, what to
     * measure next. The floor is the instrument's stated one on the training poses
     * ({@code statedFloor}, m) when the file states a noise, else the noise the residuals show once
     * every structure still located is taken out.
     */
    static List<String> warnings(List<Locator.Found> left, List<Effect> selected, Fit fit, Work w, double rssLeft, int dfLeft,
                                 int poses, int dof, double statedFloor) {
        List<String> out = new ArrayList<>();
        double sigmaW = Math.sqrt(Math.max(rssLeft, 0) / Math.max(1, dfLeft)); // residual units (1 = the fit's σ)
        boolean stated = Double.isFinite(statedFloor);
        double floor = stated ? statedFloor : noiseFloor(sigmaW * w.sigmaPos, fit.problem.measurementSize());
        double rms = fit.trainRms;
        List<Locator.Found> unexplained = left;
        if (rms > 1.2 * floor || !unexplained.isEmpty()) {
            StringBuilder sb = new StringBuilder(String.format(Locale.ROOT, "The model still leaves %.4f mm RMS on the training poses "
                    + "against %s of about %.4f mm (%.2f x)", rms * 1e3, stated ? "the instrument's stated noise floor on them"
                    : "a noise floor", floor * 1e3, rms / floor));
            if (unexplained.isEmpty()) sb.append(", and no structure could be located in what is left.");
            else {
                sb.append(". It lives in: ");
                List<String> where = new ArrayList<>();
                for (Locator.Found f : unexplained) where.add(String.format(Locale.ROOT, "%s (%.4f mm)", f.probe.shape, f.sizeM * 1e3));
                sb.append(String.join("; ", where)).append('.');
            }
            out.add(sb.toString());
            // two structures may ask for the same measurement: it is said once
            for (Locator.Found f : unexplained) {
                String next = "To tell what it is: " + nextMeasurement(f, poses);
                if (!out.contains(next)) out.add(next);
            }
        }
        return out;
    }

    /**
     * The RMS error a perfect model leaves on noise of σ per component: √3 σ for a measured point
     * (the norm of three components), σ for a distance (one component).
     */
    public static double noiseFloor(double sigma, int components) { return Math.sqrt(components) * sigma; }

    private static String nextMeasurement(Locator.Found f, int poses) {
        return switch (f.probe.var) {
            case ANGLE_PERIODIC -> String.format(Locale.ROOT, "measure joint %d over its whole range in small steps with the "
                    + "other joints still (at least %d poses per cycle of the %d-cycle error); a periodic error that stays is in "
                    + "the joint's transmission.", f.probe.joint + 1, Locator.POSES_PER_HARMONIC, f.probe.harmonic);
            case LINK_PERIODIC -> Effect.isAnotherJointsAngle(f.probe.linkAngle, f.probe.joint)
                    ? String.format(Locale.ROOT, "measure joint %d's error at a few of its angles while %s turns through a whole "
                    + "turn in small steps: an error that follows %s is in the housing joint %d's drive passes through (a bearing "
                    + "seat or a gear out of round), not in joint %d's own gear.", f.probe.joint + 1, Effect.linkAngleText(f.probe.linkAngle),
                    Effect.linkAngleText(f.probe.linkAngle), f.probe.joint + 1, f.probe.joint + 1)
                    : String.format(Locale.ROOT, "measure joint %d's error over the link angle %s in small steps, "
                    + "once turning joint %d with the link angle held, once the other way round: an error that follows the link "
                    + "angle is in the linkage (its rod, lever or bearings), not the drive.", f.probe.joint + 1,
                    Effect.linkAngleText(f.probe.linkAngle), f.probe.joint + 1);
            case WARM_PERIODIC -> String.format(Locale.ROOT, "measure joint %d over its whole range in small steps cold and again "
                    + "warmed through, with the temperature at the joint recorded: an error that repeats %d times a turn and grows as it "
                    + "warms is in its encoder (its channels' gains drifting apart), not its gear.", f.probe.joint + 1, f.probe.harmonic);
            case ANGLE_SMOOTH -> String.format(Locale.ROOT, "sweep joint %d slowly through its range with the other joints still, "
                    + "in both directions, and look for a place-bound error (a damaged gear stretch, a cable or hose pulling).",
                    f.probe.joint + 1);
            case JOINT_PAIR -> String.format(Locale.ROOT, "move joint %d through its range at several fixed angles of joint %d "
                    + "(and the reverse) to map how joint %d's error depends on both; look for cross-talk between their drives, "
                    + "cables or counterbalance.", f.probe.joint + 1, f.probe.other + 1, f.probe.joint + 1);
            // with the directions recorded, the structure is there beside every named lost motion: not one of a fixed size (a
            // structure's residual deflection decays and swings after the stop, e^(−ζωt)·cos(ω_d·t), so a reading taken within a
            // second of it carries a deflection that follows the move just made; Rao, Mechanical Vibrations, §2.6)
            case DIRECTION, SETTLING -> f.probe.var == Locator.Var.SETTLING || f.probe.dirs == Directions.Source.RECORDED
                    ? "repeat a few poses, approached from each side, reading once right after the arm stops and once after "
                    + "waiting a few seconds: an error that shrinks with the wait is the arm not yet settled at the reading (a "
                    + "residual vibration after the stop, a servo's following error: wait longer before each reading), one that "
                    + "stays is a lost motion of the drive whose size changes with the load or the move."
                    : String.format(Locale.ROOT, "approach each pose of joint %d from both directions and record dir1..dirN.",
                    f.probe.joint + 1);
            case TIME, TEMPERATURE -> f.probe.joint >= 0
                    ? String.format(Locale.ROOT, "re-measure a few fixed poses of joint %d every few minutes and record the drive's "
                    + "temperature: a zero that creeps or warms up shows as a trend at the same pose.", f.probe.joint + 1)
                    : "record temp_c near the arm and near the instrument, and re-measure a fixed reference "
                    + "point every few poses to separate the instrument's drift from the arm's growth.";
            case TIME_STEP -> String.format(Locale.ROOT, "check joint %d's zero (its calibration mark or reference position) and "
                    + "the log near %.0f s for a collision or an encoder fault; re-measure a few poses from before that time.",
                    f.probe.joint + 1, f.probe.lo);
            case ANGLE_STEP -> String.format(Locale.ROOT, "move joint %d slowly across %.1f deg in small steps, in both "
                    + "directions, with the other joints still, and compare its reading with an independent measure: a jump there "
                    + "is in the encoder (an absolute encoder's code track, a misread bit) or a damaged scale.", f.probe.joint + 1,
                    Math.toDegrees(f.probe.lo));
            case STATION -> "check which instrument station read each pose (record it, or measure the poses again from one): "
                    + "the poses whose target faces one side moved together as one body, as a second station's registration error does; "
                    + "register the stations again on common targets.";
            case RANGE_STEP -> String.format(Locale.ROOT, "check the instrument's log for a broken beam near %.0f s (the arm or "
                    + "a person crossing it); keep the line of sight clear, or measure a fixed reference point after every break "
                    + "to carry the distance over.", f.probe.lo);
            case BASE_CREEP -> "check the base's anchor bolts and their torque, and measure a fixed reference point on the base and one "
                    + "on the floor before and after a few fast moves of joint 1 in each direction: a base that slips turns with them.";
            case TARGET_DRIFT -> "re-measure one pose every few minutes through the campaign, with the tool (a spindle) run as in "
                    + "production and then at rest: a tool that grows as it warms moves the point along its axis, a holder that creeps "
                    + "does not come back.";
            case TARGET_STEP -> String.format(Locale.ROOT, "check the measured target's mounting on the flange (knocked, "
                    + "slipped in its nest) and re-measure a few poses from before %.0f s; mark the target's nest and check it "
                    + "between sessions.", f.probe.lo);
            case BASE_STEP -> String.format(Locale.ROOT, "check the instrument's stand and the robot's anchors for a knock or a slip "
                    + "near %.0f s, and measure two or three fixed reference points (nests on the floor or on the robot's base) at the "
                    + "start and the end of each campaign: they move together when the instrument or the base moved.", f.probe.lo);
            case PAYLOAD_REACH -> "measure the same poses stretched and folded with two or three payloads, and check the "
                    + "stiffness of the arm and of the point's holder.";
            case PAYLOAD -> "measure with two or three payloads at the same poses to separate deflection from geometry.";
            case REACH, HEIGHT -> "measure the same poses with the arm stretched and folded and at several heights; check the "
                    + "instrument's scale and levelling, and sag of the arm or the measured point's holder.";
            case SIGHT -> f.probe.sight == Effect.Sight.RANGE
                    ? "check the instrument's distance meter against a known length at several distances (its compensation or a "
                    + "field check), then measure a few poses again with the instrument moved to another place: an error of the "
                    + "instrument moves with it, one of the robot does not."
                    : "run the instrument's two-face (front and back sight) check and its compensation, then measure a few poses "
                    + "again with the instrument moved to another place: an error of the instrument moves with it, one of the robot does not.";
            case LINK_BEND -> String.format(Locale.ROOT, "put a second target on joint %d's housing (the link's far end) and "
                    + "measure it with the link horizontal and near vertical, with and without payload: a link that bends moves "
                    + "there across itself, a joint's spring turns it about joint %d.", f.probe.joint + 2, f.probe.joint + 1);
            case GRAVITY_PLAY -> String.format(Locale.ROOT, "measure poses where the gravity torque on joint %d is small, each "
                    + "approached from both directions, and a few with two payloads: a gear's backlash follows the last motion "
                    + "there, a clearance held by the weight does not.", f.probe.joint + 1);
            case LOAD_TILT -> String.format(Locale.ROOT, "put an electronic level or a dial indicator on the link beyond joint %d and "
                    + "read its tilt across the axis with the arm held out (the drive loaded) and folded in (unloaded), and again with "
                    + "a payload: a shaft that bends under the mesh's forces tilts with the load.", f.probe.joint + 1);
            case TOOL_PULL -> "measure a few poses twice, with whatever hangs on the tool (a hose, a cable, a retractor or a "
                    + "balancer) unhooked and then hooked: a pull from outside moves the point between the two, the joints' springs "
                    + "under the arm's own weight do not.";
            case LINK_TWIST -> "put two targets on joint 3's housing, either side of the upper arm's plane, and measure them with "
                    + "the wrist turned so the tool's weight hangs to one side and then to the other, with and without payload: an "
                    + "upper arm that twists lifts one and lowers the other.";
            case TARGET_SIGHT -> "measure a few poses again with an open-air (hollow) reflector, or with the reflector turned in its "
                    + "nest toward the instrument: an error that follows the line of sight in the tool's frame is the reflector's.";
            case TOOL_PLAY -> "measure one place with the tool leaning one way and then the other, and again pointing down: a "
                    + "play taken up by the tool's weight moves the point by about the same amount whichever way it leans; tighten "
                    + "the target's nest or the tool's mount, or check the flange bearing's clearance.";
            case TOOL_GRAVITY -> "measure a few places twice, with the flange pointing down and then sideways (and the "
                    + "holder turned about the flange's axis): a holder that bends moves the point toward gravity; shorten or "
                    + "stiffen the target's holder.";
            case AXIAL_RUNOUT -> String.format(Locale.ROOT, "put a dial indicator on the link beyond joint %d, along the joint's axis, "
                    + "and read it while the joint turns slowly through its range, both ways: a bearing that runs out axially repeats "
                    + "its pattern every turn; check the bearing's preload and the seat of its races.", f.probe.joint + 1);
            case AXIS_WOBBLE -> String.format(Locale.ROOT, "put a dial indicator or an electronic level on the link beyond joint %d "
                    + "and read its tilt across the axis while the joint turns slowly through its range, both ways: a bearing that "
                    + "wobbles repeats its pattern every turn; check the bearing's preload.", f.probe.joint + 1);
            case BASE_MOMENT -> "check the anchor bolts' torque and the base plate's grout, then put a second target (or an "
                    + "inclinometer) on the robot's foot and read it while the arm swings stretched out around joint 1 with a payload: "
                    + "a base that rocks moves there, a joint that gives way does not.";
        };
    }

    /** Whether the payload varies over the rows by 0.1 kg or more. */
    static boolean payloadVaries(List<Measurement> rows) {
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
        for (Measurement r : rows) {
            double kg = r.payloadKg();
            if (!Double.isFinite(kg)) continue;
            lo = Math.min(lo, kg);
            hi = Math.max(hi, kg);
        }
        return hi - lo >= 0.1;
    }

    /**
     * Where many poses lie beyond the calibration's outlier rule (a structure the geometry leaves), those
     * beyond this many robust sigmas of the geometric fit are still gross readings (a tracker's beam broken
     * and caught again, a target out of its nest: millimetres against a structure's tenths), when they are
     * at most {@link #MAX_GROSS} or 5 % of the poses; more than that far out is a structure too. On the
     * clean-room IRB 2400 campaigns of set G, three and five gross readings of 1-3 mm stood 21-68 robust
     * sigmas out beside poses of an unmodelled compliance or growth at 5-8, and kept they left the
     * diagnosis at 5.8-12.5 × the floor with nothing found.
     */
    static final double GROSS_SIGMAS = 20;
    /**
     * The most gross readings taken from among many poses beyond the rule (or 5 % of the poses), and
     * so the fewest poses beyond it that are too many to be bad readings: a small campaign may hold
     * five (set K's K37, five among 37 poses beside an arm's sag, four beyond the rule: taken for a
     * structure at the 5 % line, none was left out and nothing was found).
     */
    static final int MAX_GROSS = 5;

    /**
     * What a model without error leaves with p parameters fitted to n measured components, as a share
     * of the noise: √(1 − p/n) on the training poses, √(1 + p/n) on new ones (one length per pose
     * carries ten times the relative share of the parameters a point does; unaccounted, a null
     * campaign of lengths comes out near 1.2 x σ on new poses).
     */
    static double perfectShare(Fit f, boolean onValidation) {
        int components = f.m / f.problem.rowsPerPose() * f.problem.positionRowsPerPose();
        return Math.sqrt(Math.max(0.05, 1 + (onValidation ? 1 : -1) * (double) f.nf / Math.max(1, components)));
    }

    /** Whether {@code fit}'s effects and geometry, refitted without the training poses {@code leftOut}, still miss the stated floor. */
    private static boolean shortWithout(Work w, Fit fit, List<Effect> selected, Map<Effect, boolean[]> absorbedCols, List<String> leftOut,
                                        CalibrationResult geo, double stated, Measured kind) {
        Set<String> out = new HashSet<>(leftOut);
        Work wu = new Work(w.model, w.gravity, w.rows.stream().filter(m -> !out.contains(m.poseId())).toList(), geo, w.validate, w.o,
                w.sigmaPos, w.sigmaRot);
        Fit fu = wu.fit(selected, absorbedCols, fit.full, null);
        double vu = wu.validateRms(fu);
        return shortOfFloor(Double.isFinite(vu) ? vu : fu.trainRms, stated, kind, perfectShare(fu, Double.isFinite(vu)));
    }

    /** Whether a held-out RMS error (m) is beyond {@link #STATED_FLOOR_MARGIN} times the stated noise's floor (false without one). */
    static boolean shortOfFloor(double heldOutRms, double stated, Measured kind, double perfect) {
        return Double.isFinite(stated) && heldOutRms > STATED_FLOOR_MARGIN * perfect * noiseFloor(stated, kind.components);
    }

    /**
     * The poses beyond the outlier rule, when there are at least {@link #MIN_RUN} of them and they were
     * measured one after another among the training poses {@code rows} (in time): their ids in time
     * order, else none. Bad readings fall on poses at random; a run in time is a change at one time.
     */
    static List<String> runInTime(List<CalibrationResult.Outlier> beyond, List<Measurement> rows) {
        if (beyond.size() < MIN_RUN || !rows.stream().allMatch(m -> Double.isFinite(m.timeS()))) return List.of();
        Set<String> ids = new HashSet<>();
        for (CalibrationResult.Outlier ol : beyond) ids.add(ol.poseId());
        List<Measurement> byTime = rows.stream().sorted(java.util.Comparator.comparingDouble(Measurement::timeS)).toList();
        int first = -1, last = -1;
        for (int i = 0; i < byTime.size(); i++)
            if (ids.contains(byTime.get(i).poseId())) { if (first < 0) first = i; last = i; }
        if (first < 0 || last - first + 1 != ids.size()) return List.of();
        return byTime.subList(first, last + 1).stream().map(Measurement::poseId).toList();
    }

    /** The chance that g poses picked at random among n are one after another: (n − g + 1) / C(n, g). */
    static double runChance(int g, int n) {
        double c = n - g + 1;
        for (int i = 0; i < g; i++) c *= (double) (i + 1) / (n - i);
        return c;
    }

    /** The fewest poses beyond the outlier rule that {@link #runInTime} takes for a run: fewer fall together by chance too often. */
    static final int MIN_RUN = 3;

    /** Whether {@code beyond} poses beyond the outlier rule among {@code poses} are too many to be bad readings (more than {@link #MAX_GROSS} and 5 %). */
    static boolean tooManyToBeBad(int beyond, int poses) { return beyond > Math.max(MAX_GROSS, 0.05 * poses); }

    /**
     * The gross readings among poses beyond the outlier rule (of {@code poses}): the farthest out,
     * each beyond {@link #GROSS_SIGMAS} robust sigmas, down to the widest gap where the next pose out
     * (or the rule) is less than half as far, at most {@link #MAX_GROSS} or 5 % of the poses. Gross
     * readings scatter far out; a structure's poses form a band (the poses approached from the other
     * side of a lost motion stood at 17.8-21.8 robust sigmas, all alike), so a cut through the band
     * takes none. Of several such gaps the deepest cut that keeps the cap is taken (readings at 69
     * and 68 sigmas above two at 28 and 17: the two far ones, then the rule sees the other two).
     */
    static List<CalibrationResult.Outlier> grossAmong(List<CalibrationResult.Outlier> flagged, int poses) {
        List<CalibrationResult.Outlier> sorted = new ArrayList<>(flagged);
        sorted.sort(java.util.Comparator.comparingDouble(ol -> -ol.residualM() / ol.robustSigmaM()));
        int cap = (int) Math.max(MAX_GROSS, 0.05 * poses), cut = 0;
        for (int k = 1; k <= Math.min(cap, sorted.size()); k++) {
            double zk = sorted.get(k - 1).residualM() / sorted.get(k - 1).robustSigmaM();
            if (!(zk > GROSS_SIGMAS)) break;
            double next = k < sorted.size() ? sorted.get(k).residualM() / sorted.get(k).robustSigmaM() : OUTLIER_K;
            if (zk >= 2 * Math.max(next, OUTLIER_K)) cut = k;
        }
        return sorted.subList(0, cut);
    }

    /** A cyclic error of the instrument's reading is refined with at most this many harmonics of its cycle. */
    static final int MAX_CYCLE_ORDERS = 4;

    /** At most this many structures are located per scan. */
    static final int MAX_LOCATED = 8;
    /** An alias replaces a named effect when its leave-one-pose-out error is lower by this fraction. */
    static final double ALIAS_MARGIN = 0.02;

    /**
     * The solver's starting damping for a refit with effects ({@link LevenbergMarquardt#initialDamping}):
     * every refit starts from a fit of the same data (the geometric one or one with an effect more or
     * less), so the steps may be Gauss-Newton's from the first; at the default 1e-3 a refit took 10-15
     * accepted steps where 3-5 converge to the same point.
     */
    static final double NEAR_START_DAMPING = 1e-6;

    /**
     * The factor by which the ratio of the rotation rows' noise to the position rows' that the selected model leaves may
     * differ from the one the residuals were weighted with before the diagnosis is redone with it (see {@link #run}).
     */
    static final double REWEIGHT = 1.5;

    /**
     * Whether BIC a is lower than b by more than rounding: two candidates that fit the same columns
     * (a re-estimated mass model of which only the file's shape is left, say) tie, and the one tried
     * first, the simpler form, stays.
     */
    static boolean lowerBic(double a, double b) { return a < b - 1e-9 * Math.max(1, Math.abs(b)); }

    /**
     * Beside a structure of another drive that follows its joint ({@link #sharedWithAnotherDrive}), a
     * family whose shape its own fallback holds is claimed only when it predicts left-out poses better
     * than that fallback by this fraction: one load across the joints (a dress pack) gives the joint
     * the family's shape exactly where it acts as a spring, so a fit a few per cent better is no sign of
     * the family (set K's K01: a dress pack's bend named a scale error of joint 5 at 2.8 % better).
     */
    static final double SHARED_MARGIN = 0.1;

    /** Families the located structures call for: harmonics found on a joint, the smooth fallback, and the wider families. */
    static List<Effect> fromLocated(List<Locator.Found> found, KinematicModel model, List<Measurement> rows, GravityTorques gravity,
                                    double t0C, boolean hasTemp, boolean hasTime) {
        List<Effect> out = new ArrayList<>();
        int dof = model.dof();
        for (int j = 0; j < dof; j++) {
            java.util.TreeSet<Integer> hs = new java.util.TreeSet<>();
            List<Double> stages = new ArrayList<>(); // orders that are not whole (the stage-frequency scan)
            boolean any = false;
            for (Locator.Found f : found) {
                if (f.probe.joint != j) continue;
                if (f.probe.var == Locator.Var.ANGLE_PERIODIC || f.probe.var == Locator.Var.ANGLE_SMOOTH) any = true;
                if (f.probe.var == Locator.Var.ANGLE_PERIODIC && f.probe.order > 0) stages.add(f.probe.order);
                else if (f.probe.var == Locator.Var.ANGLE_PERIODIC) hs.add(f.probe.harmonic);
                if (f.probe.var == Locator.Var.ANGLE_SMOOTH && f.sparseClaim()) for (int h : f.sparse) hs.add(h);
                if (f.probe.var == Locator.Var.JOINT_PAIR) {
                    out.add(Effect.pair(j, f.probe.other));
                    // where the linkage makes the joint's angle in the arm of the two (θ3 = q3 − q2 on a parallel arm), the same
                    // structure as one curve of that angle: a parallel arm's rod or lever of the wrong length turns the forearm by a
                    // non-linear function of θ3 (the four-bar closure; Norton, Design of Machinery, §4.5)
                    Effect own = ownModelAngleSmooth(j, f.probe.other, model, rows);
                    if (own != null && out.stream().noneMatch(x -> x.label().equals(own.label()))) out.add(own);
                }
                if (f.probe.var == Locator.Var.ANGLE_STEP) out.add(stepEffect(f.probe.var, j, f.probe.lo, model));
                // (a structure in the joint's direction brings the lost motion, its family, with the settling as its rival only: a
                // candidate, the settling would take part of a play before the family is tried)
                if (f.probe.var == Locator.Var.SETTLING && f.probe.settling != null) out.add(f.probe.settling);
            }
            // two steps of one joint's reading: the reading may be off over the window between them (a step up and back)
            final int jw = j;
            List<Double> places = found.stream().filter(f -> f.probe.joint == jw && f.probe.var == Locator.Var.ANGLE_STEP)
                    .map(f -> f.probe.lo).sorted().toList();
            for (int a = 0; a < places.size(); a++)
                for (int b = a + 1; b < places.size(); b++)
                    if (places.get(b) > places.get(a)) out.add(Effect.angleWindow(j, places.get(a), places.get(b)));
            // a shaft's orders (above the output's own) are a shape of their own, never part of a gear's error
            for (int h : hs.tailSet((int) Effect.SHAFT_ORDER, false)) stages.add((double) h);
            hs.removeIf(h -> h > Effect.SHAFT_ORDER);
            if (!stages.isEmpty()) out.add(Effect.periodic(j, new int[0], stages.stream().mapToDouble(Double::doubleValue).toArray()));
            if (!hs.isEmpty() && hs.last() > Effect.HARMONICS) {
                int[] h = hs.stream().mapToInt(Integer::intValue).toArray();
                out.add(Effect.periodic(j, h));
                java.util.TreeSet<Integer> withLow = new java.util.TreeSet<>(hs);
                for (int i = 1; i <= Effect.HARMONICS; i++) withLow.add(i);
                out.add(Effect.periodic(j, withLow.stream().mapToInt(Integer::intValue).toArray()));
            }
            if (any) {
                double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
                for (Measurement r : rows) { lo = Math.min(lo, r.q(j)); hi = Math.max(hi, r.q(j)); }
                if (hi > lo) out.add(Effect.smooth(j, lo, hi));
            }
            // the masses re-estimated and, with payload steps, also the masses and their centres unknown (a centre off the
            // file's moves the torque's phase); where the linkage makes them differ, the joint's own angle giving beside its
            // drive's gear
            if (gravity != null)
                for (GravityTorques g : gravity.massesUnknown() ? List.of(gravity) : List.of(gravity, GravityTorques.massesUnknown(model))) {
                    Effect remassed = Effect.complianceRemassed(j, g);
                    if (!remassed.testableOn(rows)) continue;
                    out.add(remassed);
                    if (Effect.atJointDiffers(model, j)) out.add(Effect.complianceAtJoint(j, g, true));
                }
        }
        if (hasTemp) {
            out.add(Effect.thermalLinks(model, t0C));
            out.add(Effect.driftWithTemperature(t0C));
        }
        if (hasTime) out.add(Effect.driftWithTime());
        // a joint's zero that moves with time under a recorded payload may be the carried mass changing while the file records
        // one (a dispensing tool emptying): the payload's torque on the joint following the time (the whole torque's change, a
        // joint softening as it warms, is tried in a located zero drift's place and against a named compliance)
        if (gravity != null && rows.stream().anyMatch(r -> r.payloadKg() > 0))
            for (Locator.Found f : found)
                if (f.probe.var == Locator.Var.TIME && f.probe.joint >= 0 && f.probe.hi > f.probe.lo && loaded(gravity, f.probe.joint, rows))
                    withPayloadCentre(Effect.complianceVarying(f.probe.joint, gravity, Effect.Along.TIME, f.probe.lo, f.probe.hi,
                            Effect.POINT_BASIS, true), rows, out);
        // a zero, the target or the base stepping at moments under a recorded payload may be the carried mass changing at those
        // moments (a dispensing tool's shots, a part dropped): the payload's torque on each loaded joint, its compliance stepping there
        if (gravity != null && rows.stream().anyMatch(r -> r.payloadKg() > 0)) {
            double[] times = stepPlaces(found.stream().filter(f -> f.probe.var == Locator.Var.TIME_STEP || f.probe.var == Locator.Var.TARGET_STEP
                    || f.probe.var == Locator.Var.BASE_STEP).mapToDouble(f -> f.probe.lo), rows);
            if (times.length > 0)
                for (int j = 0; j < dof; j++) if (loaded(gravity, j, rows)) withPayloadCentre(Effect.complianceInSteps(j, gravity, times), rows, out);
        }
        for (Locator.Found f : found) {
            if (f.probe.var == Locator.Var.TARGET_STEP || f.probe.var == Locator.Var.BASE_STEP)
                out.add(stepEffect(f.probe.var, f.probe.joint, f.probe.lo, model));
            if (f.probe.var == Locator.Var.RANGE_STEP) out.add(Effect.rangeStep(f.probe.instrument, f.probe.lo));
            if (f.probe.var == Locator.Var.STATION) out.add(f.probe.station != null ? f.probe.station : Effect.secondStation(model, f.probe.facing));
        }
        // an error of the instrument's readings: modelled where it is located, so that it does not bend the robot's fit
        for (Locator.Found f : found) if (f.probe.var == Locator.Var.SIGHT) out.add(sightEffect(f.probe));
        // the base giving way under the arm's moment: the tilt searched where it was located
        for (Locator.Found f : found) if (f.probe.var == Locator.Var.BASE_MOMENT && f.probe.tilt != null) out.add(f.probe.tilt);
        out.addAll(bodyShapes(found, model));
        for (Locator.Found f : found)
            if (f.probe.var == Locator.Var.REACH || f.probe.var == Locator.Var.HEIGHT)
                out.add(Effect.pointSmooth(f.probe.var == Locator.Var.HEIGHT ? Effect.Along.HEIGHT : Effect.Along.REACH, f.probe.lo, f.probe.hi));
        return out;
    }

    /**
     * The payload's varying compliance of drive {@code joint} with time over lo..hi (s), at each
     * resolution the poses support (4 and 7 functions).
     */
    static List<Effect> payloadSplines(int joint, GravityTorques g, double lo, double hi, List<Measurement> rows) {
        List<Effect> out = new ArrayList<>();
        for (int nb : INSTRUMENT_SCALE_RESOLUTIONS)
            if (Effect.supported(nb, Effect.POINT_BASIS, rows.size())) out.add(Effect.complianceVarying(joint, g, Effect.Along.TIME, lo, hi, nb, true));
        return out;
    }

    /**
     * A payload's varying compliance {@code e} into {@code out}, and beside it the same with the payload's
     * centre estimated ({@link Effect#withPayloadCentreFree}) where the poses support its columns.
     */
    static void withPayloadCentre(Effect e, List<Measurement> rows, List<Effect> out) {
        out.add(e);
        Effect free = Effect.withPayloadCentreFree(e);
        if (Effect.supported(free.size(), 1, rows.size())) out.add(free);
    }

    /**
     * The moments (s, rising) of steps located at {@code places}, those within {@link #STEP_MERGE_SHARE}
     * of the campaign's time span of an earlier one taken as the same step.
     */
    static double[] stepPlaces(java.util.stream.DoubleStream places, List<Measurement> rows) {
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
        for (Measurement r : rows) if (Double.isFinite(r.timeS())) { lo = Math.min(lo, r.timeS()); hi = Math.max(hi, r.timeS()); }
        double gap = STEP_MERGE_SHARE * (hi - lo);
        double[] sorted = places.filter(Double::isFinite).sorted().toArray();
        List<Double> out = new ArrayList<>();
        for (double t : sorted) if (out.isEmpty() || t - out.get(out.size() - 1) > gap) out.add(t);
        return out.stream().mapToDouble(Double::doubleValue).toArray();
    }

    /** Share of the campaign's time span within which two located steps are taken as one. */
    static final double STEP_MERGE_SHARE = 0.01;

    /**
     * The effect of a step located in {@code var} at {@code place}: a reading's step in joint
     * {@code joint}'s angle (rad), that joint's zero stepping at a time (s), or the target's move at a
     * time (s).
     */
    static Effect stepEffect(Locator.Var var, int joint, double place, KinematicModel model) {
        return switch (var) {
            case ANGLE_STEP -> Effect.angleStep(joint, place);
            case TIME_STEP -> Effect.zeroStep(joint, place);
            case TARGET_STEP -> Effect.targetStep(model, place);
            case BASE_STEP -> Effect.baseStep(place);
            default -> throw new IllegalArgumentException("not a step: " + var);
        };
    }

    /**
     * The fallbacks of located structures, which every angle family must beat (docs/diagnosis.md
     * "Never a wrong claim"): a joint's smooth error at the resolution it was located with, the
     * two-joint error, the point's displacement with reach or height. The finer smooth resolutions
     * are rivals only, not stepwise candidates: with many functions they would take a gear's few
     * harmonics before the periodic family is tried.
     */
    static List<Effect> locatedFallbacks(List<Locator.Found> found, List<Measurement> rows, KinematicModel model) {
        List<Effect> out = new ArrayList<>();
        for (Locator.Found f : found)
            switch (f.probe.var) {
                case ANGLE_SMOOTH -> out.add(Effect.smooth(f.probe.joint, f.probe.lo, f.probe.hi, f.probe.basis));
                case JOINT_PAIR -> out.add(Effect.pair(f.probe.joint, f.probe.other));
                case REACH, HEIGHT -> out.add(Effect.pointSmooth(f.probe.var == Locator.Var.HEIGHT ? Effect.Along.HEIGHT : Effect.Along.REACH,
                        f.probe.lo, f.probe.hi));
                case TIME_STEP, ANGLE_STEP, TARGET_STEP, BASE_STEP -> out.add(stepEffect(f.probe.var, f.probe.joint, f.probe.lo, model));
                case RANGE_STEP -> out.add(Effect.rangeStep(f.probe.instrument, f.probe.lo));
                case STATION -> out.add(f.probe.station != null ? f.probe.station : Effect.secondStation(model, f.probe.facing));
                case PAYLOAD_REACH -> out.add(Effect.pointSmooth(Effect.Along.PAYLOAD_REACH, f.probe.lo, f.probe.hi));
                case SIGHT -> out.add(sightEffect(f.probe));
                case BASE_MOMENT -> { if (f.probe.tilt != null) out.add(f.probe.tilt); }
                case DIRECTION, SETTLING -> { if (f.probe.settling != null) out.add(f.probe.settling); }
                case GRAVITY_PLAY -> {
                    // the torque's sign follows the joint's angle closely: the structure is a curve of that angle too, the rival a
                    // family of the joint (its spring under the same torque) must beat as before
                    out.add(f.probe.play);
                    int j = f.probe.joint;
                    double lo = rows.stream().mapToDouble(r -> r.q(j)).min().orElse(0), hi = rows.stream().mapToDouble(r -> r.q(j)).max().orElse(0);
                    if (hi > lo) out.add(Effect.smooth(j, lo, hi, Effect.SMOOTH_BASIS));
                }
                case TARGET_DRIFT -> out.add(Effect.targetDrift(model, f.probe.lo, f.probe.hi, f.probe.basis));
                case BASE_CREEP -> out.add(f.probe.creep);
                case AXIS_WOBBLE, AXIAL_RUNOUT, TOOL_GRAVITY, TOOL_PLAY, LINK_BEND, LINK_TWIST, TARGET_SIGHT, TOOL_PULL, LOAD_TILT -> { }
                case TIME, TEMPERATURE -> {
                    Effect.Along a = f.probe.var == Locator.Var.TIME ? Effect.Along.TIME : Effect.Along.TEMPERATURE;
                    if (f.probe.joint >= 0) out.add(Effect.zeroDrift(f.probe.joint, a, f.probe.lo, f.probe.hi));
                    else if (!f.probe.lengths) out.add(Effect.pointSmooth(a, f.probe.lo, f.probe.hi));
                }
                default -> { }
            }
        out.addAll(bodyShapes(found, model));
        return out;
    }

    /** Whether the tool's play was located with the flange's tips (its orientation measured). */
    private static boolean playTips(List<Locator.Found> found) {
        return found.stream().anyMatch(f -> f.probe.var == Locator.Var.TOOL_PLAY && f.probe.k > Effect.PLAY_SHIFTS);
    }

    /** The orders (ascending, each once) at which structures of {@code var} were located on joint {@code j}. */
    private static int[] ordersFound(List<Locator.Found> found, Locator.Var var, int j) {
        return found.stream().filter(f -> f.probe.var == var && f.probe.joint == j).mapToInt(f -> f.probe.harmonic).distinct().sorted().toArray();
    }

    /**
     * The fallbacks of the arm's bodies giving way where they were located: each joint's axis wobble and
     * axial runout at every order located for it (one effect of each per joint), the tool's sag and
     * play, each link's bending.
     */
    static List<Effect> bodyShapes(List<Locator.Found> found, KinematicModel model) {
        List<Effect> out = new ArrayList<>();
        for (int j = 0; j < model.dof(); j++) {
            // each angle the joint's error was located to repeat with, at every order located for it
            final int jj = j;
            List<double[]> angles = new ArrayList<>();
            for (Locator.Found f : found)
                if (f.probe.var == Locator.Var.LINK_PERIODIC && f.probe.joint == j && angles.stream().noneMatch(a -> Arrays.equals(a, f.probe.linkAngle)))
                    angles.add(f.probe.linkAngle);
            for (double[] angle : angles) {
                int[] links = found.stream().filter(f -> f.probe.var == Locator.Var.LINK_PERIODIC && f.probe.joint == jj
                        && Arrays.equals(f.probe.linkAngle, angle)).mapToInt(f -> f.probe.harmonic).distinct().sorted().toArray();
                out.add(Effect.linkPeriodic(j, angle, links));
            }
            int[] warm = ordersFound(found, Locator.Var.WARM_PERIODIC, j);
            if (warm.length > 0) {
                Locator.Found f = found.stream().filter(x -> x.probe.var == Locator.Var.WARM_PERIODIC && x.probe.joint == jj).findFirst().orElseThrow();
                out.add(Effect.periodicWarming(j, warm, f.probe.lo, f.probe.hi));
            }
            int[] tilts = ordersFound(found, Locator.Var.AXIS_WOBBLE, j), shifts = ordersFound(found, Locator.Var.AXIAL_RUNOUT, j);
            if (tilts.length > 0) out.add(Effect.axisWobble(model, j, tilts));
            if (shifts.length > 0) out.add(Effect.axialRunout(model, j, shifts));
        }
        if (found.stream().anyMatch(f -> f.probe.var == Locator.Var.TOOL_GRAVITY)) out.add(Effect.toolSag(model, Effect.DOWN));
        if (found.stream().anyMatch(f -> f.probe.var == Locator.Var.TOOL_PLAY)) out.add(Effect.toolPlay(model, Effect.DOWN, playTips(found)));
        for (Locator.Found f : found) if (f.probe.var == Locator.Var.LINK_BEND || f.probe.var == Locator.Var.LINK_TWIST) out.add(f.probe.bend);
        for (Locator.Found f : found) if (f.probe.var == Locator.Var.TARGET_SIGHT) out.add(f.probe.incidence);
        for (Locator.Found f : found) if (f.probe.var == Locator.Var.TOOL_PULL && f.probe.pull != null) out.add(f.probe.pull);
        for (Locator.Found f : found) if (f.probe.var == Locator.Var.LOAD_TILT) out.add(f.probe.bend);
        return out;
    }

    /**
     * A base tilt in a family's place whose leave-one-pose-out error with the file's masses is this many
     * times the family's is not refined further (re-estimating the masses moves it by a few per cent).
     */
    static final double RIVAL_TILT_HOPELESS = 1.5;

    /** Azimuths of a base tilt's axis tried (every 15°), and the shares of the poses it tilts at (1: both ways, no hold). */
    static final int TILT_AZIMUTHS = 24;
    static final double[] TILT_SHARES = {1, 0.9, 0.75, 0.5, 0.3, 0.15};

    /**
     * The base tilting on its foundation ({@link Effect#baseTilt}) that predicts left-out poses best
     * in the place of selected family {@code k}: its axis every 15° and the moment it holds before
     * tilting (the shares of the poses it tilts at), for a family of drives 1–3 (a base that rocks
     * under the arm's weight turns everything as a compliance, a coupling or a transmission error
     * of the arm's first joints partly would); null without the robot file's masses. With {@code k}
     * negative ({@code e} null), the tilt added to the model as fitted: the shape of a base moment
     * located ({@link Locator#baseMoment}).
     */
    static Effect bestBaseTilt(Tester at, int k, Effect e, GravityTorques gravity, List<Measurement> rows, List<PoseConditions> conds) {
        if (gravity == null || gravity.massesUnknown() || at.ends > 1) return null;
        if (k >= 0 && (e.target() != Effect.Target.DRIVE || e.joint() > 2)) return null;
        double[] tilt = tiltSearch(at, k, gravity, rows, null); // press, axis azimuth, share of the poses tilted, edges
        if (!Double.isFinite(tilt[0])) return null;
        double[] scales = null;
        // a rival far behind the family keeps the file's masses: they are not worth the search
        if (k < 0 || tilt[0] <= RIVAL_TILT_HOPELESS * at.pressFull()) {
            // Each mass of the arm scaled in turn at that axis and share (a data sheet's masses are rarely better than ±30 %);
            // re-estimated masses are kept only when they predict left-out poses clearly better than the file's.
            double[] sc = new double[gravity.massCount()];
            Arrays.fill(sc, 1);
            double pr = tilt[0];
            for (int round = 0; round < 2; round++)
                for (int m = 0; m < sc.length; m++) {
                    if (m == gravity.payloadIndex() || gravity.massKg(m) == 0) continue;
                    double keep = sc[m], bestF = keep;
                    for (double f : HELD_MASS_SCALES) {
                        if (f == keep) continue;
                        sc[m] = f;
                        double p = tiltPress(at, k, moments(gravity.withMassScales(sc), rows), tilt[1], tilt[2], (int) tilt[3]);
                        if (p < pr) { pr = p; bestF = f; }
                    }
                    sc[m] = bestF;
                }
            if (pr < tilt[0] * (1 - ALIAS_MARGIN)) {
                double[] again = tiltSearch(at, k, gravity.withMassScales(sc), rows, tilt); // the axis and hold again, with those masses
                if (again[0] < pr) tilt = again;
                else tilt[0] = pr;
                scales = sc;
            }
        }
        GravityTorques g = scales == null ? gravity : gravity.withMassScales(scales);
        double hold = tiltHold(moments(g, rows), tilt[1], tilt[2], (int) tilt[3]);
        return tilt[3] == 4 ? Effect.squareFootTilt(gravity, tilt[1], hold, scales) : Effect.baseTilt(gravity, tilt[1], hold, scales);
    }

    /**
     * The base tilt's foot, axis and hold that predict left-out poses best with masses {@code g}: one
     * edge at every {@link #TILT_AZIMUTHS}th of a turn, a square foot's edges every 15° of a quarter
     * turn, and a foot that rocks toward the lean, each at the {@link #TILT_SHARES}; then the best
     * one's neighbours (a quarter and a half of the grid's step either side, and the shares between);
     * from {@code start} only its neighbours. Returns {press, azimuth (NaN: toward the lean), share,
     * edges}.
     */
    private static double[] tiltSearch(Tester at, int k, GravityTorques g, List<Measurement> rows, double[] start) {
        double[][] mom = moments(g, rows);
        double[] best = start == null ? new double[] {Double.POSITIVE_INFINITY, 0, 1, 1} : start.clone();
        if (start != null) best[0] = tiltPress(at, k, mom, best[1], best[2], (int) best[3]);
        double step = 2 * Math.PI / TILT_AZIMUTHS;
        if (start == null) {
            for (int a = 0; a < TILT_AZIMUTHS; a++)
                for (double share : TILT_SHARES) tryTilt(at, k, mom, a * step, share, 1, best);
            for (int a = 0; a < TILT_AZIMUTHS / 4; a++)
                for (double share : TILT_SHARES) if (share < 1) tryTilt(at, k, mom, a * step, share, 4, best);
            for (double share : TILT_SHARES) tryTilt(at, k, mom, Double.NaN, share, 1, best);
        }
        double b = best[2];
        double[] shares = b >= 1 ? new double[] {1} : new double[] {b * 0.8, b * 0.9, b, Math.min(0.97, b * 1.1), Math.min(0.97, b * 1.25)};
        if (Double.isNaN(best[1])) {
            for (double share : shares) tryTilt(at, k, mom, Double.NaN, share, 1, best);
            return best;
        }
        double psi = best[1];
        int edges = (int) best[3];
        for (double dp : new double[] {-step / 2, -step / 4, 0, step / 4, step / 2})
            for (double share : b >= 1 ? TILT_SHARES : shares)
                if (edges == 1 || share < 1) tryTilt(at, k, mom, psi + dp, share, edges, best);
        return best;
    }

    private static void tryTilt(Tester at, int k, double[][] mom, double psi, double share, int edges, double[] best) {
        double p = tiltPress(at, k, mom, psi, share, edges);
        if (p < best[0]) { best[0] = p; best[1] = psi; best[2] = share; best[3] = edges; }
    }

    /** The moment the base holds before it tilts: tilting at {@code share} of the poses (1: none; −∞ for one edge, both ways). */
    static double tiltHold(double[][] mom, double psi, double share, int edges) {
        if (share >= 1) return Double.isNaN(psi) || edges > 1 ? 0 : Double.NEGATIVE_INFINITY;
        double[] x = new double[mom.length];
        for (int i = 0; i < x.length; i++) x[i] = Effect.tiltAt(mom[i][0], mom[i][1], psi, edges)[2];
        Arrays.sort(x);
        return x[(int) Math.floor((1 - share) * (x.length - 1))];
    }

    /** Each row's moment of the arm's weight and payload (masses {@code g}) about the base origin (N·m, base frame). */
    static double[][] moments(GravityTorques g, List<Measurement> rows) {
        double[][] m = new double[rows.size()][];
        for (int i = 0; i < m.length; i++) {
            Measurement r = rows.get(i);
            m[i] = g.baseMoment(r.q(), Double.isFinite(r.payloadKg()) ? r.payloadKg() : 0).toArray();
        }
        return m;
    }

    /**
     * The leave-one-pose-out error with the base tilt ({@link Effect#tiltAt}: azimuth {@code psi}, NaN
     * toward the lean; {@code edges} 1 or 4), tilting at {@code share} of the poses, in the place of
     * selected effect {@code k} (negative: added): its columns, the regressor through each row's
     * translation sensitivity, and with orientations the frame's turn.
     */
    private static double tiltPress(Tester at, int k, double[][] mom, double psi, double share, int edges) {
        double[] sig = tiltColumns(at, mom, psi, tiltHold(mom, psi, share, edges), edges, Effect.TILT_COLUMNS);
        if (sig == null) return Double.POSITIVE_INFINITY;
        return k >= 0 ? at.pressReplacingColumns(k, sig, Effect.TILT_COLUMNS) : at.pressAddingColumns(sig, Effect.TILT_COLUMNS);
    }

    /**
     * The base tilt's first {@code k} signature columns of its {@link Effect#TILT_COLUMNS} (m x k,
     * row-major; {@link Effect#tiltAt}: azimuth {@code psi}, NaN toward the lean; {@code edges} 1 or 4)
     * holding {@code hold}: its regressor through each row's translation sensitivity, and with
     * orientations the frame's turn; null when no pose tilts.
     */
    static double[] tiltColumns(Tester at, double[][] mom, double psi, double hold, int edges, int k) {
        int n = Effect.TILT_COLUMNS;
        double[] sig = new double[at.m * k], g3 = new double[3 * n], dt = at.endDTrans[0], dr = at.endDRot[0];
        boolean any = false;
        for (int i = 0; i < mom.length; i++) {
            double[] t = Effect.tiltAt(mom[i][0], mom[i][1], psi, edges);
            double xt = Double.isInfinite(hold) ? t[2] : Math.max(0, t[2] - hold);
            if (xt == 0) continue;
            any = true;
            for (int a = 0; a < at.posRows; a++) {
                int row = i * at.rpp + a;
                Effect.tiltRegressor(xt, t[0], t[1], at.pointsBase[i][at.pointOfRow(a)], g3);
                for (int col = 0; col < k; col++)
                    sig[row * k + col] = dt[row * 3] * g3[col] + dt[row * 3 + 1] * g3[n + col] + dt[row * 3 + 2] * g3[2 * n + col];
            }
            // orientation rows: the measured frame turns with the base by the tilt x·e (the lift and the slide turn nothing)
            for (int a = at.posRows; a < at.rpp; a++) {
                int row = i * at.rpp + a;
                sig[row * k] = xt * (dr[row * 3] * t[0] + dr[row * 3 + 1] * t[1]);
            }
        }
        return any ? sig : null;
    }

    /** The instrument-reading fallback of an instrument probe ({@link Locator#sightProbes}). */
    static Effect sightEffect(Locator.Probe p) {
        if (p.cycle > 0) return Effect.instrumentCyclic(p.sight, p.instrument, p.azimuthRef, p.lo, p.hi, p.cycle, p.cycleOrders);
        return Effect.instrumentReading(p.sight, p.instrument, p.azimuthRef, p.lo, p.hi, p.basis);
    }

    /**
     * The instrument's own errors at every resolution the poses support, as rivals of every family
     * (positions in the instrument's frame only): an error of a tracker's distance meter or angle
     * encoder follows the instrument's readings, which over the workspace seen from metres away are
     * correlated with joint 1's angle and with the point's reach, so a family of the robot that holds
     * part of it must predict left-out poses better than the instrument's error in its place.
     */
    static List<Effect> instrumentRivals(Tester t, List<PoseConditions> conds) {
        List<Effect> out = new ArrayList<>();
        // the splines, and the few periods of a distance meter's cycle the residual holds most of
        List<Locator.Probe> periods = new ArrayList<>();
        for (Locator.Probe p : Locator.sightProbes(t, true, false)) {
            // (the cycles alone: a located cycle's fallback brings its harmonics, and is a rival as every located structure's is)
            if (p.cycle > 0) { if (p.cycleOrders == 1) periods.add(p); }
            else out.add(sightEffect(p));
        }
        if (periods.size() > INSTRUMENT_CYCLES_TRIED) {
            // the periods ranked by their F test on the residual as it is (a k x k cost each); the best few are fitted
            double[] res = t.residualOutOf(new double[0], 0);
            double rss = t.rssOutOf(new double[0], 0);
            Map<Locator.Probe, Double> p0 = new java.util.IdentityHashMap<>();
            for (Locator.Probe p : periods) {
                double pv = p.raw == null ? 0 : new Locator.Gram(p).p(t, res, rss, 0);
                p0.put(p, Double.isNaN(pv) ? 1 : pv);
            }
            periods.sort((a, b) -> Double.compare(p0.get(a), p0.get(b)));
            periods = periods.subList(0, INSTRUMENT_CYCLES_TRIED);
        }
        // the beam bent by the air's temperature gradient as it changes through the campaign
        if (t.w.instrument && t.ends == 1) {
            org.robopro.kinematics.Pose inst = t.fit.problem.instrumentOf(t.fit.full);
            double[] time = timeSpan(conds), temp = tempSpan(conds);
            for (int nb : INSTRUMENT_SCALE_RESOLUTIONS) {
                if (!Effect.supported(nb, Effect.POINT_BASIS, t.w.rows.size())) continue;
                if (time != null) out.add(Effect.refraction(Effect.Along.TIME, inst, time[0], time[1], nb));
                if (temp != null) out.add(Effect.refraction(Effect.Along.TEMPERATURE, inst, temp[0], temp[1], nb));
            }
        }
        List<Effect> cycles = new ArrayList<>();
        for (Locator.Probe p : periods) cycles.add(sightEffect(p));
        Map<Effect, Double> drop = new java.util.IdentityHashMap<>();
        for (Effect c : cycles) {
            Candidate cd = t.test(c, conds);
            drop.put(c, cd.keptColumns > 0 ? cd.drss : 0);
        }
        cycles.sort((a, b) -> Double.compare(drop.get(b), drop.get(a)));
        out.addAll(cycles.subList(0, Math.min(INSTRUMENT_CYCLE_RIVALS, cycles.size())));
        return out;
    }

    /** The periods of a distance meter's cycle put in a family's place: those that take most of what is left. */
    static final int INSTRUMENT_CYCLE_RIVALS = 3;

    /** The periods of a distance meter's cycle fitted to choose those rivals from: the ones the residual holds most of. */
    static final int INSTRUMENT_CYCLES_TRIED = 24;

    /**
     * Share of what a fallback holding part of a family's shape explains (its lowering of the
     * leave-one-pose-out error, in the family's place) that the family explains alone, at or above
     * which the family stays claimed and what the fallback finds beside it is left to be located: a
     * tracker drifting with time beside its range re-set at every beam break, which a turn of the
     * base with time follows in part (clean-room set U's h11: 99.5 %).
     */
    static final double FAMILY_SHARE = 0.95;

    /** Whether family {@code e} (at {@code k}) explains {@link #FAMILY_SHARE} of what fallback {@code f}, which holds its shape, explains in its place. */
    static boolean mostlyFamily(Tester at, int k, Effect e, Effect f, Work w) {
        double without = at.pressReplacing(k, null, null), own = at.pressFull(), rival = at.pressReplacing(k, f, w.conditions);
        double share = (without - own) / (without - rival);
        LOG.debug("{} explains {} of what {} explains in its place", e.label(), share, f.label());
        return without > rival && share >= FAMILY_SHARE;
    }

    /** Whether {@code f}, tested beside the model fitted in {@code at}, is significant at the family-wise α. */
    static boolean significantBeside(Tester at, Effect f, Work w) {
        Candidate c = at.test(f, w.conditions);
        boolean yes = c.keptColumns > 0 && c.p < w.o.alpha();
        if (!yes) LOG.debug("{} finds nothing significant beside the model (p {})", f.label(), c.p);
        return yes;
    }

    /**
     * Whether alias {@code a} has more parameters than the selected {@code e} it would replace and finds
     * nothing significant beside it (its partial F-test on the model holding {@code e}, at the
     * family-wise α). Its lower leave-one-pose-out error is then the extra parameters' share of the
     * noise, not a shape {@code e} leaves: over a joint's short range a few harmonics of its angle
     * follow a scale error's ramp as closely as the ramp itself, and the simpler form stays.
     */
    static boolean richerWithoutCause(Tester at, Effect e, Effect a, Work w) {
        // like a richer form, a fallback that holds part of the named form's shape takes its place only for what it finds beside it
        if (a.size() <= e.size() || a.isFallback() && !a.holdsPartOf(e)) return false;
        Candidate c = at.test(a, w.conditions);
        boolean without = c.keptColumns == 0 || !(c.p < w.o.alpha());
        if (without) LOG.debug("alias: {} not in place of {}: more parameters and nothing significant beside it (p {})", a.label(), e.label(), c.p);
        return without;
    }

    /** The candidates that could explain the same structure as {@code e}: other families on its drive, or other thermal forms. */
    static List<Effect> aliases(Effect e, List<Effect> family, List<Effect> selected) {
        List<Effect> out = new ArrayList<>();
        for (Effect a : family) {
            if (a == e || selected.contains(a)) continue;
            // one lost motion per joint: its other form is the alias, not a second play beside a selected one
            if (a.kind() == Effect.Kind.BACKLASH && selected.stream().anyMatch(x -> x != e && x.kind() == Effect.Kind.BACKLASH && x.joint() == a.joint()))
                continue;
            // one carried mass per joint likewise
            if (secondForm(a, selected, e)) continue;
            boolean thermalE = e.kind() == Effect.Kind.THERMAL || e.kind() == Effect.Kind.THERMAL_LINK || e.kind() == Effect.Kind.DRIFT;
            boolean thermalA = a.kind() == Effect.Kind.THERMAL || a.kind() == Effect.Kind.THERMAL_LINK || a.kind() == Effect.Kind.DRIFT;
            if (thermalE && thermalA) out.add(a);
            else if (!thermalE && !thermalA && e.joint() >= 0 && a.joint() == e.joint() && a.kind() != e.kind()) out.add(a);
            else if (!thermalE && !thermalA && e.kind() == a.kind() && a.joint() == e.joint()
                    && (e.kind() == Effect.Kind.PERIODIC || e.kind() == Effect.Kind.COMPLIANCE || e.kind() == Effect.Kind.COUPLING)
                    && !a.label().equals(e.label())) out.add(a);
        }
        return out;
    }

    private static boolean allFinite(List<Measurement> rows, java.util.function.ToDoubleFunction<Measurement> f) {
        return !rows.isEmpty() && rows.stream().allMatch(m -> Double.isFinite(f.applyAsDouble(m)));
    }

    /** Pose index as a stand-in for time. */
    static List<PoseConditions> poseOrder(List<Measurement> rows) {
        List<PoseConditions> out = new ArrayList<>();
        for (int i = 0; i < rows.size(); i++) {
            Measurement m = rows.get(i);
            out.add(new PoseConditions(m.directions(), i, m.tempC(), m.payloadKg()));
        }
        return out;
    }

    // ------------------------------------------------------------------ fitting

    /** A step of the forward selection. */
    private record Step(Candidate candidate, double trainRms, double validateRms) { }

    /** A fitted model: problem, full vector, weighted residuals and free Jacobian. */
    static final class Fit {
        IdentificationProblem problem;
        double[] full, r, jac;
        int m, nf, nEffects;
        double trainRms;

        double[] effectValues() {
            if (nEffects == 0) return new double[0];
            int off = problem.effectOffset(0);
            return Arrays.copyOfRange(full, off, full.length);
        }

        /** The fitted values of selected effect {@code k}. */
        double[] effectValues(int k) {
            int a = problem.effectOffset(k);
            return Arrays.copyOfRange(full, a, a + problem.effects().get(k).parameterNames().size());
        }
    }

    /** Shared state of one diagnosis. */
    static final class Work {
        final KinematicModel model;
        final List<Measurement> rows;
        final List<PoseConditions> conditions = new ArrayList<>();
        final boolean sixD, instrument;
        final double[] geoFull;
        final boolean[] geoFixed;
        final double sigmaPos, sigmaRot;
        final MeasurementSet validate;
        final Options o;
        final GravityTorques gravity; // the robot file's mass model (masses unknown without one)
        Pauses pauses;                // when the robot rested, from the whole file's reading times (null: unknown)
        Directions.Moves moves = Directions.Moves.NONE; // each pose's last move per joint, from the whole file's measuring order
        double[] speeds;              // each joint's top speed from the robot file (rad/s; NaN: unknown)

        Work(KinematicModel model, GravityTorques gravity, List<Measurement> rows, CalibrationResult geo, MeasurementSet validate, Options o) {
            this(model, gravity, rows, geo, validate, o, positionSigma(geo), geo.sixD() && geo.sigmaRotRad() > 0 ? geo.sigmaRotRad() : 1e-4);
        }

        /** The position rows' σ the geometric fit estimated (m; 10 µm when it has none). */
        static double positionSigma(CalibrationResult geo) { return geo.sigmaPosM() > 0 ? geo.sigmaPosM() : 1e-5; }

        /** With the residuals weighted by {@code sigmaPos} (m) and {@code sigmaRot} (rad) instead of the geometric fit's. */
        Work(KinematicModel model, GravityTorques gravity, List<Measurement> rows, CalibrationResult geo, MeasurementSet validate, Options o,
             double sigmaPos, double sigmaRot) {
            this.model = model;
            this.gravity = gravity;
            this.rows = rows;
            for (Measurement m : rows) conditions.add(PoseConditions.of(m));
            this.sixD = geo.sixD();
            this.instrument = geo.instrumentTbase() != null;
            List<CalibrationResult.ParameterEstimate> ps = geo.parameters();
            geoFull = new double[ps.size()];
            geoFixed = new boolean[ps.size()];
            for (int i = 0; i < ps.size(); i++) { geoFull[i] = ps.get(i).identified(); geoFixed[i] = ps.get(i).fixed(); }
            this.sigmaPos = sigmaPos;
            this.sigmaRot = sigmaRot;
            this.validate = validate;
            this.o = o;
        }

        List<EffectBlock> blocks(List<Effect> es) {
            List<EffectBlock> b = new ArrayList<>();
            for (Effect e : es) b.add(e.block(model));
            return b;
        }

        /** LM on geometry + the effects, from {@code start} (geometry part) and the previous effect values (new ones at 0). */
        Fit fit(List<Effect> effects, Map<Effect, boolean[]> absorbed, double[] start, Candidate added) {
            int nBase = geoFull.length;
            int nEff = 0;
            for (Effect e : effects) nEff += e.size();
            double[] full = new double[nBase + nEff];
            System.arraycopy(start, 0, full, 0, Math.min(start.length, full.length));
            if (added != null) {
                // Start the new effect at its linearised estimate: fewer LM iterations.
                int o0 = full.length - added.effect.size();
                for (int i = 0; i < added.effect.size(); i++) full[o0 + i] = added.estimate[i];
            }
            boolean[] fix = Arrays.copyOf(geoFixed, full.length);
            int off = nBase;
            for (Effect e : effects) {
                boolean[] a = absorbed.get(e);
                for (int i = 0; i < e.size(); i++) {
                    if (a != null && a[i]) { fix[off + i] = true; full[off + i] = 0; } // left to the geometry
                }
                off += e.size();
            }
            IdentificationProblem p = new IdentificationProblem(model, rows, sixD, instrument, blocks(effects), full);
            p.setSigmas(sigmaPos, sigmaRot);
            p.setFixed(fix);
            // the start is a fit of the same data with one effect more or less and the new one at its linearised estimate: close
            LevenbergMarquardt lm = new LevenbergMarquardt(p).maxIterations(100).initialDamping(NEAR_START_DAMPING);
            LevenbergMarquardt.Result res = lm.solve(p.freeOf(full), o.cancel());
            Fit f = new Fit();
            f.problem = p;
            f.full = p.fullOf(res.x());
            f.m = p.residualCount();
            f.nf = p.parameterCount();
            f.nEffects = effects.size();
            // the solver leaves its residuals and Jacobian at the solution
            f.r = lm.lastResiduals();
            f.jac = lm.lastJacobian();
            f.trainRms = p.measurementRms(f.r, sigmaPos);
            return f;
        }

        /**
         * The noise σ of the position rows (m) and of the rotation rows (rad) that {@code f} leaves: each kind's
         * mean square residual, unweighted (no degrees of freedom taken off: only their ratio is used).
         */
        double[] rowSigmas(Fit f) {
            int rpp = f.problem.rowsPerPose(), pos = f.problem.positionRowsPerPose();
            double sp = 0, sr = 0;
            int np = 0, nr = 0;
            for (int i = 0; i < f.m; i++) {
                double r = f.r[i];
                if (i % rpp < pos) { sp += r * r; np++; } else { sr += r * r; nr++; }
            }
            return new double[] {sigmaPos * Math.sqrt(sp / Math.max(1, np)), nr == 0 ? sigmaRot : sigmaRot * Math.sqrt(sr / nr)};
        }

        /** Whether there are validation poses (a set given and not empty). */
        boolean hasValidation() { return validate != null && validate.size() > 0; }

        /** The RMS error of the validation poses' measurements under {@code f}, m; NaN without validation poses. */
        double validateRms(Fit f) { return validation(f, false); }

        /**
         * The held-out error on the validation poses as the fit weighs its training rows: the sum
         * of squared residuals, each over its noise σ (position and, for 6-D data, orientation).
         * An effect seen mostly in the orientation (a wrist joint's error) moves the position RMS
         * by less than its noise; this judges it on what it predicts. NaN without validation poses.
         */
        double validateError(Fit f) { return validation(f, true); }

        /**
         * The validation poses under {@code f} (its geometry and effects; the tool's rotation left out
         * when the training data have orientations and the validation data do not): with {@code
         * weighted}, the sum of squared residuals each over its noise σ; else the measurements' RMS, m.
         */
        private double validation(Fit f, boolean weighted) {
            return hasValidation() ? heldOut(f, validate.rows(), weighted) : Double.NaN;
        }

        /** {@link #validation} of held-out {@code poses} (rows of the validation set, or ones made from them). */
        double heldOut(Fit f, List<Measurement> poses, boolean weighted) {
            boolean six = sixD && validate.hasOrientation();
            double[] full = six == sixD ? f.full : dropToolRotation(f.full, f.problem.toolOffset());
            IdentificationProblem q = new IdentificationProblem(model, poses, six, instrument, f.problem.effects(), full);
            if (weighted) q.setSigmas(sigmaPos, sigmaRot);
            else q.setSigmas(1, 1);
            double[] r = new double[q.residualCount()];
            q.evaluateFull(full, r, null);
            if (!weighted) return q.measurementRms(r, 1);
            double ss = 0;
            for (double v : r) ss += v * v;
            return ss;
        }

        private static double[] dropToolRotation(double[] full, int toolOff) {
            double[] out = new double[full.length - 3];
            System.arraycopy(full, 0, out, 0, toolOff + 3);
            System.arraycopy(full, toolOff + 6, out, toolOff + 3, full.length - toolOff - 6);
            return out;
        }

        /** σ of every effect parameter of the fit, from s² (JᵀJ)⁻¹ over the free parameters. */
        double[] effectSigmas(Fit f) {
            int n = f.nf, m = f.m;
            int[] free = f.problem.freeIndices();
            int nEff = f.full.length - (f.nEffects == 0 ? f.full.length : f.problem.effectOffset(0));
            double[] out = new double[nEff];
            if (nEff == 0) return out;
            double[] scale = new double[n];
            for (int c = 0; c < n; c++) {
                double s = 0;
                for (int i = 0; i < m; i++) s += f.jac[i * n + c] * f.jac[i * n + c];
                scale[c] = s > 0 ? Math.sqrt(s) : 1;
            }
            DMatrixRMaj a = new DMatrixRMaj(n, n);
            for (int i = 0; i < m; i++) {
                int b = i * n;
                for (int x = 0; x < n; x++) {
                    double jx = f.jac[b + x] / scale[x];
                    if (jx == 0) continue;
                    for (int y = x; y < n; y++) a.data[x * n + y] += jx * f.jac[b + y] / scale[y];
                }
            }
            for (int x = 0; x < n; x++) for (int y = 0; y < x; y++) a.data[x * n + y] = a.data[y * n + x];
            if (!org.ejml.dense.row.CommonOps_DDRM.invert(a)) { Arrays.fill(out, Double.NaN); return out; }
            double s2 = 0;
            for (double v : f.r) s2 += v * v;
            s2 /= Math.max(1, m - n);
            int eff0 = f.problem.effectOffset(0);
            for (int c = 0; c < n; c++) {
                if (free[c] < eff0) continue;
                // Residuals are weighted by 1/σ, so s² is dimensionless and the covariance is in parameter units.
                out[free[c] - eff0] = Math.sqrt(s2 * a.get(c, c)) / scale[c];
            }
            return out;
        }

        /** {@code effects} without effect {@code k} refitted, from {@code f}'s values without that effect's. */
        Fit refitWithout(Fit f, List<Effect> effects, Map<Effect, boolean[]> absorbed, int k) {
            return fit(withoutOne(effects, k), absorbed, dropEffect(f, k), null);
        }

        /** The full vector of a fit without effect {@code k}'s parameters. */
        double[] dropEffect(Fit f, int k) {
            int a = f.problem.effectOffset(k), b = a + f.problem.effects().get(k).parameterNames().size();
            double[] out = new double[f.full.length - (b - a)];
            System.arraycopy(f.full, 0, out, 0, a);
            System.arraycopy(f.full, b, out, a, f.full.length - b);
            return out;
        }

        /**
         * Backward step: the selected effect whose partial F-test (its columns against the rest of
         * the model's Jacobian) fails {@code threshold}, or whose joint estimate is implausible
         * beyond 3σ; the worst one, or -1 when all stay.
         */
        int weakest(Fit f, List<Effect> selected, double threshold) {
            return weakest(f, selected, threshold, e -> true, new double[1]);
        }

        /** {@link #weakest(Fit, List, double)} among the effects {@code which} accepts; {@code pOut[0]} gets the dropped one's p. */
        int weakest(Fit f, List<Effect> selected, double threshold, java.util.function.Predicate<Effect> which, double[] pOut) {
            int n = f.nf, m = f.m;
            int[] free = f.problem.freeIndices();
            double[] sig = effectSigmas(f);
            double rss = 0;
            for (double v : f.r) rss += v * v;
            int worst = -1;
            double worstP = -1;
            boolean worstPlausible = true;
            for (int k = 0; k < selected.size(); k++) {
                if (!which.test(selected.get(k))) continue;
                int a = f.problem.effectOffset(k), b = a + selected.get(k).size();
                List<Integer> mine = new ArrayList<>(), rest = new ArrayList<>();
                for (int c = 0; c < n; c++) (free[c] >= a && free[c] < b ? mine : rest).add(c);
                if (mine.isEmpty()) continue;
                double[] contrib = new double[m];
                for (int c : mine) for (int i = 0; i < m; i++) contrib[i] += f.jac[i * n + c] * f.full[free[c]];
                double[] u = basis(f.jac, m, n, rest);
                int rank = u.length / m;
                double[] pc = projectOut(u, rank, m, contrib);
                double drss = 0;
                for (double v : pc) drss += v * v;
                int df2 = m - n;
                double fstat = (drss / mine.size()) / (rss / Math.max(1, df2));
                double p = Stats.fUpperTail(fstat, mine.size(), df2);
                Candidate c = judged(f, selected, k, sig);
                // an implausible effect before an insignificant one; among either, the least significant (two aliases
                // fitted together can both leave the bounds: the one the data need less goes first)
                boolean fails = !c.plausible || !(p < threshold);
                if (fails && (worst < 0 || !c.plausible && worstPlausible || c.plausible == worstPlausible && p > worstP)) {
                    worstP = p;
                    worstPlausible = c.plausible;
                    worst = k;
                    pOut[0] = p;
                }
            }
            return worst;
        }

        /** Whether selected effect {@code k}'s estimate in fit {@code f} is physically plausible ({@link #plausibility}). */
        boolean plausibleIn(Fit f, List<Effect> selected, int k) {
            return judged(f, selected, k, effectSigmas(f)).plausible;
        }

        /** Selected effect {@code k}'s estimate and σ in fit {@code f} ({@code sig} from {@link #effectSigmas}), judged by {@link #plausibility}. */
        static Candidate judged(Fit f, List<Effect> selected, int k, double[] sig) {
            int eff0 = f.problem.effectOffset(0), a = f.problem.effectOffset(k), b = a + selected.get(k).size();
            Candidate c = new Candidate();
            c.effect = selected.get(k);
            c.estimate = Arrays.copyOfRange(f.full, a, b);
            c.sd = Arrays.copyOfRange(sig, a - eff0, b - eff0);
            c.absorbedMask = Arrays.copyOfRange(f.problem.fixedMask(), a, b);
            plausibility(c);
            return c;
        }

        /** The candidate tester at a fit: basis of the model's Jacobian and ∂residual/∂θ, ∂residual/∂strain. */
        Tester tester(Fit f) {
            // a tester is a function of the fit alone (its caches too), and the same fit is often tested again
            if (lastTesterFit != f) {
                lastTester = new Tester(this, f);
                lastTesterFit = f;
            }
            return lastTester;
        }

        private Fit lastTesterFit;
        private Tester lastTester;
    }

    /**
     * A probe block: q_out,j += v_j for every drive (θ = C q_out), a strain v_dof and a base-frame
     * translation v_dof+1..3 of the point, to get ∂residual/∂q_j, ∂residual/∂ε and ∂residual/∂p.
     */
    static final class Probe implements EffectBlock {
        private final int dof;
        private final double[][] c;
        Probe(KinematicModel model) { this.dof = model.dof(); this.c = model.couplingMatrix(); }
        private int size() { return dof + 7; }
        @Override public String name() { return "probe"; }
        @Override public List<String> parameterNames() {
            List<String> n = new ArrayList<>();
            for (int j = 0; j < dof; j++) n.add("dq" + (j + 1));
            n.add("strain");
            n.add("dx");
            n.add("dy");
            n.add("dz");
            n.add("wx");
            n.add("wy");
            n.add("wz");
            return n;
        }
        @Override public List<String> units() {
            List<String> n = new ArrayList<>();
            for (int j = 0; j < dof; j++) n.add("rad");
            n.add("1");
            n.add("m");
            n.add("m");
            n.add("m");
            n.add("rad");
            n.add("rad");
            n.add("rad");
            return n;
        }
        @Override public double[] initialValues() { return new double[size()]; }
        @Override public void jointDelta(double[] v, Measurement row, double[] dTheta, double[] dThetaDv) {
            int k = size();
            for (int i = 0; i < dof; i++) for (int j = 0; j < dof; j++) dTheta[i] += c[i][j] * v[j];
            if (dThetaDv != null) {
                Arrays.fill(dThetaDv, 0);
                for (int i = 0; i < dof; i++) for (int j = 0; j < dof; j++) dThetaDv[i * k + j] = c[i][j];
            }
        }
        @Override public void positionDelta(double[] v, Measurement row, double[] pb, double[] dp, double[] dpDv, double[] dpDpoint) {
            int k = size();
            if (dpDpoint != null) for (int a = 0; a < 3; a++) dpDpoint[4 * a] += v[dof];
            for (int a = 0; a < 3; a++) {
                dp[a] += v[dof] * pb[a] + v[dof + 1 + a];
                if (dpDv != null) {
                    for (int col = 0; col < k; col++) dpDv[a * k + col] = 0;
                    dpDv[a * k + dof] = pb[a];
                    dpDv[a * k + dof + 1 + a] = 1;
                }
            }
        }
        @Override public void rotationDelta(double[] v, Measurement row, double[] pb, double[] dw, double[] dwDv) {
            int k = size();
            if (dwDv != null) Arrays.fill(dwDv, 0);
            for (int a = 0; a < 3; a++) {
                dw[a] += v[dof + 4 + a];
                if (dwDv != null) dwDv[a * k + dof + 4 + a] = 1;
            }
        }
    }

    /** One candidate's test result. */
    static final class Candidate {
        Effect effect;
        int keptColumns, df1, df2;
        double ratio, f, p = 1, bic, rssReduction, pressBefore, pressAfter, threshold = Double.NaN, drss;
        double[] estimate, sd;
        double[] basis, coef; // orthonormal basis of its kept projected columns (m x df1) and the residual's coordinates
        boolean[] absorbedMask;
        List<String> absorbed = new ArrayList<>();
        boolean plausible;
        String plausibility;

        Diagnosis.Evidence evidence() {
            return new Diagnosis.Evidence(f, df1, df2, p, threshold, rssReduction, pressBefore, pressAfter, ratio,
                    List.copyOf(absorbed), plausibility, plausible);
        }
    }

    /** Tests candidates (blocks of signature columns) against one fit. */
    static final class Tester {
        final Work w;
        final Fit fit;
        final int m, rpp, dof, rank;
        final double[] u;        // m x rank orthonormal basis of the model Jacobian's span
        final double[][] pointBase; // predicted measured point per pose (the points' mean with several), base frame
        final double[][][] pointsBase; // predicted point per pose and measured point, base frame
        /**
         * The poses each residual row depends on, "ends": one (the row's pose), or two for a
         * distance between a pair of poses (the first pose, then the second). Per end, the rows as
         * poses of their own, their conditions, the predicted measured point, and the sensitivities
         * to a change at that end alone (their sum over the ends is the whole row's): ∂r/∂q_j (drive
         * outputs, weighted; m x dof), ∂r/∂ε (m) and ∂r/∂p (base-frame translation of the point;
         * m x 3), ∂r/∂ω (a base-frame rotation of the measured frame alone, which only orientation
         * rows see; m x 3). An error that is a function of the pose acts at each end with its own value.
         */
        final int ends;
        final List<List<Measurement>> endRows = new ArrayList<>();
        final List<List<PoseConditions>> endConditions = new ArrayList<>();
        final double[][][] endPoint;
        final double[][] endDQ, endDStrain, endDTrans, endDRot;
        /**
         * The measurement layout of the residual rows: each pose's first {@code posRows} rows hold
         * {@code perPose} measurements of {@code dim} components each (3 per measured point, points in
         * order, or 1 for a distance), followed by rotation rows with orientations.
         */
        final int posRows, perPose, dim;
        final double[] rPerp;    // residual with any part in span(U) removed
        final double rss0, press0;
        final double[][] h0;     // leverage block per pose (rpp x rpp, row-major)

        Tester(Work w, Fit fit) {
            this.w = w;
            this.fit = fit;
            m = fit.m;
            rpp = fit.problem.rowsPerPose();
            posRows = fit.problem.positionRowsPerPose();
            perPose = fit.problem.measurementsPerPose();
            dim = fit.problem.measurementSize();
            dof = w.model.dof();
            // Basis of the column-scaled Jacobian (thin SVD, relative rank tolerance 1e-10).
            List<Integer> all = new ArrayList<>();
            for (int c = 0; c < fit.nf; c++) all.add(c);
            u = basis(fit.jac, m, fit.nf, all);
            rank = u.length / m;
            // Drive, strain and translation sensitivities through the identification chain.
            List<EffectBlock> bl = new ArrayList<>(fit.problem.effects());
            bl.add(new Probe(w.model));
            int np = dof + 7;
            double[] full = Arrays.copyOf(fit.full, fit.full.length + np);
            IdentificationProblem pp = new IdentificationProblem(w.model, w.rows, w.sixD, w.instrument, bl, full);
            pp.setSigmas(fit.problem.sigmaPos(), fit.problem.sigmaRot());
            int nFull = pp.fullSize();
            // The Jacobian per end: the whole one for single poses; for pairs of poses split by end
            // (their sum is the whole Jacobian), one evaluation for both.
            ends = fit.problem.pairs() ? 2 : 1;
            double[][] jEnd = new double[ends][m * nFull];
            if (ends == 2) pp.evaluatePairEnds(full, jEnd[0], jEnd[1]);
            else pp.evaluateFull(full, new double[m], jEnd[0]);
            int off = nFull - np;
            endDQ = new double[ends][m * dof];
            endDStrain = new double[ends][m];
            endDTrans = new double[ends][m * 3];
            endDRot = new double[ends][m * 3];
            for (int e = 0; e < ends; e++)
                for (int i = 0; i < m; i++) {
                    for (int j = 0; j < dof; j++) endDQ[e][i * dof + j] = jEnd[e][i * nFull + off + j];
                    endDStrain[e][i] = jEnd[e][i * nFull + off + dof];
                    for (int a = 0; a < 3; a++) endDTrans[e][i * 3 + a] = jEnd[e][i * nFull + off + dof + 1 + a];
                    for (int a = 0; a < 3; a++) endDRot[e][i * 3 + a] = jEnd[e][i * nFull + off + dof + 4 + a];
                }
            KinematicModel geo = fit.problem.modelOf(fit.full);
            double[][][] ep = null;
            if (ends == 2) {
                ep = new double[2][w.rows.size()][];
                for (int e = 0; e < 2; e++) {
                    List<Measurement> er = new ArrayList<>();
                    List<PoseConditions> ec = new ArrayList<>();
                    for (Measurement r : w.rows) {
                        Measurement end = e == 0 ? r.firstPose() : r.secondPose();
                        er.add(end);
                        ec.add(PoseConditions.of(end));
                    }
                    endRows.add(er);
                    endConditions.add(ec);
                    for (int i = 0; i < er.size(); i++) {
                        org.robopro.models.Vec3 p = geo.flange(er.get(i).q()).apply(fit.problem.toolPointOf(fit.full, 0));
                        ep[e][i] = new double[] {p.x(), p.y(), p.z()};
                    }
                }
            } else {
                endRows.add(w.rows);
                endConditions.add(w.conditions);
            }
            int nPts = fit.problem.pointCount();
            pointBase = new double[w.rows.size()][3];
            pointsBase = new double[w.rows.size()][nPts][];
            for (int i = 0; i < pointBase.length; i++) {
                org.robopro.kinematics.Pose fl = geo.flange(w.rows.get(i).q());
                for (int k = 0; k < nPts; k++) {
                    org.robopro.models.Vec3 p = fl.apply(fit.problem.toolPointOf(fit.full, k));
                    pointsBase[i][k] = new double[] {p.x(), p.y(), p.z()};
                    for (int a = 0; a < 3; a++) pointBase[i][a] += pointsBase[i][k][a] / nPts;
                }
            }
            endPoint = ep != null ? ep : new double[][][] {pointBase};
            rPerp = project(fit.r);
            double s = 0;
            for (double v : rPerp) s += v * v;
            rss0 = s;
            h0 = hatBlocks(u, rank);
            press0 = press(rPerp, null, 0);
        }

        /** x − U Uᵀ x. */
        double[] project(double[] x) { return projectOut(u, rank, m, x); }

        /** Where the errors are measured, in words: "at the measured point", "at the measured points", "in the measured distances". */
        String where() { return dim == 1 ? "in the measured distances" : perPose > 1 ? "at the measured points" : "at the measured point"; }

        /** Measurements (points of every pose, or distances) in the residual. */
        int measurements() { return m / rpp * perPose; }

        /** The first residual row of measurement {@code k} (its {@link #dim} rows follow). */
        int rowOf(int k) { return k / perPose * rpp + k % perPose * dim; }

        /** The pose of measurement {@code k}. */
        int poseOf(int k) { return k / perPose; }

        /** The measured point (0-based) a pose's residual row {@code a} belongs to (rotation rows: the point of the frame, 0). */
        int pointOfRow(int a) { return a < posRows && dim == 3 ? a / 3 : 0; }

        /**
         * Leave-one-pose-out prediction error sum of squares of a linear model with residual e and
         * hat blocks h0 + Q_i Q_iᵀ (Q: m x q extra orthonormal columns, or null): Σ ‖(I − H_ii)⁻¹ e_i‖².
         */
        double press(double[] e, double[] qm, int q) { return pressBlocks(h0, e, qm, q); }

        /** The linearised model without selected effect k: a basis of its other free columns, and the residual without the effect. */
        private int withoutK = -1;
        private double[] withoutU, withoutR, withoutE;
        private double[][] withoutH;

        private void without(int k) {
            if (withoutK == k) return;
            int n = fit.nf;
            int[] free = fit.problem.freeIndices();
            int a = fit.problem.effectOffset(k), b = a + fit.problem.effects().get(k).parameterNames().size();
            List<Integer> keep = new ArrayList<>();
            double[] r = fit.r.clone();
            for (int c = 0; c < n; c++) {
                // r(v) ≈ r(0) + J v, so without the effect the residual is r − J v
                if (free[c] >= a && free[c] < b) { for (int i = 0; i < m; i++) r[i] -= fit.jac[i * n + c] * fit.full[free[c]]; }
                else keep.add(c);
            }
            withoutU = basis(fit.jac, m, n, keep);
            withoutR = r;
            withoutE = projectOut(withoutU, withoutU.length / m, m, r);
            withoutH = hatBlocks(withoutU, withoutU.length / m);
            withoutK = k;
        }

        private double[][] hatBlocks(double[] ub, int rk) {
            int poses = m / rpp;
            double[][] h = new double[poses][rpp * rpp];
            for (int i = 0; i < poses; i++)
                for (int a1 = 0; a1 < rpp; a1++)
                    for (int b1 = 0; b1 < rpp; b1++) {
                        double v = 0;
                        int ra = (i * rpp + a1) * rk, rb = (i * rpp + b1) * rk;
                        for (int t = 0; t < rk; t++) v += ub[ra + t] * ub[rb + t];
                        h[i][a1 * rpp + b1] = v;
                    }
            return h;
        }

        /**
         * Leave-one-pose-out error (PRESS) of the linearised joint model with selected effect
         * {@code k} taken out and {@code alias} (or nothing) put in its place: its free columns are
         * dropped and its fitted contribution returned to the residual.
         */
        double pressReplacing(int k, Effect alias, List<PoseConditions> conds) {
            return alias == null ? pressReplacingColumns(k, null, 0) : pressReplacingColumns(k, signature(alias, conds), alias.size());
        }

        /** {@link #pressReplacing} with the alias given by its signature columns {@code s} (m x ka, row-major; null: nothing in its place). */
        double pressReplacingColumns(int k, double[] s, int ka) { return pressReplacingColumns(k, s, ka, null); }

        /** {@link #pressReplacingColumns}, each pose's term also put in {@code perPose} (when not null). */
        private double pressReplacingColumns(int k, double[] s, int ka, double[] perPose) {
            without(k);
            if (s == null) return pressBlocks(withoutH, withoutE, null, 0, perPose);
            Projected p = projected(withoutU, withoutU.length / m, s, ka);
            return pressWithProjected(withoutH, withoutE.clone(), p.cols(), p.n0(), perPose);
        }

        /** {@link #pressReplacingColumns} with nothing taken out: the ka columns s added to the model as fitted. */
        double pressAddingColumns(double[] s, int ka) {
            if (s == null) return pressBlocks(h0, rPerp, null, 0);
            Projected p = projected(u, rank, s, ka);
            return pressWithProjected(h0, rPerp.clone(), p.cols(), p.n0());
        }

        /**
         * Columns of a signature less their projection on a model's span: each column's remnant (null
         * for a column of zeros) and its squared norm before.
         */
        record Projected(double[][] cols, double[] n0) { }

        /** The ka columns s (m x ka, row-major), each less its projection on the basis U (m x rk). */
        private Projected projected(double[] basisU, int rk, double[] s, int ka) {
            double[][] ys = new double[ka][];
            double[] n0s = new double[ka];
            for (int c = 0; c < ka; c++) {
                double[] x = new double[m];
                double n0 = 0;
                for (int i = 0; i < m; i++) { x[i] = s[i * ka + c]; n0 += x[i] * x[i]; }
                n0s[c] = n0;
                if (n0 != 0) ys[c] = projectOut(basisU, rk, m, x);
            }
            return new Projected(ys, n0s);
        }

        /** {@link #projected} for the model without selected effect {@code k}, whose PRESS {@link #pressReplacingProjected} gives. */
        Projected projectedReplacing(int k, double[] s, int ka) {
            without(k);
            return projected(withoutU, withoutU.length / m, s, ka);
        }

        /**
         * {@link #pressReplacingColumns} for columns already {@link #projectedReplacing projected} out
         * of the model without {@code k}: cols[c] and n0[c] in column order (the columns of several
         * projections may be put together, as long as each was projected for the same k).
         */
        double pressReplacingProjected(int k, double[][] cols, double[] n0) {
            without(k);
            return pressWithProjected(withoutH, withoutE.clone(), cols, n0);
        }

        /**
         * PRESS of a model of hat blocks h and residual e (out of the model's span; changed here), with
         * projected columns ys (null: a column of zeros, left out) added.
         */
        private double pressWithProjected(double[][] withoutH, double[] e, double[][] cols, double[] n0) {
            return pressWithProjected(withoutH, e, cols, n0, null);
        }

        /** {@link #pressWithProjected}, each pose's term also put in {@code perPose} (when not null). */
        private double pressWithProjected(double[][] withoutH, double[] e, double[][] cols, double[] n0, double[] perPose) {
            List<double[]> ys = new ArrayList<>();
            double[] n0s = new double[cols.length];
            for (int c = 0; c < cols.length; c++) {
                if (cols[c] == null) continue;
                n0s[ys.size()] = n0[c];
                ys.add(cols[c]);
            }
            // A column of the alias that the rest of the model holds to within the absorbed ratio is left to it, as when the
            // alias is fitted (its absorbed columns fixed at zero): kept, its remnant is rounding and the difference between
            // the rest's span at this fit and at the alias's, a direction that can carry the removed effect's own signal.
            List<double[]> qs = orthonormal(ys, n0s, m, w.o.absorbedRatio() * w.o.absorbedRatio());
            int q = qs.size();
            double[] qm = new double[m * q];
            for (int t = 0; t < q; t++) {
                double[] qv = qs.get(t);
                double d = 0;
                for (int i = 0; i < m; i++) { qm[i * q + t] = qv[i]; d += qv[i] * e[i]; }
                for (int i = 0; i < m; i++) e[i] -= d * qv[i];
            }
            return pressBlocks(withoutH, e, qm, q, perPose);
        }


        /** Leave-one-pose-out error (PRESS) of the linearised joint model as fitted (every free column). */
        double pressFull() { return pressBlocks(h0, rPerp, null, 0); }

        /** {@link #pressFull}'s term of each pose: its left-out residual's squared norm. */
        double[] pressFullPerPose() {
            double[] out = new double[m / rpp];
            pressBlocks(h0, rPerp, null, 0, out);
            return out;
        }

        /** {@link #pressReplacing}'s term of each pose (selected effect k replaced by {@code alias}). */
        double[] pressReplacingPerPose(int k, Effect alias, List<PoseConditions> conds) {
            double[] out = new double[m / rpp];
            pressReplacingColumns(k, signature(alias, conds), alias.size(), out);
            return out;
        }

        /** Σ_i ‖(I − H_ii)⁻¹ e_i‖² with H_ii = hb_i + Q_i Q_iᵀ (Q m x q, or null). */
        private double pressBlocks(double[][] hb, double[] e, double[] qm, int q) { return pressBlocks(hb, e, qm, q, null); }

        /** {@link #pressBlocks}, each pose's term also put in {@code perPose} (when not null). */
        private double pressBlocks(double[][] hb, double[] e, double[] qm, int q, double[] perPose) {
            int poses = m / rpp;
            double total = 0;
            double[] h = new double[rpp * rpp], bb = new double[rpp];
            for (int i = 0; i < poses; i++) {
                for (int a1 = 0; a1 < rpp; a1++)
                    for (int b1 = 0; b1 < rpp; b1++) {
                        double v = hb[i][a1 * rpp + b1];
                        if (qm != null) for (int t = 0; t < q; t++) v += qm[(i * rpp + a1) * q + t] * qm[(i * rpp + b1) * q + t];
                        h[a1 * rpp + b1] = (a1 == b1 ? 1 : 0) - v;
                    }
                for (int a1 = 0; a1 < rpp; a1++) bb[a1] = e[i * rpp + a1];
                if (!solve(h, bb, rpp)) { // a pose fully determines a parameter
                    if (perPose != null) Arrays.fill(perPose, i, poses, Double.POSITIVE_INFINITY);
                    return Double.POSITIVE_INFINITY;
                }
                double own = 0;
                for (double v : bb) own += v * v;
                if (perPose != null) perPose[i] = own;
                total += own;
            }
            return total;
        }

        /**
         * The signature S (m x k, row-major) of an effect: ∂r/∂v at v = 0, with the given per-pose
         * conditions. For distances between pairs of poses, the sum over the pair's two poses of each
         * one's sensitivity times the effect's regressor there (its own joints, directions and
         * measured point: the same chain as the identification's measurement function); only with the
         * rows' own conditions (zero otherwise).
         */
        double[] signature(Effect e, List<PoseConditions> conds) {
            int k = e.size();
            double[] s = new double[m * k];
            if (ends > 1 && conds != w.conditions) return s;
            int poses = m / rpp;
            Effect.Target t = e.target();
            double[] g = new double[t == Effect.Target.POSITION ? 3 * k : k];
            double[] gr = e.turnsFrame() && rpp > posRows ? new double[3 * k] : null; // the frame's turn, seen by orientation rows
            for (int end = 0; end < ends; end++) {
                List<Measurement> er = endRows.get(end);
                List<PoseConditions> ec = ends > 1 ? endConditions.get(end) : conds;
                double[] dq = endDQ[end], ds = endDStrain[end], dt = endDTrans[end], dr = endDRot[end];
                for (int i = 0; i < poses; i++) {
                    if (t != Effect.Target.POSITION) e.regressor(er.get(i), ec.get(i), g);
                    if (gr != null) e.rotationRegressor(er.get(i).q(), ec.get(i), gr);
                    for (int a = 0; a < rpp; a++) {
                        int row = i * rpp + a;
                        // An effect on the measured point moves each point by its own regressor (its place in the base frame).
                        if (t == Effect.Target.POSITION && (a == 0 || pointOfRow(a) != pointOfRow(a - 1)))
                            e.positionRegressor(er.get(i).q(), ec.get(i), ends > 1 ? endPoint[end][i] : pointsBase[i][pointOfRow(a)], g);
                        double d = t == Effect.Target.POSITION ? 0 : t == Effect.Target.STRAIN ? ds[row] : e.driveDerivative(dq, row * dof);
                        for (int col = 0; col < k; col++) {
                            double v;
                            if (t == Effect.Target.POSITION) {
                                v = dt[row * 3] * g[col] + dt[row * 3 + 1] * g[k + col] + dt[row * 3 + 2] * g[2 * k + col];
                                if (gr != null) v += dr[row * 3] * gr[col] + dr[row * 3 + 1] * gr[k + col] + dr[row * 3 + 2] * gr[2 * k + col];
                            } else v = d * g[col];
                            if (Double.isFinite(v)) s[row * k + col] += v;
                        }
                    }
                }
            }
            return s;
        }

        /** Tests one effect with the given per-row conditions. */
        Candidate test(Effect e, List<PoseConditions> conds) {
            Candidate c = testColumns(signature(e, conds), e.size(), e.parameterNames(), null, 0);
            c.effect = e;
            if (c.keptColumns > 0) plausibility(c);
            return c;
        }

        /**
         * Nested test of k signature columns (m x k, row-major) against the current model's span
         * plus {@code extra} (m x nExtra orthonormal columns already in the model, or null):
         * each column projected out of both; a column whose remaining norm (after the columns kept
         * before it, Gram–Schmidt) is below the absorbed ratio of its own norm is dropped. F-test,
         * least-squares estimate (v = −R⁻¹Qᵀr), σ, BIC and PRESS.
         */
        Candidate testColumns(double[] s, int k, List<String> names, double[] extra, int nExtra) {
            double[] proj = new double[m * k], n0 = new double[k], x = new double[m];
            for (int col = 0; col < k; col++) {
                double n = 0;
                for (int i = 0; i < m; i++) { x[i] = s[i * k + col]; n += x[i] * x[i]; }
                n0[col] = Math.sqrt(n);
                if (n == 0) continue;
                double[] px = project(x);
                for (int i = 0; i < m; i++) proj[i * k + col] = px[i];
            }
            return testProjected(proj, n0, k, names, extra, nExtra);
        }

        /** {@link #testColumns} for columns already projected out of the model's span, with their norms before. */
        Candidate testProjected(double[] sp, double[] n0s, int k, List<String> names, double[] extra, int nExtra) {
            return testProjected(sp, n0s, k, names, extra, nExtra, 1);
        }

        // The residual and PRESS with the last extra columns seen (the locate scan tests many probes on the same ones).
        private double[] cacheExtra, cacheRes;
        private double cacheRss, cachePress = Double.NaN;

        /** The residual out of the model's span and of the nExtra orthonormal columns extra (m x nExtra, or none) too. */
        double[] residualOutOf(double[] extra, int nExtra) {
            if (extra == null || nExtra <= 0) return rPerp;
            besideExtra(extra, nExtra);
            return cacheRes;
        }

        /** The sum of squares of {@link #residualOutOf}. */
        double rssOutOf(double[] extra, int nExtra) {
            if (extra == null || nExtra <= 0) return rss0;
            besideExtra(extra, nExtra);
            return cacheRss;
        }

        private void besideExtra(double[] extra, int nExtra) {
            if (cacheExtra == extra) return;
            cacheExtra = extra;
            cacheRes = projectOut(extra, nExtra, m, rPerp);
            cacheRss = 0;
            for (double v : cacheRes) cacheRss += v * v;
            cachePress = Double.NaN;
        }

        /** As above; the leave-one-out error is only computed when p is below {@code pGate} (else it stays infinite). */
        Candidate testProjected(double[] sp, double[] n0s, int k, List<String> names, double[] extra, int nExtra, double pGate) {
            return testProjected(sp, n0s, k, names, extra, nExtra, pGate, false);
        }

        /** As above; with {@code outOfExtra} the columns are already projected out of {@code extra} too. */
        Candidate testProjected(double[] sp, double[] n0s, int k, List<String> names, double[] extra, int nExtra, double pGate,
                                boolean outOfExtra) {
            Candidate c = new Candidate();
            c.absorbedMask = new boolean[k];
            double[][] qs = new double[k][];
            int[] keptIdx = new int[k];
            double[] rr = new double[k * k]; // R, row-major upper triangular over kept columns
            int q = 0;
            double minKept = Double.POSITIVE_INFINITY, maxRatio = 0;
            for (int col = 0; col < k; col++) {
                double[] x = new double[m];
                double n0 = n0s[col] * n0s[col];
                for (int i = 0; i < m; i++) x[i] = sp[i * k + col];
                double ratio = 0;
                if (n0 > 0) {
                    if (extra != null && nExtra > 0 && !outOfExtra) x = projectOut(extra, nExtra, m, x);
                    for (int t = 0; t < q; t++) { // Gram–Schmidt against the kept columns, twice for stability
                        double d = 0;
                        for (int i = 0; i < m; i++) d += qs[t][i] * x[i];
                        rr[t * k + q] = d;
                        for (int i = 0; i < m; i++) x[i] -= d * qs[t][i];
                    }
                    for (int t = 0; t < q; t++) {
                        double d = 0;
                        for (int i = 0; i < m; i++) d += qs[t][i] * x[i];
                        rr[t * k + q] += d;
                        for (int i = 0; i < m; i++) x[i] -= d * qs[t][i];
                    }
                    double n1 = 0;
                    for (double v : x) n1 += v * v;
                    ratio = Math.sqrt(n1 / n0);
                    if (ratio >= w.o.absorbedRatio()) {
                        double nn = Math.sqrt(n1);
                        for (int i = 0; i < m; i++) x[i] /= nn;
                        qs[q] = x;
                        rr[q * k + q] = nn;
                        keptIdx[q] = col;
                        q++;
                        minKept = Math.min(minKept, ratio);
                    }
                }
                maxRatio = Math.max(maxRatio, ratio);
                if (q == 0 || keptIdx[q - 1] != col) { c.absorbed.add(names.get(col)); c.absorbedMask[col] = true; }
            }
            c.keptColumns = q;
            c.ratio = q == 0 ? maxRatio : minKept;
            if (q == 0) return c;
            double[] qm = new double[m * q];
            double[] coef = new double[q];
            double[] res = residualOutOf(extra, nExtra);
            double rssBase = rssOutOf(extra, nExtra);
            for (int t = 0; t < q; t++)
                for (int i = 0; i < m; i++) {
                    qm[i * q + t] = qs[t][i];
                    coef[t] += qs[t][i] * res[i];
                }
            double drss = 0;
            for (double v : coef) drss += v * v;
            // R v = −coef (back substitution); residuals are predicted − measured: r + S v = 0
            double[] vk = new double[q];
            for (int a = q - 1; a >= 0; a--) {
                double x = -coef[a];
                for (int b = a + 1; b < q; b++) x -= rr[a * k + b] * vk[b];
                vk[a] = x / rr[a * k + a];
            }
            // R⁻¹ for the covariance
            double[] rinv = new double[q * q];
            for (int col = 0; col < q; col++) {
                for (int a = q - 1; a >= 0; a--) {
                    double x = a == col ? 1 : 0;
                    for (int b = a + 1; b < q; b++) x -= rr[a * k + b] * rinv[b * q + col];
                    rinv[a * q + col] = x / rr[a * k + a];
                }
            }
            c.df1 = q;
            c.df2 = m - rank - nExtra - q;
            double rss1 = Math.max(rssBase - drss, 1e-300);
            double s2 = rss1 / Math.max(1, c.df2);
            c.estimate = new double[k];
            c.sd = new double[k];
            for (int a = 0; a < q; a++) {
                c.estimate[keptIdx[a]] = vk[a];
                double var = 0;
                for (int b = 0; b < q; b++) var += rinv[a * q + b] * rinv[a * q + b];
                c.sd[keptIdx[a]] = Math.sqrt(s2 * var);
            }
            c.f = (drss / q) / (rss1 / Math.max(1, c.df2));
            c.p = Stats.fUpperTail(c.f, q, c.df2);
            c.bic = m * Math.log(rss1 / m) + q * Math.log(m);
            c.rssReduction = rssBase > 0 ? drss / rssBase : 0;
            c.drss = drss;
            c.basis = qm;
            c.coef = coef;
            if (!(c.p < pGate)) { c.pressBefore = press0; c.pressAfter = Double.POSITIVE_INFINITY; return c; }
            double[] e1 = res.clone();
            for (int i = 0; i < m; i++) {
                double v = 0;
                for (int t = 0; t < q; t++) v += qm[i * q + t] * coef[t];
                e1[i] -= v;
            }
            if (extra != null && nExtra > 0) {
                // PRESS with and without the candidate, both on top of the extra columns
                double[] both = new double[m * (nExtra + q)];
                for (int i = 0; i < m; i++) {
                    System.arraycopy(extra, i * nExtra, both, i * (nExtra + q), nExtra);
                    System.arraycopy(qm, i * q, both, i * (nExtra + q) + nExtra, q);
                }
                if (Double.isNaN(cachePress)) cachePress = press(res, extra, nExtra);
                c.pressBefore = cachePress;
                c.pressAfter = press(e1, both, nExtra + q);
            } else {
                c.pressBefore = press0;
                c.pressAfter = press(e1, qm, q);
            }
            return c;
        }
    }

    /** Orthonormal basis (m x rank, row-major) of the column-scaled columns {@code cols} of a row-major m x n matrix. */
    static double[] basis(double[] jac, int m, int n, List<Integer> cols) {
        int nc = cols.size();
        if (nc == 0) return new double[0];
        DMatrixRMaj a = new DMatrixRMaj(m, nc);
        for (int k = 0; k < nc; k++) {
            int c = cols.get(k);
            double s = 0;
            for (int i = 0; i < m; i++) s += jac[i * n + c] * jac[i * n + c];
            s = s > 0 ? 1 / Math.sqrt(s) : 0;
            for (int i = 0; i < m; i++) a.data[i * nc + k] = jac[i * n + c] * s;
        }
        // A = Q R (Householder), then R = U_r Σ Vᵀ: A = (Q U_r) Σ Vᵀ, the SVD's rotations applied to nc x nc, not m x nc
        // (Golub & Van Loan, Matrix Computations, 4th ed., §8.6.3, R-bidiagonalization)
        DMatrixRMaj um;
        SingularValueDecomposition_F64<DMatrixRMaj> svd;
        if (m > nc) {
            QRDecomposition<DMatrixRMaj> qr = DecompositionFactory_DDRM.qr(m, nc);
            if (!qr.decompose(a)) throw new IllegalStateException("QR of the model Jacobian failed");
            DMatrixRMaj r = qr.getR(null, true);
            svd = DecompositionFactory_DDRM.svd(nc, nc, true, false, true);
            if (!svd.decompose(r)) throw new IllegalStateException("SVD of the model Jacobian failed");
            um = new DMatrixRMaj(m, nc);
            CommonOps_DDRM.mult(qr.getQ(null, true), svd.getU(null, false), um);
        } else {
            svd = DecompositionFactory_DDRM.svd(m, nc, true, false, true);
            if (!svd.decompose(a)) throw new IllegalStateException("SVD of the model Jacobian failed");
            um = svd.getU(null, false);
        }
        double[] sv = svd.getSingularValues();
        double smax = 0;
        for (int k = 0; k < svd.numberOfSingularValues(); k++) smax = Math.max(smax, sv[k]);
        List<Integer> keep = new ArrayList<>();
        for (int k = 0; k < svd.numberOfSingularValues(); k++) if (sv[k] > 1e-10 * smax) keep.add(k);
        int rank = keep.size();
        double[] u = new double[m * rank];
        for (int i = 0; i < m; i++) for (int k = 0; k < rank; k++) u[i * rank + k] = um.get(i, keep.get(k));
        return u;
    }

    /** x − U Uᵀ x for an m x rank orthonormal U. */
    static double[] projectOut(double[] u, int rank, int m, double[] x) { return projectOut(u, rank, m, x, 1); }

    /** The k columns s (m x k, row-major) less their projection on the rank orthonormal columns u (m x rank): S − U (Uᵀ S). */
    static double[] projectOut(double[] u, int rank, int m, double[] s, int k) {
        return subtractSpan(u, rank, m, s, k, spanCoefficients(u, rank, m, s, k));
    }

    /** Uᵀ S for the k columns s (m x k, row-major) and the rank orthonormal columns u (m x rank): k x rank, row-major, in one pass over U. */
    static double[] spanCoefficients(double[] u, int rank, int m, double[] s, int k) {
        double[] c = new double[k * rank];
        for (int i = 0; i < m; i++) {
            int ui = i * rank, si = i * k;
            for (int col = 0; col < k; col++) {
                double x = s[si + col];
                if (x == 0) continue;
                int cc = col * rank;
                for (int r = 0; r < rank; r++) c[cc + r] += u[ui + r] * x;
            }
        }
        return c;
    }

    /** S − U C for the coefficients c = Uᵀ S of {@link #spanCoefficients}. */
    static double[] subtractSpan(double[] u, int rank, int m, double[] s, int k, double[] c) {
        double[] out = s.clone();
        int r4 = rank & ~3;
        for (int i = 0; i < m; i++) {
            int ui = i * rank, si = i * k;
            for (int col = 0; col < k; col++) {
                int cc = col * rank;
                // four partial sums: the row's dot product is a chain of dependent additions otherwise
                double v0 = 0, v1 = 0, v2 = 0, v3 = 0;
                int r = 0;
                for (; r < r4; r += 4) {
                    v0 += u[ui + r] * c[cc + r];
                    v1 += u[ui + r + 1] * c[cc + r + 1];
                    v2 += u[ui + r + 2] * c[cc + r + 2];
                    v3 += u[ui + r + 3] * c[cc + r + 3];
                }
                for (; r < rank; r++) v0 += u[ui + r] * c[cc + r];
                out[si + col] -= (v0 + v1) + (v2 + v3);
            }
        }
        return out;
    }

    /**
     * Physical bounds on an estimate, in words. An estimate is implausible when its
     * whole 3σ interval lies outside the bounds: a poorly determined estimate is not condemned
     * for its noise, a well determined one outside the physics is.
     */
    static void plausibility(Candidate c) {
        double[] v = c.estimate;
        double[] sd = c.sd == null ? new double[v.length] : c.sd;
        Effect e = c.effect;
        switch (e.kind()) {
            case COMPLIANCE_VARYING -> {
                // a compliance at every time or temperature: each coefficient of its spline positive, below a soft joint's
                // (with the payload's centre estimated, each function's other three are the compliance times the centre's shift
                // over 0.1 m, of either sign: within a centre no more than MAX_PAYLOAD_SHIFT_M off the file's)
                boolean ok = true;
                int per = e.payloadCentreFree() ? 4 : 1;
                double shift = MAX_PAYLOAD_SHIFT_M / GravityTorques.PAYLOAD_SHIFT_M / MIN_STIFFNESS;
                for (int i = 0; i < v.length; i++)
                    if ((c.absorbedMask == null || !c.absorbedMask[i])
                            && !(i % per == 0 ? overlaps(v[i], sd[i], 0, 1 / MIN_STIFFNESS) : overlaps(v[i], sd[i], -shift, shift))) ok = false;
                c.plausible = ok;
                c.plausibility = String.format(Locale.ROOT, "the compliance positive and below %.0e rad/(N·m) over the %s", 1 / MIN_STIFFNESS,
                        e.along().words);
            }
            case COMPLIANCE -> {
                if (e.gravity().massesUnknown()) {
                    // only the payload's coefficient is a compliance; the others are it times unknown masses and centres
                    int p = e.gravity().payloadIndex();
                    c.plausible = c.absorbedMask != null && c.absorbedMask[p] || overlaps(v[p], sd[p], 1 / MAX_STIFFNESS, 1 / MIN_STIFFNESS);
                    c.plausibility = String.format(Locale.ROOT, "stiffness from the payload %.3g N·m/rad within %.0e..%.0e (positive)",
                            1 / v[p], MIN_STIFFNESS, MAX_STIFFNESS);
                    return;
                }
                if (e.perMass()) {
                    boolean ok = true;
                    for (int i = 0; i < v.length; i++)
                        if ((c.absorbedMask == null || !c.absorbedMask[i]) && !overlaps(v[i], sd[i], 0, 3 / MIN_STIFFNESS)) ok = false;
                    c.plausible = ok;
                    c.plausibility = "every mass's compliance coefficient positive and below " + String.format(Locale.ROOT, "%.0e", 3 / MIN_STIFFNESS);
                    return;
                }
                double k = 1 / v[0];
                if (e.stiffens()) {
                    // a reducer's stiffness rises with the torque (c3 < 0); one that softens is not a spring's curve
                    c.plausible = overlaps(v[0], sd[0], 1 / MAX_STIFFNESS, 1 / MIN_STIFFNESS) && v[1] - 3 * sd[1] <= 0;
                    c.plausibility = String.format(Locale.ROOT, "stiffness %.3g N·m/rad within %.0e..%.0e (positive), cubic term %.3g "
                            + "not positive (stiffening)", k, MIN_STIFFNESS, MAX_STIFFNESS, v[1]);
                    return;
                }
                c.plausible = overlaps(v[0], sd[0], 1 / MAX_STIFFNESS, 1 / MIN_STIFFNESS);
                c.plausibility = String.format(Locale.ROOT, "stiffness %.3g N·m/rad within %.0e..%.0e (positive)", k,
                        MIN_STIFFNESS, MAX_STIFFNESS);
            }
            case PERIODIC -> {
                double max = 0;
                boolean ok = true;
                for (int h = 0; h < v.length / 2; h++) {
                    double amp = Math.hypot(v[2 * h], v[2 * h + 1]);
                    max = Math.max(max, amp);
                    if (amp - 3 * Math.max(sd[2 * h], sd[2 * h + 1]) >= MAX_PERIODIC_RAD) ok = false;
                }
                c.plausible = ok;
                c.plausibility = String.format(Locale.ROOT, "largest harmonic amplitude %.4f deg < %.2f deg",
                        Math.toDegrees(max), Math.toDegrees(MAX_PERIODIC_RAD));
            }
            case BACKLASH -> {
                c.plausible = overlaps(v[0], sd[0], 0, MAX_BACKLASH_RAD);
                c.plausibility = String.format(Locale.ROOT, "lost motion %.4f deg positive and < %.1f deg",
                        Math.toDegrees(v[0]), Math.toDegrees(MAX_BACKLASH_RAD));
                if (e.runout()) {
                    // the play may not close over the turn: its change (at every order at once) no larger than its mean
                    double change = 0, changeSd = 0;
                    for (int i = 1; i + 1 < v.length; i += 2) {
                        change += Math.hypot(v[i], v[i + 1]);
                        changeSd = Math.max(changeSd, Math.max(sd[i], sd[i + 1]));
                    }
                    c.plausible &= change - 3 * (Double.isFinite(changeSd) ? changeSd : 0) <= v[0] + 3 * (Double.isFinite(sd[0]) ? sd[0] : 0);
                    c.plausibility += String.format(Locale.ROOT, ", its change over the turn %.4f deg no larger", Math.toDegrees(change));
                }
            }
            case THERMAL -> {
                if (e.usesTimeProxy()) {
                    c.plausible = overlaps(v[0], sd[0], 0, MAX_STRAIN);
                    c.plausibility = String.format(Locale.ROOT, "warm-up strain %.3g positive and < %.0e", v[0], MAX_STRAIN);
                } else {
                    c.plausible = overlaps(v[0], sd[0], 0, MAX_ALPHA);
                    c.plausibility = String.format(Locale.ROOT, "expansion coefficient %.3g /K positive and < %.0e /K", v[0], MAX_ALPHA);
                }
            }
            case THERMAL_LINK -> {
                boolean ok = true;
                int nl = e.warms() ? v.length / 2 : v.length;
                // A link that lags the air moves through less of the air's span, so per kelvin of its own lagged temperature
                // it may grow more: the bound is on its growth over the campaign, at most MAX_LINK_ALPHA per kelvin of the air's.
                double[] taus = e.lagTaus();
                ThermalLag lag = e.lag();
                for (int i = 0; i < v.length; i++) {
                    double max = i < nl ? MAX_LINK_ALPHA : MAX_LINK_ALPHA * MAX_WARM_K;
                    if (i < nl && lag != null && taus[i] > 0 && lag.span(taus[i]) > 0) max *= Math.max(1, lag.span(0) / lag.span(taus[i]));
                    if ((c.absorbedMask == null || !c.absorbedMask[i]) && !overlaps(v[i], sd[i], 0, max)) ok = false;
                }
                c.plausible = ok;
                c.plausibility = String.format(Locale.ROOT, "every link's coefficient positive and < %.0e /K%s%s", MAX_LINK_ALPHA,
                        e.lags() ? " of the air's span" : "",
                        e.warms() ? String.format(Locale.ROOT, ", its warm-up's growth positive and < %.0e", MAX_LINK_ALPHA * MAX_WARM_K) : "");
            }
            case DRIFT -> {
                double n = Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]), sn = Math.max(sd[0], Math.max(sd[1], sd[2]));
                double max = e.usesTimeProxy() ? MAX_DRIFT_PER_H : MAX_DRIFT_PER_K;
                c.plausible = overlaps(n, sn, 0, max);
                c.plausibility = String.format(Locale.ROOT, "drift %.3g mm per %s < %.2g", n * 1e3, e.usesTimeProxy() ? "hour" : "K", max * 1e3);
            }
            case GRAVITY_PLAY -> {
                // a shape of no known family: no larger than a play can be, either way (against the torque the words say it is no
                // clearance held by gravity)
                c.plausible = Math.abs(v[0]) < MAX_BACKLASH_RAD;
                c.plausibility = String.format(Locale.ROOT, "play %.4f deg < %.1f deg", Math.toDegrees(Math.abs(v[0])),
                        Math.toDegrees(MAX_BACKLASH_RAD));
            }
            case LINK_PERIODIC -> {
                // a shape of no known family: each harmonic within a smooth error's bound
                double max = 0;
                for (int h = 0; h < v.length / 2; h++) max = Math.max(max, Math.hypot(v[2 * h], v[2 * h + 1]));
                c.plausible = max < 2 * MAX_PERIODIC_RAD;
                c.plausibility = String.format(Locale.ROOT, "largest harmonic amplitude %.4f deg < %.2f deg", Math.toDegrees(max),
                        Math.toDegrees(2 * MAX_PERIODIC_RAD));
            }
            case LOAD_PERIODIC, WARM_PERIODIC -> {
                // without load and at the reference torque (at either end of the temperatures), each order within a smooth error's bound
                double max = 0;
                for (int h = 0, n = v.length / 4; h < n; h++) {
                    double amp = Math.hypot(v[2 * h], v[2 * h + 1]), per = Math.hypot(v[2 * n + 2 * h], v[2 * n + 2 * h + 1]);
                    max = Math.max(max, Math.max(amp, amp + per));
                }
                c.plausible = max < 2 * MAX_PERIODIC_RAD;
                c.plausibility = e.kind() == Effect.Kind.WARM_PERIODIC
                        ? String.format(Locale.ROOT, "largest amplitude at %.1f or %.1f °C %.4f deg < %.2f deg", e.rangeLo(), e.rangeHi(),
                        Math.toDegrees(max), Math.toDegrees(2 * MAX_PERIODIC_RAD))
                        : String.format(Locale.ROOT, "largest amplitude at no load or at %.0f N·m %.4f deg < %.2f deg",
                        e.loadRefNm(), Math.toDegrees(max), Math.toDegrees(2 * MAX_PERIODIC_RAD));
            }
            case SMOOTH -> {
                double r = Words.rmsSmooth(e, v);
                c.plausible = r < MAX_PERIODIC_RAD * 2;
                c.plausibility = String.format(Locale.ROOT, "RMS error %.4f deg < %.2f deg", Math.toDegrees(r), Math.toDegrees(2 * MAX_PERIODIC_RAD));
            }
            case PAIR -> {
                // the periodic terms' amplitudes (the products, k's once-per-turn term) as a transmission error's (twice, as the
                // smooth error's), the terms proportional to an angle as a coupling's
                double amp = 0, lin = 0;
                for (int i = 0; i < v.length; i++)
                    if (Effect.pairTermPeriodic(i)) amp = Math.max(amp, Math.abs(v[i]));
                    else lin = Math.max(lin, Math.abs(v[i]));
                c.plausible = amp < 2 * MAX_PERIODIC_RAD && lin < MAX_COUPLING;
                c.plausibility = String.format(Locale.ROOT, "largest product amplitude %.4f deg < %.2f deg, linear terms %.2g < %.0e",
                        Math.toDegrees(amp), Math.toDegrees(2 * MAX_PERIODIC_RAD), lin, MAX_COUPLING);
            }
            case SETTLING -> {
                // the deflection after a move at a radian per second (a fast joint's speed): within a play's size, either sign (the
                // vibration's phase at the reading decides it)
                c.plausible = Math.abs(v[0]) < MAX_BACKLASH_RAD;
                c.plausibility = String.format(Locale.ROOT, "deflection at 1 rad/s %.4f deg < %.1f deg", Math.toDegrees(Math.abs(v[0])),
                        Math.toDegrees(MAX_BACKLASH_RAD));
            }
            case ZERO_STEP, ANGLE_STEP -> {
                // a slipped encoder or a misread bit can jump by more than a play, not by a visible fraction of a turn
                c.plausible = Math.abs(v[0]) < MAX_BACKLASH_RAD;
                c.plausibility = String.format(Locale.ROOT, "step %.4f deg < %.1f deg", Math.toDegrees(Math.abs(v[0])), Math.toDegrees(MAX_BACKLASH_RAD));
            }
            case ZERO_DRIFT -> {
                // (the constant is the zero's, the geometry's)
                double d = spread(v);
                c.plausible = d < MAX_BACKLASH_RAD;
                c.plausibility = String.format(Locale.ROOT, "the zero's drift within %.4f deg < %.1f deg", Math.toDegrees(d), Math.toDegrees(MAX_BACKLASH_RAD));
            }
            case SECOND_STATION -> {
                // a registration off by more than a few millimetres or milliradians would have been seen when the stations were set up
                double d = Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]), w = Math.sqrt(v[3] * v[3] + v[4] * v[4] + v[5] * v[5]);
                c.plausible = d < MAX_STATION_SHIFT_M && w < MAX_STATION_TURN_RAD;
                c.plausibility = String.format(Locale.ROOT, "shift %.3f mm < %.0f mm, turn %.1f µrad < %.0f µrad", d * 1e3, MAX_STATION_SHIFT_M * 1e3,
                        w * 1e6, MAX_STATION_TURN_RAD * 1e6);
            }
            case LOAD_TILT -> {
                // the tilt at the largest torque on the poses, a bearing's tilt error motion's bound
                double r = Math.hypot(Math.abs(v[0]) + Math.abs(v[1]), Math.abs(v[2]) + Math.abs(v[3]));
                double d = Math.hypot(Math.abs(v[4]) + Math.abs(v[5]), Math.abs(v[6]) + Math.abs(v[7]));
                c.plausible = r < MAX_WOBBLE_RAD && d < MAX_RUNOUT_M;
                c.plausibility = String.format(Locale.ROOT, "tilt at the largest torque %.4f deg < %.2f deg, shift %.4f mm < %.1f mm",
                        Math.toDegrees(r), Math.toDegrees(MAX_WOBBLE_RAD), d * 1e3, MAX_RUNOUT_M * 1e3);
            }
            case TOOL_PULL -> {
                // each joint yields toward the pull (its compliance times the force is positive) and by less than a few degrees per
                // metre of lever: a 200 N pull on a 5000 N·m/rad wrist drive; a joint the pull hardly loads has a coefficient too
                // uncertain to condemn
                boolean toward = e.pullAnchor() != null, ok = true;
                double most = 0;
                for (int i = 0; i < v.length; i++) {
                    if (c.absorbedMask != null && c.absorbedMask[i]) continue;
                    most = Math.max(most, Math.abs(v[i]));
                    if (!overlaps(v[i], sd[i], toward ? 0 : -MAX_PULL_TURN_PER_M, MAX_PULL_TURN_PER_M)) ok = false;
                }
                c.plausible = ok;
                c.plausibility = String.format(Locale.ROOT, "every joint yields %sby less than %.1f deg per metre of lever across the "
                        + "pull (largest %.4f deg)", toward ? "toward the pull and " : "", Math.toDegrees(MAX_PULL_TURN_PER_M), Math.toDegrees(most));
            }
            case LINK_TWIST -> {
                // each lever's twist at a metre of lever and at a rated payload of 20 kg
                double most = 0;
                for (int i = 0; i < v.length; i++) most = Math.max(most, Math.abs(v[i]) * (i < Effect.TWIST_ARM_TERMS ? 1 : 20));
                c.plausible = most < MAX_LINK_TURN_RAD;
                c.plausibility = String.format(Locale.ROOT, "each weight's twist at a metre's lever (20 kg of payload) %.4f deg < %.2f deg",
                        Math.toDegrees(most), Math.toDegrees(MAX_LINK_TURN_RAD));
            }
            case LINK_SAG -> {
                c.plausible = Math.abs(v[0]) < MAX_TOOL_SAG_M && Math.abs(v[1]) < MAX_LINK_TURN_RAD;
                c.plausibility = String.format(Locale.ROOT, "far end %.3f mm < %.0f mm, turn %.4f deg < %.2f deg", Math.abs(v[0]) * 1e3,
                        MAX_TOOL_SAG_M * 1e3, Math.toDegrees(Math.abs(v[1])), Math.toDegrees(MAX_LINK_TURN_RAD));
            }
            case TARGET_INCIDENCE -> {
                boolean ok = true;
                double m = 0;
                for (int i = 0; i < v.length; i++) {
                    // each term's move where the line of sight is half a radian off its mean (a reflector's acceptance)
                    double atEdge = v[i] * Math.pow(0.5, Effect.incidenceDegree(i)), sdEdge = sd[i] * Math.pow(0.5, Effect.incidenceDegree(i));
                    m = Math.max(m, Math.abs(atEdge));
                    if ((c.absorbedMask == null || !c.absorbedMask[i]) && !overlaps(atEdge, sdEdge, -MAX_INCIDENCE_M, MAX_INCIDENCE_M)) ok = false;
                }
                c.plausible = ok;
                c.plausibility = String.format(Locale.ROOT, "every term's move half a radian off the mean sight within %.0f mm (largest %.3f mm)",
                        MAX_INCIDENCE_M * 1e3, m * 1e3);
            }
            case TOOL_PLAY -> {
                double d = Words.rmsOverCircle(v);
                c.plausible = d < MAX_TOOL_SAG_M;
                c.plausibility = String.format(Locale.ROOT, "play %.3f mm < %.0f mm", d * 1e3, MAX_TOOL_SAG_M * 1e3);
            }
            case TOOL_SAG -> {
                double d = Words.sagSpan(v);
                c.plausible = d < MAX_TOOL_SAG_M;
                c.plausibility = String.format(Locale.ROOT, "deflection %.3f mm < %.0f mm", d * 1e3, MAX_TOOL_SAG_M * 1e3);
            }
            case AXIAL_RUNOUT -> {
                double r = Words.rmsOverCircle(v);
                c.plausible = r < MAX_RUNOUT_M;
                c.plausibility = String.format(Locale.ROOT, "RMS shift %.4f mm < %.1f mm", r * 1e3, MAX_RUNOUT_M * 1e3);
            }
            case AXIS_WOBBLE -> {
                double r = Words.rmsOverCircle(v);
                c.plausible = r < MAX_WOBBLE_RAD;
                c.plausibility = String.format(Locale.ROOT, "RMS tilt %.4f deg < %.2f deg", Math.toDegrees(r), Math.toDegrees(MAX_WOBBLE_RAD));
            }
            case BASE_TILT -> {
                // the base tips the way the moment pushes it; a compliance of 1e-5 rad/(N·m) would be a loose base indeed
                c.plausible = overlaps(v[0], sd[0], 0, MAX_TILT_PER_NM);
                c.plausibility = String.format(Locale.ROOT, "tilt %.3g rad/(N·m) positive and < %.0e", v[0], MAX_TILT_PER_NM);
            }
            case INSTRUMENT -> {
                double r = Words.rmsInstrument(e, v);
                boolean range = e.sight() == Effect.Sight.RANGE;
                c.plausible = r < (range ? MAX_INSTRUMENT_RANGE_M : MAX_INSTRUMENT_ANGLE_RAD);
                c.plausibility = range ? String.format(Locale.ROOT, "RMS distance error %.4f mm < %.1f mm", r * 1e3, MAX_INSTRUMENT_RANGE_M * 1e3)
                        : String.format(Locale.ROOT, "RMS angle error %.1f arc-seconds < %.0f", Math.toDegrees(r) * 3600,
                        Math.toDegrees(MAX_INSTRUMENT_ANGLE_RAD) * 3600);
            }
            case SCALE -> {
                c.plausible = overlaps(v[0], sd[0], -MAX_SCALE, MAX_SCALE);
                c.plausibility = String.format(Locale.ROOT, "|scale error| %.3g < %.0e", Math.abs(v[0]), MAX_SCALE);
            }
            case COUPLING -> {
                c.plausible = overlaps(v[0], sd[0], -MAX_COUPLING, MAX_COUPLING);
                c.plausibility = String.format(Locale.ROOT, "|coupling| %.3g < %.0e", Math.abs(v[0]), MAX_COUPLING);
            }
            case RANGE_STEP -> {
                c.plausible = Math.abs(v[0]) < MAX_RANGE_STEP_M;
                c.plausibility = String.format(Locale.ROOT, "the distance's jump %.4f mm < %.1f mm", Math.abs(v[0]) * 1e3, MAX_RANGE_STEP_M * 1e3);
            }
            case BASE_STEP -> {
                double d = Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]), turn = Math.sqrt(v[3] * v[3] + v[4] * v[4] + v[5] * v[5]);
                c.plausible = d < MAX_TARGET_STEP_M && turn < MAX_BASE_TURN_RAD;
                c.plausibility = String.format(Locale.ROOT, "the move %.4f mm < %.0f mm, the turn %.1f µrad < %.0f µrad", d * 1e3,
                        MAX_TARGET_STEP_M * 1e3, turn * 1e6, MAX_BASE_TURN_RAD * 1e6);
            }
            case BASE_CREEP -> {
                c.plausible = Math.abs(v[0]) < MAX_BASE_TURN_RAD && Math.hypot(v[1], v[2]) < MAX_TARGET_STEP_M;
                c.plausibility = String.format(Locale.ROOT, "the turn per slip %.1f µrad < %.0f µrad, the shift %.4f mm < %.0f mm",
                        Math.abs(v[0]) * 1e6, MAX_BASE_TURN_RAD * 1e6, Math.hypot(v[1], v[2]) * 1e3, MAX_TARGET_STEP_M * 1e3);
            }
            case TARGET_DRIFT -> {
                // a B-spline's curve lies within its coefficients' range: the largest change along a flange axis bounds the drift
                int n = e.basisCount();
                double d = 0;
                for (int a = 0; a < 3; a++) d = Math.max(d, spread(Arrays.copyOfRange(v, a * n, (a + 1) * n)));
                c.plausible = d < MAX_TARGET_STEP_M;
                c.plausibility = String.format(Locale.ROOT, "the target's drift along a flange axis within %.4f mm < %.0f mm", d * 1e3,
                        MAX_TARGET_STEP_M * 1e3);
            }
            case TARGET_STEP -> {
                double d = Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
                c.plausible = d < MAX_TARGET_STEP_M;
                c.plausibility = String.format(Locale.ROOT, "the target's move %.4f mm < %.0f mm", d * 1e3, MAX_TARGET_STEP_M * 1e3);
            }
            case REFRACTION -> {
                // (the constant is partly the geometry's) k = κ/2 = (n − 1)/(2T) · dT/dz: the gradient's change within a hall's
                double d = spread(v) * 2 * 293.15 / 2.7e-4;
                c.plausible = d < MAX_GRADIENT_CHANGE;
                c.plausibility = String.format(Locale.ROOT, "the air's vertical temperature gradient changing by %.2f K/m < %.0f K/m", d,
                        MAX_GRADIENT_CHANGE);
            }
            case INSTRUMENT_AXES -> {
                // a measuring machine's squareness is held to tens of µrad; an instrument a thousand off is broken, not out of square
                double d = 0, bow = 0;
                for (int i = 0; i < v.length; i++) {
                    if (i < Effect.AXES_COLUMNS) d = Math.max(d, Math.abs(v[i]));
                    else bow = Math.max(bow, Math.abs(v[i]));
                }
                c.plausible = d < MAX_INSTRUMENT_AXES && bow < MAX_INSTRUMENT_BOW;
                c.plausibility = String.format(Locale.ROOT, "the axes' scale and squareness within %.1f ppm < %.0f ppm", 1e6 * d,
                        1e6 * MAX_INSTRUMENT_AXES) + (e.bowed() ? String.format(Locale.ROOT, ", the ways' bow %.1f µm/m² < %.0f µm/m²",
                        1e6 * bow, 1e6 * MAX_INSTRUMENT_BOW) : "");
            }
            case INSTRUMENT_SCALE -> {
                // the scale's change over the readings (its constant part is the geometry's)
                double d = spread(v);
                c.plausible = d < MAX_INSTRUMENT_SCALE;
                c.plausibility = String.format(Locale.ROOT, "the scale's change within %.2f ppm < %.0f ppm", 1e6 * d, 1e6 * MAX_INSTRUMENT_SCALE);
            }
            case BASE_TURN -> {
                // a B-spline's curve lies within its coefficients' range: the largest turn bounds the tilt
                int nb = e.basisCount();
                double turn = 0, move = 0;
                for (int i = 0; i < 3 * nb; i++) turn = Math.max(turn, Math.abs(v[i]));
                for (int i = 3 * nb; i < v.length; i++) move = Math.max(move, Math.abs(v[i]));
                c.plausible = turn < MAX_BASE_TURN_RAD && move < MAX_TARGET_STEP_M;
                c.plausibility = String.format(Locale.ROOT, "turn within %.1f µrad < %.0f µrad, move %.4f mm < %.0f mm", 1e6 * turn,
                        1e6 * MAX_BASE_TURN_RAD, 1e3 * move, 1e3 * MAX_TARGET_STEP_M);
            }
            case POINT_SMOOTH -> {
                // a B-spline's curve lies within its coefficients' range, so the largest bounds the displacement
                double d = 0;
                for (double x : v) d = Math.max(d, Math.abs(x));
                c.plausible = d < MAX_TARGET_STEP_M;
                c.plausibility = String.format(Locale.ROOT, "the point's displacement within %.4f mm < %.0f mm", d * 1e3, MAX_TARGET_STEP_M * 1e3);
            }
            default -> { }
        }
    }

    /**
     * The spread of a B-spline's coefficients, max − min: the curve lies within them, so it bounds how
     * much the curve changes over its range.
     */
    private static double spread(double[] v) {
        return Arrays.stream(v).max().orElse(0) - Arrays.stream(v).min().orElse(0);
    }

    /** Whether [v − 3σ, v + 3σ] meets [lo, hi]. */
    private static boolean overlaps(double v, double sd, double lo, double hi) {
        double s = Double.isFinite(sd) ? 3 * sd : 0;
        return v + s > lo && v - s < hi;
    }

    /** Solves a small dense system in place (Gaussian elimination, partial pivoting); false when singular. */
    static boolean solve(double[] a, double[] b, int n) {
        for (int col = 0; col < n; col++) {
            int piv = col;
            for (int r = col + 1; r < n; r++) if (Math.abs(a[r * n + col]) > Math.abs(a[piv * n + col])) piv = r;
            if (Math.abs(a[piv * n + col]) < 1e-12) return false;
            if (piv != col) {
                for (int c = 0; c < n; c++) { double t = a[col * n + c]; a[col * n + c] = a[piv * n + c]; a[piv * n + c] = t; }
                double t = b[col]; b[col] = b[piv]; b[piv] = t;
            }
            for (int r = col + 1; r < n; r++) {
                double f = a[r * n + col] / a[col * n + col];
                if (f == 0) continue;
                for (int c = col; c < n; c++) a[r * n + c] -= f * a[col * n + c];
                b[r] -= f * b[col];
            }
        }
        for (int r = n - 1; r >= 0; r--) {
            double s = b[r];
            for (int c = r + 1; c < n; c++) s -= a[r * n + c] * b[c];
            b[r] = s / a[r * n + r];
        }
        return true;
    }
}
