package org.robopro.calibration.report;

import java.util.ArrayList;
import java.util.List;
import org.robopro.calibration.report.Svg.Line;
import org.robopro.calibration.report.Svg.Series;

/**
 * The one figure routine of robopro: scatter/line plots, bar charts and histograms laid out once
 * — title, legend row between the title and the plot (never over the data), axes with the
 * {@link Axis} ticks, grid, dashed reference lines (noise floor) — and drawn on a
 * {@link Canvas}: {@link Svg} turns the drawing into inline SVG for the HTML reports, the
 * workbench panels paint the same drawing with Java2D, so a report figure and a panel figure of
 * the same data look alike.
 */
public final class Figure {
    private Figure() { }

    /** Where drawing goes: coordinates in pixels from the top left; colours as "#rrggbb". */
    public interface Canvas {
        void line(double x1, double y1, double x2, double y2, String color, double width, boolean dashed);
        void rect(double x, double y, double w, double h, String color, double opacity);
        void circle(double cx, double cy, double r, String color);
        void polyline(double[] xs, double[] ys, int n, String color, double width);
        /** Text at baseline point (x, y); anchor -1 start, 0 middle, 1 end; rotated -90° when {@code vertical}. */
        void text(double x, double y, String s, int anchor, double size, boolean bold, boolean vertical);
        /** Width of {@code s} at {@code size} (for the legend and labels that must not overlap). */
        double textWidth(String s, double size);
    }

    /** A whole figure drawn on a canvas of the given size (a report's SVG, a panel, an image). */
    @FunctionalInterface
    public interface Drawing {
        void draw(Canvas c, double w, double h);
    }

    /** The plot area inside a w x h figure: left, top, right, bottom in pixels. */
    record Area(double l, double t, double r, double b) {
        double sx(Axis.Ticks t, double x) { return l + t.fraction(x) * (r - l); }
        double sy(Axis.Ticks tk, double y) { return b - tk.fraction(y) * (b - t); }
    }

    private static final double FONT = 11, TITLE = 13;

    /** Room for the title (when there is one) and the legend row above the plot, and for the y title left of the tick labels. */
    private static Area area(double w, double h, String title, String yLabel, Axis.Ticks yt, Canvas c) {
        double labelW = 0;
        for (String l : yt.labels()) labelW = Math.max(labelW, c.textWidth(l, FONT));
        double top = (title == null || title.isEmpty() ? 0 : 20) + 22, bottom = h - 40;
        YTitle yTitle = yTitle(yLabel, bottom - top, c);
        double titleW = yTitle.lines().size() < 2 ? 24 : 24 + yTitle.size() + 2;
        double left = Math.max(50, titleW + labelW + 6);
        return new Area(left, top, w - 15, bottom);
    }

    /** A category's name under its slot: its lines and their size. */
    record CategoryLabel(List<String> lines, double size) { }

    /** Room below a bar chart's axis for its category names: the first line's baseline, and the last's at the most. */
    static final double CATEGORY_FIRST = 15, CATEGORY_LAST = 35;

    /** How many lines of category names at {@code size} fit below the axis ({@link #CATEGORY_FIRST}..{@link #CATEGORY_LAST}). */
    static int categoryLines(double size) { return (int) Math.floor((CATEGORY_LAST - CATEGORY_FIRST) / (size + 2)) + 1; }

    /**
     * A category's name in {@code width}: one line, shrunk down to 9 where that fits; else broken at
     * spaces and after hyphens into the lines that fit below the axis ({@link #categoryLines}),
     * shrunk down to 8 (a leading "+" stays with its word); a name that still does not fit keeps its
     * first lines and ends in an ellipsis, so names never run into their neighbours'.
     */
    static CategoryLabel categoryLabel(String s, double width, Canvas c) {
        for (double size = FONT; size >= 9; size -= 0.5)
            if (c.textWidth(s, size) <= width) return new CategoryLabel(List.of(s), size);
        for (double size = FONT; size >= 8; size -= 0.5) {
            List<String> lines = wrap(s, width, size, c);
            double at = size;
            if (lines.size() <= categoryLines(size) && lines.stream().allMatch(l -> c.textWidth(l, at) <= width))
                return new CategoryLabel(lines, size);
        }
        int most = categoryLines(8);
        List<String> all = wrap(s, width, 8, c), lines = new ArrayList<>();
        for (int k = 0; k < Math.min(most, all.size()); k++) {
            String l = all.get(k);
            if (k == most - 1 && all.size() > most || c.textWidth(l, 8) > width) {
                while (l.length() > 1 && c.textWidth(l + "…", 8) > width) l = l.substring(0, l.length() - 1);
                l += "…";
            }
            lines.add(l);
        }
        return new CategoryLabel(lines, 8);
    }

    /**
     * {@code s} put greedily on lines no wider than {@code width} at {@code size}, broken at spaces
     * (dropped) and after hyphens (kept); a piece wider than that stands alone on its line.
     */
    private static List<String> wrap(String s, double width, double size, Canvas c) {
        List<String> pieces = new ArrayList<>();
        List<Boolean> spaced = new ArrayList<>(); // whether a space stood before the piece
        StringBuilder b = new StringBuilder();
        boolean space = false;
        for (int i = 0; i < s.length(); i++) {
            char ch = s.charAt(i);
            if (ch == ' ') {
                if (b.length() > 0) { pieces.add(b.toString()); spaced.add(space); b.setLength(0); }
                space = true;
                continue;
            }
            b.append(ch);
            if (ch == '-' && i + 1 < s.length() && s.charAt(i + 1) != ' ' && b.length() > 1) {
                pieces.add(b.toString()); spaced.add(space); b.setLength(0); space = false;
            }
        }
        if (b.length() > 0) { pieces.add(b.toString()); spaced.add(space); }
        if (pieces.size() > 1 && pieces.get(0).equals("+")) { // the "+" of an added effect stays with its name
            pieces.set(1, "+ " + pieces.get(1));
            pieces.remove(0);
            spaced.remove(0);
        }
        List<String> out = new ArrayList<>();
        String line = "";
        for (int k = 0; k < pieces.size(); k++) {
            String next = line.isEmpty() ? pieces.get(k) : line + (spaced.get(k) ? " " : "") + pieces.get(k);
            if (!line.isEmpty() && c.textWidth(next, size) > width) { out.add(line); line = pieces.get(k); }
            else line = next;
        }
        if (!line.isEmpty()) out.add(line);
        return out;
    }

    /** The rotated y title: one line, or two split at a space, at a size (at least 8) that fits the plot's height. */
    record YTitle(List<String> lines, double size) { }

    static YTitle yTitle(String label, double height, Canvas c) {
        if (label == null || label.isEmpty()) return new YTitle(List.of(), FONT);
        if (c.textWidth(label, FONT) <= height) return new YTitle(List.of(label), FONT);
        int best = -1;
        double bestW = Double.POSITIVE_INFINITY;
        for (int i = label.indexOf(' '); i > 0; i = label.indexOf(' ', i + 1)) {
            double wi = Math.max(c.textWidth(label.substring(0, i), FONT), c.textWidth(label.substring(i + 1), FONT));
            if (wi < bestW) { bestW = wi; best = i; }
        }
        List<String> lines = best < 0 ? List.of(label) : List.of(label.substring(0, best), label.substring(best + 1));
        double size = FONT;
        while (size > 8 && lines.stream().mapToDouble(l -> c.textWidth(l, FONT)).max().orElse(0) * size / FONT > height) size -= 0.5;
        return new YTitle(lines, size);
    }

    /** Points (or polylines) per series against x, with reference lines; {@code logY} plots log10 of positive values. */
    public static void plot(Canvas c, double w, double h, String title, String xLabel, String yLabel, List<Series> series,
                            boolean logY, List<Line> lines) {
        double xmin = Double.POSITIVE_INFINITY, xmax = Double.NEGATIVE_INFINITY, ymin = Double.POSITIVE_INFINITY, ymax = Double.NEGATIVE_INFINITY;
        for (Series s : series)
            for (int i = 0; i < s.x().length; i++) {
                double y = s.y()[i];
                if (!Double.isFinite(y) || (logY && !(y > 0))) continue;
                xmin = Math.min(xmin, s.x()[i]); xmax = Math.max(xmax, s.x()[i]);
                ymin = Math.min(ymin, y); ymax = Math.max(ymax, y);
            }
        for (Line l : lines) if (Double.isFinite(l.y()) && (!logY || l.y() > 0)) { ymin = Math.min(ymin, l.y()); ymax = Math.max(ymax, l.y()); }
        if (!Double.isFinite(xmin)) { xmin = 0; xmax = 1; }
        if (!Double.isFinite(ymin)) { ymin = logY ? 0.1 : 0; ymax = 1; }
        Axis.Ticks xt = Axis.linear(xmin, xmax, Math.max(2, (int) (w / 90)));
        Axis.Ticks yt = logY ? Axis.log(ymin, ymax) : Axis.linear(Math.min(0, ymin), ymax, Math.max(2, (int) (h / 55)));
        // Points (not lines) on the first or last tick are kept off the frame: the axis reaches a little past that tick.
        if (series.stream().anyMatch(s -> !s.line())) {
            xt = margin(xt, xmin, xmax, true);
            if (!logY) yt = margin(yt, ymin, ymax, yt.lo() < 0);
        }
        Area a = area(w, h, title, yLabel, yt, c);
        frame(c, w, h, a, title, xLabel, yLabel, xt, yt, null);
        for (Series s : series) {
            double[] xs = new double[s.x().length], ys = new double[s.x().length];
            int n = 0;
            for (int i = 0; i < s.x().length; i++) {
                double y = s.y()[i];
                if (!Double.isFinite(y) || (logY && !(y > 0))) continue;
                xs[n] = a.sx(xt, s.x()[i]);
                ys[n] = a.sy(yt, y);
                if (!s.line()) c.circle(xs[n], ys[n], 2.2, s.color());
                n++;
            }
            if (s.line() && n > 0) c.polyline(xs, ys, n, s.color(), 1.6);
        }
        List<Key> keys = new ArrayList<>();
        for (Series s : series) keys.add(new Key(s.name(), s.color(), s.line(), false));
        referenceLines(c, a, yt, logY, lines, keys);
        legend(c, a, title, keys);
    }

    /** {@code t} reaching 3 % further at an end the data touch (the low end only when {@code low}); the same ticks. */
    private static Axis.Ticks margin(Axis.Ticks t, double min, double max, boolean low) {
        double span = t.hi() - t.lo(), lo = t.lo(), hi = t.hi();
        if (!(span > 0)) return t;
        if (low && min - lo < 0.01 * span) lo -= 0.03 * span;
        if (hi - max < 0.01 * span) hi += 0.03 * span;
        return new Axis.Ticks(lo, hi, t.values(), t.labels(), t.log());
    }

    /**
     * Bars per category (one bar of each series side by side, its value above it) with
     * reference lines, on a linear axis from zero.
     */
    public static void bars(Canvas c, double w, double h, String title, String yLabel, List<String> categories,
                            List<Series> series, List<Line> lines, String valueFormat) {
        double max = 0;
        for (Series s : series) for (double v : s.y()) if (Double.isFinite(v)) max = Math.max(max, v);
        for (Line l : lines) if (Double.isFinite(l.y())) max = Math.max(max, l.y());
        Axis.Ticks yt = Axis.linear(0, max > 0 ? max * 1.08 : 1, Math.max(2, (int) (h / 45)));
        Area a = area(w, h, title, yLabel, yt, c);
        frame(c, w, h, a, title, "", yLabel, null, yt, categories);
        int n = Math.max(1, categories.size());
        double slot = (a.r() - a.l()) / n;
        double bw = Math.max(3, Math.min(40, slot * 0.7 / Math.max(1, series.size())));
        for (int i = 0; i < categories.size(); i++) {
            double cx = a.l() + slot * (i + 0.5);
            for (int k = 0; k < series.size(); k++) {
                Series s = series.get(k);
                if (i >= s.y().length || !Double.isFinite(s.y()[i])) continue;
                double x = cx - bw * series.size() / 2 + k * bw, y = a.sy(yt, s.y()[i]);
                c.rect(x + 1, y, bw - 2, a.b() - y, s.color(), 1);
                c.text(x + bw / 2, y - 3, String.format(java.util.Locale.ROOT, valueFormat, s.y()[i]), 0, 10, false, false);
            }
        }
        List<Key> keys = new ArrayList<>();
        for (Series s : series) keys.add(new Key(s.name(), s.color(), false, false));
        referenceLines(c, a, yt, false, lines, keys);
        legend(c, a, title, keys);
    }

    /** Histograms of several samples over shared round bins (the axis's ticks fall on bin edges). */
    public static void histogram(Canvas c, double w, double h, String title, String xLabel, List<Series> samples, int bins) {
        double max = 0;
        for (Series s : samples) for (double v : s.y()) if (Double.isFinite(v)) max = Math.max(max, v);
        if (max == 0) max = 1;
        Axis.Ticks xt = Axis.linear(0, max, Math.max(2, (int) (w / 90)));
        double bw = Axis.step(xt.hi(), bins);
        int nb = (int) Math.ceil(xt.hi() / bw - 1e-9);
        double[][] counts = new double[samples.size()][nb];
        double top = 0;
        for (int k = 0; k < samples.size(); k++) {
            double[] y = samples.get(k).y();
            for (double v : y) {
                if (!Double.isFinite(v)) continue;
                counts[k][Math.min(nb - 1, (int) (v / bw))] += 1.0 / Math.max(1, y.length);
            }
            for (double n : counts[k]) top = Math.max(top, n);
        }
        Axis.Ticks yt = Axis.linear(0, top == 0 ? 1 : top, Math.max(2, (int) (h / 55)));
        Area a = area(w, h, title, "fraction of poses", yt, c);
        frame(c, w, h, a, title, xLabel, "fraction of poses", xt, yt, null);
        double px = (a.sx(xt, bw) - a.sx(xt, 0)) / Math.max(1, samples.size());
        for (int k = 0; k < samples.size(); k++)
            for (int b = 0; b < nb; b++) {
                double x0 = a.sx(xt, b * bw) + k * px, y0 = a.sy(yt, counts[k][b]);
                c.rect(x0, y0, px * 0.95, a.b() - y0, samples.get(k).color(), 0.8);
            }
        List<Key> keys = new ArrayList<>();
        for (Series s : samples) keys.add(new Key(s.name(), s.color(), false, false));
        legend(c, a, title, keys);
    }

    /** A legend entry: a filled square (points, bars), a solid line (a line series) or a dashed one (a reference line). */
    private record Key(String name, String color, boolean line, boolean dashed) { }

    private static void referenceLines(Canvas c, Area a, Axis.Ticks yt, boolean logY, List<Line> lines, List<Key> keys) {
        for (Line l : lines) {
            if (!Double.isFinite(l.y()) || (logY && !(l.y() > 0))) continue;
            double py = a.sy(yt, l.y());
            c.line(a.l(), py, a.r(), py, l.color(), 1.4, true);
            keys.add(new Key(l.name(), l.color(), true, true));
        }
    }

    /**
     * Title, axes, grid lines and tick labels. Y tick labels end 6 px left of the axis and the
     * rotated y title sits at x = 12, left of the widest label. With {@code categories} the x axis
     * carries category names under the slots instead of ticks.
     */
    private static void frame(Canvas c, double w, double h, Area a, String title, String xLabel, String yLabel,
                              Axis.Ticks xt, Axis.Ticks yt, List<String> categories) {
        c.rect(0, 0, w, h, "#ffffff", 1);
        if (title != null && !title.isEmpty()) c.text(w / 2, 16, title, 0, TITLE, true, false);
        for (int i = 0; i < yt.values().length; i++) {
            double py = a.sy(yt, yt.values()[i]);
            c.line(a.l(), py, a.r(), py, "#dddddd", 1, false);
            c.text(a.l() - 6, py + 4, yt.labels()[i], 1, FONT, false, false);
        }
        if (xt != null)
            for (int i = 0; i < xt.values().length; i++) {
                double px = a.sx(xt, xt.values()[i]);
                c.line(px, a.b(), px, a.b() + 4, "#333333", 1, false);
                c.text(px, a.b() + 16, xt.labels()[i], 0, FONT, false, false);
            }
        if (categories != null) {
            double slot = (a.r() - a.l()) / Math.max(1, categories.size());
            for (int i = 0; i < categories.size(); i++) {
                CategoryLabel l = categoryLabel(categories.get(i), slot - 4, c);
                for (int k = 0; k < l.lines().size(); k++)
                    c.text(a.l() + slot * (i + 0.5), a.b() + CATEGORY_FIRST + k * (l.size() + 2), l.lines().get(k), 0, l.size(), false, false);
            }
        }
        c.line(a.l(), a.b(), a.r(), a.b(), "#333333", 1, false);
        c.line(a.l(), a.t(), a.l(), a.b(), "#333333", 1, false);
        if (xLabel != null && !xLabel.isEmpty()) c.text((a.l() + a.r()) / 2, h - 6, xLabel, 0, FONT, false, false);
        YTitle yt2 = yTitle(yLabel, a.b() - a.t(), c);
        for (int i = 0; i < yt2.lines().size(); i++)
            c.text(12 + i * (yt2.size() + 2), (a.t() + a.b()) / 2, yt2.lines().get(i), 0, yt2.size(), false, true);
    }

    /** The legend as one row between the title and the plot area. */
    private static void legend(Canvas c, Area a, String title, List<Key> keys) {
        double x = a.l();
        double y = a.t() - 10;
        for (Key k : keys) {
            if (k.line()) c.line(x, y - 3, x + 14, y - 3, k.color(), k.dashed() ? 1.4 : 1.8, k.dashed());
            else c.rect(x + 2, y - 8, 10, 10, k.color(), 1);
            c.text(x + 18, y + 1, k.name(), -1, FONT, false, false);
            x += 30 + c.textWidth(k.name(), FONT);
        }
    }
}
