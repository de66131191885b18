package org.robopro.models;

import java.util.List;
import java.util.Map;

/**
 * A non-geometric effect in an extended model, as the diagnosis names it
 * ({@code joint-compliance}, {@code gear-periodic}, {@code backlash}, {@code thermal-expansion},
 * {@code joint-scale}, {@code joint-coupling}), the joints it acts on (1-based) and its
 * identified parameters in SI units, keyed by name.
 */
public record EffectDescription(String effect, List<Integer> joints, Map<String, Double> parameters) {
    public EffectDescription {
        joints = List.copyOf(joints);
        parameters = Map.copyOf(parameters);
    }
}
