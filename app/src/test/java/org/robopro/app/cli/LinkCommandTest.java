package org.robopro.app.cli;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robopro.comms.sim.ControllerSim;

class LinkCommandTest {
    @TempDir Path dir;
    private ControllerSim sim;
    private String where;
    private final CliHarness cli = new CliHarness(true);

    @BeforeEach
    void start() throws Exception {
        sim = ControllerSim.start(new ControllerSim.Config("127.0.0.1:0", null, 115200, "irb2000", 2, 0.5, List.of(), 0.0,
                null, 0, dir.resolve("port"), false, 0));
        where = "127.0.0.1:" + Files.readString(dir.resolve("port")).strip();
    }

    @AfterEach
    void stop() throws Exception { sim.close(); }

    private int run(String... args) { return cli.run(args); }

    @Test
    void moveThenJoints_printsTargetInDegrees() {
        assertEquals(0, run("link", "--tcp", where, "move", "10", "-5", "15", "0", "30", "0"), cli.err());
        assertEquals(0, run("link", "--tcp", where, "joints"), cli.err());
        assertTrue(cli.out().startsWith("10.0000 -5.0000 15.0000 0.0000 30.0000 0.0000"), cli.out());
    }

    @Test
    void moveOutOfLimits_exitCode4WithReason() {
        assertEquals(4, run("link", "--tcp", where, "move", "0", "150", "0", "0", "0", "0"));
        assertTrue(cli.err().contains("E110") && cli.err().contains("joint 2"), cli.err());
    }

    @Test
    void badArguments_exitCode2WithMessage() {
        assertEquals(2, run("link", "--tcp", where, "move", "1", "2"));
        assertTrue(cli.err().contains("takes 6 arguments"), cli.err());
        assertEquals(2, run("link", "--tcp", where, "move", "1", "2", "x", "4", "5", "6"));
        assertTrue(cli.err().contains("'x'"), cli.err());
        assertEquals(2, run("link", "--tcp", "nohost", "ping"));
        assertEquals(2, run("link", "--tcp", where, "dance"));
    }

    @Test
    void noController_exitCode3WithClearError() throws Exception {
        sim.close();
        assertEquals(3, run("link", "--tcp", where, "--timeout-ms", "300", "ping"));
        assertTrue(cli.err().contains("cannot connect"), cli.err());
    }

    @Test
    void downloadRunUpload_roundTripAndNoSilentOverwrite() throws Exception {
        Path prog = dir.resolve("demo.mod");
        String text = "MODULE demo\n  PROC main()\n    MoveAbsJ [[5,0,0,0,20,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v1000, fine, tool0;\n  ENDPROC\nENDMODULE\n";
        Files.writeString(prog, text);
        assertEquals(0, run("link", "--tcp", where, "download", prog.toString()), cli.err());
        assertTrue(cli.out().contains("stored demo"), cli.out());
        assertEquals(0, run("link", "--tcp", where, "run", "demo"), cli.err());
        assertTrue(cli.out().startsWith("IDLE demo"), cli.out());
        Path back = dir.resolve("back.mod");
        assertEquals(0, run("link", "--tcp", where, "upload", "demo", "--out", back.toString()), cli.err());
        assertEquals(text, Files.readString(back, StandardCharsets.UTF_8));
        assertEquals(2, run("link", "--tcp", where, "upload", "demo", "--out", back.toString()));
        assertTrue(cli.err().contains("refusing to overwrite"), cli.err());
        assertEquals(0, run("link", "--tcp", where, "measure"), cli.err());
        assertTrue(cli.out().contains("tracker frame"));
    }

    @Test
    void campaign_twentyPoses_writesMeasurementFileAndRefusesToOverwrite() throws Exception {
        Path file = dir.resolve("campaign.csv");
        assertEquals(0, run("link", "--tcp", where, "campaign", "--poses", "20", "--out", file.toString()), cli.err());
        assertTrue(cli.out().contains("20 poses"), cli.out());
        var set = org.robopro.calibration.measurement.MeasurementReader.read(file, org.robopro.models.RobotLibrary.load("irb2000"));
        assertEquals(20, set.size());
        assertTrue(set.hasDirections() && set.hasTime() && set.hasPayload() && !set.hasTemperature());
        assertEquals("tracker", set.frame());
        assertEquals(2, run("link", "--tcp", where, "campaign", "--poses", "20", "--out", file.toString()));
        assertTrue(cli.err().contains("refusing to overwrite"), cli.err());
    }
}
