package org.robopro.app.cli;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import org.robopro.calibration.diagnosis.EffectSpec;
import org.robopro.comms.sim.ControllerSim;
import org.robopro.comms.sim.TrueSimulatedRobot;
import org.robopro.comms.sim.WorldSimulatedRobot;
import picocli.CommandLine.ArgGroup;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code robopro controller-sim --tcp HOST:PORT | --serial DEVICE ...}: runs the simulated
 * IRB-2000 controller (open_abb protocol plus robopro's extension, docs/controller-link.md)
 * until killed.
 */
@Command(name = "controller-sim", mixinStandardHelpOptions = true,
        description = "Run a simulated robot controller (open_abb protocol on TCP, or the framed serial link).")
public final class ControllerSimCommand implements Callable<Integer> {
    static final class Where {
        @Option(names = "--tcp", paramLabel = "HOST:PORT", description = "listen on HOST:PORT (PORT 0: any free port; logger on PORT+1)") String tcp;
        @Option(names = "--serial", paramLabel = "DEVICE", description = "serve on a serial device (e.g. /dev/ttyS0 or a socat pty)") String serial;
    }

    @ArgGroup(exclusive = true, multiplicity = "1") Where where;

    @Option(names = "--baud", defaultValue = "115200", description = "serial speed (default ${DEFAULT-VALUE})") int baud;

    @Option(names = "--robot", defaultValue = "irb2000", paramLabel = "ROBOT", description = "shipped robot name or robot file (default ${DEFAULT-VALUE})")
    String robot;

    @Option(names = "--seed", defaultValue = "1", description = "seed of the robot's errors and the tracker noise (default ${DEFAULT-VALUE})") long seed;

    @Option(names = "--error-mm", defaultValue = "0.5", description = "RMS flange position error of the nominal model against the simulated real robot, mm (default ${DEFAULT-VALUE})")
    double errorMm;

    @Option(names = "--effect", paramLabel = "NAME[:JOINT]", description = "non-geometric effect of the real robot (repeatable): "
            + "backlash, joint-compliance, gear-periodic, joint-scale, joint-coupling[:JOINT[<-SOURCE]], thermal-expansion, "
            + "optionally =VALUE; sizes otherwise drawn from realistic ranges with --seed (docs/controller-link.md)")
    List<String> effects = new ArrayList<>();

    @Option(names = "--noise-mm", defaultValue = "0.02", description = "laser tracker noise, mm per axis (default ${DEFAULT-VALUE})") double noiseMm;

    @Option(names = "--target", paramLabel = "X,Y,Z", defaultValue = "0,0,100",
            description = "nominal position of the tracker target on the flange, mm (default ${DEFAULT-VALUE}; the real one is off by ~2 mm)")
    String target;

    @Option(names = "--payload-kg", defaultValue = "0", description = "payload at the flange, kg (default ${DEFAULT-VALUE})") double payloadKg;

    @Option(names = "--port-file", paramLabel = "FILE", description = "write the bound TCP port to FILE (useful with PORT 0)") Path portFile;

    @Option(names = "--truth-file", paramLabel = "FILE", description = "write what the real robot is (error size, parameters, "
            + "injected effects with their sizes, noise, seed) to FILE once at start, as JSON (docs/controller-link.md)") Path truthFile;

    @Option(names = "--world", paramLabel = "SCENARIO", description = "the real robot is a scenario of the independent world simulator "
            + "(docs/diagnosis-benchmark.md; e.g. \"outside: bump in the angle of j3\"), drawn with --seed; replaces --error-mm and --effect")
    String world;

    @Option(names = "--realtime", description = "take the motion time in real time (default: simulated time, answer at once)") boolean realtime;

    @Option(names = "--fault-rate", defaultValue = "0", description = "inject faults into this share of replies/frames (testing)") double faultRate;

    @Spec CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        try (ControllerSim sim = ControllerSim.start(new ControllerSim.Config(where.tcp, where.serial, baud, robot, seed, errorMm,
                effects, noiseMm, ControllerSim.parseTargetMm(target), payloadKg, portFile, realtime, faultRate, truthFile, world))) {
            spec.commandLine().getOut().println("robopro controller-sim: " + sim.controller().robot().name() + " on " + sim.where()
                    + "; stop with Ctrl-C");
            if (sim.controller().robot() instanceof TrueSimulatedRobot t)
                for (var e : t.effects())
                    spec.commandLine().getOut().println("  effect " + EffectSpec.of(e.effect()).withSize(e.values())
                            + " (" + EffectSpec.valueUnit(e.effect().kind()) + ")");
            if (sim.controller().robot() instanceof WorldSimulatedRobot w)
                spec.commandLine().getOut().println("  world scenario '" + w.scenario().name() + "' (concealed)");
            spec.commandLine().getOut().flush();
            Thread.currentThread().join();
        }
        return 0;
    }
}
