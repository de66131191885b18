package org.robopro.calibration.report;

import java.util.List;
import java.util.Locale;

/**
 * Inline-SVG figures for self-contained HTML reports (no scripts, no external files): the
 * {@link Figure} routine drawn on an SVG canvas.
 */
public final class Svg {
    private Svg() { }

    /** A named series of values and its colour; {@code line}: joined by a polyline, else points. */
    public record Series(String name, double[] x, double[] y, String color, boolean line) { }

    /** A horizontal reference line across a plot (a noise floor, a tolerance), named in the legend. */
    public record Line(String name, double y, String color) { }

    /** Size of a report figure. */
    static final int W = 720, H = 270;

    /** Points (or a polyline) per series against x; {@code logY} plots log10 of positive values. */
    public static String plot(String title, String xLabel, String yLabel, List<Series> series, boolean logY) {
        return plot(title, xLabel, yLabel, series, logY, List.of());
    }

    /**
     * As {@link #plot(String, String, String, List, boolean)} with horizontal reference
     * {@code lines} (e.g. the noise floor on a per-pose error plot), dashed and named in the legend.
     */
    public static String plot(String title, String xLabel, String yLabel, List<Series> series, boolean logY, List<Line> lines) {
        SvgCanvas c = new SvgCanvas(W, H);
        Figure.plot(c, W, H, title, xLabel, yLabel, series, logY, lines);
        return c.toString();
    }

    /** Bars per category, one of each series side by side, with reference lines. */
    public static String bars(String title, String yLabel, List<String> categories, List<Series> series, List<Line> lines, String valueFormat) {
        SvgCanvas c = new SvgCanvas(W, H);
        Figure.bars(c, W, H, title, yLabel, categories, series, lines, valueFormat);
        return c.toString();
    }

    /** Any figure drawing (e.g. one a workbench panel paints as well) as a report-sized SVG. */
    public static String draw(Figure.Drawing d) {
        SvgCanvas c = new SvgCanvas(W, H);
        d.draw(c, W, H);
        return c.toString();
    }

    /** Histograms of several samples over shared bins. */
    public static String histogram(String title, String xLabel, List<Series> samples, int bins) {
        SvgCanvas c = new SvgCanvas(W, H);
        Figure.histogram(c, W, H, title, xLabel, samples, bins);
        return c.toString();
    }

    /** A {@link Figure.Canvas} that writes SVG elements. */
    static final class SvgCanvas implements Figure.Canvas {
        private final StringBuilder sb = new StringBuilder();

        SvgCanvas(int w, int h) {
            sb.append("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"").append(w).append("\" height=\"").append(h)
              .append("\" viewBox=\"0 0 ").append(w).append(' ').append(h).append("\" font-family=\"sans-serif\" font-size=\"11\">");
        }

        @Override public void line(double x1, double y1, double x2, double y2, String color, double width, boolean dashed) {
            sb.append("<line x1=\"").append(f(x1)).append("\" y1=\"").append(f(y1)).append("\" x2=\"").append(f(x2)).append("\" y2=\"")
              .append(f(y2)).append("\" stroke=\"").append(color).append('"');
            if (width != 1) sb.append(" stroke-width=\"").append(f(width)).append('"');
            if (dashed) sb.append(" stroke-dasharray=\"6,4\"");
            sb.append("/>");
        }

        @Override public void rect(double x, double y, double w, double h, String color, double opacity) {
            sb.append("<rect x=\"").append(f(x)).append("\" y=\"").append(f(y)).append("\" width=\"").append(f(w))
              .append("\" height=\"").append(f(Math.max(0, h))).append("\" fill=\"").append(color).append('"');
            if (opacity < 1) sb.append(" opacity=\"").append(f(opacity)).append('"');
            sb.append("/>");
        }

        @Override public void circle(double cx, double cy, double r, String color) {
            sb.append("<circle cx=\"").append(f(cx)).append("\" cy=\"").append(f(cy)).append("\" r=\"").append(f(r))
              .append("\" fill=\"").append(color).append("\"/>");
        }

        @Override public void polyline(double[] xs, double[] ys, int n, String color, double width) {
            sb.append("<polyline fill=\"none\" stroke=\"").append(color).append("\" stroke-width=\"").append(f(width)).append("\" points=\"");
            for (int i = 0; i < n; i++) sb.append(f(xs[i])).append(',').append(f(ys[i])).append(' ');
            sb.append("\"/>");
        }

        @Override public void text(double x, double y, String s, int anchor, double size, boolean bold, boolean vertical) {
            sb.append("<text ");
            if (vertical) sb.append("transform=\"translate(").append(f(x)).append(',').append(f(y)).append(") rotate(-90)\"");
            else sb.append("x=\"").append(f(x)).append("\" y=\"").append(f(y)).append('"');
            sb.append(anchor < 0 ? "" : anchor == 0 ? " text-anchor=\"middle\"" : " text-anchor=\"end\"");
            if (size != 11) sb.append(" font-size=\"").append(f(size)).append('"');
            if (bold) sb.append(" font-weight=\"bold\"");
            sb.append('>').append(Html.esc(s)).append("</text>");
        }

        /** Sans-serif text is about 0.56 em wide per character on average. */
        @Override public double textWidth(String s, double size) { return 0.56 * size * s.length(); }

        @Override public String toString() { return sb + "</svg>"; }
    }

    private static String f(double v) { return String.format(Locale.ROOT, "%.1f", v); }
}
