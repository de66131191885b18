package org.robopro.app.workbench.ui;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.FlowLayout;
import java.awt.Font;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import org.robopro.calibration.report.Figure;
import org.robopro.calibration.report.Svg;
import java.util.Locale;
import java.util.concurrent.CancellationException;
import java.util.concurrent.CompletableFuture;
import java.util.function.BooleanSupplier;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JFileChooser;
import javax.swing.JLabel;
import javax.swing.JOptionPane;
import javax.swing.JPanel;
import javax.swing.JProgressBar;
import javax.swing.JScrollPane;
import javax.swing.JSplitPane;
import javax.swing.JTabbedPane;
import javax.swing.JTextArea;
import javax.swing.SwingUtilities;
import org.robopro.app.workbench.WorkbenchSession;
import org.robopro.calibration.Cancellation;
import org.robopro.calibration.diagnosis.Diagnosis;
import org.robopro.calibration.diagnosis.DiagnosisReport;
import org.robopro.calibration.diagnosis.Effect;
import org.robopro.calibration.identification.CalibrationResult;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.models.InputException;

/**
 * Calibration panel (seed paper §5): load a measurement file (docs/measurement-file.md), run
 * the calibration in the background with a progress bar and a Cancel button, then see the RMS
 * error before and after (training and validation poses), a plot of every pose's error with the
 * nominal and the calibrated model, and the effects found: the largest parameter corrections
 * and what the data could not identify. "Diagnose" runs the diagnosis (docs/diagnosis.md: geometric
 * calibration, then the non-geometric effects: compliance, gear errors, backlash, thermal
 * expansion, scale, coupling) in the background and shows each finding in words with its
 * parameters, RMS improvement and evidence, the outliers, what could not be identified and what
 * to record next. "Apply" writes the calibrated (or, after a diagnosis that found effects, the
 * extended) robot file and makes RAPID export compensate targets with it.
 */
public final class CalibrationPanel extends JPanel {
    private final WorkbenchSession wb;
    private final JLabel file = new JLabel("no measurement file");
    private final JProgressBar progress = new JProgressBar(0, 1000);
    private final JButton run = new JButton("Calibrate");
    private final JButton diagnose = new JButton("Diagnose");
    private final JButton cancel = new JButton("Cancel");
    private final JButton apply = new JButton("Apply calibrated model...");
    private final JLabel rms = new JLabel(" ");
    private final JTextArea effects = new JTextArea(12, 60);
    private final FigurePanel plot = new FigurePanel();
    private final JTextArea findings = new JTextArea(12, 60);
    private final FigurePanel rmsChart = new FigurePanel();
    private final JTabbedPane tabs = new JTabbedPane();
    private final WorkbenchFrame owner;
    private WorkbenchSession.Measurements measurements;
    private volatile Cancellation token;
    private volatile CalibrationResult result;
    private volatile Diagnosis diagnosis;
    private volatile String state = "idle";

    public CalibrationPanel(WorkbenchFrame owner, WorkbenchSession wb) {
        super(new BorderLayout());
        this.wb = wb;
        this.owner = owner;
        setName("calibration-panel");
        JPanel top = new JPanel(new FlowLayout(FlowLayout.LEFT, 6, 4));
        JButton load = new JButton("Load measurements...");
        load.setName("cal-load");
        load.addActionListener(e -> {
            JFileChooser fc = new JFileChooser(new java.io.File("."));
            if (fc.showOpenDialog(this) == JFileChooser.APPROVE_OPTION) loadMeasurements(fc.getSelectedFile().toPath());
        });
        run.setName("cal-run");
        run.addActionListener(e -> start());
        diagnose.setName("cal-diagnose");
        diagnose.setToolTipText("Calibrate, then test which non-geometric effects explain what is left (compliance, gear errors, backlash, ...)");
        diagnose.addActionListener(e -> startDiagnosis());
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
        buttons.add(diagnose);
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
        plot.setBorder(BorderFactory.createTitledBorder("Error per pose, sorted"));
        plot.setPreferredSize(new Dimension(600, 200));
        JSplitPane split = new JSplitPane(JSplitPane.VERTICAL_SPLIT, plot, es);
        split.setResizeWeight(0.5);
        findings.setEditable(false);
        findings.setLineWrap(true);
        findings.setWrapStyleWord(true);
        findings.setName("cal-findings");
        findings.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
        JScrollPane fs = new JScrollPane(findings);
        fs.setBorder(BorderFactory.createTitledBorder("Findings, outliers, what the data cannot tell, what to record next"));
        rmsChart.setBorder(BorderFactory.createTitledBorder("RMS error: geometric model, after each effect, final fit"));
        rmsChart.setPreferredSize(new Dimension(600, 200));
        JSplitPane dsplit = new JSplitPane(JSplitPane.VERTICAL_SPLIT, rmsChart, fs);
        dsplit.setResizeWeight(0.3);
        tabs.addTab("Calibration", split);
        tabs.addTab("Diagnosis", dsplit);
        tabs.setName("cal-tabs");
        JPanel content = new JPanel(new BorderLayout());
        content.add(head, BorderLayout.NORTH);
        content.add(tabs, BorderLayout.CENTER);
        add(content, BorderLayout.CENTER);
        updateButtons();
    }

    // ---- the UI layer tests drive ---------------------------------------------------------------

    public String state() { return state; }
    public CalibrationResult result() { return result; }
    public String rmsText() { return rms.getText(); }
    public String effectsText() { return effects.getText(); }
    public Diagnosis diagnosis() { return diagnosis; }
    public String findingsText() { return findings.getText(); }
    public int progressValue() { return progress.getValue(); }

    /** Loads a measurement file; errors (file, line, column, field) are shown, nothing changes. */
    public boolean loadMeasurements(Path f) {
        try {
            measurements = wb.loadMeasurements(f);
            MeasurementSet tr = measurements.train();
            String each = tr.isPairs() ? " (a length between two poses each)" : tr.isDistance() ? " (a distance each)" : tr.pointCount() > 1 ? " (" + tr.pointCount() + " points each)" : "";
            file.setText(String.format(Locale.ROOT, "%s: %d training poses%s, %s", f.getFileName(), tr.size(), each,
                    measurements.validate() == null ? "no validation poses" : measurements.validate().size() + " validation poses"));
            result = null;
            diagnosis = null;
            state = "loaded";
            updateButtons();
            return true;
        } catch (InputException | java.io.IOException | IllegalArgumentException e) {
            owner.showError("Measurement file", e.getMessage());
            return false;
        }
    }

    /** Starts the calibration on a background thread; the future completes when it is done, failed or cancelled. */
    public CompletableFuture<CalibrationResult> start() {
        return background("Calibration", (m, c, p) -> wb.calibrate(m, c, p), this::show);
    }

    /**
     * Starts the diagnosis (geometric calibration, then the effects) on a background thread; the
     * future completes when it is done, failed or cancelled.
     */
    public CompletableFuture<Diagnosis> startDiagnosis() {
        return background("Diagnosis", (m, c, p) -> wb.diagnose(m, c, p), this::show);
    }

    private interface Job<T> { T run(WorkbenchSession.Measurements m, Cancellation c, org.robopro.calibration.Progress p); }

    /** Runs a job off the Swing thread with the progress bar and Cancel; the result is shown on the Swing thread. */
    private <T> CompletableFuture<T> background(String what, Job<T> job, java.util.function.Consumer<T> show) {
        if (measurements == null || "running".equals(state)) return CompletableFuture.failedFuture(new IllegalStateException("nothing to run"));
        Cancellation c = new Cancellation();
        token = c;
        state = "running";
        progress.setValue(0);
        progress.setString(what.toLowerCase(Locale.ROOT));
        updateButtons();
        WorkbenchSession.Measurements m = measurements;
        CompletableFuture<T> f = new CompletableFuture<>();
        Thread t = new Thread(() -> {
            try {
                T r = job.run(m, c, (stage, fraction) -> SwingUtilities.invokeLater(() -> {
                    progress.setValue((int) Math.round(1000 * Math.max(0, Math.min(1, fraction))));
                    progress.setString(stage);
                }));
                // Complete after the panel shows the result, so callers see the finished panel.
                SwingUtilities.invokeLater(() -> { show.accept(r); f.complete(r); });
            } catch (CancellationException e) {
                SwingUtilities.invokeLater(() -> { state = "cancelled"; progress.setString("cancelled"); updateButtons(); f.completeExceptionally(e); });
                wb.log(what + " cancelled; nothing changed");
            } catch (RuntimeException e) {
                SwingUtilities.invokeLater(() -> {
                    state = "failed";
                    progress.setString("failed");
                    updateButtons();
                    f.completeExceptionally(e);
                    owner.showError(what + " failed", e.getMessage());
                });
            }
        }, what.toLowerCase(Locale.ROOT));
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
        diagnosis = null;
        state = "done";
        progress.setValue(1000);
        progress.setString("done");
        rms.setText(rmsLines(r));
        // The calibration workflow's warnings (outliers and what they suggest, identifiability, validation), as the CLI prints them.
        StringBuilder w = new StringBuilder();
        wb.lastCalibration().filter(o -> o.result() == r).ifPresent(o -> {
            for (String x : o.warnings()) w.append("Warning: ").append(x).append("\n");
        });
        if (w.length() > 0) w.append('\n');
        effects.setLineWrap(w.length() > 0);
        effects.setWrapStyleWord(true);
        effects.setText(w + effectsReport(r));
        effects.setCaretPosition(0);
        List<CalibrationResult.PoseError> all = new ArrayList<>(r.train());
        all.addAll(r.validate());
        plot.show(errorFigure(all, Double.isFinite(r.sigmaPosM()) ? r.sigmaPosM() * 1e3 * Math.sqrt(r.distance() ? 1 : 3) : Double.NaN,
                r.distance(), !r.pointNames().isEmpty()));
        tabs.setSelectedIndex(0);
        updateButtons();
    }

    private void show(Diagnosis d) {
        diagnosis = d;
        show(d.geometric());
        diagnosis = d;
        apply.setText(d.effects().isEmpty() ? "Apply calibrated model..." : "Apply extended model...");
        findings.setText(diagnosisReport(d));
        findings.setCaretPosition(0);
        rmsChart.show(rmsFigure(d));
        tabs.setSelectedIndex(1);
    }

    /** The calibration's figures, one label each, on two lines (training, then validation). */
    static String rmsLines(CalibrationResult r) {
        String train = String.format(Locale.ROOT, "Training RMS %.4f mm → %.4f mm (%s)", r.nominalTrainRmsM() * 1e3, r.trainRmsM() * 1e3,
                counted(r, r.train()));
        if (r.validate().isEmpty()) return "<html>" + train + "<br>No validation poses</html>";
        return "<html>" + train + String.format(Locale.ROOT, "<br>Validation RMS %.4f mm → %.4f mm (%s, largest %.4f mm)</html>",
                r.nominalValidateRmsM() * 1e3, r.validateRmsM() * 1e3, counted(r, r.validate()), r.validateMaxM() * 1e3);
    }

    /** What the errors are counted over: "30 poses", "90 points on 30 poses", "150 distances". */
    static String counted(CalibrationResult r, List<CalibrationResult.PoseError> es) {
        if (r.distance()) return es.size() + " distances";
        if (r.pointNames().isEmpty()) return es.size() + " poses";
        return es.size() + " points on " + CalibrationResult.poses(es) + " poses";
    }

    /** A diagnosis in plain words: findings (effect, joints, parameters with units, RMS, evidence), outliers, the rest. */
    static String diagnosisReport(Diagnosis d) {
        StringBuilder b = new StringBuilder();
        boolean val = Double.isFinite(d.geometricValidateRmsM());
        String over = d.distances() ? "distances of the " : d.pointsPerPose() > 1 ? "measured points of the " : "";
        b.append(String.format(Locale.ROOT, "Geometric model: RMS %.4f mm over the %straining poses%s. Noise floor about %.4f mm (sigma %.4f mm per %s).%n",
                d.geometricTrainRmsM() * 1e3, over, val ? String.format(Locale.ROOT, ", %.4f mm on the validation poses", d.geometricValidateRmsM() * 1e3) : "",
                d.noiseFloorM() * 1e3, d.sigmaM() * 1e3, d.distances() ? "distance" : "axis"));
        if (d.effects().isEmpty()) {
            b.append(String.format(Locale.ROOT, "%nNo non-geometric effect found: %d candidates tested at a family-wise false-positive rate of %.3g. "
                    + "The geometric calibration explains the data.%n", d.candidatesTested(), d.alpha()));
        } else {
            b.append(String.format(Locale.ROOT, "With the effects below: RMS %.4f mm%s.%n", d.finalTrainRmsM() * 1e3,
                    val ? String.format(Locale.ROOT, ", validation %.4f mm", d.finalValidateRmsM() * 1e3) : ""));
        }
        double trainBefore = d.geometricTrainRmsM(), valBefore = d.geometricValidateRmsM();
        int n = 1;
        for (Diagnosis.Finding f : d.effects()) {
            Effect e = f.effect();
            b.append(String.format(Locale.ROOT, "%n%d. %s%s%n", n++, e.title(), e.joints1().isEmpty() ? ""
                    : (e.joints1().size() == 1 ? " on joint " : " on joints ") + joinInts(e.joints1())));
            b.append("   ").append(f.words()).append('\n');
            b.append("   Parameters: ").append(parameters(e, f.values(), f.sigmas())).append('\n');
            b.append(String.format(Locale.ROOT, "   RMS: training %.4f -> %.4f mm", trainBefore * 1e3, f.trainRmsM() * 1e3));
            if (Double.isFinite(f.validateRmsM()))
                b.append(String.format(Locale.ROOT, ", validation %.4f -> %.4f mm", valBefore * 1e3, f.validateRmsM() * 1e3));
            b.append('\n');
            Diagnosis.Evidence ev = f.evidence();
            b.append(String.format(Locale.ROOT, "   Evidence: removes %.0f %% of the residual sum of squares; F = %.1f (%d, %d), p %s "
                            + "< Holm threshold %.2g; leave-one-out error %.1f -> %.1f; %.0f %% of its signature distinct from geometry%s; %s.%n",
                    100 * ev.rssReduction(), ev.f(), ev.df1(), ev.df2(), ev.pValue() < 1e-300 ? "< 1e-300" : String.format(Locale.ROOT, "= %.2g", ev.pValue()), ev.threshold(), ev.pressBefore(), ev.pressAfter(),
                    100 * ev.projectionRatio(), ev.absorbed().isEmpty() ? "" : " (" + String.join(", ", ev.absorbed()) + " left to geometry)",
                    ev.plausibility()));
            trainBefore = f.trainRmsM();
            valBefore = f.validateRmsM();
        }
        b.append('\n');
        b.append(d.outliers().isEmpty() ? "Outliers: none.\n"
                : "Outliers (left out of every fit; re-measure these poses): " + String.join(", ", d.outliers()) + "\n");
        if (!d.notIdentifiable().isEmpty()) {
            b.append("Not identifiable on these data (the geometry absorbs them; not claimed):\n");
            for (Diagnosis.NotIdentifiable x : d.notIdentifiable())
                b.append(String.format(Locale.ROOT, "  - %s (%.0f %% of its signature left): %s%n", x.label(), 100 * x.ratio(), x.reason()));
        }
        if (!d.implausible().isEmpty()) {
            b.append("Significant but physically implausible (not claimed):\n");
            for (Diagnosis.Finding f : d.implausible()) b.append("  - ").append(f.words()).append('\n');
        }
        b.append(d.recommendations().isEmpty() ? "What to record next: nothing more is needed for these effects.\n" : "What to record next:\n");
        for (String r : d.recommendations()) b.append("  - ").append(r).append('\n');
        if (!d.notes().isEmpty()) {
            b.append("Notes:\n");
            for (String r : d.notes()) b.append("  - ").append(r).append('\n');
        }
        b.append(String.format(Locale.ROOT, "(%d candidates tested, %.1f s)%n", d.candidatesTested(), d.elapsedMs() / 1e3));
        return b.toString();
    }

    private static String joinInts(List<Integer> js) {
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < js.size(); i++) b.append(i == 0 ? "" : i == js.size() - 1 ? " (moved by) " : ", ").append(js.get(i));
        return b.toString();
    }

    /** Parameters with their uncertainty in the units an engineer reads: degrees, ppm, stiffness. */
    static String parameters(Effect e, double[] v, double[] s) {
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < e.size(); i++) {
            if (i > 0) b.append(", ");
            String name = e.parameterNames().get(i), unit = e.units().get(i);
            double sd = i < s.length ? s[i] : Double.NaN;
            switch (unit) {
                case "rad" -> b.append(String.format(Locale.ROOT, "%s = %.4f ± %.4f deg", name, Math.toDegrees(v[i]), Math.toDegrees(sd)));
                case "rad/(N·m)" -> b.append(String.format(Locale.ROOT, "%s = %.3g ± %.2g rad/(N·m) (stiffness %.3g N·m/rad)", name, v[i], sd, 1 / v[i]));
                case "1/K" -> b.append(String.format(Locale.ROOT, "%s = %.2f ± %.2f µm/(m·K)", name, v[i] * 1e6, sd * 1e6));
                default -> b.append(String.format(Locale.ROOT, "%s = %.1f ± %.1f ppm", name, v[i] * 1e6, sd * 1e6));
            }
        }
        return b.toString();
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
        diagnose.setEnabled(measurements != null && !"running".equals(state));
        cancel.setEnabled("running".equals(state));
        apply.setEnabled(result != null && !"running".equals(state));
        if (diagnosis == null) apply.setText("Apply calibrated model...");
    }

    private void applyInteractive() {
        JFileChooser fc = new JFileChooser(wb.projectFile().map(p -> p.toAbsolutePath().getParent().toFile()).orElse(new java.io.File(".")));
        boolean extended = diagnosis != null && !diagnosis.effects().isEmpty();
        fc.setSelectedFile(new java.io.File(wb.model().robot().name() + (extended ? "-extended" : "-calibrated") + ".robot.json"));
        if (fc.showSaveDialog(this) != JFileChooser.APPROVE_OPTION) return;
        apply(fc.getSelectedFile().toPath(), () -> JOptionPane.showConfirmDialog(this, fc.getSelectedFile() + " exists. Replace it?",
                "Apply calibration", JOptionPane.YES_NO_OPTION) == JOptionPane.YES_OPTION);
    }

    /**
     * Writes the calibrated robot file (an existing one only when confirmed) and applies it:
     * after a diagnosis that found effects, the extended model (geometry plus effects), so that
     * compensated export uses the calibration module's Compensator on it.
     */
    public boolean apply(Path robotFile, BooleanSupplier confirmOverwrite) {
        CalibrationResult r = result;
        Diagnosis d = diagnosis;
        if (r == null) return false;
        boolean exists = java.nio.file.Files.exists(robotFile);
        if (exists && !confirmOverwrite.getAsBoolean()) { wb.log("Calibration not applied: " + robotFile + " exists"); return false; }
        if (d != null && !d.effects().isEmpty()) wb.applyDiagnosis(d, robotFile, measurements.file().toString(), exists);
        else wb.applyCalibration(r, robotFile, measurements.file().toString(), exists);
        return true;
    }

    /**
     * Sorted per-pose errors with the nominal (grey) and the calibrated model (orange), log
     * scale, with the noise floor (mm; NaN: none drawn): the reports' figure routine.
     */
    static FigurePanel.Drawing errorFigure(List<CalibrationResult.PoseError> es, double noiseFloorMm) {
        return errorFigure(es, noiseFloorMm, false, false);
    }

    /** {@link #errorFigure(List, double)} for distances (floor σ, one error per distance) or several points per pose (one per point). */
    static FigurePanel.Drawing errorFigure(List<CalibrationResult.PoseError> es, double noiseFloorMm, boolean distances, boolean points) {
        double[] before = es.stream().mapToDouble(e -> e.nominalM() * 1e3).sorted().toArray();
        double[] after = es.stream().mapToDouble(e -> e.calibratedM() * 1e3).sorted().toArray();
        double[] rank = new double[before.length];
        for (int i = 0; i < rank.length; i++) rank[i] = i + 1;
        List<Svg.Series> series = List.of(new Svg.Series("nominal model", rank, before, "#8a9099", true),
                new Svg.Series("calibrated model", rank, after, "#f07a1a", true));
        List<Svg.Line> lines = noiseFloorMm > 0 ? List.of(new Svg.Line(distances ? "noise floor (σ)" : "noise floor (√3·σ)", noiseFloorMm, "#2e7d32"))
                : List.of();
        String x = distances ? "distance, sorted by error" : points ? "measured point, sorted by error" : "pose, sorted by error";
        return (c, w, h) -> Figure.plot(c, w, h, "", x, distances ? "distance error (mm)" : "error (mm)", series, true, lines);
    }

    /** The diagnosis's RMS bars, the same drawing as in its HTML report. */
    static FigurePanel.Drawing rmsFigure(Diagnosis d) {
        return (c, w, h) -> DiagnosisReport.rmsBars(c, w, h, "", d);
    }
}
