package org.robopro.comms;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Locale;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.diagnosis.Diagnoser;
import org.robopro.calibration.diagnosis.Diagnosis;
import org.robopro.calibration.diagnosis.Effect;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.comms.sim.ControllerSim;
import org.robopro.comms.sim.SimEffects;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Units;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
import org.robopro.comms.connection.ControllerConnection;

/**
 * Diagnosis through the controller link, end to end: the simulated controller as a process with {@code --effect backlash:2},
 * a campaign through the link (directions are the controller's real approach directions), and the
 * diagnosis names backlash on joint 2 with the size the simulator drew.
 */
class EffectsEndToEndTest {
    private static final long SEED = 21;

    @Test
    void controllerSimWithBacklashJoint2_campaignThroughLink_diagnoserNamesBacklashJoint2() throws Exception {
        RobotDescription irb = RobotLibrary.load("irb2000");
        KinematicModel nominal = KinematicModel.build(irb);
        ControllerSim.Config cfg = ControllerSim.Config.tcp("127.0.0.1:0").withSeed(SEED).withErrorMm(2.0).withNoiseMm(0.02)
                .withEffects(List.of("backlash:2"));
        MeasurementSet all;
        try (ControllerConnection link = ControllerConnection.startSimulator(cfg)) {
            assertTrue(link.simulatorProcess().isPresent(), "the simulator runs as a process of its own");
            all = MeasurementCampaign.run(link.invoker(), MeasurementCampaign.samplePoses(nominal, 300, 6), "irb2000",
                    "simulated laser tracker, sigma 0.02 mm");
        }
        assertTrue(all.hasDirections(), "dir columns from the controller");
        Diagnosis d = Diagnoser.diagnose(irb, all.withRows(all.rows().subList(0, 200)), all.withRows(all.rows().subList(200, 300)));
        List<String> found = d.effects().stream().map(f -> f.effect().label()).toList();
        System.out.printf(Locale.ROOT, "effects end-to-end: found %s; validation RMS %.4f mm geometric -> %.4f mm%n", found,
                Units.mToMm(d.geometricValidateRmsM()), Units.mToMm(d.finalValidateRmsM()));
        assertEquals(List.of("backlash j2"), found);

        // The simulator drew the play from its seed with diagnosis' own EffectSpec: the estimate matches it.
        Effect.Term truth = SimEffects.terms(cfg.effects(), irb, nominal, SEED).get(0);
        double b = d.effects().get(0).values()[0];
        assertEquals(truth.values()[0], b, 0.15 * truth.values()[0], "lost motion, rad");
        assertTrue(d.finalValidateRmsM() < 0.7 * d.geometricValidateRmsM(), "modelling backlash improves validation");
    }
}
