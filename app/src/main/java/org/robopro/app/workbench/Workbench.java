package org.robopro.app.workbench;

import com.jme3.system.AppSettings;
import com.jme3.system.awt.AwtPanel;
import com.jme3.system.awt.AwtPanelsContext;
import com.jme3.system.awt.PaintMode;
import java.awt.Dimension;
import java.awt.Graphics2D;
import java.awt.Point;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.lang.reflect.InvocationTargetException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicReference;
import java.util.logging.Level;
import java.util.logging.Logger;
import javax.imageio.ImageIO;
import javax.swing.SwingUtilities;
import org.robopro.app.workbench.model.CellObject;
import org.robopro.app.workbench.model.DefaultCell;
import org.robopro.app.workbench.model.Instruction;
import org.robopro.app.workbench.model.ProgramPlan;
import org.robopro.app.workbench.model.ProjectData;
import org.robopro.app.workbench.model.RapidExport;
import org.robopro.app.workbench.model.Target;
import org.robopro.app.workbench.model.WorkbenchModel;
import org.robopro.app.workbench.scene.CameraState;
import org.robopro.app.workbench.scene.WorkbenchApp;
import org.robopro.app.workbench.ui.WorkbenchFrame;
import org.robopro.kinematics.Pose;
import org.robopro.models.AtomicFiles;
import org.robopro.models.Vec3;

/**
 * The workbench: model, 3D view and Swing shell, and the operations the menus, buttons and
 * tests call (the "UI layer"). Mutations happen on the Swing thread; the 3D scene follows the
 * model on the render thread. Lengths in metres and angles in radians unless a name says mm/deg.
 */
public final class Workbench {
    private static final Logger LOG = Logger.getLogger(Workbench.class.getName());

    /** How to start. */
    public record Options(int width, int height, Path project, boolean visible, int frameRateCap, long firstFrameTimeoutMs) {
        public static Options defaults() { return new Options(1280, 720, null, true, 60, 20_000); }
        public Options withSize(int w, int h) { return new Options(w, h, project, visible, frameRateCap, firstFrameTimeoutMs); }
        public Options withProject(Path p) { return new Options(width, height, p, visible, frameRateCap, firstFrameTimeoutMs); }
        public Options withFrameRateCap(int f) { return new Options(width, height, project, visible, f, firstFrameTimeoutMs); }
    }

    private final WorkbenchModel model;
    private final WorkbenchApp app;
    private final List<String> log = new ArrayList<>();
    private volatile Path projectFile;
    private WorkbenchFrame frame;
    private AwtPanel panel;
    private ProjectStore.Autosave autosave;
    private long startNanos;
    private long firstFrameNanos;

    private Workbench(ProjectData data, Path projectFile) {
        this.model = new WorkbenchModel(data.robotRef(), data.robot());
        model.load(data);
        model.setQ(DefaultCell.readyPose().length == data.robot().dof() ? DefaultCell.readyPose() : new double[data.robot().dof()]);
        model.markSaved();
        this.projectFile = projectFile;
        this.app = new WorkbenchApp(model, this::resolveMesh);
    }

    /**
     * Opens the workbench (the given project, or the IRB-2000 welding cell) and waits for its
     * first frame. Throws when the 3D view cannot start (no OpenGL context): callers must exit
     * with a failure status then.
     */
    public static Workbench open(Options o) throws IOException, InterruptedException {
        long t0 = System.nanoTime();
        ProjectData data = o.project() == null ? DefaultCell.irb2000Welding() : ProjectStore.read(o.project());
        Workbench w = new Workbench(data, o.project());
        w.startNanos = t0;
        w.start(o);
        return w;
    }

    private void start(Options o) throws InterruptedException {
        AppSettings s = new AppSettings(true);
        s.setCustomRenderer(AwtPanelsContext.class);
        s.setFrameRate(o.frameRateCap());
        s.setAudioRenderer(null);
        s.setResolution(o.width(), o.height());
        s.setTitle("robopro workbench");
        app.setSettings(s);
        app.setShowSettings(false);
        app.setPauseOnLostFocus(false);
        app.start();
        AwtPanelsContext ctx = (AwtPanelsContext) app.getContext();
        panel = ctx.createPanel(PaintMode.Accelerated);
        panel.setPreferredSize(new Dimension(800, 500));
        ctx.setInputSource(panel);
        onEdt(() -> {
            frame = new WorkbenchFrame(this, panel);
            frame.sizeTo(o.width(), o.height());
            frame.setLocation(0, 0);
            frame.setVisible(o.visible());
            frame.validate();
        });
        app.setPanel(panel);
        try {
            app.awaitFirstFrame(o.firstFrameTimeoutMs());
        } catch (IllegalStateException e) {
            close();
            throw e;
        }
        firstFrameNanos = System.nanoTime();
        log("Ready: " + model.robot().displayName() + " (" + model.kinematics().implementation() + "), first frame after "
                + String.format(java.util.Locale.ROOT, "%.2f s", secondsToFirstFrame()));
        autosave = new ProjectStore.Autosave(this::autosaveTarget, model, 60_000);
        autosave.start();
    }

    public static void onEdt(Runnable r) {
        if (SwingUtilities.isEventDispatchThread()) { r.run(); return; }
        try {
            SwingUtilities.invokeAndWait(r);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (InvocationTargetException e) {
            Throwable c = e.getCause();
            if (c instanceof RuntimeException re) throw re;
            if (c instanceof Error er) throw er;
            throw new IllegalStateException(c);
        }
    }

    public WorkbenchModel model() { return model; }
    public WorkbenchApp app() { return app; }
    public WorkbenchFrame frame() { return frame; }
    public Optional<Path> projectFile() { return Optional.ofNullable(projectFile); }
    public double secondsToFirstFrame() { return (firstFrameNanos - startNanos) / 1e9; }
    public synchronized List<String> log() { return List.copyOf(log); }

    /** Adds a line to the log panel. */
    public void log(String line) {
        synchronized (this) { log.add(line); }
        LOG.fine(line);
        if (frame != null) SwingUtilities.invokeLater(() -> frame.appendLog(line));
    }

    private Path resolveMesh(String path) {
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

    /** Teaches the current TCP pose as a new target and returns it. */
    public Target teach() {
        String name = model.newTargetName();
        double[] q = model.q();
        Target t = new Target(name, model.worldTtcp(), q, model.kinematics().confOf(q));
        model.putTarget(t);
        log(String.format(java.util.Locale.ROOT, "Taught %s at (%.1f, %.1f, %.1f) mm", name,
                t.worldTtcp().x() * 1000, t.worldTtcp().y() * 1000, t.worldTtcp().z() * 1000));
        return t;
    }

    public void addMove(Instruction.Type type, String target, double speedMmPerS, double zoneMm) {
        model.addInstruction(new Instruction(type, target, speedMmPerS, zoneMm));
    }

    /** Checks the program and logs each failing instruction. */
    public ProgramPlan checkProgram() {
        ProgramPlan p = ProgramPlan.of(model);
        for (ProgramPlan.Step s : p.steps())
            if (!s.ok()) log("Check: instruction " + (s.index() + 1) + " (" + s.instruction() + "): " + s.message());
        log(p.ok() ? String.format(java.util.Locale.ROOT, "Check: program OK, %d instructions, %.2f s",
                p.steps().size(), p.duration()) : "Check: program has problems");
        return p;
    }

    /** Writes the program as a RAPID module (refuses to overwrite unless asked). */
    public String exportRapid(Path file, boolean overwrite) throws IOException {
        String name = file.getFileName().toString().replaceFirst("\\.[^.]*$", "").replaceAll("[^A-Za-z0-9_]", "_");
        if (name.isEmpty() || !Character.isLetter(name.charAt(0))) name = "M" + name;
        String text = RapidExport.module(name, model);
        AtomicFiles.writeString(file, text, overwrite);
        log("Exported RAPID module " + name + " to " + file);
        return text;
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
        model.addObject(o);
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
        model.addObject(o);
        model.select("object:" + id);
        log("Imported mesh " + file);
        return o;
    }

    /** Moves/rotates a cell object: position in metres, rotation about world z in radians. */
    public void placeObject(String id, double x, double y, double z, double rzRad) {
        CellObject o = model.object(id).orElseThrow(() -> new IllegalArgumentException("no object " + id));
        model.updateObject(o.withPose(Pose.translation(x, y, z).times(Pose.rotZ(rzRad))));
    }

    public void deleteSelection() {
        String s = model.selection();
        if (s == null) return;
        if (s.startsWith("object:")) {
            model.removeObject(s.substring(7));
            log("Deleted " + s.substring(7));
        } else if (s.startsWith("target:")) {
            model.removeTarget(s.substring(7));
            log("Deleted target " + s.substring(7));
        }
    }

    public void setView(CameraState.View v) { app.camera().view(v); }

    // ---- project files -----------------------------------------------------------------------

    public void save(Path file) throws IOException {
        ProjectStore.write(model.snapshot(), file, true);
        projectFile = file;
        model.markSaved();
        ProjectStore.deleteAutosave(file);
        log("Saved " + file);
    }

    /** Opens a project; on a damaged file throws and leaves the current cell untouched. */
    public void openProject(Path file) throws IOException {
        ProjectData d = ProjectStore.read(file);
        model.load(d);
        model.setQ(new double[d.robot().dof()]);
        model.markSaved();
        projectFile = file;
        log("Opened " + file);
    }

    // ---- screenshots and shutdown ------------------------------------------------------------

    /**
     * The whole window (Swing shell and 3D view) as an image, after the 3D view has drawn a few
     * frames showing the model's current state.
     */
    public BufferedImage captureWindow() throws InterruptedException {
        app.awaitFrames(4, 10_000);
        AtomicReference<BufferedImage> out = new AtomicReference<>();
        onEdt(() -> {
            var root = frame.getRootPane();
            BufferedImage img = new BufferedImage(root.getWidth(), root.getHeight(), BufferedImage.TYPE_INT_RGB);
            Graphics2D g = img.createGraphics();
            root.paintAll(g);
            Point p = SwingUtilities.convertPoint(panel, 0, 0, root);
            Graphics2D pg = (Graphics2D) g.create(p.x, p.y, panel.getWidth(), panel.getHeight());
            panel.paint(pg);
            pg.dispose();
            g.dispose();
            out.set(img);
        });
        return out.get();
    }

    public void screenshot(Path png) throws IOException, InterruptedException {
        BufferedImage img = captureWindow();
        Path abs = png.toAbsolutePath();
        if (abs.getParent() != null) Files.createDirectories(abs.getParent());
        java.io.ByteArrayOutputStream bytes = new java.io.ByteArrayOutputStream();
        ImageIO.write(img, "png", bytes);
        AtomicFiles.write(abs, bytes.toByteArray(), true);
    }

    /** Stops rendering, closes the window, removes the autosave of a saved project. */
    public void close() {
        if (autosave != null) autosave.stop();
        try {
            app.stop(true);
        } catch (RuntimeException e) {
            LOG.log(Level.FINE, "stop", e);
        }
        if (frame != null) onEdt(() -> frame.dispose());
        if (!model.dirty() && autosave != null) {
            try {
                Files.deleteIfExists(autosaveTarget());
            } catch (IOException ignored) {
                // a leftover autosave only means recovery is offered once more
            }
        }
    }
}
