package org.robopro.world;

/**
 * A rigid transform x' = R x + p, written out in plain doubles (this module keeps its own
 * geometry so that nothing here is shared with the estimator's kinematics). R is row-major.
 * Immutable.
 */
public record Rigid(double[] r, double[] p) {
    public static final Rigid IDENTITY = new Rigid(new double[] {1, 0, 0, 0, 1, 0, 0, 0, 1}, new double[3]);

    public Rigid {
        r = r.clone();
        p = p.clone();
    }

    @Override public double[] r() { return r.clone(); }

    @Override public double[] p() { return p.clone(); }

    public static Rigid translation(double x, double y, double z) {
        return new Rigid(IDENTITY.r, new double[] {x, y, z});
    }

    /**
     * Rotation by {@code angle} about the unit axis {@code w} through the point {@code point}:
     * R = I + sin a [w] + (1 - cos a) [w]^2 (Rodrigues), p = (I - R) point. This is the matrix
     * exponential of a revolute joint's twist (Lynch &amp; Park, Modern Robotics, 2017, §3.2.3.3 and
     * §3.3.3.2).
     */
    public static Rigid rotation(double[] w, double angle, double[] point) {
        double c = Math.cos(angle), s = Math.sin(angle), v = 1 - c;
        double x = w[0], y = w[1], z = w[2];
        double[] r = {
            c + x * x * v, x * y * v - z * s, x * z * v + y * s,
            y * x * v + z * s, c + y * y * v, y * z * v - x * s,
            z * x * v - y * s, z * y * v + x * s, c + z * z * v};
        double[] p = new double[3];
        for (int i = 0; i < 3; i++)
            p[i] = point[i] - (r[3 * i] * point[0] + r[3 * i + 1] * point[1] + r[3 * i + 2] * point[2]);
        return new Rigid(r, p);
    }

    /** A frame from its origin and its x and z axes (unit, orthogonal), y = z × x. */
    public static Rigid frame(double[] origin, double[] xAxis, double[] zAxis) {
        double[] y = cross(zAxis, xAxis);
        return new Rigid(new double[] {
            xAxis[0], y[0], zAxis[0],
            xAxis[1], y[1], zAxis[1],
            xAxis[2], y[2], zAxis[2]}, origin);
    }

    /** this · o (apply o first). */
    public Rigid times(Rigid o) {
        double[] rr = new double[9], pp = new double[3];
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++)
                rr[3 * i + j] = r[3 * i] * o.r[j] + r[3 * i + 1] * o.r[3 + j] + r[3 * i + 2] * o.r[6 + j];
            pp[i] = r[3 * i] * o.p[0] + r[3 * i + 1] * o.p[1] + r[3 * i + 2] * o.p[2] + p[i];
        }
        return new Rigid(rr, pp);
    }

    public double[] apply(double[] x) {
        double[] out = rotate(x);
        for (int i = 0; i < 3; i++) out[i] += p[i];
        return out;
    }

    public double[] rotate(double[] x) {
        return new double[] {
            r[0] * x[0] + r[1] * x[1] + r[2] * x[2],
            r[3] * x[0] + r[4] * x[1] + r[5] * x[2],
            r[6] * x[0] + r[7] * x[1] + r[8] * x[2]};
    }

    public Rigid inverse() {
        double[] rt = {r[0], r[3], r[6], r[1], r[4], r[7], r[2], r[5], r[8]};
        double[] pp = new double[3];
        for (int i = 0; i < 3; i++) pp[i] = -(rt[3 * i] * p[0] + rt[3 * i + 1] * p[1] + rt[3 * i + 2] * p[2]);
        return new Rigid(rt, pp);
    }

    /** Column j of R: the image of base axis j. */
    public double[] axis(int j) { return new double[] {r[j], r[3 + j], r[6 + j]}; }

    /**
     * The rotation as a unit quaternion (w, x, y, z) with w &ge; 0 (Shepperd's method: the largest
     * of the four squared components first, for accuracy).
     */
    public double[] quaternion() {
        double t = r[0] + r[4] + r[8];
        double w, x, y, z;
        if (t > r[0] && t > r[4] && t > r[8]) {
            double s = Math.sqrt(1 + t) * 2;
            w = s / 4; x = (r[7] - r[5]) / s; y = (r[2] - r[6]) / s; z = (r[3] - r[1]) / s;
        } else if (r[0] >= r[4] && r[0] >= r[8]) {
            double s = Math.sqrt(1 + r[0] - r[4] - r[8]) * 2;
            w = (r[7] - r[5]) / s; x = s / 4; y = (r[1] + r[3]) / s; z = (r[2] + r[6]) / s;
        } else if (r[4] >= r[8]) {
            double s = Math.sqrt(1 + r[4] - r[0] - r[8]) * 2;
            w = (r[2] - r[6]) / s; x = (r[1] + r[3]) / s; y = s / 4; z = (r[5] + r[7]) / s;
        } else {
            double s = Math.sqrt(1 + r[8] - r[0] - r[4]) * 2;
            w = (r[3] - r[1]) / s; x = (r[2] + r[6]) / s; y = (r[5] + r[7]) / s; z = s / 4;
        }
        double n = Math.sqrt(w * w + x * x + y * y + z * z) * (w < 0 ? -1 : 1);
        return new double[] {w / n, x / n, y / n, z / n};
    }

    // 3-vector helpers, public for tests that place things on a world robot.

    public static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }

    public static double dot(double[] a, double[] b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

    public static double[] minus(double[] a, double[] b) { return new double[] {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

    public static double[] plus(double[] a, double[] b) { return new double[] {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }

    public static double[] scale(double[] a, double s) { return new double[] {a[0] * s, a[1] * s, a[2] * s}; }

    public static double norm(double[] a) { return Math.sqrt(dot(a, a)); }

    public static double[] unit(double[] a) { return scale(a, 1 / norm(a)); }
}
