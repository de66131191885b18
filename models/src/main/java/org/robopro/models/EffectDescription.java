package org.robopro.models;

import java.util.List;
import java.util.Map;
import java.util.Objects;

/**
 * A non-geometric effect in an extended model, as the diagnosis names it
 * ({@code joint-compliance}, {@code gear-periodic}, {@code backlash}, {@code thermal-expansion},
 * {@code joint-scale}, {@code joint-coupling}), the joints it acts on (1-based) and its
 * identified parameters in SI units, keyed by name. Read from a robot file it keeps its place
 * there ({@code source}), so that a reader that finds its values wrong can name the line; equality
 * and the text form are of the three values alone.
 */
public record EffectDescription(String effect, List<Integer> joints, Map<String, Double> parameters, LocatedJson.Node source) {
    public EffectDescription {
        joints = List.copyOf(joints);
        parameters = Map.copyOf(parameters);
    }

    /** An effect made in code (no place in a file). */
    public EffectDescription(String effect, List<Integer> joints, Map<String, Double> parameters) {
        this(effect, joints, parameters, null);
    }

    /**
     * Bad input at {@code field} of this effect ("joints", "parameters_si", "parameters_si.b", or ""
     * for the effect as a whole): located at that field's value in the file where it is there, else
     * at the nearest enclosing one (a parameter that is missing: its effect's); without a place in a
     * file, {@code file} and the field's path under the effect's name ("effects.backlash.parameters_si.b";
     * "effects.joints").
     */
    public InputException error(String file, String field, String problem) {
        if (source == null)
            return new InputException(file, 0, 0, field.isEmpty() || field.startsWith("parameters_si") ? "effects." + effect
                    + (field.isEmpty() ? "" : "." + field) : "effects." + field, problem);
        LocatedJson.Node at = source;
        if (!field.isEmpty())
            for (String part : field.split("\\.")) {
                if (at.kind() != LocatedJson.Kind.OBJECT || !at.has(part)) break;
                at = at.get(part);
            }
        return new InputException(at.file(), at.line(), at.column(), field.isEmpty() ? source.path() : source.path() + "." + field, problem);
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof EffectDescription d && effect.equals(d.effect) && joints.equals(d.joints) && parameters.equals(d.parameters);
    }

    @Override
    public int hashCode() { return Objects.hash(effect, joints, parameters); }

    @Override
    public String toString() { return "EffectDescription[effect=" + effect + ", joints=" + joints + ", parameters=" + parameters + "]"; }
}
