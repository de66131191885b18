package org.robopro.calibration.diagnosis;

import java.util.Random;
import org.robopro.calibration.PoseConditions;
import org.robopro.calibration.simulation.CampaignSimulator;

/**
 * Realistic per-pose conditions for a simulated campaign with non-geometric effects (the
 * measurement file's optional columns, shared/formats/measurements.md):
 * <ul>
 * <li>{@code dir1..dirN}: each joint's approach direction, the sign of its move from the previous
 *     pose in the sequence as measured (the first pose: random);</li>
 * <li>{@code time_s}: {@link #SECONDS_PER_POSE} per pose plus 0–2 s of jitter;</li>
 * <li>{@code temp_c}: a warm-up T(t) = 20 °C + ΔT (1 − e^(−t/τ)) plus 0.05 K of sensor noise;</li>
 * <li>{@code payload_kg} (only when asked, for compliance): 0, ½ and the full rated payload in
 *     turn, changed every 15 poses.</li>
 * </ul>
 * Used by {@code robopro simulate --effect} and the concealed-effect benchmark. Stateful (it
 * remembers the previous pose): one instance per campaign, not thread-safe.
 */
public final class SimulatedConditions implements CampaignSimulator.ConditionsSource {
    /** Seconds between poses of a campaign (time_s). */
    public static final double SECONDS_PER_POSE = 20;
    /** Poses between payload changes. */
    public static final int POSES_PER_PAYLOAD = 15;

    private final Random rng;
    private final double warmK, tauS, ratedPayloadKg;
    private double[] prevQ;

    /**
     * @param seed           seed of the conditions' own randomness (first directions, time jitter, sensor noise)
     * @param warmK          temperature rise of the warm-up, K
     * @param tauS           its time constant, s
     * @param ratedPayloadKg payload steps up to this mass, or NaN for no payload column
     */
    public SimulatedConditions(long seed, double warmK, double tauS, double ratedPayloadKg) {
        if (!(warmK >= 0) || !(tauS > 0)) throw new IllegalArgumentException("warm-up " + warmK + " K over " + tauS + " s");
        this.rng = new Random(seed);
        this.warmK = warmK;
        this.tauS = tauS;
        this.ratedPayloadKg = ratedPayloadKg;
    }

    /**
     * Conditions with a warm-up drawn from a realistic range (ΔT 10–15 K, τ 900–2400 s; two numbers
     * taken from {@code sizes}).
     */
    public static SimulatedConditions realistic(Random sizes, long seed, double ratedPayloadKg) {
        double warm = EffectSpec.uniform(sizes, 10, 15), tau = EffectSpec.uniform(sizes, 900, 2400);
        return new SimulatedConditions(seed, warm, tau, ratedPayloadKg);
    }

    public double warmK() { return warmK; }

    public double tauS() { return tauS; }

    /** The warm-up curve without sensor noise, °C at t seconds. */
    public double temperatureC(double tS) { return EffectSpec.AMBIENT_C + warmK * (1 - Math.exp(-tS / tauS)); }

    @Override
    public PoseConditions conditions(Random simulatorRng, double[] q, int i) {
        int[] dir = new int[q.length];
        for (int j = 0; j < q.length; j++) dir[j] = prevQ == null ? (rng.nextBoolean() ? 1 : -1) : (q[j] >= prevQ[j] ? 1 : -1);
        prevQ = q.clone();
        double t = i * SECONDS_PER_POSE + EffectSpec.uniform(rng, 0, 2);
        double temp = temperatureC(t) + 0.05 * rng.nextGaussian();
        double payload = Double.isNaN(ratedPayloadKg) ? Double.NaN : ratedPayloadKg * ((i / POSES_PER_PAYLOAD) % 3) / 2.0;
        return new PoseConditions(dir, t, temp, payload);
    }
}
