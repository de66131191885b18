package org.robopro.app.workbench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * The welding cell drawn with and without shadows: with them, floor under the casters gets
 * darker and nothing gets lighter; everywhere else (the floor away from the casters, drawn
 * without a shadow pass, the sky, the robot) the two pictures are the same, so the
 * shadow-receiving patch of floor leaves no seam.
 */
class ShadowLookTest {
    static XvfbDisplay display;

    @BeforeAll
    static void startDisplay() throws Exception {
        display = XvfbDisplay.acquire();
        Files.createDirectories(WorkbenchScenarioTest.SHOTS);
    }

    @AfterAll
    static void stopDisplay() {
        if (display != null) display.close();
    }

    private static BufferedImage shot(String name, String... extra) throws Exception {
        Path png = WorkbenchScenarioTest.SHOTS.resolve(name + ".png").toAbsolutePath();
        Files.deleteIfExists(png);
        List<String> args = new java.util.ArrayList<>(List.of("workbench", "--screenshot", png.toString(), "--size", "1280x720"));
        args.addAll(List.of(extra));
        Process p = WorkbenchScenarioTest.java(display.display(), List.of(), "org.robopro.app.Main", args.toArray(new String[0]));
        String log = WorkbenchScenarioTest.finish(p, WorkbenchScenarioTest.SHOTS.resolve(name + ".log"), 120);
        assertEquals(0, p.exitValue(), log);
        return ImageIO.read(png.toFile());
    }

    private static int luminance(int rgb) {
        return (299 * ((rgb >> 16) & 255) + 587 * ((rgb >> 8) & 255) + 114 * (rgb & 255)) / 1000;
    }

    @Test
    void shadowsDarkenTheFloorUnderTheCastersAndChangeNothingElse() throws Exception {
        BufferedImage on = shot("shadows-on");
        BufferedImage off = shot("shadows-off", "--no-shadows");
        // The 3D view: right of the cell tree, left of the properties, above the program panel.
        int x0 = 230, y0 = 60, x1 = 935, y1 = 440;
        int darker = 0, lighter = 0, changedFar = 0;
        for (int y = y0; y < y1; y++)
            for (int x = x0; x < x1; x++) {
                int d = luminance(on.getRGB(x, y)) - luminance(off.getRGB(x, y));
                if (d < -12) darker++;
                if (d > 12) lighter++;
                // The far right of the view is floor and sky well away from every caster.
                if (x > 820 && d != 0) changedFar++;
            }
        assertTrue(darker > 2000, "shadows darken the floor under the robot and cell objects: " + darker + " pixels");
        assertTrue(lighter < darker / 100 + 20, "shadows only darken: " + lighter + " pixels got lighter");
        assertEquals(0, changedFar, "the floor away from the casters must look the same with and without shadows");
    }
}
