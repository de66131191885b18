package org.robopro.app.workbench.model;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.Optional;

/**
 * Undo and redo for the workbench's edits. Each edit is a command that knows the project state
 * before and after it ({@link ProjectData} without the joint values: jogging is not an edit) and
 * is undone by restoring the one and redone by restoring the other; the model's state is made of
 * immutable lists, so a command costs a few references. Edits with the same label in quick
 * succession (a spinner held down, a drag) merge into one command.
 */
public final class EditHistory {
    /** One undoable edit. */
    public record Command(String label, ProjectData before, ProjectData after, long atMillis) { }

    /** Edits with the same label closer together than this are one command. */
    public static final long MERGE_MS = 800;
    /** Commands kept; the oldest are forgotten first. */
    public static final int LIMIT = 200;

    private final Deque<Command> undo = new ArrayDeque<>();
    private final Deque<Command> redo = new ArrayDeque<>();
    private boolean mergeable = true;

    /** Records an edit; clears the redo stack. */
    synchronized void push(String label, ProjectData before, ProjectData after, long now) {
        redo.clear();
        Command top = undo.peek();
        if (mergeable && top != null && top.label().equals(label) && now - top.atMillis() < MERGE_MS) {
            undo.pop();
            undo.push(new Command(label, top.before(), after, now));
            return;
        }
        undo.push(new Command(label, before, after, now));
        while (undo.size() > LIMIT) undo.removeLast();
        mergeable = true;
    }

    synchronized Optional<Command> popUndo() {
        Command c = undo.poll();
        if (c != null) redo.push(c);
        mergeable = false;
        return Optional.ofNullable(c);
    }

    synchronized Optional<Command> popRedo() {
        Command c = redo.poll();
        if (c != null) undo.push(c);
        mergeable = false;
        return Optional.ofNullable(c);
    }

    /** Forgets everything (a project was opened or created). */
    synchronized void clear() {
        undo.clear();
        redo.clear();
    }

    /** The label of the edit Undo would take back, if any. */
    public synchronized Optional<String> undoLabel() { return Optional.ofNullable(undo.peek()).map(Command::label); }

    /** The label of the edit Redo would make again, if any. */
    public synchronized Optional<String> redoLabel() { return Optional.ofNullable(redo.peek()).map(Command::label); }

    public synchronized int undoSize() { return undo.size(); }
}
