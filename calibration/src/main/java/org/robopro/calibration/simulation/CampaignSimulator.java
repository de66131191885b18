package org.robopro.calibration.simulation;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import org.robopro.calibration.JointEffect;
import org.robopro.calibration.PoseConditions;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.calibration.report.CalibrationReport;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.ModelParameter;
import org.robopro.kinematics.Pose;
import org.robopro.kinematics.Units;
import org.robopro.models.AtomicFiles;
import org.robopro.models.Vec3;

/**
 * Simulates a calibration campaign: a "true" robot is the nominal model with random
 * errors on its identifiable parameter vector (so the truth is exactly representable and
 * parameters compare one to one), scaled so the nominal model's RMS flange error is
 * {@link SimulationSettings#errorM()}; a measured point on the flange with its own error; an
 * instrument 2.5–3.5 m away at a random heading (unless frame: base); Gaussian noise; poses by
 * {@link PoseSampler}'s rule. Effects (diagnosis) are added through {@link JointEffect}s.
 */
public final class CampaignSimulator {
    private CampaignSimulator() { }

    public static Campaign simulate(KinematicModel nominal, SimulationSettings s) {
        return simulate(nominal, s, List.of(), (rng, q, i) -> PoseConditions.NONE);
    }

    /** Supplies the conditions of pose i (time, temperature, payload, directions) for effect studies. */
    @FunctionalInterface
    public interface ConditionsSource {
        PoseConditions conditions(Random rng, double[] q, int index);
    }

    /** A campaign with non-geometric effects on the true robot and per-pose conditions. */
    public static Campaign simulate(KinematicModel nominal, SimulationSettings s, List<JointEffect> effects,
                                    ConditionsSource conditions) {
        Random rng = new Random(s.seed());
        PoseSampler sampler = new PoseSampler(nominal);
        List<double[]> sizing = sampler.sample(100, new Random(s.seed() ^ 0x5DEECE66DL));
        KinematicModel trueModel = perturb(nominal, s.errorM(), sizing, rng);

        Vec3 target = s.nominalTarget().plus(new Vec3(rng.nextGaussian(), rng.nextGaussian(), rng.nextGaussian())
                .times(s.targetErrorM()));
        Pose flangeTtool = Pose.translation(target);
        if (s.sixD()) {
            Vec3 axis = new Vec3(rng.nextGaussian(), rng.nextGaussian(), rng.nextGaussian());
            flangeTtool = flangeTtool.times(Pose.rotAxis(axis, Math.toRadians(0.5) * rng.nextGaussian()));
        }
        Pose instrumentTbase = Pose.IDENTITY;
        if (!s.baseFrame()) {
            double heading = 2 * Math.PI * rng.nextDouble();
            double dist = 2.5 + rng.nextDouble();
            Pose baseTinstrument = Pose.translation(dist * Math.cos(heading), dist * Math.sin(heading), rng.nextDouble())
                    .times(Pose.rotZ(2 * Math.PI * rng.nextDouble()))
                    .times(Pose.rotX(Math.toRadians(5) * (2 * rng.nextDouble() - 1)))
                    .times(Pose.rotY(Math.toRadians(5) * (2 * rng.nextDouble() - 1)));
            instrumentTbase = baseTinstrument.inverse();
        }
        TrueRobot truth = new TrueRobot(trueModel, flangeTtool, instrumentTbase, s.sigmaM(), s.sixD() ? s.sigmaRotRad() : 0, effects);

        List<double[]> qs = sampler.sample(s.poses() + s.validatePoses(), rng);
        List<Measurement> train = new ArrayList<>(), validate = new ArrayList<>();
        double sumSq = 0;
        for (int i = 0; i < qs.size(); i++) {
            double[] q = qs.get(i);
            PoseConditions c = conditions.conditions(rng, q, i);
            Vec3 p = truth.measure(q, c, rng);
            double[] o = s.sixD() ? truth.measureOrientation(q, c, rng) : null;
            Measurement m = new Measurement(Integer.toString(i + 1), q, p, o, c.directions(), c.timeS(), c.tempC(),
                    c.payloadKg(), null, 0);
            if (i < s.poses()) {
                train.add(m);
                sumSq += Math.pow(nominal.flange(q).distanceTo(trueModel.flange(q)), 2);
            } else validate.add(m);
        }
        Map<String, String> meta = new LinkedHashMap<>();
        meta.put("robot", nominal.description().name());
        meta.put("frame", s.baseFrame() ? MeasurementSet.BASE_FRAME : "tracker");
        meta.put("instrument", String.format(java.util.Locale.ROOT, "simulated, sigma %.4f mm, seed %d",
                Units.mToMm(s.sigmaM()), s.seed()));
        String frame = meta.get("frame");
        MeasurementSet trainSet = new MeasurementSet("simulated", meta, frame, train);
        MeasurementSet validateSet = validate.isEmpty() ? null : new MeasurementSet("simulated-validate", meta, frame, validate);
        return new Campaign(nominal, truth, s, trainSet, validateSet, Math.sqrt(sumSq / Math.max(1, s.poses())));
    }

    /**
     * The campaign with more reflectors on the flange: point 1 is the campaign's measured point,
     * points 2.. sit nominally at {@code morePoints} (flange coordinates, m) with the same
     * placement error per axis as the first; every pose measures them all (the same true robot,
     * instrument and noise; conditions from each row). Noise and placement errors come from their
     * own random stream, so point 1 is the single-point campaign's. Points are named 1, 2, ...
     */
    public static Campaign withPoints(Campaign c, List<Vec3> morePoints) {
        if (morePoints.isEmpty()) return c;
        SimulationSettings s = c.settings();
        if (s.sixD()) throw new IllegalArgumentException("several measured points per pose go without orientations");
        Random rng = new Random(s.seed() * 31 + 17);
        TrueRobot t = c.truth();
        List<TrueRobot> others = new ArrayList<>();
        for (Vec3 v : morePoints) {
            Vec3 target = v.plus(new Vec3(rng.nextGaussian(), rng.nextGaussian(), rng.nextGaussian()).times(s.targetErrorM()));
            others.add(new TrueRobot(t.model(), Pose.translation(target), t.instrumentTbase(), t.sigmaM(), 0, t.effects()));
        }
        List<String> names = new ArrayList<>();
        for (int k = 1; k <= morePoints.size() + 1; k++) names.add(Integer.toString(k));
        MeasurementSet train = morePoints(c.measurements(), others, names, rng);
        MeasurementSet validate = c.validation() == null ? null : morePoints(c.validation(), others, names, rng);
        return new Campaign(c.nominal(), t, s, train, validate, c.nominalErrorRmsM(), others.stream().map(o -> o.flangeTtool().position()).toList(),
                null);
    }

    private static MeasurementSet morePoints(MeasurementSet set, List<TrueRobot> others, List<String> names, Random rng) {
        List<Measurement> rows = new ArrayList<>();
        for (Measurement m : set.rows()) {
            List<Vec3> pts = new ArrayList<>(List.of(m.position()));
            for (TrueRobot o : others) pts.add(o.measure(m.q(), PoseConditions.of(m), rng));
            rows.add(new Measurement(m.poseId(), m.q(), null, null, m.directions(), m.timeS(), m.tempC(), m.payloadKg(), m.set(),
                    m.line(), pts, Double.NaN));
        }
        return new MeasurementSet(set.source(), set.metadata(), set.frame(), rows, names, null);
    }

    /**
     * The campaign as lengths between the true measured point's places at consecutive poses (a
     * length artefact or a ballbar probed by the robot, a tracker's distance between two stops): a
     * row per pose after the first of each file, with the pose before it as the first pose (its
     * joints and directions; each end at its own conditions), the campaign's noise σ on each length
     * (its own random stream).
     */
    public static Campaign asPairs(Campaign c) {
        SimulationSettings s = c.settings();
        if (s.sixD() || !c.morePoints().isEmpty()) throw new IllegalArgumentException("distances are measured to one point, without orientations");
        Random rng = new Random(s.seed() * 31 + 37);
        MeasurementSet train = pairs(c, c.measurements(), rng);
        MeasurementSet validate = c.validation() == null ? null : pairs(c, c.validation(), rng);
        return new Campaign(c.nominal(), c.truth(), s, train, validate, c.nominalErrorRmsM(), List.of(), null);
    }

    private static MeasurementSet pairs(Campaign c, MeasurementSet set, Random rng) {
        if (set.size() < 2) throw new IllegalArgumentException("distances between consecutive poses need at least two poses per file");
        List<Measurement> rows = new ArrayList<>();
        Measurement prev = null;
        Vec3 before = null;
        for (Measurement m : set.rows()) {
            Vec3 p = c.truth().tool(m.q(), PoseConditions.of(m)).position();
            if (prev != null) {
                double d = p.minus(before).norm() + c.truth().sigmaM() * rng.nextGaussian();
                rows.add(new Measurement(m.poseId(), m.q(), null, null, m.directions(), m.timeS(), m.tempC(), m.payloadKg(), m.set(),
                        m.line(), null, d, prev.q(), m.directions() == null ? null : prev.directions()));
            }
            prev = m;
            before = p;
        }
        Map<String, String> meta = new LinkedHashMap<>(set.metadata());
        meta.remove("frame");
        meta.put("instrument", meta.getOrDefault("instrument", "simulated").replace("simulated", "simulated length between two poses"));
        return new MeasurementSet(set.source(), meta, MeasurementSet.BASE_FRAME, rows, List.of(), null);
    }

    /**
     * The campaign as a draw-wire sensor (or a tracker in distance mode) would have measured it:
     * per pose the length from {@code anchorBase} (robot base frame, m) to the true measured
     * point, with the campaign's noise σ on the length (its own random stream). The anchor is not
     * written in the files (it is what a user would not know); truth.json holds it.
     */
    public static Campaign asDistances(Campaign c, Vec3 anchorBase) {
        SimulationSettings s = c.settings();
        if (s.sixD() || !c.morePoints().isEmpty()) throw new IllegalArgumentException("distances are measured to one point, without orientations");
        Random rng = new Random(s.seed() * 31 + 29);
        MeasurementSet train = distances(c, c.measurements(), anchorBase, rng);
        MeasurementSet validate = c.validation() == null ? null : distances(c, c.validation(), anchorBase, rng);
        return new Campaign(c.nominal(), c.truth(), s, train, validate, c.nominalErrorRmsM(), List.of(), anchorBase);
    }

    private static MeasurementSet distances(Campaign c, MeasurementSet set, Vec3 anchor, Random rng) {
        List<Measurement> rows = new ArrayList<>();
        for (Measurement m : set.rows()) {
            Vec3 p = c.truth().tool(m.q(), PoseConditions.of(m)).position();
            double d = p.minus(anchor).norm() + c.truth().sigmaM() * rng.nextGaussian();
            rows.add(new Measurement(m.poseId(), m.q(), null, null, m.directions(), m.timeS(), m.tempC(), m.payloadKg(), m.set(),
                    m.line(), null, d));
        }
        Map<String, String> meta = new LinkedHashMap<>(set.metadata());
        meta.remove("frame");
        meta.put("instrument", meta.getOrDefault("instrument", "simulated").replace("simulated", "simulated draw-wire"));
        return new MeasurementSet(set.source(), meta, MeasurementSet.BASE_FRAME, rows, List.of(), null);
    }

    /**
     * The nominal model with Gaussian errors on every identifiable parameter (1 mm : 1 mrad),
     * scaled so that the RMS flange position error over {@code poses} is {@code errorM}.
     */
    public static KinematicModel perturb(KinematicModel nominal, double errorM, List<double[]> poses, Random rng) {
        double[] p0 = nominal.parameterValues();
        List<ModelParameter> ps = nominal.parameters();
        double[] dir = new double[p0.length];
        for (int i = 0; i < dir.length; i++) dir[i] = rng.nextGaussian() * 1e-3;
        if (errorM == 0) return nominal;
        double k = errorM / 1e-3 / Math.sqrt(ps.size()); // first guess
        KinematicModel m = nominal;
        for (int iter = 0; iter < 4; iter++) {
            double[] p = p0.clone();
            for (int i = 0; i < p.length; i++) p[i] += k * dir[i];
            m = nominal.withParameterValues(p);
            double rms = flangeRms(nominal, m, poses);
            if (!(rms > 0)) break;
            k *= errorM / rms;
        }
        double[] p = p0.clone();
        for (int i = 0; i < p.length; i++) p[i] += k * dir[i];
        return nominal.withParameterValues(p);
    }

    /** RMS distance between two models' flange origins over poses, m. */
    public static double flangeRms(KinematicModel a, KinematicModel b, List<double[]> poses) {
        double s = 0;
        for (double[] q : poses) s += Math.pow(a.flange(q).distanceTo(b.flange(q)), 2);
        return Math.sqrt(s / poses.size());
    }

    /**
     * The truth as JSON (mm, deg, quaternions w-first): true parameters next to the nominal ones,
     * the instrument pose, the measured point and tool frame, noise, seed, and the nominal error.
     */
    public static String truthJson(Campaign c) {
        return truthJson(c, null);
    }

    /**
     * The truth as JSON with {@code effects} given by the caller (e.g. each injected effect with its
     * values, as diagnosis describes them) instead of the effects' names; null: the names.
     */
    public static String truthJson(Campaign c, List<? extends Map<String, ?>> effectEntries) {
        Map<String, Object> root = new LinkedHashMap<>();
        SimulationSettings s = c.settings();
        root.put("robot", c.nominal().description().name());
        root.put("seed", s.seed());
        root.put("sigma_mm", Units.mToMm(s.sigmaM()));
        root.put("sigma_rot_deg", Units.radToDeg(c.truth().sigmaRotRad()));
        root.put("nominal_flange_rms_mm", Units.mToMm(c.nominalErrorRmsM()));
        root.put("frame", c.measurements().frame());
        root.put("instrument_T_base", CalibrationReport.poseJson(c.truth().instrumentTbase()));
        root.put("target_in_flange_mm", vecMm(c.truth().flangeTtool().position()));
        if (!c.morePoints().isEmpty()) root.put("more_targets_in_flange_mm", c.morePoints().stream().map(CampaignSimulator::vecMm).toList());
        if (c.anchor() != null) root.put("anchor_base_mm", vecMm(c.anchor()));
        root.put("flange_T_tool", CalibrationReport.poseJson(c.truth().flangeTtool()));
        List<Map<String, Object>> params = new ArrayList<>();
        double[] nom = c.nominal().parameterValues(), tru = c.truth().model().parameterValues();
        List<ModelParameter> ps = c.nominal().parameters();
        for (int i = 0; i < ps.size(); i++) {
            Map<String, Object> e = new LinkedHashMap<>();
            boolean t = ps.get(i).kind() == ModelParameter.Kind.TRANSLATION;
            e.put("name", ps.get(i).name());
            e.put("unit", t ? "mm" : "deg");
            e.put("nominal", t ? Units.mToMm(nom[i]) : Units.radToDeg(nom[i]));
            e.put("true", t ? Units.mToMm(tru[i]) : Units.radToDeg(tru[i]));
            e.put("true_si", tru[i]);
            params.add(e);
        }
        root.put("parameters", params);
        List<String> eff = new ArrayList<>();
        for (JointEffect e : c.truth().effects()) eff.add(e.name());
        root.put("effects", effectEntries != null ? effectEntries : eff);
        try {
            return org.robopro.models.JsonMapper.create().writeValueAsString(root);
        } catch (IOException e) {
            throw new IllegalStateException(e);
        }
    }

    public static void writeTruth(Campaign c, Path file, boolean overwrite) throws IOException {
        writeTruth(c, null, file, overwrite);
    }

    /** Writes {@link #truthJson(Campaign, List)}. */
    public static void writeTruth(Campaign c, List<? extends Map<String, ?>> effectEntries, Path file, boolean overwrite) throws IOException {
        AtomicFiles.writeString(file, truthJson(c, effectEntries) + "\n", overwrite);
    }

    static List<Double> vecMm(Vec3 v) {
        return List.of(Units.mToMm(v.x()), Units.mToMm(v.y()), Units.mToMm(v.z()));
    }
}
