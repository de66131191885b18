package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.measurement.Measurement;
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
}
