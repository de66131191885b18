package org.robopro.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/** simulate → calibrate → compensate through the command line, as docs/calibration.md shows. */
class CalibrationCliTest {
    @TempDir Path dir;
    final StringWriter out = new StringWriter(), err = new StringWriter();

    int run(String... args) {
        CommandLine cl = RoboproCommand.commandLine();
        cl.setOut(new PrintWriter(out, true));
        cl.setErr(new PrintWriter(err, true));
        return cl.execute(args);
    }

    @Test
    void calibrateCompensate_worldCampaignIrb2000_writesEveryOutput() throws Exception {
        // The campaign of a real robot drawn by the independent world simulator (geometric errors,
        // unknown instrument pose, sigma 0.02 mm, the measured point off the joint-6 axis at
        // (80, 40, 150) mm on the flange), one file with a train/validate set column.
        Path cal = dir.resolve("cal"), file = dir.resolve("campaign.csv");
        var robot = org.robopro.models.RobotLibrary.shipped("irb2000");
        var world = org.robopro.world.Scenario.baseRobot(robot, new java.util.Random(7), 1e-3, Math.toRadians(0.1),
                new double[] {0.08, 0.04, 0.15});
        Files.writeString(file, org.robopro.world.Campaign.run(world, robot,
                org.robopro.world.Campaign.Plan.defaults(7).withPoses(120, 80)).text());
        assertEquals(0, run("calibrate", "--robot", "irb2000", "--measurements", file.toString(), "--out", cal.toString()), err.toString());
        JsonNode s = new ObjectMapper().readTree(cal.resolve("summary.json").toFile());
        for (String k : List.of("nominal_train_rms_mm", "train_rms_mm", "nominal_validate_rms_mm", "validate_rms_mm",
                "train_max_mm", "validate_max_mm", "parameters", "unidentifiable", "outliers"))
            assertTrue(s.has(k), k);
        assertEquals(0, s.get("warnings").size(), "same set-up: no warning " + s.get("warnings"));
        assertFalse(err.toString().contains("warning"), err.toString());
        assertTrue(s.get("validate_rms_mm").asDouble() < 0.045, s.get("validate_rms_mm").toString());
        assertTrue(s.get("nominal_validate_rms_mm").asDouble() > 1);
        JsonNode p0 = s.get("parameters").get(0);
        for (String k : List.of("name", "nominal", "identified", "sigma", "unit")) assertTrue(p0.has(k), k);
        String html = Files.readString(cal.resolve("report.html"));
        assertTrue(html.contains("<svg") && html.contains("Parameters"));
        assertFalse(html.contains("<script") || html.contains("<link") || html.contains("src=\"http"), "report must be self-contained");
        assertTrue(Files.readString(cal.resolve("calibrated.robot.json")).contains("calibrated-from"));
        assertTrue(Files.readString(cal.resolve("calibrated.robot.json")).contains("\"calibration-untrustworthy-parameters\": \"none\""));

        // Compensate a few targets with the calibrated model.
        Path targets = dir.resolve("targets.csv"), comp = dir.resolve("comp.csv");
        Files.writeString(targets, "# frame: base\nx,y,z\n1200,100,900\n1100,-200,1000\n");
        assertEquals(0, run("compensate", "--nominal", "irb2000", "--calibrated", cal.resolve("calibrated.robot.json").toString(),
                "--targets", targets.toString(), "--out", comp.toString()), err.toString());
        List<String> lines = Files.readAllLines(comp);
        assertEquals(4, lines.size(), lines.toString());
        assertTrue(lines.get(2).endsWith("converged"), lines.get(2));

        // Existing outputs are not overwritten without --force.
        assertEquals(2, run("calibrate", "--robot", "irb2000", "--measurements", file.toString(), "--out", cal.toString()));
    }

    @Test
    void calibrate_validationFromAnotherSetUp_warnsInOutputAndSummary() throws Exception {
        Path a = dir.resolve("a"), b = dir.resolve("b"), cal = dir.resolve("cal");
        assertEquals(0, run("simulate", "--robot", "irb2000", "--poses", "80", "--seed", "1", "--out", a.toString()), err.toString());
        // Another seed: another robot and another tracker pose (frame), as a file from another session would be.
        assertEquals(0, run("simulate", "--robot", "irb2000", "--poses", "40", "--seed", "2", "--out", b.toString()), err.toString());
        assertEquals(0, run("calibrate", "--robot", "irb2000", "--measurements", a.resolve("measurements.csv").toString(),
                "--validate", b.resolve("measurements.csv").toString(), "--out", cal.toString()), err.toString());
        JsonNode s = new ObjectMapper().readTree(cal.resolve("summary.json").toFile());
        assertTrue(s.get("validate_rms_mm").asDouble() > 10 * s.get("train_rms_mm").asDouble());
        List<String> ws = new java.util.ArrayList<>();
        s.get("warnings").forEach(x -> ws.add(x.asText()));
        List<String> validation = ws.stream().filter(x -> x.startsWith("validation RMS")).toList();
        assertEquals(1, validation.size(), ws.toString());
        String w = validation.get(0);
        // The simulated point sits on the joint-6 axis: the wrist offsets are named as not determined, and so marked.
        assertTrue(ws.stream().anyMatch(x -> x.startsWith("j5.a is not determined") && x.contains("off the joint-6 axis")), ws.toString());
        JsonNode untrusted = s.get("untrustworthy");
        assertTrue(untrusted.toString().contains("\"j5.a\""), untrusted.toString());
        for (JsonNode p : s.get("parameters"))
            if (p.get("name").asText().equals("j5.a")) assertFalse(p.get("trustworthy").asBoolean());
            else if (p.get("name").asText().equals("j2.offset")) assertTrue(p.get("trustworthy").asBoolean());
        assertTrue(Files.readString(cal.resolve("calibrated.robot.json")).contains("j5.a"));
        assertTrue(w.contains("different instrument set-up or robot") && w.contains("seed 1") && w.contains("seed 2"), w);
        assertTrue(err.toString().contains("robopro: warning: validation RMS"), err.toString());
        assertTrue(Files.readString(cal.resolve("report.html")).contains("Warning:"));
    }

    @Test
    void calibrate_measurementFileWithWrongJointCount_failsWithLocation() throws Exception {
        Path m = dir.resolve("m.csv");
        Files.writeString(m, "# robopro-measurements 1\n# length-unit: mm\n# angle-unit: deg\npose,q1,q2,x,y,z\n1,0,0,1,2,3\n");
        assertEquals(2, run("calibrate", "--robot", "irb2000", "--measurements", m.toString(), "--out", dir.resolve("o").toString()));
        assertTrue(err.toString().contains("m.csv:4") && err.toString().contains("6 joints"), err.toString());
        assertFalse(Files.exists(dir.resolve("o")));
    }

    @Test
    void calibrate_folds_crossValidationPerFoldAndOverallAgreesWithAnIndependentValidationFile() throws Exception {
        // A robot of the independent world simulator: 150 training poses and 300 validation poses of the same
        // session (σ 0.02 mm), written as two files.
        Path cal = dir.resolve("cal"), trainFile = dir.resolve("measurements.csv"), validate = dir.resolve("validate.csv");
        var robot = org.robopro.models.RobotLibrary.shipped("irb2000");
        var world = org.robopro.world.Scenario.baseRobot(robot, new java.util.Random(12), 1e-3, Math.toRadians(0.1));
        String text = org.robopro.world.Campaign.run(world, robot, org.robopro.world.Campaign.Plan.defaults(12).withPoses(150, 300)
                .withDirColumns(false).withConditionColumns(false)).text();
        StringBuilder a = new StringBuilder(), b = new StringBuilder();
        for (String l : text.split("\n")) {
            if (l.startsWith("#")) { a.append(l).append('\n'); b.append(l).append('\n'); continue; }
            String row = l.substring(0, l.lastIndexOf(',')) + "\n"; // without the set column
            if (l.startsWith("pose,")) { a.append(row); b.append(row); }
            else (l.endsWith(",validate") ? b : a).append(row);
        }
        Files.writeString(trainFile, a.toString());
        Files.writeString(validate, b.toString());
        assertEquals(0, run("calibrate", "--robot", "irb2000", "--measurements", trainFile.toString(),
                "--validate", validate.toString(), "--folds", "5", "--out", cal.toString()), err.toString());
        JsonNode s = new ObjectMapper().readTree(cal.resolve("summary.json").toFile());
        JsonNode per = s.get("cross_validation").get("per_fold");
        assertEquals(5, per.size());
        int heldOut = 0;
        for (JsonNode f : per) {
            heldOut += f.get("poses_held_out").asInt();
            assertEquals(150, f.get("poses_held_out").asInt() + f.get("poses_train").asInt());
        }
        assertEquals(150, heldOut, "every training pose held out once");
        JsonNode errors = s.get("errors");
        double train = errors.get("train").get("calibrated").get("rms_mm").asDouble();
        double cv = errors.get("cross_validation").get("calibrated").get("rms_mm").asDouble();
        double val = errors.get("validate").get("calibrated").get("rms_mm").asDouble();
        assertTrue(cv > train, "held-out errors exceed the in-sample ones: " + cv + " vs " + train);
        assertTrue(Math.abs(cv - val) < 0.25 * val, "cross-validation estimates the error on unseen poses: " + cv + " vs " + val);
        for (String k : List.of("n", "rms_mm", "mean_mm", "median_mm", "p95_mm", "max_mm"))
            assertTrue(errors.get("validate").get("nominal").has(k), k);
        JsonNode st = errors.get("validate").get("calibrated");
        assertTrue(st.get("median_mm").asDouble() <= st.get("p95_mm").asDouble() && st.get("p95_mm").asDouble() <= st.get("max_mm").asDouble());
        assertTrue(out.toString().contains("5-fold cross-validation") && out.toString().contains("p95"), out.toString());

        List<String> rows = Files.readAllLines(cal.resolve("residuals.csv"));
        assertEquals(1 + 150 + 300, rows.size());
        assertTrue(rows.get(0).startsWith("pose,set,fold,outlier,nominal_mm,dx_mm,dy_mm,dz_mm,norm_mm"), rows.get(0));
        for (String row : rows.subList(1, rows.size())) {
            String[] c = row.split(",", -1);
            double dx = Double.parseDouble(c[5]), dy = Double.parseDouble(c[6]), dz = Double.parseDouble(c[7]), n = Double.parseDouble(c[8]);
            assertEquals(n, Math.sqrt(dx * dx + dy * dy + dz * dz), 2e-6, row);
            assertEquals(c[1].equals("train"), !c[2].isEmpty(), row);
        }
        assertTrue(Files.readString(cal.resolve("report.html")).contains("Cross-validation"));
    }

    @Test
    void calibrate_knownBaseAndTool_keptFixedOrUsedAsStart() throws Exception {
        Path sim = dir.resolve("sim"), free = dir.resolve("free"), known = dir.resolve("known"), wrong = dir.resolve("wrong"),
                start = dir.resolve("start");
        assertEquals(0, run("simulate", "--robot", "irb2000", "--poses", "100", "--target", "80,40,150", "--seed", "5",
                "--out", sim.toString()), err.toString());
        String m = sim.resolve("measurements.csv").toString();
        assertEquals(0, run("calibrate", "--robot", "irb2000", "--measurements", m, "--out", free.toString()), err.toString());
        ObjectMapper om = new ObjectMapper();
        JsonNode f = om.readTree(free.resolve("summary.json").toFile());
        // A registration known from elsewhere (here: the free fit's) is kept as given.
        assertEquals(0, run("calibrate", "--robot", "irb2000", "--measurements", m, "--base", free.resolve("summary.json").toString(),
                "--tool", free.resolve("summary.json").toString(), "--out", known.toString()), err.toString());
        JsonNode k = om.readTree(known.resolve("summary.json").toFile());
        for (JsonNode p : k.get("parameters"))
            if (p.get("block").asText().equals("instrument") || p.get("block").asText().equals("tool"))
                assertTrue(p.get("fixed").asBoolean(), p.toString());
        for (String c : List.of("x_mm", "y_mm", "z_mm", "qw"))
            assertEquals(f.get("instrument_T_base").get(c).asDouble(), k.get("instrument_T_base").get(c).asDouble(), 1e-9, c);
        double freeRms = f.get("train_rms_mm").asDouble();
        assertEquals(freeRms, k.get("train_rms_mm").asDouble(), 0.05 * freeRms);
        assertTrue(Files.readString(known.resolve("calibrated.robot.json")).contains("given, kept fixed"));

        // A base 5 mm off, kept fixed, spoils the fit (the option really fixes it); as a start only, the fit recovers.
        JsonNode b = f.get("instrument_T_base");
        String off = String.format(java.util.Locale.ROOT, "%.9f,%.9f,%.9f,%.12f,%.12f,%.12f,%.12f", b.get("x_mm").asDouble() + 5,
                b.get("y_mm").asDouble(), b.get("z_mm").asDouble(), b.get("qw").asDouble(), b.get("qx").asDouble(), b.get("qy").asDouble(),
                b.get("qz").asDouble());
        assertEquals(0, run("calibrate", "--robot", "irb2000", "--measurements", m, "--base", off, "--out", wrong.toString()), err.toString());
        assertTrue(om.readTree(wrong.resolve("summary.json").toFile()).get("train_rms_mm").asDouble() > 10 * freeRms);
        assertEquals(0, run("calibrate", "--robot", "irb2000", "--measurements", m, "--base", off, "--free-base", "--out", start.toString()),
                err.toString());
        assertEquals(freeRms, om.readTree(start.resolve("summary.json").toFile()).get("train_rms_mm").asDouble(), 0.05 * freeRms);
        assertEquals(2, run("calibrate", "--robot", "irb2000", "--measurements", m, "--base", "1,2", "--out", dir.resolve("bad").toString()));
    }

    @Test
    void measurementsJoin_pointListAndJointLog_campaignThatCalibrates() throws Exception {
        Path sim = dir.resolve("sim");
        assertEquals(0, run("simulate", "--robot", "irb2000", "--poses", "60", "--target", "80,40,150", "--seed", "9",
                "--out", sim.toString()), err.toString());
        // Split the simulated campaign into what a tracker and a controller would export: names, points; names, joints.
        List<String> lines = Files.readAllLines(sim.resolve("measurements.csv"));
        StringBuilder pts = new StringBuilder("# frame: tracker\nname,x,y,z\n"), log = new StringBuilder("name,q1,q2,q3,q4,q5,q6\n");
        for (String l : lines) {
            if (l.startsWith("#") || l.startsWith("pose")) continue;
            String[] c = l.split(",");
            pts.append("P").append(c[0]).append(',').append(c[7]).append(',').append(c[8]).append(',').append(c[9]).append('\n');
            log.append("P").append(c[0]);
            for (int k = 1; k <= 6; k++) log.append(',').append(c[k]);
            log.append('\n');
        }
        Path p = dir.resolve("points.csv"), j = dir.resolve("joints.csv"), joined = dir.resolve("joined.csv");
        Files.writeString(p, pts);
        Files.writeString(j, log);
        assertEquals(0, run("measurements", "join", "--robot", "irb2000", "--points", p.toString(), "--joints", j.toString(),
                "--out", joined.toString()), err.toString());
        assertTrue(out.toString().contains("60 poses"), out.toString());
        assertEquals(0, run("calibrate", "--robot", "irb2000", "--measurements", joined.toString(), "--out", dir.resolve("cal").toString()),
                err.toString());
        JsonNode s = new ObjectMapper().readTree(dir.resolve("cal/summary.json").toFile());
        assertTrue(s.get("train_rms_mm").asDouble() < 0.05, s.get("train_rms_mm").toString());
    }
}
