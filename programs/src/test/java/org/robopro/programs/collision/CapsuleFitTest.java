package org.robopro.programs.collision;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.RobotLibrary;
import org.robopro.models.Vec3;

class CapsuleFitTest {
    /** Points on the surface of the capsule a-b with radius r (cylinder and both caps). */
    static float[] capsuleSurface(Vec3 a, Vec3 b, double r, int n, long seed) {
        Random rnd = new Random(seed);
        Vec3 u = b.minus(a).normalized();
        Vec3 e1 = Math.abs(u.x()) < 0.9 ? u.cross(new Vec3(1, 0, 0)).normalized() : u.cross(new Vec3(0, 1, 0)).normalized();
        Vec3 e2 = u.cross(e1);
        double len = b.minus(a).norm();
        float[] out = new float[3 * n];
        for (int i = 0; i < n; i++) {
            Vec3 p;
            if (i % 3 == 0) { // a cap: a random direction on the half sphere beyond the end
                Vec3 d = new Vec3(rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()).normalized();
                boolean atB = i % 2 == 0;
                double along = d.dot(u);
                if (atB == along < 0) d = d.minus(u.times(2 * along));
                p = (atB ? b : a).plus(d.times(r));
            } else {
                double t = rnd.nextDouble() * len, phi = rnd.nextDouble() * 2 * Math.PI;
                p = a.plus(u.times(t)).plus(e1.times(r * Math.cos(phi))).plus(e2.times(r * Math.sin(phi)));
            }
            out[3 * i] = (float) p.x();
            out[3 * i + 1] = (float) p.y();
            out[3 * i + 2] = (float) p.z();
        }
        return out;
    }

    static void assertEncloses(Convex.Capsule c, float[] xyz) {
        for (int i = 0; i < xyz.length; i += 3) {
            Vec3 p = new Vec3(xyz[i], xyz[i + 1], xyz[i + 2]);
            assertTrue(CapsuleFit.segmentDistance(p, c.a(), c.b()) <= c.radius() + 1e-9, "point " + p + " outside " + c);
        }
    }

    @Test
    void surfaceOfAKnownCapsule_sameCapsuleRecovered_evenFromAPoorSegment() {
        Vec3 a = new Vec3(0.2, -0.1, 0.3), b = new Vec3(0.5, 0.3, 0.9);
        float[] pts = capsuleSurface(a, b, 0.08, 6000, 1);
        // The caller's segment is off to the side: the fit must find the capsule's own axis.
        Convex.Capsule c = CapsuleFit.bound(pts, new Vec3(0, 0, 0), new Vec3(0, 0, 0.5));
        assertEncloses(c, pts);
        assertEquals(0.08, c.radius(), 0.002);
        // Ends within a few mm of the true ones (either way round).
        double d1 = c.a().minus(a).norm() + c.b().minus(b).norm(), d2 = c.a().minus(b).norm() + c.b().minus(a).norm();
        assertTrue(Math.min(d1, d2) < 0.01, c.toString());
    }

    @Test
    void enclosingCircle_squareCornersAndInnerPoints_halfTheDiagonal() {
        double[] x = {0, 1, 1, 0, 0.5, 0.2, 0.7}, y = {0, 0, 1, 1, 0.5, 0.9, 0.1};
        double[] c = CapsuleFit.enclosingCircle(x, y);
        assertEquals(0.5, c[0], 1e-12);
        assertEquals(0.5, c[1], 1e-12);
        assertEquals(Math.sqrt(0.5), c[2], 1e-12);
    }

    @Test
    void boxCorners_enclosed_noLargerThanAroundTheGivenSegment() {
        float[] pts = new float[8 * 3];
        int k = 0;
        for (int i = 0; i < 8; i++) {
            pts[k++] = (i & 1) == 0 ? -0.05f : 0.05f;
            pts[k++] = (i & 2) == 0 ? -0.1f : 0.1f;
            pts[k++] = (i & 4) == 0 ? 0f : 0.6f;
        }
        Vec3 a = new Vec3(0, 0, 0), b = new Vec3(0, 0, 0.6);
        Convex.Capsule c = CapsuleFit.bound(pts, a, b);
        assertEncloses(c, pts);
        assertTrue(CapsuleFit.volume(c) <= CapsuleFit.volume(CapsuleFit.aboutSegment(pts, a, b)) + 1e-12);
        assertEquals(Math.hypot(0.05, 0.1), c.radius(), 1e-6, "half the cross-section's diagonal");
    }

    @Test
    void linkCapsules_moveWithTheirLinks() {
        KinematicModel m = KinematicModel.build(RobotLibrary.shipped("irb2000"));
        Pose[] zero = m.linkFrames(new double[6]);
        List<Convex.Capsule> caps = new java.util.ArrayList<>();
        for (int k = 0; k + 1 < zero.length; k++) // offset from the joint segment, so the transform shows
            caps.add(new Convex.Capsule(zero[k].position().plus(new Vec3(0, 0.05, 0)), zero[k + 1].position(), 0.04 + 0.01 * k));
        ClearanceChecker.Options o = ClearanceChecker.Options.forRobot(m).withLinkCapsules(caps);
        ClearanceChecker c = new ClearanceChecker(m, Pose.IDENTITY, List.of(), o);
        double[] q = {0.4, -0.3, 0.5, 1.0, -0.7, 0.2};
        var shapes = c.robotShapes(q, Pose.IDENTITY);
        Pose[] f = m.linkFrames(q);
        for (int k = 0; k + 1 < zero.length; k++) {
            Convex.Capsule s = shapes.get("link:" + k);
            assertEquals(caps.get(k).radius(), s.radius(), 0);
            // Rigid with link k: the same distances to the link's frame origin as at zero.
            assertEquals(caps.get(k).a().minus(zero[k].position()).norm(), s.a().minus(f[k].position()).norm(), 1e-9);
            assertEquals(caps.get(k).b().minus(zero[k].position()).norm(), s.b().minus(f[k].position()).norm(), 1e-9);
            // The end at joint k+1's origin follows that origin.
            assertEquals(0, s.b().minus(f[k + 1].position()).norm(), 1e-9);
        }
    }
}
