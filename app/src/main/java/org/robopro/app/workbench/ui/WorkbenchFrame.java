package org.robopro.app.workbench.ui;

import com.jme3.system.awt.AwtPanel;
import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.Font;
import java.awt.event.ActionEvent;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.awt.event.MouseWheelEvent;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.io.IOException;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.Consumer;
import javax.swing.AbstractAction;
import javax.swing.Action;
import javax.swing.BorderFactory;
import javax.swing.JCheckBoxMenuItem;
import javax.swing.JFileChooser;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;
import javax.swing.JOptionPane;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JSplitPane;
import javax.swing.JTabbedPane;
import javax.swing.JTextArea;
import javax.swing.JToolBar;
import javax.swing.KeyStroke;
import javax.swing.SwingUtilities;
import javax.swing.Timer;
import javax.swing.WindowConstants;
import org.robopro.app.workbench.WorkbenchSession;
import org.robopro.app.workbench.model.CellObject;
import org.robopro.app.workbench.model.Instruction;
import org.robopro.app.workbench.model.WorkbenchModel;
import org.robopro.app.workbench.scene.CameraState;
import org.robopro.app.workbench.scene.WorkbenchApp;
import org.robopro.kinematics.Pose;

/**
 * The workbench window: menus and toolbar, the cell tree on the left, the 3D view in the
 * middle with the program and log below it, properties and jogging on the right, a status bar.
 * Every menu entry is an {@link Action} reachable by id ({@link #action(String)}), so tests
 * drive the same code paths as a user.
 */
public final class WorkbenchFrame extends JFrame {

    private final WorkbenchSession wb;
    private final WorkbenchApp app;
    private final WindowOps window;
    private final Map<String, Action> actions = new LinkedHashMap<>();
    private final CellTree tree;
    private final PropertiesPanel properties;
    private final JogPanel jog;
    private final ProgramPanel program;
    private final JTextArea logArea = new JTextArea(6, 60);
    private final JLabel status = new JLabel(" ");
    private final AtomicBoolean refreshQueued = new AtomicBoolean();
    /** When the last refresh ran (System.nanoTime), for spacing joint-only refreshes. */
    private volatile long lastRefreshNanos;
    /**
     * Joint changes come at frame rate (jogging, playback); the jog panel's HTML labels cost the
     * event thread about as much as a frame costs the software rasteriser, so joint-only
     * refreshes run at most this often (docs/performance.md).
     */
    private static final long JOINT_REFRESH_NANOS = 50_000_000L;
    private volatile boolean robotChanged;
    private volatile boolean structureChanged = true;
    private volatile boolean selectionChanged;
    private volatile String lastError;
    private JSplitPane mainSplit;
    private JSplitPane midSplit;
    private final JTabbedPane dock = new JTabbedPane();
    private final Map<javax.swing.JComponent, Runnable> docked = new LinkedHashMap<>();

    /** What the frame asks of the window around it: a picture of itself, and closing everything. */
    public interface WindowOps {
        void screenshot(Path png) throws IOException, InterruptedException;
        void close();
    }

    public WorkbenchFrame(WorkbenchSession wb, WorkbenchApp app, AwtPanel view, WindowOps window) {
        super("robopro workbench");
        this.wb = wb;
        this.app = app;
        this.window = window;
        setDefaultCloseOperation(WindowConstants.DO_NOTHING_ON_CLOSE);
        addWindowListener(new WindowAdapter() {
            @Override public void windowClosing(WindowEvent e) { action("exit").actionPerformed(null); }
        });
        tree = new CellTree(wb.model());
        properties = new PropertiesPanel(wb);
        jog = new JogPanel(wb);
        program = new ProgramPanel(wb);
        defineActions();
        updateUndoActions();
        setJMenuBar(menus());

        view.setMinimumSize(new Dimension(100, 100));
        navigation(view);
        logArea.setEditable(false);
        logArea.setFont(new Font(Font.MONOSPACED, Font.PLAIN, 12));
        JTabbedPane bottom = new JTabbedPane();
        bottom.addTab("Program", program);
        bottom.addTab("Log", new JScrollPane(logArea));
        JSplitPane centre = new JSplitPane(JSplitPane.VERTICAL_SPLIT, view, bottom);
        centre.setResizeWeight(0.72);
        centre.setBorder(null);
        JScrollPane treeScroll = new JScrollPane(tree);
        treeScroll.setPreferredSize(new Dimension(210, 400));
        JSplitPane right = new JSplitPane(JSplitPane.VERTICAL_SPLIT, properties, jog);
        right.setResizeWeight(0.35);
        dock.setName("dock");
        dock.addTab("Properties", right);
        dock.setPreferredSize(new Dimension(330, 400));
        // Tool panels (calibration, robot wizard) dock here beside the 3D view, with a close button on their tab.
        dock.putClientProperty("JTabbedPane.tabCloseCallback", (java.util.function.IntConsumer) i -> {
            if (dock.getComponentAt(i) instanceof javax.swing.JComponent c) closeDock(c);
        });
        getRootPane().getInputMap(javax.swing.JComponent.WHEN_IN_FOCUSED_WINDOW).put(KeyStroke.getKeyStroke("ESCAPE"), "close-dock");
        getRootPane().getActionMap().put("close-dock", new AbstractAction() {
            @Override public void actionPerformed(ActionEvent e) {
                if (dock.getSelectedIndex() > 0 && dock.getSelectedComponent() instanceof javax.swing.JComponent c) closeDock(c);
            }
        });
        JSplitPane mid = new JSplitPane(JSplitPane.HORIZONTAL_SPLIT, centre, dock);
        mid.setResizeWeight(1);
        JSplitPane main = new JSplitPane(JSplitPane.HORIZONTAL_SPLIT, treeScroll, mid);
        mainSplit = main;
        midSplit = mid;
        main.setResizeWeight(0);
        JPanel content = new JPanel(new BorderLayout());
        content.add(toolbar(), BorderLayout.NORTH);
        content.add(main, BorderLayout.CENTER);
        status.setBorder(BorderFactory.createEmptyBorder(2, 6, 2, 6));
        content.add(status, BorderLayout.SOUTH);
        setContentPane(content);

        wb.model().addListener(this::modelChanged);
        wb.model().history().addListener(() -> SwingUtilities.invokeLater(this::updateUndoActions));
        wb.addLogListener(line -> SwingUtilities.invokeLater(() -> appendLog(line)));
        wb.pathChecker().addListener(r -> SwingUtilities.invokeLater(this::pathChecked));
        Timer statusTimer = new Timer(500, e -> updateStatus());
        statusTimer.setInitialDelay(50);
        statusTimer.start();
    }

    /** Sizes the window and places the split panes: tree 17 %, properties/jog 27 % of the width. */
    public void sizeTo(int width, int height) {
        setSize(width, height);
        validate(); // the split panes take divider locations only once they have their new size
        int tree = Math.max(170, (int) (width * 0.17));
        mainSplit.setDividerLocation(tree);
        placeDock();
        validate();
    }

    /** The dock's width: 27 % of the window for properties and jogging, 46 % while a tool panel is open. */
    private void placeDock() {
        int width = getWidth();
        int tree = mainSplit.getDividerLocation();
        int dockW = docked.isEmpty() ? Math.max(300, (int) (width * 0.27)) : Math.max(560, (int) (width * 0.46));
        midSplit.setDividerLocation(Math.max(300, width - tree - dockW));
    }

    /**
     * Shows {@code panel} as a tab of the dock beside the 3D view (added once, then selected);
     * {@code onClose} runs when it is closed (its tab's close button, Escape, or its own Close).
     */
    public void openDock(String title, javax.swing.JComponent panel, Runnable onClose) {
        if (!docked.containsKey(panel)) {
            docked.put(panel, onClose);
            panel.putClientProperty("JTabbedPane.tabClosable", true);
            dock.addTab(title, panel);
            placeDock();
        }
        dock.setSelectedComponent(panel);
        dock.revalidate();
    }

    /** Closes a docked panel; the dock narrows again when none is left. */
    public void closeDock(javax.swing.JComponent panel) {
        Runnable r = docked.remove(panel);
        if (r == null) return;
        dock.remove(panel);
        r.run();
        placeDock();
        dock.revalidate();
    }

    /** True while {@code panel} is docked. */
    public boolean isDocked(javax.swing.JComponent panel) { return docked.containsKey(panel); }

    public Action action(String id) {
        Action a = actions.get(id);
        if (a == null) throw new IllegalArgumentException("no action " + id + "; known: " + actions.keySet());
        return a;
    }

    /** The message of the last error dialog (tests read it; under robopro.test no modal dialog opens). */
    public String lastError() { return lastError; }

    /** Shows an error: a modal dialog for a user, only the log and {@link #lastError()} under tests. */
    public void showError(String title, String message) {
        lastError = message;
        wb.log(title + ": " + message);
        if (isShowing() && System.getenv("robopro.test") == null)
            JOptionPane.showMessageDialog(this, message, title, JOptionPane.ERROR_MESSAGE);
    }

    /**
     * File > Import RAPID: replaces the program with the module's main; a file with errors is
     * shown in a dialog with its line and column and changes nothing.
     */
    /** Asks which procedure of an uploaded module becomes the program (main preselected); null when cancelled. */
    String chooseProcedure(java.util.List<String> procs) {
        return (String) JOptionPane.showInputDialog(this, "The module has " + procs.size() + " procedures. Which one is the program?",
                "Upload program: PROC", JOptionPane.QUESTION_MESSAGE, null, procs.toArray(), WorkbenchSession.defaultProcedure(procs));
    }

    public boolean importRapid(Path file) {
        try {
            var imp = wb.importRapid(file);
            if (!imp.notes().isEmpty() && isShowing() && System.getenv("robopro.test") == null)
                JOptionPane.showMessageDialog(this, String.join("\n", imp.notes()), "RAPID import", JOptionPane.INFORMATION_MESSAGE);
            return true;
        } catch (org.robopro.models.InputException e) {
            showError("RAPID import failed", e.file() + "\nline " + e.line() + ", column " + e.column()
                    + (e.field() == null || e.field().isEmpty() ? "" : " (" + e.field() + ")") + ":\n" + e.problem());
            return false;
        } catch (IOException e) {
            showError("RAPID import failed", "cannot read " + file + ": " + e.getMessage());
            return false;
        }
    }

    private RobotWizard wizard;
    private CalibrationPanel calibration;

    /** Opens (or brings to front) the calibration panel, docked beside the 3D view. */
    public CalibrationPanel openCalibration() {
        if (calibration == null || !isDocked(calibration)) calibration = new CalibrationPanel(this, wb);
        openDock("Calibration", calibration, () -> { });
        return calibration;
    }

    /**
     * Opens (or brings to front) the robot model wizard, docked beside the 3D view whose preview
     * it drives. The one wizard keeps its robot while closed, so its edits in the undo history
     * can still be taken back (which opens it again).
     */
    public RobotWizard openWizard() {
        if (wizard == null) wizard = new RobotWizard(this, wb);
        openDock("Robot model", wizard, wizard::closed);
        wizard.opened();
        return wizard;
    }

    public JogPanel jogPanel() { return jog; }
    public ProgramPanel programPanel() { return program; }
    public CellTree cellTree() { return tree; }
    public PropertiesPanel propertiesPanel() { return properties; }

    public void appendLog(String line) {
        logArea.append(line + "\n");
        logArea.setCaretPosition(logArea.getDocument().getLength());
        status.setToolTipText(line);
    }

    private void modelChanged(WorkbenchModel.Change c) {
        if (c == WorkbenchModel.Change.ROBOT) robotChanged = true;
        // Joint changes (jogging, playback) come at frame rate: they only touch the jog panel.
        if (c == WorkbenchModel.Change.SELECTION || c == WorkbenchModel.Change.VIEW) selectionChanged = true;
        else if (c != WorkbenchModel.Change.JOINTS) structureChanged = true;
        if (!refreshQueued.compareAndSet(false, true)) return;
        long wait = c == WorkbenchModel.Change.JOINTS ? lastRefreshNanos + JOINT_REFRESH_NANOS - System.nanoTime() : 0;
        if (wait <= 0) {
            SwingUtilities.invokeLater(this::refresh);
        } else {
            Timer later = new Timer((int) Math.max(1, wait / 1_000_000L), e -> refresh());
            later.setRepeats(false);
            later.start();
        }
    }

    private void refresh() {
        refreshQueued.set(false);
        lastRefreshNanos = System.nanoTime();
        if (robotChanged) { robotChanged = false; jog.rebuild(); }
        jog.refresh();
        String sel = wb.model().selection();
        if (!structureChanged) {
            if (selectionChanged) {
                selectionChanged = false;
                tree.showSelection();
                properties.refresh();
            } else if (sel != null && sel.startsWith("link:")) {
                properties.refresh();
            }
            return;
        }
        selectionChanged = false;
        structureChanged = false;
        tree.rebuild(latestStatuses());
        properties.refresh();
        program.refresh();
        updateUndoActions();
        updateTitle();
    }

    /** Target statuses of the last background path check (none before the first). */
    private Map<String, org.robopro.app.workbench.model.TargetStatus> latestStatuses() {
        var r = wb.pathChecker().latest();
        return r == null ? Map.of() : r.statuses();
    }

    /** A background path check finished: show its statuses and per-instruction results. */
    private void pathChecked() {
        tree.rebuild(latestStatuses());
        program.refresh();
    }

    private void updateTitle() {
        String name = wb.projectFile().map(p -> p.getFileName().toString()).orElse("IRB-2000 welding cell (unsaved)");
        setTitle((wb.model().dirty() ? "* " : "") + name + " - robopro workbench");
    }

    /** Updates the status line now (screenshots; otherwise a timer does it twice a second). */
    public void refreshStatus() { updateStatus(); }

    private void updateStatus() {
        Pose p = wb.model().worldTtcp();
        double fps = app.fps();
        String clearance = wb.clearance().current().map(r -> "  |  " + r.text()).orElse("");
        status.setText(String.format(Locale.ROOT, "%s  |  TCP %.1f, %.1f, %.1f mm%s  |  %d targets, %d moves  |  %s",
                wb.model().robot().displayName(), p.x() * 1000, p.y() * 1000, p.z() * 1000, clearance, wb.model().targets().size(),
                wb.model().program().stream().filter(i -> i.type().motion()).count(), fps > 0 ? String.format(Locale.ROOT, "%.0f fps", fps) : "3D view starting"));
        updateTitle();
    }

    // ---- actions and menus ------------------------------------------------------------------

    private Action def(String id, String name, String key, Consumer<ActionEvent> body) {
        Action a = new AbstractAction(name) {
            @Override public void actionPerformed(ActionEvent e) {
                try {
                    body.accept(e);
                } catch (RuntimeException ex) {
                    showError(name + " failed", String.valueOf(ex.getMessage()));
                }
            }
        };
        if (key != null) a.putValue(Action.ACCELERATOR_KEY, KeyStroke.getKeyStroke(key));
        a.putValue(Action.ACTION_COMMAND_KEY, id);
        actions.put(id, a);
        return a;
    }

    /** Controller actions are enabled only while connected. */
    private void controllerChanged() {
        boolean on = wb.controller().isPresent();
        for (String id : new String[] {"disconnect", "download", "upload", "run", "read-position"})
            if (actions.containsKey(id)) action(id).setEnabled(on);
    }

    private interface IoAction { void run() throws IOException; }

    private void io(IoAction a) {
        try {
            a.run();
        } catch (IOException e) {
            throw new IllegalStateException(e.getMessage(), e);
        }
    }

    private Path choose(boolean save, String suffix) {
        JFileChooser fc = new JFileChooser(wb.projectFile().map(p -> p.toAbsolutePath().getParent().toFile()).orElse(new java.io.File(".")));
        int r = save ? fc.showSaveDialog(this) : fc.showOpenDialog(this);
        if (r != JFileChooser.APPROVE_OPTION) return null;
        Path p = fc.getSelectedFile().toPath();
        if (save && suffix != null && !p.getFileName().toString().contains(".")) p = p.resolveSibling(p.getFileName() + suffix);
        return p;
    }

    /**
     * Before the open cell is replaced: with unsaved changes asks whether to save them; false
     * when the user cancels (or saving failed). Under tests (no visible window) it never asks.
     */
    private boolean changesHandled() {
        if (!wb.model().dirty() || !isShowing() || System.getenv("robopro.test") != null) return true;
        int r = JOptionPane.showConfirmDialog(this, "Save changes to the open project first?", "robopro", JOptionPane.YES_NO_CANCEL_OPTION);
        if (r == JOptionPane.CANCEL_OPTION || r == JOptionPane.CLOSED_OPTION) return false;
        if (r == JOptionPane.YES_OPTION) { action("save").actionPerformed(null); return !wb.model().dirty(); }
        return true;
    }

    /** Undo / Redo name the edit they act on and are enabled only when there is one. */
    private void updateUndoActions() {
        var h = wb.model().history();
        Action u = action("undo"), r = action("redo");
        u.putValue(Action.NAME, h.undoLabel().map(l -> "Undo " + l).orElse("Undo"));
        u.putValue(Action.SHORT_DESCRIPTION, u.getValue(Action.NAME) + " (Ctrl+Z)");
        u.setEnabled(h.undoLabel().isPresent());
        r.putValue(Action.NAME, h.redoLabel().map(l -> "Redo " + l).orElse("Redo"));
        r.putValue(Action.SHORT_DESCRIPTION, r.getValue(Action.NAME) + " (Ctrl+Y)");
        r.setEnabled(h.redoLabel().isPresent());
    }

    private void defineActions() {
        def("new", "New project", "ctrl N", e -> { if (changesHandled()) wb.newProject(); });
        def("open", "Open project...", "ctrl O", e -> {
            if (!changesHandled()) return;
            Path p = choose(false, null);
            if (p != null) io(() -> wb.openProject(p));
        });
        def("undo", "Undo", "ctrl Z", e -> wb.undo());
        def("redo", "Redo", "ctrl Y", e -> wb.redo());
        // Ctrl+Shift+Z redoes as well (the other common binding).
        getRootPane().getInputMap(javax.swing.JComponent.WHEN_IN_FOCUSED_WINDOW).put(KeyStroke.getKeyStroke("ctrl shift Z"), "redo");
        getRootPane().getActionMap().put("redo", action("redo"));
        def("save", "Save project", "ctrl S", e -> {
            Path p = wb.projectFile().orElseGet(() -> choose(true, ".robopro.json"));
            if (p != null) io(() -> wb.save(p));
        });
        def("save-as", "Save project as...", "ctrl shift S", e -> {
            Path p = choose(true, ".robopro.json");
            if (p != null) io(() -> wb.save(p));
        });
        def("export-rapid", "Export RAPID...", "ctrl E", e -> {
            Path p = choose(true, ".mod");
            if (p != null) io(() -> wb.exportRapid(p, true));
        });
        def("import-rapid", "Import RAPID...", "ctrl I", e -> {
            Path p = choose(false, null);
            if (p != null) importRapid(p);
        });
        def("screenshot", "Save screenshot...", null, e -> {
            Path p = choose(true, ".png");
            if (p != null) new Thread(() -> {
                try { window.screenshot(p); wb.log("Screenshot " + p); } catch (Exception ex) { wb.log("Screenshot failed: " + ex); }
            }, "screenshot").start();
        });
        def("exit", "Exit", "ctrl Q", e -> {
            if (wb.model().dirty() && isShowing()) {
                int r = JOptionPane.showConfirmDialog(this, "Save changes before closing?", "robopro", JOptionPane.YES_NO_CANCEL_OPTION);
                if (r == JOptionPane.CANCEL_OPTION || r == JOptionPane.CLOSED_OPTION) return;
                if (r == JOptionPane.YES_OPTION) { action("save").actionPerformed(null); if (wb.model().dirty()) return; }
            }
            new Thread(() -> { window.close(); System.exit(0); }, "exit").start();
        });
        def("add-table", "Add table", null, e -> wb.addObject(CellObject.Kind.TABLE));
        def("add-fixture", "Add fixture", null, e -> wb.addObject(CellObject.Kind.FIXTURE));
        def("add-part", "Add part", null, e -> wb.addObject(CellObject.Kind.PART));
        def("import-mesh", "Import mesh (STL, OBJ, glTF)...", null, e -> {
            Path p = choose(false, null);
            if (p == null) return;
            String s = JOptionPane.showInputDialog(this, "Scale to metres (0.001 for a mesh in mm):", "0.001");
            if (s != null) wb.importMesh(p, Double.parseDouble(s));
        });
        def("delete", "Delete selection", "DELETE", e -> wb.deleteSelection());
        def("edit-tool", "Tool...", null, e -> wb.model().select("tool"));
        def("view-front", "Front view", "F1", e -> app.camera().view(CameraState.View.FRONT));
        def("view-top", "Top view", "F2", e -> app.camera().view(CameraState.View.TOP));
        def("view-side", "Side view", "F3", e -> app.camera().view(CameraState.View.SIDE));
        def("view-iso", "Isometric view", "F4", e -> app.camera().view(CameraState.View.ISO));
        def("show-frames", "Show frames (joint axes)", null, e -> wb.model().setShowFrames(!wb.model().showFrames()));
        def("show-path", "Show targets and path", null, e -> wb.model().setShowPath(!wb.model().showPath()));
        def("show-shadows", "Shadows", null, e -> wb.model().setShadows(!wb.model().shadows()));
        def("teach", "Teach target", "ctrl T", e -> wb.teach());
        def("add-movej", "Add MoveJ", null, e -> program.addMove(Instruction.Type.MOVEJ));
        def("add-movel", "Add MoveL", null, e -> program.addMove(Instruction.Type.MOVEL));
        def("add-movec", "Add MoveC (through the target taught before)", null, e -> program.addMove(Instruction.Type.MOVEC));
        def("check", "Check program", "ctrl K", e -> program.check());
        def("connect", "Connect to controller...", null, e -> {
            String a = JOptionPane.showInputDialog(this, "Controller address: host:port (TCP) or a serial device.\n"
                    + "Leave empty to start the simulated controller.", "");
            if (a != null) wb.connectController(a);
        });
        def("disconnect", "Disconnect", null, e -> wb.disconnectController());
        def("download", "Download program", null, e -> wb.downloadProgram());
        def("upload", "Upload program...", null, e -> wb.controllerPrograms().whenComplete((list, err) -> SwingUtilities.invokeLater(() -> {
            // Offer the controller's programs; type a name when it cannot list them (plain SERVER.mod).
            String n;
            if (err == null && list != null && !list.isEmpty()) {
                Object[] names = list.stream().map(org.robopro.comms.ProgramInfo::name).toArray();
                Object def = java.util.Arrays.asList(names).contains(wb.controllerProgramName()) ? wb.controllerProgramName() : names[0];
                n = (String) JOptionPane.showInputDialog(this, "Program on the controller:", "Upload program",
                        JOptionPane.QUESTION_MESSAGE, null, names, def);
            } else {
                n = JOptionPane.showInputDialog(this, "Program name on the controller:", wb.controllerProgramName());
            }
            if (n != null && !n.isBlank()) wb.uploadProgram(n.trim(), this::chooseProcedure);
        })));
        def("run", "Run on controller", null, e -> wb.runProgram());
        def("read-position", "Read robot position", null, e -> wb.readRobotPosition());
        wb.addControllerListener(() -> SwingUtilities.invokeLater(this::controllerChanged));
        controllerChanged();
        def("calibration", "Calibration panel...", null, e -> openCalibration());
        def("robot-wizard", "Robot model wizard...", null, e -> openWizard());
        def("about", "About", null, e -> JOptionPane.showMessageDialog(this,
                "robopro workbench\nOff-line programming and calibration of industrial robots.\n"
                        + "Left drag: orbit, right/middle drag: pan, wheel: zoom, click: select.", "About", JOptionPane.INFORMATION_MESSAGE));
    }

    private JMenu menu(String name, int mnemonic, String... ids) {
        JMenu m = new JMenu(name);
        m.setMnemonic(mnemonic);
        for (String id : ids) {
            if (id == null) { m.addSeparator(); continue; }
            Action a = action(id);
            JMenuItem it = id.startsWith("show-") ? new JCheckBoxMenuItem(a) : new JMenuItem(a);
            if (id.equals("show-path")) it.setSelected(true);
            it.setName("menu-" + id);
            if (a.getValue(Action.SHORT_DESCRIPTION) != null) it.setToolTipText((String) a.getValue(Action.SHORT_DESCRIPTION));
            m.add(it);
        }
        return m;
    }

    /**
     * View: the standard views, the frames (all of the robot's at once, or each kind on its own
     * in the Frames submenu), targets and path, shadows; the check marks follow the model each
     * time the menu opens.
     */
    private JMenu viewMenu() {
        JMenu view = menu("View", KeyEvent.VK_V, "view-front", "view-top", "view-side", "view-iso", null, "show-frames");
        JMenu frames = new JMenu("Frames");
        frames.setName("menu-frames");
        java.util.Map<WorkbenchModel.FrameKind, JCheckBoxMenuItem> items = new java.util.EnumMap<>(WorkbenchModel.FrameKind.class);
        for (WorkbenchModel.FrameKind k : WorkbenchModel.FrameKind.values()) {
            JCheckBoxMenuItem it = new JCheckBoxMenuItem(k.label());
            it.setName("menu-frame-" + k.name().toLowerCase(java.util.Locale.ROOT));
            it.addActionListener(e -> wb.model().setFrameShown(k, it.isSelected()));
            items.put(k, it);
            frames.add(it);
        }
        view.add(frames);
        for (String id : new String[] {"show-path", "show-shadows"}) {
            JCheckBoxMenuItem it = new JCheckBoxMenuItem(action(id));
            it.setName("menu-" + id);
            view.add(it);
        }
        view.addMenuListener(new javax.swing.event.MenuListener() {
            @Override public void menuSelected(javax.swing.event.MenuEvent e) {
                WorkbenchModel m = wb.model();
                for (var en : items.entrySet()) en.getValue().setSelected(m.frameShown(en.getKey()));
                for (java.awt.Component c : view.getMenuComponents()) {
                    if (!(c instanceof JCheckBoxMenuItem it) || it.getName() == null) continue;
                    switch (it.getName()) {
                        case "menu-show-frames" -> it.setSelected(m.showFrames());
                        case "menu-show-path" -> it.setSelected(m.showPath());
                        case "menu-show-shadows" -> it.setSelected(m.shadows());
                        default -> { }
                    }
                }
            }
            @Override public void menuDeselected(javax.swing.event.MenuEvent e) { }
            @Override public void menuCanceled(javax.swing.event.MenuEvent e) { }
        });
        return view;
    }

    private JMenuBar menus() {
        JMenuBar bar = new JMenuBar();
        bar.add(menu("File", KeyEvent.VK_F, "new", "open", "save", "save-as", null, "import-rapid", "export-rapid", "screenshot", null, "exit"));
        bar.add(menu("Edit", KeyEvent.VK_E, "undo", "redo", null, "delete"));
        bar.add(menu("Cell", KeyEvent.VK_C, "add-table", "add-fixture", "add-part", "import-mesh", null, "edit-tool", "robot-wizard", null, "delete"));
        bar.add(viewMenu());
        bar.add(menu("Program", KeyEvent.VK_P, "teach", "add-movej", "add-movel", "add-movec", null, "check", "import-rapid", "export-rapid"));
        bar.add(menu("Controller", KeyEvent.VK_R, "connect", "disconnect", null, "download", "upload", "run", null, "read-position"));
        bar.add(menu("Calibration", KeyEvent.VK_A, "calibration"));
        bar.add(menu("Help", KeyEvent.VK_H, "about"));
        return bar;
    }

    private JToolBar toolbar() {
        JToolBar t = new JToolBar();
        t.setFloatable(false);
        for (String id : new String[] {"open", "save", null, "undo", "redo", null, "view-front", "view-top", "view-side", "view-iso", null,
                "add-table", "add-part", "delete", null, "teach", "add-movej", "add-movel", "check", "export-rapid", null, "connect", "calibration"}) {
            if (id == null) { t.addSeparator(); continue; }
            var b = t.add(action(id));
            b.setName("tool-" + id);
            b.setHideActionText(true); // the short name stays when the action renames itself ("Undo Add table")
            b.setText(shortName(id));
            if (action(id).getValue(Action.SHORT_DESCRIPTION) != null) b.setToolTipText((String) action(id).getValue(Action.SHORT_DESCRIPTION));
        }
        return t;
    }

    private static String shortName(String id) {
        return switch (id) {
            case "open" -> "Open"; case "save" -> "Save"; case "undo" -> "Undo"; case "redo" -> "Redo";
            case "view-front" -> "Front"; case "view-top" -> "Top"; case "view-side" -> "Side"; case "view-iso" -> "Iso";
            case "add-table" -> "+Table"; case "add-part" -> "+Part"; case "delete" -> "Delete";
            case "teach" -> "Teach"; case "add-movej" -> "MoveJ"; case "add-movel" -> "MoveL"; case "check" -> "Check";
            case "export-rapid" -> "RAPID"; case "connect" -> "Connect"; case "calibration" -> "Calibrate";
            default -> id;
        };
    }

    /** Mouse navigation on the 3D view: left drag orbits, right or middle drag pans, the wheel zooms, a click selects. */
    private void navigation(AwtPanel view) {
        MouseAdapter m = new MouseAdapter() {
            private int lx, ly, px, py;
            private boolean dragged;

            @Override public void mousePressed(MouseEvent e) { lx = px = e.getX(); ly = py = e.getY(); dragged = false; }

            @Override
            public void mouseDragged(MouseEvent e) {
                int dx = e.getX() - lx, dy = e.getY() - ly;
                lx = e.getX();
                ly = e.getY();
                if (Math.abs(e.getX() - px) + Math.abs(e.getY() - py) > 3) dragged = true;
                double h = Math.max(1, view.getHeight());
                if ((e.getModifiersEx() & (InputEvent.BUTTON3_DOWN_MASK | InputEvent.BUTTON2_DOWN_MASK)) != 0
                        || e.isShiftDown()) app.camera().pan(dx / h, dy / h);
                else app.camera().orbit(-dx * 0.01, dy * 0.01);
            }

            @Override
            public void mouseReleased(MouseEvent e) {
                if (dragged || e.getButton() != MouseEvent.BUTTON1) return;
                app.pick(e.getX(), e.getY()).thenAccept(k -> SwingUtilities.invokeLater(() -> wb.model().select(k)));
            }

            @Override public void mouseWheelMoved(MouseWheelEvent e) { app.camera().zoom(Math.pow(1.12, e.getPreciseWheelRotation())); }
        };
        view.addMouseListener(m);
        view.addMouseMotionListener(m);
        view.addMouseWheelListener(m);
    }
}
