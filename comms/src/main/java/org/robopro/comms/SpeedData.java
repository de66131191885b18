package org.robopro.comms;

/**
 * RAPID speeddata in SI units: TCP speed (m/s), reorientation speed (rad/s), external linear
 * axes (m/s) and external rotating axes (rad/s). The protocol carries mm/s and deg/s.
 */
public record SpeedData(double tcpMPerS, double oriRadPerS, double leaxMPerS, double reaxRadPerS) {
    public SpeedData {
        if (!(tcpMPerS > 0 && oriRadPerS > 0 && leaxMPerS >= 0 && reaxRadPerS >= 0)
                || !Double.isFinite(tcpMPerS + oriRadPerS + leaxMPerS + reaxRadPerS))
            throw new IllegalArgumentException("speed must be finite and positive: tcp " + tcpMPerS + " m/s, ori "
                    + oriRadPerS + " rad/s, leax " + leaxMPerS + ", reax " + reaxRadPerS);
    }

    /** SERVER.mod's default after Initialize: v100 (100 mm/s, 50 deg/s). */
    public static final SpeedData DEFAULT = new SpeedData(0.1, Math.toRadians(50), 0, 0);
}
