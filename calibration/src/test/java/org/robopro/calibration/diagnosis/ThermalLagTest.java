package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.PoseConditions;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.kinematics.KinematicModel;
import org.robopro.models.RobotLibrary;
import org.robopro.models.Vec3;

/**
 * The lagged temperature of a body against the closed-form solution of Newton's law of cooling
 * for an air temperature that warms up exponentially, T_air = A + R (1 − exp(−t/τa)): a body with
 * time constant τ starting at A follows T_b = A + R [1 − (τa exp(−t/τa) − τ exp(−t/τ)) / (τa − τ)]
 * (the convolution of the air's rise with the body's impulse response exp(−t/τ)/τ).
 */
class ThermalLagTest {
    private static Measurement row(int i, double t, double temp) {
        return new Measurement(Integer.toString(i), new double[6], new Vec3(0, 0, 0), null, null, t, temp, Double.NaN, null, 0);
    }

    private static double air(double t) { return 20 + 6 * (1 - Math.exp(-t / 1500)); }

    private static double body(double t, double tau) {
        double ta = 1500;
        return 20 + 6 * (1 - (ta * Math.exp(-t / ta) - tau * Math.exp(-t / tau)) / (ta - tau));
    }

    @Test
    void followsTheClosedFormLagOfAWarmUp() {
        List<Measurement> rows = new ArrayList<>();
        // readings every 12 s over 2400 s, in shuffled order (the history is taken in time order)
        for (int i = 200; i >= 0; i--) rows.add(row(i, 12.0 * i, air(12.0 * i)));
        ThermalLag lag = ThermalLag.of(rows);
        for (double tau : new double[] {150, 600, 2400})
            for (double t : new double[] {60, 600, 1203, 2400}) {
                double expect = body(t, tau);
                assertEquals(expect, lag.at(tau, t, air(t)), 2e-3, "tau " + tau + " at " + t + " s");
            }
        // no lag, and outside the campaign: the reading
        assertEquals(23.5, lag.at(0, 600, 23.5), 0);
        assertEquals(25.0, lag.at(600, 9000, 25.0), 0);
        assertEquals(25.0, lag.at(600, Double.NaN, 25.0), 0);
        // a long lag lags far behind the air late in the warm-up
        assertEquals(air(2400) - body(2400, 2400), air(2400) - lag.at(2400, 2400, air(2400)), 2e-3);
    }

    @Test
    void noHistoryWithoutAChangeOfTemperature() {
        List<Measurement> rows = new ArrayList<>();
        for (int i = 0; i < 20; i++) rows.add(row(i, 10.0 * i, 21.0));
        assertNull(ThermalLag.of(rows));
        assertNull(ThermalLag.of(List.of(row(0, 0, 20), row(1, 10, 21))));
    }

    @Test
    void laggedGrowthIsWrittenAndReadBackWithItsLags_andTakesTheReadingWithoutItsHistory() {
        KinematicModel model = KinematicModel.build(RobotLibrary.shipped("irb2400"));
        List<Measurement> rows = new ArrayList<>();
        for (int i = 0; i <= 200; i++) rows.add(row(i, 12.0 * i, air(12.0 * i)));
        ThermalLag lag = ThermalLag.of(rows);
        int n = Effect.thermalLinks(model, 20).size();
        double[] taus = new double[n], alpha = new double[n];
        for (int i = 0; i < n; i++) { taus[i] = i == 0 ? 2400 : 600; alpha[i] = 2e-5; }
        Effect grown = Effect.thermalLinks(model, 20, lag, taus);
        Effect.Term back = Effect.fromDescription(grown.describe(alpha), model, null, "test");
        assertArrayEquals(taus, back.effect().lagTaus(), 0);
        assertEquals(grown.label(), back.effect().label());
        // read back, the campaign's history is gone: each link is taken at the reading (in equilibrium), as unlagged
        double[] q = {0.3, -0.2, 0.4, 0.1, 0.5, -0.3}, point = {1.2, 0.3, 0.9};
        PoseConditions c = new PoseConditions(null, 600, air(600), Double.NaN);
        double[] g = new double[3 * n], gPlain = new double[3 * n], gLag = new double[3 * n];
        back.effect().positionRegressor(q, c, point, g);
        Effect.thermalLinks(model, 20).positionRegressor(q, c, point, gPlain);
        assertArrayEquals(gPlain, g, 1e-15);
        // with the history, the link lagging by 600 s is cooler than the air at 600 s into the warm-up
        grown.positionRegressor(q, c, point, gLag);
        double ratio = (body(600, 600) - 20) / (air(600) - 20);
        for (int a = 0; a < 3; a++) assertEquals(ratio * gPlain[a * n + 1], gLag[a * n + 1], 1e-4 * Math.abs(gPlain[a * n + 1]) + 1e-12);
        // a negative lag is refused with the field named
        var bad = new java.util.LinkedHashMap<>(grown.describe(alpha).parameters());
        bad.put("lag_s_tool", -5.0);
        var d = new org.robopro.models.EffectDescription("thermal-link", List.of(), bad);
        assertThrows(org.robopro.models.InputException.class, () -> Effect.fromDescription(d, model, null, "robot.json"));
    }

    /**
     * A link that lags the air moves through only part of the air's span, so per kelvin of its own
     * (lagged) temperature its growth over the campaign may be larger: the bound is on that growth,
     * at most {@link Diagnoser#MAX_LINK_ALPHA} per kelvin of the air's span. For air warming on a
     * ramp, T = T0 + s t, a body with time constant τ follows T0 + s (t − τ (1 − exp(−t/τ))) (the
     * ramp response of a first-order lag), so over a campaign of length L its span is
     * s (L − τ (1 − exp(−L/τ))).
     */
    @Test
    void aLaggingLinksBound_isOnItsGrowthOverTheAirsSpan() {
        List<Measurement> rows = new ArrayList<>();
        double slope = 4.0 / 3600, length = 3600, tau = 4800;
        for (int i = 0; i <= 60; i++) rows.add(row(i, 60.0 * i, 19 + slope * 60 * i));
        ThermalLag lag = ThermalLag.of(rows);
        double bodySpan = slope * (length - tau * (1 - Math.exp(-length / tau)));
        assertEquals(4.0, lag.span(0), 1e-9);
        assertEquals(bodySpan, lag.span(tau), 1e-6);
        double allowed = Diagnoser.MAX_LINK_ALPHA * 4.0 / bodySpan; // per kelvin of the lagged temperature
        KinematicModel model = KinematicModel.build(RobotLibrary.shipped("irb2400"));
        int n = Effect.thermalLinks(model, 19).size();
        double[] taus = new double[n];
        java.util.Arrays.fill(taus, tau);
        for (double[] c : new double[][] {{0.9, 1}, {1.1, 0}}) {
            Diagnoser.Candidate lagged = candidate(Effect.thermalLinks(model, 19, lag, taus), c[0] * allowed, n);
            Diagnoser.plausibility(lagged);
            assertEquals(c[1] == 1, lagged.plausible, c[0] + " x the bound: " + lagged.plausibility);
        }
        // at the reading's own temperature the bound stays MAX_LINK_ALPHA per kelvin
        Diagnoser.Candidate plain = candidate(Effect.thermalLinks(model, 19), 0.9 * allowed, n);
        Diagnoser.plausibility(plain);
        assertEquals(false, plain.plausible, plain.plausibility);
    }

    private static Diagnoser.Candidate candidate(Effect e, double alpha, int n) {
        Diagnoser.Candidate c = new Diagnoser.Candidate();
        c.effect = e;
        c.estimate = new double[n];
        java.util.Arrays.fill(c.estimate, alpha);
        c.sd = new double[n];
        java.util.Arrays.fill(c.sd, 1e-8);
        return c;
    }
}
