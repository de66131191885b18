/** Robot programs: the RAPID model, reading and writing, interpretation, path checks, compensated export. */
module org.robopro.programs {
    requires transitive org.robopro.calibration;

    exports org.robopro.programs;
    exports org.robopro.programs.check;
    exports org.robopro.programs.collision;
    exports org.robopro.programs.compensation;
    exports org.robopro.programs.project;
    exports org.robopro.programs.rapid;
    exports org.robopro.programs.sim;
}
