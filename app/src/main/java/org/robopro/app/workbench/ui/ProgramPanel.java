package org.robopro.app.workbench.ui;

import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.Component;
import java.awt.FlowLayout;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import javax.swing.JButton;
import javax.swing.JComboBox;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JSlider;
import javax.swing.JSpinner;
import javax.swing.JTable;
import javax.swing.SpinnerNumberModel;
import javax.swing.Timer;
import javax.swing.table.AbstractTableModel;
import javax.swing.table.DefaultTableCellRenderer;
import org.robopro.app.workbench.WorkbenchSession;
import org.robopro.app.workbench.model.Instruction;
import org.robopro.app.workbench.model.ProgramRun;
import org.robopro.app.workbench.model.Target;
import org.robopro.programs.rapid.RapidAst;

/**
 * The program: instructions in a table (editable type, target, circle point, speed, zone; after
 * a check the path checker's problems per instruction, failing ones in red), buttons to teach
 * (in the chosen work object), add moves, reorder and check, and a timeline to play the
 * program back (the checked run's joint values).
 */
public final class ProgramPanel extends JPanel {
    private final WorkbenchSession wb;
    private final Rows rows = new Rows();
    private final FittingTable table = new FittingTable(rows);
    private final JSpinner speed = new JSpinner(new SpinnerNumberModel(500, 5, 7000, 50));
    private final JSpinner zone = new JSpinner(new SpinnerNumberModel(10, 0, 200, 5));
    private final JSlider timeline = new JSlider(0, 1000, 0);
    private final JLabel time = new JLabel("0.00 s");
    private final JButton play = new JButton("Play");
    private final JComboBox<String> wobj = new JComboBox<>();
    private boolean updatingWobjs;
    private final Timer player;
    private ProgramRun plan;
    private long playStart;
    private double playFrom;
    private boolean scrubbing;
    /** The program time (s) the timeline shows. */
    private double shownTime;

    public ProgramPanel(WorkbenchSession wb) {
        super(new BorderLayout(4, 4));
        this.wb = wb;
        table.setRowHeight(20);
        table.setDefaultRenderer(Object.class, new StatusRenderer());
        table.getColumnModel().getColumn(0).setMaxWidth(40);
        table.getColumnModel().getColumn(1).setCellEditor(new javax.swing.DefaultCellEditor(
                new JComboBox<>(new String[] {"MoveJ", "MoveL", "MoveC", "MoveAbsJ"})));
        table.getColumnModel().getColumn(6).setPreferredWidth(260);
        table.setName("program-table");
        wobj.setName("teach-wobj");
        wobj.addActionListener(e -> {
            Object w = wobj.getSelectedItem();
            if (!updatingWobjs && w != null && !w.equals(wb.model().activeWorkObject())) wb.model().setActiveWorkObject(w.toString());
        });
        add(new JScrollPane(table), BorderLayout.CENTER);
        JPanel buttons = new JPanel(new WrapLayout(FlowLayout.LEFT, 4, 2));
        buttons.add(button("Teach", "teach", e -> wb.teach()));
        buttons.add(new JLabel("in"));
        buttons.add(wobj);
        buttons.add(button("MoveJ", "add-movej", e -> addMove(Instruction.Type.MOVEJ)));
        buttons.add(button("MoveL", "add-movel", e -> addMove(Instruction.Type.MOVEL)));
        buttons.add(button("MoveC", "add-movec", e -> addMove(Instruction.Type.MOVEC)));
        buttons.add(button("Check", "check", e -> check()));
        buttons.add(new JLabel(" speed mm/s"));
        buttons.add(speed);
        buttons.add(new JLabel("zone mm"));
        buttons.add(zone);
        buttons.add(new JLabel(" "));
        buttons.add(button("Up", "move-up", e -> shift(-1)));
        buttons.add(button("Down", "move-down", e -> shift(1)));
        buttons.add(button("Remove", "remove-instruction", e -> remove()));
        add(buttons, BorderLayout.NORTH);
        JPanel tl = new JPanel(new BorderLayout(4, 0));
        play.setName("play");
        timeline.setName("timeline");
        time.setName("timeline-time");
        play.addActionListener(e -> togglePlay());
        tl.add(play, BorderLayout.WEST);
        tl.add(timeline, BorderLayout.CENTER);
        tl.add(time, BorderLayout.EAST);
        add(tl, BorderLayout.SOUTH);
        timeline.addChangeListener(e -> {
            if (scrubbing || plan == null || plan.sampleCount() == 0) return;
            showTime(plan.duration() * timeline.getValue() / 1000.0);
        });
        player = new Timer(30, e -> tick());
        refreshWobjs();
    }

    private JButton button(String text, String name, java.awt.event.ActionListener l) {
        JButton b = new JButton(text);
        b.setMargin(new java.awt.Insets(2, 6, 2, 6));
        b.setName(name);
        b.addActionListener(l);
        return b;
    }

    /** Adds a move to the selected target, or to the last taught one. */
    public void addMove(Instruction.Type type) {
        String sel = wb.model().selection();
        String target;
        if (sel != null && sel.startsWith("target:")) target = sel.substring(7);
        else {
            List<Target> ts = wb.model().targets();
            if (ts.isEmpty()) { wb.log("Teach a target first"); return; }
            target = ts.get(ts.size() - 1).name();
        }
        String via = null;
        if (type == Instruction.Type.MOVEC) {
            // MoveC goes through the target taught just before the end point.
            List<Target> ts = wb.model().targets();
            int at = -1;
            for (int i = 0; i < ts.size(); i++) if (ts.get(i).name().equals(target)) at = i;
            if (at < 1) { wb.log("MoveC needs a circle point: teach it before the end point"); return; }
            via = ts.get(at - 1).name();
        }
        wb.addMove(type, target, via, ((Number) speed.getValue()).doubleValue(), ((Number) zone.getValue()).doubleValue());
    }

    private void refreshWobjs() {
        updatingWobjs = true;
        try {
            wobj.removeAllItems();
            wobj.addItem(Target.WOBJ0);
            for (var w : wb.model().workObjects()) wobj.addItem(w.name());
            wobj.setSelectedItem(wb.model().activeWorkObject());
        } finally {
            updatingWobjs = false;
        }
    }

    private void shift(int d) {
        int r = table.getSelectedRow();
        List<Instruction> p = new ArrayList<>(wb.model().program());
        if (r < 0 || r + d < 0 || r + d >= p.size()) return;
        Instruction i = p.remove(r);
        p.add(r + d, i);
        wb.model().setProgram(p);
        table.getSelectionModel().setSelectionInterval(r + d, r + d);
    }

    private void remove() {
        int r = table.getSelectedRow();
        List<Instruction> p = new ArrayList<>(wb.model().program());
        if (r < 0 || r >= p.size()) return;
        p.remove(r);
        wb.model().setProgram(p);
    }

    /** Checks the program and shows the outcome per row. */
    public ProgramRun check() {
        plan = wb.checkProgram();
        showTimeline();
        rows.fireTableDataChanged();
        return plan;
    }

    private void togglePlay() {
        if (player.isRunning()) { stop(); return; }
        plan = wb.model().programRun();
        rows.fireTableDataChanged();
        if (plan.sampleCount() < 2) { wb.log("Nothing to play: the program needs two reachable moves"); return; }
        playFrom = timeline.getValue() >= 1000 ? 0 : plan.duration() * timeline.getValue() / 1000.0;
        playStart = System.nanoTime();
        play.setText("Stop");
        player.start();
    }

    private void stop() {
        player.stop();
        play.setText("Play");
    }

    private void tick() {
        double t = playFrom + (System.nanoTime() - playStart) / 1e9;
        if (t >= plan.duration()) { t = plan.duration(); stop(); }
        showTime(t);
    }

    /** Puts the robot where the program has it at time t (s). */
    public void showTime(double t) {
        if (plan == null) plan = wb.model().programRun();
        if (plan.sampleCount() == 0) return;
        wb.model().setQ(plan.qAtTime(t));
        shownTime = t;
        showTimeline();
    }

    /** The time label and the slider at the shown time of the current plan (its duration may have changed since). */
    private void showTimeline() {
        double d = plan == null ? 0 : plan.duration();
        double t = Math.max(0, Math.min(shownTime, d));
        time.setText(String.format(Locale.ROOT, "%.2f / %.2f s", t, d));
        scrubbing = true;
        timeline.setValue(d > 0 ? (int) Math.round(1000 * t / d) : 0);
        scrubbing = false;
    }

    /** The Check column as shown, one entry per row ("ok 0.42 s", "FAIL unreachable: ..."): what the user reads. */
    public List<String> checkColumn() {
        List<String> out = new ArrayList<>();
        for (int r = 0; r < rows.getRowCount(); r++) out.add(String.valueOf(rows.getValueAt(r, rows.getColumnCount() - 1)));
        return out;
    }

    /** The model's program changed. */
    public void refresh() {
        // Keep check results live once checked, from the background check (never computed on this thread).
        var latest = wb.pathChecker().latest();
        if (plan != null && !player.isRunning() && latest != null && latest.program().equals(wb.model().program())) {
            plan = latest.run();
            showTimeline();
        }
        refreshWobjs();
        rows.fireTableDataChanged();
    }

    private final class Rows extends AbstractTableModel {
        private final String[] cols = {"#", "Move", "Target", "Via", "Speed mm/s", "Zone mm", "Check"};

        @Override public int getRowCount() { return wb.model().program().size(); }
        @Override public int getColumnCount() { return cols.length; }
        @Override public String getColumnName(int c) { return cols[c]; }
        /** Motions are edited here; a statement kept from an imported module is shown read-only. */
        @Override public boolean isCellEditable(int r, int c) {
            List<Instruction> p = wb.model().program();
            return c >= 1 && c <= 5 && r < p.size() && p.get(r).type().motion();
        }

        @Override
        public Object getValueAt(int r, int c) {
            List<Instruction> p = wb.model().program();
            if (r >= p.size()) return "";
            Instruction i = p.get(r);
            if (c == 6) { // a kept call or loop shows the outcome of the motions it ran
                ProgramRun.Step s = step(r);
                return s == null ? "" : (!s.ok() ? "FAIL " : s.problems().isEmpty() ? "ok " : "warning ") + s.message();
            }
            if (!i.type().motion()) return c == 0 ? r + 1 : c == 1 ? "RAPID" : c == 2 ? i.statementText() : "";
            return switch (c) {
                case 0 -> r + 1;
                case 1 -> i.type().rapid();
                case 2 -> i.target();
                case 3 -> i.via() == null ? "" : i.via();
                case 4 -> i.speedMmPerS();
                default -> i.zoneMm();
            };
        }

        @Override
        public void setValueAt(Object v, int r, int c) {
            List<Instruction> p = new ArrayList<>(wb.model().program());
            Instruction i = p.get(r);
            try {
                Instruction n = switch (c) {
                    case 1 -> {
                        Instruction.Type t = Instruction.Type.ofRapid(v.toString());
                        String via = t != Instruction.Type.MOVEC ? null : i.via() != null ? i.via() : i.target();
                        yield new Instruction(t, i.target(), i.speedMmPerS(), i.zoneMm(), via);
                    }
                    case 2 -> new Instruction(i.type(), v.toString().trim(), i.speedMmPerS(), i.zoneMm(), i.via());
                    case 3 -> new Instruction(i.type(), i.target(), i.speedMmPerS(), i.zoneMm(), v.toString().trim());
                    case 4 -> new Instruction(i.type(), i.target(), Double.parseDouble(v.toString()), i.zoneMm(), i.via());
                    case 5 -> new Instruction(i.type(), i.target(), i.speedMmPerS(), Double.parseDouble(v.toString()), i.via());
                    default -> i;
                };
                if (n.equals(new Instruction(i.type(), i.target(), i.speedMmPerS(), i.zoneMm(), i.via()))) return; // unchanged: stays linked
                p.set(r, n);
                wb.model().setProgram(p);
                String dropped = unmodelledOptions(i.statement());
                if (!dropped.isEmpty())
                    wb.log("Line " + (r + 1) + " is rewritten in the workbench's terms on export: its RAPID option(s) " + dropped
                            + " are not written back (edit them in RAPID to keep them)");
            } catch (IllegalArgumentException e) {
                wb.log("Not changed: " + e.getMessage());
            }
        }
    }

    /** The optional arguments of an imported motion the workbench's own moves do not carry (all but {@code \WObj}), e.g. "\Conc, \V". */
    static String unmodelledOptions(RapidAst.Stmt statement) {
        if (!(statement instanceof RapidAst.Call call)) return "";
        List<String> out = new ArrayList<>();
        for (RapidAst.Arg a : call.args())
            if (a.kind() != RapidAst.ArgKind.POSITIONAL && a.kind() != RapidAst.ArgKind.NAMED && !"WObj".equalsIgnoreCase(a.name())) out.add("\\" + a.name());
        return String.join(", ", out);
    }

    private ProgramRun.Step step(int r) {
        return plan == null ? null : plan.line(r).orElse(null);
    }

    private final class StatusRenderer extends DefaultTableCellRenderer {
        @Override
        public Component getTableCellRendererComponent(JTable t, Object v, boolean sel, boolean focus, int r, int c) {
            Component comp = super.getTableCellRendererComponent(t, v, sel, focus, r, c);
            ProgramRun.Step s = step(r);
            if (!sel) comp.setForeground(s == null || s.problems().isEmpty() ? Color.BLACK
                    : s.ok() ? new Color(0xA0, 0x60, 0x00) : new Color(0xC0, 0x20, 0x20));
            if (comp instanceof javax.swing.JComponent jc && s != null && !s.problems().isEmpty())
                jc.setToolTipText("<html>" + String.join("<br>", s.problems().stream().map(p -> p.severity() + " " + p.message()).toList()));
            return comp;
        }
    }
}
