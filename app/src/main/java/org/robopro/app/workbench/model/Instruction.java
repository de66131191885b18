package org.robopro.app.workbench.model;

import java.util.Objects;
import org.robopro.programs.rapid.RapidAst;
import org.robopro.programs.rapid.RapidAstWriter;

/**
 * One line of the workbench's program, one RAPID statement of its {@code PROC main} each
 * ({@link ProgramModule} maps the program 1:1 to a RAPID module): MoveJ, MoveL or MoveC to a
 * named target (MoveC through {@code via}), or MoveAbsJ to the target's joint values (a
 * jointtarget), with speed (mm/s) and zone (mm; 0 = fine); or ({@link Type#RAPID}) any other
 * statement of an imported module, kept as written and shown read-only (waits, I/O, calls,
 * comments, control flow).
 *
 * @param statement the statement of the imported module this line stands for (RAPID: the
 *                  statement kept; a move: the statement it was read from, written back as it
 *                  was while the move is unchanged); null for a move taught or edited here
 */
public record Instruction(Type type, String target, double speedMmPerS, double zoneMm, String via, RapidAst.Stmt statement) {
    public enum Type { MOVEJ, MOVEL, MOVEC, MOVEABSJ, RAPID;
        public String rapid() {
            return switch (this) {
                case MOVEJ -> "MoveJ"; case MOVEL -> "MoveL"; case MOVEC -> "MoveC"; case MOVEABSJ -> "MoveAbsJ"; case RAPID -> "RAPID";
            };
        }

        /** A motion the workbench edits (every type but RAPID). */
        public boolean motion() { return this != RAPID; }

        public static Type ofRapid(String s) {
            for (Type t : values()) if (t.motion() && t.rapid().equalsIgnoreCase(s.trim())) return t;
            throw new IllegalArgumentException("expected MoveJ, MoveL, MoveC or MoveAbsJ, got " + s);
        }
    }

    public Instruction {
        Objects.requireNonNull(type, "type");
        Objects.requireNonNull(target, "target");
        if (type == Type.RAPID) {
            Objects.requireNonNull(statement, "a kept statement");
            if (!target.isEmpty() || via != null) throw new IllegalArgumentException("a kept statement has no target");
        } else {
            if (!(speedMmPerS > 0)) throw new IllegalArgumentException("speed must be > 0 mm/s, got " + speedMmPerS);
            if (!(zoneMm >= 0)) throw new IllegalArgumentException("zone must be >= 0 mm, got " + zoneMm);
            if (via != null && via.isBlank()) via = null;
            if ((type == Type.MOVEC) != (via != null))
                throw new IllegalArgumentException(type == Type.MOVEC ? "MoveC needs a circle point (via)" : type.rapid() + " takes no circle point");
        }
    }

    /** A move taught or edited in the workbench. */
    public Instruction(Type type, String target, double speedMmPerS, double zoneMm, String via) {
        this(type, target, speedMmPerS, zoneMm, via, null);
    }

    public Instruction(Type type, String target, double speedMmPerS, double zoneMm) { this(type, target, speedMmPerS, zoneMm, null, null); }

    /** A statement of an imported module the workbench keeps as written. */
    public static Instruction kept(RapidAst.Stmt statement) { return new Instruction(Type.RAPID, "", 0, 0, null, statement); }

    /** This move as read from {@code s} (written back as {@code s} while unchanged). */
    public Instruction readFrom(RapidAst.Stmt s) { return new Instruction(type, target, speedMmPerS, zoneMm, via, s); }

    public String speedName() { return "v" + Math.round(speedMmPerS); }
    public String zoneName() { return zoneMm == 0 ? "fine" : "z" + Math.round(zoneMm); }

    /** True when the instruction moves to or through {@code name}. */
    public boolean uses(String name) { return type.motion() && (target.equals(name) || name.equals(via)); }

    /** The RAPID text of a kept statement (its first line; a compound statement ends in "..."). */
    public String statementText() {
        if (statement == null) return "";
        String t = RapidAstWriter.statement(statement).strip();
        int nl = t.indexOf('\n');
        return nl < 0 ? t : t.substring(0, nl).strip() + " ...";
    }

    @Override public String toString() {
        if (type == Type.RAPID) return statementText();
        return type.rapid() + " " + (via != null ? via + ", " : "") + target + ", " + speedName() + ", " + zoneName() + ", tool;";
    }
}
