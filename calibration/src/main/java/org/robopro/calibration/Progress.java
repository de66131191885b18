package org.robopro.calibration;

/** Receives progress of a long computation: a stage name and a fraction in [0, 1]. */
@FunctionalInterface
public interface Progress {
    Progress NONE = (stage, fraction) -> { };

    void update(String stage, double fraction);
}
