package org.robopro.programs.sim;

import java.util.Optional;
import java.util.OptionalDouble;
import org.robopro.kinematics.ConfData;
import org.robopro.kinematics.Pose;
import org.robopro.programs.Move;
import org.robopro.programs.SpeedData;
import org.robopro.programs.ToolData;
import org.robopro.programs.WObjData;
import org.robopro.programs.ZoneData;
import org.robopro.programs.rapid.RapidAst;
import org.robopro.programs.rapid.SourcePos;

/**
 * One resolved motion: targets, tool and work object looked up, poses in base coordinates (the
 * world frame is taken as the robot base), speeds in SI with {@code \V}/{@code \Z} applied.
 *
 * @param kind          instruction
 * @param targetName    ToPoint's name, "*" when inline
 * @param circName      MoveC's CirPoint name ("*" inline), empty otherwise
 * @param baseTflange   flange pose at ToPoint (robtargets; empty for MoveAbsJ)
 * @param baseTtcp      TCP pose at ToPoint in base coordinates (robtargets)
 * @param baseTflangeCirc flange pose at MoveC's CirPoint
 * @param baseTtcpCirc  TCP pose at MoveC's CirPoint
 * @param conf          the robtarget's confdata (empty for MoveAbsJ)
 * @param q             MoveAbsJ's joint values (rad), empty otherwise
 * @param speed         speeddata with \V applied to the TCP speed
 * @param time          \T: the motion's time (s)
 * @param zone          zonedata with \Z applied to the TCP zone
 * @param flangeTtcp    the tool frame in the flange (for a robot-held tool)
 * @param context       call path and loop iteration ("main#4[i=2] > weld#3"), empty at the top level
 * @param instruction   the instruction as written (MoveL, ArcL, TriggL, ...); {@code kind} is its geometry
 * @param statement     the statement that ran: the very node of the program's syntax tree (compare
 *                      with {@code ==}; a statement run twice, in a loop or from two calls, gives two
 *                      steps with the same node)
 */
public record MoveStep(String procedure, int statementIndex, Optional<SourcePos> source, Move.Kind kind,
                       String targetName, Optional<String> circName,
                       Optional<Pose> baseTflange, Optional<Pose> baseTtcp,
                       Optional<Pose> baseTflangeCirc, Optional<Pose> baseTtcpCirc,
                       Optional<ConfData> conf, Optional<double[]> q, SpeedData speed, OptionalDouble time,
                       ZoneData zone, String toolName, ToolData tool, String wobjName, WObjData wobj, Pose flangeTtcp,
                       String context, String instruction, Optional<RapidAst.Stmt> statement)
        implements ProgramStep {

    @Override public Optional<double[]> q() { return q.map(double[]::clone); }

    @Override public String label() {
        return (context.isEmpty() ? "" : context + " > ") + procedure + "#" + (statementIndex + 1) + " " + instruction + " " + targetName;
    }
}
