package org.robopro.models;

/**
 * A placement in a file-level description (cell layouts, tools, work objects): a position (m) and
 * a unit quaternion (w, x, y, z; w the scalar, as in RAPID). Named by use, e.g. a cell's
 * {@code worldTbase}: the robot base frame seen from the world. Kinematics converts it with
 * {@code Pose.fromQuaternion(qw, qx, qy, qz, x, y, z)}.
 */
public record PoseDescription(Vec3 position, double qw, double qx, double qy, double qz) {
    public static final PoseDescription IDENTITY = new PoseDescription(Vec3.ZERO, 1, 0, 0, 0);

    public PoseDescription {
        if (position == null || !position.isFinite())
            throw new IllegalArgumentException("position must be finite: " + position);
        double n = Math.sqrt(qw * qw + qx * qx + qy * qy + qz * qz);
        if (!(Math.abs(n - 1) < 1e-9))
            throw new IllegalArgumentException("quaternion (" + qw + ", " + qx + ", " + qy + ", " + qz + ") is not unit");
    }

    /**
     * From fixed-axis roll, pitch, yaw (rad): R = Rz(yaw) Ry(pitch) Rx(roll), the URDF and
     * ABB "Euler ZYX" convention.
     */
    public static PoseDescription fromRpy(Vec3 position, double roll, double pitch, double yaw) {
        double cr = Math.cos(roll / 2), sr = Math.sin(roll / 2);
        double cp = Math.cos(pitch / 2), sp = Math.sin(pitch / 2);
        double cy = Math.cos(yaw / 2), sy = Math.sin(yaw / 2);
        double w = cy * cp * cr + sy * sp * sr;
        double x = cy * cp * sr - sy * sp * cr;
        double y = cy * sp * cr + sy * cp * sr;
        double z = sy * cp * cr - cy * sp * sr;
        double n = Math.sqrt(w * w + x * x + y * y + z * z);
        return new PoseDescription(position, w / n, x / n, y / n, z / n);
    }
}
