package org.robopro.app.workbench.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.kinematics.KinematicModel;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
import org.robopro.models.Vec3;
import org.robopro.programs.collision.Convex;

/** Collision capsules fitted to the shipped link meshes: every vertex inside its link's capsule. */
class LinkCapsulesTest {
    static double segmentDistance(Vec3 p, Vec3 a, Vec3 b) {
        Vec3 ab = b.minus(a);
        double l2 = ab.dot(ab);
        double t = l2 > 0 ? Math.max(0, Math.min(1, p.minus(a).dot(ab) / l2)) : 0;
        return p.minus(a.plus(ab.times(t))).norm();
    }

    @Test
    void shippedMeshes_everyVertexInsideItsLinkCapsule() throws Exception {
        for (String robot : List.of("irb2400", "puma560")) {
            RobotDescription d = RobotLibrary.shipped(robot);
            KinematicModel m = KinematicModel.build(d);
            List<Convex.Capsule> caps = ShippedMeshes.linkCapsules(d, m).orElseThrow();
            assertEquals(m.dof() + 1, caps.size());
            StringBuilder radii = new StringBuilder(robot + ":");
            for (ShippedMeshes.Part part : ShippedMeshes.BY_ROBOT.get(robot)) {
                Convex.Capsule c = caps.get(part.link());
                float[] t = ShippedMeshes.triangles(robot, part).orElseThrow();
                double farthest = 0;
                for (int i = 0; i < t.length; i += 3)
                    farthest = Math.max(farthest, segmentDistance(new Vec3(t[i], t[i + 1], t[i + 2]), c.a(), c.b()));
                assertTrue(farthest <= c.radius() + 1e-6, robot + " " + part.file() + ": vertex " + farthest + " m from the axis, radius " + c.radius());
            }
            for (Convex.Capsule c : caps) radii.append(String.format(java.util.Locale.ROOT, " %.0f/%.0f", c.radius() * 1e3, c.b().minus(c.a()).norm() * 1e3));
            System.out.println("link capsules radius/length mm " + radii);
            // Tighter than enclosing the whole arm: no link capsule as wide as the robot's reach.
            for (Convex.Capsule c : caps) assertTrue(c.radius() < 0.5 * m.characteristicLength(), radii.toString());
        }
    }

    @Test
    void robotWithoutMeshes_guessedRadius() {
        RobotDescription d = RobotLibrary.shipped("irb2000");
        KinematicModel m = KinematicModel.build(d);
        assertTrue(ShippedMeshes.linkCapsules(d, m).isEmpty());
        assertTrue(ShippedMeshes.collisionOptions(d, m).linkCapsules().isEmpty());
        assertTrue(ShippedMeshes.collisionOptions(d, m).linkShapes().contains("guessed"));
    }
}
