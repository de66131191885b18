package org.robopro.app.workbench.ui;

import java.awt.Component;
import javax.swing.JTable;
import javax.swing.table.TableCellRenderer;
import javax.swing.table.TableColumn;
import javax.swing.table.TableModel;

/**
 * A table whose columns are never narrower than their header text: it fills a wide viewport
 * like any table, and in a narrow one keeps its columns' widths and scrolls sideways instead of
 * squeezing them into "Spe…".
 */
public class FittingTable extends JTable {
    public FittingTable(TableModel m) { super(m); }

    /** Sets every column's minimum width to its header's width (call after the columns exist). */
    public void fitHeaders() {
        for (int c = 0; c < getColumnCount(); c++) {
            TableColumn col = getColumnModel().getColumn(c);
            TableCellRenderer r = col.getHeaderRenderer() != null ? col.getHeaderRenderer() : getTableHeader().getDefaultRenderer();
            Component h = r.getTableCellRendererComponent(this, col.getHeaderValue(), false, false, -1, c);
            int w = h.getPreferredSize().width + 12;
            col.setMinWidth(Math.min(w, col.getMaxWidth()));
            if (col.getPreferredWidth() < w) col.setPreferredWidth(w);
        }
    }

    @Override
    public boolean getScrollableTracksViewportWidth() {
        return getParent() == null || getPreferredSize().width <= getParent().getWidth();
    }

    @Override
    public void createDefaultColumnsFromModel() {
        super.createDefaultColumnsFromModel();
        if (getTableHeader() != null) fitHeaders();
    }

    @Override
    public void addNotify() {
        super.addNotify();
        fitHeaders();
    }
}
