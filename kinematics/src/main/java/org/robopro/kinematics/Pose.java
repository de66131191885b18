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
        Vec3 u = axis.normalized();
        double c = Math.cos(angle), s = Math.sin(angle), t = 1 - c;
        double ux = u.x(), uy = u.y(), uz = u.z();
        return new Pose(new double[] {
                t * ux * ux + c, t * ux * uy - s * uz, t * ux * uz + s * uy,
                t * ux * uy + s * uz, t * uy * uy + c, t * uy * uz - s * ux,
                t * ux * uz - s * uy, t * uy * uz + s * ux, t * uz * uz + c}, 0, 0, 0);
    }

    /** A pose from a unit quaternion (w, x, y, z; normalised here) and a translation. */
    public static Pose fromQuaternion(double qw, double qx, double qy, double qz, double x, double y, double z) {
        double n = Math.sqrt(qw * qw + qx * qx + qy * qy + qz * qz);
        if (!(n > 1e-9) || !Double.isFinite(n))
            throw new IllegalArgumentException("quaternion (" + qw + ", " + qx + ", " + qy + ", " + qz + ") has no direction");
        qw /= n; qx /= n; qy /= n; qz /= n;
        double[] m = {
                1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy - qz * qw), 2 * (qx * qz + qy * qw),
                2 * (qx * qy + qz * qw), 1 - 2 * (qx * qx + qz * qz), 2 * (qy * qz - qx * qw),
                2 * (qx * qz - qy * qw), 2 * (qy * qz + qx * qw), 1 - 2 * (qx * qx + qy * qy)};
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

    /** Unit quaternion (w, x, y, z) with w >= 0 (Shepperd's method). */
    public double[] quaternion() {
        double t = r[0] + r[4] + r[8];
        double w, qx, qy, qz;
        if (t > 0) {
            double s = Math.sqrt(t + 1) * 2;
            w = 0.25 * s; qx = (r[7] - r[5]) / s; qy = (r[2] - r[6]) / s; qz = (r[3] - r[1]) / s;
        } else if (r[0] > r[4] && r[0] > r[8]) {
            double s = Math.sqrt(1 + r[0] - r[4] - r[8]) * 2;
            w = (r[7] - r[5]) / s; qx = 0.25 * s; qy = (r[1] + r[3]) / s; qz = (r[2] + r[6]) / s;
        } else if (r[4] > r[8]) {
            double s = Math.sqrt(1 + r[4] - r[0] - r[8]) * 2;
            w = (r[2] - r[6]) / s; qx = (r[1] + r[3]) / s; qy = 0.25 * s; qz = (r[5] + r[7]) / s;
        } else {
            double s = Math.sqrt(1 + r[8] - r[0] - r[4]) * 2;
            w = (r[3] - r[1]) / s; qx = (r[2] + r[6]) / s; qy = (r[5] + r[7]) / s; qz = 0.25 * s;
        }
        double n = Math.sqrt(w * w + qx * qx + qy * qy + qz * qz);
        if (w < 0) n = -n;
        return new double[] {w / n, qx / n, qy / n, qz / n};
    }

    /** Rotation vector (axis * angle, rad) of this pose's rotation: the log map. */
    public Vec3 rotationVector() {
        double c = Math.max(-1, Math.min(1, (r[0] + r[4] + r[8] - 1) / 2));
        double angle = Math.acos(c);
        double vx = r[7] - r[5], vy = r[2] - r[6], vz = r[3] - r[1];
        double s = Math.sin(angle);
        if (angle < 1e-7) return new Vec3(vx / 2, vy / 2, vz / 2);
        if (Math.PI - angle < 1e-6) {
            double[] q = quaternion();
            Vec3 axis = new Vec3(q[1], q[2], q[3]).normalized();
            return axis.times(angle);
        }
        double k = angle / (2 * s);
        return new Vec3(vx * k, vy * k, vz * k);
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
