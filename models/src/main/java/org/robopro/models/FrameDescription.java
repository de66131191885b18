package org.robopro.models;

/**
 * A frame given by its origin and two of its axes (z and x), as robot data sheets describe the
 * flange at the zero position: e.g. IRB-2000 "z axis along +x of the base, x axis along -z".
 * Origin in metres; axes unit vectors, orthogonal.
 */
public record FrameDescription(Vec3 origin, Vec3 xAxis, Vec3 zAxis) {
    public Vec3 yAxis() { return zAxis.cross(xAxis); }
}
