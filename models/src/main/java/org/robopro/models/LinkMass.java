package org.robopro.models;

/**
 * Mass of the link moved by joint {@code joint} (1-based) and its centre of mass, in base
 * coordinates at the zero position (m). Used for gravity torques (joint compliance).
 */
public record LinkMass(int joint, String name, double massKg, Vec3 centreOfMass) { }
