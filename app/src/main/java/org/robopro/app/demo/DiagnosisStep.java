package org.robopro.app.demo;

import java.nio.file.Path;
import java.util.List;
import org.robopro.calibration.compensation.Compensator;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.RobotDescription;

/**
 * Step 4's diagnosis: names the concealed effect and builds the extended model's compensator.
 *
 * <p>PENDING: the diagnosis (issue 4, package org.robopro.calibration.diagnosis) is not on main
 * yet; until it lands this step says so and the demo leaves the "diagnosed" column empty
 * rather than inventing numbers.
 */
final class DiagnosisStep {
    private DiagnosisStep() { }

    /** What the diagnosis gave the demo. */
    static final class Outcome {
        private final List<String> named;
        private final Pose instrumentTbase;

        Outcome(List<String> named, Pose instrumentTbase) {
            this.named = List.copyOf(named);
            this.instrumentTbase = instrumentTbase;
        }

        boolean available() { return instrumentTbase != null; }

        /** Effects named, as "kind jN" labels. */
        List<String> named() { return named; }

        Pose instrumentTbase() { return instrumentTbase; }

        /** The report's diagnosis section. */
        String html() {
            return "<p class=\"pending\">Pending: the diagnosis module is not in this build, so no effect was named and "
                    + "the program was not compensated for one.</p>\n";
        }

        Compensator compensator(KinematicModel nominal, Pose flangeTtcp, org.robopro.calibration.PoseConditions conditions) {
            throw new IllegalStateException("no diagnosis in this build");
        }
    }

    static Outcome run(Console con, RobotDescription desc, MeasurementSet train, MeasurementSet validate, Path out) {
        con.line("diagnosis: PENDING - the diagnosis module is not in this build yet; no diagnosed numbers");
        return new Outcome(List.of(), null);
    }
}
