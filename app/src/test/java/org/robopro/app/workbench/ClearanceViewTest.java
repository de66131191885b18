package org.robopro.app.workbench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Properties;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/** The live collision view under X: jogging the torch into the plates draws the colliding parts red. */
class ClearanceViewTest {
    static XvfbDisplay display;

    @BeforeAll
    static void startDisplay() throws Exception { display = XvfbDisplay.acquire(); }

    @AfterAll
    static void stopDisplay() {
        if (display != null) display.close();
    }

    /** Pixels the overlay made redder: red up and green down by together more than 40 levels. */
    static int reddened(BufferedImage on, BufferedImage off) {
        int n = 0;
        for (int y = 0; y < on.getHeight(); y++)
            for (int x = 0; x < on.getWidth(); x++) {
                int a = on.getRGB(x, y), b = off.getRGB(x, y);
                int dr = ((a >> 16) & 255) - ((b >> 16) & 255), dg = ((a >> 8) & 255) - ((b >> 8) & 255);
                if (dr - dg > 40) n++;
            }
        return n;
    }

    @Test
    void jogIntoThePlates_collisionReported_partsDrawnRed() throws Exception {
        Path out = WorkbenchScenarioTest.SHOTS.resolve("clearance").toAbsolutePath();
        Files.createDirectories(out);
        Files.deleteIfExists(out.resolve("results.properties"));
        Process p = WorkbenchScenarioTest.java(display.display(), List.of(), ClearanceViewScenario.class.getName(), out.toString());
        String log = WorkbenchScenarioTest.finish(p, out.resolve("scenario.log"), 180);
        Properties r = new Properties();
        try (var in = Files.newBufferedReader(out.resolve("results.properties"))) { r.load(in); }
        assertEquals("done", r.getProperty("status"), log);
        String docs = System.getProperty("robopro.docImages"); // as WorkbenchScenarioTest: refresh the documentation's picture
        if (docs != null && !docs.isBlank())
            Files.copy(out.resolve("collision-on.png"), Path.of(docs).resolve("workbench-clearance.png"), java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        assertTrue(r.getProperty("readyText").startsWith("clearance "), r.getProperty("readyText"));
        assertTrue(r.getProperty("text").startsWith("COLLISION: tool - "), r.getProperty("text"));
        assertTrue(r.getProperty("highlights").contains("tool=COLLIDING"), r.getProperty("highlights"));
        assertEquals(r.getProperty("highlights"), r.getProperty("shown"), "the scene draws the reading at the robot's pose");
        BufferedImage on = ImageIO.read(out.resolve("collision-on.png").toFile());
        BufferedImage off = ImageIO.read(out.resolve("collision-off.png").toFile());
        int red = reddened(on, off);
        assertTrue(red > 300, "the colliding tool and object are drawn red: " + red + " pixels reddened");
        assertTrue(red < on.getWidth() * on.getHeight() / 4, "only the colliding parts are: " + red);
    }
}
