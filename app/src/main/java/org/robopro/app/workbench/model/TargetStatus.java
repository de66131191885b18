package org.robopro.app.workbench.model;

/** Whether the robot can reach a target: drawn green, or red when not. */
public enum TargetStatus {
    REACHABLE, UNREACHABLE, OUTSIDE_LIMITS,
    /** Reachable by itself, but the path check reports an error moving to it. */
    PATH_PROBLEM;

    public boolean ok() { return this == REACHABLE; }
}
