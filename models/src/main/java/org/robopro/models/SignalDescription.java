package org.robopro.models;

import java.util.List;
import java.util.Locale;

/**
 * One I/O signal of a cell (the controller's EIO configuration, as far as a program check needs
 * it): its name, type and, for inputs, how the simulation drives it.
 *
 * @param name    signal name as RAPID uses it (compared ignoring case)
 * @param type    digital/analog/group, input/output
 * @param value   value at the start of the cycle
 * @param script  for inputs: value changes at given times after the cycle starts, in time order
 * @param follows for inputs: an output this input echoes (a gripper's "closed" sensor follows its
 *                valve), empty when none
 * @param delayS  how long after {@code follows} changes this input takes the same value, s
 */
public record SignalDescription(String name, Type type, double value, List<Change> script, String follows, double delayS) {
    public enum Type {
        DI, DO, AI, AO, GI, GO;

        public boolean input() { return this == DI || this == AI || this == GI; }

        public boolean digital() { return this == DI || this == DO; }

        /** The type named in a file ("DI", "do", ...), or null. */
        public static Type parse(String s) {
            for (Type t : values()) if (t.name().equalsIgnoreCase(s)) return t;
            return null;
        }
    }

    /** The input takes {@code value} at {@code timeS} after the cycle starts. */
    public record Change(double timeS, double value) { }

    public SignalDescription {
        if (name == null || name.isEmpty()) throw new IllegalArgumentException("signal name must not be empty");
        script = List.copyOf(script);
        follows = follows == null ? "" : follows;
        if (!type.input() && (!script.isEmpty() || !follows.isEmpty()))
            throw new IllegalArgumentException("only inputs are scripted: " + name + " is " + type);
        if (!(delayS >= 0 && Double.isFinite(delayS))) throw new IllegalArgumentException("delay must be finite and >= 0: " + delayS);
    }

    /** A signal held at {@code value}. */
    public static SignalDescription constant(String name, Type type, double value) {
        return new SignalDescription(name, type, value, List.of(), "", 0);
    }

    /** The name as a lookup key. */
    public String key() { return name.toLowerCase(Locale.ROOT); }
}
