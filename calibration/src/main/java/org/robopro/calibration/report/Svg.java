package org.robopro.calibration.report;

import java.util.List;
import java.util.Locale;

/** Minimal inline-SVG charts for self-contained HTML reports (no scripts, no external files). */
public final class Svg {
    private Svg() { }

    /** A named series of values and its colour. */
    public record Series(String name, double[] x, double[] y, String color, boolean line) { }

    /** A horizontal reference line across a plot (a noise floor, a tolerance), named in the legend. */
    public record Line(String name, double y, String color) { }

    /** Plot area: the legend row sits between the title and the plot, never over the data. */
    static final int W = 720, H = 270, L = 64, R = 15, T = 44, B = 40;

    /** Points (or a polyline) per series against x; {@code logY} plots log10 of positive values. */
    public static String plot(String title, String xLabel, String yLabel, List<Series> series, boolean logY) {
        return plot(title, xLabel, yLabel, series, logY, List.of());
    }

    /**
     * As {@link #plot(String, String, String, List, boolean)} with horizontal reference
     * {@code lines} (e.g. the noise floor on a per-pose error plot), dashed and named in the legend.
     */
    public static String plot(String title, String xLabel, String yLabel, List<Series> series, boolean logY, List<Line> lines) {
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
        Axis.Ticks xt = Axis.linear(xmin, xmax, 8);
        Axis.Ticks yt = logY ? Axis.log(ymin, ymax) : Axis.linear(Math.min(0, ymin), ymax, 5);
        StringBuilder sb = frame(title, xLabel, yLabel, xt, yt);
        for (Series s : series) {
            StringBuilder pts = new StringBuilder();
            for (int i = 0; i < s.x().length; i++) {
                double y = s.y()[i];
                if (!Double.isFinite(y) || (logY && !(y > 0))) continue;
                double px = sx(xt, s.x()[i]), py = sy(yt, y);
                if (s.line()) pts.append(f(px)).append(',').append(f(py)).append(' ');
                else sb.append("<circle cx=\"").append(f(px)).append("\" cy=\"").append(f(py)).append("\" r=\"2.2\" fill=\"")
                        .append(s.color()).append("\"/>");
            }
            if (s.line()) sb.append("<polyline fill=\"none\" stroke=\"").append(s.color()).append("\" stroke-width=\"1.6\" points=\"")
                    .append(pts).append("\"/>");
        }
        List<String[]> keys = new java.util.ArrayList<>();
        for (Series s : series) keys.add(new String[] {s.name(), s.color(), "box"});
        for (Line l : lines) {
            if (!Double.isFinite(l.y()) || (logY && !(l.y() > 0))) continue;
            double py = sy(yt, l.y());
            sb.append("<line x1=\"").append(L).append("\" y1=\"").append(f(py)).append("\" x2=\"").append(W - R).append("\" y2=\"")
              .append(f(py)).append("\" stroke=\"").append(l.color()).append("\" stroke-width=\"1.4\" stroke-dasharray=\"6,4\"/>");
            keys.add(new String[] {l.name(), l.color(), "line"});
        }
        legend(sb, keys);
        return sb.append("</svg>").toString();
    }

    /** Histograms of several samples over shared bins. */
    public static String histogram(String title, String xLabel, List<Series> samples, int bins) {
        double max = 0;
        for (Series s : samples) for (double v : s.y()) if (Double.isFinite(v)) max = Math.max(max, v);
        if (max == 0) max = 1;
        // Round bins: the axis's ticks fall on bin edges.
        Axis.Ticks xt = Axis.linear(0, max, 8);
        double w = Axis.step(xt.hi(), bins);
        int nb = (int) Math.ceil(xt.hi() / w - 1e-9);
        double[][] counts = new double[samples.size()][nb];
        double top = 0;
        for (int k = 0; k < samples.size(); k++) {
            double[] y = samples.get(k).y();
            for (double v : y) {
                if (!Double.isFinite(v)) continue;
                int b = Math.min(nb - 1, (int) (v / w));
                counts[k][b] += 1.0 / Math.max(1, y.length);
            }
            for (double c : counts[k]) top = Math.max(top, c);
        }
        Axis.Ticks yt = Axis.linear(0, top == 0 ? 1 : top, 5);
        StringBuilder sb = frame(title, xLabel, "fraction of poses", xt, yt);
        double bw = (sx(xt, w) - sx(xt, 0)) / samples.size();
        for (int k = 0; k < samples.size(); k++)
            for (int b = 0; b < nb; b++) {
                double x0 = sx(xt, b * w) + k * bw, y0 = sy(yt, counts[k][b]);
                sb.append("<rect x=\"").append(f(x0)).append("\" y=\"").append(f(y0)).append("\" width=\"").append(f(bw * 0.95))
                  .append("\" height=\"").append(f(H - B - y0)).append("\" fill=\"").append(samples.get(k).color()).append("\" opacity=\"0.8\"/>");
            }
        List<String[]> keys = new java.util.ArrayList<>();
        for (Series s : samples) keys.add(new String[] {s.name(), s.color(), "box"});
        legend(sb, keys);
        return sb.append("</svg>").toString();
    }

    /**
     * Title, axes, grid lines and tick labels at the ticks {@link Axis} chose. Y tick labels end
     * 6 px left of the axis and the rotated y title sits at x = 12, so a label up to 44 px wide
     * (seven characters) never runs into it.
     */
    private static StringBuilder frame(String title, String xLabel, String yLabel, Axis.Ticks xt, Axis.Ticks yt) {
        StringBuilder sb = new StringBuilder();
        sb.append("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"").append(W).append("\" height=\"").append(H)
          .append("\" viewBox=\"0 0 ").append(W).append(' ').append(H).append("\" font-family=\"sans-serif\" font-size=\"11\">");
        sb.append("<rect width=\"100%\" height=\"100%\" fill=\"white\"/>");
        sb.append("<text x=\"").append(W / 2).append("\" y=\"16\" text-anchor=\"middle\" font-size=\"13\" font-weight=\"bold\">")
          .append(Html.esc(title)).append("</text>");
        for (int i = 0; i < yt.values().length; i++) {
            double py = sy(yt, yt.values()[i]);
            sb.append("<line x1=\"").append(L).append("\" y1=\"").append(f(py)).append("\" x2=\"").append(W - R).append("\" y2=\"")
              .append(f(py)).append("\" stroke=\"#ddd\"/>");
            sb.append("<text x=\"").append(L - 6).append("\" y=\"").append(f(py + 4)).append("\" text-anchor=\"end\">")
              .append(Html.esc(yt.labels()[i])).append("</text>");
        }
        for (int i = 0; i < xt.values().length; i++) {
            double px = sx(xt, xt.values()[i]);
            sb.append("<line x1=\"").append(f(px)).append("\" y1=\"").append(H - B).append("\" x2=\"").append(f(px)).append("\" y2=\"")
              .append(H - B + 4).append("\" stroke=\"#333\"/>");
            sb.append("<text x=\"").append(f(px)).append("\" y=\"").append(H - B + 16).append("\" text-anchor=\"middle\">")
              .append(Html.esc(xt.labels()[i])).append("</text>");
        }
        sb.append("<line x1=\"").append(L).append("\" y1=\"").append(H - B).append("\" x2=\"").append(W - R).append("\" y2=\"")
          .append(H - B).append("\" stroke=\"#333\"/>");
        sb.append("<line x1=\"").append(L).append("\" y1=\"").append(T).append("\" x2=\"").append(L).append("\" y2=\"")
          .append(H - B).append("\" stroke=\"#333\"/>");
        sb.append("<text x=\"").append((L + W - R) / 2).append("\" y=\"").append(H - 6).append("\" text-anchor=\"middle\">")
          .append(Html.esc(xLabel)).append("</text>");
        sb.append("<text transform=\"translate(12,").append((T + H - B) / 2).append(") rotate(-90)\" text-anchor=\"middle\">")
          .append(Html.esc(yLabel)).append("</text>");
        return sb;
    }

    /** The legend as one row between the title and the plot area: {name, colour, "box" or "line"} per entry. */
    private static void legend(StringBuilder sb, List<String[]> keys) {
        double x = L;
        int y = 34;
        for (String[] k : keys) {
            if ("line".equals(k[2]))
                sb.append("<line x1=\"").append(f(x)).append("\" y1=\"").append(y - 3).append("\" x2=\"").append(f(x + 14)).append("\" y2=\"")
                  .append(y - 3).append("\" stroke=\"").append(k[1]).append("\" stroke-width=\"1.4\" stroke-dasharray=\"4,3\"/>");
            else sb.append("<rect x=\"").append(f(x + 2)).append("\" y=\"").append(y - 8).append("\" width=\"10\" height=\"10\" fill=\"")
                    .append(k[1]).append("\"/>");
            sb.append("<text x=\"").append(f(x + 18)).append("\" y=\"").append(y + 1).append("\">").append(Html.esc(k[0])).append("</text>");
            x += 30 + 6.2 * k[0].length();
        }
    }

    private static double sx(Axis.Ticks t, double x) { return L + t.fraction(x) * (W - L - R); }
    private static double sy(Axis.Ticks t, double y) { return H - B - t.fraction(y) * (H - B - T); }
    private static String f(double v) { return String.format(Locale.ROOT, "%.1f", v); }
}
