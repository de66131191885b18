package org.robopro.app.cli;

import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.robopro.calibration.PoseConditions;
import org.robopro.calibration.compensation.Compensator;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.RobotDescription;
import org.robopro.models.AtomicFiles;
import org.robopro.models.RobotLibrary;
import org.robopro.models.TextFiles;
import org.robopro.programs.compensation.ProgramCompensation;
import org.robopro.programs.RapidModule;
import org.robopro.programs.RapidParser;
import org.robopro.programs.RapidWriter;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code robopro program compensate FILE.mod --robot irb2000 --calibrated MODEL --out FILE.mod}:
 * rewrites the targets so the real (calibrated) robot reaches them; prints each target's correction.
 */
@Command(name = "compensate", mixinStandardHelpOptions = true,
        description = "Rewrite a RAPID module's targets with a calibrated model so the real robot reaches them.")
public final class ProgramCompensateCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "FILE.mod") Path file;

    @Mixin RobotOptions robot;

    @Option(names = "--calibrated", required = true, paramLabel = "MODEL", description = "robot file of the calibrated model") String calibrated;

    @Mixin OutputFileOptions out;

    @Option(names = "--proc", defaultValue = "main", paramLabel = "PROC") String proc;

    @Option(names = "--temp-c", paramLabel = "C", description = "temperature the program runs at (thermal effect of an extended model)") Double tempC;

    @Option(names = "--payload-kg", paramLabel = "KG", description = "payload the program carries (joint compliance of an extended model)") Double payloadKg;

    @Spec CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        RapidModule m = RapidParser.parse(TextFiles.readUtf8(file), file.toString());
        KinematicModel nominal = robot.model();
        RobotDescription realDesc = RobotLibrary.load(calibrated);
        String nominalName = nominal.description().name();
        // Which robot the model is of: its calibration, diagnosis or simulation provenance, else its name.
        String of = realDesc.name();
        for (String k : new String[] {"simulated-from", "diagnosed-nominal", "calibrated-nominal"})
            of = realDesc.provenance().getOrDefault(k, of);
        if (realDesc.joints().size() != nominal.dof() || !of.equalsIgnoreCase(nominalName))
            throw new IllegalArgumentException("--calibrated " + calibrated + " is a model of " + of + " (" + realDesc.joints().size()
                    + " joints), not of " + nominalName + "; give the calibrated robot file of " + nominalName + "; nothing written");
        // An extended model (robopro diagnose) brings its effects, evaluated under the given conditions.
        Compensator tc = Compensator.forRobotFile(nominal, realDesc, calibrated, Pose.IDENTITY, Pose.IDENTITY,
                new PoseConditions(null, Double.NaN, tempC == null ? Double.NaN : tempC, payloadKg == null ? Double.NaN : payloadKg));
        ProgramCompensation.Outcome o = ProgramCompensation.compensate(m, proc, nominal, tc);
        int failed = 0;
        for (ProgramCompensation.Correction c : o.corrections()) {
            spec.commandLine().getOut().println(c);
            if (!c.ok()) failed++;
        }
        if (failed > 0) {
            // A program with some targets left uncompensated would look done: write nothing.
            spec.commandLine().getErr().printf("robopro: %d of %d targets could not be compensated (listed above); nothing written%n",
                    failed, o.corrections().size());
            return 1;
        }
        AtomicFiles.writeString(out.file(), RapidWriter.export(o.module()).text(), out.force());
        spec.commandLine().getOut().printf("wrote %s (%d targets compensated)%n", out.file(), o.corrections().size());
        return 0;
    }
}
