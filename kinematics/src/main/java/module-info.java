/** Kinematic models, forward and inverse kinematics, rigid transforms, and the DH/URDF importers. */
module org.robopro.kinematics {
    requires transitive org.robopro.models;
    requires java.xml;           // URDF
    requires ejml.core;          // EJML 0.44 has no module names: automatic modules named after the jars
    requires ejml.ddense;

    exports org.robopro.kinematics;
    exports org.robopro.kinematics.importers;
}
