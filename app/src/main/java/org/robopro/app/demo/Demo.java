package org.robopro.app.demo;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.time.temporal.ChronoUnit;
import java.util.ArrayList;
import java.util.List;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.Random;
import org.robopro.calibration.PoseConditions;
import org.robopro.calibration.compensation.Compensator;
import org.robopro.calibration.compensation.TargetCompensator;
import org.robopro.calibration.identification.CalibrationResult;
import org.robopro.calibration.workflow.CalibrationWorkflow;
import org.robopro.calibration.Cancellation;
import org.robopro.calibration.Progress;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.calibration.simulation.PoseSampler;
import org.robopro.comms.CommandInvoker;
import org.robopro.comms.Commands;
import org.robopro.comms.CommsException;
import org.robopro.comms.connection.ControllerConnection;
import org.robopro.comms.ControllerStatus;
import org.robopro.comms.MeasurementCampaign;
import org.robopro.comms.client.ProtocolClient;
import org.robopro.comms.sim.ControllerSim;
import org.robopro.calibration.diagnosis.EffectSpec;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.kinematics.Units;
import org.robopro.models.AtomicFiles;
import org.robopro.models.CellDescription;
import org.robopro.models.CellFile;
import org.robopro.models.JointType;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
import org.robopro.models.Vec3;
import org.robopro.programs.Move;
import org.robopro.programs.compensation.ProgramCompensation;
import org.robopro.programs.RapidModule;
import org.robopro.programs.check.CheckReport;
import org.robopro.programs.check.PathChecker;
import org.robopro.programs.check.Problem;
import org.robopro.programs.RapidWriter;
import org.robopro.programs.sim.MotionInterpreter;
import org.robopro.programs.sim.MoveStep;

/**
 * {@code robopro demo}: the seed paper's whole loop, headless, on a simulated IRB-2000 controller
 * running as its own process. An off-line welding program misses its targets by the
 * robot's real inaccuracy; a measurement campaign through the controller link, calibration and
 * diagnosis model that inaccuracy; the compensated program hits the targets.
 *
 * <p>Target errors are what the controller's laser tracker measures at each target (the program
 * run up to that target), expressed in the robot base frame as the calibration registered the
 * tracker to it, and compared with the programmed TCP position. Each compensated program is
 * evaluated in the registration of the model that compensated it; the nominal program in the
 * geometric calibration's.
 */
public final class Demo {
    /** Tracker noise of the simulated controller, mm per axis. */
    public static final double NOISE_MM = 0.02;

    /** The default concealed effect. */
    public static final String DEFAULT_EFFECT = "gear-periodic";

    /**
     * Effects the demo can conceal ("none": geometric errors only), each with the joints (1-based)
     * the seed picks from when {@code --effect} names no joint: those where the effect is clearly
     * distinct from geometry (joint 3's periodic error or scale barely is) and, for compliance,
     * the joints that carry the arm's weight. A gear's error of harmonics 1-3 on joint 1 only: it
     * turns through a whole turn, where the error is seen to repeat; over joint 2's 200° it is one
     * smooth curve among many, which the diagnosis locates and does not name (docs/diagnosis.md).
     */
    static final Map<String, int[]> CONCEALABLE = concealable();

    /** The names of {@link #CONCEALABLE}, in order. */
    public static final List<String> EFFECTS = List.copyOf(CONCEALABLE.keySet());

    private static Map<String, int[]> concealable() {
        Map<String, int[]> m = new LinkedHashMap<>();
        m.put("gear-periodic", new int[] {1});
        m.put("joint-compliance", new int[] {2, 3});
        m.put("backlash", new int[] {1, 2, 3});
        m.put("joint-scale", new int[] {1, 2});
        m.put("none", new int[0]);
        return java.util.Collections.unmodifiableMap(m);
    }

    /**
     * The simulator's {@code --effect} spec for the demo's {@code --effect}: NAME alone gets a
     * joint drawn from the seed (its size is drawn by the simulator, docs/diagnosis.md "Injecting
     * effects"); NAME:JOINT[=VALUE] is passed as given; "none" gives null.
     *
     * @throws IllegalArgumentException for an effect the demo cannot conceal or a malformed spec
     */
    static String concealedSpec(String effect, long seed) {
        String e = effect.strip().toLowerCase(Locale.ROOT);
        String name = e.split("[:=]", 2)[0];
        if (!CONCEALABLE.containsKey(name))
            throw new IllegalArgumentException("--effect: unknown effect '" + effect + "'; choose one of " + String.join(", ", EFFECTS)
                    + " (optionally NAME:JOINT[=VALUE])");
        if (name.equals("none")) {
            if (!e.equals("none")) throw new IllegalArgumentException("--effect: 'none' takes no joint or value, got '" + effect + "'");
            return null;
        }
        String spec = e.equals(name) ? name + ":" + pick(CONCEALABLE.get(name), new Random(seed * 1_000_003L + 11)) : e;
        int joint = EffectSpec.parse(spec).joint(); // malformed: IllegalArgumentException naming the spec
        if (joint > IRB2000_AXES) throw new IllegalArgumentException("--effect '" + effect + "': the IRB-2000 has joints 1-" + IRB2000_AXES);
        return spec;
    }

    private static final int IRB2000_AXES = 6;

    private static int pick(int[] joints, Random rng) { return joints[rng.nextInt(joints.length)]; }

    /** The true robot's RMS geometric flange error of a seed, mm: uniform in 5-15 mm, the spread of uncalibrated industrial arms the demo shows. */
    static double errorMm(long seed) {
        return 5 + 10 * new Random(seed * 7_919L + 3).nextDouble();
    }

    /**
     * @param seed   seed of the true robot (errors, effect) and of the campaign poses
     * @param effect the concealed effect: a name of {@link #EFFECTS}, optionally NAME:JOINT[=VALUE]
     * @param poses  measured poses of the campaign (every 5th is kept for validation)
     * @param passes welding passes of the program
     * @param out    output folder
     */
    public record Options(long seed, String effect, int poses, int passes, Path out, String conceal) {
        public Options {
            if (poses < 40) throw new IllegalArgumentException("--poses must be at least 40 (the calibration needs more equations than its ~30 unknowns), got " + poses);
            if (passes < 1 || passes > 4) throw new IllegalArgumentException("passes must be 1..4, got " + passes);
            if (conceal == null) concealedSpec(effect, seed); // fails early, naming the choices
            else concealedScenario(conceal, seed);
        }

        /** Concealing {@code effect} (the controller simulator's own effects). */
        public Options(long seed, String effect, int poses, int passes, Path out) { this(seed, effect, poses, passes, out, null); }
    }

    /**
     * Whether the demo can conceal a world scenario: one on the IRB-2000 whose answer does not belong
     * to its own campaign (the demo measures with its own).
     */
    private static boolean concealable(org.robopro.world.Scenario s) { return s.robot().equals("irb2000") && !s.answerNeedsItsCampaign(); }

    /** The groups of world scenarios the demo can conceal with {@code --conceal} (those on the IRB-2000). */
    public static List<String> concealGroups() {
        return org.robopro.world.Scenario.families().stream()
                .filter(f -> org.robopro.world.Scenario.ofFamily(f).stream().anyMatch(Demo::concealable)).toList();
    }

    /**
     * The world scenario the demo conceals for {@code --conceal GROUP}: one of the group's IRB-2000
     * scenarios, drawn from the seed (the independent world simulator's robot, docs/diagnosis-benchmark.md).
     *
     * @throws IllegalArgumentException for an unknown group, naming the choices
     */
    static String concealedScenario(String group, long seed) {
        List<org.robopro.world.Scenario> ss = org.robopro.world.Scenario.ofFamily(group.strip()).stream().filter(Demo::concealable).toList();
        if (ss.isEmpty())
            throw new IllegalArgumentException("--conceal: unknown group '" + group + "'; choose one of " + String.join(", ", concealGroups()));
        return ss.get(new Random(seed * 1_000_003L + 11).nextInt(ss.size())).name();
    }

    /** Per-target errors of one program run, mm. */
    public record Run(String label, String program, double[] errorsMm) {
        public double meanMm() { return java.util.Arrays.stream(errorsMm).average().orElse(Double.NaN); }
        public double maxMm() { return java.util.Arrays.stream(errorsMm).max().orElse(Double.NaN); }
    }

    /**
     * What the demo found: the before/after table and the effects.
     *
     * @param nominal         the off-line program as taught
     * @param calibrated      compensated with the geometric calibration
     * @param diagnosed       compensated with the diagnosed extended model
     * @param concealedEffect what the simulator hid (revealed after the diagnosis)
     * @param namedEffects    what the diagnosis named
     * @param noiseFloorMm    √3 σ of the tracker noise (σ as configured on the simulated tracker)
     * @param elapsedS        wall time of the whole demo
     */
    public record Result(Run nominal, Run calibrated, Run diagnosed, String concealedEffect, List<String> namedEffects,
                         double noiseFloorMm, double elapsedS) { }

    /** A step that failed, with its number. */
    public static final class StepFailure extends Exception {
        private static final long serialVersionUID = 1L;
        public final int step;

        StepFailure(int step, String message, Throwable cause) {
            super("step " + step + ": " + message, cause);
            this.step = step;
        }
    }

    private final Options o;
    private final Console con;
    private final java.util.function.IntConsumer beforeStep;
    private int step;
    private Path work;

    private Demo(Options o, Console con, java.util.function.IntConsumer beforeStep) {
        this.o = o;
        this.con = con;
        this.beforeStep = beforeStep;
    }

    /** Runs the demo, printing as it goes; the simulated controller is stopped in every case. */
    public static Result run(Options o, PrintWriter out, boolean terminal) throws StepFailure {
        return run(o, out, terminal, k -> { });
    }

    /** With a hook called before steps 2-5 (tests make a step fail with it). */
    static Result run(Options o, PrintWriter out, boolean terminal, java.util.function.IntConsumer beforeStep) throws StepFailure {
        return new Demo(o, new Console(out, terminal), beforeStep).run();
    }

    private void begin(int k) {
        step = k;
        beforeStep.accept(k);
    }

    private Result run() throws StepFailure {
        Path out = o.out();
        try {
            prepareOut(out);
        } catch (IOException | IllegalArgumentException e) {
            throw new StepFailure(0, e.getMessage(), e);
        }
        step = 1;
        con.step(1, "Start the simulated IRB-2000 controller");
        ControllerConnection sim;
        Path truthFile;
        try {
            work = Files.createTempDirectory("robopro-demo");
            truthFile = work.resolve("truth.json");
            String spec = o.conceal() == null ? concealedSpec(o.effect(), o.seed()) : null;
            // The tracker's reflector sits at the torch tip (nominally; the real one is off by ~2 mm).
            Vec3 tipMm = WeldProgram.torch(CellFile.shipped("irb2000-welding")).position().times(1e3);
            ControllerSim.Config cfg = ControllerSim.Config.tcp("127.0.0.1:0").withSeed(o.seed()).withErrorMm(errorMm(o.seed()))
                    .withNoiseMm(NOISE_MM).withTargetMm(tipMm).withEffects(spec == null ? List.of() : List.of(spec))
                    .withTruthFile(truthFile);
            if (o.conceal() != null) cfg = cfg.withWorld(concealedScenario(o.conceal(), o.seed()));
            sim = ControllerConnection.startSimulator(cfg, Duration.ofSeconds(60),
                    CommandInvoker.Options.DEFAULT.withReplyTimeout(Duration.ofSeconds(20)));
        } catch (IOException | RuntimeException e) {
            deleteQuietly(work);
            throw new StepFailure(1, e.getMessage(), e);
        }
        try (sim) {
            con.line("%s (robopro controller-sim: its own JVM, open_abb protocol), started in %.1f s", sim.description(), con.stepS());
            if (o.conceal() == null)
                con.line("true robot: seeded geometric errors of 5-15 mm and one concealed effect (--effect %s)", o.effect());
            else
                con.line("true robot: the independent world simulator's, with geometric errors and a concealed %s scenario (--conceal)",
                        o.conceal());
            try {
                return loop(sim, truthFile);
            } finally {
                copyLog(sim, out.resolve("controller.log"));
            }
        } catch (StepFailure e) {
            throw e;
        } catch (CommsException e) {
            throw new StepFailure(step, "controller link: " + e.getMessage(), e);
        } catch (RuntimeException | IOException e) {
            throw new StepFailure(step, e.getClass().getSimpleName() + ": " + e.getMessage(), e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new StepFailure(step, "interrupted", e);
        } finally {
            deleteQuietly(work);
        }
    }

    private static void copyLog(ControllerConnection sim, Path to) {
        try {
            Path log = sim.simulatorLog().orElse(null);
            if (log != null && Files.exists(log)) AtomicFiles.writeString(to, Files.readString(log), true);
        } catch (IOException e) {
            // the log is a convenience; the demo's outcome does not depend on it
        }
    }

    private static void deleteQuietly(Path dir) {
        if (dir == null) return;
        try (var s = Files.list(dir)) {
            for (Path p : s.toList()) Files.deleteIfExists(p);
            Files.deleteIfExists(dir);
        } catch (IOException e) {
            // a temporary folder left behind is harmless
        }
    }

    /** Refuses a folder that holds anything but an earlier demo's output (user data is never overwritten). */
    static void prepareOut(Path out) throws IOException {
        if (Files.exists(out) && !Files.isDirectory(out)) throw new IllegalArgumentException("--out " + out + " is a file, not a folder");
        if (Files.isDirectory(out)) {
            try (var s = Files.list(out)) {
                if (s.findAny().isPresent() && !Files.exists(out.resolve("demo.json")))
                    throw new IllegalArgumentException("--out " + out + " is not empty and holds no earlier demo (no demo.json);"
                            + " choose a new folder");
            }
        }
        Files.createDirectories(out);
    }

    private Result loop(ControllerConnection sim, Path truthFile) throws StepFailure, IOException, InterruptedException {
        Path out = o.out();
        // ------------------------------------------------------------------ 2. model, cell, program
        begin(2);
        con.step(2, "Model, cell and an off-line welding program");
        RobotDescription desc = RobotLibrary.shipped("irb2000");
        KinematicModel nominal = KinematicModel.build(desc);
        int revolute = 0;
        for (int i = 0; i < nominal.dof(); i++) if (!nominal.isPrismatic(i)) revolute++;
        con.line("IRB-2000 kinematic model (seed paper Table 1): %d parameters = 4·%d revolute + 2·%d prismatic + 6",
                nominal.parameters().size(), revolute, nominal.dof() - revolute);
        if (nominal.parameters().size() != nominal.expectedParameterCount())
            throw new StepFailure(2, "the model has " + nominal.parameters().size() + " parameters, expected "
                    + nominal.expectedParameterCount(), null);
        CellDescription cell = CellFile.shipped("irb2000-welding");
        con.line("cell %s: %d objects, tool torch, work object wobj_table", cell.name(), cell.objects().size());
        WeldProgram weld = WeldProgram.teach(cell, nominal, o.passes());
        List<MoveStep> moves = MotionInterpreter.of(weld.module).moves("main");
        List<Integer> targetIdx = new ArrayList<>();
        List<Pose> targets = new ArrayList<>();
        List<String> targetNames = new ArrayList<>();
        for (MoveStep m : moves)
            if (m.kind() != Move.Kind.MOVE_ABS_J) {
                targetIdx.add(m.statementIndex());
                targets.add(m.baseTtcp().orElseThrow());
                targetNames.add(m.targetName());
            }
        con.line("taught with Teach.seam along the T joint of base_plate and web_plate: %d passes, %d targets",
                weld.passes, targets.size());
        CheckReport check = new PathChecker(nominal, PathChecker.Options.DEFAULT.withStart(WeldProgram.homeRad()))
                .check(MotionInterpreter.of(weld.module).run());
        long warnings = check.problems().stream().filter(p -> p.severity() == Problem.Severity.WARNING).count();
        con.line("path check: %d moves, %d errors, %d warnings, cycle time %.1f s", moves.size(),
                check.problems().size() - warnings, warnings, check.cycleTimeS());
        if (check.hasErrors()) throw new StepFailure(2, "the program does not pass the path check:\n" + check.format(), null);
        String rapid = RapidWriter.export(weld.module).text();
        AtomicFiles.writeString(out.resolve(WeldProgram.MODULE + ".mod"), rapid, true);
        con.line("exported RAPID: %s (%d lines)", WeldProgram.MODULE + ".mod", rapid.split("\n").length);

        CommandInvoker inv = sim.invoker();
        ProtocolClient client = sim.client();
        {
            // -------------------------------------------------------------- 3. run the off-line program
            begin(3);
            con.step(3, "Run the off-line program on the controller and measure the targets");
            inv.execute(Commands.ping());
            con.line("connected: %s controller, robopro protocol extension %s", client.robotName(), client.extended() ? "on" : "off");
            List<Vec3> nominalReadings = runAndMeasure(inv, weld.module, "DemoWeld", targetIdx);
            con.line("(the tracker stands somewhere in the cell: its readings become target errors once step 4's calibration"
                    + " has registered it to the robot base)");

            // -------------------------------------------------------------- 4. campaign, calibration, diagnosis, compensation
            begin(4);
            con.step(4, "Measurement campaign, calibration, diagnosis, compensation");
            CalibrationWorkflow.Campaign sets = campaign(inv, nominal, desc, weld);
            CalibrationResult cal = calibrate(desc, sets);
            double floorMm = Math.sqrt(3) * NOISE_MM;
            Run nominalRun = evaluate("nominal (off-line)", "DemoWeld", nominalReadings, targets, cal.instrumentTbase());

            DiagnosisStep.Outcome diag = DiagnosisStep.run(con, desc, sets.train(), sets.validate(), out);

            Pose toolCal = Pose.of(weld.flangeTtcp.rotationRowMajor(), cal.flangeTtool().x(), cal.flangeTtool().y(), cal.flangeTtool().z());
            Compensator geometric = new Compensator(nominal, cal.calibrated(), weld.flangeTtcp, toolCal);
            RapidModule calModule = compensate(weld, nominal, geometric, "DemoWeldCal", out);
            List<Vec3> calReadings = runAndMeasure(inv, calModule, "DemoWeldCal", targetIdx);
            Run calibratedRun = evaluate("geometric calibration", "DemoWeldCal", calReadings, targets, cal.instrumentTbase());

            // The extended model predicts each target under the approach directions the program reaches it with.
            List<int[]> approach = approachDirections(check, moves);
            Run diagnosedRun;
            if (diag.modelsSomething()) {
                TargetCompensator withEffects = (t, tool, seed) -> diag.compensator(nominal, weld.flangeTtcp,
                        new PoseConditions(approach.get(indexOf(targets, t)), Double.NaN, Double.NaN, Double.NaN)).compensate(t, tool, seed);
                RapidModule diagModule = compensate(weld, nominal, withEffects, "DemoWeldDiag", out);
                List<Vec3> diagReadings = runAndMeasure(inv, diagModule, "DemoWeldDiag", targetIdx);
                diagnosedRun = evaluate("with the diagnosed effect", "DemoWeldDiag", diagReadings, targets, diag.instrumentTbase());
            } else {
                // Nothing held on held-out poses: the geometric calibration's program is the diagnosis' too.
                compensate(weld, nominal, geometric, "DemoWeldDiag", out);
                con.line("the diagnosis models nothing beyond the geometry: DemoWeldDiag.mod is the geometric calibration's program");
                diagnosedRun = evaluate("with the diagnosed effect", "DemoWeldDiag", calReadings, targets, cal.instrumentTbase());
            }

            // -------------------------------------------------------------- 5. table and report
            begin(5);
            con.step(5, "Before and after");
            String concealed = DemoReport.concealedEffect(truthFile);
            con.line("concealed effect (revealed now): %s; the diagnosis named: %s%s", concealed,
                    diag.named().isEmpty() ? "nothing" : String.join(", ", diag.named()),
                    diag.located().isEmpty() ? "" : "; located without a known cause: " + String.join(", ", diag.located()));
            Files.copy(truthFile, out.resolve("truth.json"), java.nio.file.StandardCopyOption.REPLACE_EXISTING);
            Result r = new Result(nominalRun, calibratedRun, diagnosedRun, concealed, diag.named(), floorMm, con.elapsedS());
            for (String line : DemoReport.table(r).split("\n")) con.line("%s", line);
            String created = Instant.now().truncatedTo(ChronoUnit.SECONDS).toString();
            AtomicFiles.writeString(out.resolve("demo.json"), DemoReport.json(r), true);
            AtomicFiles.writeString(out.resolve("report.html"),
                    DemoReport.html(r, o, cal, diag, targetNames, created), true);
            con.line("wrote %s: report.html, demo.json, DemoWeld.mod, DemoWeldCal.mod, DemoWeldDiag.mod, measurements.csv,"
                    + " calibration/, diagnosis/", out.toAbsolutePath().normalize());
            con.line("elapsed %.1f s", con.elapsedS());
            return new Result(nominalRun, calibratedRun, diagnosedRun, concealed, diag.named(), floorMm, con.elapsedS());
        }
    }

    /**
     * Downloads and runs the program once (it must end without error), then measures the TCP at
     * every target by running the program up to that target and reading the tracker.
     */
    private List<Vec3> runAndMeasure(CommandInvoker inv, RapidModule module, String name, List<Integer> targetIdx)
            throws StepFailure, InterruptedException {
        String text = RapidWriter.export(module).text();
        var info = inv.execute(Commands.downloadProgram(name, text.getBytes(StandardCharsets.UTF_8)));
        double clock0 = inv.execute(Commands.readStatus()).clockS();
        ControllerStatus st = runToEnd(inv, name);
        con.line("downloaded %s (%d bytes, CRC verified) and ran it: %s after %.1f s of robot time", name, info.length(),
                st.state(), st.clockS() - clock0);
        List<Vec3> readings = new ArrayList<>();
        Console.Bar bar = con.bar("targets measured", targetIdx.size());
        String stepName = name + "To";
        for (int k = 0; k < targetIdx.size(); k++) {
            String part = RapidWriter.export(WeldProgram.truncated(module, targetIdx.get(k))).text();
            inv.execute(Commands.downloadProgram(stepName, part.getBytes(StandardCharsets.UTF_8)));
            runToEnd(inv, stepName);
            readings.add(inv.execute(Commands.measure()));
            bar.update(k + 1);
        }
        bar.done("tracker reading at each of the %d targets (program run up to the target)", readings.size());
        return readings;
    }

    private ControllerStatus runToEnd(CommandInvoker inv, String name) throws StepFailure, InterruptedException {
        inv.execute(Commands.startProgram(name));
        ControllerStatus st;
        long deadline = System.nanoTime() + 60_000_000_000L;
        do {
            Thread.sleep(2);
            st = inv.execute(Commands.readStatus());
            if (System.nanoTime() > deadline) throw new StepFailure(step, "program " + name + " still running after 60 s", null);
        } while (st.state() == ControllerStatus.State.RUNNING);
        if (st.state() == ControllerStatus.State.ERROR)
            throw new StepFailure(step, "program " + name + " stopped with an error: " + st.lastErrorMessage(), null);
        return st;
    }

    /**
     * The campaign through the link: sampled poses, tracker on the torch TCP; written to
     * measurements.csv with the workflow's hold-out rule in its set column (every 5th pose
     * validates), and read back from there as every front end reads a campaign.
     */
    private CalibrationWorkflow.Campaign campaign(CommandInvoker inv, KinematicModel nominal, RobotDescription desc, WeldProgram weld)
            throws IOException {
        List<double[]> poses = new PoseSampler(nominal).sample(o.poses(), new Random(o.seed() * 31 + 7));
        inv.execute(Commands.setWorkObject(Pose.IDENTITY));
        inv.execute(Commands.setTool(weld.flangeTtcp));
        Console.Bar bar = con.bar("poses measured", poses.size());
        long t0 = System.nanoTime();
        MeasurementSet all = MeasurementCampaign.run(inv, poses, desc.name(), String.format(Locale.ROOT,
                "simulated laser tracker, reflector at the torch tip, sigma %.3f mm", NOISE_MM), bar::update);
        List<Measurement> split = new ArrayList<>();
        for (int i = 0; i < all.size(); i++)
            split.add(all.rows().get(i).withSet(CalibrationWorkflow.heldOut(i, HOLDOUT) ? Measurement.Split.VALIDATE : Measurement.Split.TRAIN));
        List<JointType> types = desc.joints().stream().map(j -> j.type()).toList();
        Path file = o.out().resolve("measurements.csv");
        MeasurementCampaign.write(all.withRows(split), types, file, true);
        bar.done("campaign: %d poses moved to and measured through the link in %.1f s -> measurements.csv", all.size(),
                (System.nanoTime() - t0) / 1e9);
        return CalibrationWorkflow.load(desc, file, null, null);
    }

    /** Fraction of the campaign held out for validation. */
    static final double HOLDOUT = 0.2;

    /** The calibration workflow with its default settings, as {@code robopro calibrate} runs it, into calibration/. */
    private CalibrationResult calibrate(RobotDescription desc, CalibrationWorkflow.Campaign c) throws IOException {
        CalibrationWorkflow.Outcome oc = CalibrationWorkflow.run(desc, c, CalibrationWorkflow.Settings.defaults(),
                Instant.now().truncatedTo(ChronoUnit.SECONDS).toString(), Cancellation.NONE, Progress.NONE);
        oc.write(o.out().resolve("calibration"), true);
        CalibrationResult r = oc.result();
        con.line("calibrated (%d training poses): RMS %.3f mm -> %.4f mm; validation (%d poses) %.3f mm -> %.4f mm",
                r.train().size(), Units.mToMm(r.nominalTrainRmsM()), Units.mToMm(r.trainRmsM()),
                r.validate().size(), Units.mToMm(r.nominalValidateRmsM()), Units.mToMm(r.validateRmsM()));
        for (String w : oc.warnings()) con.line("warning: %s", w);
        con.line("tracker noise floor √3·σ = %.4f mm; what is left above it is not geometry (see the diagnosis)",
                Math.sqrt(3) * NOISE_MM);
        return r;
    }

    /** Compensates every target of the program (Fig. 5) and writes the module. */
    private RapidModule compensate(WeldProgram weld, KinematicModel nominal, TargetCompensator compensator, String name, Path out)
            throws IOException {
        ProgramCompensation.Outcome oc = ProgramCompensation.compensate(weld.module, "main", nominal, compensator);
        double maxShift = 0;
        for (ProgramCompensation.Correction k : oc.corrections()) {
            if (!k.ok()) throw new IllegalStateException("compensation of " + k);
            maxShift = Math.max(maxShift, k.shiftM());
        }
        String text = RapidWriter.export(oc.module()).text();
        AtomicFiles.writeString(out.resolve(name + ".mod"), text, true);
        con.line("compensated %d targets (largest shift %.2f mm) -> %s.mod", oc.corrections().size(), Units.mToMm(maxShift), name);
        return oc.module();
    }

    /**
     * Sign of each joint's last motion on arrival at each target (robtarget moves in program
     * order), from the path check's joint values at the end of every move; 0 before a joint has moved.
     */
    static List<int[]> approachDirections(CheckReport check, List<MoveStep> moves) {
        List<int[]> out = new ArrayList<>();
        double[] prev = null;
        int[] dir = null;
        for (int i = 0; i < moves.size(); i++) {
            double[] q = check.steps().get(i).qEnd();
            if (dir == null) dir = new int[q.length];
            if (prev != null)
                for (int j = 0; j < q.length; j++) if (Math.abs(q[j] - prev[j]) > 1e-9) dir[j] = q[j] > prev[j] ? 1 : -1;
            prev = q;
            if (moves.get(i).kind() != Move.Kind.MOVE_ABS_J) out.add(dir.clone());
        }
        return out;
    }

    private static int indexOf(List<Pose> targets, Pose t) {
        for (int k = 0; k < targets.size(); k++)
            if (targets.get(k).distanceTo(t) < 1e-9 && targets.get(k).angleTo(t) < 1e-9) return k;
        throw new IllegalStateException("not a target of the program: " + t);
    }

    /** Target errors: tracker readings taken to the base frame by a registration, against the programmed TCP positions. */
    private Run evaluate(String label, String program, List<Vec3> readings, List<Pose> targets, Pose instrumentTbase) {
        Pose baseTinstrument = instrumentTbase.inverse();
        double[] e = new double[readings.size()];
        for (int k = 0; k < e.length; k++) e[k] = Units.mToMm(baseTinstrument.apply(readings.get(k)).minus(targets.get(k).position()).norm());
        Run r = new Run(label, program, e);
        con.line("%s: target error mean %.3f mm, max %.3f mm", label, r.meanMm(), r.maxMm());
        return r;
    }
}
