package org.robopro.models;

/** A colour, components 0..1. */
public record Rgba(double r, double g, double b, double a) {
    public Rgba {
        for (double c : new double[] {r, g, b, a})
            if (!(c >= 0 && c <= 1)) throw new IllegalArgumentException("colour components must be in 0..1: " + c);
    }
}
