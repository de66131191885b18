package org.robopro.app.workbench.ui;

import java.awt.Component;
import java.awt.Container;
import java.awt.Dimension;
import java.awt.FlowLayout;
import java.awt.Insets;
import javax.swing.JScrollPane;
import javax.swing.SwingUtilities;

/**
 * A {@link FlowLayout} whose preferred size wraps its components onto as many rows as the
 * container's width needs, so a row of buttons in a narrow panel moves to a second line
 * instead of falling off the edge (plain FlowLayout asks for one long row).
 */
public final class WrapLayout extends FlowLayout {
    public WrapLayout(int align, int hgap, int vgap) { super(align, hgap, vgap); }

    @Override public Dimension preferredLayoutSize(Container target) { return size(target, true); }

    @Override
    public Dimension minimumLayoutSize(Container target) {
        Dimension d = size(target, false);
        d.width -= getHgap() + 1;
        return d;
    }

    private Dimension size(Container target, boolean preferred) {
        synchronized (target.getTreeLock()) {
            int width = target.getSize().width;
            Container c = target;
            while (width == 0 && c.getParent() != null) { c = c.getParent(); width = c.getSize().width; }
            if (width == 0) width = Integer.MAX_VALUE;
            Insets in = target.getInsets();
            int max = width - (in.left + in.right + getHgap() * 2);
            Dimension out = new Dimension(0, 0);
            int rowW = 0, rowH = 0;
            for (Component m : target.getComponents()) {
                if (!m.isVisible()) continue;
                Dimension d = preferred ? m.getPreferredSize() : m.getMinimumSize();
                if (rowW + d.width > max && rowW > 0) {
                    out.width = Math.max(out.width, rowW);
                    out.height += rowH + getVgap();
                    rowW = 0;
                    rowH = 0;
                }
                if (rowW != 0) rowW += getHgap();
                rowW += d.width;
                rowH = Math.max(rowH, d.height);
            }
            out.width = Math.max(out.width, rowW);
            out.height += rowH;
            out.width += in.left + in.right + getHgap() * 2;
            out.height += in.top + in.bottom + getVgap() * 2;
            // Inside a scroll pane the width follows the viewport, not the content.
            Container sp = SwingUtilities.getAncestorOfClass(JScrollPane.class, target);
            if (sp != null && target.isValid()) out.width -= getHgap() + 1;
            return out;
        }
    }
}
