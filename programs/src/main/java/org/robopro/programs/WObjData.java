package org.robopro.programs;

/**
 * RAPID's {@code wobjdata}: whether the robot holds the work object, whether a user frame is
 * moved by a programmable unit (ufprog), the mechanical unit moving it (ufmec, "" for none), the
 * user frame (in world) and the object frame (in the user frame).
 */
public record WObjData(boolean robhold, boolean ufprog, String ufmec, RapidPose uframe, RapidPose oframe)
        implements RapidValue {
    /** RAPID's predefined wobj0: the world frame. */
    public static final WObjData WOBJ0 = new WObjData(false, true, "", RapidPose.IDENTITY, RapidPose.IDENTITY);

    public WObjData {
        if (ufmec == null || uframe == null || oframe == null) throw new IllegalArgumentException("wobjdata fields must not be null");
    }

    @Override public String rapidType() { return "wobjdata"; }
}
