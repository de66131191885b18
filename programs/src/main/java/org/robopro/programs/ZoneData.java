package org.robopro.programs;

import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import org.robopro.kinematics.Units;

/**
 * RAPID's {@code zonedata}, SI inside: whether the move ends in a stop point (finep), the TCP
 * path zone, the zones for reorientation and external axes (m), the tool reorientation zone
 * (rad), the linear (m) and rotating (rad) external axis zones. RAPID writes mm and degrees.
 */
public record ZoneData(boolean finep, double pzoneTcp, double pzoneOri, double pzoneEax, double zoneOri,
                       double zoneLeax, double zoneReax) implements RapidValue {

    public ZoneData {
        double s = pzoneTcp + pzoneOri + pzoneEax + zoneOri + zoneLeax + zoneReax;
        if (!Double.isFinite(s) || pzoneTcp < 0 || pzoneOri < 0 || pzoneEax < 0 || zoneOri < 0 || zoneLeax < 0 || zoneReax < 0)
            throw new IllegalArgumentException("zonedata must be finite and >= 0");
    }

    /** A stop point: RAPID's predefined {@code fine}. */
    public static final ZoneData FINE = new ZoneData(true, 0, 0, 0, 0, 0, 0);

    /**
     * A fly-by zone from the three sizes open_abb's "set zone" instruction sets (TCP path zone and
     * orientation path zone in m, tool reorientation zone in rad); the external-axis zones take the
     * orientation sizes, in the proportions of the predefined data.
     */
    public static ZoneData flyBy(double pzoneTcp, double pzoneOri, double zoneOri) {
        return new ZoneData(false, pzoneTcp, pzoneOri, pzoneOri, zoneOri, pzoneOri, zoneOri);
    }

    /** A zonedata from RAPID's units (mm, mm, mm, deg, mm, deg). */
    public static ZoneData ofRapid(boolean finep, double pzoneTcpMm, double pzoneOriMm, double pzoneEaxMm,
                                   double zoneOriDeg, double zoneLeaxMm, double zoneReaxDeg) {
        return new ZoneData(finep, Units.mmToM(pzoneTcpMm), Units.mmToM(pzoneOriMm), Units.mmToM(pzoneEaxMm),
                Units.degToRad(zoneOriDeg), Units.mmToM(zoneLeaxMm), Units.degToRad(zoneReaxDeg));
    }

    private static final Map<String, ZoneData> PREDEFINED = new LinkedHashMap<>();

    static {
        // RAPID Technical reference manual, "zonedata", predefined data (mm, mm, mm, deg, mm, deg).
        PREDEFINED.put("fine", ofRapid(true, 0, 0, 0, 0, 0, 0));
        PREDEFINED.put("z0", ofRapid(false, 0.3, 0.3, 0.3, 0.03, 0.3, 0.03));
        PREDEFINED.put("z1", ofRapid(false, 1, 1, 1, 0.1, 1, 0.1));
        PREDEFINED.put("z5", ofRapid(false, 5, 8, 8, 0.8, 8, 0.8));
        PREDEFINED.put("z10", ofRapid(false, 10, 15, 15, 1.5, 15, 1.5));
        PREDEFINED.put("z15", ofRapid(false, 15, 23, 23, 2.3, 23, 2.3));
        PREDEFINED.put("z20", ofRapid(false, 20, 30, 30, 3.0, 30, 3.0));
        PREDEFINED.put("z30", ofRapid(false, 30, 45, 45, 4.5, 45, 4.5));
        PREDEFINED.put("z40", ofRapid(false, 40, 60, 60, 6.0, 60, 6.0));
        PREDEFINED.put("z50", ofRapid(false, 50, 75, 75, 7.5, 75, 7.5));
        PREDEFINED.put("z60", ofRapid(false, 60, 90, 90, 9.0, 90, 9.0));
        PREDEFINED.put("z80", ofRapid(false, 80, 120, 120, 12, 120, 12));
        PREDEFINED.put("z100", ofRapid(false, 100, 150, 150, 15, 150, 15));
        PREDEFINED.put("z150", ofRapid(false, 150, 225, 225, 23, 225, 23));
        PREDEFINED.put("z200", ofRapid(false, 200, 300, 300, 30, 300, 30));
    }

    /** The predefined zonedata named {@code name} (case-insensitive: fine, z0 .. z200). */
    public static Optional<ZoneData> predefined(String name) {
        return Optional.ofNullable(PREDEFINED.get(name.toLowerCase(Locale.ROOT)));
    }

    public static Map<String, ZoneData> predefinedAll() { return Map.copyOf(PREDEFINED); }

    @Override public String rapidType() { return "zonedata"; }
}
