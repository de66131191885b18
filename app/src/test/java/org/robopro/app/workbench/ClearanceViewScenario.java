package org.robopro.app.workbench;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Properties;
import java.util.concurrent.atomic.AtomicBoolean;
import org.robopro.app.workbench.ui.WorkbenchWindow;

/**
 * Run in a child JVM by {@link ClearanceViewTest}: opens the workbench on the welding cell, jogs
 * the torch down onto the plates until the live view reports a collision, and saves the window
 * with the collision view on and, at the same pose, off; results go to results.properties.
 */
public final class ClearanceViewScenario {
    public static void main(String[] args) throws Exception {
        Path out = Path.of(args[0]);
        Files.createDirectories(out);
        Properties r = new Properties();
        WorkbenchWindow win = WorkbenchWindow.open(WorkbenchWindow.Options.defaults().withSize(1280, 720));
        try {
            var wb = win.session();
            var app = win.app();
            r.setProperty("readyText", wb.clearance().current().map(LiveClearance.Reading::text).orElse("none"));
            AtomicBoolean hit = new AtomicBoolean();
            for (int i = 0; i < 200 && !hit.get(); i++) {
                WorkbenchWindow.onEdt(() -> wb.jogCartesian(WorkbenchSession.JogFrame.WORLD, 0, 0, -0.005, 0, 0, 0));
                hit.set(wb.clearance().current().map(LiveClearance.Reading::colliding).orElse(false));
            }
            app.awaitFrames(6, 10_000);
            WorkbenchWindow.onEdt(() -> win.frame().refreshStatus());
            var reading = wb.clearance().current().orElseThrow();
            r.setProperty("text", reading.text());
            r.setProperty("highlights", reading.highlights().toString());
            r.setProperty("shown", app.clearanceState().shown().map(x -> x.highlights().toString()).orElse("none"));
            win.screenshot(out.resolve("collision-on.png"));
            app.enqueue(() -> app.clearanceState().setEnabled(false));
            app.awaitFrames(4, 10_000);
            win.screenshot(out.resolve("collision-off.png"));
            r.setProperty("status", "done");
        } catch (Throwable t) {
            r.setProperty("status", "failed: " + t);
            t.printStackTrace();
        } finally {
            try (var w = Files.newBufferedWriter(out.resolve("results.properties"))) {
                r.store(w, "clearance view");
            }
            win.close();
        }
        System.exit(0);
    }
}
