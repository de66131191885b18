package org.robopro.programs;

/**
 * RAPID's {@code tooldata}: whether the robot holds the tool, the tool frame (TCP) in the flange
 * frame (or, for a stationary tool, in the world frame), and the tool's load.
 */
public record ToolData(boolean robhold, RapidPose tframe, LoadData tload) implements RapidValue {
    /** RAPID's predefined tool0: the flange itself. */
    public static final ToolData TOOL0 = new ToolData(true, RapidPose.IDENTITY, LoadData.LOAD0);

    public ToolData {
        if (tframe == null || tload == null) throw new IllegalArgumentException("tooldata needs tframe and tload");
    }

    @Override public String rapidType() { return "tooldata"; }
}
