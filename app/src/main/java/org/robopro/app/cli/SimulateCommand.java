package org.robopro.app.cli;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import org.robopro.calibration.diagnosis.Effect;
import org.robopro.calibration.diagnosis.EffectCampaign;
import org.robopro.calibration.diagnosis.EffectSpec;
import org.robopro.calibration.measurement.MeasurementWriter;
import org.robopro.calibration.simulation.Campaign;
import org.robopro.calibration.simulation.CampaignSimulator;
import org.robopro.calibration.simulation.SimulationSettings;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Units;
import org.robopro.models.JointType;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
import org.robopro.models.Vec3;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code robopro simulate}: a simulated calibration campaign (docs/calibration.md). Writes
 * {@code DIR/measurements.csv}, optionally {@code DIR/validate.csv}, and the truth separately:
 * {@code DIR/truth.json} and {@code DIR/true.robot.json}. With {@code --effect SPEC} the true robot
 * also has non-geometric effects (diagnosis' {@link EffectSpec}), the files get the conditions
 * columns (dir1..dirN, time_s, temp_c, payload_kg with compliance) and truth.json the injected
 * effects with their values.
 */
@Command(name = "simulate", mixinStandardHelpOptions = true,
        description = "Simulate a calibration campaign on a robot with random geometric errors.")
public final class SimulateCommand implements Callable<Integer> {
    @Mixin RobotOptions robot;

    @Option(names = "--poses", defaultValue = "200", description = "training poses (default ${DEFAULT-VALUE})")
    int poses;

    @Option(names = "--validate-poses", defaultValue = "0", paramLabel = "N", description = "extra poses written to validate.csv")
    int validatePoses;

    @Option(names = "--sigma", defaultValue = "0.02", paramLabel = "MM", description = "position noise per axis, mm (default ${DEFAULT-VALUE})")
    double sigmaMm;

    @Option(names = "--sigma-deg", defaultValue = "0.001", paramLabel = "DEG", description = "orientation noise per axis with --six-d, deg")
    double sigmaDeg;

    @Option(names = "--error-mm", defaultValue = "10", paramLabel = "MM", description = "RMS flange error of the nominal model, mm (default ${DEFAULT-VALUE})")
    double errorMm;

    @Option(names = "--target", defaultValue = "0,0,100", paramLabel = "X,Y,Z", description = "nominal measured point on the flange, mm; several reflectors per pose: X,Y,Z;X,Y,Z;... (written one row per pose and point)")
    String target;

    @Option(names = "--distance-to", paramLabel = "X,Y,Z",
            description = "measure distances instead of positions: the length from this anchor (robot base frame, mm) to the point, "
                    + "as a draw-wire sensor would; the anchor is written to truth.json only")
    String distanceTo;

    @Option(names = "--distance-between-poses",
            description = "measure distances instead of positions: the length between the point's places at each pose and the "
                    + "pose before it (a length artefact or ballbar probed by the robot); written with the first pose in from_q1..")
    boolean betweenPoses;

    @Option(names = "--six-d", description = "also measure the tool orientation")
    boolean sixD;

    @Option(names = "--frame-base", description = "the instrument measures in the robot base frame")
    boolean frameBase;

    @Option(names = "--seed", defaultValue = "1", description = "random seed (default ${DEFAULT-VALUE})")
    long seed;

    @Option(names = "--effect", paramLabel = "SPEC",
            description = "inject a non-geometric effect, repeatable: NAME[:JOINT[<-SOURCE]][=VALUE], e.g. backlash:2, "
                    + "gear-periodic:1=0.008, joint-coupling:3<-2, thermal-expansion; sizes drawn from realistic ranges with --seed "
                    + "unless VALUE is given (docs/diagnosis.md)")
    List<String> effects = new ArrayList<>();

    @Mixin OutputDirOptions out;

    @Spec CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        if (poses < 1) throw new IllegalArgumentException("--poses must be at least 1");
        if (!(sigmaMm >= 0 && sigmaMm <= 100)) throw new IllegalArgumentException("--sigma must be in 0 .. 100 mm, got " + sigmaMm);
        if (!(errorMm >= 0 && errorMm <= 1000))
            throw new IllegalArgumentException("--error-mm must be in 0 .. 1000 mm (a robot more than a metre off its model is not "
                    + "a calibration case), got " + errorMm);
        RobotDescription desc = robot.description();
        KinematicModel nominal = robot.model();
        String[] targets = target.split(";", -1);
        double[] t = CliSupport.numbers("--target", targets[0], 3);
        List<Vec3> more = new ArrayList<>();
        for (int k = 1; k < targets.length; k++) {
            double[] v = CliSupport.numbers("--target", targets[k], 3);
            more.add(new Vec3(Units.mmToM(v[0]), Units.mmToM(v[1]), Units.mmToM(v[2])));
        }
        if (!more.isEmpty() && sixD) throw new IllegalArgumentException("--six-d measures one point per pose; give one --target");
        SimulationSettings s = new SimulationSettings(poses, validatePoses, Units.mmToM(sigmaMm), Units.degToRad(sigmaDeg),
                Units.mmToM(errorMm), 2e-3, new Vec3(Units.mmToM(t[0]), Units.mmToM(t[1]), Units.mmToM(t[2])), sixD, frameBase, seed);
        List<EffectSpec> specs = EffectSpec.parseAll(effects);
        EffectCampaign ec = specs.isEmpty() ? null : EffectCampaign.simulate(desc, s, specs);
        Campaign c = CampaignSimulator.withPoints(ec != null ? ec.campaign() : CampaignSimulator.simulate(nominal, s), more);
        if (distanceTo != null) {
            if (sixD || !more.isEmpty()) throw new IllegalArgumentException("--distance-to measures one point, without --six-d");
            double[] a = CliSupport.numbers("--distance-to", distanceTo, 3);
            c = CampaignSimulator.asDistances(c, new Vec3(Units.mmToM(a[0]), Units.mmToM(a[1]), Units.mmToM(a[2])));
        }
        if (betweenPoses) {
            if (sixD || !more.isEmpty() || distanceTo != null)
                throw new IllegalArgumentException("--distance-between-poses measures one point, without --six-d or --distance-to");
            c = CampaignSimulator.asPairs(c);
        }
        List<JointType> types = new ArrayList<>();
        desc.joints().forEach(j -> types.add(j.type()));
        RobotDescription trueDesc = c.truth().model().toDescription()
                .withProvenance(Map.of("simulated-from", desc.name(), "seed", Long.toString(seed),
                        "error-mm", Double.toString(errorMm)));
        // The injected effects in the robot file's effects section, so the truth can be compensated with too.
        if (ec != null) trueDesc = trueDesc.withEffects(ec.injected().stream().map(e -> e.effect().describe(e.values())).toList());
        // The four files as one set: whole or not at all.
        var set = out.set().addString("measurements.csv", MeasurementWriter.format(c.measurements(), types));
        if (c.validation() != null) set.addString("validate.csv", MeasurementWriter.format(c.validation(), types));
        set.addString("truth.json", CampaignSimulator.truthJson(c, ec != null ? ec.truthEntries() : null) + "\n")
                .addString("true.robot.json", org.robopro.models.RobotFile.format(trueDesc))
                .commit();
        spec.commandLine().getOut().printf(Locale.ROOT,
                "simulated %s: %d poses%s, sigma %.4f mm, nominal flange error %.3f mm RMS, %s%n  wrote %s%n",
                desc.name(), poses, validatePoses > 0 ? " + " + validatePoses + " validation" : "", sigmaMm,
                Units.mToMm(c.nominalErrorRmsM()), c.anchor() != null ? "distances to an anchor"
                        : c.measurements().isPairs() ? "distances between consecutive poses" : "frame " + c.measurements().frame(),
                out.dir().toAbsolutePath());
        if (ec != null)
            for (int i = 0; i < specs.size(); i++) {
                Effect.Term term = ec.injected().get(i);
                spec.commandLine().getOut().printf(Locale.ROOT, "  effect %s (%s)%n", specs.get(i).withSize(term.values()),
                        EffectSpec.valueUnit(term.effect().kind()));
            }
        return 0;
    }
}
