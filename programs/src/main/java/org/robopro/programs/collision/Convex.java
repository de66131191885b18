package org.robopro.programs.collision;

import java.util.List;
import org.robopro.kinematics.Pose;
import org.robopro.models.Vec3;

/**
 * A convex shape as GJK sees it: a convex core given by its support function, grown by a
 * radius (a sphere is a point grown by r, a capsule a segment grown by r). Coordinates in one
 * frame shared by the shapes compared (robopro uses the robot base frame), metres.
 */
public sealed interface Convex permits Convex.Sphere, Convex.Capsule, Convex.Box, Convex.Hull {
    /** The core's point farthest along {@code d}. */
    Vec3 support(Vec3 d);

    /** How far the surface lies outside the core, m. */
    double radius();

    /** A point inside the core (GJK's start). */
    Vec3 centre();

    record Sphere(Vec3 centre, double radius) implements Convex {
        @Override public Vec3 support(Vec3 d) { return centre; }
    }

    /** The segment a-b grown by {@code radius}. */
    record Capsule(Vec3 a, Vec3 b, double radius) implements Convex {
        @Override public Vec3 support(Vec3 d) { return d.dot(b.minus(a)) > 0 ? b : a; }

        @Override public Vec3 centre() { return a.plus(b).times(0.5); }
    }

    /** A box with half sizes {@code half} along the axes of {@code pose}, centred on its origin. */
    record Box(Pose pose, Vec3 half) implements Convex {
        @Override public Vec3 support(Vec3 d) {
            Vec3 local = pose.inverse().rotate(d);
            return pose.apply(new Vec3(Math.copySign(half.x(), local.x()), Math.copySign(half.y(), local.y()),
                    Math.copySign(half.z(), local.z())));
        }

        @Override public double radius() { return 0; }

        @Override public Vec3 centre() { return pose.position(); }
    }

    /** The convex hull of points (a cylinder's rims, a mesh's vertices). */
    record Hull(List<Vec3> points) implements Convex {
        public Hull {
            points = List.copyOf(points);
            if (points.isEmpty()) throw new IllegalArgumentException("a hull needs points");
        }

        @Override public Vec3 support(Vec3 d) {
            Vec3 best = points.get(0);
            double bd = best.dot(d);
            for (Vec3 p : points) {
                double v = p.dot(d);
                if (v > bd) { bd = v; best = p; }
            }
            return best;
        }

        @Override public double radius() { return 0; }

        @Override public Vec3 centre() {
            Vec3 c = Vec3.ZERO;
            for (Vec3 p : points) c = c.plus(p);
            return c.times(1.0 / points.size());
        }
    }
}
