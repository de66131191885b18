package org.robopro.programs;

import java.util.Optional;
import java.util.OptionalDouble;

/**
 * A motion instruction: {@code MoveAbsJ}, {@code MoveJ}, {@code MoveL} or {@code MoveC} with the
 * optional arguments robopro understands:
 * {@code Move* [\Conc,] [CirPoint,] ToPoint [\NoEOffs], Speed [\V:=|\T:=], Zone [\Z:=], Tool [\WObj:=];}.
 *
 * @param kind      which instruction
 * @param conc      {@code \Conc}: concurrent execution
 * @param circPoint MoveC's circle point (empty for the others)
 * @param toPoint   a jointtarget for MoveAbsJ, a robtarget otherwise
 * @param noEOffs   MoveAbsJ's {@code \NoEOffs}
 * @param speed     speed data
 * @param v         {@code \V}: TCP speed override (m/s)
 * @param t         {@code \T}: motion time (s)
 * @param zone      zone data
 * @param z         {@code \Z}: TCP zone size override (m)
 * @param tool      tool name (tooldata is always named: a persistent in RAPID)
 * @param wobj      work object name; empty means wobj0
 */
public record Move(Kind kind, boolean conc, Optional<Ref<RobTarget>> circPoint, Ref<? extends RapidValue> toPoint,
                   boolean noEOffs, Ref<SpeedData> speed, OptionalDouble v, OptionalDouble t, Ref<ZoneData> zone,
                   OptionalDouble z, String tool, Optional<String> wobj) implements Statement {

    public enum Kind {
        MOVE_ABS_J("MoveAbsJ"), MOVE_J("MoveJ"), MOVE_L("MoveL"), MOVE_C("MoveC");

        private final String rapidName;

        Kind(String rapidName) { this.rapidName = rapidName; }

        public String rapidName() { return rapidName; }
    }

    public Move {
        if (kind == null || circPoint == null || toPoint == null || speed == null || v == null || t == null
                || zone == null || z == null || tool == null || wobj == null)
            throw new IllegalArgumentException("move fields must not be null (use Optional.empty())");
        if ((kind == Kind.MOVE_C) != circPoint.isPresent())
            throw new IllegalArgumentException("a circle point belongs to MoveC and only MoveC: " + kind);
        if (toPoint instanceof Ref.Inline<?> in) {
            boolean joint = in.value() instanceof JointTarget;
            if (joint != (kind == Kind.MOVE_ABS_J) || !(joint || in.value() instanceof RobTarget))
                throw new IllegalArgumentException(kind.rapidName() + " cannot take a " + in.value().rapidType());
        }
        if (noEOffs && kind != Kind.MOVE_ABS_J) throw new IllegalArgumentException("\\NoEOffs belongs to MoveAbsJ");
        if (v.isPresent() && t.isPresent()) throw new IllegalArgumentException("\\V and \\T exclude each other");
        if (v.isPresent() && !(v.getAsDouble() > 0)) throw new IllegalArgumentException("\\V must be > 0");
        if (t.isPresent() && !(t.getAsDouble() > 0)) throw new IllegalArgumentException("\\T must be > 0");
        if (z.isPresent() && !(z.getAsDouble() >= 0)) throw new IllegalArgumentException("\\Z must be >= 0");
        if (tool.isEmpty()) throw new IllegalArgumentException("move needs a tool");
    }

    public static Move moveL(Ref<RobTarget> to, Ref<SpeedData> speed, Ref<ZoneData> zone, String tool, String wobjOrNull) {
        return new Move(Kind.MOVE_L, false, Optional.empty(), to, false, speed, OptionalDouble.empty(), OptionalDouble.empty(),
                zone, OptionalDouble.empty(), tool, Optional.ofNullable(wobjOrNull));
    }

    public static Move moveJ(Ref<RobTarget> to, Ref<SpeedData> speed, Ref<ZoneData> zone, String tool, String wobjOrNull) {
        return new Move(Kind.MOVE_J, false, Optional.empty(), to, false, speed, OptionalDouble.empty(), OptionalDouble.empty(),
                zone, OptionalDouble.empty(), tool, Optional.ofNullable(wobjOrNull));
    }

    public static Move moveC(Ref<RobTarget> circ, Ref<RobTarget> to, Ref<SpeedData> speed, Ref<ZoneData> zone, String tool,
                             String wobjOrNull) {
        return new Move(Kind.MOVE_C, false, Optional.of(circ), to, false, speed, OptionalDouble.empty(), OptionalDouble.empty(),
                zone, OptionalDouble.empty(), tool, Optional.ofNullable(wobjOrNull));
    }

    public static Move moveAbsJ(Ref<JointTarget> to, Ref<SpeedData> speed, Ref<ZoneData> zone, String tool, String wobjOrNull) {
        return new Move(Kind.MOVE_ABS_J, false, Optional.empty(), to, false, speed, OptionalDouble.empty(), OptionalDouble.empty(),
                zone, OptionalDouble.empty(), tool, Optional.ofNullable(wobjOrNull));
    }

    public Move withConc(boolean c) { return new Move(kind, c, circPoint, toPoint, noEOffs, speed, v, t, zone, z, tool, wobj); }

    public Move withSpeedOverride(OptionalDouble newV, OptionalDouble newT) {
        return new Move(kind, conc, circPoint, toPoint, noEOffs, speed, newV, newT, zone, z, tool, wobj);
    }

    public Move withZoneOverride(OptionalDouble newZ) { return new Move(kind, conc, circPoint, toPoint, noEOffs, speed, v, t, zone, newZ, tool, wobj); }

    public Move withToPoint(Ref<? extends RapidValue> to) { return new Move(kind, conc, circPoint, to, noEOffs, speed, v, t, zone, z, tool, wobj); }

    public Move withCircPoint(Ref<RobTarget> c) { return new Move(kind, conc, Optional.of(c), toPoint, noEOffs, speed, v, t, zone, z, tool, wobj); }

    /** The work object name, "wobj0" when none is given. */
    public String wobjName() { return wobj.orElse("wobj0"); }
}
