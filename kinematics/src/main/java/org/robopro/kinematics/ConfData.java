package org.robopro.kinematics;

/** ABB configuration data (confdata): quadrants of axes 1, 4, 6 and the configuration number cfx. */
public record ConfData(int cf1, int cf4, int cf6, int cfx) { }
