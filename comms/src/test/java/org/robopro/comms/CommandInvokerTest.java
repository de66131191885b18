package org.robopro.comms;

import static org.junit.jupiter.api.Assertions.*;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CancellationException;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionException;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.robopro.comms.sim.TestSupport;

class CommandInvokerTest {
    private static final CommandInvoker.Options FAST = CommandInvoker.Options.DEFAULT.withRetryDelay(Duration.ZERO).withMaxRetries(3);

    /** A command that times out {@code failures} times, then succeeds; counts executions. */
    static final class Flaky extends ControllerCommand<String> {
        final AtomicInteger runs = new AtomicInteger();
        final int failures;

        Flaky(RetryPolicy p, int failures) {
            super("flaky", p);
            this.failures = failures;
        }

        @Override public String execute(ControllerReceiver r) {
            if (runs.incrementAndGet() <= failures) throw new CommsException.Timeout("no answer");
            return "done";
        }
    }

    @Test
    void submit_safeCommandTimesOutTwice_retriedAndSucceeds() {
        try (CommandInvoker inv = new CommandInvoker(TestSupport.gantryController(0), FAST)) {
            Flaky f = new Flaky(ControllerCommand.RetryPolicy.SAFE, 2);
            assertEquals("done", inv.execute(f));
            assertEquals(3, f.runs.get());
            assertEquals(3, inv.history().get(0).attempt());
        }
    }

    @Test
    void submit_neverRetriedCommandTimesOut_failsAfterOneAttempt() {
        try (CommandInvoker inv = new CommandInvoker(TestSupport.gantryController(0), FAST)) {
            Flaky f = new Flaky(ControllerCommand.RetryPolicy.NEVER, 1);
            CompletionException e = assertThrows(CompletionException.class, () -> inv.submit(f).join());
            assertInstanceOf(CommsException.Timeout.class, e.getCause());
            assertTrue(e.getCause().getMessage().contains("unknown"), e.getCause().getMessage());
            assertEquals(1, f.runs.get());
        }
    }

    @Test
    void submit_retriesExhausted_failsWithAttemptCount() {
        try (CommandInvoker inv = new CommandInvoker(TestSupport.gantryController(0), FAST)) {
            Flaky f = new Flaky(ControllerCommand.RetryPolicy.SAFE, 100);
            CompletionException e = assertThrows(CompletionException.class, () -> inv.submit(f).join());
            assertEquals(4, f.runs.get());
            assertTrue(e.getCause().getMessage().contains("after 4 attempts"), e.getCause().getMessage());
        }
    }

    @Test
    void cancelPending_queuedCommands_cancelledAndNeverExecuted() throws Exception {
        CountDownLatch release = new CountDownLatch(1);
        ControllerCommand<Void> blocker = new ControllerCommand<>("block", ControllerCommand.RetryPolicy.SAFE) {
            @Override public Void execute(ControllerReceiver r) {
                try {
                    release.await(5, TimeUnit.SECONDS);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
                return null;
            }
        };
        var sim = TestSupport.gantryController(0);
        try (CommandInvoker inv = new CommandInvoker(sim, FAST)) {
            List<CommandRecord> events = new ArrayList<>();
            inv.addListener(events::add);
            CompletableFuture<Void> first = inv.submit(blocker);
            List<CompletableFuture<MotionResult>> queued = new ArrayList<>();
            for (int i = 0; i < 5; i++) queued.add(inv.submit(Commands.moveJoints(new double[] {0.1 * (i + 1), 0, 0, 0, 0, 0})));
            Thread.sleep(50);
            assertEquals(5, inv.cancelPending());
            release.countDown();
            first.get(5, TimeUnit.SECONDS);
            for (var f : queued) assertThrows(CancellationException.class, f::join);
            Thread.sleep(100);
            assertEquals(0, sim.motionsExecuted());
            synchronized (events) {
                assertEquals(5, events.stream().filter(r -> r.state() == CommandRecord.State.CANCELLED).count());
                assertEquals(CommandRecord.State.QUEUED, events.get(0).state());
            }
        }
    }

    @Test
    void listener_successfulCommand_seesQueuedRunningSucceededInOrder() {
        try (CommandInvoker inv = new CommandInvoker(TestSupport.gantryController(0), FAST)) {
            List<CommandRecord.State> states = new java.util.concurrent.CopyOnWriteArrayList<>();
            inv.addListener(r -> states.add(r.state()));
            inv.execute(Commands.ping());
            assertEquals(List.of(CommandRecord.State.QUEUED, CommandRecord.State.RUNNING, CommandRecord.State.SUCCEEDED), states);
        }
    }
}
