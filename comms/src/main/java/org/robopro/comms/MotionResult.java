package org.robopro.comms;

/**
 * What the controller reports after a motion: the motion time in seconds (simulated time on the
 * simulator; NaN when the controller, like plain SERVER.mod, does not report it).
 */
public record MotionResult(double motionTimeS) { }
