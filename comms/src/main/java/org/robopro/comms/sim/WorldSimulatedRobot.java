package org.robopro.comms.sim;

import com.fasterxml.jackson.core.type.TypeReference;
import java.io.IOException;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import org.robopro.calibration.PoseConditions;
import org.robopro.kinematics.KinematicModel;
import org.robopro.models.JsonMapper;
import org.robopro.models.RobotDescription;
import org.robopro.models.Vec3;
import org.robopro.world.Scenario;
import org.robopro.world.WorldRobot;

/**
 * The simulated controller's robot when the physical robot comes from the independent world
 * simulator ({@code controller-sim --world SCENARIO}): the controller computes with the nominal
 * model as always; the tracker sees a {@link WorldRobot} of the named scenario (its own
 * kinematics and physics, with whatever the scenario conceals, including effects outside every
 * diagnosis family), under the controller's real approach directions, clock, warm-up and payload.
 * Immutable.
 */
public final class WorldSimulatedRobot extends NominalController {
    private final Scenario scenario;
    private final long seed;
    private final WorldRobot world;
    private final double noiseM;

    private WorldSimulatedRobot(RobotDescription d, Scenario scenario, long seed, WorldRobot world, double noiseM) {
        super(d, KinematicModel.build(d));
        this.scenario = scenario;
        this.seed = seed;
        this.world = world;
        this.noiseM = noiseM;
    }

    /**
     * The real robot of world scenario {@code scenarioName} drawn with {@code seed}, its tracker
     * target nominally at {@code targetM} on the flange, tracker noise {@code noiseM} per axis.
     *
     * @throws IllegalArgumentException for an unknown scenario or one on another robot than {@code d}
     */
    public static WorldSimulatedRobot create(RobotDescription d, String scenarioName, long seed, double noiseM, Vec3 targetM) {
        Scenario s = Scenario.named(scenarioName);
        if (!s.robot().equals(d.name()))
            throw new IllegalArgumentException("--world '" + scenarioName + "' is a scenario of the " + s.robot() + ", not of " + d.name());
        return new WorldSimulatedRobot(d, s, seed, s.robot(seed, targetM.toArray()), noiseM);
    }

    public Scenario scenario() { return scenario; }

    public WorldRobot world() { return world; }

    /**
     * What the physical robot conceals, as JSON: the world's truth record, with {@code effects}
     * holding one entry whose {@code label} names the scenario (what a demo reveals).
     */
    public Map<String, Object> truthJson() {
        try {
            Map<String, Object> m = JsonMapper.create().readValue(scenario.truthJson(seed, world),
                    new TypeReference<LinkedHashMap<String, Object>>() { });
            m.put("effects", scenario.expected().verdict() == org.robopro.world.Expected.Verdict.NULL ? List.of()
                    : List.of(Map.of("label", scenario.name())));
            return m;
        } catch (IOException e) {
            throw new IllegalStateException(e);
        }
    }

    @Override
    public Vec3 measure(double[] q, PoseConditions c, Random rng) {
        int[] dir = c.directions();
        if (dir == null) {
            dir = new int[q.length];
            Arrays.fill(dir, 1);
        }
        double payload = Double.isNaN(c.payloadKg()) ? 0 : c.payloadKg();
        double[] p = world.target(q, dir, c.tempC(), c.timeS(), payload).p();
        return new Vec3(p[0] + noiseM * rng.nextGaussian(), p[1] + noiseM * rng.nextGaussian(), p[2] + noiseM * rng.nextGaussian());
    }

    @Override public boolean thermal() { return world.temperatureMatters(); }
}
