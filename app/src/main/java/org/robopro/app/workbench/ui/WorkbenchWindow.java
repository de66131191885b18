package org.robopro.app.workbench.ui;

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
import java.util.Locale;
import java.util.concurrent.atomic.AtomicReference;
import java.util.logging.Level;
import java.util.logging.Logger;
import javax.imageio.ImageIO;
import javax.swing.SwingUtilities;
import org.robopro.app.workbench.WorkbenchSession;
import org.robopro.app.workbench.scene.CameraState;
import org.robopro.app.workbench.scene.WorkbenchApp;
import org.robopro.models.AtomicFiles;

/**
 * The workbench window: the 3D view (jMonkeyEngine in an {@link AwtPanel}) and the Swing frame
 * over a {@link WorkbenchSession}, which holds the model and does every operation. The window
 * only shows the session and forwards the user's requests to it; the 3D scene follows the model
 * on the render thread.
 */
public final class WorkbenchWindow {
    private static final Logger LOG = Logger.getLogger(WorkbenchWindow.class.getName());

    /** How to start. */
    public record Options(int width, int height, Path project, boolean visible, int frameRateCap, long firstFrameTimeoutMs) {
        public static Options defaults() { return new Options(1280, 720, null, true, 60, 20_000); }
        public Options withSize(int w, int h) { return new Options(w, h, project, visible, frameRateCap, firstFrameTimeoutMs); }
        public Options withProject(Path p) { return new Options(width, height, p, visible, frameRateCap, firstFrameTimeoutMs); }
        public Options withFrameRateCap(int f) { return new Options(width, height, project, visible, f, firstFrameTimeoutMs); }
    }

    private final WorkbenchSession session;
    private final WorkbenchApp app;
    private WorkbenchFrame frame;
    private AwtPanel panel;
    private long startNanos;
    private long firstFrameNanos;

    private WorkbenchWindow(WorkbenchSession session) {
        this.session = session;
        this.app = new WorkbenchApp(session.model(), session.pathChecker(), session::resolvePath);
        app.setClearance(session.clearance());
    }

    /**
     * Opens the workbench (the given project, or the IRB-2000 welding cell) and waits for its
     * first frame. Throws when the 3D view cannot start (no OpenGL context): callers must exit
     * with a failure status then.
     */
    public static WorkbenchWindow open(Options o) throws IOException, InterruptedException {
        long t0 = System.nanoTime();
        WorkbenchWindow w = new WorkbenchWindow(WorkbenchSession.open(o.project()));
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
        session.setUiThread(WorkbenchWindow::onEdt);
        onEdt(() -> {
            com.formdev.flatlaf.FlatLightLaf.setup();
            frame = new WorkbenchFrame(session, app, panel, new WorkbenchFrame.WindowOps() {
                @Override public void screenshot(Path png) throws IOException, InterruptedException { WorkbenchWindow.this.screenshot(png); }
                @Override public void close() { WorkbenchWindow.this.close(); }
            });
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
        session.log("Ready: " + session.model().robot().displayName() + ", first frame after "
                + String.format(Locale.ROOT, "%.2f s", secondsToFirstFrame()));
        session.startAutosave(60_000);
    }

    /**
     * Interactive use: shadows that hold the frame rate under {@code minFps} for 3 s are switched
     * off once, with a line in the log (not for screenshots, benchmarks and tests, whose pictures
     * and figures must not depend on the machine's load).
     */
    public void enableShadowFallback(double minFps) {
        app.setShadowFallback(minFps, msg -> javax.swing.SwingUtilities.invokeLater(() -> {
            session.model().setShadows(false);
            session.log(msg);
        }));
    }

    /** Runs {@code r} on the Swing thread and waits for it (at once when already there). */
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

    public WorkbenchSession session() { return session; }
    public WorkbenchApp app() { return app; }
    public WorkbenchFrame frame() { return frame; }
    public double secondsToFirstFrame() { return (firstFrameNanos - startNanos) / 1e9; }

    public void setView(CameraState.View v) { app.camera().view(v); }

    /**
     * The whole window (Swing shell and 3D view) as an image, after the 3D view has drawn a few
     * frames showing the model's current state.
     */
    public BufferedImage captureWindow() throws InterruptedException {
        awaitPathCheck();
        app.awaitFrames(4, 10_000);
        AtomicReference<BufferedImage> out = new AtomicReference<>();
        onEdt(() -> {
            frame.refreshStatus(); // the picture shows this moment's status line, not the last timer tick's
            var root = frame.getRootPane();
            BufferedImage img = new BufferedImage(root.getWidth(), root.getHeight(), BufferedImage.TYPE_INT_RGB);
            Graphics2D g = img.createGraphics();
            root.paintAll(g);
            Point p = SwingUtilities.convertPoint(panel, 0, 0, root);
            Graphics2D pg = (Graphics2D) g.create(p.x, p.y, panel.getWidth(), panel.getHeight());
            panel.paint(pg);
            pg.dispose();
            // Open dialogs (model wizard, calibration) are drawn where they stand over the window.
            for (java.awt.Window w : frame.getOwnedWindows()) {
                if (!w.isShowing() || !(w instanceof javax.swing.RootPaneContainer rc)) continue;
                Point o = w.getLocationOnScreen(), f = root.getLocationOnScreen();
                Graphics2D dg = (Graphics2D) g.create(o.x - f.x, o.y - f.y, w.getWidth(), w.getHeight());
                dg.setColor(java.awt.Color.DARK_GRAY);
                dg.fillRect(0, 0, w.getWidth(), w.getHeight());
                rc.getRootPane().paintAll(dg);
                dg.setColor(java.awt.Color.GRAY);
                dg.drawRect(0, 0, rc.getRootPane().getWidth() - 1, rc.getRootPane().getHeight() - 1);
                dg.dispose();
            }
            g.dispose();
            out.set(img);
        });
        return out.get();
    }

    /**
     * Waits until the background path check has caught up with the model and the 3D view and
     * the panels show it (for tests and screenshots; interactive use never waits).
     */
    public void awaitPathCheck() throws InterruptedException {
        var r = session.awaitPathCheck();
        long end = System.currentTimeMillis() + 10_000;
        while (app.pathState().shownRequest() < r.request() && System.currentTimeMillis() < end) Thread.sleep(5);
        onEdt(() -> { }); // the Swing side's invokeLater has run
    }

    public void screenshot(Path png) throws IOException, InterruptedException {
        BufferedImage img = captureWindow();
        Path abs = png.toAbsolutePath();
        if (abs.getParent() != null) Files.createDirectories(abs.getParent());
        java.io.ByteArrayOutputStream bytes = new java.io.ByteArrayOutputStream();
        ImageIO.write(img, "png", bytes);
        AtomicFiles.write(abs, bytes.toByteArray(), true);
    }

    /** Stops rendering, closes the window and the session (which removes the autosave of a saved project). */
    public void close() {
        session.close();
        try {
            app.stop(true);
        } catch (RuntimeException e) {
            LOG.log(Level.FINE, "stop", e);
        }
        if (frame != null) onEdt(() -> frame.dispose());
    }
}
