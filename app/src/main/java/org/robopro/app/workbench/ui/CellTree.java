package org.robopro.app.workbench.ui;

import java.util.Enumeration;
import javax.swing.JTree;
import javax.swing.tree.DefaultMutableTreeNode;
import javax.swing.tree.DefaultTreeModel;
import javax.swing.tree.TreePath;
import org.robopro.app.workbench.model.CellObject;
import org.robopro.app.workbench.model.Instruction;
import org.robopro.app.workbench.model.Target;
import org.robopro.app.workbench.model.TargetStatus;
import org.robopro.app.workbench.model.WorkObject;
import org.robopro.app.workbench.model.WorkbenchModel;

/**
 * The cell as a tree, after the seed paper's "graphic tree": the robot's links nested base to
 * flange and tool, the cell objects, work objects, targets (with their reachability) and the
 * program. Selecting a node selects the thing in the 3D view and the properties panel.
 */
public final class CellTree extends JTree {
    /** A tree entry: its label and selection key. */
    public record Item(String label, String key) {
        @Override public String toString() { return label; }
    }

    private final WorkbenchModel model;
    private boolean updating;

    public CellTree(WorkbenchModel model) {
        super(new DefaultTreeModel(new DefaultMutableTreeNode("Cell")));
        this.model = model;
        setName("cell-tree");
        setRootVisible(true);
        addTreeSelectionListener(e -> {
            if (updating) return;
            TreePath p = e.getNewLeadSelectionPath();
            if (p == null) return;
            Object u = ((DefaultMutableTreeNode) p.getLastPathComponent()).getUserObject();
            if (u instanceof Item it && it.key() != null) model.select(it.key());
        });
        rebuild(java.util.Map.of());
    }

    /** Rebuilds from the model; {@code status} marks unreachable targets. */
    public void rebuild(java.util.Map<String, TargetStatus> status) {
        updating = true;
        try {
            DefaultMutableTreeNode root = new DefaultMutableTreeNode(new Item("Cell", null));
            String shown = model.robot().displayName().length() <= 22 ? model.robot().displayName() : model.robot().name();
            DefaultMutableTreeNode robot = new DefaultMutableTreeNode(new Item("Robot: " + shown, "link:0"));
            root.add(robot);
            // The links in chain order, one level deep (a nested chain pushes the last links' labels off the column).
            robot.add(new DefaultMutableTreeNode(new Item("base", "link:0")));
            for (int i = 1; i <= model.robot().dof(); i++)
                robot.add(new DefaultMutableTreeNode(new Item("link " + i + " (" + model.robot().joints().get(i - 1).name() + ")", "link:" + i)));
            robot.add(new DefaultMutableTreeNode(new Item("tool: " + model.tool().name(), "tool")));
            DefaultMutableTreeNode objs = new DefaultMutableTreeNode(new Item("Objects", null));
            for (CellObject o : model.objects()) objs.add(new DefaultMutableTreeNode(new Item(o.name() + " [" + o.id() + "]", "object:" + o.id())));
            root.add(objs);
            DefaultMutableTreeNode wobjs = new DefaultMutableTreeNode(new Item("Work objects", null));
            wobjs.add(new DefaultMutableTreeNode(new Item("wobj0 (world)", null)));
            for (WorkObject w : model.workObjects()) wobjs.add(new DefaultMutableTreeNode(new Item(w.name(), null)));
            root.add(wobjs);
            DefaultMutableTreeNode targets = new DefaultMutableTreeNode(new Item("Targets", null));
            for (Target t : model.targets()) {
                TargetStatus s = status.get(t.name());
                String mark = s == null || s.ok() ? "" : switch (s) {
                    case UNREACHABLE -> " (out of reach)";
                    case OUTSIDE_LIMITS -> " (outside limits)";
                    default -> " (path problem)";
                };
                targets.add(new DefaultMutableTreeNode(new Item(t.name() + mark, "target:" + t.name())));
            }
            root.add(targets);
            DefaultMutableTreeNode prog = new DefaultMutableTreeNode(new Item("Program " + model.programSource().map(org.robopro.app.workbench.model.ProgramModule.Source::entry).orElse("main"), null));
            for (Instruction i : model.program())
                prog.add(new DefaultMutableTreeNode(!i.type().motion() ? new Item(i.statementText(), null)
                        : new Item(i.type().rapid() + " " + (i.via() != null ? i.via() + ", " : "") + i.target(), "target:" + i.target())));
            root.add(prog);
            ((DefaultTreeModel) getModel()).setRoot(root);
            for (int r = 0; r < getRowCount() && r < 60; r++) expandRow(r);
            showSelection();
        } finally {
            updating = false;
        }
    }

    /** Highlights the model's selection in the tree. */
    public void showSelection() {
        String key = model.selection();
        boolean was = updating;
        updating = true;
        try {
            if (key == null) { clearSelection(); return; }
            DefaultMutableTreeNode root = (DefaultMutableTreeNode) getModel().getRoot();
            for (Enumeration<?> e = root.depthFirstEnumeration(); e.hasMoreElements(); ) {
                DefaultMutableTreeNode n = (DefaultMutableTreeNode) e.nextElement();
                if (n.getUserObject() instanceof Item it && key.equals(it.key()) && !it.label().startsWith("Robot")) {
                    TreePath p = new TreePath(n.getPath());
                    setSelectionPath(p);
                    scrollPathToVisible(p);
                    return;
                }
            }
        } finally {
            updating = was;
        }
    }
}
