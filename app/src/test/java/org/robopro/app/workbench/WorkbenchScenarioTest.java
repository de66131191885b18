package org.robopro.app.workbench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Properties;
import java.util.concurrent.TimeUnit;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * End-to-end workbench tests under X (Xvfb when DISPLAY is unset): the user scenario of
 * {@link WorkbenchScenario}, the screenshot command, and the failure when no GL context can be
 * created. Screenshots are kept in app/target/screenshots as test artifacts.
 */
class WorkbenchScenarioTest {
    static final Path SHOTS = Path.of("target", "screenshots");
    static XvfbDisplay display;

    @BeforeAll
    static void startDisplay() throws Exception {
        display = XvfbDisplay.acquire();
        Files.createDirectories(SHOTS);
    }

    @AfterAll
    static void stopDisplay() {
        if (display != null) display.close();
    }

    static Process java(String display, List<String> extraEnv, String mainClass, String... args) throws Exception {
        List<String> cmd = new ArrayList<>();
        cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        cmd.add("-Xmx768m");
        cmd.add("-cp");
        cmd.add(System.getProperty("java.class.path"));
        cmd.add(mainClass);
        cmd.addAll(List.of(args));
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectErrorStream(true);
        pb.environment().put("DISPLAY", display);
        pb.environment().put("robopro.test", "1");
        for (String kv : extraEnv) pb.environment().put(kv.substring(0, kv.indexOf('=')), kv.substring(kv.indexOf('=') + 1));
        return pb.start();
    }

    static String finish(Process p, Path log, int seconds) throws Exception {
        byte[] all = p.getInputStream().readAllBytes();
        boolean done = p.waitFor(seconds, TimeUnit.SECONDS);
        if (!done) p.destroyForcibly();
        Files.write(log, all);
        assertTrue(done, "process did not finish within " + seconds + " s; log " + log);
        return new String(all);
    }

    /** Fraction of pixels in the rectangle whose red, green, blue pass {@code colour}. */
    static double fraction(BufferedImage img, int x0, int y0, int x1, int y1, java.util.function.IntPredicate colour) {
        int n = 0, hit = 0;
        for (int y = y0; y < y1; y++)
            for (int x = x0; x < x1; x++) {
                n++;
                if (colour.test(img.getRGB(x, y))) hit++;
            }
        return (double) hit / n;
    }

    /** Fraction of pixels in the rectangle close to ABB orange (the robot). */
    static double orangeFraction(BufferedImage img, int x0, int y0, int x1, int y1) {
        return fraction(img, x0, y0, x1, y1, c -> {
            int r = (c >> 16) & 255, g = (c >> 8) & 255, b = c & 255;
            return r > 120 && r > g + 45 && g > b + 20 && b < 90;
        });
    }

    static int colourCount(BufferedImage img) {
        java.util.Set<Integer> s = new java.util.HashSet<>();
        for (int y = 0; y < img.getHeight(); y += 3)
            for (int x = 0; x < img.getWidth(); x += 3) s.add(img.getRGB(x, y) & 0xF0F0F0);
        return s.size();
    }

    /** Pixels of the translucent blue ghost robot. */
    static int blueCount(BufferedImage img) {
        int hit = 0;
        for (int y = 60; y < Math.min(460, img.getHeight()); y++)
            for (int x = 230; x < Math.min(940, img.getWidth()); x++) {
                int c = img.getRGB(x, y);
                int r = (c >> 16) & 255, g = (c >> 8) & 255, b = c & 255;
                if (b > r + 50 && b > g + 20) hit++;
            }
        return hit;
    }

    static int redCount(BufferedImage img) {
        int hit = 0;
        for (int y = 0; y < img.getHeight(); y++)
            for (int x = 0; x < img.getWidth(); x++) {
                int c = img.getRGB(x, y);
                int r = (c >> 16) & 255, g = (c >> 8) & 255, b = c & 255;
                if (r > 180 && g < 70 && b < 70) hit++;
            }
        return hit;
    }

    /** The scenario's screenshots and the docs/images names they are published under. */
    static final String[][] DOC_IMAGES = {{"01-cell.png", "workbench-cell.png"}, {"02-path.png", "workbench-program.png"},
            {"03-layout.png", "workbench-layout.png"}, {"04-wizard.png", "workbench-wizard.png"},
            {"06-controller.png", "workbench-controller.png"}, {"07-calibration.png", "workbench-calibration.png"},
            {"08-diagnosis.png", "workbench-diagnosis.png"}};

    /**
     * With {@code -Drobopro.docImages=DIR} (e.g. {@code ../docs/images}) the screenshots, taken at
     * 1280 x 720, replace the documentation's pictures.
     */
    static void copyToDocs(Path out) throws java.io.IOException {
        String dir = System.getProperty("robopro.docImages");
        if (dir == null || dir.isBlank()) return;
        for (String[] m : DOC_IMAGES)
            Files.copy(out.resolve(m[0]), Path.of(dir).resolve(m[1]), java.nio.file.StandardCopyOption.REPLACE_EXISTING);
    }

    @Test
    void scenario_loadJogTeachCheckExport_resultsAndPicturesAsExpected() throws Exception {
        Path out = SHOTS.resolve("scenario").toAbsolutePath();
        Files.createDirectories(out);
        Files.deleteIfExists(out.resolve("results.properties"));
        Process p = java(display.display(), List.of(), WorkbenchScenario.class.getName(), out.toString());
        String log = finish(p, out.resolve("scenario.log"), 240);
        Properties r = new Properties();
        try (var in = Files.newBufferedReader(out.resolve("results.properties"))) { r.load(in); }
        assertEquals("done", r.getProperty("status"), "scenario failed; see " + out.resolve("scenario.log") + "\n" + log);
        copyToDocs(out);

        assertEquals("5", r.getProperty("objects"), "the shipped irb2000-welding cell has five objects");
        assertNotEquals(r.getProperty("q0"), r.getProperty("qJointJog"));
        assertTrue(r.getProperty("qJointJog").startsWith("10.000000 30.000000"), r.getProperty("qJointJog"));
        assertEquals("true", r.getProperty("cartesianJogOk"));
        assertEquals(-0.050, Double.parseDouble(r.getProperty("cartesianDz")), 1e-6);
        assertEquals(0, Double.parseDouble(r.getProperty("cartesianDxy")), 1e-6);
        assertEquals(0, Double.parseDouble(r.getProperty("cartesianAngle")), 1e-6);
        assertEquals("p10,p20,p30", r.getProperty("targets"));
        assertEquals("MoveJ p10, v500, z10, tool;;MoveL p20, v500, z10, tool;;MoveL p30, v500, z10, tool;;MoveL p10, v500, z10, tool;",
                r.getProperty("program"));
        assertEquals("true", r.getProperty("checkOk"));
        assertTrue(Double.parseDouble(r.getProperty("duration")) > 0.3, r.getProperty("duration"));
        assertEquals("false", r.getProperty("checkWithFarOk"));
        assertEquals("UNREACHABLE", r.getProperty("farStatus"));
        assertEquals("UNREACHABLE p99", r.getProperty("farProblem"), "the path checker names the instruction's target");
        assertEquals("p99", r.getProperty("badTargets"));
        assertEquals("true", r.getProperty("rapidOverwriteRefused"));
        String rapid = Files.readString(Path.of(r.getProperty("rapidFile")));
        assertTrue(rapid.startsWith("MODULE Weld"), rapid);
        for (String s : new String[] {"CONST robtarget p10:=[[", "CONST robtarget p20", "CONST robtarget p30",
                "MoveJ p10, v500, z10, torch;", "MoveL p30, v500, z10, torch;", "PERS tooldata torch:=[TRUE,[[110,0,340]", "ENDMODULE"})
            assertTrue(rapid.contains(s), "RAPID lacks " + s + ":\n" + rapid);
        assertEquals("true", r.getProperty("importOk"));
        assertEquals("true", r.getProperty("importSameProgram"), "export then import must give the same program");
        assertEquals("p10,p20,p30", r.getProperty("importTargets"));
        // The program table of the imported program, right after the import and in the 03-layout
        // picture: p10, taught at the robot's own pose (axes 4 and 6 at 0), exported and read back,
        // is reachable in its own configuration, and so is every other move.
        for (String key : new String[] {"importCheck", "table.03-layout"}) {
            String[] rows = r.getProperty(key, "").split(" \\| ");
            assertEquals(4, rows.length, key + ": " + r.getProperty(key));
            for (String row : rows) assertTrue(row.startsWith("ok "), key + ": " + r.getProperty(key));
        }
        String[] pathRows = r.getProperty("table.02-path", "").split(" \\| ");
        assertEquals(5, pathRows.length, r.getProperty("table.02-path"));
        for (int i = 0; i < 4; i++) assertTrue(pathRows[i].startsWith("ok "), "02-path: " + r.getProperty("table.02-path"));
        assertTrue(pathRows[4].startsWith("FAIL unreachable"), "02-path: the far target p99 fails: " + r.getProperty("table.02-path"));
        // Every other picture's program is sound: no FAIL or warning in its table, and the kept
        // calls of 10-kept-statements show the outcome of the motions they ran.
        for (String shot : new String[] {"03-layout", "04-wizard", "05-new-robot", "06-controller", "07-calibration", "08-diagnosis",
                "09-large", "10-kept-statements"}) {
            String table = r.getProperty("table." + shot, "");
            assertTrue(!table.isEmpty() && !table.contains("FAIL") && !table.contains("warning"), shot + ": " + table);
        }
        assertTrue(r.getProperty("table.10-kept-statements").matches("ok [0-9.]+ s \\| ok [0-9.]+ s"), r.getProperty("table.10-kept-statements"));
        // In every picture the table shows the last check of the program it lists.
        for (String shot : new String[] {"02-path", "03-layout", "04-wizard", "05-new-robot", "06-controller", "07-calibration",
                "08-diagnosis", "09-large", "10-kept-statements"})
            assertEquals("", r.getProperty("stale." + shot), shot);
        assertEquals("false", r.getProperty("brokenImportOk"));
        assertTrue(r.getProperty("brokenImportError").contains("Broken.mod") && r.getProperty("brokenImportError").contains("line "),
                r.getProperty("brokenImportError"));
        assertEquals("4", r.getProperty("afterBrokenProgram"), "a broken import leaves the program as it was");
        assertTrue(!rapid.contains("p99"), "the removed target must not be exported");
        assertEquals("6", r.getProperty("objectsAfterAdd"));
        // Nothing a user needs is clipped at 1280 x 720 (toolbar buttons, table columns, labels, tree rows), nor at 1920 x 1080.
        for (String k : new String[] {"clippedMain", "clippedController", "clippedCalibration", "clippedDiagnosis", "clippedWizard", "clippedLarge"})
            assertEquals("", r.getProperty(k), k);
        assertEquals("true", r.getProperty("escapeClosedDock"), "Escape closes a docked panel");
        assertTrue(r.getProperty("undoName").startsWith("Undo Move Table"), r.getProperty("undoName"));
        assertEquals("5", r.getProperty("objectsAfterUndo"), "Edit > Undo took the table back");
        assertEquals("6", r.getProperty("objectsAfterRedo"), "Edit > Redo put it back");
        assertEquals("3", r.getProperty("reopenedTargets"));
        assertEquals("4", r.getProperty("reopenedProgram"));
        assertEquals("6", r.getProperty("reopenedObjects"));
        assertTrue(r.getProperty("damaged").contains("damaged.robopro.json"), r.getProperty("damaged"));
        assertTrue(Integer.parseInt(r.getProperty("damagedLine")) > 1, r.getProperty("damaged"));
        assertTrue(r.getProperty("damagedField").endsWith("speed_mm_s"), r.getProperty("damagedField"));
        assertEquals("3", r.getProperty("afterDamagedTargets"), "a damaged project must not disturb the open one");
        assertTrue(r.getProperty("projectFile").endsWith("cell.robopro.json"));

        assertEquals("false", r.getProperty("downloadEnabledBefore"), "controller actions wait for a connection");
        assertEquals("true", r.getProperty("downloadEnabledAfter"));
        assertEquals("irb2000", r.getProperty("controllerRobot"));
        assertEquals("cell", r.getProperty("downloadedName"), "the program is named after the project file");
        assertTrue(Integer.parseInt(r.getProperty("downloadedLength")) > 300, r.getProperty("downloadedLength"));
        assertEquals("IDLE", r.getProperty("runState"), r.getProperty("controllerLog"));
        assertEquals(0, Double.parseDouble(r.getProperty("ghostToLastTargetMm")), 0.05,
                "after the run the real robot's joints put the TCP at the program's last target");
        assertEquals("4", r.getProperty("uploadedInstructions"));
        assertEquals("4", r.getProperty("programAfterUpload"));
        assertTrue(r.getProperty("controllerLog").contains("succeeded"), r.getProperty("controllerLog"));
        assertEquals("true", r.getProperty("moveCCheckOk"));
        assertTrue(r.getProperty("moveCRunState").startsWith("IDLE"), r.getProperty("moveCRunState"));
        assertEquals(0, Double.parseDouble(r.getProperty("moveCGhostToP30Mm")), 0.05, "MoveC ends at its ToPoint on the controller");
        assertEquals("main,twice", r.getProperty("uploadOfferedProcs"));
        assertEquals("RAPID main;|RAPID main;", r.getProperty("uploadTwiceProgram"), "PROC twice calls main twice: two calls kept as written");
        assertEquals("MoveJ p10;MoveC p30;MoveJ p10;MoveC p30", r.getProperty("uploadTwiceMotions"), "the calls' motions are run, checked and drawn");
        assertEquals("2", r.getProperty("uploadCancelled"), "choosing no PROC leaves the program as it was");
        assertEquals("false", r.getProperty("ghostAfterDisconnect"));
        BufferedImage ctl = ImageIO.read(out.resolve("06-controller.png").toFile());
        assertTrue(blueCount(ctl) > 500, "no ghost robot in 06-controller.png");

        assertEquals("true", r.getProperty("calLoaded"));
        assertEquals("CancellationException", r.getProperty("calCancelled"), "Cancel stops the background calibration");
        assertEquals("true", r.getProperty("calSummarySameAsCli"), "the workbench and robopro calibrate give the same summary.json");
        assertEquals("cancelled", r.getProperty("calStateAfterCancel"));
        assertEquals("done", r.getProperty("calState"));
        assertEquals("1000", r.getProperty("calProgress"));
        double before = Double.parseDouble(r.getProperty("calNominalRmsMm")), after = Double.parseDouble(r.getProperty("calRmsMm"));
        assertTrue(before > 1, "the world's robot has millimetres of error: " + before);
        assertTrue(after < 0.1, "calibration reaches the noise floor: " + after);
        assertTrue(Double.parseDouble(r.getProperty("calValidateRmsMm")) < 0.1, r.getProperty("calValidateRmsMm"));
        assertTrue(r.getProperty("calRms").contains("Training RMS ") && r.getProperty("calRms").contains("Validation RMS "), r.getProperty("calRms"));
        for (String fig : r.getProperty("calCliFigures").split("\\|"))
            assertTrue(r.getProperty("calRms").contains(fig), "the panel shows robopro calibrate's figure '" + fig + "': " + r.getProperty("calRms"));
        assertTrue(r.getProperty("calEffects").contains("correction"), r.getProperty("calEffects"));
        assertEquals("true", r.getProperty("calApplied"));
        assertTrue(r.getProperty("calReference").endsWith("irb2000-calibrated.robot.json"), r.getProperty("calReference"));
        assertEquals("true", r.getProperty("compensatedDiffers"), "the applied calibration changes the exported targets");
        assertTrue(r.getProperty("compensationLog").startsWith("Compensated 3 targets"), r.getProperty("compensationLog"));

        assertEquals("true", r.getProperty("diagLoaded"));
        assertEquals("CancellationException", r.getProperty("diagCancelled"), "Cancel stops the background diagnosis");
        assertEquals("done", r.getProperty("diagState"));
        assertEquals("1000", r.getProperty("diagProgress"));
        assertEquals("backlash j1", r.getProperty("diagEffects"), "the concealed lost motion on joint 1 is found, nothing else");
        String words = r.getProperty("diagFindings");
        for (String s : new String[] {"Backlash", "on joint 1", "b = ", " deg", "RMS: training", "validation", "Evidence:", "Outliers",
                "What to record next"})
            assertTrue(words.contains(s), "the findings lack '" + s + "':\n" + words);
        double floor = Double.parseDouble(r.getProperty("diagFloorMm"));
        assertTrue(Double.parseDouble(r.getProperty("diagGeometricValidateMm")) > 1.5 * floor, r.getProperty("diagGeometricValidateMm"));
        assertTrue(Double.parseDouble(r.getProperty("diagFinalValidateMm")) < 1.2 * floor, r.getProperty("diagFinalValidateMm"));
        assertEquals("true", r.getProperty("diagApplied"));
        assertEquals("1", r.getProperty("diagExtendedEffects"));
        assertEquals("1", r.getProperty("diagFileHasEffects"), "the extended robot file carries the effect");
        assertEquals("true", r.getProperty("diagCompensatedDiffers"));
        assertTrue(r.getProperty("diagCompensationLog").contains("extended model"), r.getProperty("diagCompensationLog"));
        BufferedImage diag = ImageIO.read(out.resolve("08-diagnosis.png").toFile());
        assertTrue(colourCount(diag) > 40, "08-diagnosis.png looks uniform");

        assertEquals("6", r.getProperty("wizardJoints"));
        assertEquals("true", r.getProperty("wizardFirstOk"));
        assertEquals("false", r.getProperty("wizardBrokenOk"));
        assertTrue(r.getProperty("wizardBrokenError").contains("axis"), r.getProperty("wizardBrokenError"));
        assertEquals("true", r.getProperty("wizardFixedOk"), r.getProperty("wizardError"));
        assertEquals("", r.getProperty("wizardError"));
        assertEquals(Double.parseDouble(r.getProperty("wizardFlangeZ0")) + 0.2, Double.parseDouble(r.getProperty("wizardFlangeZ")), 1e-9,
                "the flange frame follows the typed flange origin");
        assertEquals("8", r.getProperty("wizardPreviewFrames"), "base, six links, flange");
        assertEquals("8", r.getProperty("wizardPreviewDrawn"));
        assertEquals("6", r.getProperty("wizardPreviewDrums"), "a drum on each joint axis");
        assertTrue(Integer.parseInt(r.getProperty("wizardPreviewLinksExpected")) >= 4);
        assertEquals(r.getProperty("wizardPreviewLinksExpected"), r.getProperty("wizardPreviewLinks"), "links from joint to joint and to the flange");
        assertEquals("Undo Robot model: flange origin mm z", r.getProperty("wizardUndoName"), "the Edit menu names the wizard's edit");
        assertEquals(-200, Double.parseDouble(r.getProperty("wizardCtrlZFlangeDelta")), 1e-9, "Ctrl+Z in the wizard undoes its last edit");
        assertEquals(0, Double.parseDouble(r.getProperty("wizardCtrlYFlangeDelta")), 1e-9, "Ctrl+Y redoes it");
        assertEquals("irb2000", r.getProperty("undoUseInCellRobot"), "Undo takes Use in cell back first");
        assertEquals("true", r.getProperty("undoWizardReopened"), "undoing a closed wizard's edit opens it again");
        assertEquals(Double.parseDouble(r.getProperty("redoWizardFlangeZ")) - 200, Double.parseDouble(r.getProperty("undoWizardFlangeZ")), 1e-9,
                "the wizard's last edit (flange z + 200 mm) taken back");
        assertEquals("irb2000_long", r.getProperty("redoRobot"), "Redo makes both again");
        assertEquals("true", r.getProperty("wizardReportHasTable"));
        assertEquals("true", r.getProperty("wizardSaved"));
        assertEquals("true", r.getProperty("wizardOverwriteRefused"));
        assertEquals("true", r.getProperty("wizardOverwriteConfirmed"));
        assertEquals("true", r.getProperty("wizardUsed"));
        assertEquals("irb2000_long", r.getProperty("cellRobot"));
        assertTrue(r.getProperty("cellRobotRef").endsWith("irb2000_long.robot.json"), r.getProperty("cellRobotRef"));
        assertEquals("false", r.getProperty("previewAfterUse"));
        assertEquals("irb2000_long", r.getProperty("reopenedRobot"));
        BufferedImage wizard = ImageIO.read(out.resolve("04-wizard.png").toFile());
        assertTrue(orangeFraction(wizard, 230, 60, 640, 460) > 0.005, "no preview drums in the 3D view of 04-wizard.png");
        assertTrue(colourCount(wizard) > 40);
        BufferedImage newRobot = ImageIO.read(out.resolve("05-new-robot.png").toFile());
        assertTrue(orangeFraction(newRobot, 230, 60, 940, 460) > 0.01, "the new robot is not drawn in 05-new-robot.png");

        BufferedImage cell = ImageIO.read(out.resolve("01-cell.png").toFile());
        assertEquals(1280, cell.getWidth());
        assertTrue(colourCount(cell) > 40, "01-cell.png looks uniform: " + colourCount(cell) + " colours");
        // The 3D view lies right of the tree (x > 230) and above the program panel (y < 460).
        assertTrue(orangeFraction(cell, 230, 60, 940, 460) > 0.01, "no robot-orange in the 3D view of 01-cell.png");
        BufferedImage path = ImageIO.read(out.resolve("02-path.png").toFile());
        assertTrue(orangeFraction(path, 230, 60, 940, 460) > 0.01, "no robot in 02-path.png");
        assertTrue(redCount(path) > 30, "the unreachable target is not marked red in 02-path.png");
        BufferedImage layout = ImageIO.read(out.resolve("03-layout.png").toFile());
        assertTrue(colourCount(layout) > 40);
    }

    @Test
    void screenshotCommand_defaultCell_writesWholeWindowPng() throws Exception {
        Path png = SHOTS.resolve("workbench-command.png").toAbsolutePath();
        Files.deleteIfExists(png);
        Process p = java(display.display(), List.of(), "org.robopro.app.Main", "workbench", "--screenshot", png.toString(), "--size", "1024x640");
        String log = finish(p, SHOTS.resolve("workbench-command.log"), 120);
        assertEquals(0, p.exitValue(), log);
        BufferedImage img = ImageIO.read(png.toFile());
        assertEquals(1024, img.getWidth());
        assertEquals(640, img.getHeight());
        assertTrue(orangeFraction(img, 0, 0, img.getWidth(), img.getHeight()) * img.getWidth() * img.getHeight() > 1500, "no robot in the screenshot");
    }

    /** Fraction of pixels in the rectangle of the PUMA's warm light grey castings (neither the bluish floor nor the sky). */
    static double creamFraction(BufferedImage img, int x0, int y0, int x1, int y1) {
        return fraction(img, x0, y0, x1, y1, c -> {
            int r = (c >> 16) & 255, g = (c >> 8) & 255, b = c & 255;
            return r > 120 && r >= g && g >= b && r - b >= 6 && r - b < 45;
        });
    }

    /**
     * Every shipped robot drawn from its own model (IRB 2000 procedural, IRB 2400 and PUMA 560
     * meshes) at the same pose: one --screenshot each, the robots cut out side by side into
     * docs/images/workbench-robots.png when -Drobopro.docImages is set.
     */
    @Test
    void screenshotCommand_shippedRobots_eachDrawnFromItsModel() throws Exception {
        String[] robots = {"irb2000", "irb2400", "puma560"};
        int cw = 300, ch = 280, k = 2;
        BufferedImage sheet = new BufferedImage(cw * k * robots.length, ch * k, BufferedImage.TYPE_INT_RGB);
        var g = sheet.createGraphics();
        g.setRenderingHint(java.awt.RenderingHints.KEY_INTERPOLATION, java.awt.RenderingHints.VALUE_INTERPOLATION_BICUBIC);
        for (int i = 0; i < robots.length; i++) {
            Path project = SHOTS.resolve("robot-" + robots[i] + ".robopro.json").toAbsolutePath();
            Files.writeString(project, "{ \"format\" : \"robopro-project\", \"version\" : 2, \"cell\" : { \"format\" : \"robopro-cell 1\", "
                    + "\"name\" : \"c\", \"robot\" : { \"ref\" : \"" + robots[i] + "\", \"base\" : { \"position\" : [ 0, 0, 0 ], "
                    + "\"quaternion\" : [ 1, 0, 0, 0 ] } }, \"objects\" : [], \"tools\" : [], \"work_objects\" : [] }, \"targets\" : [], "
                    + "\"programs\" : [ { \"name\" : \"main\", \"instructions\" : [] } ], \"calibration\" : { \"reference\" : null }, "
                    + "\"workbench_state\" : { \"joints_deg\" : [ 30, 20, 20, 40, 30, 0 ] } }");
            Path png = SHOTS.resolve("robot-" + robots[i] + ".png").toAbsolutePath();
            Files.deleteIfExists(png);
            Process p = java(display.display(), List.of(), "org.robopro.app.Main", "workbench", "--screenshot", png.toString(),
                    "--project", project.toString(), "--size", "1280x720");
            String log = finish(p, SHOTS.resolve("robot-" + robots[i] + ".log"), 120);
            assertEquals(0, p.exitValue(), log);
            BufferedImage img = ImageIO.read(png.toFile());
            int x0 = 400, y0 = 70;
            double robot = robots[i].equals("puma560") ? creamFraction(img, x0, y0, x0 + cw, y0 + ch) : orangeFraction(img, x0, y0, x0 + cw, y0 + ch);
            assertTrue(robot * cw * ch > 2500, robots[i] + ": robot not drawn in its colours (" + Math.round(robot * cw * ch) + " pixels)");
            g.drawImage(img.getSubimage(x0, y0, cw, ch), i * cw * k, 0, cw * k, ch * k, null);
        }
        g.dispose();
        ImageIO.write(sheet, "png", SHOTS.resolve("robots.png").toFile());
        String dir = System.getProperty("robopro.docImages");
        if (dir != null && !dir.isBlank()) ImageIO.write(sheet, "png", Path.of(dir).resolve("workbench-robots.png").toFile());
    }

    @Test
    void screenshotCommand_noGlContext_failsWithNonZeroStatus() throws Exception {
        Path png = SHOTS.resolve("no-gl.png").toAbsolutePath();
        Files.deleteIfExists(png);
        // Mesa cannot create any context when told to expose OpenGL 1.1 only; jME needs 2.0+.
        Process p = java(display.display(), List.of("MESA_GL_VERSION_OVERRIDE=1.1", "MESA_GLSL_VERSION_OVERRIDE=100"),
                "org.robopro.app.Main", "workbench", "--screenshot", png.toString(), "--first-frame-timeout", "15");
        String log = finish(p, SHOTS.resolve("no-gl.log"), 120);
        assertNotEquals(0, p.exitValue(), "must fail loudly without GL:\n" + log);
        assertTrue(log.contains("robopro workbench:"), log);
        assertTrue(!new File(png.toString()).exists(), "no picture may be written");
    }
}
