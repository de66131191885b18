package org.robopro.app.workbench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.lang.reflect.Array;
import java.lang.reflect.RecordComponent;
import java.util.List;
import org.robopro.kinematics.Pose;

/**
 * Compares two projects field by field, walking every record component (so a field added to
 * the project later is compared too): poses to 1e-9 m / rad, numbers to 1e-9 relative, the
 * rest exactly. The message names the path of the first difference.
 */
final class ProjectRoundTrip {
    private ProjectRoundTrip() { }

    static void assertSame(Object expected, Object actual) { compare("project", expected, actual); }

    private static void compare(String path, Object a, Object b) {
        if (a == null || b == null) {
            if (a != b) fail(path + ": " + a + " vs " + b);
            return;
        }
        if (a instanceof Pose p && b instanceof Pose q) {
            assertEquals(0, p.distanceTo(q), 1e-9, path + " position");
            assertEquals(0, p.angleTo(q), 1e-9, path + " rotation");
            return;
        }
        if (a instanceof Double x && b instanceof Double y) {
            assertEquals(x, y, 1e-9 * Math.max(1, Math.abs(x)), path);
            return;
        }
        if (a.getClass().isArray()) {
            assertTrue(b.getClass().isArray(), path + " is an array");
            assertEquals(Array.getLength(a), Array.getLength(b), path + " length");
            for (int i = 0; i < Array.getLength(a); i++) compare(path + "[" + i + "]", Array.get(a, i), Array.get(b, i));
            return;
        }
        if (a instanceof List<?> x && b instanceof List<?> y) {
            assertEquals(x.size(), y.size(), path + " size");
            for (int i = 0; i < x.size(); i++) compare(path + "[" + i + "]", x.get(i), y.get(i));
            return;
        }
        // The robot description is read back from the same robot file: compared whole.
        if (a.getClass().isRecord() && !(a instanceof org.robopro.models.RobotDescription)) {
            assertEquals(a.getClass(), b.getClass(), path);
            for (RecordComponent c : a.getClass().getRecordComponents()) {
                try {
                    compare(path + "." + c.getName(), c.getAccessor().invoke(a), c.getAccessor().invoke(b));
                } catch (ReflectiveOperationException e) {
                    throw new AssertionError(path + "." + c.getName(), e);
                }
            }
            return;
        }
        assertEquals(a, b, path);
    }
}
