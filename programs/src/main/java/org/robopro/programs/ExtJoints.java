package org.robopro.programs;

import java.util.Arrays;

/**
 * The six external axis values (eax_a .. eax_f) of a robtarget or jointtarget. Kept as written in
 * the controller's units (mm for linear, degrees for rotating axes: the program does not know
 * which an axis is); {@link #UNUSED} (9E9) marks an axis that is not there.
 */
public final class ExtJoints {
    public static final double UNUSED = org.robopro.programs.rapid.RapidNumbers.UNUSED_AXIS;
    public static final ExtJoints NONE = new ExtJoints(new double[] {UNUSED, UNUSED, UNUSED, UNUSED, UNUSED, UNUSED});

    private final double[] values;

    private ExtJoints(double[] values) { this.values = values; }

    public static ExtJoints of(double... values) {
        if (values.length != 6) throw new IllegalArgumentException("external axes need 6 values, got " + values.length);
        for (double v : values) if (!Double.isFinite(v)) throw new IllegalArgumentException("non-finite external axis " + Arrays.toString(values));
        return new ExtJoints(values.clone());
    }

    public double get(int i) { return values[i]; }

    public double[] values() { return values.clone(); }

    public boolean allUnused() {
        for (double v : values) if (v != UNUSED) return false;
        return true;
    }

    @Override public boolean equals(Object o) { return o instanceof ExtJoints e && Arrays.equals(values, e.values); }
    @Override public int hashCode() { return Arrays.hashCode(values); }
    @Override public String toString() { return "ExtJoints" + Arrays.toString(values); }
}
