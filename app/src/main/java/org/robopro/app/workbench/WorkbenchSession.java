package org.robopro.app.workbench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Consumer;
import java.util.logging.Logger;
import org.robopro.app.workbench.model.CellObject;
import org.robopro.app.workbench.model.DefaultCell;
import org.robopro.app.workbench.model.Instruction;
import org.robopro.app.workbench.model.ProgramModule;
import org.robopro.app.workbench.model.ProgramRun;
import org.robopro.app.workbench.model.ProjectData;
import org.robopro.app.workbench.model.Target;
import org.robopro.app.workbench.model.PathChecker;
import org.robopro.app.workbench.model.WorkbenchModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.AtomicFiles;
import org.robopro.models.TextFiles;
import org.robopro.models.Vec3;
import org.robopro.programs.RapidModule;
import org.robopro.programs.ParsedModule;
import org.robopro.programs.rapid.RapidExport;
import org.robopro.programs.RapidParser;
import org.robopro.programs.RapidWriter;

/**
 * The workbench's headless session: the cell model and every operation the menus, buttons,
 * the command line and tests call (jog, teach, RAPID import and export, compensation, the
 * controller link, calibration and diagnosis, cell edits, project files, the log). It knows
 * nothing of Swing or the 3D view, so its operations are tested without a display; the window
 * ({@code ui.WorkbenchWindow}) is a view over it. Mutations happen on the UI thread (the
 * caller's thread when there is no window; see {@link #setUiThread}). Lengths in metres and
 * angles in radians unless a name says mm/deg.
 */
public final class WorkbenchSession implements AutoCloseable {
    private static final Logger LOG = Logger.getLogger(WorkbenchSession.class.getName());

    /** Edits closer together than this cost one path check. */
    public static final long PATH_CHECK_DEBOUNCE_MS = 120;

    private final WorkbenchModel model;
    private final PathChecker pathChecker;
    private final LiveClearance clearance;
    private final List<String> log = new ArrayList<>();
    private final List<Consumer<String>> logListeners = new CopyOnWriteArrayList<>();
    private volatile Path projectFile;
    private volatile Consumer<Runnable> uiThread = Runnable::run;
    private ProjectStore.Autosave autosave;

    /** A session on a project's contents; {@code projectFile} is where it was read from (null: untitled). */
    public WorkbenchSession(ProjectData data, Path projectFile) {
        this.model = new WorkbenchModel(data.robotRef(), data.robot());
        model.load(data);
        if (data.q() == null) model.setQ(startPose(data));
        model.markSaved();
        this.projectFile = projectFile;
        this.clearance = new LiveClearance(model);
        model.setClearance(clearance::checker);
        this.pathChecker = new PathChecker(model, PATH_CHECK_DEBOUNCE_MS);
    }

    /** Where a project without saved joint values puts the robot: the ready pose of the IRB-2000 cell, else all zero. */
    private static double[] startPose(ProjectData data) {
        return DefaultCell.readyPose().length == data.robot().dof() ? DefaultCell.readyPose() : new double[data.robot().dof()];
    }

    /** A session on the given project, or on the IRB-2000 welding cell when {@code project} is null. */
    public static WorkbenchSession open(Path project) throws IOException {
        return new WorkbenchSession(project == null ? DefaultCell.irb2000Welding() : ProjectStore.read(project), project);
    }

    /**
     * Where model mutations made by background work (controller upload) run, and where a
     * procedure chooser is asked: the window passes its Swing thread. Default: the calling thread.
     */
    public void setUiThread(Consumer<Runnable> runAndWait) { this.uiThread = runAndWait; }

    /** Writes the model to its autosave file every {@code periodMs} while it has unsaved changes. */
    public void startAutosave(int periodMs) {
        if (autosave != null) return;
        autosave = new ProjectStore.Autosave(this::autosaveTarget, model, periodMs);
        autosave.start();
    }

    public WorkbenchModel model() { return model; }
    /** The background path check of the program (debounced; listeners hand results to their own thread). */
    public PathChecker pathChecker() { return pathChecker; }
    /** Collision and clearance of the robot where it stands (the live view while jogging). */
    public LiveClearance clearance() { return clearance; }
    public Optional<Path> projectFile() { return Optional.ofNullable(projectFile); }
    public synchronized List<String> log() { return List.copyOf(log); }

    /** Told (on the logging thread) about every log line. */
    public void addLogListener(Consumer<String> l) { logListeners.add(l); }

    /** Adds a line to the log. */
    public void log(String line) {
        synchronized (this) { log.add(line); }
        LOG.fine(line);
        for (Consumer<String> l : logListeners) l.accept(line);
    }

    /**
     * Waits until the background path check has caught up with the model (for tests and
     * screenshots; interactive use never waits).
     */
    public PathChecker.Result awaitPathCheck() throws InterruptedException {
        var r = pathChecker.awaitCurrent(60_000);
        if (r == null) throw new IllegalStateException("the path check did not finish within 60 s");
        return r;
    }

    /** A mesh or robot file path as written in the project: relative ones are beside the project file. */
    public Path resolvePath(String path) {
        Path p = Path.of(path);
        if (p.isAbsolute() || projectFile == null) return p;
        return projectFile.toAbsolutePath().getParent().resolve(p);
    }

    private Path autosaveTarget() { return ProjectStore.autosavePath(projectFile); }

    // ---- jogging -----------------------------------------------------------------------------

    /** Sets joint {@code i} (0-based) to {@code deg} degrees. */
    public void jogJointDeg(int i, double deg) {
        double[] q = model.q();
        q[i] = Math.toRadians(deg);
        model.setQ(q);
    }

    /** The frame a Cartesian jog acts in. */
    public enum JogFrame { WORLD, BASE, TOOL }

    /**
     * Moves the TCP by (dx, dy, dz) metres and rotates it by (rx, ry, rz) radians about the axes of
     * {@code frame} (rotation about the TCP), keeping the configuration (IK from the current joints).
     * Returns false (and leaves the robot where it is) when the pose cannot be reached within the limits.
     */
    public boolean jogCartesian(JogFrame frame, double dx, double dy, double dz, double rx, double ry, double rz) {
        Pose cur = model.worldTtcp();
        Pose axes = switch (frame) {
            case WORLD -> Pose.IDENTITY;
            case BASE -> model.worldTbase();
            case TOOL -> cur;
        };
        Vec3 d = axes.rotate(new Vec3(dx, dy, dz));
        Vec3 r = axes.rotate(new Vec3(rx, ry, rz));
        Pose rot = r.norm() < 1e-12 ? Pose.IDENTITY : Pose.rotAxis(r, r.norm());
        Pose curRot = Pose.translation(cur.position().times(-1)).times(cur);
        Pose next = Pose.translation(cur.position().plus(d)).times(rot).times(curRot);
        Optional<double[]> q = model.solveTcp(next, model.q());
        if (q.isEmpty() || !model.kinematics().withinLimits(q.get())) {
            log("Jog refused: the pose is " + (q.isEmpty() ? "out of reach" : "outside the joint limits"));
            return false;
        }
        model.setQ(q.get());
        return true;
    }

    // ---- teaching and programs ---------------------------------------------------------------

    /**
     * Teaches the current TCP pose as a new target in the active work object and returns it
     * (the programs module's {@code Teach.taught}: forward kinematics and confdata of the joints).
     */
    public Target teach() {
        String name = model.newTargetName();
        double[] q = model.q();
        Target t = new Target(name, model.worldTtcp(), q, model.kinematics().confOf(q), model.activeWorkObject());
        model.edit("Teach " + name, () -> model.putTarget(t));
        log(String.format(java.util.Locale.ROOT, "Taught %s at (%.1f, %.1f, %.1f) mm in %s", name,
                t.worldTtcp().x() * 1000, t.worldTtcp().y() * 1000, t.worldTtcp().z() * 1000, t.wobj()));
        return t;
    }

    public void addMove(Instruction.Type type, String target, double speedMmPerS, double zoneMm) {
        addMove(type, target, null, speedMmPerS, zoneMm);
    }

    /** Appends a move; {@code via} is MoveC's circle point (null for MoveJ/MoveL). */
    public void addMove(Instruction.Type type, String target, String via, double speedMmPerS, double zoneMm) {
        Instruction i = new Instruction(type, target, speedMmPerS, zoneMm, via);
        model.edit("Add " + type.rapid() + " " + target, () -> model.addInstruction(i));
    }

    /** Checks the program with the programs module's path checker and logs every problem by instruction and target. */
    public ProgramRun checkProgram() {
        ProgramRun p = model.programRun();
        for (String line : p.problemLines()) log("Check: " + line);
        if (p.report() != null) log(String.format(java.util.Locale.ROOT, "Check: %s, %d instructions, cycle time %.2f s (%s)",
                p.ok() ? "program OK" : "program has errors", p.steps().size(), p.report().cycleTimeS(), p.report().assumptions()));
        else log(p.ok() ? "Check: program OK (reachability only: no kinematics-module model)" : "Check: program has errors");
        return p;
    }

    /** A RAPID module name from a file name ("weld-1.mod" -> "weld_1"). */
    /** The RAPID module name an export to {@code file} gets: the file's name without extension, as a RAPID name. */
    public static String moduleName(Path file) {
        String name = file.getFileName().toString().replaceFirst("\\.[^.]*$", "").replaceAll("[^A-Za-z0-9_]", "_");
        return name.isEmpty() || !Character.isLetter(name.charAt(0)) ? "M" + name : name;
    }

    /**
     * Writes the program as a RAPID module with the programs module's writer: targets in their
     * work objects, confdata of the IK solutions used (refuses to overwrite unless asked).
     */
    public String exportRapid(Path file, boolean overwrite) throws IOException {
        RapidModule module = ProgramModule.toRapid(model, moduleName(file));
        var cal = calibratedModel;
        var ext = extendedModel;
        var nominal = model.kinematics().kinematicModel();
        boolean compensated = cal != null && nominal.isPresent();
        if (compensated) {
            var out = org.robopro.programs.compensation.ProgramCompensation.compensate(module, "main", nominal.get(),
                    compensator(nominal.get(), cal, ext, compensationConditions));
            module = out.module();
            double max = 0;
            for (var c : out.corrections()) {
                max = Math.max(max, c.shiftM());
                if (!c.ok()) log("Compensation: " + c);
            }
            log(String.format(java.util.Locale.ROOT, "Compensated %d targets with the %s (largest shift %.3f mm)",
                    out.corrections().size(), ext != null && ext.hasEffects() ? "extended model (geometry and effects)" : "calibrated model",
                    max * 1e3));
        }
        // A compensated program through the writer (every target rewritten at file precision).
        RapidExport ex = compensated ? RapidWriter.export(module) : ProgramModule.write(model, module);
        AtomicFiles.writeString(file, ex.text(), overwrite);
        for (RapidExport.Rename r : ex.renames()) log("RAPID export renamed " + r);
        log("Exported RAPID module " + module.name() + " to " + file);
        return ex.text();
    }

    /**
     * Reads a RAPID module (programs module's parser and interpreter) and replaces the targets
     * and program with its {@code main}. A file with errors throws an InputException naming the
     * line and column, and the open program is left as it was.
     */
    public ProgramModule.Imported importRapid(Path file) throws IOException {
        String text = TextFiles.readUtf8(file);
        ParsedModule parsed = RapidParser.parseDetailed(text, file.toString());
        ProgramModule.Imported imp = ProgramModule.fromRapid(parsed, model, "main");
        model.edit("Import RAPID " + imp.moduleName(), () -> model.replaceProgram(imp));
        for (String n : imp.notes()) log("RAPID import: " + n);
        log(String.format(java.util.Locale.ROOT, "Imported RAPID module %s from %s: %d targets, %d instructions",
                imp.moduleName(), file, imp.targets().size(), imp.program().size()));
        return imp;
    }

    // ---- controller link -----------------------------------------------------------------------

    private volatile ControllerSession controller;
    private final java.util.concurrent.ExecutorService background = java.util.concurrent.Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "workbench-controller");
        t.setDaemon(true);
        return t;
    });
    private final List<Runnable> controllerListeners = new java.util.concurrent.CopyOnWriteArrayList<>();

    public Optional<ControllerSession> controller() { return Optional.ofNullable(controller); }

    /** Told (on any thread) when the controller link opens or closes. */
    public void addControllerListener(Runnable r) { controllerListeners.add(r); }

    /**
     * Connects off the UI thread: to {@code address} ("host:port" or a serial device), or with
     * null/blank to a simulated controller started for the cell's robot.
     */
    public java.util.concurrent.CompletableFuture<ControllerSession> connectController(String address) {
        return java.util.concurrent.CompletableFuture.supplyAsync(() -> {
            disconnectNow();
            try {
                ControllerSession s = address == null || address.isBlank()
                        ? ControllerSession.startSimulator(model.robotRef(), 30_000, this::log)
                        : ControllerSession.connect(address.trim(), this::log);
                controller = s;
                log("Connected to " + s.description() + (s.robotName().isEmpty() ? "" : " (robot " + s.robotName() + ")"));
                return s;
            } catch (IOException e) {
                throw new java.util.concurrent.CompletionException(e);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new java.util.concurrent.CompletionException(e);
            } finally {
                controllerListeners.forEach(Runnable::run);
            }
        }, background).whenComplete((s, e) -> { if (e != null) log("Connect failed: " + rootMessage(e)); });
    }

    private void disconnectNow() {
        ControllerSession s = controller;
        controller = null;
        if (s != null) {
            s.close();
            model.setGhostQ(null);
            log("Disconnected from " + s.description());
        }
    }

    public java.util.concurrent.CompletableFuture<Void> disconnectController() {
        return java.util.concurrent.CompletableFuture.runAsync(() -> {
            disconnectNow();
            controllerListeners.forEach(Runnable::run);
        }, background);
    }

    private ControllerSession needController() {
        ControllerSession s = controller;
        if (s == null) throw new IllegalStateException("not connected to a controller (Controller > Connect)");
        return s;
    }

    static String rootMessage(Throwable e) {
        while ((e instanceof java.util.concurrent.CompletionException || e instanceof java.util.concurrent.ExecutionException) && e.getCause() != null)
            e = e.getCause();
        return e.getMessage() == null ? e.toString() : e.getMessage();
    }

    /** The RAPID program name used on the controller: the project's name, or "Workbench". */
    public String controllerProgramName() {
        return projectFile == null ? "Workbench" : moduleName(Path.of(projectFile.getFileName().toString().replaceFirst("\\.robopro\\.json$", ".mod")));
    }

    /** Downloads the program (RAPID written by the programs module) to the controller. */
    public java.util.concurrent.CompletableFuture<org.robopro.comms.ProgramInfo> downloadProgram() {
        ControllerSession s = needController();
        String name = controllerProgramName();
        String text = RapidWriter.export(ProgramModule.toRapid(model, name)).text();
        return s.download(name, text).whenComplete((info, e) -> log(e == null
                ? String.format(java.util.Locale.ROOT, "Downloaded %s: %d bytes, CRC-32 %08x", info.name(), info.length(), info.crc32())
                : "Download failed: " + rootMessage(e)));
    }

    /** Uploads program {@code name} and makes its {@code main} (or its only procedure) the workbench program. */
    public java.util.concurrent.CompletableFuture<ProgramModule.Imported> uploadProgram(String name) {
        return uploadProgram(name, WorkbenchSession::defaultProcedure);
    }

    /** "main" when the module has it, else its first procedure. */
    public static String defaultProcedure(List<String> procedures) {
        for (String p : procedures) if (p.equalsIgnoreCase("main")) return p;
        return procedures.isEmpty() ? "main" : procedures.get(0);
    }

    /** The procedures of a RAPID module, in file order. */
    public static List<String> procedures(ParsedModule parsed) {
        return parsed.module().procedures().stream().map(org.robopro.programs.Procedure::name).toList();
    }

    /**
     * Uploads program {@code name} and makes the procedure {@code chooseProc} picks from the
     * module's procedures (called on the UI thread; null cancels and changes nothing) the
     * workbench program ({@link ProgramModule#fromRapid}: its motions editable, its other
     * statements kept as written; calls and loops run, checked and drawn through the module).
     */
    public java.util.concurrent.CompletableFuture<ProgramModule.Imported> uploadProgram(String name,
            java.util.function.Function<List<String>, String> chooseProc) {
        ControllerSession s = needController();
        // Off the invoker's thread: choosing may wait for the user.
        return s.upload(name).thenApplyAsync(text -> {
            ParsedModule parsed = RapidParser.parseDetailed(text, "controller:" + name);
            List<String> procs = procedures(parsed);
            AtomicReference<String> proc = new AtomicReference<>();
            uiThread.accept(() -> proc.set(procs.size() == 1 ? procs.get(0) : chooseProc.apply(procs)));
            if (proc.get() == null) throw new java.util.concurrent.CancellationException("no procedure chosen");
            ProgramModule.Imported imp = ProgramModule.fromRapid(parsed, model, proc.get());
            uiThread.accept(() -> model.edit("Upload " + name, () -> model.replaceProgram(imp)));
            for (String n : imp.notes()) log("Upload: " + n);
            log("Uploaded " + name + " (" + text.length() + " bytes), PROC " + proc.get() + ": " + imp.targets().size() + " targets, "
                    + imp.program().size() + " instructions");
            return imp;
        }, background).whenComplete((imp, e) -> { if (e != null) log("Upload failed: " + rootMessage(e)); });
    }

    /** The programs stored on the controller. */
    public java.util.concurrent.CompletableFuture<List<org.robopro.comms.ProgramInfo>> controllerPrograms() {
        return needController().programs();
    }

    /**
     * Runs the downloaded program on the controller, waits (polling its status) until it
     * stops, and shows where the real robot ended as the ghost.
     */
    public java.util.concurrent.CompletableFuture<org.robopro.comms.ControllerStatus> runProgram() {
        ControllerSession s = needController();
        String name = controllerProgramName();
        return s.run(name).thenApplyAsync(v -> {
            log("Running " + name + " on the controller");
            long end = System.currentTimeMillis() + 120_000;
            org.robopro.comms.ControllerStatus st = s.status().join();
            while (st.state() == org.robopro.comms.ControllerStatus.State.RUNNING && System.currentTimeMillis() < end) {
                try {
                    Thread.sleep(100);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    break;
                }
                st = s.status().join();
            }
            log("Controller after the run: " + describe(st));
            model.setGhostQ(s.readJoints().join());
            return st;
        }, background).whenComplete((st, e) -> { if (e != null) log("Run failed: " + rootMessage(e)); });
    }

    /** A controller status in words for the log ("idle, program Weld, no errors, clock 12.40 s"). */
    static String describe(org.robopro.comms.ControllerStatus st) {
        StringBuilder b = new StringBuilder(st.state().name().toLowerCase(java.util.Locale.ROOT));
        if (st.program() != null && !st.program().isBlank()) b.append(", program ").append(st.program());
        b.append(st.errorCount() == 0 ? ", no errors" : ", " + st.errorCount() + (st.errorCount() == 1 ? " error" : " errors"));
        if (st.errorCount() > 0 && st.lastErrorMessage() != null && !st.lastErrorMessage().isBlank())
            b.append(" (last: ").append(st.lastErrorMessage()).append(st.lastError() == null ? "" : ", code " + st.lastError()).append(')');
        return b.append(String.format(java.util.Locale.ROOT, ", clock %.2f s", st.clockS())).toString();
    }

    /** Reads the real robot's joints and shows them as the ghost robot. */
    public java.util.concurrent.CompletableFuture<double[]> readRobotPosition() {
        return needController().readJoints().whenComplete((q, e) -> {
            if (e != null) { log("Read position failed: " + rootMessage(e)); return; }
            model.setGhostQ(q);
            StringBuilder b = new StringBuilder("Real robot joints (deg):");
            for (double v : q) b.append(String.format(java.util.Locale.ROOT, " %.3f", Math.toDegrees(v)));
            log(b.toString());
        });
    }

    // ---- calibration ---------------------------------------------------------------------------

    private volatile org.robopro.kinematics.KinematicModel calibratedModel;
    private volatile org.robopro.calibration.diagnosis.ExtendedModel extendedModel;
    private volatile org.robopro.calibration.PoseConditions compensationConditions = org.robopro.calibration.PoseConditions.NONE;

    /** The applied extended model (geometry plus the effects a diagnosis found), if any. */
    public Optional<org.robopro.calibration.diagnosis.ExtendedModel> extendedModel() { return Optional.ofNullable(extendedModel); }

    /**
     * Conditions the program will run under, for compensation with an extended model
     * (temperature °C, payload kg; NaN = unknown, which makes that effect contribute nothing).
     */
    public void setCompensationConditions(double tempC, double payloadKg) {
        compensationConditions = new org.robopro.calibration.PoseConditions(null, Double.NaN, tempC, payloadKg);
    }

    /** The calibration module's Compensator on the extended model when it has effects, else on the calibrated geometry. */
    static org.robopro.calibration.compensation.Compensator compensator(org.robopro.kinematics.KinematicModel nominal,
            org.robopro.kinematics.KinematicModel cal, org.robopro.calibration.diagnosis.ExtendedModel ext,
            org.robopro.calibration.PoseConditions cond) {
        var tool = org.robopro.kinematics.Pose.IDENTITY; // the program's tools are given per target
        return ext != null && ext.hasEffects() ? new org.robopro.calibration.compensation.Compensator(nominal, ext, tool, tool, cond)
                : new org.robopro.calibration.compensation.Compensator(nominal, cal, tool, tool);
    }

    /** The applied calibrated model (RAPID export is compensated with it), if any. */
    public Optional<org.robopro.kinematics.KinematicModel> calibratedModel() { return Optional.ofNullable(calibratedModel); }

    /**
     * Training and validation sets of a measurement file, split by the calibration workflow: its
     * set column, else every 5th pose held out.
     */
    public record Measurements(org.robopro.calibration.workflow.CalibrationWorkflow.Campaign campaign) {
        public Path file() { return campaign.file(); }
        public org.robopro.calibration.measurement.MeasurementSet train() { return campaign.train(); }
        public org.robopro.calibration.measurement.MeasurementSet validate() { return campaign.validate(); }
    }

    /** Fraction of the poses held out for validation when the file has no set column. */
    public static final double HOLDOUT = 0.2;

    public Measurements loadMeasurements(Path file) throws IOException {
        return new Measurements(org.robopro.calibration.workflow.CalibrationWorkflow.load(model.robot(), file, null, HOLDOUT));
    }

    private volatile org.robopro.calibration.workflow.CalibrationWorkflow.Outcome lastCalibration;

    /** The last calibration's outcome (figures, warnings, files), if any. */
    public Optional<org.robopro.calibration.workflow.CalibrationWorkflow.Outcome> lastCalibration() { return Optional.ofNullable(lastCalibration); }

    /**
     * Calibrates the cell's robot from measurements with the calibration workflow's default
     * settings, as {@code robopro calibrate} does (blocking: run it off the UI thread).
     * Throws CancellationException when {@code cancel} fires.
     */
    public org.robopro.calibration.identification.CalibrationResult calibrate(Measurements m, org.robopro.calibration.Cancellation cancel,
                                                                            org.robopro.calibration.Progress progress) {
        var oc = org.robopro.calibration.workflow.CalibrationWorkflow.run(model.robot(), m.campaign(),
                org.robopro.calibration.workflow.CalibrationWorkflow.Settings.defaults(),
                java.time.Instant.now().truncatedTo(java.time.temporal.ChronoUnit.SECONDS).toString(), cancel, progress);
        lastCalibration = oc;
        var r = oc.result();
        log(String.format(java.util.Locale.ROOT, "Calibrated from %d poses: RMS %.4f mm -> %.4f mm%s", r.train().size(),
                r.nominalTrainRmsM() * 1e3, r.trainRmsM() * 1e3, m.validate() == null ? ""
                        : String.format(java.util.Locale.ROOT, "; validation %.4f mm -> %.4f mm", r.nominalValidateRmsM() * 1e3, r.validateRmsM() * 1e3)));
        for (String w : oc.warnings()) log("Warning: " + w);
        return r;
    }

    /**
     * Applies a calibration: writes the calibrated robot file (refusing to replace one unless
     * {@code overwrite}), records it as the project's calibration reference and compensates RAPID
     * exports with it from now on (seed paper Fig. 5; the controller keeps the nominal model).
     */
    public void applyCalibration(org.robopro.calibration.identification.CalibrationResult r, Path robotFile, String source, boolean overwrite) {
        var oc = lastCalibration;
        if (oc == null || oc.result() != r) throw new IllegalStateException("not the last calibration's result");
        org.robopro.models.RobotLibrary.write(oc.calibrated(), robotFile, overwrite);
        changeApplied("Apply calibration " + robotFile.getFileName(), new Applied(r.calibrated(), null, robotFile.toString()));
        log("Applied the calibrated model " + robotFile + ": RAPID exports are compensated with it");
    }

    /**
     * Diagnoses the cell's robot from measurements (docs/diagnosis.md: geometric calibration, then the
     * non-geometric effects one by one; blocking: run it off the UI thread). Throws
     * CancellationException when {@code cancel} fires.
     */
    public org.robopro.calibration.diagnosis.Diagnosis diagnose(Measurements m, org.robopro.calibration.Cancellation cancel,
                                                               org.robopro.calibration.Progress progress) {
        var o = org.robopro.calibration.diagnosis.Diagnoser.Options.defaults().withCancel(cancel).withProgress(progress);
        var d = org.robopro.calibration.diagnosis.Diagnoser.diagnose(model.robot(), m.train(), m.validate(), o);
        StringBuilder found = new StringBuilder();
        for (var f : d.effects()) found.append(found.length() == 0 ? "" : ", ").append(f.effect().label());
        log(String.format(java.util.Locale.ROOT, "Diagnosed from %d poses: geometric RMS %.4f mm -> %.4f mm with %s", m.train().size(),
                d.geometricTrainRmsM() * 1e3, d.finalTrainRmsM() * 1e3, found.length() == 0 ? "no effect found" : found));
        return d;
    }

    /**
     * Applies a diagnosis: writes its extended model (identified geometry plus an effects
     * section, docs/robot-file.md; an existing file only when {@code overwrite}), records it as
     * the project's calibration reference, and compensates RAPID exports with the calibration
     * module's Compensator on the extended model from now on.
     */
    public void applyDiagnosis(org.robopro.calibration.diagnosis.Diagnosis d, Path robotFile, String source, boolean overwrite) {
        java.util.Map<String, String> prov = new java.util.LinkedHashMap<>(model.robot().provenance());
        prov.put("diagnosed-from", source);
        prov.put("diagnosed-nominal", model.robot().name());
        prov.put("diagnosis-train-rms-mm", String.format(java.util.Locale.ROOT, "%.5f", d.finalTrainRmsM() * 1e3));
        org.robopro.models.RobotLibrary.write(d.model().toDescription().withProvenance(prov), robotFile, overwrite);
        changeApplied("Apply extended model " + robotFile.getFileName(), new Applied(d.model().geometry(), d.model(), robotFile.toString()));
        log("Applied the extended model " + robotFile + " (" + d.effects().size() + " effects): RAPID exports are compensated with it");
    }

    /** Stops compensating RAPID exports (undoable: Edit &gt; Undo applies the calibration again). */
    public void clearCalibration() {
        changeApplied("Stop compensating", new Applied(null, null, model.calibrationReference()));
        log("Calibration no longer applied: RAPID exports are nominal");
    }

    /**
     * What compensation uses: the calibrated geometry, the extended model (or null), and the robot
     * file the project records as its calibration reference.
     */
    private record Applied(org.robopro.kinematics.KinematicModel calibrated,
                           org.robopro.calibration.diagnosis.ExtendedModel extended, String reference) {}

    private synchronized Applied applied() { return new Applied(calibratedModel, extendedModel, model.calibrationReference()); }

    /**
     * Changes what compensation uses as one edit on the window's undo history (Edit &gt; Undo,
     * Ctrl+Z), so applying a calibration can be taken back like any other edit. Undo puts the
     * models in use back; a robot file the apply wrote stays on disk.
     */
    private void changeApplied(String label, Applied after) {
        Applied before = applied();
        if (before.equals(after)) return; // nothing changes: no edit to undo
        putApplied(after);
        model.history().push(label, before, after, this::restoreApplied);
    }

    private void restoreApplied(Applied a) {
        putApplied(a);
        log(a.calibrated() == null ? "Calibration no longer applied: RAPID exports are nominal"
                : "Compensating RAPID exports with " + (a.extended() != null ? "the extended model " : "the calibrated model ") + a.reference());
    }

    private void putApplied(Applied a) {
        synchronized (this) {
            calibratedModel = a.calibrated();
            extendedModel = a.extended();
        }
        if (!java.util.Objects.equals(model.calibrationReference(), a.reference())) model.setCalibrationReference(a.reference());
    }

    // ---- cell layout -------------------------------------------------------------------------

    public CellObject addObject(CellObject.Kind kind) {
        String prefix = kind.name().toLowerCase(java.util.Locale.ROOT);
        String id = model.newObjectId(prefix);
        Vec3 size = switch (kind) {
            case TABLE -> new Vec3(0.8, 0.6, 0.7);
            case FIXTURE -> new Vec3(0.3, 0.1, 0.1);
            case PART, MESH -> new Vec3(0.2, 0.15, 0.05);
            case CYLINDER -> new Vec3(0.3, 0.3, 0.5);
        };
        int rgb = switch (kind) { case TABLE -> 0x5A6270; case FIXTURE -> 0x2F7D3A; default -> 0xB8C4D0; };
        CellObject o = new CellObject(id, Character.toUpperCase(prefix.charAt(0)) + prefix.substring(1) + " " + id.substring(prefix.length()),
                kind, Pose.translation(0.9, -1.2, 0), size, null, rgb);
        model.edit("Add " + o.name(), () -> model.addObject(o));
        model.select("object:" + id);
        log("Added " + o.name());
        return o;
    }

    public CellObject importMesh(Path file, double scale) {
        String id = model.newObjectId("mesh");
        String rel = projectFile != null ? projectFile.toAbsolutePath().getParent().relativize(file.toAbsolutePath()).toString()
                : file.toAbsolutePath().toString();
        CellObject o = new CellObject(id, file.getFileName().toString(), CellObject.Kind.MESH, Pose.translation(1, 1, 0),
                new Vec3(scale, scale, scale), rel, 0x9AA5B1);
        model.edit("Import mesh " + o.name(), () -> model.addObject(o));
        model.select("object:" + id);
        log("Imported mesh " + file);
        return o;
    }

    /** Moves/rotates a cell object: position in metres, rotation about world z in radians. */
    public void placeObject(String id, double x, double y, double z, double rzRad) {
        CellObject o = model.object(id).orElseThrow(() -> new IllegalArgumentException("no object " + id));
        model.edit("Move " + o.name(), () -> model.updateObject(o.withPose(Pose.translation(x, y, z).times(Pose.rotZ(rzRad)))));
    }

    /** Deletes the selected object or target (and the instructions that move to that target). */
    public void deleteSelection() {
        String s = model.selection();
        if (s == null) return;
        if (s.startsWith("object:")) {
            String id = s.substring(7);
            model.edit("Delete " + model.object(id).map(CellObject::name).orElse(id), () -> model.removeObject(id));
            log("Deleted " + id);
        } else if (s.startsWith("target:")) {
            model.edit("Delete " + s.substring(7), () -> model.removeTarget(s.substring(7)));
            log("Deleted target " + s.substring(7));
        }
    }

    // ---- undo and redo -----------------------------------------------------------------------

    /** Takes back the last edit (cell, tool, targets, program, robot); false when there is nothing to undo. */
    public boolean undo() {
        var l = model.undo();
        l.ifPresent(x -> log("Undo: " + x));
        return l.isPresent();
    }

    /** Makes the last undone edit again; false when there is nothing to redo. */
    public boolean redo() {
        var l = model.redo();
        l.ifPresent(x -> log("Redo: " + x));
        return l.isPresent();
    }

    // ---- project files -----------------------------------------------------------------------

    /**
     * Saves the project (joint values and the active work object included) and removes the
     * autosaves of both its old and its new name, so the next start offers no recovery.
     */
    public void save(Path file) throws IOException {
        Path old = projectFile;
        ProjectStore.write(model.snapshot(), file, true);
        projectFile = file;
        model.markSaved();
        ProjectStore.deleteAutosave(file);
        if (old == null || !old.toAbsolutePath().equals(file.toAbsolutePath())) ProjectStore.deleteAutosave(old);
        log("Saved " + file);
    }

    /** Opens a project; on a damaged file throws and leaves the current cell untouched. */
    public void openProject(Path file) throws IOException {
        ProjectData d = ProjectStore.read(file);
        load(d, file);
        log("Opened " + file);
    }

    /** Starts a new, untitled project: the shipped IRB-2000 welding cell with no targets and no program. */
    public void newProject() {
        load(DefaultCell.irb2000Welding(), null);
        log("New project");
    }

    private void load(ProjectData d, Path file) {
        Path old = projectFile;
        model.load(d);
        if (d.q() == null) model.setQ(startPose(d));
        model.markSaved();
        projectFile = file;
        // The autosave of the project left behind holds changes the user chose to leave (the
        // window asks first); kept, it would offer a false recovery at the next start.
        if (!java.util.Objects.equals(old, file)) {
            try {
                ProjectStore.deleteAutosave(old);
            } catch (IOException ignored) {
                // a leftover autosave only means recovery is offered once more
            }
        }
    }

    // ---- shutdown ----------------------------------------------------------------------------

    /** Stops the path check, autosave and controller link; removes the autosave of a saved project. */
    @Override
    public void close() {
        if (autosave != null) autosave.stop();
        pathChecker.close();
        disconnectNow();
        background.shutdownNow();
        if (!model.dirty() && autosave != null) {
            try {
                Files.deleteIfExists(autosaveTarget());
            } catch (IOException ignored) {
                // a leftover autosave only means recovery is offered once more
            }
        }
    }
}
