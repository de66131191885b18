/** Measurements, identification, diagnosis, compensation and the calibration workflow. */
module org.robopro.calibration {
    requires transitive org.robopro.kinematics;
    requires org.slf4j;
    requires ejml.core;
    requires ejml.ddense;
    requires commons.math3;      // automatic module named after the jar

    exports org.robopro.calibration;
    exports org.robopro.calibration.compensation;
    exports org.robopro.calibration.diagnosis;
    exports org.robopro.calibration.identification;
    exports org.robopro.calibration.measurement;
    exports org.robopro.calibration.report;
    exports org.robopro.calibration.simulation;
    exports org.robopro.calibration.workflow;
}
