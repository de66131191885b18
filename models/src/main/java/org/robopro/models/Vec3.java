package org.robopro.models;

/** An immutable 3-vector. Units are those of the context (metres for positions inside robopro). */
public record Vec3(double x, double y, double z) {
    public static final Vec3 ZERO = new Vec3(0, 0, 0);
    public static final Vec3 X = new Vec3(1, 0, 0);
    public static final Vec3 Y = new Vec3(0, 1, 0);
    public static final Vec3 Z = new Vec3(0, 0, 1);

    public static Vec3 of(double[] a) {
        if (a.length != 3) throw new IllegalArgumentException("Vec3 needs 3 components, got " + a.length);
        return new Vec3(a[0], a[1], a[2]);
    }

    public Vec3 plus(Vec3 o) { return new Vec3(x + o.x, y + o.y, z + o.z); }
    public Vec3 minus(Vec3 o) { return new Vec3(x - o.x, y - o.y, z - o.z); }
    public Vec3 times(double s) { return new Vec3(x * s, y * s, z * s); }
    public double dot(Vec3 o) { return x * o.x + y * o.y + z * o.z; }
    public Vec3 cross(Vec3 o) { return new Vec3(y * o.z - z * o.y, z * o.x - x * o.z, x * o.y - y * o.x); }
    public double norm() { return Math.sqrt(x * x + y * y + z * z); }
    public boolean isFinite() { return Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(z); }

    /** This vector scaled to unit length; throws for a zero or non-finite vector. */
    public Vec3 normalized() {
        double n = norm();
        if (!(n > 1e-12) || !Double.isFinite(n)) throw new IllegalArgumentException("cannot normalise " + this);
        return times(1.0 / n);
    }

    public double[] toArray() { return new double[] {x, y, z}; }
}
