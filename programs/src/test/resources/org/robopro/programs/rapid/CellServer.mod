MODULE CellServer
  ! robopro fixture: a small cell server written for the tests (not taken from any
  ! public program). It uses the constructs socket servers and drivers rely on.

  RECORD cellcmd
    num code;
    num arg1;
    string text;
  ENDRECORD

  CONST num MAX_QUEUE := 16;
  CONST num PORT_NO := 0x1F90;
  PERS speeddata cellSpeed;
  PERS zonedata cellZone;
  PERS tooldata gripper := [TRUE,[[0,0,120],[1,0,0,0]],[2.5,[0,0,60],[1,0,0,0],0,0,0]];
  VAR socketdev listener;
  VAR socketdev peer;
  VAR num queue{MAX_QUEUE};
  VAR num queued := 0;
  VAR jointtarget home;
  VAR intnum timerInt;
  VAR bool busy;

  PROC main()
    VAR string request;
    VAR num code;
    home := CJointT();
    busy := FALSE;
    cellSpeed := [200, 100, 0, 0];
    cellZone := [FALSE, 5, 8, 8, 0.8, 8, 0.8];
    IF queued = 0 Reset_queue;
    StopMove; ClearPath; StartMove;
    WaitUntil (queued < MAX_QUEUE) \PollRate:=.05;
    SocketCreate listener;
    SocketBind listener, "127.0.0.1", PORT_NO;
    SocketListen listener;
    SocketAccept listener, peer \Time:=WAIT_MAX;
    WHILE TRUE DO
      SocketReceive peer \Str:=request \Time:=WAIT_MAX;
      code := StrLen(request) MOD 8;
      TEST code
        CASE 0, 1:
          MoveAbsJ home, cellSpeed, cellZone, gripper;
        CASE 2, 3, 4:
          if busy THEN
            busy := FALSE;
          ENDIF
        DEFAULT:
          TPWrite "unknown request";
      ENDTEST
      SocketSend peer \Str:="ack " + NumToStr(code, 0);
    ENDWHILE
  ERROR (LONG_JMP_ALL_ERR, ERR_SOCK_CLOSED)
    TEST ERRNO
      CASE ERR_SOCK_CLOSED, ERR_SOCK_TIMEOUT:
        SocketClose peer;
        RETRY;
      DEFAULT:
        TRYNEXT;
    ENDTEST
  UNDO
    IF SocketGetStatus(peer) <> SOCKET_CLOSED SocketClose peer;
  ENDPROC

  PROC Reset_queue()
    FOR k FROM 1 TO Dim(queue, 1) DO
      queue{k} := 0;
    ENDFOR
    queued := 0;
  ERROR
    RAISE;
  ENDPROC

  LOCAL TRAP on_timer
    IF NOT busy RETURN;
    busy := FALSE;
  ENDTRAP
ENDMODULE
