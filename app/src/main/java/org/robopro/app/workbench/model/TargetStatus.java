package org.robopro.app.workbench.model;

/** Whether the robot can reach a target: drawn green, or red when not. */
public enum TargetStatus {
    REACHABLE, UNREACHABLE, OUTSIDE_LIMITS;

    public boolean ok() { return this == REACHABLE; }
}
