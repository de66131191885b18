package org.robopro.kinematics;

/** The one place where robopro converts between SI (inside) and mm/degrees (at the edges). */
public final class Units {
    private Units() { }
    public static final double MM = 1e-3;
    public static double mmToM(double mm) { return mm * 1e-3; }
    public static double mToMm(double m) { return m * 1e3; }
    public static double degToRad(double deg) { return Math.toRadians(deg); }
    public static double radToDeg(double rad) { return Math.toDegrees(rad); }
    public static double[] degToRad(double[] deg) {
        double[] r = new double[deg.length];
        for (int i = 0; i < r.length; i++) r[i] = Math.toRadians(deg[i]);
        return r;
    }
    public static double[] radToDeg(double[] rad) {
        double[] r = new double[rad.length];
        for (int i = 0; i < r.length; i++) r[i] = Math.toDegrees(rad[i]);
        return r;
    }
}
