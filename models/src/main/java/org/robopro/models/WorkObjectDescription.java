package org.robopro.models;

/** A work object (RAPID wobjdata): its user frame seen from the world. SI units. */
public record WorkObjectDescription(String name, PoseDescription worldTuser) { }
