package org.robopro.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robopro.calibration.measurement.MeasurementReader;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.comms.sim.ControllerSim;
import org.robopro.models.RobotLibrary;

/** A link drop or a kill during `link campaign` keeps every pose measured; --resume continues. */
class CampaignJournalTest {
    @TempDir Path dir;

    ControllerSim start(String name) throws Exception {
        Path port = dir.resolve(name);
        ControllerSim sim = ControllerSim.start(new ControllerSim.Config("127.0.0.1:0", null, 115200, "irb2000", 2, 0.5, List.of(),
                0.0, null, 0, port, false, 0));
        return sim;
    }

    String where(String name) throws Exception { return "127.0.0.1:" + Files.readString(dir.resolve(name)).strip(); }

    static List<String> dataRows(Path f) throws Exception {
        return Files.readAllLines(f).stream().filter(l -> !l.startsWith("#") && !l.startsWith("pose") && !l.isBlank()).toList();
    }

    @Test
    void linkDropMidCampaign_keepsEveryMeasuredPose_andResumeCompletesTheFile() throws Exception {
        Path file = dir.resolve("campaign.csv"), journal = dir.resolve("campaign.csv.journal");
        ControllerSim sim = start("p1");
        CliHarness cli = new CliHarness(true);
        String where = where("p1");
        CompletableFuture<Integer> run = CompletableFuture.supplyAsync(() -> cli.run("link", "--tcp", where, "--timeout-ms", "500",
                "campaign", "--poses", "400", "--out", file.toString()));
        // The link drops once 30 poses are on disk.
        long deadline = System.currentTimeMillis() + 60_000;
        while ((!Files.exists(journal) || dataRows(journal).size() < 30) && System.currentTimeMillis() < deadline) Thread.sleep(5);
        sim.close();
        int code = run.get();
        assertEquals(3, code, cli.err());
        assertFalse(Files.exists(file));
        List<String> kept = dataRows(journal);
        assertTrue(kept.size() >= 30 && kept.size() < 400, "kept " + kept.size());
        assertTrue(cli.err().contains("kept in " + journal) && cli.err().contains("--resume"), cli.err());
        // A kill -9 in the middle of a write leaves a row cut short.
        Files.writeString(journal, "999,1.5,2", java.nio.file.StandardOpenOption.APPEND);

        // Without --resume the journal is not overwritten.
        ControllerSim sim2 = start("p2");
        try {
            CliHarness c2 = new CliHarness(true);
            assertEquals(2, c2.run("link", "--tcp", where("p2"), "campaign", "--poses", "400", "--out", file.toString()));
            assertTrue(c2.err().contains("--resume"), c2.err());
            // Another seed cannot resume it.
            assertEquals(2, c2.run("link", "--tcp", where("p2"), "campaign", "--poses", "400", "--seed", "9", "--resume",
                    "--out", file.toString()));
            assertEquals(0, c2.run("link", "--tcp", where("p2"), "campaign", "--poses", "400", "--resume", "--out", file.toString()),
                    c2.err());
            assertTrue(c2.err().contains("resuming: " + kept.size() + " of 400"), c2.err());
        } finally {
            sim2.close();
        }
        assertFalse(Files.exists(journal));
        MeasurementSet set = MeasurementReader.read(file, RobotLibrary.load("irb2000"));
        assertEquals(400, set.size());
        List<String> all = dataRows(file);
        assertEquals(kept, all.subList(0, kept.size()), "the poses measured before the drop are kept as measured");
        for (int i = 0; i < 400; i++) assertEquals(Integer.toString(i + 1), set.rows().get(i).poseId());
    }
}
