package org.robopro.bench;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.OptionalDouble;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.CellDescription;
import org.robopro.models.CellFile;
import org.robopro.models.RobotLibrary;
import org.robopro.models.Vec3;
import org.robopro.programs.JointTarget;
import org.robopro.programs.LoadData;
import org.robopro.programs.ModuleItem;
import org.robopro.programs.Move;
import org.robopro.programs.Procedure;
import org.robopro.programs.Quaternion;
import org.robopro.programs.RapidModule;
import org.robopro.programs.RapidPose;
import org.robopro.programs.Ref;
import org.robopro.programs.RobTarget;
import org.robopro.programs.Statement;
import org.robopro.programs.Teach;
import org.robopro.programs.ToolData;
import org.robopro.programs.WObjData;
import org.robopro.programs.check.CheckCache;
import org.robopro.programs.check.CheckReport;
import org.robopro.programs.check.PathChecker;
import org.robopro.programs.collision.ClearanceChecker;
import org.robopro.programs.sim.MotionInterpreter;
import org.robopro.programs.sim.ProgramStep;
import org.robopro.programs.sim.Simulation;

/**
 * Speed target (docs/performance.md): the path check of a 200-move program with collisions in
 * under 1 s. The program: 200 moves (MoveJ / MoveL / MoveC mixed, fly-by zones) over taught
 * targets in front of the IRB-2000 in the shipped welding cell; collisions against its table,
 * plates, cabinet and pedestal plus self-collision. The edit benchmarks change one move of it
 * (each call a new value, so the cache never has the answer) and check it again, from scratch or
 * incrementally.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
public class ProgramCheckBench {
    KinematicModel model;
    RapidModule module;
    CellDescription cell;
    List<ProgramStep> steps;
    CheckReport report;
    ClearanceChecker clearance;
    List<Statement> body;
    RobTarget p100;
    /** Path checker and cache of the incremental benchmarks, warmed on the program as built. */
    PathChecker checker;
    CheckCache cache;
    int edits;

    @Setup
    public void setup() {
        model = KinematicModel.build(RobotLibrary.shipped("irb2000"));
        cell = CellFile.shipped("irb2000-welding");
        ToolData torch = new ToolData(true, new RapidPose(new Vec3(0, 0, 0.15), Quaternion.IDENTITY), LoadData.LOAD0);
        RapidModule.Builder b = RapidModule.builder("Bench").pers("tTorch", torch).constant("jHome", JointTarget.of(0, 0, 0, 0, 0.5, 0));
        body = new ArrayList<>();
        body.add(Move.moveAbsJ(Ref.to("jHome"), Ref.to("v1000"), Ref.to("fine"), "tTorch", null));
        for (int k = 0; k < 200; k++) {
            double s = k / 200.0;
            double[] q = {-0.6 + 1.2 * s, 0.25 + 0.1 * Math.sin(7 * s), 0.05 + 0.05 * Math.cos(5 * s), 0.15, 0.9 + 0.1 * Math.sin(3 * s), 0.25};
            b.constant("p" + k, Teach.taught(model, q, torch, WObjData.WOBJ0));
            String zone = k % 5 == 4 ? "fine" : "z10";
            if (k % 10 == 9) {
                // circle point half way in joint 1, raised in joint 2: off the chord
                double h = (k - 0.5) / 200.0;
                double[] c = {-0.6 + 1.2 * h, 0.3 + 0.1 * Math.sin(7 * h), 0.05 + 0.05 * Math.cos(5 * h), 0.15, 0.9 + 0.1 * Math.sin(3 * h), 0.25};
                b.constant("c" + k, Teach.taught(model, c, torch, WObjData.WOBJ0));
                body.add(Move.moveC(Ref.to("c" + k), Ref.to("p" + k), Ref.to("v200"), Ref.to(zone), "tTorch", null));
            }
            else if (k % 3 == 0) body.add(Move.moveJ(Ref.to("p" + k), Ref.to("v1000"), Ref.to(zone), "tTorch", null));
            else body.add(Move.moveL(Ref.to("p" + k), Ref.to("v200"), Ref.to(zone), "tTorch", null));
        }
        module = b.procedure("main", body).build();
        steps = MotionInterpreter.of(module).run();
        report = new PathChecker(model).check(steps);
        clearance = new ClearanceChecker(model, ClearanceChecker.pose(cell.worldTbase()), cell.objects(), ClearanceChecker.Options.forRobot(model));
        p100 = (RobTarget) module.declaration("p100").orElseThrow().value();
        checker = new PathChecker(model);
        cache = new CheckCache();
        checker.check(MotionInterpreter.of(module).simulate("main"), List.of(), cache);
    }

    /** The program with statement {@code index} of main replaced. */
    RapidModule edited(int index, Statement s) {
        List<Statement> b = new ArrayList<>(body);
        b.set(index, s);
        List<ModuleItem> items = new ArrayList<>();
        for (ModuleItem it : module.items()) items.add(it instanceof Procedure p && p.name().equals("main") ? p.withBody(b) : it);
        return module.withItems(items);
    }

    /** An edit the cache has not seen: move 100 (a MoveL) goes to a target shifted by a new amount along x. */
    RapidModule targetEdit() {
        double dx = 1e-5 * (1 + edits++ % 1000);
        RobTarget t = p100.withPose(Pose.translation(dx, 0, 0).times(p100.pose()));
        return edited(101, ((Move) body.get(101)).withToPoint(Ref.inline(t)));
    }

    /** An edit the cache has not seen: move 100 gets a new \V speed. */
    RapidModule speedEdit() {
        double v = 0.1 + 1e-4 * (1 + edits++ % 1000);
        return edited(101, ((Move) body.get(101)).withSpeedOverride(OptionalDouble.of(v), OptionalDouble.empty()));
    }

    /** A new edit's simulation, made before each call and not timed: the check-only benchmarks time the path check alone. */
    @State(Scope.Thread)
    public static class NextEdit {
        Simulation target, speed;

        @Setup(Level.Invocation)
        public void prepare(ProgramCheckBench b) {
            target = MotionInterpreter.of(b.targetEdit()).simulate("main");
            speed = MotionInterpreter.of(b.speedEdit()).simulate("main");
        }
    }

    /** Path check alone, from scratch, of a program with one move's target edited. */
    @Benchmark
    public CheckReport checkOnlyTargetEditFull(NextEdit e) {
        return new PathChecker(model).check(e.target, List.of());
    }

    /** Path check alone, incremental, of a program with one move's target edited. */
    @Benchmark
    public CheckReport checkOnlyTargetEditIncremental(NextEdit e) {
        return checker.check(e.target, List.of(), cache);
    }

    /** Path check alone, incremental, of a program with one move's speed edited. */
    @Benchmark
    public CheckReport checkOnlySpeedEditIncremental(NextEdit e) {
        return checker.check(e.speed, List.of(), cache);
    }

    /** The interpreter alone on an edited program (part of every edit benchmark; subtract it to see the check). */
    @Benchmark
    public Simulation editTargetInterpreterOnly() {
        return MotionInterpreter.of(targetEdit()).simulate("main");
    }

    /** One move's target edited, the whole program checked again (interpreter + path check). */
    @Benchmark
    public CheckReport editTargetFull() {
        return new PathChecker(model).check(MotionInterpreter.of(targetEdit()).simulate("main"), List.of());
    }

    /** One move's target edited, checked incrementally (the edited motion and the one after it are solved). */
    @Benchmark
    public CheckReport editTargetIncremental() {
        return checker.check(MotionInterpreter.of(targetEdit()).simulate("main"), List.of(), cache);
    }

    /** One move's speed edited, checked incrementally (only that motion is solved). */
    @Benchmark
    public CheckReport editSpeedIncremental() {
        return checker.check(MotionInterpreter.of(speedEdit()).simulate("main"), List.of(), cache);
    }

    /** Interpreter + path check (IK along every path, limits, configuration, blending, cycle time). */
    @Benchmark
    public CheckReport pathCheck200Moves() {
        return new PathChecker(model).check(MotionInterpreter.of(module).run());
    }

    /** The collision sweep alone over the checked path. */
    @Benchmark
    public ClearanceChecker.Result clearance200Moves() {
        return clearance.check(steps, report, Optional.empty());
    }

    /** Everything a `program check --cell` does: interpreter, path check, collision sweep. */
    @Benchmark
    public ClearanceChecker.Result pathCheckWithCollisions200Moves() {
        List<ProgramStep> s = MotionInterpreter.of(module).run();
        CheckReport r = new PathChecker(model).check(s);
        return new ClearanceChecker(model, ClearanceChecker.pose(cell.worldTbase()), cell.objects(), ClearanceChecker.Options.forRobot(model))
                .check(s, r, Optional.empty());
    }
}
