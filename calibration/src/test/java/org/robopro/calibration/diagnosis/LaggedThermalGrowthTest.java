package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.WorldCampaigns;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
import org.robopro.models.Vec3;
import org.robopro.world.Campaign;
import org.robopro.world.Scenario;
import org.robopro.world.WorldRobot;

/**
 * Thermal growth link by link where each link's temperature lags the air the sensor reads: a
 * heavy pedestal slowly, the arm's links quickly. The truth is the independent world simulator's
 * (org.robopro.world: its own kinematics, each link growing by its own coefficient; nothing shared
 * with {@link Effect} or {@link ThermalLag}); each link's temperature is the closed-form solution
 * of Newton's law of cooling for the campaign's exponential warm-up, written here, not the
 * diagnosis's recursion. The file records the air's temperature (with the sensor's noise), as a
 * real campaign does.
 */
class LaggedThermalGrowthTest {
    private final RobotDescription irb2000 = RobotLibrary.shipped("irb2000");

    /** A body with time constant tau (s) starting at the air's temperature, under the warm-up w, at t. */
    static double bodyTemperature(Campaign.Warmup w, double tauS, double t) {
        double ta = w.tauS();
        if (tauS == 0) return w.at(t);
        if (Math.abs(ta - tauS) < 1e-6) tauS = ta * (1 + 1e-6);
        return w.ambientC() + w.riseK() * (1 - (ta * Math.exp(-t / ta) - tauS * Math.exp(-t / tauS)) / (ta - tauS));
    }

    /**
     * The trial's campaign re-measured with link i (pedestal 0 … last link) at the temperature of a
     * body with time constant {@code taus[i]}: each point moves by the world's own difference
     * between the lagged and the unlagged growth (the noise and everything else stay).
     */
    static MeasurementSet lagged(Scenario.Trial t, MeasurementSet set, double[] taus) {
        if (set == null) return null;
        WorldRobot w = t.world();
        WorldRobot.Thermal th = w.thermal();
        Campaign.Warmup warm = t.campaign().warmup();
        Map<String, Campaign.Row> byId = new HashMap<>();
        for (Campaign.Row r : t.campaign().rows()) byId.put(r.id(), r);
        List<Measurement> out = new ArrayList<>();
        for (Measurement m : set.rows()) {
            Campaign.Row r = byId.get(m.poseId());
            double[] alpha = th.linkAlpha();
            double[] strain = new double[alpha.length];
            for (int i = 0; i < alpha.length; i++) strain[i] = alpha[i] * (bodyTemperature(warm, taus[i], r.timeS()) - th.refC());
            // strain_i = linkAlpha_i (T − ref) with ref 0 and T 1; the target holder at the air's temperature
            WorldRobot.Thermal at = new WorldRobot.Thermal(0, strain, new double[3], new double[3],
                    th.holderAlpha() * (warm.at(r.timeS()) - th.refC()));
            double[] p = w.withThermal(at).target(r.q(), r.dir(), r.lastMove(), 1, r.timeS(), r.payloadKg()).p();
            double[] d = {p[0] - r.truePoint()[0], p[1] - r.truePoint()[1], p[2] - r.truePoint()[2]};
            Vec3 old = m.position();
            out.add(m.withPosition(new Vec3(old.x() + d[0], old.y() + d[1], old.z() + d[2])));
        }
        return set.withRows(out);
    }

    private static List<String> labels(Diagnosis d) { return d.effects().stream().map(f -> f.effect().label()).toList(); }

    @Test
    void linksLaggingTheAir_areNamedWithALagAndReachTheFloor() {
        // pedestal (a casting) 2400 s, the arm's links 400 s
        double[] taus = {2400, 400, 400, 400, 400, 400, 400};
        for (long seed : new long[] {20261125L, 20261127L}) {
            Scenario.Trial t = Scenario.named("thermal growth per link").trial(seed);
            WorldCampaigns.Sim c = WorldCampaigns.of(t);
            assertTrue(t.world().thermal().linkAlpha().length == taus.length, "links " + t.world().thermal().linkAlpha().length);
            MeasurementSet train = lagged(t, c.train(), taus), val = lagged(t, c.validation(), taus);
            Diagnosis d = Diagnoser.diagnose(irb2000, train, val);
            Diagnosis.Finding growth = d.effects().stream().filter(f -> f.effect().kind() == Effect.Kind.THERMAL_LINK).findFirst()
                    .orElse(null);
            assertTrue(growth != null, "seed " + seed + ": growth link by link not named: " + labels(d) + ", notes " + d.notes());
            // only the growth is named: not a drift with time (its alias), nothing else
            assertTrue(d.effects().size() == 1, "seed " + seed + ": named " + labels(d));
            assertTrue(growth.effect().lags(), "seed " + seed + ": no lag found: " + growth.effect().label());
            // the arm's links (most of the reach) lag by the order of their true 400 s, not by none or by hours
            double[] found = growth.effect().lagTaus();
            int near = 0;
            for (double x : found) if (x >= 150 && x <= 1200) near++;
            assertTrue(near >= found.length / 2, "seed " + seed + ": lags " + growth.effect().label());
            assertTrue(d.finalValidateRmsM() < 1.15 * c.floorM(), "seed " + seed + ": " + d.finalValidateRmsM() + " vs floor " + c.floorM());
        }
    }

    @Test
    void linksAtTheAirsTemperature_needNoLag() {
        // the world's own growth: every link at the air's temperature (no lag): the unlagged growth stays
        Scenario.Trial t = Scenario.named("thermal growth per link").trial(20261125L);
        WorldCampaigns.Sim c = WorldCampaigns.of(t);
        Diagnosis d = Diagnoser.diagnose(irb2000, c.train(), c.validation());
        Diagnosis.Finding growth = d.effects().stream().filter(f -> f.effect().kind() == Effect.Kind.THERMAL_LINK).findFirst()
                .orElse(null);
        assertTrue(growth != null, "growth not named: " + labels(d));
        for (double x : growth.effect().lagTaus()) assertTrue(x <= 300, "a lag where there is none: " + growth.effect().label());
        assertTrue(d.finalValidateRmsM() < 1.15 * c.floorM(), d.finalValidateRmsM() + " vs floor " + c.floorM());
    }
}
