%%%
  VERSION:1
  LANGUAGE:ENGLISH
%%%

MODULE PickPlace
  !***********************************************************
  ! Hand-written test fixture in the style of controller files:
  ! CONST/PERS/VAR data, LOCAL, comments, inline targets,
  ! optional arguments and a called procedure.
  !***********************************************************
  PERS tooldata tGripper:=[TRUE,[[0,0,150],[1,0,0,0]],[2.5,[0,0,60],[1,0,0,0],0.01,0.01,0.005]];
  PERS wobjdata wobjConveyor:=[FALSE,TRUE,"",[[800,-200,400],[0.7071067812,0,0,0.7071067812]],[[0,0,0],[1,0,0,0]]];
  CONST jointtarget jHome:=[[0,0,0,0,30,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget pPick:=[[100,50,20],[0,0,1,0],[0,0,0,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]];
  CONST robtarget pPickAbove:=[[100, 50, 220], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  LOCAL CONST robtarget pVia:=[[300,0,300],[0,0,1,0],[0,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR speeddata vApproach:=[250,200,5000,1000];
  LOCAL VAR zonedata zSoft:=[FALSE,5,8,8,0.8,8,0.8];
  VAR num nParts:=0;
  PERS bool bDone:=FALSE;
  VAR string sMsg:="pick \22fast\22";

  PROC main()
    MoveAbsJ jHome\NoEOffs, v1000, fine, tool0;
    pick;
    ! place: via a circle
    MoveC pVia, [[500,-100,220],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], vApproach, zSoft, tGripper\WObj:=wobjConveyor;
    MoveL [[500,-100,20],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v100\V:=80, fine, tGripper\WObj:=wobjConveyor;
    WaitTime 0.5;
    MoveAbsJ jHome, v1000, z50, tool0;
  ENDPROC

  PROC pick()
    MoveJ pPickAbove, v1000, z50, tGripper\WObj:=wobjConveyor; ! above the part
    MoveL pPick, vApproach, fine\Z:=0, tGripper\WObj:=wobjConveyor;
    WaitTime 0.2;
    MoveL \Conc, pPickAbove, v500\T:=0.8, z10, tGripper\WObj:=wobjConveyor;
  ENDPROC
ENDMODULE
