package org.robopro.calibration.report;

import java.util.List;
import java.util.Locale;

/** Minimal inline-SVG charts for self-contained HTML reports (no scripts, no external files). */
public final class Svg {
    private Svg() { }

    /** A named series of values and its colour. */
    public record Series(String name, double[] x, double[] y, String color, boolean line) { }

    static final int W = 720, H = 260, L = 60, R = 15, T = 28, B = 38;

    /** Points (or a polyline) per series against x; {@code logY} plots log10 of positive values. */
    public static String plot(String title, String xLabel, String yLabel, List<Series> series, boolean logY) {
        double xmin = Double.POSITIVE_INFINITY, xmax = Double.NEGATIVE_INFINITY, ymin = Double.POSITIVE_INFINITY, ymax = Double.NEGATIVE_INFINITY;
        for (Series s : series)
            for (int i = 0; i < s.x().length; i++) {
                double y = tr(s.y()[i], logY);
                if (!Double.isFinite(y)) continue;
                xmin = Math.min(xmin, s.x()[i]); xmax = Math.max(xmax, s.x()[i]);
                ymin = Math.min(ymin, y); ymax = Math.max(ymax, y);
            }
        if (!Double.isFinite(xmin)) { xmin = 0; xmax = 1; ymin = 0; ymax = 1; }
        if (!logY) ymin = Math.min(0, ymin);
        if (xmax == xmin) xmax = xmin + 1;
        if (ymax == ymin) ymax = ymin + 1;
        ymax += 0.05 * (ymax - ymin);
        StringBuilder sb = frame(title, xLabel, yLabel, xmin, xmax, ymin, ymax, logY);
        for (Series s : series) {
            StringBuilder pts = new StringBuilder();
            for (int i = 0; i < s.x().length; i++) {
                double y = tr(s.y()[i], logY);
                if (!Double.isFinite(y)) continue;
                double px = sx(s.x()[i], xmin, xmax), py = sy(y, ymin, ymax);
                if (s.line()) pts.append(f(px)).append(',').append(f(py)).append(' ');
                else sb.append("<circle cx=\"").append(f(px)).append("\" cy=\"").append(f(py)).append("\" r=\"2.2\" fill=\"")
                        .append(s.color()).append("\"/>");
            }
            if (s.line()) sb.append("<polyline fill=\"none\" stroke=\"").append(s.color()).append("\" stroke-width=\"1.6\" points=\"")
                    .append(pts).append("\"/>");
        }
        legend(sb, series);
        return sb.append("</svg>").toString();
    }

    /** Histograms of several samples over shared bins. */
    public static String histogram(String title, String xLabel, List<Series> samples, int bins) {
        double max = 0;
        for (Series s : samples) for (double v : s.y()) if (Double.isFinite(v)) max = Math.max(max, v);
        if (max == 0) max = 1;
        double w = max / bins;
        double[][] counts = new double[samples.size()][bins];
        double top = 0;
        for (int k = 0; k < samples.size(); k++) {
            double[] y = samples.get(k).y();
            for (double v : y) {
                if (!Double.isFinite(v)) continue;
                int b = Math.min(bins - 1, (int) (v / w));
                counts[k][b] += 1.0 / Math.max(1, y.length);
            }
            for (double c : counts[k]) top = Math.max(top, c);
        }
        top = top == 0 ? 1 : top * 1.1;
        StringBuilder sb = frame(title, xLabel, "fraction of poses", 0, max, 0, top, false);
        double bw = (W - L - R) / (double) bins / samples.size();
        for (int k = 0; k < samples.size(); k++)
            for (int b = 0; b < bins; b++) {
                double x0 = sx(b * w, 0, max) + k * bw, y0 = sy(counts[k][b], 0, top);
                sb.append("<rect x=\"").append(f(x0)).append("\" y=\"").append(f(y0)).append("\" width=\"").append(f(bw * 0.95))
                  .append("\" height=\"").append(f(H - B - y0)).append("\" fill=\"").append(samples.get(k).color()).append("\" opacity=\"0.8\"/>");
            }
        legend(sb, samples);
        return sb.append("</svg>").toString();
    }

    private static StringBuilder frame(String title, String xLabel, String yLabel, double xmin, double xmax, double ymin,
                                       double ymax, boolean logY) {
        StringBuilder sb = new StringBuilder();
        sb.append("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"").append(W).append("\" height=\"").append(H)
          .append("\" viewBox=\"0 0 ").append(W).append(' ').append(H).append("\" font-family=\"sans-serif\" font-size=\"11\">");
        sb.append("<rect width=\"100%\" height=\"100%\" fill=\"white\"/>");
        sb.append("<text x=\"").append(W / 2).append("\" y=\"16\" text-anchor=\"middle\" font-size=\"13\" font-weight=\"bold\">")
          .append(Html.esc(title)).append("</text>");
        sb.append("<line x1=\"").append(L).append("\" y1=\"").append(H - B).append("\" x2=\"").append(W - R).append("\" y2=\"")
          .append(H - B).append("\" stroke=\"#333\"/>");
        sb.append("<line x1=\"").append(L).append("\" y1=\"").append(T).append("\" x2=\"").append(L).append("\" y2=\"")
          .append(H - B).append("\" stroke=\"#333\"/>");
        for (int i = 0; i <= 5; i++) {
            double xv = xmin + (xmax - xmin) * i / 5, yv = ymin + (ymax - ymin) * i / 5;
            double px = sx(xv, xmin, xmax), py = sy(yv, ymin, ymax);
            sb.append("<text x=\"").append(f(px)).append("\" y=\"").append(H - B + 14).append("\" text-anchor=\"middle\">")
              .append(num(xv)).append("</text>");
            sb.append("<line x1=\"").append(L).append("\" y1=\"").append(f(py)).append("\" x2=\"").append(W - R).append("\" y2=\"")
              .append(f(py)).append("\" stroke=\"#ddd\"/>");
            sb.append("<text x=\"").append(L - 4).append("\" y=\"").append(f(py + 4)).append("\" text-anchor=\"end\">")
              .append(logY ? num(Math.pow(10, yv)) : num(yv)).append("</text>");
        }
        sb.append("<text x=\"").append((L + W - R) / 2).append("\" y=\"").append(H - 6).append("\" text-anchor=\"middle\">")
          .append(Html.esc(xLabel)).append("</text>");
        sb.append("<text transform=\"translate(14,").append((T + H - B) / 2).append(") rotate(-90)\" text-anchor=\"middle\">")
          .append(Html.esc(yLabel)).append("</text>");
        return sb;
    }

    private static void legend(StringBuilder sb, List<Series> series) {
        int x = W - R - 170, y = T + 6;
        for (Series s : series) {
            sb.append("<rect x=\"").append(x).append("\" y=\"").append(y - 8).append("\" width=\"10\" height=\"10\" fill=\"")
              .append(s.color()).append("\"/><text x=\"").append(x + 14).append("\" y=\"").append(y + 1).append("\">")
              .append(Html.esc(s.name())).append("</text>");
            y += 14;
        }
    }

    private static double tr(double v, boolean log) { return log ? (v > 0 ? Math.log10(v) : Double.NaN) : v; }
    private static double sx(double x, double a, double b) { return L + (x - a) / (b - a) * (W - L - R); }
    private static double sy(double y, double a, double b) { return H - B - (y - a) / (b - a) * (H - B - T); }
    private static String f(double v) { return String.format(Locale.ROOT, "%.1f", v); }

    static String num(double v) {
        double a = Math.abs(v);
        if (a == 0) return "0";
        if (a >= 1000 || a < 0.001) return String.format(Locale.ROOT, "%.1e", v);
        if (a >= 10) return String.format(Locale.ROOT, "%.0f", v);
        if (a >= 1) return String.format(Locale.ROOT, "%.1f", v);
        return String.format(Locale.ROOT, "%.3f", v);
    }
}
