package org.robopro.app.workbench.model;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicLong;
import org.robopro.kinematics.Pose;
import org.robopro.models.RobotDescription;

/**
 * The workbench's plain application model: the cell (robot and its placement, tool, objects,
 * work objects), the robot's joint values, taught targets and the program. The 3D scene is
 * updated FROM it each frame (scene states compare {@link #version()}), the Swing panels listen
 * to it. Mutators are synchronized and bump the version; getters return immutable snapshots, so
 * the render thread may read at any time. Angles inside are radians, lengths metres.
 */
public final class WorkbenchModel {
    /** What changed, for listeners that care. */
    public enum Change { ROBOT, JOINTS, CELL, TOOL, TARGETS, PROGRAM, SELECTION, VIEW, PROJECT }

    /** Told about each change, on the thread that made it. */
    public interface Listener { void changed(Change what); }

    private final AtomicLong version = new AtomicLong();
    private final AtomicLong jointVersion = new AtomicLong();
    private final List<Listener> listeners = new CopyOnWriteArrayList<>();

    private String robotRef;
    private RobotKinematics kinematics;
    private Pose worldTbase = Pose.IDENTITY;
    private Tool tool = Tool.flange();
    private List<CellObject> objects = List.of();
    private List<WorkObject> workObjects = List.of();
    private List<Target> targets = List.of();
    private List<Instruction> program = List.of();
    /** The RAPID module the program was imported from (its other statements and items are kept); null when taught here. */
    private ProgramModule.Source source;
    private String calibrationReference;
    private volatile double[] q;
    private volatile String selection;
    private volatile boolean showPath = true;
    private volatile boolean dirty;
    private String activeWorkObject = Target.WOBJ0;
    private volatile ModelPreview preview;
    private volatile double[] ghostQ;
    private final AtomicLong ghostVersion = new AtomicLong();
    private ProgramRun run;
    /**
     * Bumped, with {@link #run} cleared, inside the lock of every change a program run depends on
     * (robot, placement, tool, cell, work objects, targets, program, clearance checker): a run
     * computed while one happened is then never kept (joint changes do not count: a run does not
     * depend on where the robot stands).
     */
    private long runInputs;
    /** Path-check results by motion, kept across edits: a check after an edit solves only the motions it changed. */
    private final org.robopro.programs.check.CheckCache checkCache = new org.robopro.programs.check.CheckCache();
    private volatile java.util.function.Supplier<Optional<org.robopro.programs.collision.ClearanceChecker>> clearance = Optional::empty;
    private final EditHistory history = new EditHistory();
    /** The edit state after the last recorded command: the "before" of the next one. */
    private ProjectData committed;
    /** The edit state when last saved (or opened). */
    private ProjectData savedState;
    private int editDepth;
    private volatile boolean restoring;

    public WorkbenchModel(String robotRef, RobotDescription robot) {
        setRobot(robotRef, robot);
        dirty = false;
        synchronized (this) { committed = editState(); savedState = committed; }
        history.clear();
    }

    public void addListener(Listener l) { listeners.add(l); }
    public void removeListener(Listener l) { listeners.remove(l); }

    private void fire(Change c) {
        if (c != Change.SELECTION && c != Change.VIEW && c != Change.JOINTS) synchronized (this) { runInputsChanged(); }
        version.incrementAndGet();
        if (c != Change.SELECTION && c != Change.VIEW) dirty = true;
        if (!restoring) {
            if (c == Change.PROJECT) synchronized (this) { committed = editState(); }
            else if (c != Change.SELECTION && c != Change.VIEW && c != Change.JOINTS) record(defaultLabel(c));
        }
        for (Listener l : listeners) l.changed(c);
    }

    // ---- undo and redo -------------------------------------------------------------------

    /** What the undo history saves and restores: the project without the joint values and the active work object. */
    private synchronized ProjectData editState() { return snapshot().withState(null, null); }

    private static String defaultLabel(Change c) {
        return switch (c) {
            case ROBOT -> "Change robot";
            case CELL -> "Edit cell";
            case TOOL -> "Edit tool";
            case TARGETS -> "Edit targets";
            case PROGRAM -> "Edit program";
            default -> "Edit";
        };
    }

    /** Records the change since the last command as one undoable command (inside {@link #edit}: at its end). */
    private synchronized void record(String label) {
        if (editDepth > 0 || committed == null) return;
        ProjectData now = editState();
        if (now.equals(committed)) return;
        history.push(label, committed, now, System.currentTimeMillis());
        committed = now;
    }

    /**
     * Runs {@code body} (any number of mutations) as one undoable command named {@code label}
     * ("Add table", "Move p20"); nested edits belong to the outermost one.
     */
    public void edit(String label, Runnable body) {
        synchronized (this) { editDepth++; }
        try {
            body.run();
        } finally {
            synchronized (this) { editDepth--; }
            record(label);
        }
    }

    /** The undo history (labels for the Edit menu). */
    public EditHistory history() { return history; }

    /** Takes back the last edit; returns its label, empty when there was none. */
    public Optional<String> undo() { return history.popUndo().map(c -> { apply(c, c.before()); return c.label(); }); }

    /** Makes the last undone edit again; returns its label, empty when there was none. */
    public Optional<String> redo() { return history.popRedo().map(c -> { apply(c, c.after()); return c.label(); }); }

    /** The program run's inputs changed (the caller holds the lock): the kept run is dropped. */
    private void runInputsChanged() {
        run = null;
        runInputs++;
    }

    /** A project edit restores the project; another editor's edit (the robot wizard) is handed to that editor. */
    private void apply(EditHistory.Command c, Object state) {
        if (c.project()) restore((ProjectData) state);
        else c.editor().restore(state);
    }

    /** Puts an edit state back: the robot keeps its joint values when the robot stays; the calibration reference is kept. */
    private void restore(ProjectData s) {
        boolean robotChanged;
        synchronized (this) {
            robotChanged = !robotRef.equals(s.robotRef()) || !kinematics.description().equals(s.robot());
            if (robotChanged) {
                robotRef = s.robotRef();
                kinematics = RobotKinematics.of(s.robot());
                if (q.length != s.robot().dof()) q = new double[s.robot().dof()];
            }
            worldTbase = s.worldTbase();
            tool = s.tool();
            objects = s.objects();
            workObjects = s.workObjects();
            targets = s.targets();
            program = s.program();
            source = s.source();
            if (!activeWorkObject.equalsIgnoreCase(Target.WOBJ0) && workObjects.stream().noneMatch(w -> w.name().equals(activeWorkObject)))
                activeWorkObject = Target.WOBJ0;
            if (selection != null && !selectionExists(selection)) selection = null;
            runInputsChanged();
        }
        restoring = true;
        try {
            if (robotChanged) { jointVersion.incrementAndGet(); fire(Change.ROBOT); }
            for (Change c : new Change[] {Change.CELL, Change.TOOL, Change.TARGETS, Change.PROGRAM}) fire(c);
        } finally {
            restoring = false;
        }
        synchronized (this) {
            committed = editState();
            dirty = !committed.equals(savedState);
        }
    }

    private boolean selectionExists(String sel) {
        if (sel.startsWith("object:")) return objects.stream().anyMatch(o -> o.id().equals(sel.substring(7)));
        if (sel.startsWith("target:")) return targets.stream().anyMatch(t -> t.name().equals(sel.substring(7)));
        return true;
    }

    /** Incremented by every change; scene states rebuild when it moved. */
    public long version() { return version.get(); }

    /** Incremented when only the joint values changed (cheap per-frame update). */
    public long jointVersion() { return jointVersion.get(); }

    /** True when there are changes not yet saved. */
    public boolean dirty() { return dirty; }

    public void markSaved() {
        synchronized (this) { savedState = editState(); }
        dirty = false;
    }

    // ---- robot ---------------------------------------------------------------------------

    public void setRobot(String ref, RobotDescription robot) {
        synchronized (this) {
            robotRef = Objects.requireNonNull(ref);
            kinematics = RobotKinematics.of(robot);
            q = new double[robot.dof()];
            // Taught joints of another robot are only IK seeds now: keep their length right.
            List<Target> n = new ArrayList<>();
            for (Target t : targets)
                n.add(t.qTaught().length == robot.dof() ? t
                        : new Target(t.name(), t.worldTtcp(), java.util.Arrays.copyOf(t.qTaught(), robot.dof()), t.conf(), t.wobj()));
            targets = List.copyOf(n);
            runInputsChanged();
        }
        jointVersion.incrementAndGet();
        fire(Change.ROBOT);
    }

    public synchronized String robotRef() { return robotRef; }
    public synchronized RobotKinematics kinematics() { return kinematics; }
    public RobotDescription robot() { return kinematics().description(); }

    public synchronized Pose worldTbase() { return worldTbase; }

    public void setWorldTbase(Pose p) {
        synchronized (this) { worldTbase = Objects.requireNonNull(p); runInputsChanged(); }
        fire(Change.CELL);
    }

    /** Controller joint values (rad / m), a copy. */
    public double[] q() { return q.clone(); }

    public void setQ(double[] newQ) {
        if (newQ.length != q.length)
            throw new IllegalArgumentException("expected " + q.length + " joint values, got " + newQ.length);
        for (double v : newQ) if (!Double.isFinite(v)) throw new IllegalArgumentException("non-finite joint value");
        q = newQ.clone();
        jointVersion.incrementAndGet();
        for (Listener l : listeners) l.changed(Change.JOINTS);
    }

    /** TCP in world coordinates at the current joint values. */
    public Pose worldTtcp() { return worldTtcp(q); }

    public Pose worldTtcp(double[] qq) {
        RobotKinematics k;
        Pose base;
        Tool t;
        synchronized (this) { k = kinematics; base = worldTbase; t = tool; }
        return base.times(k.flange(qq)).times(t.flangeTtcp());
    }

    /** Joint values putting the TCP at {@code worldTtcp}, nearest to {@code seed}. */
    public Optional<double[]> solveTcp(Pose worldTtcp, double[] seed) {
        RobotKinematics k;
        Pose base;
        Tool t;
        synchronized (this) { k = kinematics; base = worldTbase; t = tool; }
        Pose baseTflange = base.inverse().times(worldTtcp).times(t.flangeTtcp().inverse());
        return k.solveNear(baseTflange, seed);
    }

    // ---- tool ----------------------------------------------------------------------------

    public synchronized Tool tool() { return tool; }

    public void setTool(Tool t) {
        synchronized (this) { tool = Objects.requireNonNull(t); runInputsChanged(); }
        fire(Change.TOOL);
    }

    // ---- cell objects --------------------------------------------------------------------

    public synchronized List<CellObject> objects() { return objects; }

    public synchronized Optional<CellObject> object(String id) {
        return objects.stream().filter(o -> o.id().equals(id)).findFirst();
    }

    /** A fresh id with the given prefix ("table" -> "table2"). */
    public synchronized String newObjectId(String prefix) {
        for (int i = 1; ; i++) {
            String id = prefix + i;
            if (objects.stream().noneMatch(o -> o.id().equals(id))) return id;
        }
    }

    public void addObject(CellObject o) {
        synchronized (this) {
            if (objects.stream().anyMatch(x -> x.id().equals(o.id())))
                throw new IllegalArgumentException("an object with id " + o.id() + " exists already");
            List<CellObject> n = new ArrayList<>(objects);
            n.add(o);
            objects = List.copyOf(n);
            runInputsChanged();
        }
        fire(Change.CELL);
    }

    /** Replaces the object with the same id. */
    public void updateObject(CellObject o) {
        synchronized (this) {
            List<CellObject> n = new ArrayList<>(objects);
            int i = indexOf(n, o.id());
            n.set(i, o);
            objects = List.copyOf(n);
            runInputsChanged();
        }
        fire(Change.CELL);
    }

    public void removeObject(String id) {
        synchronized (this) {
            List<CellObject> n = new ArrayList<>(objects);
            n.remove(indexOf(n, id));
            objects = List.copyOf(n);
            if (("object:" + id).equals(selection)) selection = null;
            runInputsChanged();
        }
        fire(Change.CELL);
    }

    private static int indexOf(List<CellObject> list, String id) {
        for (int i = 0; i < list.size(); i++) if (list.get(i).id().equals(id)) return i;
        throw new IllegalArgumentException("no object with id " + id);
    }

    public synchronized List<WorkObject> workObjects() { return workObjects; }

    public void setWorkObjects(List<WorkObject> w) {
        synchronized (this) { workObjects = List.copyOf(w); runInputsChanged(); }
        fire(Change.CELL);
    }

    // ---- targets and program -------------------------------------------------------------

    public synchronized List<Target> targets() { return targets; }

    public synchronized Optional<Target> target(String name) {
        return targets.stream().filter(t -> t.name().equals(name)).findFirst();
    }

    /** A fresh target name: p10, p20, ... as RAPID programmers write them. */
    public synchronized String newTargetName() {
        for (int i = 10; ; i += 10) {
            String n = "p" + i;
            if (targets.stream().noneMatch(t -> t.name().equals(n))) return n;
        }
    }

    /** Adds a target, or replaces the one with the same name. */
    public void putTarget(Target t) {
        synchronized (this) {
            List<Target> n = new ArrayList<>(targets);
            n.removeIf(x -> x.name().equals(t.name()));
            n.add(t);
            targets = List.copyOf(n);
            runInputsChanged();
        }
        fire(Change.TARGETS);
    }

    /** Removes a target and the instructions moving to it (a program never names a missing target). */
    public void removeTarget(String name) {
        boolean programChanged;
        synchronized (this) {
            List<Target> n = new ArrayList<>(targets);
            n.removeIf(x -> x.name().equals(name));
            targets = List.copyOf(n);
            List<Instruction> p = new ArrayList<>(program);
            programChanged = p.removeIf(i -> i.uses(name));
            program = List.copyOf(p);
            if (("target:" + name).equals(selection)) selection = null;
            runInputsChanged();
        }
        fire(Change.TARGETS);
        if (programChanged) fire(Change.PROGRAM);
    }

    public synchronized List<Instruction> program() { return program; }

    /** The RAPID module the program was imported from, empty when it was taught here. */
    public synchronized Optional<ProgramModule.Source> programSource() { return Optional.ofNullable(source); }

    public void setProgram(List<Instruction> p) {
        synchronized (this) { program = List.copyOf(p); runInputsChanged(); }
        fire(Change.PROGRAM);
    }

    public void addInstruction(Instruction i) {
        List<Instruction> n;
        synchronized (this) { n = new ArrayList<>(program); }
        n.add(i);
        setProgram(n);
    }

    /**
     * The program mapped to RAPID, stepped, checked and sampled (computed once per change of the
     * robot, cell, tool, targets or program; callers on any thread share it). The path check is
     * incremental: motions an edit did not change are taken from the previous checks.
     */
    public ProgramRun programRun() {
        long v;
        synchronized (this) {
            if (run != null) return run;
            v = runInputs;
        }
        ProgramRun r = ProgramRun.of(this, checkCache, clearance.get().orElse(null));
        // Kept only when nothing it depends on changed meanwhile (such a run may mix the states
        // before and after the change; the change requests a check of its own).
        synchronized (this) {
            if (runInputs == v) run = r;
        }
        return r;
    }

    /**
     * Where the program run finds the cell's collision checker (the session's live clearance
     * sets it); without one, programs are not checked for collisions.
     */
    public void setClearance(java.util.function.Supplier<Optional<org.robopro.programs.collision.ClearanceChecker>> c) {
        synchronized (this) {
            clearance = c;
            runInputsChanged();
        }
    }

    /** The path check's results by motion, kept across edits (its hit and miss counts show what a check solved). */
    public org.robopro.programs.check.CheckCache checkCache() { return checkCache; }

    /** A robot model under construction drawn instead of the cell's robot (the model wizard). */
    public record ModelPreview(RobotDescription robot, Pose[] frames) { }

    /** The model wizard's robot, or null when none is being built. */
    public ModelPreview preview() { return preview; }

    public void setPreview(ModelPreview p) {
        preview = p;
        fire(Change.VIEW);
    }

    /** Joint values read from the real controller, drawn as a ghost robot; null when none. A copy. */
    public double[] ghostQ() { double[] g = ghostQ; return g == null ? null : g.clone(); }

    public long ghostVersion() { return ghostVersion.get(); }

    public void setGhostQ(double[] q) {
        ghostQ = q == null ? null : q.clone();
        ghostVersion.incrementAndGet();
        for (Listener l : listeners) l.changed(Change.JOINTS);
    }

    /** The work object new targets are taught in ("wobj0": the world). */
    public synchronized String activeWorkObject() { return activeWorkObject; }

    public void setActiveWorkObject(String name) {
        synchronized (this) {
            if (!name.equalsIgnoreCase(Target.WOBJ0) && workObjects.stream().noneMatch(w -> w.name().equals(name)))
                throw new IllegalArgumentException("no work object " + name);
            activeWorkObject = name;
        }
        fire(Change.VIEW);
    }

    /** Replaces the tool, work objects, targets and program with an imported program's. */
    public void replaceProgram(ProgramModule.Imported imp) {
        synchronized (this) {
            tool = imp.tool();
            List<WorkObject> w = new ArrayList<>(workObjects);
            for (WorkObject n : imp.workObjects()) {
                w.removeIf(x -> x.name().equals(n.name()));
                w.add(n);
            }
            workObjects = List.copyOf(w);
            targets = List.copyOf(imp.targets());
            program = List.copyOf(imp.program());
            source = imp.source();
            selection = null;
            runInputsChanged();
        }
        for (Change c : new Change[] {Change.TOOL, Change.CELL, Change.TARGETS, Change.PROGRAM}) fire(c);
    }

    /** How the robot can reach {@code t} from its taught joint values (the seed keeps the configuration). */
    public TargetStatus status(Target t) {
        Optional<double[]> sol = solveTcp(t.worldTtcp(), t.qTaught());
        if (sol.isEmpty()) return TargetStatus.UNREACHABLE;
        return kinematics().withinLimits(sol.get()) ? TargetStatus.REACHABLE : TargetStatus.OUTSIDE_LIMITS;
    }

    /** Every target's status, with targets the path check names in an error marked {@link TargetStatus#PATH_PROBLEM}. */
    public java.util.Map<String, TargetStatus> statuses() { return statuses(programRun()); }

    /** As {@link #statuses()}, with the path errors of a given run. */
    public java.util.Map<String, TargetStatus> statuses(ProgramRun r) {
        java.util.Map<String, TargetStatus> out = new java.util.HashMap<>();
        for (Target t : targets()) {
            TargetStatus s = status(t);
            if (s.ok() && r.badTargets().contains(t.name())) s = TargetStatus.PATH_PROBLEM;
            out.put(t.name(), s);
        }
        return out;
    }

    public synchronized String calibrationReference() { return calibrationReference; }

    public void setCalibrationReference(String ref) {
        synchronized (this) { calibrationReference = ref; }
        fire(Change.PROJECT);
    }

    // ---- selection and view --------------------------------------------------------------

    /** "object:ID", "link:N", "target:NAME", "tool", or null. */
    public String selection() { return selection; }

    public void select(String s) {
        if (Objects.equals(s, selection)) return;
        selection = s;
        fire(Change.SELECTION);
    }

    /** The frames the 3D view can show, each switched on its own (View → Frames). */
    public enum FrameKind {
        WORLD("World triad"), BASE("Robot base"), JOINTS("Joint axes"), FLANGE("Flange"), TCP("Tool (TCP)"), TARGETS("Target triads");
        private final String label;
        FrameKind(String label) { this.label = label; }
        public String label() { return label; }
    }

    private volatile java.util.Set<FrameKind> shownFrames = java.util.Collections.unmodifiableSet(
            java.util.EnumSet.of(FrameKind.WORLD, FrameKind.TARGETS));
    private volatile boolean shadows = true;

    /** Whether the robot's joint axis frames are shown. */
    public boolean showFrames() { return frameShown(FrameKind.JOINTS); }

    /** Shows or hides the robot's frames together: base, joint axes, flange and TCP (the paper's Fig. 8 view). */
    public void setShowFrames(boolean b) {
        java.util.EnumSet<FrameKind> s = java.util.EnumSet.copyOf(shownFrames);
        for (FrameKind k : new FrameKind[] {FrameKind.BASE, FrameKind.JOINTS, FrameKind.FLANGE, FrameKind.TCP}) if (b) s.add(k); else s.remove(k);
        shownFrames = java.util.Collections.unmodifiableSet(s);
        fire(Change.VIEW);
    }

    public boolean frameShown(FrameKind k) { return shownFrames.contains(k); }

    /** The frames shown now (an unmodifiable snapshot; a new set after every change). */
    public java.util.Set<FrameKind> shownFrames() { return shownFrames; }

    public void setFrameShown(FrameKind k, boolean b) {
        if (frameShown(k) == b) return;
        java.util.EnumSet<FrameKind> s = java.util.EnumSet.noneOf(FrameKind.class);
        s.addAll(shownFrames);
        if (b) s.add(k); else s.remove(k);
        shownFrames = java.util.Collections.unmodifiableSet(s);
        fire(Change.VIEW);
    }

    /** Whether the key light casts shadows in the 3D view. */
    public boolean shadows() { return shadows; }
    public void setShadows(boolean b) { shadows = b; fire(Change.VIEW); }
    public boolean showPath() { return showPath; }
    public void setShowPath(boolean b) { showPath = b; fire(Change.VIEW); }

    /**
     * Replaces everything with the content of a loaded project (one change event per part; the
     * joint values when the project has them) and forgets the undo history.
     */
    public void load(ProjectData p) {
        synchronized (this) {
            robotRef = p.robotRef();
            kinematics = RobotKinematics.of(p.robot());
            q = new double[p.robot().dof()];
            worldTbase = p.worldTbase();
            tool = p.tool();
            objects = List.copyOf(p.objects());
            workObjects = List.copyOf(p.workObjects());
            targets = List.copyOf(p.targets());
            program = List.copyOf(p.program());
            source = p.source();
            calibrationReference = p.calibrationReference();
            activeWorkObject = p.activeWorkObject().equalsIgnoreCase(Target.WOBJ0)
                    || workObjects.stream().anyMatch(w -> w.name().equals(p.activeWorkObject())) ? p.activeWorkObject() : Target.WOBJ0;
            double[] pq = p.q();
            if (pq != null && pq.length == q.length) q = pq;
            selection = null;
            runInputsChanged();
        }
        jointVersion.incrementAndGet();
        restoring = true;
        try {
            for (Change c : new Change[] {Change.ROBOT, Change.CELL, Change.TOOL, Change.TARGETS, Change.PROGRAM, Change.PROJECT})
                fire(c);
        } finally {
            restoring = false;
        }
        history.clear();
        synchronized (this) { committed = editState(); savedState = committed; }
        dirty = false;
    }

    /** A snapshot of everything a project file holds. */
    public synchronized ProjectData snapshot() {
        return new ProjectData(robotRef, kinematics.description(), worldTbase, tool, objects, workObjects, targets,
                program, calibrationReference, activeWorkObject, q, source);
    }
}
