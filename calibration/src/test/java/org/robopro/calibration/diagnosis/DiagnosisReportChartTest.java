package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.report.Figure;

/**
 * The diagnosis report's RMS bar chart: one bar per row of the report's RMS table (geometric,
 * after each effect, final fit), training and validation side by side, bar heights in
 * proportion to the table's values, the noise floor √3·σ dashed at its height, the legend above
 * the plot, and the same drawing in the HTML report's SVG.
 */
class DiagnosisReportChartTest {
    /** Records bars (filled rectangles), dashed lines and texts. */
    private static final class Recorder implements Figure.Canvas {
        record Box(double x, double y, double w, double h, String color) { }
        record Text(double x, double y, String s) { }
        final List<Box> rects = new ArrayList<>();
        final List<double[]> dashed = new ArrayList<>();
        final List<double[]> solid = new ArrayList<>();
        final List<Text> texts = new ArrayList<>();

        @Override public void line(double x1, double y1, double x2, double y2, String color, double width, boolean d) {
            (d ? dashed : solid).add(new double[] {x1, y1, x2, y2});
        }
        @Override public void rect(double x, double y, double w, double h, String color, double opacity) { rects.add(new Box(x, y, w, h, color)); }
        @Override public void circle(double cx, double cy, double r, String color) { }
        @Override public void polyline(double[] xs, double[] ys, int n, String color, double width) { }
        @Override public void text(double x, double y, String s, int anchor, double size, boolean bold, boolean vertical) {
            texts.add(new Text(x, y, s));
        }
        @Override public double textWidth(String s, double size) { return 0.56 * size * s.length(); }
    }

    /** Two effects found, validation data present; RMS figures in metres as the diagnoser reports them. */
    static Diagnosis diagnosis(boolean validation) {
        double nan = Double.NaN;
        List<Diagnosis.Finding> effects = List.of(
                new Diagnosis.Finding(Effect.backlash(0), new double[] {7e-4}, new double[] {1e-5}, 0.21e-3, validation ? 0.24e-3 : nan,
                        null, null, "backlash on joint 1"),
                new Diagnosis.Finding(Effect.scale(1), new double[] {1e-4}, new double[] {1e-6}, 0.09e-3, validation ? 0.11e-3 : nan,
                        null, null, "scale on joint 2"));
        // A geometric calibration of measured points (no distance anchor, one tool point): only its kind is read here.
        var geometric = new org.robopro.calibration.identification.CalibrationResult(null, null, null, null, List.of(), List.of(), 0, 0,
                List.of(), List.of(), List.of(), null, null, 0.03e-3, 0, false, 0, List.of(), List.of(), List.of(), null, false, false);
        return new Diagnosis("irb2000", geometric, 0.03e-3, 0.62e-3, validation ? 0.70e-3 : nan, effects, 0.085e-3, validation ? 0.105e-3 : nan,
                List.of(), List.of(), List.of(), List.of(), List.of(), null, null, null, 40, 0.05, 12,
                Directions.Source.RECORDED, List.of(), List.of());
    }

    @Test
    void rmsBars_oneBarPerTableRowInProportionNoiseFloorAtItsHeight() {
        Diagnosis d = diagnosis(true);
        Recorder c = new Recorder();
        DiagnosisReport.rmsBars(c, 720, 270, "RMS", d);
        List<String> cats = List.of("geometric", "+ " + Effect.backlash(0).label(), "+ " + Effect.scale(1).label(), "final fit");
        for (String cat : cats) assertTrue(c.texts.stream().anyMatch(t -> t.s().equals(cat)), "no category " + cat);
        // Training bars (dark orange) and validation bars (light) in table order, left to right.
        double[] train = {0.62, 0.21, 0.09, 0.085}, val = {0.70, 0.24, 0.11, 0.105};
        List<Recorder.Box> tb = c.rects.stream().filter(b -> b.color().equals("#f07a1a") && b.w() < 100).toList();
        List<Recorder.Box> vb = c.rects.stream().filter(b -> b.color().equals("#f5b77f") && b.w() < 100).toList();
        // One legend swatch each, then the bars.
        assertEquals(cats.size() + 1, tb.size());
        assertEquals(cats.size() + 1, vb.size());
        double bottom = tb.get(1).y() + tb.get(1).h();
        List<Recorder.Box> tBars = tb.stream().filter(b -> Math.abs(b.y() + b.h() - bottom) < 1e-6).toList();
        List<Recorder.Box> vBars = vb.stream().filter(b -> Math.abs(b.y() + b.h() - bottom) < 1e-6).toList();
        assertEquals(cats.size(), tBars.size());
        assertEquals(cats.size(), vBars.size());
        double perMm = tBars.get(0).h() / train[0];
        for (int i = 0; i < cats.size(); i++) {
            assertEquals(train[i] * perMm, tBars.get(i).h(), 0.5, "training bar " + cats.get(i));
            assertEquals(val[i] * perMm, vBars.get(i).h(), 0.5, "validation bar " + cats.get(i));
            assertTrue(vBars.get(i).x() > tBars.get(i).x(), "validation right of training");
            if (i > 0) assertTrue(tBars.get(i).x() > tBars.get(i - 1).x(), "bars in table order");
        }
        // The noise floor: dashed across the plot at √3·σ = 0.052 mm.
        double floorMm = Math.sqrt(3) * 0.03;
        double[] floor = c.dashed.stream().filter(l -> l[2] - l[0] > 300).findFirst().orElseThrow();
        assertEquals(bottom - floorMm * perMm, floor[1], 0.5);
        // Legend row above every bar.
        for (String k : List.of("training", "validation", "noise floor √3·σ")) {
            Recorder.Text t = c.texts.stream().filter(x -> x.s().equals(k)).findFirst().orElseThrow();
            for (Recorder.Box b : tBars) assertTrue(t.y() < b.y(), k + " legend over a bar");
        }
        assertTrue(c.texts.stream().anyMatch(t -> t.s().equals("0.085")), "final fit's value over its bar");
    }

    @Test
    void rmsBars_withoutValidation_noValidationSeries() {
        Recorder c = new Recorder();
        DiagnosisReport.rmsBars(c, 720, 270, "", diagnosis(false));
        assertFalse(c.texts.stream().anyMatch(t -> t.s().equals("validation")));
        assertTrue(c.rects.stream().noneMatch(b -> b.color().equals("#f5b77f")));
    }

    @Test
    void htmlReport_carriesTheBarChartAsSvg() throws Exception {
        String html = DiagnosisReport.html(diagnosis(true), new DiagnosisReport.Context("train.csv", "validate.csv", "now"));
        int at = html.indexOf("RMS error: geometric model, after each effect, final fit");
        assertTrue(at > 0, "chart title in the report");
        String svg = html.substring(html.lastIndexOf("<svg", at), html.indexOf("</svg>", at) + 6);
        assertTrue(svg.contains(">final fit</text>") && svg.contains(">noise floor √3·σ</text>") && svg.contains("stroke-dasharray"), svg);
        assertTrue(svg.contains(">0.620</text>") && svg.contains(">0.105</text>"), "bar values printed");
        assertFalse(svg.contains("NaN"));
        String keep = System.getenv("ROBOPRO_KEEP_REPORT");
        if (keep != null) {
            Files.createDirectories(Path.of(keep));
            Files.writeString(Path.of(keep, "rms-bars.svg"), svg);
            Files.writeString(Path.of(keep, "report.html"), html);
        }
    }
}
