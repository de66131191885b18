package org.robopro.models;

/**
 * A mesh drawn for a link: {@code link} 0 is the base, i the link moved by joint i. The path is
 * relative to the robot file. The mesh is given in base coordinates at the zero position (as
 * CAD exports them) unless {@code inLinkFrame}; {@code scale} converts its units to metres.
 */
public record MeshRef(int link, String path, double scale, boolean inLinkFrame) { }
