package org.robopro.app.workbench.scene;

import com.jme3.app.SimpleApplication;
import com.jme3.app.state.AppState;
import com.jme3.collision.CollisionResult;
import com.jme3.collision.CollisionResults;
import com.jme3.math.FastMath;
import com.jme3.math.Ray;
import com.jme3.math.Vector2f;
import com.jme3.math.Vector3f;
import com.jme3.renderer.Camera;
import com.jme3.scene.Node;
import com.jme3.scene.Spatial;
import com.jme3.system.awt.AwtPanel;
import java.nio.file.Path;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Function;
import org.robopro.app.workbench.LiveClearance;
import org.robopro.app.workbench.model.PathChecker;
import org.robopro.app.workbench.model.WorkbenchModel;

/**
 * The jME side of the workbench: one AppState per feature (environment, robot, cell, path,
 * camera, selection), all updated from the {@link WorkbenchModel} each frame. Other threads
 * talk to the scene only through {@link #enqueue} or the model. Reports the first frame, the
 * frame rate, and GL errors (jME would otherwise exit quietly with status 0 when it cannot
 * create a context).
 */
public final class WorkbenchApp extends SimpleApplication {
    private final WorkbenchModel model;
    private final Function<String, Path> meshResolver;
    private final CountDownLatch panelReady = new CountDownLatch(1);
    private final CountDownLatch firstFrame = new CountDownLatch(1);
    private final AtomicReference<Throwable> error = new AtomicReference<>();
    private final AtomicLong frames = new AtomicLong();
    private volatile AwtPanel panel;
    private final Node world = new Node("world");
    private final Node worldTriad = new Node("frame-world-triad");
    private final CameraState cameraState = new CameraState();
    private volatile PreviewState previewState;
    private final PathState pathState;
    private final PathChecker pathChecker;
    private RobotState robotState;
    private volatile LiveClearance clearance;
    private volatile ClearanceState clearanceState;
    private volatile double fps;
    private long windowStartNanos;
    private long windowFrames;
    private int lastW, lastH;
    private volatile double shadowFallbackFps;
    private volatile java.util.function.Consumer<String> shadowFallbackLog;
    private int slowWindows;
    /** -Drobopro.render.stats=true: print jME's render statistics (triangles, vertices, objects) of one frame. */
    private static final boolean STATS = Boolean.getBoolean("robopro.render.stats");

    /** A scene over {@code model} that shows the results of {@code pathChecker} (owned by the caller). */
    public WorkbenchApp(WorkbenchModel model, PathChecker pathChecker, Function<String, Path> meshResolver) {
        super(new AppState[0]); // no fly camera, no stats overlay: navigation is CameraState
        this.model = model;
        this.meshResolver = meshResolver;
        this.pathState = new PathState(model, world);
        // Path checks run off the render thread; the scene takes each result in its own update.
        this.pathChecker = pathChecker;
        pathChecker.addListener(r -> enqueue(() -> pathState.show(r)));
    }

    /** Shows the live collision and clearance view of {@code c} (call before the scene starts). */
    public void setClearance(LiveClearance c) { clearance = c; }

    /** The live collision view (null when no clearance was set). */
    public ClearanceState clearanceState() { return clearanceState; }

    /** Hands over the Swing panel the scene is drawn into; simpleInitApp waits for it. */
    public void setPanel(AwtPanel p) {
        panel = p;
        panelReady.countDown();
    }

    @Override
    public void simpleInitApp() {
        try {
            if (!panelReady.await(30, TimeUnit.SECONDS)) throw new IllegalStateException("the Swing panel never arrived");
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return;
        }
        // Both view ports: the panel resizes their cameras, and the renderer reads the frame back
        // with the last-used view port's size (a stale GUI camera garbles the picture).
        panel.attachTo(true, viewPort, guiViewPort);
        // All lights in one pass (jME's default draws each lit object once per light, blending;
        // a software rasteriser pays for every pass).
        renderManager.setPreferredLightMode(com.jme3.material.TechniqueDef.LightMode.SinglePass);
        renderManager.setSinglePassLightBatchSize(3);
        setPauseOnLostFocus(false);
        // robopro's scene is z-up; jME's world is y-up.
        world.rotate(-FastMath.HALF_PI, 0, 0);
        rootNode.attachChild(world);
        world.setShadowMode(com.jme3.renderer.queue.RenderQueue.ShadowMode.Cast);
        worldTriad.setShadowMode(com.jme3.renderer.queue.RenderQueue.ShadowMode.Off);
        // The world frame: a triad with X, Y, Z at the origin of the cell.
        Shapes sh = new Shapes(assetManager);
        world.attachChild(worldTriad);
        worldTriad.attachChild(sh.axes("frame-world", 0.5f));
        String[] names = {"X", "Y", "Z"};
        int[] colours = {0xC62828, 0x2E7D32, 0x1565C0};
        for (int i = 0; i < 3; i++) {
            Node l = sh.label("frame-world-" + names[i], names[i], 0.09f, colours[i]);
            l.setLocalTranslation(i == 0 ? 0.53f : 0, i == 1 ? 0.53f : 0, i == 2 ? 0.53f : 0);
            worldTriad.attachChild(l);
        }
        java.util.function.Function<String, Path> robotMeshes = path -> {
            // Robot meshes are relative to the robot file; shipped robots (a name, not a path) have none on disk.
            String ref = model.robotRef();
            boolean isFile = ref.contains("/") || ref.contains("\\") || ref.endsWith(".json");
            if (!isFile) return null;
            Path robotFile = meshResolver.apply(ref);
            return robotFile.toAbsolutePath().getParent().resolve(path);
        };
        robotState = new RobotState(model, world, robotMeshes);
        RobotState ghostState = new RobotState(model, world, robotMeshes, true);
        previewState = new PreviewState(model, world);
        stateManager.attachAll(new EnvironmentState(model), robotState, new CellState(model, world, meshResolver),
                pathState, previewState, ghostState, cameraState, new SelectionState(model, world, rootNode));
        if (clearance != null) {
            clearanceState = new ClearanceState(model, clearance, world);
            stateManager.attach(clearanceState);
        }
        windowStartNanos = System.nanoTime();
    }

    @Override
    public void simpleUpdate(float tpf) {
        worldTriad.setCullHint(model.frameShown(WorkbenchModel.FrameKind.WORLD) ? Spatial.CullHint.Inherit : Spatial.CullHint.Always);
        if (cam.getWidth() != lastW || cam.getHeight() != lastH) {
            lastW = cam.getWidth();
            lastH = cam.getHeight();
            cameraState.refresh();
        }
    }

    @Override
    public void simpleRender(com.jme3.renderer.RenderManager rm) {
        long n = frames.incrementAndGet();
        long now = System.nanoTime();
        if (n == 1) {
            // The rate counts from the first frame drawn, not from the start-up before it.
            windowStartNanos = now;
            windowFrames = 0;
            firstFrame.countDown();
            return;
        }
        windowFrames++;
        if (STATS && n == 40) {
            var st = rm.getRenderer().getStatistics();
            String[] labels = st.getLabels();
            int[] data = new int[labels.length];
            st.getData(data);
            StringBuilder b = new StringBuilder("render stats:");
            for (int i = 0; i < labels.length; i++) b.append(' ').append(labels[i]).append('=').append(data[i]);
            System.out.println(b);
        }
        if (STATS && n == 39) rm.getRenderer().getStatistics().setEnabled(true);
        // The first half second reports as it goes (the status bar shows a rate from the first view on), then per window.
        if (fps == 0 || now - windowStartNanos > 500_000_000L) fps = windowFrames * 1e9 / Math.max(1, now - windowStartNanos);
        if (now - windowStartNanos > 500_000_000L) {
            windowFrames = 0;
            windowStartNanos = now;
            shadowFallback();
        }
    }

    /**
     * Once, when with shadows on the frame rate stays under {@code minFps} for six half-second
     * windows in a row (a software rasteriser under load), hands {@code switchOff} the message
     * to log; it switches the shadows off (View → Shadows turns them back on, and then they
     * stay). 0 disables the fallback (benchmarks).
     */
    public void setShadowFallback(double minFps, java.util.function.Consumer<String> switchOff) {
        shadowFallbackLog = switchOff;
        shadowFallbackFps = minFps;
    }

    private void shadowFallback() {
        double min = shadowFallbackFps;
        if (min <= 0 || !model.shadows()) { slowWindows = 0; return; }
        slowWindows = fps < min ? slowWindows + 1 : 0;
        if (slowWindows < 6) return;
        shadowFallbackFps = 0;
        var off = shadowFallbackLog;
        if (off != null) off.accept(String.format(java.util.Locale.ROOT,
                "Shadows switched off: %.0f fps with them on this display (View → Shadows turns them back on)", fps));
    }

    @Override
    public void handleError(String errMsg, Throwable t) {
        error.compareAndSet(null, t != null ? new IllegalStateException(errMsg, t) : new IllegalStateException(errMsg));
        firstFrame.countDown();
        super.handleError(errMsg, t);
    }

    /**
     * Waits for the first rendered frame; throws with the GL error, or when nothing was drawn
     * within {@code timeoutMs} (no usable OpenGL context).
     */
    public void awaitFirstFrame(long timeoutMs) throws InterruptedException {
        boolean done = firstFrame.await(timeoutMs, TimeUnit.MILLISECONDS);
        Throwable e = error.get();
        if (e != null) throw new IllegalStateException("3D view failed: " + e.getMessage(), e);
        if (!done) throw new IllegalStateException("3D view did not draw a frame within " + timeoutMs
                + " ms: no usable OpenGL context (is DISPLAY set and Mesa/GL installed?)");
    }

    /** Waits until {@code n} more frames were drawn after this call (so model changes are visible). */
    public void awaitFrames(int n, long timeoutMs) throws InterruptedException {
        long target = frames.get() + n;
        long end = System.currentTimeMillis() + timeoutMs;
        while (frames.get() < target) {
            if (error.get() != null) throw new IllegalStateException("3D view failed", error.get());
            if (System.currentTimeMillis() > end) throw new IllegalStateException("3D view stopped drawing");
            Thread.sleep(5);
        }
    }

    public long frameCount() { return frames.get(); }
    public double fps() { return fps; }
    public Throwable error() { return error.get(); }
    public CameraState camera() { return cameraState; }
    public PathState pathState() { return pathState; }
    public PathChecker pathChecker() { return pathChecker; }
    public PreviewState previewState() { return previewState; }
    public RobotState robotState() { return robotState; }
    public Node world() { return world; }

    /** Picks at panel pixel (x, y) (Swing coordinates, y down); completes with a pick key or null. */
    public CompletableFuture<String> pick(int x, int y) {
        CompletableFuture<String> f = new CompletableFuture<>();
        enqueue(() -> {
            try {
                Camera c = cam;
                float sy = c.getHeight() - y;
                Vector3f near = c.getWorldCoordinates(new Vector2f(x, sy), 0f);
                Vector3f far = c.getWorldCoordinates(new Vector2f(x, sy), 1f);
                CollisionResults res = new CollisionResults();
                world.collideWith(new Ray(near, far.subtractLocal(near).normalizeLocal()), res);
                String key = null;
                for (CollisionResult r : res) {
                    if (r.getGeometry().getName().startsWith("grid") || r.getGeometry().getName().startsWith("frame")) continue;
                    key = keyOf(r.getGeometry());
                    if (key != null) break;
                }
                f.complete(key);
            } catch (RuntimeException e) {
                f.completeExceptionally(e);
            }
        });
        return f;
    }

    private static String keyOf(Spatial s) {
        for (Spatial p = s; p != null; p = p.getParent()) {
            Object k = p.getUserData("pick");
            if (k != null) return k.toString();
        }
        return null;
    }
}
