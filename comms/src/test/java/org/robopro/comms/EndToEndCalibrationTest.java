package org.robopro.comms;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robopro.calibration.compensation.Compensator;
import org.robopro.calibration.identification.CalibrationResult;
import org.robopro.calibration.identification.Calibrator;
import org.robopro.calibration.measurement.MeasurementReader;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.comms.sim.ControllerSim;
import org.robopro.kinematics.InverseKinematics;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.kinematics.Units;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
import org.robopro.programs.RapidParser;
import org.robopro.programs.sim.MotionInterpreter;
import org.robopro.programs.sim.MoveStep;
import org.robopro.comms.connection.ControllerConnection;

/**
 * Calibration through the controller link, end to end: the simulated IRB-2000 in its own process on loopback TCP, a measurement
 * campaign through the Command pattern, the file written and read in the measurement format,
 * calibration, and compensated program targets measured on the simulated real robot.
 */
class EndToEndCalibrationTest {
    private static final double NOISE_MM = 0.02;
    private static final Pose NOMINAL_TOOL = Pose.translation(0, 0, 0.1);

    @TempDir Path dir;

    @Test
    void campaignThroughLink_calibrated_validationAtNoiseFloorAndCompensatedTargetsLandCloser() throws Exception {
        RobotDescription irb = RobotLibrary.load("irb2000");
        KinematicModel nominal = KinematicModel.build(irb);
        ControllerSim.Config cfg = ControllerSim.Config.tcp("127.0.0.1:0").withSeed(11).withErrorMm(2.0).withNoiseMm(NOISE_MM);
        try (ControllerConnection link = ControllerConnection.startSimulator(cfg)) {
            CommandInvoker inv = link.invoker();
            assertTrue(link.simulatorProcess().isPresent(), "the simulator runs as a process of its own");
            inv.execute(Commands.ping());
            assertEquals("irb2000", link.client().robotName());

            // 1. Campaign: 150 training poses plus 100 validation poses, through the invoker.
            List<double[]> poses = MeasurementCampaign.samplePoses(nominal, 250, 5);
            MeasurementSet all = MeasurementCampaign.run(inv, poses, "irb2000", "simulated laser tracker, sigma 0.02 mm");
            Path file = dir.resolve("measurements.csv");
            MeasurementCampaign.write(all, irb.joints().stream().map(j -> j.type()).toList(), file, false);

            // 2. Calibrate from the file, as the calibrate command would.
            MeasurementSet read = MeasurementReader.read(file, irb);
            assertEquals(250, read.size());
            assertTrue(read.hasDirections() && read.hasTime() && read.hasPayload());
            MeasurementSet train = read.withRows(read.rows().subList(0, 150));
            MeasurementSet validate = read.withRows(read.rows().subList(150, 250));
            CalibrationResult cal = Calibrator.calibrate(nominal, train, validate, Calibrator.Options.defaults().withInitialTool(NOMINAL_TOOL));
            double floorM = Math.sqrt(3) * Units.mmToM(NOISE_MM);
            System.out.printf(Locale.ROOT, "end-to-end: nominal %.4f mm -> validation RMS %.4f mm (floor %.4f mm)%n",
                    Units.mToMm(cal.nominalValidateRmsM()), Units.mToMm(cal.validateRmsM()), Units.mToMm(floorM));
            assertTrue(cal.nominalValidateRmsM() > 20 * floorM, "the simulated robot has errors: " + cal.nominalValidateRmsM());
            assertEquals(1.0, cal.validateRmsM() / floorM, 0.15, "validation RMS within 15 % of the noise floor");

            // 3. A program's targets, compensated with the result, land closer on the real robot.
            List<Pose> targets = programTargets(nominal);
            Compensator comp = new Compensator(nominal, cal.calibrated(), NOMINAL_TOOL, cal.flangeTtool());
            InverseKinematics ik = InverseKinematics.of(nominal);
            Pose baseTinstrument = cal.instrumentTbase().inverse();
            double sumPlain = 0, sumComp = 0;
            double[] seed = inv.execute(Commands.readJoints());
            for (Pose target : targets) {
                double[] qPlain = ik.solveNear(target.times(NOMINAL_TOOL.inverse()), seed).orElseThrow().q();
                Compensator.Result r = comp.compensate(target, qPlain);
                assertEquals(Compensator.Status.CONVERGED, r.status());
                inv.execute(Commands.moveJoints(qPlain));
                double plain = baseTinstrument.apply(inv.execute(Commands.measure())).minus(target.position()).norm();
                inv.execute(Commands.moveJoints(r.q()));
                double compensated = baseTinstrument.apply(inv.execute(Commands.measure())).minus(target.position()).norm();
                sumPlain += plain * plain;
                sumComp += compensated * compensated;
                seed = qPlain;
            }
            double rmsPlain = Math.sqrt(sumPlain / targets.size()), rmsComp = Math.sqrt(sumComp / targets.size());
            System.out.printf(Locale.ROOT, "end-to-end: %d program targets, RMS %.4f mm uncompensated -> %.4f mm compensated%n",
                    targets.size(), Units.mToMm(rmsPlain), Units.mToMm(rmsComp));
            assertTrue(rmsComp < 0.1 * rmsPlain, "compensation brings targets closer: " + rmsPlain + " -> " + rmsComp);
            assertTrue(rmsComp < 3 * floorM, "compensated targets land within the measurement noise: " + rmsComp);

            // The same program runs on the controller.
            byte[] text = program(nominal).getBytes(StandardCharsets.UTF_8);
            inv.execute(Commands.downloadProgram("E2E", text));
            inv.execute(Commands.startProgram("E2E"));
            ControllerStatus st = inv.execute(Commands.readStatus());
            for (int i = 0; i < 200 && st.state() == ControllerStatus.State.RUNNING; i++) {
                Thread.sleep(20);
                st = inv.execute(Commands.readStatus());
            }
            assertEquals(ControllerStatus.State.IDLE, st.state(), String.valueOf(st));
        }
    }

    /** A RAPID program of MoveJ to 10 reachable robtargets with the tracker target as its tool. */
    private static String program(KinematicModel nominal) {
        StringBuilder sb = new StringBuilder("MODULE E2E\n  PERS tooldata smr := [TRUE,[[0,0,100],[1,0,0,0]],[0.2,[0,0,50],[1,0,0,0],0,0,0]];\n");
        List<double[]> qs = MeasurementCampaign.samplePoses(nominal, 10, 99);
        for (int k = 0; k < qs.size(); k++) {
            Pose p = nominal.flange(qs.get(k)).times(NOMINAL_TOOL);
            double[] qt = p.quaternion();
            sb.append(String.format(Locale.ROOT, "  CONST robtarget p%d := [[%.4f,%.4f,%.4f],[%.9f,%.9f,%.9f,%.9f],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];%n",
                    k + 1, Units.mToMm(p.x()), Units.mToMm(p.y()), Units.mToMm(p.z()), qt[0], qt[1], qt[2], qt[3]));
        }
        sb.append("  PROC main()\n");
        for (int k = 0; k < qs.size(); k++) sb.append("    MoveJ p").append(k + 1).append(", v500, fine, smr;\n");
        return sb.append("  ENDPROC\nENDMODULE\n").toString();
    }

    /** The program's TCP targets in the base frame, as org.robopro.programs reads them. */
    private static List<Pose> programTargets(KinematicModel nominal) {
        List<Pose> out = new ArrayList<>();
        for (MoveStep m : MotionInterpreter.of(RapidParser.parseDetailed(program(nominal), "E2E.mod")).moves("main"))
            out.add(m.baseTtcp().orElseThrow());
        return out;
    }

}
