package org.robopro.comms;

import org.robopro.calibration.PoseConditions;
import org.robopro.models.Vec3;

/**
 * One laser-tracker reading with the conditions it was taken under, as the controller knows
 * them: the sign of each joint's last motion (the real approach direction), the controller clock
 * (s since it started), the temperature near the robot (°C, NaN when not modelled) and the
 * payload (kg).
 *
 * @param position   the target on the tool, tracker frame, m
 * @param conditions directions, time, temperature, payload
 */
public record TrackerReading(Vec3 position, PoseConditions conditions) { }
