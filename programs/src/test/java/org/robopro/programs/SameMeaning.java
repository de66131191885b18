package org.robopro.programs;

import static org.junit.jupiter.api.Assertions.fail;

import java.lang.reflect.RecordComponent;
import java.util.List;
import java.util.Optional;
import java.util.OptionalDouble;
import org.robopro.models.Vec3;

/** Test helper: two program models mean the same up to the file precision (recursive over records). */
public final class SameMeaning {
    private SameMeaning() { }

    /** Absolute tolerance for SI numbers (m, rad, m/s); the file keeps 1e-6 mm and 1e-6 degree. */
    public static final double TOL = 1e-8;

    public static void assertSame(Object expected, Object actual) {
        String d = diff(expected, actual, "");
        if (d != null) fail("models differ at " + d);
    }

    static String diff(Object a, Object b, String path) {
        if (a == null || b == null) return a == b ? null : path + ": " + a + " vs " + b;
        if (a instanceof Double x && b instanceof Double y)
            return Math.abs(x - y) <= TOL * Math.max(1, Math.abs(x)) ? null : path + ": " + x + " vs " + y;
        if (a instanceof Quaternion p && b instanceof Quaternion q) {
            Quaternion u = p.normalized(), v = q.normalized();
            double e = Math.abs(u.q1() - v.q1()) + Math.abs(u.q2() - v.q2()) + Math.abs(u.q3() - v.q3()) + Math.abs(u.q4() - v.q4());
            return e < 1e-8 ? null : path + ": " + p + " vs " + q;
        }
        if (a instanceof Vec3 p && b instanceof Vec3 q) return p.minus(q).norm() < TOL ? null : path + ": " + p + " vs " + q;
        if (a instanceof JointTarget p && b instanceof JointTarget q) {
            for (int k = 0; k < 6; k++) if (Math.abs(p.robax(k) - q.robax(k)) > TOL) return path + ".robax" + k + ": " + p + " vs " + q;
            return diff(p.extax(), q.extax(), path + ".extax");
        }
        if (a instanceof ExtJoints p && b instanceof ExtJoints q) {
            for (int k = 0; k < 6; k++) if (Math.abs(p.get(k) - q.get(k)) > 1e-6 * Math.max(1, Math.abs(p.get(k)))) return path + ": " + p + " vs " + q;
            return null;
        }
        if (a instanceof Optional<?> p && b instanceof Optional<?> q) {
            if (p.isPresent() != q.isPresent()) return path + ": " + p + " vs " + q;
            return p.isPresent() ? diff(p.get(), q.get(), path) : null;
        }
        if (a instanceof OptionalDouble p && b instanceof OptionalDouble q) {
            if (p.isPresent() != q.isPresent()) return path + ": " + p + " vs " + q;
            return p.isPresent() ? diff(p.getAsDouble(), q.getAsDouble(), path) : null;
        }
        if (a instanceof List<?> p && b instanceof List<?> q) {
            if (p.size() != q.size()) return path + ": size " + p.size() + " vs " + q.size();
            for (int k = 0; k < p.size(); k++) {
                String d = diff(p.get(k), q.get(k), path + "[" + k + "]");
                if (d != null) return d;
            }
            return null;
        }
        if (a instanceof RapidModule p && b instanceof RapidModule q) {
            if (!p.name().equals(q.name()) || !p.options().equals(q.options())) return path + ": module " + p + " vs " + q;
            return diff(p.items(), q.items(), path + ".items");
        }
        if (a.getClass() != b.getClass()) return path + ": " + a.getClass().getSimpleName() + " vs " + b.getClass().getSimpleName();
        if (a.getClass().isRecord()) {
            for (RecordComponent rc : a.getClass().getRecordComponents()) {
                try {
                    rc.getAccessor().setAccessible(true);
                    String d = diff(rc.getAccessor().invoke(a), rc.getAccessor().invoke(b), path + "." + rc.getName());
                    if (d != null) return d;
                } catch (ReflectiveOperationException e) {
                    throw new IllegalStateException(e);
                }
            }
            return null;
        }
        return a.equals(b) ? null : path + ": " + a + " vs " + b;
    }
}
