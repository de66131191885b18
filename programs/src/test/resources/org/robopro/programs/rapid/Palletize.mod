MODULE Palletize(NOSTEPIN)
  ! Hand-written fixture in the style of a controller program:
  ! records, arrays, routines with parameters, loops, TEST, error handler.
  RECORD layer
    num rows;
    num cols; ! per row
  ENDRECORD
  ALIAS num counter;
  PERS tooldata tGrip:=[TRUE,[[0,0,120],[1,0,0,0]],[1.5,[0,0,40],[1,0,0,0],0,0,0]];
  CONST robtarget pBase:=[[600,-200,100],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget jHome:=[[0,0,0,0,30,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR robtarget pNow;
  VAR num pitch{2}:=[50,0x28];
  VAR layer lay:=[2,3];
  VAR counter nDone;
  LOCAL VAR intnum irStop;
  VAR bool bSlow:=FALSE;
  CONST num nMax:=1.2E+01;

  PROC main()
    MoveAbsJ jHome, v1000, fine, tool0;
    FOR r FROM 1 TO lay.rows DO
      FOR c FROM 1 TO lay.cols DO
        place r, c\Lift:=30;
      ENDFOR
    ENDFOR
    IF nDone >= nMax OR NOT bSlow AND nDone <> 0 THEN
      TPWrite "done " + NumToStr(nDone, 0);
    ELSEIF bSlow THEN
      WaitTime 1;
    ELSE
      Stop;
    ENDIF
    TEST nDone MOD 2
    CASE 0, 2:
      pNow := CRobT(\Tool:=tGrip);
      MoveL Offs(pNow, 0, 0, -(pitch{1} - 10) * 2), v200, fine, tGrip;
    DEFAULT:
      MoveAbsJ jHome, v1000, fine, tool0;
    ENDTEST
  ENDPROC

  PROC place(num row, num col, \num Lift)
    VAR robtarget p;
    VAR num up:=50;
    IF Present(Lift) up := Lift;
    p := Offs(pBase, (row - 1) * pitch{1}, (col - 1) * pitch{2}, 0);
    MoveJ RelTool(p, 0, 0, -up), v500, z10, tGrip;
    MoveL p, v100, fine, tGrip;
    Incr nDone;
    MoveL RelTool(p, 0, 0, -up\Rz:=90), v500, z10, tGrip;
  ERROR
    RETURN;
  ENDPROC

  FUNC num area(layer l)
    RETURN l.rows * l.cols;
  ENDFUNC

  TRAP onStop
    bSlow := TRUE;
  ENDTRAP
ENDMODULE
