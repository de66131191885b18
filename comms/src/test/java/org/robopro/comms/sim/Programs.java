package org.robopro.comms.sim;

/** RAPID programs for tests (written for the test gantry robot: reachable x 0.2..1.4 m). */
final class Programs {
    private Programs() { }

    static final int SQUARE_MOVES = 5;

    static String square() {
        return """
                MODULE square
                  ! a square in a horizontal plane
                  CONST robtarget p1 := [[800,0,1000],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
                  CONST robtarget p2 := [[900,0,1000],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
                  CONST robtarget p3 := [[900,100,1000],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
                  CONST jointtarget home := [[0,0,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
                  PERS tooldata pen := [TRUE,[[0,0,0],[1,0,0,0]],[1,[0,0,1],[1,0,0,0],0,0,0]];
                  PROC main()
                    MoveAbsJ home\\NoEOffs, v1000, z50, tool0;
                    MoveJ p1, v500, fine, pen;
                    MoveL p2, v200, z10, pen;
                    WaitTime 0.5;
                    MoveL p3, v200, z10, pen \\WObj:=wobj0;
                    MoveL [[900,100,1000],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v200, fine, pen;
                  ENDPROC
                ENDMODULE
                """;
    }
}
