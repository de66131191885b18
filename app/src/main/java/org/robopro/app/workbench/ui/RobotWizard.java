package org.robopro.app.workbench.ui;

import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.FlowLayout;
import java.awt.Font;
import java.awt.GridLayout;
import java.nio.file.Path;
import java.util.function.BooleanSupplier;
import javax.swing.BorderFactory;
import javax.swing.DefaultCellEditor;
import javax.swing.JButton;
import javax.swing.JComboBox;
import javax.swing.JFileChooser;
import javax.swing.JLabel;
import javax.swing.JOptionPane;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JSplitPane;
import javax.swing.JTable;
import javax.swing.JTextArea;
import javax.swing.JTextField;
import javax.swing.table.AbstractTableModel;
import org.robopro.app.workbench.WorkbenchSession;
import org.robopro.app.workbench.model.EditHistory;
import org.robopro.app.workbench.model.RobotWizardModel;
import org.robopro.app.workbench.model.RobotWizardModel.JointRow;
import org.robopro.app.workbench.model.WorkbenchModel;
import org.robopro.models.InputException;
import org.robopro.models.JointType;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;

/**
 * Robot model construction wizard (seed paper §6, Fig. 7): the joints one row each — type,
 * a point on the axis (mm) and the axis direction, in base coordinates with every joint at zero,
 * limits and speed — then the flange frame. Every edit rebuilds the kinematic model: the 3D view
 * shows its frames at once (the cell's robot is hidden meanwhile), the text area the Table-1
 * parameter report, and a problem is shown in red under the table instead of failing. The robot
 * is saved as a robot file (atomically; an existing file only after confirmation) and can then
 * replace the cell's robot.
 */
public final class RobotWizard extends JPanel {
    private static final String[] COLS = {"Joint", "Type", "X mm", "Y mm", "Z mm", "Axis x", "Axis y", "Axis z", "Min", "Max", "Speed /s"};

    private final WorkbenchSession wb;
    private final WorkbenchFrame owner;
    private RobotWizardModel wm;
    private final JointTable joints = new JointTable();
    private final FlangeTable flange = new FlangeTable();
    private final JTable jointTable = new FittingTable(joints);
    private final JTextField name = new JTextField(12);
    private final JTextField display = new JTextField(18);
    private final JLabel error = new JLabel(" ");
    private final JTextArea report = new JTextArea(14, 70);
    private final JComboBox<String> template = new JComboBox<>();
    private boolean loading;
    /**
     * The state the last edit left: the "before" of the next one. Each edit is recorded in the
     * workbench's one undo history (Edit &gt; Undo, Ctrl+Z) with {@link #applyState} to put it back.
     */
    private RobotWizardModel.State shown;
    /** What the edit being made is called in the Edit menu ("Robot model: j3 Z mm"). */
    private String editLabel;
    private final EditHistory.Editor<RobotWizardModel.State> editor = this::applyState;
    private RobotWizardModel.Result result;
    private Path savedTo;

    public RobotWizard(WorkbenchFrame owner, WorkbenchSession wb) {
        super(new BorderLayout());
        this.wb = wb;
        this.owner = owner;
        this.wm = RobotWizardModel.from(wb.model().robot());
        setName("robot-wizard");

        JPanel head = new JPanel(new java.awt.GridLayout(0, 1, 0, 0));
        JPanel head1 = new JPanel(new FlowLayout(FlowLayout.LEFT, 6, 2));
        JPanel head2 = new JPanel(new FlowLayout(FlowLayout.LEFT, 6, 2));
        JPanel head3 = new JPanel(new FlowLayout(FlowLayout.LEFT, 6, 2));
        head.add(head1);
        head.add(head2);
        head.add(head3);
        template.addItem("current robot");
        for (String n : RobotLibrary.shippedNames()) template.addItem(n);
        template.addItem("empty (one joint)");
        template.setName("wizard-template");
        template.addActionListener(e -> { if (!loading) startFrom(String.valueOf(template.getSelectedItem())); });
        head1.add(new JLabel("Start from"));
        head1.add(template);
        head2.add(new JLabel("Name"));
        head2.add(name);
        head3.add(new JLabel("Display name"));
        head3.add(display);
        name.setName("wizard-name");
        name.addActionListener(e -> edited("name"));
        name.addFocusListener(new java.awt.event.FocusAdapter() {
            @Override public void focusLost(java.awt.event.FocusEvent e) { edited("name"); }
        });
        display.addActionListener(e -> edited("display name"));
        display.addFocusListener(new java.awt.event.FocusAdapter() {
            @Override public void focusLost(java.awt.event.FocusEvent e) { edited("display name"); }
        });

        jointTable.setName("wizard-joints");
        jointTable.setRowHeight(20);
        jointTable.getColumnModel().getColumn(1).setCellEditor(new DefaultCellEditor(new JComboBox<>(new String[] {"revolute", "prismatic"})));
        JPanel jointButtons = new JPanel(new WrapLayout(FlowLayout.LEFT, 4, 2));
        jointButtons.add(button("Add joint", "wizard-add", this::addJoint));
        jointButtons.add(button("Remove joint", "wizard-remove", () -> {
            int r = jointTable.getSelectedRow();
            if (r >= 0 && r < wm.jointCount()) removeJoint(r);
        }));
        // Undo and redo are the window's (Edit menu, toolbar, Ctrl+Z / Ctrl+Y): one history for every edit.
        jointButtons.add(new JLabel("revolute: deg, deg/s; prismatic: mm, mm/s; base coordinates, joints at zero"));
        JTable flangeTable = new FittingTable(flange);
        flangeTable.setName("wizard-flange");
        flangeTable.setRowHeight(20);
        JScrollPane fs = new JScrollPane(flangeTable);
        fs.setPreferredSize(new Dimension(400, 86));
        fs.setBorder(BorderFactory.createTitledBorder("Flange (tool0) at zero, base coordinates"));
        JPanel tables = new JPanel(new BorderLayout(4, 4));
        JScrollPane js = new JScrollPane(jointTable);
        js.setBorder(BorderFactory.createTitledBorder("Joints, base to flange"));
        tables.add(js, BorderLayout.CENTER);
        JPanel south = new JPanel(new BorderLayout());
        south.add(jointButtons, BorderLayout.NORTH);
        south.add(fs, BorderLayout.CENTER);
        error.setName("wizard-error");
        error.setForeground(new Color(0xC0, 0x20, 0x20));
        error.setBorder(BorderFactory.createEmptyBorder(2, 6, 2, 6));
        south.add(error, BorderLayout.SOUTH);
        tables.add(south, BorderLayout.SOUTH);

        report.setEditable(false);
        report.setName("wizard-report");
        report.setFont(new Font(Font.MONOSPACED, Font.PLAIN, 11));
        JScrollPane rs = new JScrollPane(report);
        rs.setBorder(BorderFactory.createTitledBorder("Model report: joint parameters and frames"));
        JSplitPane split = new JSplitPane(JSplitPane.VERTICAL_SPLIT, tables, rs);
        split.setResizeWeight(0.55);

        JPanel bottom = new JPanel(new GridLayout(1, 0, 6, 0));
        bottom.add(button("Save robot file...", "wizard-save", this::saveInteractive));
        bottom.add(button("Use in cell", "wizard-use", () -> useInCell(() -> true)));
        bottom.add(button("Close", "wizard-close", () -> owner.closeDock(this)));
        JPanel bp = new JPanel(new FlowLayout(FlowLayout.RIGHT));
        bp.add(bottom);

        JPanel content = new JPanel(new BorderLayout(4, 4));
        content.setBorder(BorderFactory.createEmptyBorder(6, 6, 6, 6));
        content.add(head, BorderLayout.NORTH);
        content.add(split, BorderLayout.CENTER);
        content.add(bp, BorderLayout.SOUTH);
        add(content, BorderLayout.CENTER);
        load();
    }

    /** The panel was closed: the cell's robot is drawn again instead of the model being built. */
    void closed() { wb.model().setPreview(null); }

    /** The panel is shown (again): the 3D view previews its model. */
    void opened() { if (wb.model().preview() == null) rebuild(); }

    private JButton button(String text, String id, Runnable r) {
        JButton b = new JButton(text);
        b.setName(id);
        b.addActionListener(e -> r.run());
        return b;
    }

    /**
     * Puts the wizard back to a state of its own (Edit &gt; Undo or Redo of one of its edits);
     * a closed wizard opens again so the user sees what was taken back.
     */
    private void applyState(RobotWizardModel.State s) {
        if (jointTable.isEditing()) jointTable.getCellEditor().cancelCellEditing();
        if (owner != null && !owner.isDocked(this)) owner.openWizard();
        wm.restore(s);
        shown = s;
        name.setText(s.name());
        display.setText(s.displayName());
        rebuild();
    }

    // ---- the UI layer tests drive ---------------------------------------------------------------

    public RobotWizardModel wizardModel() { return wm; }
    public RobotWizardModel.Result result() { return result; }
    public String errorText() { return error.getText().trim(); }
    public String reportText() { return report.getText(); }
    public JTable jointTable() { return jointTable; }

    /** Edits a joint cell as a user typing into the table does (column names as shown). */
    public void setJointCell(int row, String column, Object value) {
        int c = java.util.Arrays.asList(COLS).indexOf(column);
        if (c < 0) throw new IllegalArgumentException("no column " + column);
        joints.setValueAt(value, row, c);
    }

    /** Edits the flange: row 0 origin mm, 1 x axis, 2 z axis; column 0..2 = x, y, z. */
    public void setFlangeCell(int row, int xyz, double value) { flange.setValueAt(value, row, xyz + 1); }

    public void setRobotName(String n, String displayName) {
        name.setText(n);
        display.setText(displayName);
        edited("name");
    }

    public void addJoint() {
        editLabel = "add joint " + wm.addJoint().name();
        rebuild();
    }

    public void removeJoint(int row) {
        editLabel = "remove joint " + wm.joint(row).name();
        wm.removeJoint(row);
        rebuild();
    }

    private void edited(String what) {
        editLabel = what;
        rebuild();
    }

    /** Starts over from a shipped robot, the current one, or a single joint. */
    public void startFrom(String what) {
        if (what.startsWith("current")) wm = RobotWizardModel.from(wb.model().robot());
        else if (what.startsWith("empty")) {
            wm = new RobotWizardModel();
            wm.addJoint();
            wm.setFlange(new double[] {0, 0, 500}, new double[] {1, 0, 0}, new double[] {0, 0, 1});
        } else wm = RobotWizardModel.from(RobotLibrary.shipped(what));
        loading = true;
        template.setSelectedItem(what);
        loading = false;
        editLabel = "start from " + what;
        load();
    }

    private void load() {
        name.setText(wm.name());
        display.setText(wm.displayName());
        savedTo = null;
        rebuild();
    }

    /** Rebuilds the model from the wizard's fields; updates the 3D preview, report and error line. */
    public void rebuild() {
        wm.setName(name.getText());
        wm.setDisplayName(display.getText());
        RobotWizardModel.State now = wm.state();
        if (shown != null && !now.key().equals(shown.key()))
            wb.model().history().push("Robot model: " + (editLabel == null ? "edit" : editLabel), shown, now, editor);
        shown = now;
        editLabel = null;
        result = wm.build();
        joints.fireTableDataChanged();
        flange.fireTableDataChanged();
        if (result.ok()) {
            error.setText(" ");
            report.setText(result.report());
            report.setCaretPosition(0);
            wb.model().setPreview(new WorkbenchModel.ModelPreview(result.robot().orElseThrow(), result.framesAtZero()));
        } else {
            error.setText("Model not built: " + result.error());
            // The last good model stays in 3D and in the report, so one typo does not blank the view.
        }
    }

    private void saveInteractive() {
        if (!result.ok()) { JOptionPane.showMessageDialog(this, errorText(), "Cannot save", JOptionPane.ERROR_MESSAGE); return; }
        JFileChooser fc = new JFileChooser(new java.io.File("."));
        fc.setSelectedFile(new java.io.File(wm.name() + ".robot.json"));
        if (fc.showSaveDialog(this) != JFileChooser.APPROVE_OPTION) return;
        save(fc.getSelectedFile().toPath(), () -> JOptionPane.showConfirmDialog(this,
                fc.getSelectedFile() + " exists. Replace it?", "Save robot file", JOptionPane.YES_NO_OPTION) == JOptionPane.YES_OPTION);
    }

    /**
     * Writes the robot file atomically. An existing file is replaced only when
     * {@code confirmOverwrite} says yes; returns whether the file was written.
     */
    public boolean save(Path file, BooleanSupplier confirmOverwrite) {
        if (!result.ok()) { error.setText("Not saved: " + result.error()); return false; }
        RobotDescription d = result.robot().orElseThrow();
        try {
            RobotLibrary.write(d, file, false);
        } catch (InputException exists) {
            if (!java.nio.file.Files.exists(file)) throw exists;
            if (!confirmOverwrite.getAsBoolean()) { wb.log("Robot file not saved: " + file + " exists"); return false; }
            RobotLibrary.write(d, file, true);
        }
        savedTo = file;
        wb.log("Saved robot file " + file + " (" + wm.summary() + ")");
        return true;
    }

    /** Puts the built robot into the cell (saving it first next to the project if it was never saved). */
    public boolean useInCell(BooleanSupplier confirmOverwrite) {
        if (!result.ok()) { error.setText("Cannot use: " + result.error()); return false; }
        if (savedTo == null) {
            Path dir = wb.projectFile().map(p -> p.toAbsolutePath().getParent()).orElse(Path.of(".").toAbsolutePath());
            if (!save(dir.resolve(wm.name() + ".robot.json"), confirmOverwrite)) return false;
        }
        RobotDescription d = RobotLibrary.read(savedTo);
        wb.model().setPreview(null);
        wb.model().setRobot(savedTo.toAbsolutePath().toString(), d);
        wb.log("The cell now uses " + d.displayName() + " from " + savedTo);
        return true;
    }

    // ---- table models ------------------------------------------------------------------------

    private final class JointTable extends AbstractTableModel {
        @Override public int getRowCount() { return wm.jointCount(); }
        @Override public int getColumnCount() { return COLS.length; }
        @Override public String getColumnName(int c) { return COLS[c]; }
        @Override public boolean isCellEditable(int r, int c) { return true; }

        @Override
        public Object getValueAt(int r, int c) {
            JointRow j = wm.joint(r);
            return switch (c) {
                case 0 -> j.name();
                case 1 -> j.type() == JointType.REVOLUTE ? "revolute" : "prismatic";
                case 2, 3, 4 -> round(j.pointMm()[c - 2]);
                case 5, 6, 7 -> round(j.axis()[c - 5]);
                case 8 -> round(j.minDeg());
                case 9 -> round(j.maxDeg());
                default -> round(j.speedDegPerS());
            };
        }

        @Override
        public void setValueAt(Object v, int r, int c) {
            JointRow j = wm.joint(r);
            try {
                double x = c >= 2 ? Double.parseDouble(v.toString().trim()) : 0;
                double[] p = j.pointMm(), a = j.axis();
                if (c >= 2 && c <= 4) p[c - 2] = x;
                if (c >= 5 && c <= 7) a[c - 5] = x;
                JointType t = c == 1 ? (v.toString().startsWith("p") ? JointType.PRISMATIC : JointType.REVOLUTE) : j.type();
                wm.setJoint(r, new JointRow(c == 0 ? v.toString().trim() : j.name(), t, p, a, c == 8 ? x : j.minDeg(),
                        c == 9 ? x : j.maxDeg(), c == 10 ? x : j.speedDegPerS()));
                editLabel = j.name() + " " + COLS[c];
            } catch (NumberFormatException e) {
                error.setText("Not a number: '" + v + "' (" + COLS[c] + " of " + j.name() + ")");
                return;
            }
            rebuild();
        }
    }

    private final class FlangeTable extends AbstractTableModel {
        private final String[] rows = {"origin mm", "x axis", "z axis"};

        @Override public int getRowCount() { return 3; }
        @Override public int getColumnCount() { return 4; }
        @Override public String getColumnName(int c) { return c == 0 ? "" : "xyz".substring(c - 1, c); }
        @Override public boolean isCellEditable(int r, int c) { return c > 0; }

        @Override
        public Object getValueAt(int r, int c) {
            if (c == 0) return rows[r];
            double[] v = r == 0 ? wm.flangeOriginMm() : r == 1 ? wm.flangeX() : wm.flangeZ();
            return round(v[c - 1]);
        }

        @Override
        public void setValueAt(Object v, int r, int c) {
            double x;
            try {
                x = Double.parseDouble(v.toString().trim());
            } catch (NumberFormatException e) {
                error.setText("Not a number: '" + v + "' (flange " + rows[r] + ")");
                return;
            }
            double[] o = wm.flangeOriginMm(), xa = wm.flangeX(), za = wm.flangeZ();
            (r == 0 ? o : r == 1 ? xa : za)[c - 1] = x;
            wm.setFlange(o, xa, za);
            editLabel = "flange " + rows[r] + " " + getColumnName(c);
            rebuild();
        }
    }

    private static double round(double v) { return Math.round(v * 1e6) / 1e6; }
}
