/**
 * The independent "real robot" and campaign simulator: truth for benchmarks and the simulated
 * controller, sharing no code with kinematics or calibration (it reads only robot descriptions).
 */
module org.robopro.world {
    requires transitive org.robopro.models;

    exports org.robopro.world;
}
