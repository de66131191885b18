package org.robopro.app.workbench.ui;

import java.awt.BasicStroke;
import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.FlowLayout;
import java.awt.Font;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CancellationException;
import java.util.concurrent.CompletableFuture;
import java.util.function.BooleanSupplier;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JDialog;
import javax.swing.JFileChooser;
import javax.swing.JLabel;
import javax.swing.JOptionPane;
import javax.swing.JPanel;
import javax.swing.JProgressBar;
import javax.swing.JScrollPane;
import javax.swing.JSplitPane;
import javax.swing.JTextArea;
import javax.swing.SwingUtilities;
import org.robopro.app.workbench.Workbench;
import org.robopro.calibration.Cancellation;
import org.robopro.calibration.identification.CalibrationResult;
import org.robopro.models.InputException;

/**
 * Calibration panel (seed paper §5): load a measurement file (docs/measurement-file.md), run
 * the calibration in the background with a progress bar and a Cancel button, then see the RMS
 * error before and after (training and validation poses), a plot of every pose's error with the
 * nominal and the calibrated model, and the effects found: the largest parameter corrections
 * and what the data could not identify. "Apply" writes the calibrated robot file and makes RAPID
 * export compensate targets with it.
 */
public final class CalibrationPanel extends JDialog {
    private final Workbench wb;
    private final JLabel file = new JLabel("no measurement file");
    private final JProgressBar progress = new JProgressBar(0, 1000);
    private final JButton run = new JButton("Calibrate");
    private final JButton cancel = new JButton("Cancel");
    private final JButton apply = new JButton("Apply calibrated model...");
    private final JLabel rms = new JLabel(" ");
    private final JTextArea effects = new JTextArea(12, 60);
    private final ErrorPlot plot = new ErrorPlot();
    private Workbench.Measurements measurements;
    private volatile Cancellation token;
    private volatile CalibrationResult result;
    private volatile String state = "idle";

    public CalibrationPanel(WorkbenchFrame owner, Workbench wb) {
        super(owner, "Calibration", false);
        this.wb = wb;
        setDefaultCloseOperation(DISPOSE_ON_CLOSE);
        JPanel top = new JPanel(new FlowLayout(FlowLayout.LEFT, 6, 4));
        JButton load = new JButton("Load measurements...");
        load.setName("cal-load");
        load.addActionListener(e -> {
            JFileChooser fc = new JFileChooser(new java.io.File("."));
            if (fc.showOpenDialog(this) == JFileChooser.APPROVE_OPTION) loadMeasurements(fc.getSelectedFile().toPath());
        });
        run.setName("cal-run");
        run.addActionListener(e -> start());
        cancel.setName("cal-cancel");
        cancel.addActionListener(e -> cancel());
        apply.setName("cal-apply");
        apply.addActionListener(e -> applyInteractive());
        top.add(load);
        top.add(file);
        JPanel bar = new JPanel(new BorderLayout(6, 0));
        progress.setStringPainted(true);
        progress.setString("");
        progress.setName("cal-progress");
        bar.add(progress, BorderLayout.CENTER);
        JPanel buttons = new JPanel(new FlowLayout(FlowLayout.RIGHT, 4, 0));
        buttons.add(run);
        buttons.add(cancel);
        buttons.add(apply);
        bar.add(buttons, BorderLayout.EAST);
        rms.setName("cal-rms");
        rms.setFont(rms.getFont().deriveFont(Font.BOLD, 13f));
        JPanel head = new JPanel(new BorderLayout(4, 4));
        head.add(top, BorderLayout.NORTH);
        head.add(bar, BorderLayout.CENTER);
        head.add(rms, BorderLayout.SOUTH);
        head.setBorder(BorderFactory.createEmptyBorder(4, 6, 4, 6));
        effects.setEditable(false);
        effects.setName("cal-effects");
        effects.setFont(new Font(Font.MONOSPACED, Font.PLAIN, 11));
        JScrollPane es = new JScrollPane(effects);
        es.setBorder(BorderFactory.createTitledBorder("Effects found (largest parameter corrections) and identifiability"));
        plot.setBorder(BorderFactory.createTitledBorder("Error per pose, sorted (grey: nominal model, orange: calibrated)"));
        plot.setPreferredSize(new Dimension(600, 200));
        JSplitPane split = new JSplitPane(JSplitPane.VERTICAL_SPLIT, plot, es);
        split.setResizeWeight(0.5);
        JPanel content = new JPanel(new BorderLayout());
        content.add(head, BorderLayout.NORTH);
        content.add(split, BorderLayout.CENTER);
        setContentPane(content);
        setSize(760, 600);
        updateButtons();
    }

    // ---- the UI layer tests drive ---------------------------------------------------------------

    public String state() { return state; }
    public CalibrationResult result() { return result; }
    public String rmsText() { return rms.getText(); }
    public String effectsText() { return effects.getText(); }
    public int progressValue() { return progress.getValue(); }

    /** Loads a measurement file; errors (file, line, column, field) are shown, nothing changes. */
    public boolean loadMeasurements(Path f) {
        try {
            measurements = wb.loadMeasurements(f);
            file.setText(String.format(Locale.ROOT, "%s: %d training poses, %s", f.getFileName(), measurements.train().size(),
                    measurements.validate() == null ? "no validation poses" : measurements.validate().size() + " validation poses"));
            result = null;
            state = "loaded";
            updateButtons();
            return true;
        } catch (InputException | java.io.IOException | IllegalArgumentException e) {
            ((WorkbenchFrame) getOwner()).showError("Measurement file", e.getMessage());
            return false;
        }
    }

    /** Starts the calibration on a background thread; the future completes when it is done, failed or cancelled. */
    public CompletableFuture<CalibrationResult> start() {
        if (measurements == null || "running".equals(state)) return CompletableFuture.failedFuture(new IllegalStateException("nothing to run"));
        Cancellation c = new Cancellation();
        token = c;
        state = "running";
        progress.setValue(0);
        updateButtons();
        Workbench.Measurements m = measurements;
        CompletableFuture<CalibrationResult> f = new CompletableFuture<>();
        Thread t = new Thread(() -> {
            try {
                CalibrationResult r = wb.calibrate(m, c, (stage, fraction) -> SwingUtilities.invokeLater(() -> {
                    progress.setValue((int) Math.round(1000 * Math.max(0, Math.min(1, fraction))));
                    progress.setString(stage);
                }));
                SwingUtilities.invokeLater(() -> show(r));
                f.complete(r);
            } catch (CancellationException e) {
                SwingUtilities.invokeLater(() -> { state = "cancelled"; progress.setString("cancelled"); updateButtons(); });
                wb.log("Calibration cancelled; nothing changed");
                f.completeExceptionally(e);
            } catch (RuntimeException e) {
                SwingUtilities.invokeLater(() -> {
                    state = "failed";
                    progress.setString("failed");
                    updateButtons();
                    ((WorkbenchFrame) getOwner()).showError("Calibration failed", e.getMessage());
                });
                f.completeExceptionally(e);
            }
        }, "calibration");
        t.setDaemon(true);
        t.start();
        return f;
    }

    public void cancel() {
        Cancellation c = token;
        if (c != null) c.cancel();
    }

    private void show(CalibrationResult r) {
        result = r;
        state = "done";
        progress.setValue(1000);
        progress.setString("done");
        rms.setText(String.format(Locale.ROOT, "RMS %.4f mm -> %.4f mm (%d training poses)%s", r.nominalTrainRmsM() * 1e3,
                r.trainRmsM() * 1e3, r.train().size(), r.validate().isEmpty() ? ""
                        : String.format(Locale.ROOT, ";  validation %.4f mm -> %.4f mm (max %.4f mm)", r.nominalValidateRmsM() * 1e3,
                        r.validateRmsM() * 1e3, r.validateMaxM() * 1e3)));
        effects.setText(effectsReport(r));
        effects.setCaretPosition(0);
        List<CalibrationResult.PoseError> all = new ArrayList<>(r.train());
        all.addAll(r.validate());
        plot.set(all);
        updateButtons();
    }

    /** The parameters that moved most (in units of their uncertainty where known) and what was fixed. */
    static String effectsReport(CalibrationResult r) {
        StringBuilder b = new StringBuilder();
        List<CalibrationResult.ParameterEstimate> ps = new ArrayList<>(r.parameters());
        ps.removeIf(p -> !"geometry".equals(p.block()));
        ps.sort(Comparator.comparingDouble((CalibrationResult.ParameterEstimate p) -> -Math.abs(p.identified() - p.nominal())
                * ("m".equals(p.unitSi()) ? 1 : 1.0)));
        b.append(String.format(Locale.ROOT, "%-14s %14s %14s %12s%n", "parameter", "correction", "sigma", ""));
        for (int i = 0; i < Math.min(12, ps.size()); i++) {
            CalibrationResult.ParameterEstimate p = ps.get(i);
            boolean metres = "m".equals(p.unitSi());
            double d = p.identified() - p.nominal();
            b.append(String.format(Locale.ROOT, "%-14s %11.4f %-2s %11.4f %-2s%n", p.name(), metres ? d * 1e3 : Math.toDegrees(d),
                    metres ? "mm" : "deg", Double.isNaN(p.sigma()) ? Double.NaN : metres ? p.sigma() * 1e3 : Math.toDegrees(p.sigma()),
                    metres ? "mm" : "deg"));
        }
        b.append(String.format(Locale.ROOT, "%n%d parameters not identifiable from this data (fixed), condition number %.3g, %d outliers%n",
                r.unidentifiable().size(), r.conditionNumber(), r.outliers().size()));
        for (CalibrationResult.Outlier o : r.outliers()) b.append("  outlier ").append(o.poseId()).append(": ").append(o.reason()).append('\n');
        var t = r.flangeTtool().position();
        b.append(String.format(Locale.ROOT, "measured point on the flange: (%.3f, %.3f, %.3f) mm%n", t.x() * 1e3, t.y() * 1e3, t.z() * 1e3));
        return b.toString();
    }

    private void updateButtons() {
        run.setEnabled(measurements != null && !"running".equals(state));
        cancel.setEnabled("running".equals(state));
        apply.setEnabled(result != null);
    }

    private void applyInteractive() {
        JFileChooser fc = new JFileChooser(wb.projectFile().map(p -> p.toAbsolutePath().getParent().toFile()).orElse(new java.io.File(".")));
        fc.setSelectedFile(new java.io.File(wb.model().robot().name() + "-calibrated.robot.json"));
        if (fc.showSaveDialog(this) != JFileChooser.APPROVE_OPTION) return;
        apply(fc.getSelectedFile().toPath(), () -> JOptionPane.showConfirmDialog(this, fc.getSelectedFile() + " exists. Replace it?",
                "Apply calibration", JOptionPane.YES_NO_OPTION) == JOptionPane.YES_OPTION);
    }

    /** Writes the calibrated robot file (an existing one only when confirmed) and applies it. */
    public boolean apply(Path robotFile, BooleanSupplier confirmOverwrite) {
        CalibrationResult r = result;
        if (r == null) return false;
        boolean exists = java.nio.file.Files.exists(robotFile);
        if (exists && !confirmOverwrite.getAsBoolean()) { wb.log("Calibration not applied: " + robotFile + " exists"); return false; }
        wb.applyCalibration(r, robotFile, measurements.file().toString(), exists);
        return true;
    }

    /** Sorted per-pose errors before (grey) and after (orange) calibration, log scale. */
    private static final class ErrorPlot extends JPanel {
        private double[] before = new double[0], after = new double[0];

        void set(List<CalibrationResult.PoseError> es) {
            before = es.stream().mapToDouble(CalibrationResult.PoseError::nominalM).sorted().toArray();
            after = es.stream().mapToDouble(CalibrationResult.PoseError::calibratedM).sorted().toArray();
            repaint();
        }

        @Override
        protected void paintComponent(Graphics g0) {
            super.paintComponent(g0);
            Graphics2D g = (Graphics2D) g0;
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            var in = getInsets();
            int x0 = in.left + 46, y0 = in.top + 6, w = getWidth() - x0 - in.right - 8, h = getHeight() - y0 - in.bottom - 20;
            g.setColor(Color.WHITE);
            g.fillRect(x0, y0, w, h);
            if (before.length == 0 || w < 10 || h < 10) return;
            double lo = 1e-3, hi = 100; // mm, log scale
            g.setFont(g.getFont().deriveFont(10f));
            for (double d = lo; d <= hi * 1.001; d *= 10) {
                int y = y0 + h - (int) Math.round(h * Math.log10(d / lo) / Math.log10(hi / lo));
                g.setColor(new Color(0xE0E0E0));
                g.drawLine(x0, y, x0 + w, y);
                g.setColor(Color.DARK_GRAY);
                g.drawString(d >= 1 ? String.format(Locale.ROOT, "%.0f mm", d) : String.format(Locale.ROOT, "%s mm", d), in.left + 2, y + 4);
            }
            g.drawString("poses, sorted by error", x0 + w / 2 - 50, y0 + h + 15);
            curve(g, before, new Color(0x8A9099), x0, y0, w, h, lo, hi);
            curve(g, after, new Color(0xF07A1A), x0, y0, w, h, lo, hi);
        }

        private static void curve(Graphics2D g, double[] v, Color c, int x0, int y0, int w, int h, double lo, double hi) {
            g.setColor(c);
            g.setStroke(new BasicStroke(2f));
            int px = -1, py = -1;
            for (int i = 0; i < v.length; i++) {
                double mm = Math.max(lo, Math.min(hi, v[i] * 1e3));
                int x = x0 + (int) Math.round(w * (v.length == 1 ? 0.5 : (double) i / (v.length - 1)));
                int y = y0 + h - (int) Math.round(h * Math.log10(mm / lo) / Math.log10(hi / lo));
                if (px >= 0) g.drawLine(px, py, x, y);
                px = x;
                py = y;
            }
        }
    }
}
