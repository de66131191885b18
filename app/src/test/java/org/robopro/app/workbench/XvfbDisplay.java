package org.robopro.app.workbench;

import static org.junit.jupiter.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * An X display for the workbench tests: $DISPLAY when set, else a private Xvfb on a free
 * display number. Without either, the test fails when CI=true (CI must install xvfb, see
 * .ci/install-deps) and is skipped otherwise.
 */
final class XvfbDisplay implements AutoCloseable {
    private final String display;
    private final Process xvfb;

    private XvfbDisplay(String display, Process xvfb) {
        this.display = display;
        this.xvfb = xvfb;
    }

    String display() { return display; }

    static XvfbDisplay acquire() throws Exception {
        String env = System.getenv("DISPLAY");
        if (env != null && !env.isBlank()) return new XvfbDisplay(env, null);
        String exe = onPath("Xvfb");
        if (exe == null) {
            if ("true".equalsIgnoreCase(System.getenv("CI")))
                fail("Xvfb is not installed and DISPLAY is unset: the workbench tests need it on CI (apt-get install xvfb xauth libgl1-mesa-dri)");
            assumeTrue(false, "no DISPLAY and no Xvfb: workbench tests skipped");
        }
        for (int n = 91; n < 140; n++) {
            if (Files.exists(Path.of("/tmp/.X11-unix/X" + n)) || Files.exists(Path.of("/tmp/.X" + n + "-lock"))) continue;
            Process p = new ProcessBuilder(exe, ":" + n, "-screen", "0", "1920x1200x24", "-nolisten", "tcp")
                    .redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
            for (int i = 0; i < 100 && p.isAlive(); i++) {
                if (Files.exists(Path.of("/tmp/.X11-unix/X" + n))) return new XvfbDisplay(":" + n, p);
                Thread.sleep(50);
            }
            p.destroy();
        }
        throw new IllegalStateException("could not start Xvfb on any display :91..:139");
    }

    private static String onPath(String exe) {
        for (String dir : System.getenv().getOrDefault("PATH", "/usr/bin").split(File.pathSeparator)) {
            File f = new File(dir, exe);
            if (f.canExecute()) return f.getPath();
        }
        return null;
    }

    @Override
    public void close() {
        if (xvfb != null) xvfb.destroy();
    }
}
