package org.robopro.app;

import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;
import static com.tngtech.archunit.library.dependencies.SlicesRuleDefinition.slices;

import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import com.tngtech.archunit.core.importer.ImportOption;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * The architecture of docs/architecture.md as rules over the main classes of every module on this
 * module's class path (all but the benchmarks): no cycle between packages, modules depend one
 * way, and the third-party toolkits stay in the one module that owns them.
 */
class ArchitectureTest {
    private static JavaClasses classes;

    @BeforeAll
    static void importMainClasses() {
        // Jars are imported too: under `mvn verify` the other modules reach this one as packaged jars,
        // under `mvn test` as class folders; importPackages keeps only robopro's own classes.
        classes = new ClassFileImporter().withImportOption(ImportOption.Predefined.DO_NOT_INCLUDE_TESTS)
                .importPackages("org.robopro");
    }

    @Test
    void importedEveryModule() {
        // Guards the rules below against passing on an empty or partial import.
        for (String p : new String[] {"models", "world", "kinematics", "calibration", "programs", "comms", "app"})
            org.junit.jupiter.api.Assertions.assertTrue(
                    classes.stream().anyMatch(c -> c.getPackageName().startsWith("org.robopro." + p)), "no classes of " + p);
    }

    @Test
    void packages_haveNoCycles() {
        slices().matching("org.robopro.(**)").should().beFreeOfCycles().check(classes);
    }

    @Test
    void modules_dependOneWay() {
        forbid("org.robopro.models..", "org.robopro.world..", "org.robopro.kinematics..", "org.robopro.calibration..",
                "org.robopro.programs..", "org.robopro.comms..", "org.robopro.app..");
        forbid("org.robopro.world..", "org.robopro.kinematics..", "org.robopro.calibration..", "org.robopro.programs..",
                "org.robopro.comms..", "org.robopro.app..");
        forbid("org.robopro.kinematics..", "org.robopro.world..", "org.robopro.calibration..", "org.robopro.programs..",
                "org.robopro.comms..", "org.robopro.app..");
        forbid("org.robopro.calibration..", "org.robopro.world..", "org.robopro.programs..", "org.robopro.comms..",
                "org.robopro.app..");
        forbid("org.robopro.programs..", "org.robopro.world..", "org.robopro.comms..", "org.robopro.app..");
        // The simulated controller may stand on the world's truth; nothing that estimates may.
        forbid("org.robopro.comms..", "org.robopro.app..");
        noClasses().that().resideInAPackage("org.robopro.comms..").and().resideOutsideOfPackage("org.robopro.comms.sim..")
                .should().dependOnClassesThat().resideInAPackage("org.robopro.world..").check(classes);
    }

    @Test
    void toolkits_stayInTheirModule() {
        // Only the application draws (jMonkeyEngine, Swing, AWT); only comms opens serial ports.
        noClasses().that().resideOutsideOfPackage("org.robopro.app..")
                .should().dependOnClassesThat().resideInAnyPackage("com.jme3..", "javax.swing..", "java.awt..")
                .check(classes);
        noClasses().that().resideOutsideOfPackage("org.robopro.comms..")
                .should().dependOnClassesThat().resideInAnyPackage("com.fazecast..")
                .check(classes);
    }

    @Test
    void rapidSyntaxTree_knowsNothingOfThePrograms() {
        // The program is its syntax tree; the typed view, interpreter and checks stand on it, never the reverse.
        noClasses().that().resideInAPackage("org.robopro.programs.rapid..").should().dependOnClassesThat()
                .resideInAnyPackage("org.robopro.programs", "org.robopro.programs.sim..", "org.robopro.programs.check..",
                        "org.robopro.programs.collision..", "org.robopro.programs.compensation..", "org.robopro.programs.project..")
                .check(classes);
    }

    private static void forbid(String module, String... below) {
        noClasses().that().resideInAPackage(module).should().dependOnClassesThat().resideInAnyPackage(below).check(classes);
    }
}
