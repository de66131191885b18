package org.robopro.programs.collision;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.robopro.kinematics.Pose;
import org.robopro.models.Vec3;

/** Distances with answers known from geometry (not from GJK). */
class GjkTest {
    @Test
    void spheres_centreDistanceMinusRadii() {
        assertEquals(0.7, Gjk.distance(new Convex.Sphere(Vec3.ZERO, 0.1), new Convex.Sphere(new Vec3(0.6, 0.8, 0), 0.2)), 1e-12);
        assertTrue(Gjk.distance(new Convex.Sphere(Vec3.ZERO, 0.5), new Convex.Sphere(new Vec3(0.6, 0, 0), 0.2)) < 0);
    }

    @Test
    void sphereAndBox_faceEdgeCornerRegions() {
        Convex.Box box = new Convex.Box(Pose.IDENTITY, new Vec3(0.5, 0.3, 0.2));
        assertEquals(1.0 - 0.5 - 0.1, Gjk.distance(box, new Convex.Sphere(new Vec3(1, 0.1, 0), 0.1)), 1e-9, "face");
        assertEquals(Math.hypot(0.5, 0.7) - 0.1, Gjk.distance(box, new Convex.Sphere(new Vec3(1, 1, 0.1), 0.1)), 1e-9, "edge");
        assertEquals(Math.sqrt(0.25 + 0.49 + 0.64) - 0.1, Gjk.distance(box, new Convex.Sphere(new Vec3(1, 1, 1), 0.1)), 1e-9, "corner");
        // The box turned 90 deg about z: its 0.5 half size now lies along y.
        Convex.Box turned = new Convex.Box(Pose.rotZ(Math.PI / 2), new Vec3(0.5, 0.3, 0.2));
        assertEquals(1.0 - 0.5, Gjk.distance(turned, new Convex.Sphere(new Vec3(0, 1, 0), 0)), 1e-9);
        assertTrue(Gjk.distance(box, new Convex.Sphere(new Vec3(0.2, 0.1, 0), 0.01)) < 0, "inside");
    }

    @Test
    void capsules_parallelCrossingAndSkew() {
        Convex.Capsule a = new Convex.Capsule(new Vec3(0, 0, 0), new Vec3(1, 0, 0), 0.05);
        assertEquals(0.3 - 0.1, Gjk.distance(a, new Convex.Capsule(new Vec3(0.2, 0.3, 0), new Vec3(0.8, 0.3, 0), 0.05)), 1e-9, "parallel");
        // Skew segments: x axis and a line along y at z = 0.4 over x = 0.5: closest points (0.5,0,0)-(0.5,0,0.4).
        assertEquals(0.4 - 0.1, Gjk.distance(a, new Convex.Capsule(new Vec3(0.5, -1, 0.4), new Vec3(0.5, 1, 0.4), 0.05)), 1e-9, "skew");
        // Beyond the end: from (1,0,0) to (1.3,0.4,0) is 0.5.
        assertEquals(0.5 - 0.1, Gjk.distance(a, new Convex.Capsule(new Vec3(1.3, 0.4, 0), new Vec3(1.3, 0.4, 1), 0.05)), 1e-9, "end");
        assertTrue(Gjk.distance(a, new Convex.Capsule(new Vec3(0.5, -1, 0), new Vec3(0.5, 1, 0), 0.05)) < 0, "crossing");
    }

    @Test
    void boxes_separatedAlongAxisAndRotated() {
        Convex.Box a = new Convex.Box(Pose.IDENTITY, new Vec3(0.5, 0.5, 0.5));
        assertEquals(0.25, Gjk.distance(a, new Convex.Box(Pose.translation(1.25, 0.3, -0.2), new Vec3(0.5, 0.5, 0.5))), 1e-9);
        // A unit cube turned 45 deg about z next to it: its edge points at a, at sqrt(2)/2 from its centre.
        Pose turned = Pose.translation(2, 0, 0).times(Pose.rotZ(Math.PI / 4));
        assertEquals(2 - 0.5 - Math.sqrt(0.5), Gjk.distance(a, new Convex.Box(turned, new Vec3(0.5, 0.5, 0.5))), 1e-9);
    }

    @Test
    void hullOfCylinder_matchesRandomPointDistancesFromGeometry() {
        // A cylinder (radius 0.2, height 0.6, axis z) as the hull of 64 rim points per end; far points see its rim.
        List<Vec3> rim = new ArrayList<>();
        for (int k = 0; k < 64; k++) {
            double t = 2 * Math.PI * k / 64;
            rim.add(new Vec3(0.2 * Math.cos(t), 0.2 * Math.sin(t), -0.3));
            rim.add(new Vec3(0.2 * Math.cos(t), 0.2 * Math.sin(t), 0.3));
        }
        Convex.Hull cyl = new Convex.Hull(rim);
        Random r = new Random(3);
        for (int n = 0; n < 200; n++) {
            Vec3 p = new Vec3(r.nextGaussian(), r.nextGaussian(), r.nextGaussian());
            double radial = Math.hypot(p.x(), p.y()), dz = Math.max(0, Math.abs(p.z()) - 0.3), dr = Math.max(0, radial - 0.2);
            double truth = Math.hypot(dr, dz);
            if (truth < 1e-3) continue;
            // The 64-gon lies inside the circle by at most 0.2 (1 - cos(pi/64)) = 0.24 mm.
            assertEquals(truth, Gjk.distance(cyl, new Convex.Sphere(p, 0)), 2.5e-4, p.toString());
        }
    }
}
