package org.robopro.comms;

/**
 * Told about every step of every command (the GUI shows them). Called on the invoker's worker
 * thread; implementations hand work to their own thread (e.g. {@code app.enqueue}) and return fast.
 */
@FunctionalInterface
public interface CommandListener {
    void onCommandEvent(CommandRecord record);
}
