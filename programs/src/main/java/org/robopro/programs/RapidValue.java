package org.robopro.programs;

/** A value a RAPID module declares: the record types robopro understands, and num/bool/string. */
public sealed interface RapidValue permits RobTarget, JointTarget, ToolData, WObjData, LoadData, SpeedData,
        ZoneData, RapidPose, RapidValue.Num, RapidValue.Bool, RapidValue.Str {

    /** The RAPID data type name (robtarget, tooldata, ...). */
    String rapidType();

    record Num(double value) implements RapidValue {
        public String rapidType() { return "num"; }
    }

    record Bool(boolean value) implements RapidValue {
        public String rapidType() { return "bool"; }
    }

    /** A string value (RAPID's "" and backslash escapes resolved); at most 80 characters. */
    record Str(String value) implements RapidValue {
        public Str {
            if (value == null || value.length() > 80) throw new IllegalArgumentException("RAPID strings hold 0..80 characters");
            for (int k = 0; k < value.length(); k++)
                if (value.charAt(k) > 0xFF) throw new IllegalArgumentException("RAPID strings hold ISO-8859-1 characters only: " + value);
        }


        public String rapidType() { return "string"; }
    }
}
