package org.robopro.kinematics;

import java.util.Arrays;
import org.robopro.models.FrameDescription;
import org.robopro.models.Vec3;

/**
 * An immutable rigid transform (rotation and translation, metres). Named by the frames it
 * relates: {@code baseTflange} is the flange frame seen from the base, and
 * {@code baseTflange.times(flangeTtool)} is the tool seen from the base.
 * Rotation stored row-major; quaternions are (w, x, y, z) with w the scalar, as in RAPID.
 */
public final class Pose {
    public static final Pose IDENTITY = new Pose(new double[] {1, 0, 0, 0, 1, 0, 0, 0, 1}, 0, 0, 0);

    private final double[] r; // row-major 3x3
    private final double x, y, z;

    private Pose(double[] r, double x, double y, double z) {
        this.r = r;
        this.x = x;
        this.y = y;
        this.z = z;
    }

    /**
     * A pose from a row-major rotation matrix and a translation. Rejects a matrix that is not a
     * rotation (orthonormality or determinant off by more than 1e-6), naming the matrix.
     */
    public static Pose of(double[] rowMajorRotation, double x, double y, double z) {
        if (rowMajorRotation.length != 9) throw new IllegalArgumentException("rotation needs 9 entries");
        double[] m = rowMajorRotation.clone();
        checkRotation(m);
        if (!(Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(z)))
            throw new IllegalArgumentException("non-finite translation " + x + ", " + y + ", " + z);
        return new Pose(m, x, y, z);
    }

    /** Trusted constructor for hot paths: no checks, the array is owned by the pose afterwards. */
    static Pose ofTrusted(double[] rowMajorRotation, double x, double y, double z) {
        return new Pose(rowMajorRotation, x, y, z);
    }

    public static Pose translation(double x, double y, double z) {
        return new Pose(IDENTITY.r.clone(), x, y, z);
    }

    public static Pose translation(Vec3 t) { return translation(t.x(), t.y(), t.z()); }

    public static Pose rotX(double a) {
        double c = Math.cos(a), s = Math.sin(a);
        return new Pose(new double[] {1, 0, 0, 0, c, -s, 0, s, c}, 0, 0, 0);
    }

    public static Pose rotY(double a) {
        double c = Math.cos(a), s = Math.sin(a);
        return new Pose(new double[] {c, 0, s, 0, 1, 0, -s, 0, c}, 0, 0, 0);
    }

    public static Pose rotZ(double a) {
        double c = Math.cos(a), s = Math.sin(a);
        return new Pose(new double[] {c, -s, 0, s, c, 0, 0, 0, 1}, 0, 0, 0);
    }

    /** Rotation of {@code angle} about the unit {@code axis} (Rodrigues). */
    public static Pose rotAxis(Vec3 axis, double angle) {
        Vec3 w = axis.normalized().times(angle);
        double[] m = new double[9];
        Se3.rotExp(w.x(), w.y(), w.z(), m);
        return new Pose(m, 0, 0, 0);
    }

    /** A pose from a unit quaternion (w, x, y, z; normalised here) and a translation. */
    public static Pose fromQuaternion(double qw, double qx, double qy, double qz, double x, double y, double z) {
        double[] m = new double[9];
        Se3.rotFromQuaternion(qw, qx, qy, qz, m);
        return new Pose(m, x, y, z);
    }

    /** The frame of a {@link FrameDescription} (origin, x and z axes) as a pose. */
    public static Pose fromFrame(FrameDescription f) {
        Vec3 zA = f.zAxis().normalized();
        Vec3 xA = f.xAxis().minus(zA.times(f.xAxis().dot(zA))).normalized();
        Vec3 yA = zA.cross(xA);
        return of(new double[] {xA.x(), yA.x(), zA.x(), xA.y(), yA.y(), zA.y(), xA.z(), yA.z(), zA.z()},
                f.origin().x(), f.origin().y(), f.origin().z());
    }

    public FrameDescription toFrame() {
        return new FrameDescription(position(), xAxis(), zAxis());
    }

    /** this * other: {@code aTb.times(bTc)} is {@code aTc}. */
    public Pose times(Pose o) {
        double[] a = r, b = o.r;
        double[] m = new double[9];
        for (int i = 0; i < 3; i++) {
            double a0 = a[3 * i], a1 = a[3 * i + 1], a2 = a[3 * i + 2];
            m[3 * i] = a0 * b[0] + a1 * b[3] + a2 * b[6];
            m[3 * i + 1] = a0 * b[1] + a1 * b[4] + a2 * b[7];
            m[3 * i + 2] = a0 * b[2] + a1 * b[5] + a2 * b[8];
        }
        double tx = a[0] * o.x + a[1] * o.y + a[2] * o.z + x;
        double ty = a[3] * o.x + a[4] * o.y + a[5] * o.z + y;
        double tz = a[6] * o.x + a[7] * o.y + a[8] * o.z + z;
        return new Pose(m, tx, ty, tz);
    }

    public Pose inverse() {
        double[] m = {r[0], r[3], r[6], r[1], r[4], r[7], r[2], r[5], r[8]};
        return new Pose(m, -(m[0] * x + m[1] * y + m[2] * z), -(m[3] * x + m[4] * y + m[5] * z),
                -(m[6] * x + m[7] * y + m[8] * z));
    }

    /** A point given in this pose's frame, seen from the reference frame. */
    public Vec3 apply(Vec3 p) {
        return new Vec3(r[0] * p.x() + r[1] * p.y() + r[2] * p.z() + x,
                r[3] * p.x() + r[4] * p.y() + r[5] * p.z() + y,
                r[6] * p.x() + r[7] * p.y() + r[8] * p.z() + z);
    }

    /** A direction given in this pose's frame, seen from the reference frame. */
    public Vec3 rotate(Vec3 d) {
        return new Vec3(r[0] * d.x() + r[1] * d.y() + r[2] * d.z(),
                r[3] * d.x() + r[4] * d.y() + r[5] * d.z(),
                r[6] * d.x() + r[7] * d.y() + r[8] * d.z());
    }

    public double x() { return x; }
    public double y() { return y; }
    public double z() { return z; }
    public Vec3 position() { return new Vec3(x, y, z); }
    public Vec3 xAxis() { return new Vec3(r[0], r[3], r[6]); }
    public Vec3 yAxis() { return new Vec3(r[1], r[4], r[7]); }
    public Vec3 zAxis() { return new Vec3(r[2], r[5], r[8]); }

    /** Rotation entry (row, col), 0-based. */
    public double rot(int row, int col) { return r[3 * row + col]; }

    /** Copy of the row-major rotation matrix. */
    public double[] rotationRowMajor() { return r.clone(); }

    /** Unit quaternion (w, x, y, z) with w >= 0 (Shepperd's method, {@link Se3#rotQuaternion}). */
    public double[] quaternion() {
        double[] q = new double[4];
        Se3.rotQuaternion(r, q, 0);
        return q;
    }

    /** Rotation vector (axis * angle, rad) of this pose's rotation: the log map ({@link Se3#rotLog}, exact near 180°). */
    public Vec3 rotationVector() {
        double[] w = new double[3];
        Se3.rotLog(r, w, 0);
        return new Vec3(w[0], w[1], w[2]);
    }

    /** Angle (rad) of the rotation taking this orientation to {@code o}'s. */
    public double angleTo(Pose o) {
        return this.inverse().times(o).rotationVector().norm();
    }

    /** Distance (m) between the origins. */
    public double distanceTo(Pose o) {
        double dx = x - o.x, dy = y - o.y, dz = z - o.z;
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    private static void checkRotation(double[] m) {
        for (double v : m)
            if (!Double.isFinite(v)) throw new IllegalArgumentException("non-finite rotation " + Arrays.toString(m));
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) {
                double d = m[i] * m[j] + m[3 + i] * m[3 + j] + m[6 + i] * m[6 + j];
                if (Math.abs(d - (i == j ? 1 : 0)) > 1e-6)
                    throw new IllegalArgumentException("not a rotation (columns not orthonormal): " + Arrays.toString(m));
            }
        double det = m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6])
                + m[2] * (m[3] * m[7] - m[4] * m[6]);
        if (Math.abs(det - 1) > 1e-6) throw new IllegalArgumentException("not a rotation (det " + det + "): " + Arrays.toString(m));
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Pose p && Arrays.equals(r, p.r) && x == p.x && y == p.y && z == p.z;
    }

    @Override
    public int hashCode() { return Arrays.hashCode(r) * 31 + Double.hashCode(x + 3 * y + 7 * z); }

    @Override
    public String toString() {
        double[] q = quaternion();
        return String.format(java.util.Locale.ROOT, "Pose[pos=(%.6f, %.6f, %.6f) m, q=(%.6f, %.6f, %.6f, %.6f)]",
                x, y, z, q[0], q[1], q[2], q[3]);
    }
}
