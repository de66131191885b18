package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.models.Vec3;

/**
 * The drives' warm-up share of a link through a campaign with a pause, against the heat balance of
 * a lumped body integrated numerically: m c dT/dt = P u(t) − h A (T − T_air), so the rise's share of
 * its warmed-through value P / (h A) obeys ds/dt = (u − s)/τ with τ = m c / (h A) (Incropera &amp;
 * DeWitt, §5.2); u = 1 while the robot moves, 0 while it stands. Fourth-order Runge–Kutta steps of
 * 0.5 s, with the robot's schedule written out here: working from time 0, resting from one reading
 * until one typical gap before the next after a long gap.
 */
class PausesTest {
    private static Measurement row(String id, double t) {
        return new Measurement(id, new double[6], new Vec3(0, 0, 0), null, null, t, 20, Double.NaN, null, 0);
    }

    /** Readings every 12 s from 30 s to 1830 s, a 1500 s pause, then every 12 s for another 1200 s. */
    private static List<Measurement> campaign() {
        List<Measurement> rows = new ArrayList<>();
        for (int i = 0; i <= 150; i++) rows.add(row("a" + i, 30 + 12.0 * i));
        for (int i = 1; i <= 100; i++) rows.add(row("b" + i, 1830 + 1500 + 12.0 * i));
        Collections.shuffle(rows, new java.util.Random(3)); // the history is taken in time order
        return rows;
    }

    /** The robot works except from 1830 s to 1830 + 1500 + 12 − 12 s (the pause less the move to the next pose). */
    private static double u(double t) { return t > 1830 && t < 1830 + 1500 ? 0 : 1; }

    private static double integrated(double tau, double until) {
        double s = 0, h = 0.5;
        for (double t = 0; t < until - 1e-9; t += h) {
            double step = Math.min(h, until - t);
            double k1 = (u(t) - s) / tau, k2 = (u(t + step / 2) - (s + step / 2 * k1)) / tau;
            double k3 = (u(t + step / 2) - (s + step / 2 * k2)) / tau, k4 = (u(t + step) - (s + step * k3)) / tau;
            s += step / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
        }
        return s;
    }

    @Test
    void theWarmUpCoolsThroughAPause_asTheHeatBalanceIntegrated() {
        Pauses p = Pauses.of(campaign());
        assertTrue(p.any());
        assertEquals(1, p.pauses().size());
        assertEquals(1830, p.pauses().get(0)[0], 1e-9);
        assertEquals(1830 + 1500 + 12, p.pauses().get(0)[1], 1e-9);
        for (double tau : new double[] {300, 600, 2400})
            for (double t : new double[] {600, 1830, 1830 + 1512, 1830 + 1512 + 360, 1830 + 1500 + 1200}) {
                double expect = integrated(tau, t);
                assertEquals(expect, p.share(tau, t), 2e-3, "tau " + tau + " s at " + t + " s");
            }
        // the pause matters: after it, the share is well below the uninterrupted warm-up's
        double t = 1830 + 1512;
        assertTrue(p.share(600, t) < (1 - Math.exp(-t / 600)) - 0.5, "cooled through 1500 s");
        // an unknown time (a compensated program) is warmed through
        assertEquals(1, p.share(600, Double.NaN), 0);
    }

    @Test
    void withoutAPause_theShareIsTheUninterruptedWarmUp() {
        List<Measurement> rows = new ArrayList<>();
        double time = 30;
        for (int i = 0; i < 100; i++) {
            rows.add(row("r" + i, time));
            time += i % 7 == 6 ? 50 : 10;
        }
        Pauses p = Pauses.of(rows);
        assertFalse(p.any(), "gaps of up to 5 typical ones are no pause");
        for (double t : new double[] {30, 500, 1000}) assertEquals(1 - Math.exp(-t / 600), p.share(600, t), 0);
        assertNull(Pauses.of(List.of(row("a", 0), row("b", 10))));
    }
}
