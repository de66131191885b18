package org.robopro.models;

/** The seed paper's two joint types (Fig. 7). */
public enum JointType {
    REVOLUTE, PRISMATIC;

    /** Parses "revolute"/"prismatic" (case-insensitive); null if unknown. */
    public static JointType parse(String s) {
        if (s == null) return null;
        return switch (s.trim().toLowerCase(java.util.Locale.ROOT)) {
            case "revolute", "r" -> REVOLUTE;
            case "prismatic", "p" -> PRISMATIC;
            default -> null;
        };
    }

    public String fileName() { return name().toLowerCase(java.util.Locale.ROOT); }
}
