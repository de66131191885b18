package org.robopro.programs;

import java.util.Arrays;

/** RAPID's {@code jointtarget}: the six robot axes (rad or m inside; degrees in RAPID) and the external axes. */
public final class JointTarget implements RapidValue {
    private final double[] robax;
    private final ExtJoints extax;

    private JointTarget(double[] robax, ExtJoints extax) {
        this.robax = robax;
        this.extax = extax;
    }

    /** robax: joint values q (rad for revolute joints); up to six, missing ones written as 0. */
    public static JointTarget of(double[] robax, ExtJoints extax) {
        if (robax.length != 6) throw new IllegalArgumentException("jointtarget needs 6 robot axes, got " + robax.length);
        for (double v : robax) if (!Double.isFinite(v)) throw new IllegalArgumentException("non-finite robot axis " + Arrays.toString(robax));
        if (extax == null) throw new IllegalArgumentException("extax must not be null");
        return new JointTarget(robax.clone(), extax);
    }

    public static JointTarget of(double... robax) { return of(robax, ExtJoints.NONE); }

    public double[] robax() { return robax.clone(); }

    public double robax(int i) { return robax[i]; }

    public ExtJoints extax() { return extax; }

    @Override public String rapidType() { return "jointtarget"; }

    @Override public boolean equals(Object o) {
        return o instanceof JointTarget j && Arrays.equals(robax, j.robax) && extax.equals(j.extax);
    }

    @Override public int hashCode() { return Arrays.hashCode(robax) * 31 + extax.hashCode(); }

    @Override public String toString() { return "JointTarget[robax=" + Arrays.toString(robax) + " rad, " + extax + "]"; }
}
