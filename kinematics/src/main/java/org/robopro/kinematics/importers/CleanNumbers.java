package org.robopro.kinematics.importers;

import java.math.BigDecimal;
import java.math.RoundingMode;
import org.robopro.models.FileNumbers;
import org.robopro.models.FrameDescription;
import org.robopro.models.JointDescription;
import org.robopro.models.JointType;
import org.robopro.models.Vec3;

/**
 * Removes floating-point noise from imported geometry before it is written: chaining a table's
 * transforms leaves axis components such as 6e-17 and 0.9999999999999998, and degrees turned
 * into radians by multiplying with pi/180 read back as 59.99999999999999. Points are rounded to
 * 1e-9 mm and axis components to 1e-12, far below any measurable size, through the file's exact
 * decimal conversions ({@link FileNumbers}); table values in degrees or millimetres are converted
 * exactly ({@link #fromFile}), so the robot file shows 60 and 0.
 */
final class CleanNumbers {
    private CleanNumbers() { }

    static double length(double m) {
        if (!Double.isFinite(m)) return m;
        return zero(FileNumbers.mmToM(BigDecimal.valueOf(m * 1e3).setScale(9, RoundingMode.HALF_EVEN)));
    }

    static double unit(double v) {
        return zero(BigDecimal.valueOf(v).setScale(12, RoundingMode.HALF_EVEN).doubleValue());
    }

    static Vec3 point(Vec3 m) { return new Vec3(length(m.x()), length(m.y()), length(m.z())); }

    static Vec3 axis(Vec3 a) { return new Vec3(unit(a.x()), unit(a.y()), unit(a.z())); }

    /** A joint with its point and axis cleaned; limits and speed come straight from the file's numbers and stay as given. */
    static JointDescription joint(String name, JointType type, Vec3 point, Vec3 axis, double min, double max, double speed) {
        return new JointDescription(name, type, point(point), axis(axis), min, max, speed);
    }

    static FrameDescription frame(Vec3 origin, Vec3 xAxis, Vec3 zAxis) {
        return new FrameDescription(point(origin), axis(xAxis), axis(zAxis));
    }

    /** A number of the table in its unit (deg, rad, mm, m) to SI, correctly rounded from the decimal text. */
    static double fromFile(String text, double factor) {
        BigDecimal d = new BigDecimal(text.trim());
        if (factor == Math.PI / 180) return FileNumbers.degToRad(d);
        if (factor == 1e-3) return FileNumbers.mmToM(d);
        return d.doubleValue() * factor;
    }

    private static double zero(double v) { return v == 0 ? 0.0 : v; }
}
