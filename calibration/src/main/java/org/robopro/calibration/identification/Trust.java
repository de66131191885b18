package org.robopro.calibration.identification;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.robopro.calibration.identification.CalibrationResult.ParameterEstimate;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.models.JointDescription;
import org.robopro.models.JointType;

/**
 * Which identified parameters the data really determine, in words. A parameter is not
 * trustworthy when its σ exceeds a physically meaningful size ({@value #SIGMA_MM} mm for a
 * length, {@value #SIGMA_DEG}° for an angle) or when its estimate is correlated with another's
 * beyond |ρ| = {@value #CORRELATION} (the data move the two together, so each value alone means
 * little). The fit may still predict the measured point well; such a parameter makes the
 * calibrated file unreliable for another tool point, for orientation, or for another tool. Each
 * concern names what to measure to fix it.
 */
public final class Trust {
    private Trust() { }

    public static final double SIGMA_MM = 1.0, SIGMA_DEG = 0.1, CORRELATION = 0.99;

    /** Distance of the measured point from the last joint's axis below which wrist offsets are poorly seen, m. */
    static final double NEAR_AXIS_M = 0.05;

    /** Fraction of a joint's range the poses should span. */
    static final double SPAN_FRACTION = 0.6;

    /**
     * One parameter the data do not determine well.
     *
     * @param parameter  its name
     * @param reason     why, with the figure (σ or ρ)
     * @param advice     what data would fix it
     */
    public record Concern(String parameter, String reason, String advice) {
        public String sentence() {
            return parameter + " is not determined by these data (" + reason + "): " + advice
                    + "; do not rely on the calibrated file for another tool point or for orientation";
        }
    }

    private static final Pattern JOINT = Pattern.compile("j(\\d+)\\..+");

    /** The concerns of a calibration of {@code train}, one per parameter, in parameter order. */
    public static List<Concern> assess(CalibrationResult r, MeasurementSet train) {
        Map<String, Concern> out = new LinkedHashMap<>();
        for (ParameterEstimate p : r.parameters()) {
            if (p.fixed() || Double.isNaN(p.sigma())) continue;
            String reason = null;
            if ("m".equals(p.unitSi()) && p.sigma() * 1e3 > SIGMA_MM)
                reason = String.format(Locale.ROOT, "σ %.3g mm > %.0f mm", p.sigma() * 1e3, SIGMA_MM);
            else if ("rad".equals(p.unitSi()) && Math.toDegrees(p.sigma()) > SIGMA_DEG)
                reason = String.format(Locale.ROOT, "σ %.3g° > %.1f°", Math.toDegrees(p.sigma()), SIGMA_DEG);
            if (reason != null) out.put(p.name(), new Concern(p.name(), reason, advice(p.name(), r, train)));
        }
        for (CalibrationResult.Correlation c : r.correlations()) {
            if (Math.abs(c.rho()) <= CORRELATION) continue;
            String reason = String.format(Locale.ROOT, "its estimate moves with %s's, correlation %.4f", c.b(), c.rho());
            out.merge(c.a(), new Concern(c.a(), reason, advice(c.a(), r, train)),
                    (old, fresh) -> new Concern(old.parameter(), old.reason() + "; " + fresh.reason(), old.advice()));
            String reasonB = String.format(Locale.ROOT, "its estimate moves with %s's, correlation %.4f", c.a(), c.rho());
            out.merge(c.b(), new Concern(c.b(), reasonB, advice(c.b(), r, train)),
                    (old, fresh) -> new Concern(old.parameter(), old.reason() + "; " + fresh.reason(), old.advice()));
        }
        List<Concern> ordered = new ArrayList<>();
        for (ParameterEstimate p : r.parameters()) if (out.containsKey(p.name())) ordered.add(out.get(p.name()));
        return ordered;
    }

    /** What data would determine parameter {@code name} better. */
    static String advice(String name, CalibrationResult r, MeasurementSet train) {
        List<JointDescription> joints = r.nominal().description().joints();
        int dof = joints.size();
        Matcher m = JOINT.matcher(name);
        if (m.matches()) {
            int j = Integer.parseInt(m.group(1));
            // The farthest measured point from the last joint's axis (the flange z axis) decides what the wrist shows.
            double offAxis = 0;
            for (var tool : r.toolPoints()) offAxis = Math.max(offAxis, Math.hypot(tool.x(), tool.y()));
            if (j >= dof - 1 && offAxis < NEAR_AXIS_M && !r.sixD())
                return String.format(Locale.ROOT, "move the measured point off the joint-%d axis (it is %.1f mm from it; "
                        + "50 mm or more separates the wrist offsets), or measure orientations too (6-D data) or two more "
                        + "points on the flange (several reflectors per pose)", dof, offAxis * 1e3);
            if (j >= 1 && j <= dof) {
                String span = span(train, joints.get(j - 1), j - 1);
                if (span != null) return span;
            }
            return String.format(Locale.ROOT, "add poses that move joint %d together with its neighbours in more varied "
                    + "configurations, or measure orientations or a second point on the flange", j);
        }
        if (name.startsWith("tool.")) {
            String wrist = "";
            for (int j = Math.max(1, dof - 2); j <= dof; j++) {
                String s = span(train, joints.get(j - 1), j - 1);
                if (s != null) wrist = "; " + s;
            }
            return "measure the point with the wrist (joints " + Math.max(1, dof - 2) + " to " + dof + ") turned over wider ranges" + wrist;
        }
        if (name.startsWith("instrument."))
            return "spread the poses over a larger part of the workspace, in all three directions";
        return "add poses in more varied configurations";
    }

    /** "add poses with joint N beyond ..." when the data span less than {@link #SPAN_FRACTION} of the joint's range, else null. */
    static String span(MeasurementSet train, JointDescription jd, int index) {
        if (!(jd.max() > jd.min()) || !Double.isFinite(jd.max() - jd.min()) || train.size() == 0) return null;
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
        for (Measurement row : train.rows()) {
            lo = Math.min(lo, row.q(index));
            hi = Math.max(hi, row.q(index));
        }
        double range = jd.max() - jd.min();
        if (hi - lo >= SPAN_FRACTION * range) return null;
        boolean rev = jd.type() == JointType.REVOLUTE;
        double k = rev ? 180 / Math.PI : 1e3;
        String u = rev ? "°" : " mm";
        return String.format(Locale.ROOT, "add poses with joint %d over more of its range (the poses span %.0f%s to %.0f%s of %.0f%s to %.0f%s)",
                index + 1, lo * k, u, hi * k, u, jd.min() * k, u, jd.max() * k, u);
    }

    /** Provenance value listing the untrustworthy parameters, or "none". */
    public static String provenance(List<Concern> concerns) {
        if (concerns.isEmpty()) return "none";
        List<String> names = new ArrayList<>();
        for (Concern c : concerns) names.add(c.parameter());
        return String.join(", ", names);
    }
}
