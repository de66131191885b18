package org.robopro.programs.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import java.util.Optional;
import org.robopro.calibration.compensation.Compensator;
import org.robopro.calibration.compensation.TargetCompensator.Status;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.RobotLibrary;
import org.robopro.models.SignalDescription;
import org.robopro.models.Vec3;
import org.robopro.programs.JointTarget;
import org.robopro.programs.LoadData;
import org.robopro.programs.Move;
import org.robopro.programs.compensation.ProgramCompensation;
import org.robopro.programs.Quaternion;
import org.robopro.programs.RapidModule;
import org.robopro.programs.RapidPose;
import org.robopro.programs.Ref;
import org.robopro.programs.Teach;
import org.robopro.programs.ToolData;
import org.robopro.programs.WObjData;
import org.robopro.programs.check.CheckReport;
import org.robopro.programs.check.PathChecker;
import org.robopro.programs.check.Problem;
import org.robopro.programs.ParsedModule;
import org.robopro.programs.rapid.RapidChecker;
import org.robopro.programs.RapidParser;
import org.robopro.programs.RapidWriter;
import org.robopro.programs.rapid.RapidAstParser;

/**
 * A welding module written the way ABB arc-welding cells are: clamp and wait for the clamp
 * sensor, gas pre-flow by a trigger, a two-pass seam in a FOR loop through a procedure, a
 * second seam, arc start/weld/end with seam and weld data, a pulse to the PLC, named and inline
 * targets, an instruction robopro does not simulate.
 */
class WeldModuleTest {
    static final KinematicModel IRB2000 = KinematicModel.build(RobotLibrary.shipped("irb2000"));
    // Bent torch: TCP 110 mm along x and 340 mm along z of the flange, tilted 35 deg about y.
    static final ToolData TORCH = new ToolData(true, new RapidPose(new Vec3(0.11, 0, 0.34),
            new Quaternion(Math.cos(Math.toRadians(17.5)), 0, Math.sin(Math.toRadians(17.5)), 0)), LoadData.LOAD0);
    static final WObjData FIXTURE = new WObjData(false, true, "", new RapidPose(new Vec3(0.8, -0.2, 0.7), Quaternion.IDENTITY), RapidPose.IDENTITY);

    static final List<SignalDescription> SIGNALS = List.of(
            SignalDescription.constant("doClamp", SignalDescription.Type.DO, 0),
            new SignalDescription("diClamped", SignalDescription.Type.DI, 0, List.of(), "doClamp", 0.3),
            new SignalDescription("diOperatorOk", SignalDescription.Type.DI, 0, List.of(new SignalDescription.Change(2.0, 1)), "", 0),
            SignalDescription.constant("diGasOk", SignalDescription.Type.DI, 1),
            SignalDescription.constant("doGas", SignalDescription.Type.DO, 0),
            SignalDescription.constant("doPartDone", SignalDescription.Type.DO, 0));

    static final String SEAM_DATA = "  PERS seamdata sm1:=[0.5,0.5,[5,0,24,120,0,0,0,0,0],0.5,0,0,0,0,[0,0,0,0,0,0,0,0,0],0,1,[5,0,24,120,0,0,0,0,0],0,0,[0,0,0,0,0,0,0,0,0],0];";
    static final String WELD_ROOT = "  PERS welddata wdRoot:=[6,0,[5,0,24,120,0,0,0,0,0],[0,0,0,0,0,0,0,0,0]];";
    static final String WELD_CAP = "  PERS welddata wdCap:=[8,0,[5,0,26,140,0,0,0,0,0],[0,0,0,0,0,0,0,0,0]];";

    static double[] q(double... v) { return v; }

    /** The module's text: taught targets written by robopro's writer, process code as a cell engineer writes it. */
    static String module() {
        RapidModule.Builder b = RapidModule.builder("WeldCell").pers("tTorch", TORCH).pers("wFixture", FIXTURE)
                .constant("jHome", JointTarget.of(0, 0, 0, 0, 0.5, 0));
        String[][] targets = {
                {"pApproach", "0.1,0.2,0.0,0.15,1.0,0.25"},
                {"pA0", "-0.1,0.25,0.05,0.15,1.0,0.25"}, {"pA1", "-0.1,0.35,0.1,0.15,0.9,0.25"}, {"pA2", "0.0,0.35,0.1,0.15,0.9,0.25"},
                {"pA3", "0.05,0.38,0.12,0.15,0.88,0.25"}, {"pA4", "0.1,0.35,0.1,0.15,0.9,0.25"},
                {"pB0", "0.3,0.25,0.05,0.15,1.0,0.25"}, {"pB1", "0.3,0.35,0.1,0.15,0.9,0.25"}, {"pB2", "0.4,0.35,0.1,0.15,0.9,0.25"}};
        for (String[] t : targets) {
            String[] parts = t[1].split(",");
            double[] qq = new double[6];
            for (int j = 0; j < 6; j++) qq[j] = Double.parseDouble(parts[j]);
            b.constant(t[0], Teach.taught(IRB2000, qq, TORCH, FIXTURE));
        }
        // An inline retract target, written by the writer inside a MoveL.
        String inline = RapidWriter.export(RapidModule.builder("X").pers("tTorch", TORCH).pers("wFixture", FIXTURE)
                .procedure("main", List.of(Move.moveL(Ref.inline(Teach.taught(IRB2000, q(0.35, 0.15, -0.05, 0.15, 1.1, 0.25), TORCH, FIXTURE)),
                        Ref.to("v1000"), Ref.to("z50"), "tTorch", "wFixture"))).build()).text();
        String retract = inline.lines().filter(l -> l.contains("MoveL")).findFirst().orElseThrow();
        String head = RapidWriter.export(b.build()).text();
        head = head.substring(0, head.lastIndexOf("ENDMODULE"));
        return head
                + SEAM_DATA + "\n" + WELD_ROOT + "\n" + WELD_CAP + "\n"
                + "  VAR triggdata gasPre;\n"
                + "  VAR num nParts:=0;\n"
                + "  PROC main()\n"
                + "    MoveAbsJ jHome, v1000, fine, tTorch;\n"
                + "    TPWrite \"Cycle start\";\n"
                + "    MotionSup\\On\\TuneValue:=200;\n"
                + "    SetDO doClamp, 1;\n"
                + "    WaitDI diClamped, 1\\MaxTime:=2;\n"
                + "    WaitDI diOperatorOk, 1;\n"
                + "    WaitUntil DInput(diGasOk) = 1;\n"
                + "    TriggIO gasPre, 0.2\\Time\\DOp:=doGas, 1;\n"
                + "    TriggL pApproach, v1000, gasPre, fine, tTorch\\WObj:=wFixture;\n"
                + "    FOR pass FROM 1 TO 2 DO\n"
                + "      seamA pass;\n"
                + "    ENDFOR\n"
                + "    seamB;\n"
                + "    SetDO doGas, 0;\n"
                + retract + "\n"
                + "    SetDO doClamp, 0;\n"
                + "    WaitDI diClamped, 0;\n"
                + "    PulseDO\\PLength:=0.5, doPartDone;\n"
                + "    Incr nParts;\n"
                + "    MoveAbsJ jHome, v1000, fine, tTorch;\n"
                + "  ENDPROC\n"
                + "  PROC seamA(num pass)\n"
                + "    MoveJ pA0, v1000, z10, tTorch\\WObj:=wFixture;\n"
                + "    MotionSup\\On\\TuneValue:=200;\n"
                + "    IF pass = 1 THEN\n"
                + "      ArcLStart pA1, v100, sm1, wdRoot, fine, tTorch\\WObj:=wFixture;\n"
                + "      ArcL pA2, v100, sm1, wdRoot, z1, tTorch\\WObj:=wFixture;\n"
                + "      ArcCEnd pA3, pA4, v100, sm1, wdRoot, fine, tTorch\\WObj:=wFixture;\n"
                + "    ELSE\n"
                + "      ArcLStart pA1, v100, sm1, wdCap\\Weave:=weave1, fine, tTorch\\WObj:=wFixture;\n"
                + "      ArcL pA2, v100, sm1, wdCap, z1, tTorch\\WObj:=wFixture;\n"
                + "      ArcCEnd pA3, pA4, v100, sm1, wdCap, fine, tTorch\\WObj:=wFixture;\n"
                + "    ENDIF\n"
                + "    MoveL pA0, v500, z10, tTorch\\WObj:=wFixture;\n"
                + "  ENDPROC\n"
                + "  PROC seamB()\n"
                + "    MoveJ pB0, v1000, z10, tTorch\\WObj:=wFixture;\n"
                + "    ArcLStart pB1, v100, sm1, wdRoot, fine, tTorch\\WObj:=wFixture;\n"
                + "    ArcLEnd pB2, v100, sm1, wdRoot, fine, tTorch\\WObj:=wFixture;\n"
                + "    MoveL pB0, v500, z10, tTorch\\WObj:=wFixture;\n"
                + "  ENDPROC\n"
                + "ENDMODULE\n";
    }

    static ParsedModule parsed() { return RapidParser.parseDetailed(module(), "WeldCell.mod"); }

    @Test
    void check_weldModule_passesWithIoTimeLineArcTimeAndLabelledPasses() {
        Simulation sim = MotionInterpreter.of(parsed()).withSignals(SIGNALS).simulate("main");
        CheckReport r = new PathChecker(IRB2000).check(sim, SIGNALS);
        assertFalse(r.hasErrors(), r::format);
        // MotionSup runs twice (main and seamA): reported once, as not simulated, with its line.
        List<Problem> notSim = r.problems().stream().filter(p -> p.kind() == Problem.Kind.NOT_SIMULATED).toList();
        assertEquals(1, notSim.size(), r::format);
        assertTrue(notSim.get(0).message().contains("MotionSup") && notSim.get(0).source().orElseThrow().line() > 0, notSim.toString());
        assertTrue(r.problems().stream().noneMatch(p -> p.kind() == Problem.Kind.IO_WAIT), r::format);

        // Time line: the clamp sensor follows the valve after 0.3 s; the operator's OK is scripted at 2 s.
        double clampAt = event(r, "doClamp", 1).timeS();
        assertEquals(clampAt + 0.3, event(r, "diClamped", 1).timeS(), 1e-12);
        double t = 0;
        for (CheckReport.StepResult s : r.steps()) {
            t += s.durationS();
            if (s.step().contains("WaitDI diOperatorOk")) break;
        }
        assertEquals(2.0, t, 1e-9, "the program waits for the scripted input");
        // Gas on 0.2 s before the end of the TriggL approach.
        double end = 0;
        for (CheckReport.StepResult s : r.steps()) {
            end += s.durationS();
            if (s.step().contains("TriggL pApproach")) break;
        }
        assertEquals(end - 0.2, event(r, "doGas", 1).timeS(), 1e-9);
        // Three seams welded (A twice, B once): three arc starts and ends; the arc burns during the Arc moves after each start.
        assertEquals(3, r.io().stream().filter(e -> e.signal().equals("arc") && e.value() == 1).count());
        assertEquals(3, r.io().stream().filter(e -> e.signal().equals("arc") && e.value() == 0).count());
        double welding = r.steps().stream().filter(s -> s.step().matches(".* (ArcL|ArcCEnd|ArcLEnd) .*")).mapToDouble(CheckReport.StepResult::durationS).sum();
        assertTrue(welding > 0.5, r::format);
        assertEquals(welding, r.arcTimeS(), 1e-9);
        // The pulse to the PLC: on, then off 0.5 s later.
        List<CheckReport.IoEvent> pulse = r.io().stream().filter(e -> e.signal().equals("doPartDone")).toList();
        assertEquals(2, pulse.size());
        assertEquals(0.5, pulse.get(1).timeS() - pulse.get(0).timeS(), 1e-12);

        // Moves in the loop carry the pass and the call: the same statement, two labels.
        List<String> starts = sim.steps().stream().filter(s -> s instanceof MoveStep m && m.instruction().equals("ArcLStart")
                && m.targetName().equals("pA1")).map(ProgramStep::label).toList();
        assertEquals(2, starts.size());
        assertNotEquals(starts.get(0), starts.get(1));
        assertTrue(starts.get(0).startsWith("main#12[pass=1] > main#1 > seamA#3 > ArcLStart pA1") || starts.get(0).contains("[pass=1]"), starts.toString());
        assertTrue(starts.get(1).contains("[pass=2]"), starts.toString());
        assertTrue(r.format().contains("I/O time line"), r::format);
    }

    static CheckReport.IoEvent event(CheckReport r, String signal, double value) {
        return r.io().stream().filter(e -> e.signal().equals(signal) && e.value() == value).findFirst()
                .orElseThrow(() -> new AssertionError("no " + signal + " = " + value + " in\n" + r.format()));
    }

    @Test
    void export_weldModule_rapidcheckerAcceptsAndReimportsToSameTree() {
        String text = module();
        String exported = RapidWriter.export(RapidParser.parse(text, "WeldCell.mod")).text();
        assertEquals(RapidAstParser.parse(text, "a.mod").module(), RapidAstParser.parse(exported, "b.mod").module());
        assertEquals(exported, RapidWriter.export(RapidParser.parse(exported, "WeldCell.mod")).text());
        RapidChecker.assertValid("WeldCell.mod", exported);
    }

    @Test
    void compensate_weldModule_changesOnlyTargetsProcessDataByteForByte() {
        KinematicModel nominal = IRB2000;
        // A calibrated model of a robot of the independent world simulator.
        KinematicModel real = org.robopro.programs.compensation.WorldCalibration.of(5).calibrated();
        String text = module();
        RapidModule m = RapidParser.parse(text, "WeldCell.mod");
        String before = RapidWriter.export(m).text();
        ProgramCompensation.Outcome out = ProgramCompensation.compensate(m, "main", nominal, new Compensator(nominal, real, Pose.IDENTITY, Pose.IDENTITY));
        // Nine named targets (approach, five of seam A, three of seam B) and the inline retract.
        assertEquals(10, out.corrections().size(), out.corrections().toString());
        for (ProgramCompensation.Correction c : out.corrections()) assertEquals(Optional.of(Status.CONVERGED), c.status(), c.toString());
        String after = RapidWriter.export(out.module()).text();
        List<String> a = before.lines().toList(), b = after.lines().toList();
        assertEquals(a.size(), b.size());
        List<String> changed = new ArrayList<>();
        for (int k = 0; k < a.size(); k++) {
            if (a.get(k).equals(b.get(k))) continue;
            changed.add(a.get(k));
            assertTrue(a.get(k).contains("robtarget") || a.get(k).trim().startsWith("MoveL [["), "only targets change: " + a.get(k) + " -> " + b.get(k));
        }
        assertEquals(10, changed.size(), String.join("\n", changed));
        for (String data : List.of(SEAM_DATA, WELD_ROOT, WELD_CAP)) assertTrue(after.contains(data + "\n"), "process data byte for byte: " + data);
        RapidChecker.assertValid("WeldCell.mod", after);
        // The compensated program still checks and runs the same I/O.
        CheckReport r = new PathChecker(nominal).check(MotionInterpreter.of(RapidParser.parseDetailed(after, "WeldCell.mod")).withSignals(SIGNALS)
                .simulate("main"), SIGNALS);
        assertFalse(r.hasErrors(), r::format);
    }

    @Test
    void check_waitForSignalNothingSets_warningWithLineNotAHang() {
        String text = "MODULE W\n  PROC main()\n    SetDO doValve, 1;\n    WaitDI diNever, 1;\n    WaitDI diLate, 1\\MaxTime:=1;\n    WaitUntil bFlag;\n"
                + "    SocketCreate sock;\n  ENDPROC\n  VAR bool bFlag:=FALSE;\nENDMODULE\n";
        List<SignalDescription> table = List.of(new SignalDescription("diLate", SignalDescription.Type.DI, 0,
                List.of(new SignalDescription.Change(3, 1)), "", 0), SignalDescription.constant("doValve", SignalDescription.Type.DO, 0));
        CheckReport r = assertTimeoutPreemptively(Duration.ofSeconds(5), () -> new PathChecker(IRB2000).check(
                MotionInterpreter.of(RapidParser.parseDetailed(text, "W.mod")).withSignals(table).simulate("main"), table));
        assertFalse(r.hasErrors(), r::format);
        Problem never = r.problems().stream().filter(p -> p.message().contains("diNever = 1")).findFirst().orElseThrow(() -> new AssertionError(r.format()));
        assertEquals(Problem.Kind.IO_WAIT, never.kind());
        assertEquals(4, never.source().orElseThrow().line());
        assertTrue(never.message().contains("nothing sets it"), never.message());
        Problem late = r.problems().stream().filter(p -> p.message().contains("MaxTime")).findFirst().orElseThrow(() -> new AssertionError(r.format()));
        assertEquals(5, late.source().orElseThrow().line());
        Problem cond = r.problems().stream().filter(p -> p.message().contains("WaitUntil bFlag")).findFirst().orElseThrow(() -> new AssertionError(r.format()));
        assertEquals(6, cond.source().orElseThrow().line());
        // diNever is not in the table (a notice), SocketCreate is not simulated (a notice): each once, with its line.
        assertTrue(r.problems().stream().anyMatch(p -> p.kind() == Problem.Kind.NOT_SIMULATED && p.message().contains("diNever")), r::format);
        Problem sock = r.problems().stream().filter(p -> p.message().contains("SocketCreate")).findFirst().orElseThrow(() -> new AssertionError(r.format()));
        assertEquals(7, sock.source().orElseThrow().line());
        assertEquals(1.0, r.cycleTimeS(), 1e-12, "only the MaxTime wait counts");
    }
}
