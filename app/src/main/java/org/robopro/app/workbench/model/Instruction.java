package org.robopro.app.workbench.model;

import java.util.Objects;

/**
 * One motion instruction of the workbench's program view: MoveJ or MoveL to a named target,
 * with RAPID speed (mm/s) and zone (mm; 0 = fine).
 */
public record Instruction(Type type, String target, double speedMmPerS, double zoneMm) {
    public enum Type { MOVEJ, MOVEL;
        public String rapid() { return this == MOVEJ ? "MoveJ" : "MoveL"; }
    }

    public Instruction {
        Objects.requireNonNull(type, "type");
        Objects.requireNonNull(target, "target");
        if (!(speedMmPerS > 0)) throw new IllegalArgumentException("speed must be > 0 mm/s, got " + speedMmPerS);
        if (!(zoneMm >= 0)) throw new IllegalArgumentException("zone must be >= 0 mm, got " + zoneMm);
    }

    public String speedName() { return "v" + Math.round(speedMmPerS); }
    public String zoneName() { return zoneMm == 0 ? "fine" : "z" + Math.round(zoneMm); }

    @Override public String toString() {
        return type.rapid() + " " + target + ", " + speedName() + ", " + zoneName() + ", tool;";
    }
}
