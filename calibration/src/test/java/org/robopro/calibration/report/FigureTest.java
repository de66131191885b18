package org.robopro.calibration.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The figure routine's layout, checked on what it draws: legends above the plot, data inside
 * it, reference lines where their value is, bars as tall as their values, no text over the
 * axis, the same drawing for the report SVG and any other canvas.
 */
class FigureTest {
    /** Records every call; text width as the SVG canvas estimates it. */
    static final class Recorder implements Figure.Canvas {
        record Text(double x, double y, String s, int anchor, double size, boolean vertical) { }
        record Seg(double x1, double y1, double x2, double y2, String color, boolean dashed) { }
        record Box(double x, double y, double w, double h, String color) { }
        final List<Text> texts = new ArrayList<>();
        final List<Seg> lines = new ArrayList<>();
        final List<Box> rects = new ArrayList<>();
        final List<double[]> points = new ArrayList<>();

        @Override public void line(double x1, double y1, double x2, double y2, String color, double width, boolean dashed) {
            lines.add(new Seg(x1, y1, x2, y2, color, dashed));
        }
        @Override public void rect(double x, double y, double w, double h, String color, double opacity) { rects.add(new Box(x, y, w, h, color)); }
        @Override public void circle(double cx, double cy, double r, String color) { points.add(new double[] {cx, cy}); }
        @Override public void polyline(double[] xs, double[] ys, int n, String color, double width) {
            for (int i = 0; i < n; i++) points.add(new double[] {xs[i], ys[i]});
        }
        @Override public void text(double x, double y, String s, int anchor, double size, boolean bold, boolean vertical) {
            texts.add(new Text(x, y, s, anchor, size, vertical));
        }
        @Override public double textWidth(String s, double size) { return 0.56 * size * s.length(); }

        /** The plot area: the y axis line (vertical, at the left) and the x axis line. */
        double[] area() {
            Seg yAxis = lines.stream().filter(l -> l.x1() == l.x2() && l.color().equals("#333333") && l.y2() - l.y1() > 20).findFirst().orElseThrow();
            return new double[] {yAxis.x1(), yAxis.y1(), yAxis.y2()};
        }
    }

    private static Svg.Series series(String name, int n, long seed, double scale) {
        Random r = new Random(seed);
        double[] x = new double[n], y = new double[n];
        for (int i = 0; i < n; i++) { x[i] = i + 1; y[i] = scale * Math.exp(r.nextGaussian()); }
        return new Svg.Series(name, x, y, "#f07a1a", false);
    }

    @Test
    void plot_legendAboveThePlotDataInsideNoiseFloorAtItsValue() {
        Recorder c = new Recorder();
        Svg.Series s = series("calibrated model", 60, 3, 0.05);
        Figure.plot(c, 720, 270, "After", "pose", "error (mm)", List.of(s), true, List.of(new Svg.Line("noise floor", 0.02, "#2e7d32")));
        double[] a = c.area();
        double left = a[0], top = a[1], bottom = a[2];
        for (double[] p : c.points) assertTrue(p[0] >= left && p[1] >= top - 1e-9 && p[1] <= bottom + 1e-9, "point off the plot");
        Recorder.Text legend = c.texts.stream().filter(t -> t.s().equals("calibrated model")).findFirst().orElseThrow();
        assertTrue(legend.y() < top, "legend over the data");
        // The noise floor: a dashed line across the plot at 0.02 on the log axis.
        Recorder.Seg floor = c.lines.stream().filter(Recorder.Seg::dashed).filter(l -> l.x2() - l.x1() > 100).findFirst().orElseThrow();
        Axis.Ticks yt = Axis.log(Math.min(0.02, min(s.y())), max(s.y()));
        assertEquals(bottom - yt.fraction(0.02) * (bottom - top), floor.y1(), 0.5);
        // Y tick labels end left of the axis, clear of the rotated y title at x = 12.
        for (Recorder.Text t : c.texts)
            if (!t.vertical() && t.anchor() == 1) {
                assertTrue(t.x() <= left - 5, "tick label touches the axis: " + t.s());
                assertTrue(t.x() - c.textWidth(t.s(), t.size()) > 12 + 6, "tick label runs into the y title: " + t.s());
            }
    }

    @Test
    void bars_heightsProportionalToValuesLabelsFitTheirSlots() {
        Recorder c = new Recorder();
        List<String> cats = List.of("geometric", "+ backlash j2", "+ thermal growth of link 3 and the long label");
        double[] train = {0.30, 0.12, 0.05}, val = {0.35, 0.13, 0.06};
        Figure.bars(c, 600, 200, "", "RMS (mm)", cats, List.of(new Svg.Series("training", null, train, "#f07a1a", false),
                new Svg.Series("validation", null, val, "#f5b77f", false)), List.of(new Svg.Line("noise floor", 0.04, "#2e9e44")), "%.3f");
        double[] a = c.area();
        double bottom = a[2];
        List<Recorder.Box> bars = c.rects.stream().filter(b -> b.color().equals("#f07a1a") && b.w() < 60 && b.y() > a[1] - 1).toList();
        assertEquals(3, bars.size());
        for (int i = 0; i < 3; i++)
            assertEquals(train[i] / train[0], bars.get(i).h() / bars.get(0).h(), 0.01, "bar " + i + " not proportional to its value");
        for (Recorder.Box b : bars) assertEquals(bottom, b.y() + b.h(), 1e-6, "bar not standing on the axis");
        assertTrue(c.texts.stream().anyMatch(t -> t.s().equals("0.120")), "value labels with the format given");
        double slot = (a[0] >= 0 ? (600 - 15 - a[0]) / 3 : 0);
        for (int i = 0; i < cats.size(); i++) {
            // the name's lines under its slot: each within the slot, none below the picture, the words all there
            double cx = a[0] + slot * (i + 0.5);
            List<Recorder.Text> lines = c.texts.stream().filter(x -> Math.abs(x.x() - cx) < 1e-6 && x.y() > bottom).toList();
            assertTrue(!lines.isEmpty(), "no name under slot " + i);
            for (Recorder.Text t : lines) {
                assertTrue(c.textWidth(t.s(), t.size()) <= slot - 4 + 1e-9, "category line wider than its slot: " + t.s());
                assertTrue(t.y() <= 200 - 4, "category line below the picture: " + t.s());
            }
            String joined = String.join(" ", lines.stream().map(Recorder.Text::s).toList()).replace("- ", "-");
            assertEquals(cats.get(i), joined, "the name, its lines joined");
        }
        assertTrue(c.texts.stream().noneMatch(x -> x.s().equals(cats.get(2))), "the long name is broken into lines");
        assertTrue(c.lines.stream().anyMatch(Recorder.Seg::dashed), "noise floor drawn");
    }

    @Test
    void svg_isTheSameDrawing() {
        Svg.Series s = series("nominal", 20, 5, 1);
        String svg = Svg.plot("Before", "pose", "error (mm)", List.of(s), false, List.of());
        Recorder c = new Recorder();
        Figure.plot(c, 720, 270, "Before", "pose", "error (mm)", List.of(s), false, List.of());
        assertEquals(c.points.size(), svg.split("<circle").length - 1);
        for (Recorder.Text t : c.texts) assertTrue(svg.contains(">" + Html.esc(t.s()) + "</text>"), "SVG lacks " + t.s());
        assertFalse(svg.contains("NaN"));
    }

    @Test
    void longYTitle_twoLinesWithinThePlotHeight_tickLabelsClearOfIt() {
        Recorder c = new Recorder();
        String yLabel = "residual along the structure's displacement (mm)";
        double[] x = {-1, -1, 1, 1}, y = {0.1, 0.55, 0.05, 0.76};
        Figure.plot(c, 720, 270, "Evidence", "approach direction", yLabel, List.of(new Svg.Series("residual", x, y, "#1f77b4", false)),
                false, List.of());
        double[] a = c.area();
        double left = a[0], top = a[1], bottom = a[2];
        List<Recorder.Text> title = c.texts.stream().filter(Recorder.Text::vertical).toList();
        assertEquals(2, title.size(), "split into two lines");
        assertEquals(yLabel, title.get(0).s() + " " + title.get(1).s());
        double rightmost = 0;
        for (Recorder.Text t : title) {
            assertTrue(c.textWidth(t.s(), t.size()) <= bottom - top + 1e-9, "y title line longer than the plot: " + t.s());
            assertTrue(t.x() - t.size() >= 0, "y title line off the figure");
            rightmost = Math.max(rightmost, t.x());
        }
        for (Recorder.Text t : c.texts)
            if (!t.vertical() && t.anchor() == 1) assertTrue(t.x() - c.textWidth(t.s(), t.size()) > rightmost + 2, "tick label over the y title: " + t.s());
        // Points at the ends of the data range stay off the frame.
        for (double[] p : c.points) assertTrue(p[0] > left + 2 && p[0] < 720 - 15 - 2, "point on the frame at x " + p[0]);
    }

    @Test
    void legend_lineSeriesSolidReferenceLinesDashed() {
        Recorder c = new Recorder();
        double[] x = {1, 2, 3}, y = {3, 2, 1};
        Figure.plot(c, 720, 270, "", "x", "y", List.of(new Svg.Series("fit", x, y, "#d62728", true)), false,
                List.of(new Svg.Line("noise floor", 0.5, "#2e7d32")));
        double top = c.area()[1];
        List<Recorder.Seg> keys = c.lines.stream().filter(l -> l.y1() < top && l.y1() == l.y2() && l.x2() - l.x1() < 20).toList();
        assertEquals(2, keys.size(), "two line keys in the legend row");
        assertTrue(keys.stream().anyMatch(k -> k.color().equals("#d62728") && !k.dashed()), "a line series is keyed by a solid line");
        assertTrue(keys.stream().anyMatch(k -> k.color().equals("#2e7d32") && k.dashed()), "a reference line by a dashed one");
    }

    private static double min(double[] v) { double m = Double.POSITIVE_INFINITY; for (double x : v) m = Math.min(m, x); return m; }
    private static double max(double[] v) { double m = 0; for (double x : v) m = Math.max(m, x); return m; }
}
