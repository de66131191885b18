package org.robopro.models;

/**
 * A tool on the robot flange, as RAPID tooldata: its TCP frame seen from the flange (tool0) and
 * its load. SI units.
 *
 * @param flangeTtcp   TCP frame in flange coordinates
 * @param massKg       tool mass
 * @param centreOfMass tool centre of mass in flange coordinates (m)
 */
public record ToolDescription(String name, PoseDescription flangeTtcp, double massKg, Vec3 centreOfMass) { }
