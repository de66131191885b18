package org.robopro.app.workbench.ui;

import java.awt.Component;
import java.awt.Container;
import java.awt.Rectangle;
import java.util.ArrayList;
import java.util.List;
import javax.swing.AbstractButton;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JMenuItem;
import javax.swing.JScrollBar;
import javax.swing.JSpinner;
import javax.swing.JSplitPane;
import javax.swing.JTable;
import javax.swing.JTree;
import javax.swing.JViewport;
import javax.swing.table.TableCellRenderer;
import javax.swing.table.TableColumn;

/**
 * Finds what a user could not read or reach in a window: buttons narrower than their text or
 * cut off by their container, table columns narrower than their header, labels shortened to
 * "…", tree rows running past the visible width. Call on the Swing thread.
 */
public final class LayoutCheck {
    private LayoutCheck() { }

    /** One line per clipped component; empty when everything fits. */
    public static List<String> clipped(Container root) {
        List<String> out = new ArrayList<>();
        walk(root, out);
        return out;
    }

    private static void walk(Component c, List<String> out) {
        if (!c.isShowing()) return;
        if (c instanceof JComponent j) check(j, out);
        if (c instanceof Container k) for (Component ch : k.getComponents()) walk(ch, out);
    }

    private static boolean internal(Component c) {
        Container p = c.getParent();
        return p instanceof JComboBox || p instanceof JSpinner || p instanceof JScrollBar || p instanceof JSplitPane
                || c.getClass().getName().contains("Arrow") || c.getClass().getName().contains("$") && !(c instanceof JTable);
    }

    private static String name(Component c) {
        String text = c instanceof AbstractButton b ? b.getText() : c instanceof JLabel l ? l.getText() : null;
        return c.getClass().getSimpleName() + (c.getName() != null ? " " + c.getName() : "") + (text != null ? " '" + text + "'" : "");
    }

    private static void check(JComponent c, List<String> out) {
        if (c instanceof AbstractButton b && !(c instanceof JMenuItem) && !internal(c)) {
            Rectangle v = b.getVisibleRect();
            if (b.getWidth() + 1 < b.getPreferredSize().width)
                out.add(name(b) + ": " + b.getWidth() + " px wide, needs " + b.getPreferredSize().width);
            else if (!inScrolledView(b) && (v.width + 1 < b.getWidth() || v.height + 1 < b.getHeight()))
                out.add(name(b) + ": only " + v.width + "x" + v.height + " of " + b.getWidth() + "x" + b.getHeight() + " visible");
        }
        if ((c instanceof javax.swing.JTextField || c instanceof JComboBox || c instanceof JSpinner) && !internal(c) && !inScrolledView(c)) {
            Rectangle v = c.getVisibleRect();
            if (v.width + 1 < c.getWidth() || v.height + 1 < c.getHeight() || c.getWidth() < 12)
                out.add(name(c) + ": only " + v.width + "x" + v.height + " of " + c.getWidth() + "x" + c.getHeight() + " visible");
        }
        if (c instanceof JLabel l && l.getText() != null && !l.getText().isBlank() && !internal(c)
                && l.getWidth() + 1 < l.getPreferredSize().width && !inScrolledView(l))
            out.add(name(l) + ": " + l.getWidth() + " px wide, needs " + l.getPreferredSize().width);
        if (c instanceof JTable t && t.getTableHeader() != null) {
            for (int i = 0; i < t.getColumnCount(); i++) {
                TableColumn col = t.getColumnModel().getColumn(i);
                TableCellRenderer r = col.getHeaderRenderer() != null ? col.getHeaderRenderer() : t.getTableHeader().getDefaultRenderer();
                int need = r.getTableCellRendererComponent(t, col.getHeaderValue(), false, false, -1, i).getPreferredSize().width;
                if (col.getWidth() + 1 < need)
                    out.add("table " + t.getName() + " column '" + col.getHeaderValue() + "': " + col.getWidth() + " px wide, header needs " + need);
            }
        }
        if (c instanceof JTree tree && tree.getParent() instanceof JViewport vp) {
            for (int r = 0; r < tree.getRowCount(); r++) {
                Rectangle b = tree.getRowBounds(r);
                if (b != null && b.x + b.width > vp.getWidth() + 1)
                    out.add("tree " + tree.getName() + " row '" + tree.getPathForRow(r).getLastPathComponent() + "': ends at " + (b.x + b.width)
                            + " px, visible " + vp.getWidth());
            }
        }
    }

    /** Inside a scroll pane the user scrolls to what is out of view: not clipped. */
    private static boolean inScrolledView(Component c) {
        for (Container p = c.getParent(); p != null; p = p.getParent())
            if (p instanceof JViewport) return true;
        return false;
    }
}
