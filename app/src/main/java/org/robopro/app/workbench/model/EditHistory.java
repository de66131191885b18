package org.robopro.app.workbench.model;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.CopyOnWriteArrayList;

/**
 * Undo and redo for every edit of the workbench, in the order the user made them. Each edit is
 * a command that knows the state before and after it and is undone by restoring the one and
 * redone by restoring the other. Project edits keep {@link ProjectData} without the joint values
 * (jogging is not an edit); an editor outside the project (the robot model wizard) records its
 * own immutable states with the {@link Editor} that puts them back, so Edit &gt; Undo takes back
 * the last edit whichever of them it was. States are immutable, so a command costs a few
 * references. Edits with the same label by the same editor in quick succession (a spinner held
 * down, a drag) merge into one command.
 */
public final class EditHistory {
    /** Something outside the project whose edits share this history: it puts one of its states back. */
    @FunctionalInterface
    public interface Editor<S> {
        void restore(S state);
    }

    /** One undoable edit; {@code editor} is null for a project edit (states are {@link ProjectData}). */
    public record Command(String label, Object before, Object after, long atMillis, Editor<Object> editor) {
        /** True for an edit of the project (cell, tool, targets, program, robot). */
        public boolean project() { return editor == null; }
    }

    /** Edits with the same label closer together than this are one command. */
    public static final long MERGE_MS = 800;
    /** Commands kept; the oldest are forgotten first. */
    public static final int LIMIT = 200;

    private final Deque<Command> undo = new ArrayDeque<>();
    private final Deque<Command> redo = new ArrayDeque<>();
    private final List<Runnable> listeners = new CopyOnWriteArrayList<>();
    private boolean mergeable = true;

    /** {@code l} runs (on the thread that changed it) whenever the history changes: Undo and Redo rename themselves. */
    public void addListener(Runnable l) { listeners.add(l); }

    private void changed() { for (Runnable l : listeners) l.run(); }

    /** Records a project edit; clears the redo stack. */
    void push(String label, ProjectData before, ProjectData after, long now) { add(label, before, after, now, null); }

    /**
     * Records an edit made outside the project by {@code editor} (its state {@code before} and
     * {@code after}); clears the redo stack. Undo hands {@code before} back to the editor.
     */
    @SuppressWarnings("unchecked")
    public <S> void push(String label, S before, S after, Editor<S> editor) {
        add(label, before, after, System.currentTimeMillis(), (Editor<Object>) editor);
    }

    private void add(String label, Object before, Object after, long now, Editor<Object> editor) {
        synchronized (this) {
            redo.clear();
            Command top = undo.peek();
            if (mergeable && top != null && top.label().equals(label) && top.editor() == editor && now - top.atMillis() < MERGE_MS) {
                undo.pop();
                undo.push(new Command(label, top.before(), after, now, editor));
            } else {
                undo.push(new Command(label, before, after, now, editor));
                while (undo.size() > LIMIT) undo.removeLast();
                mergeable = true;
            }
        }
        changed();
    }

    Optional<Command> popUndo() { return move(undo, redo); }

    Optional<Command> popRedo() { return move(redo, undo); }

    private Optional<Command> move(Deque<Command> from, Deque<Command> to) {
        Command c;
        synchronized (this) {
            c = from.poll();
            if (c != null) to.push(c);
            mergeable = false;
        }
        if (c != null) changed();
        return Optional.ofNullable(c);
    }

    /** Forgets everything (a project was opened or created). */
    void clear() {
        synchronized (this) {
            undo.clear();
            redo.clear();
        }
        changed();
    }

    /** The label of the edit Undo would take back, if any. */
    public synchronized Optional<String> undoLabel() { return Optional.ofNullable(undo.peek()).map(Command::label); }

    /** The label of the edit Redo would make again, if any. */
    public synchronized Optional<String> redoLabel() { return Optional.ofNullable(redo.peek()).map(Command::label); }

    public synchronized int undoSize() { return undo.size(); }
}
