package org.robopro.comms;

/**
 * RAPID zonedata as open_abb's instruction 9 sets it: a fine point, or the TCP path zone (m),
 * the orientation path zone (m) and the tool reorientation zone (rad).
 */
public record ZoneData(boolean fine, double pathZoneM, double oriZoneM, double reorientZoneRad) {
    public ZoneData {
        if (!(pathZoneM >= 0 && oriZoneM >= 0 && reorientZoneRad >= 0)
                || !Double.isFinite(pathZoneM + oriZoneM + reorientZoneRad))
            throw new IllegalArgumentException("zone sizes must be finite and >= 0: " + pathZoneM + ", "
                    + oriZoneM + ", " + reorientZoneRad);
    }

    public static final ZoneData FINE = new ZoneData(true, 0, 0, 0);
}
