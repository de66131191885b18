package org.robopro.programs;

import org.robopro.models.Vec3;

/**
 * RAPID's {@code loaddata}: mass (kg), centre of gravity (m, tool/flange frame), axes of moment
 * (orientation of the inertia axes) and the moments of inertia ix, iy, iz (kg m^2).
 */
public record LoadData(double mass, Vec3 cog, Quaternion aom, double ix, double iy, double iz) implements RapidValue {
    /** RAPID's predefined load0. */
    public static final LoadData LOAD0 = new LoadData(0.001, new Vec3(0, 0, 0.000001), Quaternion.IDENTITY, 0, 0, 0);

    public LoadData {
        if (cog == null || aom == null) throw new IllegalArgumentException("loaddata needs cog and aom");
        if (!(Double.isFinite(mass) && Double.isFinite(ix) && Double.isFinite(iy) && Double.isFinite(iz)))
            throw new IllegalArgumentException("non-finite loaddata");
    }

    @Override public String rapidType() { return "loaddata"; }
}
