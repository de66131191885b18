package org.robopro.app.workbench.ui;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.AffineTransform;
import java.awt.geom.Path2D;
import javax.swing.JPanel;
import org.robopro.calibration.report.Figure;

/**
 * A panel that paints one {@link Figure} (the reports' figure routine) with Java2D at the
 * panel's size: the workbench's plots and the report SVGs come from the same layout code.
 */
final class FigurePanel extends JPanel {
    /** Draws the figure on a canvas of the given width and height. */
    interface Drawing extends Figure.Drawing { }

    private volatile Drawing drawing;

    FigurePanel() { setOpaque(true); setBackground(Color.WHITE); }

    /** Shows {@code d} (null: empty). */
    void show(Drawing d) {
        drawing = d;
        repaint();
    }

    Drawing drawing() { return drawing; }

    @Override
    protected void paintComponent(Graphics g0) {
        super.paintComponent(g0);
        Drawing d = drawing;
        var in = getInsets();
        int w = getWidth() - in.left - in.right, h = getHeight() - in.top - in.bottom;
        if (d == null || w < 60 || h < 60) return;
        Graphics2D g = (Graphics2D) g0.create(in.left, in.top, w, h);
        try {
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
            d.draw(new Java2dCanvas(g), w, h);
        } finally {
            g.dispose();
        }
    }

    /** Paints a figure into {@code g} (also used for tests and image export). */
    static void paint(Graphics2D g, Drawing d, int w, int h) { d.draw(new Java2dCanvas(g), w, h); }

    /** {@link Figure.Canvas} on a Graphics2D. */
    static final class Java2dCanvas implements Figure.Canvas {
        private final Graphics2D g;
        private final Font base;

        Java2dCanvas(Graphics2D g) {
            this.g = g;
            this.base = g.getFont();
        }

        private static Color color(String hex, double opacity) {
            Color c = Color.decode(hex);
            return opacity >= 1 ? c : new Color(c.getRed(), c.getGreen(), c.getBlue(), (int) Math.round(255 * opacity));
        }

        private Font font(double size, boolean bold) { return base.deriveFont(bold ? Font.BOLD : Font.PLAIN, (float) size); }

        @Override public void line(double x1, double y1, double x2, double y2, String color, double width, boolean dashed) {
            g.setColor(color(color, 1));
            g.setStroke(dashed ? new BasicStroke((float) width, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f, new float[] {6f, 4f}, 0f)
                    : new BasicStroke((float) width));
            g.draw(new java.awt.geom.Line2D.Double(x1, y1, x2, y2));
        }

        @Override public void rect(double x, double y, double w, double h, String color, double opacity) {
            g.setColor(color(color, opacity));
            g.fill(new java.awt.geom.Rectangle2D.Double(x, y, w, Math.max(0, h)));
        }

        @Override public void circle(double cx, double cy, double r, String color) {
            g.setColor(color(color, 1));
            g.fill(new java.awt.geom.Ellipse2D.Double(cx - r, cy - r, 2 * r, 2 * r));
        }

        @Override public void polyline(double[] xs, double[] ys, int n, String color, double width) {
            if (n == 0) return;
            Path2D.Double p = new Path2D.Double();
            p.moveTo(xs[0], ys[0]);
            for (int i = 1; i < n; i++) p.lineTo(xs[i], ys[i]);
            g.setColor(color(color, 1));
            g.setStroke(new BasicStroke((float) width, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
            g.draw(p);
        }

        @Override public void text(double x, double y, String s, int anchor, double size, boolean bold, boolean vertical) {
            Font f = font(size, bold);
            g.setFont(f);
            g.setColor(new Color(0x222222));
            double w = g.getFontMetrics(f).stringWidth(s);
            double dx = anchor < 0 ? 0 : anchor == 0 ? -w / 2 : -w;
            if (!vertical) {
                g.drawString(s, (float) (x + dx), (float) y);
                return;
            }
            AffineTransform old = g.getTransform();
            g.translate(x, y);
            g.rotate(-Math.PI / 2);
            g.drawString(s, (float) dx, 0f);
            g.setTransform(old);
        }

        @Override public double textWidth(String s, double size) { return g.getFontMetrics(font(size, false)).stringWidth(s); }
    }

}
