package org.robopro.calibration;

import org.robopro.calibration.measurement.Measurement;

/**
 * The conditions a pose was reached and measured under, as the measurement file's optional
 * columns record them; non-geometric effects depend on them. NaN / null when unknown.
 *
 * @param directions sign of each joint's last motion (-1, 0, 1), or null
 * @param timeS      seconds since the start of the campaign
 * @param tempC      temperature near the robot, °C
 * @param payloadKg  mass carried at the flange, kg
 */
public record PoseConditions(int[] directions, double timeS, double tempC, double payloadKg) {
    public static final PoseConditions NONE = new PoseConditions(null, Double.NaN, Double.NaN, Double.NaN);

    public PoseConditions {
        directions = directions == null ? null : directions.clone();
    }

    @Override public int[] directions() { return directions == null ? null : directions.clone(); }

    /** Direction of joint i (0-based), 0 when unknown. */
    public int direction(int i) { return directions == null ? 0 : directions[i]; }

    public static PoseConditions of(Measurement m) {
        return new PoseConditions(m.directions(), m.timeS(), m.tempC(), m.payloadKg());
    }
}
