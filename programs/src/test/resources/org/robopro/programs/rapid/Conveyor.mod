MODULE Conveyor
  ! robopro fixture: conveyor tracking written for the tests; every construct here is one
  ! rapidchecker 0.1.5 accepts, so the faithful export can be checked by it.

  RECORD slot
    num x;
    num y;
    bool full;
  ENDRECORD

  CONST num NSLOTS := 4;
  PERS speeddata vBelt;
  VAR slot slots{NSLOTS};
  VAR num picked := 0;
  VAR robtarget pPick := [[500,0,200],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS tooldata tSuction := [TRUE,[[0,0,90],[1,0,0,0]],[0.8,[0,0,30],[1,0,0,0],0,0,0]];

  FUNC num freeSlot()
    FOR k FROM 1 TO NSLOTS DO
      IF NOT slots{k}.full RETURN k;
    ENDFOR
    RETURN -1;
  ENDFUNC

  PROC main()
    VAR num k;
    vBelt := [150, 200, 0, 0];
    WaitUntil (picked < NSLOTS) \PollRate:=.05;
    WHILE picked < NSLOTS DO
      k := freeSlot();
      TEST k
        CASE -1:
          TPWrite "full";
        DEFAULT:
          slots{k}.x := 100 * k;
          slots{k}.full := TRUE;
          MoveL Offs(pPick, slots{k}.x, 0, 0), vBelt, fine, tSuction;
      ENDTEST
      Incr picked;
    ENDWHILE
  ERROR
    IF ERRNO = ERR_PATH_STOP THEN
      StorePath;
      RETRY;
    ENDIF
    RAISE;
  ENDPROC
ENDMODULE
