package org.robopro.calibration.diagnosis;

import java.util.Locale;

/** Findings in plain words for the report. */
final class Words {
    private Words() { }

    static String finding(Effect e, double[] v, double[] s, Diagnosis.Evidence ev, double trainBefore, double trainAfter,
                          double valBefore, double valAfter, Directions.Source dirs) {
        String what = switch (e.kind()) {
            case COMPLIANCE -> String.format(Locale.ROOT, "Joint %d gives way under the arm's weight: compliance %.3g ± %.2g "
                    + "rad/(N·m), a stiffness of %.3g N·m/rad.", e.joint() + 1, v[0], s[0], 1 / v[0]);
            case PERIODIC -> {
                StringBuilder sb = new StringBuilder(String.format(Locale.ROOT,
                        "Joint %d has a transmission error that repeats with its angle (gear or encoder eccentricity):", e.joint() + 1));
                for (int h = 1; h <= Effect.HARMONICS; h++)
                    sb.append(String.format(Locale.ROOT, " harmonic %d %.4f ± %.4f deg%s", h,
                            Math.toDegrees(Math.hypot(v[2 * h - 2], v[2 * h - 1])),
                            Math.toDegrees(Math.max(s[2 * h - 2], s[2 * h - 1])), h < Effect.HARMONICS ? "," : "."));
                if (ev.projectionRatio() < 0.3)
                    sb.append(String.format(Locale.ROOT, " Only %.0f %% of its signature is distinct from geometry on these poses, "
                            + "so the amplitudes are uncertain; a wider range of joint %d would separate them.",
                            100 * ev.projectionRatio(), e.joint() + 1));
                if (!ev.absorbed().isEmpty())
                    sb.append(" Terms ").append(String.join(", ", ev.absorbed()))
                            .append(" look like geometry on these poses and were left to the geometric model.");
                yield sb.toString();
            }
            case BACKLASH -> String.format(Locale.ROOT, "Joint %d has lost motion (backlash): its output lags the motor-side "
                    + "encoder by half of %.4f ± %.4f deg behind the direction it last moved in (directions %s).", e.joint() + 1,
                    Math.toDegrees(v[0]), Math.toDegrees(s[0]), dirs.words);
            case THERMAL -> e.usesTimeProxy()
                    ? String.format(Locale.ROOT, "The arm grows while it warms up (thermal expansion, inferred from time): "
                    + "strain %.3g ± %.2g at saturation, time constant %.0f s.", v[0], s[0], e.tauS())
                    : String.format(Locale.ROOT, "The arm grows with temperature (thermal expansion): %.3g ± %.2g per K "
                    + "(steel is about 12e-6, aluminium 23e-6), reference %.1f °C.", v[0], s[0], e.t0C());
            case SCALE -> String.format(Locale.ROOT, "Joint %d turns by a slightly different amount than commanded (gear ratio "
                    + "or encoder scale error): %.3g ± %.2g.", e.joint() + 1, v[0], s[0]);
            case COUPLING -> String.format(Locale.ROOT, "Joint %d moves a little with joint %d (coupling error between the axes): "
                    + "%.3g ± %.2g rad per rad.", e.joint() + 1, e.source() + 1, v[0], s[0]);
        };
        String fit = String.format(Locale.ROOT, " Modelling it lowers the training RMS from %.4f to %.4f mm", trainBefore * 1e3,
                trainAfter * 1e3);
        if (Double.isFinite(valBefore)) fit += String.format(Locale.ROOT, " and the validation RMS from %.4f to %.4f mm", valBefore * 1e3, valAfter * 1e3);
        fit += String.format(Locale.ROOT, " (F = %.1f on %d and %d degrees of freedom, p = %.2g below the corrected "
                + "threshold %.2g; leave-one-out prediction error %.1f -> %.1f; %s).", ev.f(), ev.df1(), ev.df2(), ev.pValue(),
                ev.threshold(), ev.pressBefore(), ev.pressAfter(), ev.plausibility());
        return what + fit;
    }

    static String p(double p) { return p < 1e-300 ? "< 1e-300" : String.format(Locale.ROOT, "= %.2g", p); }

    static String implausible(Effect e, double[] v, Diagnosis.Evidence ev) {
        return String.format(Locale.ROOT, "%s would reduce the residuals significantly (F = %.1f, p = %.2g), but its estimate "
                + "is physically implausible (%s), so it is not claimed: the residual structure it fits probably has another "
                + "cause.", e.label(), ev.f(), ev.pValue(), ev.plausibility()).replace("p = 0,", "p < 1e-300,");
    }
}
