package org.robopro.app.workbench.model;

import java.util.Objects;

/**
 * One motion instruction of the workbench's program, one RAPID statement each
 * ({@link ProgramModule} maps the program 1:1 to a RAPID module): MoveJ, MoveL or MoveC to a
 * named target (MoveC through {@code via}), or MoveAbsJ to the target's joint values (a
 * jointtarget), with speed (mm/s) and zone (mm; 0 = fine).
 */
public record Instruction(Type type, String target, double speedMmPerS, double zoneMm, String via) {
    public enum Type { MOVEJ, MOVEL, MOVEC, MOVEABSJ;
        public String rapid() {
            return switch (this) { case MOVEJ -> "MoveJ"; case MOVEL -> "MoveL"; case MOVEC -> "MoveC"; case MOVEABSJ -> "MoveAbsJ"; };
        }

        public static Type ofRapid(String s) {
            for (Type t : values()) if (t.rapid().equalsIgnoreCase(s.trim())) return t;
            throw new IllegalArgumentException("expected MoveJ, MoveL, MoveC or MoveAbsJ, got " + s);
        }
    }

    public Instruction {
        Objects.requireNonNull(type, "type");
        Objects.requireNonNull(target, "target");
        if (!(speedMmPerS > 0)) throw new IllegalArgumentException("speed must be > 0 mm/s, got " + speedMmPerS);
        if (!(zoneMm >= 0)) throw new IllegalArgumentException("zone must be >= 0 mm, got " + zoneMm);
        if (via != null && via.isBlank()) via = null;
        if ((type == Type.MOVEC) != (via != null))
            throw new IllegalArgumentException(type == Type.MOVEC ? "MoveC needs a circle point (via)" : type.rapid() + " takes no circle point");
    }

    public Instruction(Type type, String target, double speedMmPerS, double zoneMm) { this(type, target, speedMmPerS, zoneMm, null); }

    public String speedName() { return "v" + Math.round(speedMmPerS); }
    public String zoneName() { return zoneMm == 0 ? "fine" : "z" + Math.round(zoneMm); }

    /** True when the instruction moves to or through {@code name}. */
    public boolean uses(String name) { return target.equals(name) || name.equals(via); }

    @Override public String toString() {
        return type.rapid() + " " + (via != null ? via + ", " : "") + target + ", " + speedName() + ", " + zoneName() + ", tool;";
    }
}
