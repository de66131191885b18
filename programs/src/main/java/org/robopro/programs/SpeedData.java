package org.robopro.programs;

import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import org.robopro.kinematics.Units;

/**
 * RAPID's {@code speeddata}, SI inside: TCP speed (m/s), reorientation speed (rad/s), linear
 * and rotating external axis speeds (m/s, rad/s). RAPID writes mm/s and deg/s.
 */
public record SpeedData(double vTcp, double vOri, double vLeax, double vReax) implements RapidValue {

    public SpeedData {
        if (!(vTcp >= 0 && vOri >= 0 && vLeax >= 0 && vReax >= 0) || !Double.isFinite(vTcp + vOri + vLeax + vReax))
            throw new IllegalArgumentException("speeddata must be finite and >= 0: " + vTcp + ", " + vOri + ", " + vLeax + ", " + vReax);
    }

    /** A speeddata from RAPID's units: mm/s, deg/s, mm/s, deg/s. */
    public static SpeedData ofRapid(double vTcpMmPerS, double vOriDegPerS, double vLeaxMmPerS, double vReaxDegPerS) {
        return new SpeedData(Units.mmToM(vTcpMmPerS), Units.degToRad(vOriDegPerS), Units.mmToM(vLeaxMmPerS),
                Units.degToRad(vReaxDegPerS));
    }

    private static final Map<String, SpeedData> PREDEFINED = new LinkedHashMap<>();

    static {
        // RAPID Technical reference manual, "speeddata", predefined data: vN = [N, 500, 5000, 1000].
        int[] tcp = {5, 10, 20, 30, 40, 50, 60, 80, 100, 150, 200, 300, 400, 500, 600, 800, 1000, 1500, 2000,
                2500, 3000, 4000, 5000, 6000, 7000};
        for (int v : tcp) PREDEFINED.put("v" + v, ofRapid(v, 500, 5000, 1000));
        // vmax is the robot type's maximum TCP speed; 5000 mm/s is the manual's nominal figure.
        PREDEFINED.put("vmax", ofRapid(5000, 500, 5000, 1000));
    }

    /** The predefined speeddata named {@code name} (case-insensitive: v5 .. v7000, vmax). */
    public static Optional<SpeedData> predefined(String name) {
        return Optional.ofNullable(PREDEFINED.get(name.toLowerCase(Locale.ROOT)));
    }

    public static Map<String, SpeedData> predefinedAll() { return Map.copyOf(PREDEFINED); }

    @Override public String rapidType() { return "speeddata"; }
}
