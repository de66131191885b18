package org.robopro.app.cli;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import javax.swing.JOptionPane;
import org.robopro.app.workbench.ProjectStore;
import org.robopro.app.workbench.ui.WorkbenchWindow;
import org.robopro.app.workbench.model.Instruction;
import org.robopro.app.workbench.model.Target;
import org.robopro.models.InputException;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code robopro workbench}: opens the desktop workbench (also what {@code robopro} with no
 * arguments does); with {@code --screenshot} renders once, saves a PNG of the whole window and
 * exits; with {@code --benchmark} measures the start-up time and frame rate.
 * Exit codes: 0 fine, 2 bad input, 3 the 3D view could not start (no OpenGL context).
 */
@Command(name = "workbench", mixinStandardHelpOptions = true,
        description = "Open the 3D workbench (cell layout, jogging, teaching, programs).")
public final class WorkbenchCommand implements Callable<Integer> {
    @Option(names = "--project", paramLabel = "FILE", description = "Project file to open (default: the IRB-2000 welding cell).")
    Path project;

    @Option(names = "--screenshot", paramLabel = "FILE", description = "Render, save a PNG of the whole window, exit.")
    Path screenshot;

    @Option(names = "--size", paramLabel = "WxH", defaultValue = "1280x720", description = "Window size (default ${DEFAULT-VALUE}).")
    String size;

    @Option(names = "--benchmark", description = "Measure time to first frame and frames per second, print them, exit.")
    boolean benchmark;

    @Option(names = "--benchmark-seconds", defaultValue = "6", description = "Measuring time of --benchmark (default ${DEFAULT-VALUE} s).")
    double benchmarkSeconds;

    @Option(names = "--benchmark-moves", defaultValue = "0", paramLabel = "N",
            description = "With --benchmark: a program of N MoveL/MoveC instructions, edited twice a second while the robot "
                    + "moves, so the background path check runs during the measurement (default ${DEFAULT-VALUE}).")
    int benchmarkMoves;

    @Option(names = "--no-shadows", description = "Start with shadows off (View → Shadows), e.g. to compare frame rates.")
    boolean noShadows;

    @Option(names = "--benchmark-shadows-ab",
            description = "With --benchmark: switch shadows on and off every second and report both frame rates "
                    + "(the two halves see the same machine load).")
    boolean shadowsAb;

    @Option(names = "--benchmark-edits", defaultValue = "2", paramLabel = "N",
            description = "With --benchmark-moves: edits per second (0: the program is drawn but never edited; default ${DEFAULT-VALUE}).")
    double benchmarkEdits;

    @Option(names = "--first-frame-timeout", defaultValue = "20", paramLabel = "S",
            description = "Fail when no frame is drawn within S seconds (default ${DEFAULT-VALUE}).")
    double firstFrameTimeout;

    @Spec CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        int[] wh = parseSize(size);
        if (java.awt.GraphicsEnvironment.isHeadless()) {
            spec.commandLine().getErr().println("robopro workbench: no display (DISPLAY is unset or java.awt.headless is true); "
                    + "run under a desktop or Xvfb (e.g. xvfb-run ./robopro workbench ...)");
            return 3;
        }
        boolean interactive = screenshot == null && !benchmark;
        Path open = project;
        if (interactive) open = offerRecovery(project).orElse(project);
        WorkbenchWindow.Options o = WorkbenchWindow.Options.defaults().withSize(wh[0], wh[1]).withProject(open)
                .withFrameRateCap(benchmark ? -1 : 60);
        o = new WorkbenchWindow.Options(o.width(), o.height(), o.project(), o.visible(), o.frameRateCap(), (long) (firstFrameTimeout * 1000));
        WorkbenchWindow wb;
        try {
            wb = WorkbenchWindow.open(o);
        } catch (IllegalStateException e) {
            spec.commandLine().getErr().println("robopro workbench: " + e.getMessage());
            return 3;
        }
        if (noShadows) wb.session().model().setShadows(false);
        if (interactive) wb.enableShadowFallback(30);
        if (interactive) {
            new CountDownLatch(1).await(); // the window's Exit action ends the process
            return 0;
        }
        try {
            if (benchmark) benchmark(wb);
            if (screenshot != null) {
                wb.screenshot(screenshot);
                spec.commandLine().getOut().println("robopro workbench: saved " + screenshot.toAbsolutePath());
            }
        } catch (IllegalStateException e) {
            spec.commandLine().getErr().println("robopro workbench: " + e.getMessage());
            return 3;
        } finally {
            wb.close();
        }
        return 0;
    }

    private void benchmark(WorkbenchWindow wb) throws InterruptedException {
        double first = wb.secondsToFirstFrame();
        // Keep the robot moving so every frame re-poses the links, as when jogging or playing.
        double[] q0 = wb.session().model().q();
        List<Instruction> program = benchmarkMoves > 0 ? longProgram(wb, benchmarkMoves) : List.of();
        long checks0 = wb.session().pathChecker().checks();
        Thread.sleep(1500);
        long[] cpu0 = threadCpu();
        long f0 = wb.app().frameCount();
        long t0 = System.nanoTime();
        long end = t0 + (long) (benchmarkSeconds * 1e9);
        // A/B: window k (1 s) has shadows on when k is even; its first 0.25 s settles and is not counted.
        long[] abFrames = new long[2];
        double[] abSecs = new double[2];
        double[] abCpu = new double[2];
        int abWindow = -1;
        long abF = 0, abT = 0, abC = 0;
        long pcpu0 = processCpu();
        boolean abCounting = false;
        while (System.nanoTime() < end) {
            double t = (System.nanoTime() - t0) / 1e9;
            if (shadowsAb) {
                int w = (int) t;
                if (w != abWindow) {
                    if (abCounting) {
                        abFrames[abWindow % 2] += wb.app().frameCount() - abF;
                        abSecs[abWindow % 2] += (System.nanoTime() - abT) / 1e9;
                        abCpu[abWindow % 2] += (processCpu() - abC) / 1e6;
                    }
                    abWindow = w;
                    abCounting = false;
                    wb.session().model().setShadows(w % 2 == 0);
                } else if (!abCounting && t - w >= 0.25) {
                    abCounting = true;
                    abF = wb.app().frameCount();
                    abT = System.nanoTime();
                    abC = processCpu();
                }
            }
            double[] q = q0.clone();
            q[0] += Math.toRadians(30) * Math.sin(t);
            wb.session().model().setQ(q);
            long tick = (long) (benchmarkEdits * t);
            if (!program.isEmpty() && benchmarkEdits > 0 && tick != editTick) {
                // An edit every 1/benchmarkEdits s (a speed change): each one starts a background path check.
                editTick = tick;
                List<Instruction> p = new ArrayList<>(program);
                Instruction i = p.get((int) (tick % p.size()));
                p.set((int) (tick % p.size()), new Instruction(i.type(), i.target(), 100 + 50 * (tick % 5), i.zoneMm(), i.via()));
                WorkbenchWindow.onEdt(() -> wb.session().model().setProgram(p));
            }
            Thread.sleep(16); // a jog or playback update per 60 Hz frame
        }
        long frames = wb.app().frameCount() - f0;
        double secs = (System.nanoTime() - t0) / 1e9;
        long[] cpu1 = threadCpu();
        long pcpu1 = processCpu();
        spec.commandLine().getOut().printf(Locale.ROOT, "workbench benchmark: size %s, first frame after %.2f s, %.1f fps (%d frames in %.1f s)%s%n",
                size, first, frames / secs, frames, secs, program.isEmpty() ? ""
                        : String.format(Locale.ROOT, "; program of %d moves, %d background path checks", program.size(),
                        wb.session().pathChecker().checks() - checks0));
        // CPU time per thread over the measurement: steadier than the frame rate when other work shares the machine.
        spec.commandLine().getOut().printf(Locale.ROOT, "workbench benchmark: CPU in %.1f s: path-check thread %.0f ms, render thread %.0f ms, Swing thread %.0f ms%n",
                secs, (cpu1[0] - cpu0[0]) / 1e6, (cpu1[1] - cpu0[1]) / 1e6, (cpu1[2] - cpu0[2]) / 1e6);
        spec.commandLine().getOut().printf(Locale.ROOT, "workbench benchmark: process CPU %.2f ms per frame%n", (pcpu1 - pcpu0) / 1e6 / Math.max(1, frames));
        if (shadowsAb && abSecs[0] > 0 && abSecs[1] > 0)
            spec.commandLine().getOut().printf(Locale.ROOT, "shadows on: %.1f fps, off: %.1f fps (alternating 1 s windows, %.1f s measured each); "
                            + "process CPU per frame on %.2f ms, off %.2f ms%n",
                    abFrames[0] / abSecs[0], abFrames[1] / abSecs[1], abSecs[0], abCpu[0] / abFrames[0], abCpu[1] / abFrames[1]);
    }

    /** CPU time (ns) of the whole process so far. */
    private static long processCpu() {
        return ((com.sun.management.OperatingSystemMXBean) java.lang.management.ManagementFactory.getOperatingSystemMXBean()).getProcessCpuTime();
    }

    /** CPU time (ns) so far of the path-check, render (jME) and Swing event threads. */
    private static long[] threadCpu() {
        java.lang.management.ThreadMXBean mx = java.lang.management.ManagementFactory.getThreadMXBean();
        long[] out = new long[3];
        String[][] names = {{"path-check"}, {"jME3 Main", "LWJGL Renderer Thread"}, {"AWT-EventQueue"}};
        for (Thread t : Thread.getAllStackTraces().keySet())
            for (int k = 0; k < names.length; k++)
                for (String n : names[k])
                    if (t.getName().startsWith(n)) out[k] += Math.max(0, mx.getThreadCpuTime(t.getId()));
        return out;
    }

    private long editTick = -1;

    /** Targets of the benchmark program (a sphere and a triad each in 3D). */
    static final int GRID = Integer.getInteger("robopro.benchmark.targets", 100);

    /**
     * A long program over targets on a 10 x 10 grid (±100 mm, ±150 mm) about the TCP at the ready
     * pose: MoveL between them, every fifth move a MoveC.
     */
    private static List<Instruction> longProgram(WorkbenchWindow wb, int moves) throws InterruptedException {
        var m = wb.session().model();
        org.robopro.kinematics.Pose tcp = m.worldTtcp();
        double[] q = m.q();
        List<Instruction> p = new ArrayList<>();
        WorkbenchWindow.onEdt(() -> {
            for (int i = 0; i < GRID; i++) {
                org.robopro.kinematics.Pose t = org.robopro.kinematics.Pose.translation(0, -0.1 + 0.02 * (i % 10), -0.15 + 0.3 * (i / 10) / Math.max(1, GRID / 10)).times(tcp);
                m.putTarget(new Target(String.format(Locale.ROOT, "b%03d", i), t, q, m.kinematics().confOf(q)));
            }
            for (int i = 0; i < moves; i++) {
                String to = String.format(Locale.ROOT, "b%03d", (i * 37) % GRID);
                if (i % 5 == 4) p.add(new Instruction(Instruction.Type.MOVEC, to, 200, 10, String.format(Locale.ROOT, "b%03d", (i * 37 + 11) % GRID)));
                else p.add(new Instruction(i == 0 ? Instruction.Type.MOVEJ : Instruction.Type.MOVEL, to, 200, 10));
            }
            m.setProgram(p);
        });
        return List.copyOf(p);
    }

    /** An autosave left by a crash: asks whether to open it instead. */
    private static Optional<Path> offerRecovery(Path project) throws java.io.IOException {
        Optional<Path> a = ProjectStore.recoverable(project);
        if (a.isEmpty()) return Optional.empty();
        try {
            ProjectStore.read(a.get());
        } catch (InputException e) {
            return Optional.empty();
        }
        int r = JOptionPane.showConfirmDialog(null, "robopro found unsaved work from an earlier session:\n" + a.get()
                + "\n\nRecover it? (No keeps the autosave file; it is replaced at the next autosave.)", "Recover unsaved work",
                JOptionPane.YES_NO_OPTION);
        if (r != JOptionPane.YES_OPTION) return Optional.empty();
        Path recovered = a.get().resolveSibling(a.get().getFileName() + ".recovered.json");
        Files.copy(a.get(), recovered, java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        return Optional.of(recovered);
    }

    static int[] parseSize(String s) {
        String[] p = s.toLowerCase(Locale.ROOT).split("x");
        try {
            if (p.length == 2) {
                int w = Integer.parseInt(p[0].trim()), h = Integer.parseInt(p[1].trim());
                if (w >= 320 && h >= 240 && w <= 8192 && h <= 8192) return new int[] {w, h};
            }
        } catch (NumberFormatException ignored) {
            // reported below
        }
        throw new IllegalArgumentException("--size: expected WIDTHxHEIGHT between 320x240 and 8192x8192, got '" + s + "'");
    }
}
