package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.kinematics.KinematicModel;
import org.robopro.models.RobotLibrary;
import org.robopro.models.Vec3;

/**
 * Which poses beyond the outlier rule are bad readings, and which drives can turn another: the
 * rules judged on poses and arms whose answer is known by construction.
 */
class PosesBeyondTheRuleTest {
    private static Measurement pose(String id, double t, double... q) {
        return new Measurement(id, q, Vec3.ZERO, null, null, t, Double.NaN, Double.NaN, null, 0);
    }

    /** n poses at random over ±π on six joints, one a second apart. */
    private static List<Measurement> randomPoses(int n, Random r) {
        List<Measurement> out = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            double[] q = new double[6];
            for (int j = 0; j < 6; j++) q[j] = (2 * r.nextDouble() - 1) * Math.PI;
            out.add(pose("p" + i, i, q));
        }
        return out;
    }

    @Test
    void region_posesOfOneCornerOfTwoJoints_lieNextToOneAnother_randomPosesDoNot() {
        Random r = new Random(11);
        List<Measurement> poses = randomPoses(120, r);
        // a corner of joints 2 and 3 (a linkage near its dead point), the wrist anywhere
        List<String> corner = new ArrayList<>();
        for (int i = 0; i < 10; i++) {
            double[] q = poses.get(i).q().clone();
            q[1] = 1.2 + 0.25 * r.nextDouble();
            q[2] = -0.9 + 0.25 * r.nextDouble();
            poses.set(i, pose("p" + i, i, q));
            corner.add("p" + i);
        }
        Diagnoser.Region region = Diagnoser.region(corner, poses);
        assertNotNull(region);
        assertTrue(region.p() < Diagnoser.REGION_ALPHA, "a corner's poses: " + region.words());
        assertArrayEquals(new int[] {1, 2}, region.joints(), "the region lies in joints 2 and 3: " + region.words());

        // bad readings fall on poses at random: over many draws, the rule calls them a region about as often as its level
        int called = 0, draws = 200;
        for (int d = 0; d < draws; d++) {
            List<String> picked = new ArrayList<>();
            while (picked.size() < 8) {
                String id = "p" + (10 + r.nextInt(110));
                if (!picked.contains(id)) picked.add(id);
            }
            if (Diagnoser.region(picked, poses).p() < Diagnoser.REGION_ALPHA) called++;
        }
        assertTrue(called <= 0.03 * draws, called + " of " + draws + " random picks called a region");
    }

    /**
     * A parallel rod near its dead point: the forearm's error grows where the rod's angle (q3 − q2 on
     * an IRB 2000, robots.md) reaches either end of its range, so the poses a model misses there lie
     * at both ends of that angle but far apart in joints 2 and 3 themselves, and not next to one
     * another. The rule finds them by that angle, takes in a validation pose at the same ends, and
     * calls random picks a region about as rarely as its level.
     */
    @Test
    void region_posesAtBothEndsOfALinkageAngle_areARegion_randomPosesAreNot() {
        Random r = new Random(5);
        List<Measurement> poses = randomPoses(90, r);
        // joint 2 over ±1.5 rad, the rod's angle over ±1 rad: its ends lie along two edges of the (q2, q3) range, far apart
        for (int i = 0; i < poses.size(); i++) {
            double[] q = poses.get(i).q().clone();
            q[1] = 3 * r.nextDouble() - 1.5;
            q[2] = q[1] + 2 * r.nextDouble() - 1;
            poses.set(i, pose("p" + i, i, q));
        }
        double[] rod = poses.stream().mapToDouble(m -> m.q(2) - m.q(1)).sorted().toArray();
        // the two lowest and two highest rod angles, and one more among the five highest
        List<String> ends = new ArrayList<>();
        for (Measurement m : poses) {
            double x = m.q(2) - m.q(1);
            if (x <= rod[1] || x >= rod[rod.length - 2] || x == rod[rod.length - 5]) ends.add(m.poseId());
        }
        assertTrue(ends.size() == 5);
        Diagnoser.Region nearest = Diagnoser.region(ends, poses);
        assertNotNull(nearest);
        assertTrue(nearest.p() < Diagnoser.REGION_ALPHA, "the rod's ends: " + nearest.words());
        assertArrayEquals(new int[] {1, 2}, nearest.joints(), nearest.words());
        assertTrue(nearest.words().contains("q2 − q3"), nearest.words());
        double[] q = poses.get(0).q().clone();
        q[1] = 0.5;
        q[2] = 0.5 + rod[0] - 0.01;
        assertTrue(nearest.holds(pose("v", 0, q), poses), "beyond the lowest rod angle: in the region");
        q[2] = 0.5 + 0.5 * (rod[0] + rod[rod.length - 1]);
        assertFalse(nearest.holds(pose("v", 0, q), poses), "mid-range: not in it");

        // five poses among the 13 lowest rod angles (every third): beyond chance on their own, but the model
        // follows most poses there, so they are no region it misses
        List<Measurement> byRod = new ArrayList<>(poses);
        byRod.sort(java.util.Comparator.comparingDouble(m -> m.q(2) - m.q(1)));
        List<String> sparse = new ArrayList<>();
        for (int k = 0; k <= 12; k += 3) sparse.add(byRod.get(k).poseId());
        Diagnoser.Region loose = Diagnoser.region(sparse, poses);
        assertTrue(loose == null || !(loose.p() < Diagnoser.REGION_ALPHA), "every third pose at one end: " + (loose == null ? "-" : loose.words()));

        int called = 0, draws = 300;
        for (int d = 0; d < draws; d++) {
            List<String> picked = new ArrayList<>();
            while (picked.size() < 3 + d % 4) {
                String id = "p" + r.nextInt(90);
                if (!picked.contains(id)) picked.add(id);
            }
            Diagnoser.Region any = Diagnoser.region(picked, poses);
            if (any != null && any.p() < Diagnoser.REGION_ALPHA) called++;
        }
        assertTrue(called <= 0.03 * draws, called + " of " + draws + " random picks called a region");
    }

    @Test
    void stepGap_aPoseBetweenTheTrainingPosesAStepWasPlacedBetween_isNotJudged() {
        KinematicModel model = KinematicModel.build(RobotLibrary.shipped("irb2000"));
        List<Measurement> train = new ArrayList<>();
        for (int i = 0; i < 20; i++) train.add(pose("t" + i, 10.0 * i, new double[6]));
        // placed between the training poses at 100 s and 110 s
        List<Effect> steps = List.of(Effect.targetStep(model, 105));
        assertTrue(Diagnoser.inStepGap(steps, pose("v1", 103, new double[6]), train), "103 s: either side of a step in 100..110 s");
        assertFalse(Diagnoser.inStepGap(steps, pose("v2", 96, new double[6]), train), "96 s: before the training pose at 100 s");
        assertFalse(Diagnoser.inStepGap(steps, pose("v3", 112, new double[6]), train), "112 s: after the one at 110 s");
        // a step of joint 2's reading placed between training angles 0.30 and 0.40 rad
        List<Measurement> swept = new ArrayList<>();
        for (int i = 0; i < 10; i++) swept.add(pose("s" + i, i, 0, 0.1 * i, 0, 0, 0, 0));
        List<Effect> angle = List.of(Effect.angleStep(1, 0.35));
        assertTrue(Diagnoser.inStepGap(angle, pose("w1", 0, 0, 0.33, 0, 0, 0, 0), swept));
        assertFalse(Diagnoser.inStepGap(angle, pose("w2", 0, 0, 0.45, 0, 0, 0, 0), swept));
    }

    /**
     * A drive train runs from its motor to its joint and can be turned only by the joints it passes:
     * the wrist's shafts run through axes 4 and 5 (Craig, Introduction to Robotics, ch. 8, actuation
     * schemes: wrist motors on the forearm drive through it); the IRB 2000's forearm is driven through a parallel rod from
     * the turret, so the controller's θ3 = q3 − q2 (robots.md) ties joints 2 and 3 both ways.
     */
    @Test
    void canCouple_onlyThroughTheJointsADriveTrainPasses() {
        KinematicModel irb = KinematicModel.build(RobotLibrary.shipped("irb2000"));
        KinematicModel puma = KinematicModel.build(RobotLibrary.shipped("puma560"));
        assertTrue(Effect.canCouple(irb, 4, 3), "joint 5 from joint 4: its shaft runs through axis 4");
        assertTrue(Effect.canCouple(irb, 5, 4));
        assertTrue(Effect.canCouple(irb, 2, 1), "the parallel rod: joint 3 from joint 2");
        assertTrue(Effect.canCouple(irb, 1, 2), "the parallel rod ties the pair both ways");
        assertFalse(Effect.canCouple(irb, 2, 5), "joint 6 has no path to joint 3's drive");
        assertFalse(Effect.canCouple(irb, 3, 4), "nor joint 5 to joint 4's");
        assertFalse(Effect.canCouple(irb, 5, 1), "the wrist's motors ride on the upper arm: no shaft of joint 6 passes axis 2");
        assertFalse(Effect.canCouple(irb, 3, 2), "joint 4's motor rides beyond axis 3");
        assertFalse(Effect.canCouple(puma, 4, 0), "nor does joint 5's pass axis 1");
        assertFalse(Effect.canCouple(puma, 1, 2), "a serial arm without a linkage: joint 3 does not turn joint 2");
        assertFalse(Effect.canCouple(puma, 3, 3));
    }
}
