package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.robopro.calibration.WorldCampaigns;
import org.robopro.world.JointError;
import org.robopro.world.Scenario;

/**
 * Joints read as whole counts of their motor encoders (the world's {@link JointError.Counts}: the
 * joint anywhere within the count, an error no recorded variable predicts). Nothing is named and no
 * shape is located; the joints whose counts matter at the point are located as scattering, each by
 * about the world's own count over √12.
 */
class JointScatterTest {

    @Test
    void coarseEncoderCounts_locatedAsTheJointsScatter_sizedByTheCount() {
        for (long seed : new long[] {20261124, 20261126}) {
            WorldCampaigns.Sim s = WorldCampaigns.of(Scenario.named(
                    "outside: joint angles read as whole counts of 1000-count motor encoders, puma560, sigma 0.01 mm").trial(seed));
            Diagnosis d = Diagnoser.diagnose(s.nominal(), s.train(), s.validation());
            assertEquals(List.of(), d.effects().stream().map(f -> f.effect().label()).toList(), "seed " + seed + ": notes " + d.notes());
            List<Diagnosis.Located> scatter = d.located().stream().filter(l -> l.variable().endsWith(" reading")).toList();
            assertTrue(scatter.size() >= 2, "seed " + seed + ": " + d.located());
            for (Diagnosis.Located l : scatter) {
                int joint = Integer.parseInt(l.variable().replaceAll("\\D", "")) - 1;
                double count = s.world().errors().stream().filter(e -> e instanceof JointError.Counts c && c.joint() == joint)
                        .mapToDouble(e -> ((JointError.Counts) e).countRad()).findFirst().orElseThrow();
                double truthDeg = Math.toDegrees(count) / Math.sqrt(12);
                double found = Double.parseDouble(l.shape().replaceAll(".* by ([0-9.]+) deg.*", "$1"));
                assertTrue(Math.abs(found - truthDeg) < 0.35 * truthDeg, "seed " + seed + ": " + l.shape() + " against the world's "
                        + truthDeg + " deg RMS");
                assertTrue(l.words().contains("whole counts") && l.words().contains("settle"), l.words());
                // a count's error does not grow with the move before the reading
                assertTrue(!l.words().contains("grows with the joint's speed"), l.words());
                // the evidence: the residual along the joint's motion spreads more where its lever is longer (the poses split at the median lever)
                Diagnosis.Plot p = l.plot();
                double lo = 0, hi = 0;
                int nLo = 0, nHi = 0;
                double mid = java.util.Arrays.stream(p.x()).sorted().toArray()[p.x().length / 2];
                for (int i = 0; i < p.x().length; i++)
                    if (p.x()[i] < mid) { lo += p.y()[i] * p.y()[i]; nLo++; } else { hi += p.y()[i] * p.y()[i]; nHi++; }
                assertTrue(hi / nHi > lo / nLo, "seed " + seed + ": spread " + Math.sqrt(lo / nLo) + " then " + Math.sqrt(hi / nHi));
            }
        }
    }

    /**
     * The arm read while it still rings after its stop, the moment of the reading varying by most of
     * the vibration's period (the world's settling at 8 Hz, ζ 0.03, read 0.5-0.6 s after the stop):
     * the deflection's phase at the reading is as good as random, so no shape follows it, but its size
     * follows the braking. The joints are located as scattering, and the words say the scatter grows
     * with the joint's speed in the move before the reading: the arm read before it settled.
     */
    @Test
    void armRingingAtAVaryingMomentOfTheReading_scattersWithTheMovesSpeed() {
        double[] accel = {2.0, 1.6, 2.4, 6, 6, 8};
        List<JointError> ringing = new java.util.ArrayList<>();
        for (int j = 0; j < 3; j++) ringing.add(new JointError.Settling(j, 8, 0.03, 0.5, 0.1, accel));
        for (long seed : new long[] {1, 2}) {
            WorldCampaigns.Sim s = HeldOutFormsTest.world("irb2000", org.robopro.world.Expected.outside(), ringing, p -> p, seed);
            Diagnosis d = Diagnoser.diagnose(s.nominal(), s.train(), s.validation());
            assertTrue(d.effects().stream().noneMatch(f -> !f.effect().isFallback()), "seed " + seed + ": notes " + d.notes());
            List<Diagnosis.Located> scatter = d.located().stream().filter(l -> l.variable().endsWith(" reading")).toList();
            assertTrue(!scatter.isEmpty(), "seed " + seed + ": " + d.located());
            assertTrue(scatter.stream().anyMatch(l -> l.words().contains("grows with the joint's speed in the move made just before")),
                    "seed " + seed + ": " + scatter.stream().map(Diagnosis.Located::words).toList());
        }
    }
}
