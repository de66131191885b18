package org.robopro.app.workbench.model;

import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import java.util.logging.Level;
import java.util.logging.Logger;

/**
 * Recomputes the path check (the program stepped, checked and sampled, and every target's
 * status) on a background thread, debounced: a burst of edits costs one check, started
 * {@code debounceMs} after the last of them. Neither the render thread nor the Swing thread
 * waits for it; listeners get each {@link Result} on the checker's thread and hand it over to
 * their own thread (the 3D scene through {@code app.enqueue}, Swing through {@code invokeLater}).
 * Jogging, selection and view changes do not start a check.
 */
public final class PathChecker implements AutoCloseable {
    private static final Logger LOG = Logger.getLogger(PathChecker.class.getName());

    /** One finished check: the run, the target statuses, and the targets and program it saw. */
    public record Result(long request, ProgramRun run, Map<String, TargetStatus> statuses, List<Target> targets,
                         List<Instruction> program) { }

    private final WorkbenchModel model;
    private final long debounceMs;
    private final ScheduledExecutorService exec;
    private final List<Consumer<Result>> listeners = new CopyOnWriteArrayList<>();
    private final AtomicLong requested = new AtomicLong();
    private final AtomicLong checks = new AtomicLong();
    private final WorkbenchModel.Listener modelListener;
    private ScheduledFuture<?> pending;
    private volatile Result latest;
    /** The last result every listener has been handed (what {@link #awaitCurrent} waits for). */
    private Result delivered;

    public PathChecker(WorkbenchModel model, long debounceMs) {
        this.model = model;
        this.debounceMs = debounceMs;
        this.exec = Executors.newSingleThreadScheduledExecutor(r -> {
            Thread t = new Thread(r, "path-check");
            t.setDaemon(true);
            t.setPriority(Thread.NORM_PRIORITY - 1); // rendering and the UI come first
            return t;
        });
        this.modelListener = c -> {
            if (c != WorkbenchModel.Change.JOINTS && c != WorkbenchModel.Change.SELECTION && c != WorkbenchModel.Change.VIEW) request();
        };
        model.addListener(modelListener);
        request();
    }

    /** Told about every finished check, on the checker's thread. */
    public void addListener(Consumer<Result> l) { listeners.add(l); }

    /** The last finished check (null before the first); it may lag the model by one debounce and one check. */
    public Result latest() { return latest; }

    /** How many checks ran (a burst of edits runs one). */
    public long checks() { return checks.get(); }

    /** Asks for a check after the debounce delay (a pending one is pushed back). */
    public synchronized void request() {
        long id = requested.incrementAndGet();
        if (pending != null) pending.cancel(false);
        if (exec.isShutdown()) return;
        pending = exec.schedule(() -> check(id), debounceMs, TimeUnit.MILLISECONDS);
    }

    private void check(long id) {
        try {
            // Snapshots first: the run and statuses are computed from the same model version; the
            // program is the one the run checked, so its results are never shown beside another.
            List<Target> targets = model.targets();
            ProgramRun run = model.programRun();
            List<Instruction> program = run.program();
            Map<String, TargetStatus> st = Map.copyOf(model.statuses(run));
            Result r = new Result(id, run, st, targets, program);
            checks.incrementAndGet();
            // Published before the listeners run: a listener that hands the news to another
            // thread (the UI's invokeLater) must find this result as latest() there, not the one
            // before it (it would show the previous program's results beside this one).
            latest = r;
            for (Consumer<Result> l : listeners) {
                try {
                    l.accept(r);
                } catch (RuntimeException e) {
                    LOG.log(Level.WARNING, "path check listener failed", e);
                }
            }
            // Delivered after the listeners: a caller of awaitCurrent (a screenshot, a test) must
            // find the result already handed to the scene and the UI, not on its way there.
            synchronized (this) {
                delivered = r;
                notifyAll();
            }
        } catch (RuntimeException e) {
            // A failing check must not stop later ones; the next edit tries again.
            LOG.log(Level.WARNING, "path check failed", e);
            synchronized (this) { notifyAll(); }
        }
    }

    /**
     * Waits until a check has finished, and been delivered to every listener, that started after
     * the last request (for tests and screenshots); returns it, or null on timeout.
     */
    public Result awaitCurrent(long timeoutMs) throws InterruptedException {
        long end = System.currentTimeMillis() + timeoutMs;
        synchronized (this) {
            while (delivered == null || delivered.request() < requested.get()) {
                long left = end - System.currentTimeMillis();
                if (left <= 0) return null;
                wait(left);
            }
            return delivered;
        }
    }

    @Override
    public void close() {
        model.removeListener(modelListener);
        exec.shutdownNow();
    }
}
