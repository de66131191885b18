package org.robopro.app.cli;

import java.io.PrintWriter;
import java.util.Locale;
import org.robopro.calibration.Cancellation;
import org.robopro.calibration.Progress;
import org.robopro.kinematics.Pose;
import org.robopro.kinematics.Units;

/** Small helpers shared by the calibration commands: parsing mm/deg lists, a progress bar, Ctrl-C. */
final class CliSupport {
    private CliSupport() { }

    /** Parses "a,b,c" into numbers, naming the option in the error. */
    static double[] numbers(String option, String text, int... allowedCounts) {
        String[] parts = text.split(",");
        double[] v = new double[parts.length];
        for (int i = 0; i < parts.length; i++) {
            try {
                v[i] = Double.parseDouble(parts[i].trim());
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException(option + ": '" + parts[i].trim() + "' is not a number");
            }
            if (!Double.isFinite(v[i])) throw new IllegalArgumentException(option + ": values must be finite");
        }
        for (int c : allowedCounts) if (c == v.length) return v;
        throw new IllegalArgumentException(option + ": expected " + java.util.Arrays.toString(allowedCounts)
                .replace("[", "").replace("]", "").replace(", ", " or ") + " comma-separated values, got " + v.length);
    }

    /** "x,y,z" (mm) or "x,y,z,qw,qx,qy,qz" as a pose. */
    static Pose poseMm(String option, String text) {
        double[] v = numbers(option, text, 3, 7);
        if (v.length == 3) return Pose.translation(Units.mmToM(v[0]), Units.mmToM(v[1]), Units.mmToM(v[2]));
        return Pose.fromQuaternion(v[3], v[4], v[5], v[6], Units.mmToM(v[0]), Units.mmToM(v[1]), Units.mmToM(v[2]));
    }

    /** A text progress bar on stderr (only when attached to a terminal, so logs stay clean). */
    static Progress progressBar(PrintWriter err) {
        if (System.console() == null) return Progress.NONE;
        return new Progress() {
            @Override
            public synchronized void update(String stage, double fraction) {
                int w = 30, k = (int) Math.round(Math.max(0, Math.min(1, fraction)) * w);
                err.printf(Locale.ROOT, "\r[%s%s] %3.0f%% %-20s", "#".repeat(k), " ".repeat(w - k), fraction * 100, stage);
                if (fraction >= 1) err.println();
                err.flush();
            }
        };
    }

    /** Cancels {@code token} on Ctrl-C and gives the work a moment to stop cleanly. Returns the hook to remove. */
    static Thread cancelOnInterrupt(Cancellation token, Thread worker) {
        Thread hook = new Thread(() -> {
            token.cancel();
            try {
                worker.join(3000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, "robopro-cancel");
        Runtime.getRuntime().addShutdownHook(hook);
        return hook;
    }

    static void removeHook(Thread hook) {
        try {
            Runtime.getRuntime().removeShutdownHook(hook);
        } catch (IllegalStateException shuttingDown) {
            // the JVM is already exiting (Ctrl-C): nothing to remove
        }
    }
}
