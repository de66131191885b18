package org.robopro.programs.collision;

import org.robopro.models.Vec3;

/**
 * Distance between two convex shapes by the Gilbert-Johnson-Keerthi algorithm (Gilbert, Johnson,
 * Keerthi 1988; closest points on the simplex as in Ericson, Real-Time Collision Detection, 2005,
 * §5.1 and §9.5): the distance of the cores' Minkowski difference from the origin, minus the two
 * radii. Pure Java, no allocation beyond small vectors; thread-safe.
 */
public final class Gjk {
    private Gjk() { }

    /** Separation of the two surfaces, m: positive apart, 0 touching, negative overlapping (-(ra + rb) when the cores overlap: depth unknown). */
    public static double distance(Convex a, Convex b) {
        return coreDistance(a, b) - a.radius() - b.radius();
    }

    /** Distance between the two cores (0 when they intersect). */
    static double coreDistance(Convex a, Convex b) {
        Vec3[] s = new Vec3[4];
        Simplex sx = new Simplex();
        int n = 1;
        Vec3 v = a.centre().minus(b.centre());
        if (v.norm() < 1e-12) v = Vec3.X;
        s[0] = support(a, b, v.times(-1));
        v = s[0];
        double scale = Math.max(1e-9, v.norm());
        for (int iter = 0; iter < 64; iter++) {
            double vv = v.dot(v);
            if (vv < 1e-24 * scale * scale) return 0;
            Vec3 w = support(a, b, v.times(-1));
            // No point of the difference closer along -v than v itself: v is the closest point.
            if (vv - v.dot(w) <= 1e-12 * vv + 1e-18) return Math.sqrt(vv);
            boolean seen = false;
            for (int k = 0; k < n; k++) if (s[k].minus(w).norm() < 1e-15 * scale) seen = true;
            if (seen) return Math.sqrt(vv);
            s[n++] = w;
            n = sx.closest(s, n);
            if (n == 4) return 0; // the tetrahedron holds the origin
            v = sx.last;
        }
        return Math.sqrt(v.dot(v));
    }

    private static Vec3 support(Convex a, Convex b, Vec3 d) { return a.support(d).minus(b.support(d.times(-1))); }

    /** One distance query's simplex work: {@code last} is the closest point found by the latest reduction. */
    private static final class Simplex {
        Vec3 last;

        /**
         * Reduces simplex {@code s[0..n)} to the smallest sub-simplex holding its point closest to the
         * origin, stores that point in {@code last}; returns the new size (4: the origin is inside).
         */
        private int closest(Vec3[] s, int n) {
            switch (n) {
                case 2 -> { return segment(s, s[0], s[1]); }
                case 3 -> { return triangle(s, s[0], s[1], s[2]); }
                default -> { return tetrahedron(s); }
            }
        }

        private int segment(Vec3[] s, Vec3 a, Vec3 b) {
            Vec3 ab = b.minus(a);
            double t = -a.dot(ab) / Math.max(ab.dot(ab), 1e-300);
            if (t <= 0) { s[0] = a; last = a; return 1; }
            if (t >= 1) { s[0] = b; last = b; return 1; }
            s[0] = a; s[1] = b;
            last = a.plus(ab.times(t));
            return 2;
        }

        /** Ericson's ClosestPtPointTriangle with p = origin, keeping the vertices of the region found. */
        private int triangle(Vec3[] s, Vec3 a, Vec3 b, Vec3 c) {
            Vec3 ab = b.minus(a), ac = c.minus(a), ap = a.times(-1);
            double d1 = ab.dot(ap), d2 = ac.dot(ap);
            if (d1 <= 0 && d2 <= 0) { s[0] = a; last = a; return 1; }
            Vec3 bp = b.times(-1);
            double d3 = ab.dot(bp), d4 = ac.dot(bp);
            if (d3 >= 0 && d4 <= d3) { s[0] = b; last = b; return 1; }
            double vc = d1 * d4 - d3 * d2;
            if (vc <= 0 && d1 >= 0 && d3 <= 0) {
                double v = d1 / (d1 - d3);
                s[0] = a; s[1] = b; last = a.plus(ab.times(v));
                return 2;
            }
            Vec3 cp = c.times(-1);
            double d5 = ab.dot(cp), d6 = ac.dot(cp);
            if (d6 >= 0 && d5 <= d6) { s[0] = c; last = c; return 1; }
            double vb = d5 * d2 - d1 * d6;
            if (vb <= 0 && d2 >= 0 && d6 <= 0) {
                double w = d2 / (d2 - d6);
                s[0] = a; s[1] = c; last = a.plus(ac.times(w));
                return 2;
            }
            double va = d3 * d6 - d5 * d4;
            if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
                double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
                s[0] = b; s[1] = c; last = b.plus(c.minus(b).times(w));
                return 2;
            }
            double denom = 1 / (va + vb + vc);
            double v = vb * denom, w = vc * denom;
            s[0] = a; s[1] = b; s[2] = c;
            last = a.plus(ab.times(v)).plus(ac.times(w));
            return 3;
        }

        /** Ericson §5.1.6: the origin inside (4), else the closest of the faces it lies outside of. */
        private int tetrahedron(Vec3[] s) {
            Vec3 a = s[0], b = s[1], c = s[2], d = s[3];
            int[][] faces = {{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 3, 2, 0}};
            double best = Double.POSITIVE_INFINITY;
            Vec3[] bestS = null;
            int bestN = 4;
            Vec3 bestP = null;
            Vec3[] v = {a, b, c, d};
            for (int[] f : faces) {
                if (!outside(v[f[0]], v[f[1]], v[f[2]], v[f[3]])) continue;
                Vec3[] t = new Vec3[4];
                int m = triangle(t, v[f[0]], v[f[1]], v[f[2]]);
                double dd = last.dot(last);
                if (dd < best) { best = dd; bestS = t; bestN = m; bestP = last; }
            }
            if (bestS == null) return 4;
            System.arraycopy(bestS, 0, s, 0, bestN);
            last = bestP;
            return bestN;
        }
    }

    /** Whether the origin and {@code d} lie on opposite sides of plane abc (degenerate: treated as outside). */
    private static boolean outside(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
        Vec3 n = b.minus(a).cross(c.minus(a));
        double so = -a.dot(n), sd = d.minus(a).dot(n);
        if (Math.abs(sd) < 1e-300) return true;
        return so * sd < 0;
    }
}
