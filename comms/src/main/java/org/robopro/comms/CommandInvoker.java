package org.robopro.comms;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The Invoker of the seed paper's Command pattern (§2.1, Fig. 3): a queue of commands run one
 * at a time against a {@link ControllerReceiver}, with a bounded history, listeners,
 * cancellation, a reply timeout per command, and retries only where they are safe
 * ({@link ControllerCommand#mayRetry}): a motion is re-sent only to a receiver that
 * de-duplicates request ids, so it never executes twice; when it cannot be re-sent its future
 * fails saying the outcome is unknown, so it is never lost silently.
 *
 * <p>Each submitted command's result or failure completes its {@link CompletableFuture}.
 * Thread-safe; the receiver is only touched by the one worker thread.
 */
public final class CommandInvoker implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(CommandInvoker.class);
    private static final AtomicInteger THREADS = new AtomicInteger();

    /**
     * @param replyTimeout timeout for each reply, unless the submit call gives one
     * @param maxRetries   how many times a command may be re-sent after a timeout or link failure
     * @param retryDelay   pause before a retry (the link reconnects in between)
     * @param historySize  how many final records the history keeps
     */
    public record Options(Duration replyTimeout, int maxRetries, Duration retryDelay, int historySize) {
        public Options {
            if (replyTimeout.isNegative() || replyTimeout.isZero() || maxRetries < 0 || retryDelay.isNegative()
                    || historySize < 1)
                throw new IllegalArgumentException("bad invoker options: " + replyTimeout + ", " + maxRetries + ", "
                        + retryDelay + ", " + historySize);
        }

        public static final Options DEFAULT = new Options(Duration.ofSeconds(5), 3, Duration.ofMillis(100), 1000);

        public Options withReplyTimeout(Duration d) { return new Options(d, maxRetries, retryDelay, historySize); }

        public Options withMaxRetries(int n) { return new Options(replyTimeout, n, retryDelay, historySize); }

        public Options withRetryDelay(Duration d) { return new Options(replyTimeout, maxRetries, d, historySize); }
    }

    private final ControllerReceiver receiver;
    private final Options options;
    private final ExecutorService worker;
    private final List<CommandListener> listeners = new CopyOnWriteArrayList<>();
    private final ArrayDeque<CommandRecord> history = new ArrayDeque<>();
    private final Set<CompletableFuture<?>> pending = ConcurrentHashMap.newKeySet(); // queued, not yet started
    private volatile boolean closed;

    public CommandInvoker(ControllerReceiver receiver, Options options) {
        this.receiver = receiver;
        this.options = options;
        this.worker = Executors.newSingleThreadExecutor(r -> {
            Thread t = new Thread(r, "robopro-invoker-" + THREADS.incrementAndGet());
            t.setDaemon(true);
            return t;
        });
    }

    public CommandInvoker(ControllerReceiver receiver) { this(receiver, Options.DEFAULT); }

    public Options options() { return options; }

    public void addListener(CommandListener l) { listeners.add(l); }

    public void removeListener(CommandListener l) { listeners.remove(l); }

    /** Queues a command with the default reply timeout. */
    public <T> CompletableFuture<T> submit(ControllerCommand<T> command) {
        return submit(command, options.replyTimeout());
    }

    /**
     * Queues a command. The future completes with its result, or exceptionally with a
     * {@link CommsException} (or {@link java.util.concurrent.CancellationException} if cancelled
     * before it was sent). Cancelling the future of a command already sent does not stop the
     * controller; send {@link Commands#stopProgram()} for that.
     */
    public <T> CompletableFuture<T> submit(ControllerCommand<T> command, Duration replyTimeout) {
        if (closed) throw new IllegalStateException("invoker closed");
        CompletableFuture<T> future = new CompletableFuture<>();
        pending.add(future);
        future.whenComplete((v, e) -> pending.remove(future));
        emit(command, CommandRecord.State.QUEUED, 0, "");
        worker.execute(() -> run(command, replyTimeout, future));
        return future;
    }

    /** Runs a command and waits for it: the convenient blocking form. */
    public <T> T execute(ControllerCommand<T> command) {
        try {
            return submit(command).join();
        } catch (java.util.concurrent.CompletionException e) {
            if (e.getCause() instanceof RuntimeException re) throw re;
            throw e;
        }
    }

    /** Cancels every command not yet sent; returns how many were cancelled. */
    public int cancelPending() {
        int n = 0;
        for (CompletableFuture<?> f : List.copyOf(pending)) if (f.cancel(false)) n++;
        return n;
    }

    /** The latest final records (succeeded, failed, cancelled), oldest first. */
    public List<CommandRecord> history() {
        synchronized (history) {
            return new ArrayList<>(history);
        }
    }

    private <T> void run(ControllerCommand<T> command, Duration replyTimeout, CompletableFuture<T> future) {
        pending.remove(future); // from here on it is running, no longer "pending"
        if (future.isDone()) {
            emit(command, CommandRecord.State.CANCELLED, 0, "cancelled before it was sent");
            return;
        }
        int attempt = 1;
        while (true) {
            emit(command, CommandRecord.State.RUNNING, attempt, "");
            try {
                receiver.setReplyTimeout(replyTimeout);
                T result = command.execute(receiver);
                // History first, then the future: a caller that sees the result also sees the record.
                emit(command, CommandRecord.State.SUCCEEDED, attempt, describeResult(result));
                if (!future.complete(result))
                    LOG.info("{} finished after its future was cancelled", command.describe());
                return;
            } catch (CommsException.Timeout | CommsException.LinkDown | CommsException.Protocol e) {
                boolean retry = attempt <= options.maxRetries() && command.mayRetry(receiver) && !closed;
                if (!retry) {
                    String why = !command.mayRetry(receiver)
                            ? " (not re-sent: the controller does not de-duplicate requests, so whether it executed is unknown)"
                            : " (after " + attempt + " attempt" + (attempt > 1 ? "s" : "") + ")";
                    fail(command, future, attempt, copyWithContext(e, command.describe() + " failed: " + e.getMessage() + why));
                    return;
                }
                emit(command, CommandRecord.State.RETRYING, attempt, e.getMessage());
                attempt++;
                if (!pause(options.retryDelay())) {
                    fail(command, future, attempt, e);
                    return;
                }
                try {
                    receiver.reconnect();
                } catch (CommsException re) {
                    LOG.debug("reconnect failed before retry of {}: {}", command.describe(), re.getMessage());
                }
            } catch (RuntimeException e) {
                fail(command, future, attempt, e);
                return;
            }
        }
    }

    private static CommsException copyWithContext(CommsException e, String message) {
        CommsException c;
        if (e instanceof CommsException.Timeout) c = new CommsException.Timeout(message);
        else if (e instanceof CommsException.LinkDown) c = new CommsException.LinkDown(message, e);
        else c = new CommsException.Protocol(message);
        if (c.getCause() == null) c.initCause(e);
        return c;
    }

    private static boolean pause(Duration d) {
        try {
            Thread.sleep(d.toMillis());
            return true;
        } catch (InterruptedException ie) {
            Thread.currentThread().interrupt();
            return false;
        }
    }

    private <T> void fail(ControllerCommand<T> command, CompletableFuture<T> future, int attempt, RuntimeException e) {
        emit(command, CommandRecord.State.FAILED, attempt, e.getMessage() == null ? e.toString() : e.getMessage());
        future.completeExceptionally(e);
    }

    private static String describeResult(Object result) {
        if (result == null) return "ok";
        if (result instanceof double[] d) return Commands.degrees(d);
        if (result instanceof byte[] b) return b.length + " bytes";
        if (result instanceof org.robopro.kinematics.Pose p) return Commands.pose(p);
        return result.toString();
    }

    private void emit(ControllerCommand<?> command, CommandRecord.State state, int attempt, String detail) {
        CommandRecord rec = new CommandRecord(command.requestId(), command.describe(), state, attempt, Instant.now(), detail);
        if (state.isFinal()) {
            synchronized (history) {
                history.addLast(rec);
                while (history.size() > options.historySize()) history.removeFirst();
            }
        }
        if (state == CommandRecord.State.FAILED || state == CommandRecord.State.RETRYING) LOG.info("{}", rec);
        else LOG.debug("{}", rec);
        for (CommandListener l : listeners) {
            try {
                l.onCommandEvent(rec);
            } catch (RuntimeException ex) {
                LOG.warn("command listener threw", ex);
            }
        }
    }

    /** Cancels pending commands, waits briefly for the running one, and stops the worker. */
    @Override
    public void close() {
        closed = true;
        cancelPending();
        worker.shutdown();
        try {
            if (!worker.awaitTermination(2, TimeUnit.SECONDS)) worker.shutdownNow();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            worker.shutdownNow();
        }
    }
}
