package org.robopro.app.demo;

import java.io.PrintWriter;
import java.util.Locale;

/**
 * What the demo prints: numbered steps, indented details, and a progress bar for slow parts
 * (redrawn in place on a terminal; on a log only the finished line is written).
 */
final class Console {
    private final PrintWriter out;
    private final boolean terminal;
    private final long startNs = System.nanoTime();
    private long stepNs = startNs;

    Console(PrintWriter out, boolean terminal) {
        this.out = out;
        this.terminal = terminal;
    }

    double elapsedS() { return (System.nanoTime() - startNs) / 1e9; }

    void step(int k, String title) {
        stepNs = System.nanoTime();
        out.printf(Locale.ROOT, "%n[%d/5] %s%n", k, title);
        out.flush();
    }

    void line(String format, Object... args) {
        out.printf(Locale.ROOT, "      " + format + "%n", args);
        out.flush();
    }

    /** Seconds since the current step started. */
    double stepS() { return (System.nanoTime() - stepNs) / 1e9; }

    /** A progress bar for {@code total} items. */
    Bar bar(String what, int total) { return new Bar(what, total); }

    final class Bar {
        private final String what;
        private final int total;
        private int shown = -1;

        Bar(String what, int total) {
            this.what = what;
            this.total = Math.max(1, total);
        }

        void update(int done) {
            if (!terminal) return;
            int w = 30, k = (int) Math.round(Math.min(1.0, (double) done / total) * w);
            if (k == shown && done < total) return;
            shown = k;
            out.printf(Locale.ROOT, "\r      [%s%s] %d/%d %s", "#".repeat(k), " ".repeat(w - k), done, total, what);
            out.flush();
        }

        /** Ends the bar with a summary line. */
        void done(String format, Object... args) {
            if (terminal) out.print("\r" + " ".repeat(50 + what.length()) + "\r");
            line(format, args);
        }
    }
}
