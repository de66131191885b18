package org.robopro.comms.sim;

import java.nio.charset.StandardCharsets;

/** Test fixtures shared across packages: controllers on the test gantry robot and programs. */
public final class TestSupport {
    private TestSupport() { }

    public static SimulatedController gantryController(double noiseM) {
        return SimulatedControllerTest.controller(noiseM);
    }

    public static SimulatedRobot gantry() { return new GantryRobot(); }

    /** The tracker target's true position (tracker frame, no noise) of a gantry controller at its current joints. */
    public static org.robopro.models.Vec3 gantryTruePoint(SimulatedController c) {
        return ((GantryRobot) c.robot()).truePoint(c.readJoints());
    }

    public static byte[] squareProgram() { return Programs.square().getBytes(StandardCharsets.UTF_8); }

    /** A valid program of {@code moves} MoveL lines back and forth (about 75 bytes a move). */
    public static byte[] longProgram(int moves) {
        StringBuilder sb = new StringBuilder("MODULE long\n  PROC main()\n");
        for (int i = 0; i < moves; i++)
            sb.append("    MoveL [[").append(800 + (i % 2) * 50).append(",").append(i % 7).append(",1000],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v500, fine, tool0;\n");
        return sb.append("  ENDPROC\nENDMODULE\n").toString().getBytes(StandardCharsets.UTF_8);
    }
}
