package org.robopro.app.cli;

import static org.junit.jupiter.api.Assertions.*;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

/** The root command's help and the shared option mixins. */
class RoboproCommandTest {
    private final CliHarness cli = new CliHarness();

    private int run(String... args) { return cli.run(args); }

    @Test
    void help_root_commandsListedInTheOrderAUserMeetsThem() {
        assertEquals(0, run("--help"));
        String text = cli.out();
        List<String> expected = List.of("workbench", "demo", "model", "fk", "ik", "simulate", "measurements", "calibrate", "diagnose", "compensate",
                "program", "link", "controller-sim", "diagnose-benchmark", "help");
        List<String> listed = new ArrayList<>();
        boolean in = false;
        for (String line : text.split("\n")) {
            if (line.startsWith("Commands:")) { in = true; continue; }
            if (in && line.matches("  \\S.*")) listed.add(line.strip().split("\\s+")[0]);
        }
        assertEquals(expected, listed, text);
    }

    @Test
    void help_ik_poseLabelPrintedOnceInUsageAndList() {
        assertEquals(0, run("ik", "--help"));
        String text = cli.out();
        assertEquals(2, text.split("X Y Z QW QX QY QZ", -1).length - 1, "once in the usage line, once in the list:\n" + text);
        assertFalse(text.contains("QZ X"), text);
    }

    @Test
    void mixins_calibrateDiagnoseSimulate_shareRobotOutAndForceOptions() {
        CommandLine root = RoboproCommand.commandLine();
        for (String name : List.of("simulate", "calibrate", "diagnose")) {
            var spec = root.getSubcommands().get(name).getCommandSpec();
            assertTrue(spec.mixins().containsKey("robot") && spec.mixins().containsKey("out"), name + ": " + spec.mixins().keySet());
            assertTrue(spec.findOption("--robot").required() && spec.findOption("--out").required(), name);
            assertNotNull(spec.findOption("--force"), name);
        }
        for (String name : List.of("calibrate", "diagnose"))
            assertNotNull(root.getSubcommands().get(name).getCommandSpec().findOption("--validate"), name);
    }

    @Test
    void calibrate_missingRobot_exitCode2NamingTheOption() {
        assertEquals(2, run("calibrate", "--measurements", "m.csv", "--out", "x"));
        assertTrue(cli.err().contains("--robot"), cli.err());
    }
}
