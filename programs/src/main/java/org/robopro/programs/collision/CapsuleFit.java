package org.robopro.programs.collision;

import java.util.Random;
import org.robopro.models.Vec3;

/**
 * A capsule around a point cloud (a link's mesh vertices): every point inside it, volume as
 * small as the candidates allow. Candidates: (1) the segment the caller gives (a link's joint
 * origins) with the radius of the farthest point; (2) for each of two axis directions, the
 * points' principal axis and the given segment's direction, the axis placed at the centre of the
 * smallest circle enclosing the points projected across it, that circle's radius, and the
 * shortest segment along the axis that keeps every point within the radius, the direction then
 * tilted in halving steps while that shrinks the volume. The smallest volume wins. A bounding capsule never misses a contact with the mesh it encloses; it
 * overstates the clearance's loss near bulky parts (a motor housing widens the whole link).
 */
public final class CapsuleFit {
    private CapsuleFit() { }

    /**
     * @param xyz points as x, y, z triples (m)
     * @param a   one end of the link's own segment
     * @param b   the other end
     */
    public static Convex.Capsule bound(float[] xyz, Vec3 a, Vec3 b) {
        if (xyz.length < 3 || xyz.length % 3 != 0) throw new IllegalArgumentException("need x, y, z triples");
        Convex.Capsule best = aboutSegment(xyz, a, b);
        Vec3 along = b.minus(a);
        Vec3[] dirs = along.norm() > 1e-9 ? new Vec3[] {principalAxis(xyz), along.normalized()} : new Vec3[] {principalAxis(xyz)};
        for (Vec3 u : dirs) {
            Convex.Capsule c = refined(xyz, u);
            if (volume(c) < volume(best)) best = c;
        }
        return best;
    }

    /** {@link #aboutAxis} from direction u, the direction then tilted while that shrinks the volume (halving steps from 3 deg). */
    static Convex.Capsule refined(float[] xyz, Vec3 u) {
        Convex.Capsule best = aboutAxis(xyz, u);
        double bestV = volume(best);
        for (double step = Math.toRadians(3); step > 1e-5; ) {
            Vec3 e1 = Math.abs(u.x()) < 0.9 ? u.cross(new Vec3(1, 0, 0)).normalized() : u.cross(new Vec3(0, 1, 0)).normalized();
            Vec3 e2 = u.cross(e1);
            boolean moved = false;
            for (Vec3 tilt : new Vec3[] {e1, e1.times(-1), e2, e2.times(-1)}) {
                Vec3 v = u.times(Math.cos(step)).plus(tilt.times(Math.sin(step))).normalized();
                Convex.Capsule c = aboutAxis(xyz, v);
                double vol = volume(c);
                if (vol < bestV) {
                    best = c;
                    bestV = vol;
                    u = v;
                    moved = true;
                    break;
                }
            }
            if (!moved) step /= 2;
        }
        return best;
    }

    /** Capsule volume, m³. */
    public static double volume(Convex.Capsule c) {
        double r = c.radius();
        return Math.PI * r * r * c.b().minus(c.a()).norm() + 4.0 / 3 * Math.PI * r * r * r;
    }

    /** The segment a-b with the radius of the farthest point. */
    static Convex.Capsule aboutSegment(float[] xyz, Vec3 a, Vec3 b) {
        double r = 0;
        for (int i = 0; i < xyz.length; i += 3) r = Math.max(r, segmentDistance(new Vec3(xyz[i], xyz[i + 1], xyz[i + 2]), a, b));
        return new Convex.Capsule(a, b, r);
    }

    static double segmentDistance(Vec3 p, Vec3 a, Vec3 b) {
        Vec3 ab = b.minus(a);
        double l2 = ab.dot(ab);
        double t = l2 > 0 ? Math.max(0, Math.min(1, p.minus(a).dot(ab) / l2)) : 0;
        return p.minus(a.plus(ab.times(t))).norm();
    }

    /** Along unit direction u: the axis through the smallest enclosing circle of the points' projection, the shortest segment. */
    static Convex.Capsule aboutAxis(float[] xyz, Vec3 u) {
        u = u.normalized();
        Vec3 e1 = Math.abs(u.x()) < 0.9 ? u.cross(new Vec3(1, 0, 0)).normalized() : u.cross(new Vec3(0, 1, 0)).normalized();
        Vec3 e2 = u.cross(e1);
        int n = xyz.length / 3;
        double[] px = new double[n], py = new double[n], t = new double[n];
        for (int i = 0; i < n; i++) {
            Vec3 p = new Vec3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
            px[i] = p.dot(e1);
            py[i] = p.dot(e2);
            t[i] = p.dot(u);
        }
        double[] c = enclosingCircle(px, py);
        double r = c[2] * (1 + 1e-9) + 1e-12;
        double t0 = Double.POSITIVE_INFINITY, t1 = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < n; i++) {
            double d2 = (px[i] - c[0]) * (px[i] - c[0]) + (py[i] - c[1]) * (py[i] - c[1]);
            double h = Math.sqrt(Math.max(0, r * r - d2));
            t0 = Math.min(t0, t[i] + h);
            t1 = Math.max(t1, t[i] - h);
        }
        if (t0 > t1) { // every point lies within r of one point of the axis: a sphere
            double m = (t0 + t1) / 2;
            t0 = m;
            t1 = m;
        }
        Vec3 base = e1.times(c[0]).plus(e2.times(c[1]));
        return new Convex.Capsule(base.plus(u.times(t0)), base.plus(u.times(t1)), r);
    }

    /** The direction of largest spread (covariance's leading eigenvector by power iteration). */
    static Vec3 principalAxis(float[] xyz) {
        int n = xyz.length / 3;
        double mx = 0, my = 0, mz = 0;
        for (int i = 0; i < n; i++) { mx += xyz[3 * i]; my += xyz[3 * i + 1]; mz += xyz[3 * i + 2]; }
        mx /= n; my /= n; mz /= n;
        double[][] c = new double[3][3];
        for (int i = 0; i < n; i++) {
            double[] d = {xyz[3 * i] - mx, xyz[3 * i + 1] - my, xyz[3 * i + 2] - mz};
            for (int r = 0; r < 3; r++) for (int k = 0; k < 3; k++) c[r][k] += d[r] * d[k];
        }
        double[] v = {1, 0.7, 0.3};
        for (int it = 0; it < 200; it++) {
            double[] w = new double[3];
            for (int r = 0; r < 3; r++) for (int k = 0; k < 3; k++) w[r] += c[r][k] * v[k];
            double l = Math.sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
            if (!(l > 0)) return new Vec3(0, 0, 1);
            v = new double[] {w[0] / l, w[1] / l, w[2] / l};
        }
        return new Vec3(v[0], v[1], v[2]);
    }

    /**
     * The smallest circle enclosing the points (Welzl's algorithm, iterative, points taken in a
     * fixed pseudo-random order): {cx, cy, r}.
     */
    static double[] enclosingCircle(double[] x, double[] y) {
        int n = x.length;
        int[] idx = new int[n];
        for (int i = 0; i < n; i++) idx[i] = i;
        Random rnd = new Random(1);
        for (int i = n - 1; i > 0; i--) {
            int j = rnd.nextInt(i + 1);
            int s = idx[i]; idx[i] = idx[j]; idx[j] = s;
        }
        double[] c = {x[idx[0]], y[idx[0]], 0};
        for (int i = 1; i < n; i++) {
            int p = idx[i];
            if (inside(c, x[p], y[p])) continue;
            c = new double[] {x[p], y[p], 0};
            for (int j = 0; j < i; j++) {
                int q = idx[j];
                if (inside(c, x[q], y[q])) continue;
                c = new double[] {(x[p] + x[q]) / 2, (y[p] + y[q]) / 2, Math.hypot(x[p] - x[q], y[p] - y[q]) / 2};
                for (int k = 0; k < j; k++) {
                    int s = idx[k];
                    if (inside(c, x[s], y[s])) continue;
                    c = circumcircle(x[p], y[p], x[q], y[q], x[s], y[s]);
                }
            }
        }
        return c;
    }

    private static boolean inside(double[] c, double x, double y) {
        return Math.hypot(x - c[0], y - c[1]) <= c[2] * (1 + 1e-12) + 1e-12;
    }

    private static double[] circumcircle(double ax, double ay, double bx, double by, double cx, double cy) {
        double d = 2 * (ax * (by - cy) + bx * (cy - ay) + cx * (ay - by));
        if (Math.abs(d) < 1e-18) { // collinear: the circle on the farthest pair
            double[][] pairs = {{ax, ay, bx, by}, {ax, ay, cx, cy}, {bx, by, cx, cy}};
            double[] best = null;
            for (double[] q : pairs) {
                double r = Math.hypot(q[0] - q[2], q[1] - q[3]) / 2;
                if (best == null || r > best[2]) best = new double[] {(q[0] + q[2]) / 2, (q[1] + q[3]) / 2, r};
            }
            return best;
        }
        double a2 = ax * ax + ay * ay, b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
        double ux = (a2 * (by - cy) + b2 * (cy - ay) + c2 * (ay - by)) / d;
        double uy = (a2 * (cx - bx) + b2 * (ax - cx) + c2 * (bx - ax)) / d;
        return new double[] {ux, uy, Math.hypot(ax - ux, ay - uy)};
    }
}
