package org.robopro.app.cli;

import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.robopro.app.demo.Demo;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code robopro demo}: the whole loop, headless: a simulated IRB-2000 controller in its
 * own process, an off-line welding program, its error, a measurement campaign through the link,
 * calibration, diagnosis, the compensated program and its error. Exit code 0, or 1 when a step
 * fails (the controller process is stopped in every case), 2 for bad arguments.
 */
@Command(name = "demo", mixinStandardHelpOptions = true,
        description = "Run the whole loop headless on a simulated IRB-2000: program, measure, calibrate, diagnose, compensate.")
public final class DemoCommand implements Callable<Integer> {
    @Option(names = "--seed", defaultValue = "1", description = "seed of the true robot and the campaign (default ${DEFAULT-VALUE})")
    long seed;

    @Option(names = "--effect", defaultValue = Demo.DEFAULT_EFFECT, paramLabel = "NAME",
            description = "concealed non-geometric effect of the true robot: ${COMPLETION-CANDIDATES}; optionally NAME:JOINT[=VALUE]"
                    + " as for controller-sim (default ${DEFAULT-VALUE}, joint drawn from the seed)",
            completionCandidates = EffectNames.class)
    String effect;

    @Option(names = "--conceal", paramLabel = "GROUP", completionCandidates = ConcealGroups.class,
            description = "instead of --effect, conceal a scenario of the independent world simulator from this group: "
                    + "${COMPLETION-CANDIDATES} (\"outside\": a structure no diagnosis family holds; the scenario is drawn from --seed)")
    String conceal;

    @Option(names = "--poses", defaultValue = "200", paramLabel = "N",
            description = "poses of the measurement campaign, every 5th for validation (default ${DEFAULT-VALUE})")
    int poses;

    @Option(names = "--passes", defaultValue = "3", paramLabel = "N", description = "welding passes of the program, 1-4 (default ${DEFAULT-VALUE})")
    int passes;

    @Option(names = "--out", defaultValue = "robopro-demo", paramLabel = "DIR",
            description = "output folder: RAPID programs, measurements, reports, demo.json (default ${DEFAULT-VALUE})")
    Path out;

    @Spec CommandSpec spec;

    static final class ConcealGroups extends java.util.ArrayList<String> {
        private static final long serialVersionUID = 1L;

        ConcealGroups() { super(Demo.concealGroups()); }
    }

    static final class EffectNames extends java.util.ArrayList<String> {
        private static final long serialVersionUID = 1L;

        EffectNames() { super(Demo.EFFECTS); }
    }

    @Override
    public Integer call() {
        Demo.Options o = new Demo.Options(seed, effect, poses, passes, out, conceal);
        var w = spec.commandLine().getOut();
        w.println("robopro demo: the off-line programming and calibration loop on a simulated IRB-2000 (seed " + seed + ")");
        try {
            Demo.run(o, w, System.console() != null);
            return 0;
        } catch (Demo.StepFailure e) {
            w.flush();
            spec.commandLine().getErr().println("robopro demo: " + e.getMessage());
            if (e.getCause() != null && !(e.getCause() instanceof java.io.IOException) && !(e.getCause() instanceof IllegalArgumentException))
                e.getCause().printStackTrace(spec.commandLine().getErr());
            return 1;
        }
    }
}
