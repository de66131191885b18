package org.robopro.programs.collision;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.robopro.kinematics.InverseKinematics;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.CellFile;
import org.robopro.models.CellObject;
import org.robopro.models.PoseDescription;
import org.robopro.models.RobotLibrary;
import org.robopro.models.Rgba;
import org.robopro.models.Vec3;
import org.robopro.programs.LoadData;
import org.robopro.programs.Move;
import org.robopro.programs.Quaternion;
import org.robopro.programs.RapidModule;
import org.robopro.programs.RapidPose;
import org.robopro.programs.Ref;
import org.robopro.programs.RobTarget;
import org.robopro.programs.Teach;
import org.robopro.programs.ToolData;
import org.robopro.programs.WObjData;
import org.robopro.programs.check.CheckReport;
import org.robopro.programs.check.PathChecker;
import org.robopro.programs.check.Problem;
import org.robopro.programs.sim.MotionInterpreter;
import org.robopro.programs.sim.ProgramStep;

class ClearanceCheckerTest {
    static final KinematicModel IRB2000 = KinematicModel.build(RobotLibrary.shipped("irb2000"));
    static final ToolData TORCH = new ToolData(true, new RapidPose(new Vec3(0, 0, 0.15), Quaternion.IDENTITY), LoadData.LOAD0);

    static CellObject box(String name, Vec3 centre, Vec3 size) {
        return new CellObject(name, CellObject.Kind.BOX, new PoseDescription(centre, 1, 0, 0, 0), size, new Rgba(0.5, 0.5, 0.5, 1), "", 1);
    }

    /** A vertical MoveL with the torch pointing down from 800 mm to 500 mm over (900, 0). */
    static List<ProgramStep> plunge() {
        InverseKinematics ik = InverseKinematics.of(IRB2000);
        double[] seed = {0, 0.2, 0.1, 0.1, 1.2, 0.1};
        List<RobTarget> t = new ArrayList<>();
        for (double z : new double[] {0.8, 0.5}) {
            Pose tcp = Pose.of(new double[] {-1, 0, 0, 0, 1, 0, 0, 0, -1}, 0.9, 0, z);
            double[] q = ik.solveNear(tcp.times(TORCH.tframe().toPose().inverse()), seed).orElseThrow().q();
            t.add(Teach.taught(IRB2000, q, TORCH, WObjData.WOBJ0));
            seed = q;
        }
        RapidModule m = RapidModule.builder("C").pers("tTorch", TORCH).constant("pUp", t.get(0)).constant("pDown", t.get(1))
                .procedure("main", List.of(Move.moveJ(Ref.to("pUp"), Ref.to("v1000"), Ref.to("fine"), "tTorch", null),
                        Move.moveL(Ref.to("pDown"), Ref.to("v100"), Ref.to("fine"), "tTorch", null))).build();
        return MotionInterpreter.of(m).run();
    }

    @Test
    void check_plungeIntoBlock_collisionWithLine_clearOtherwiseWithKnownClearance() {
        List<ProgramStep> steps = plunge();
        CheckReport r = new PathChecker(IRB2000).check(steps);
        assertFalse(r.hasErrors(), r::format);
        ClearanceChecker.Options o = new ClearanceChecker.Options(0.05, 0.025, Math.toRadians(1), 0.01);
        // A block whose top is at 600 mm right under the TCP: the torch drives into it.
        ClearanceChecker hitting = new ClearanceChecker(IRB2000, Pose.IDENTITY, List.of(box("fixture", new Vec3(0.9, 0, 0.55), new Vec3(0.1, 0.1, 0.1))), o);
        ClearanceChecker.Result hit = hitting.check(steps, r, Optional.empty());
        Problem p = hit.problems().stream().filter(x -> x.severity() == Problem.Severity.ERROR).findFirst().orElseThrow(() -> new AssertionError(hit.toString()));
        assertEquals(Problem.Kind.COLLISION, p.kind());
        assertTrue(p.step().contains("MoveL pDown") && p.message().contains("tool - fixture"), p.toString());
        // Top at 400 mm: the lowest TCP (500 mm) passes 100 mm over it, less the torch's 25 mm radius.
        ClearanceChecker clear = new ClearanceChecker(IRB2000, Pose.IDENTITY, List.of(box("fixture", new Vec3(0.9, 0, 0.35), new Vec3(0.1, 0.1, 0.1))), o);
        ClearanceChecker.Result ok = clear.check(steps, r, Optional.empty());
        assertTrue(ok.problems().isEmpty(), ok.toString());
        ClearanceChecker.MoveClearance down = ok.moves().get(1);
        assertEquals(0.075, down.minClearanceM(), 1e-6, down.toString());
        assertEquals("tool - fixture", down.closestPair());
    }

    @Test
    void at_homePose_noSelfCollisionAndFarFromAnEmptyCell() {
        ClearanceChecker c = new ClearanceChecker(IRB2000, Pose.IDENTITY, List.of(), ClearanceChecker.Options.forRobot(IRB2000));
        ClearanceChecker.Snapshot s = c.at(new double[6], TORCH.tframe().toPose());
        assertTrue(s.colliding().isEmpty(), s.toString());
        // Folding the arm back onto itself (axis 3 far over) brings non-neighbour links together.
        double[] folded = {0, 0, 0, 0, 0, 0};
        folded[2] = IRB2000.qMin(2);
        folded[4] = IRB2000.qMax(4);
        assertTrue(c.at(folded, TORCH.tframe().toPose()).minClearanceM() < s.minClearanceM(), "folding brings links closer");
    }

    @Test
    void placement_shippedCellClean_tableThroughCabinetWarns() {
        List<CellObject> objects = CellFile.shipped("irb2000-welding").objects();
        assertEquals(List.of(), ClearanceChecker.placement(objects, 0.001));
        List<CellObject> moved = new ArrayList<>(objects);
        CellObject first = moved.get(0);
        moved.add(box("crate", first.worldTobject().position(), new Vec3(0.2, 0.2, 0.2)));
        List<String> w = ClearanceChecker.placement(moved, 0.001);
        assertEquals(1, w.size(), w.toString());
        assertTrue(w.get(0).contains("crate"), w.toString());
    }
}
