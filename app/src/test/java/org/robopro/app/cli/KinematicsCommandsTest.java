package org.robopro.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import org.junit.jupiter.api.Test;
import org.robopro.models.RobotLibrary;

/** model show / model check / fk / ik on the command line (RobotLibrary-dependent parts skip until it lands). */
class KinematicsCommandsTest {
    private final CliHarness cli = new CliHarness();

    private int run(String... args) { return cli.run(args); }

    private static boolean libraryAvailable() {
        try {
            RobotLibrary.load("irb2000");
            return true;
        } catch (UnsupportedOperationException e) {
            if ("true".equals(System.getenv("CI"))) throw new AssertionError("RobotLibrary is still a stub on CI", e);
            return false;
        }
    }

    @Test
    void fk_noArguments_exitCode2WithMessage() {
        assertEquals(2, run("fk"));
        assertTrue(cli.err().contains("ROBOT"), cli.err());
    }

    @Test
    void fk_nonNumericJointValue_exitCode2() {
        assertEquals(2, run("fk", "irb2000", "abc"));
        assertTrue(cli.err().contains("abc"), cli.err());
    }

    @Test
    void ik_missingPoseValues_exitCode2() {
        assertEquals(2, run("ik", "irb2000", "1000", "0", "1615"));
    }

    @Test
    void fk_irb2000ZeroJson_exactFormat() {
        assumeTrue(libraryAvailable());
        assertEquals(0, run("fk", "irb2000", "0", "0", "0", "0", "0", "0", "--json"));
        assertEquals("{\"position_mm\": [1000.000000, 0.000000, 1615.000000], \"quaternion\": [0.707106781, 0.000000000, 0.707106781, 0.000000000]}",
                cli.out().trim());
    }

    @Test
    void fk_wrongJointCount_exitCode2() {
        assumeTrue(libraryAvailable());
        assertEquals(2, run("fk", "irb2000", "0", "0", "0"));
        assertTrue(cli.err().contains("6 joints"), cli.err());
    }

    @Test
    void ik_irb2000_listsSolutionsWithConfdataAsJson() {
        assumeTrue(libraryAvailable());
        assertEquals(0, run("ik", "irb2000", "1000", "0", "1615", "0.70710678", "0", "0.70710678", "0", "--json"));
        String s = cli.out();
        assertTrue(s.startsWith("[{\"joints\": ["), s);
        assertTrue(s.contains("\"cfx\": 0"), s);
    }

    @Test
    void model_showAndCheck_irb2000() {
        assumeTrue(libraryAvailable());
        assertEquals(0, run("model", "show", "irb2000"));
        assertTrue(cli.out().contains("30 identified parameters"), cli.out());
        assertEquals(0, run("model", "check", "irb2000"));
        assertTrue(cli.out().contains("SINGULAR"), "plain DH comparison shows the singularity: " + cli.out());
    }
}
