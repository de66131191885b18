package org.robopro.app.workbench.ui;

import java.awt.BorderLayout;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.function.Consumer;
import javax.swing.BorderFactory;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JTable;
import javax.swing.table.AbstractTableModel;
import org.robopro.app.workbench.WorkbenchSession;
import org.robopro.app.workbench.model.CellObject;
import org.robopro.app.workbench.model.Target;
import org.robopro.app.workbench.model.Tool;
import org.robopro.app.workbench.model.WorkbenchModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.JointDescription;
import org.robopro.models.Vec3;

/**
 * Properties of the selection as name/value rows (mm and degrees). Objects can be renamed,
 * moved, rotated about z and resized here; the tool's TCP and body can be edited (tool construction).
 */
public final class PropertiesPanel extends JPanel {
    private record Row(String name, String value, Consumer<String> edit) { }

    private final WorkbenchSession wb;
    private final List<Row> rows = new ArrayList<>();
    private final Table table = new Table();

    public PropertiesPanel(WorkbenchSession wb) {
        super(new BorderLayout());
        this.wb = wb;
        setBorder(BorderFactory.createTitledBorder("Properties"));
        JTable t = new FittingTable(table);
        t.setName("properties");
        t.setRowHeight(19);
        add(new JScrollPane(t), BorderLayout.CENTER);
        refresh();
    }

    private static String f(double v) { return String.format(Locale.ROOT, "%.1f", v); }

    private static double num(String s) {
        try {
            return Double.parseDouble(s.trim());
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("not a number: " + s);
        }
    }

    /** Shows the model's current selection. */
    public void refresh() {
        rows.clear();
        WorkbenchModel m = wb.model();
        String sel = m.selection();
        if (sel == null) {
            rows.add(new Row("robot", m.robot().displayName(), null));
            rows.add(new Row("joints", String.valueOf(m.robot().dof()), null));
            rows.add(new Row("objects", String.valueOf(m.objects().size()), null));
            rows.add(new Row("targets", String.valueOf(m.targets().size()), null));
        } else if (sel.startsWith("object:")) {
            m.object(sel.substring(7)).ifPresent(this::objectRows);
        } else if (sel.startsWith("link:")) {
            int i = Integer.parseInt(sel.substring(5));
            rows.add(new Row("link", i == 0 ? "base" : "link " + i, null));
            if (i > 0) {
                JointDescription j = m.robot().joints().get(i - 1);
                Vec3 p = j.point(), a = j.axis();
                rows.add(new Row("joint", j.name() + " (" + j.type().fileName() + ")", null));
                rows.add(new Row("axis point mm", f(p.x() * 1000) + ", " + f(p.y() * 1000) + ", " + f(p.z() * 1000), null));
                rows.add(new Row("axis direction", String.format(Locale.ROOT, "%.3f, %.3f, %.3f", a.x(), a.y(), a.z()), null));
                rows.add(new Row("limits deg", f(Math.toDegrees(j.min())) + " .. " + f(Math.toDegrees(j.max())), null));
                rows.add(new Row("max speed deg/s", f(Math.toDegrees(j.maxSpeed())), null));
                rows.add(new Row("value deg", f(Math.toDegrees(m.q()[i - 1])), v -> wb.jogJointDeg(i - 1, num(v))));
            } else {
                Pose b = m.worldTbase();
                rows.add(new Row("base x mm", f(b.x() * 1000), v -> moveBase(0, num(v))));
                rows.add(new Row("base y mm", f(b.y() * 1000), v -> moveBase(1, num(v))));
                rows.add(new Row("base z mm", f(b.z() * 1000), v -> moveBase(2, num(v))));
            }
        } else if (sel.startsWith("target:")) {
            m.target(sel.substring(7)).ifPresent(t -> targetRows(m, t));
        } else if (sel.equals("tool")) {
            toolRows(m.tool());
        }
        table.fireTableDataChanged();
    }

    private void moveBase(int axis, double mm) {
        Pose b = wb.model().worldTbase();
        double[] p = {b.x(), b.y(), b.z()};
        p[axis] = mm / 1000;
        wb.model().setWorldTbase(Pose.translation(p[0], p[1], p[2]).times(Pose.translation(b.position().times(-1)).times(b)));
    }

    private void objectRows(CellObject o) {
        Pose p = o.worldTobject();
        double rz = Math.toDegrees(Math.atan2(p.rot(1, 0), p.rot(0, 0)));
        rows.add(new Row("id", o.id(), null));
        rows.add(new Row("name", o.name(), v -> wb.model().updateObject(o.withName(v))));
        rows.add(new Row("kind", o.kind().name().toLowerCase(Locale.ROOT), null));
        rows.add(new Row("x mm", f(p.x() * 1000), v -> wb.placeObject(o.id(), num(v) / 1000, p.y(), p.z(), Math.toRadians(rz))));
        rows.add(new Row("y mm", f(p.y() * 1000), v -> wb.placeObject(o.id(), p.x(), num(v) / 1000, p.z(), Math.toRadians(rz))));
        rows.add(new Row("z mm", f(p.z() * 1000), v -> wb.placeObject(o.id(), p.x(), p.y(), num(v) / 1000, Math.toRadians(rz))));
        rows.add(new Row("rotation z deg", f(rz), v -> wb.placeObject(o.id(), p.x(), p.y(), p.z(), Math.toRadians(num(v)))));
        if (o.meshPath() == null) {
            Vec3 s = o.size();
            rows.add(new Row("size x mm", f(s.x() * 1000), v -> wb.model().updateObject(o.withSize(new Vec3(num(v) / 1000, s.y(), s.z())))));
            rows.add(new Row("size y mm", f(s.y() * 1000), v -> wb.model().updateObject(o.withSize(new Vec3(s.x(), num(v) / 1000, s.z())))));
            rows.add(new Row("size z mm", f(s.z() * 1000), v -> wb.model().updateObject(o.withSize(new Vec3(s.x(), s.y(), num(v) / 1000)))));
        } else {
            rows.add(new Row("mesh", o.meshPath(), null));
            rows.add(new Row("scale", String.valueOf(o.size().x()), null));
        }
    }

    private void targetRows(WorkbenchModel m, Target t) {
        Pose p = t.worldTtcp();
        rows.add(new Row("target", t.name(), null));
        rows.add(new Row("x mm", f(p.x() * 1000), v -> m.putTarget(t.withPose(Pose.translation(num(v) / 1000 - p.x(), 0, 0).times(p)))));
        rows.add(new Row("y mm", f(p.y() * 1000), v -> m.putTarget(t.withPose(Pose.translation(0, num(v) / 1000 - p.y(), 0).times(p)))));
        rows.add(new Row("z mm", f(p.z() * 1000), v -> m.putTarget(t.withPose(Pose.translation(0, 0, num(v) / 1000 - p.z()).times(p)))));
        double[] q = p.quaternion();
        rows.add(new Row("quaternion", String.format(Locale.ROOT, "%.4f, %.4f, %.4f, %.4f", q[0], q[1], q[2], q[3]), null));
        rows.add(new Row("confdata", t.conf().cf1() + ", " + t.conf().cf4() + ", " + t.conf().cf6() + ", " + t.conf().cfx(), null));
        rows.add(new Row("status", m.status(t).name().toLowerCase(Locale.ROOT).replace('_', ' '), null));
    }

    private void toolRows(Tool t) {
        Pose p = t.flangeTtcp();
        rows.add(new Row("tool", t.name(), v -> wb.model().setTool(new Tool(v.trim(), p, t.bodyRadius(), t.bodyLength(), t.massKg()))));
        rows.add(new Row("TCP x mm", f(p.x() * 1000), v -> setTcp(t, 0, num(v))));
        rows.add(new Row("TCP y mm", f(p.y() * 1000), v -> setTcp(t, 1, num(v))));
        rows.add(new Row("TCP z mm", f(p.z() * 1000), v -> setTcp(t, 2, num(v))));
        rows.add(new Row("body radius mm", f(t.bodyRadius() * 1000), v -> wb.model().setTool(new Tool(t.name(), p, num(v) / 1000, t.bodyLength(), t.massKg()))));
        rows.add(new Row("body length mm", f(t.bodyLength() * 1000), v -> wb.model().setTool(new Tool(t.name(), p, t.bodyRadius(), num(v) / 1000, t.massKg()))));
        rows.add(new Row("mass kg", f(t.massKg()), v -> wb.model().setTool(new Tool(t.name(), p, t.bodyRadius(), t.bodyLength(), num(v)))));
    }

    private void setTcp(Tool t, int axis, double mm) {
        Pose p = t.flangeTtcp();
        double[] x = {p.x(), p.y(), p.z()};
        x[axis] = mm / 1000;
        Pose rot = Pose.translation(p.position().times(-1)).times(p);
        wb.model().setTool(new Tool(t.name(), Pose.translation(x[0], x[1], x[2]).times(rot), t.bodyRadius(), t.bodyLength(), t.massKg()));
    }

    private final class Table extends AbstractTableModel {
        @Override public int getRowCount() { return rows.size(); }
        @Override public int getColumnCount() { return 2; }
        @Override public String getColumnName(int c) { return c == 0 ? "Property" : "Value"; }
        @Override public Object getValueAt(int r, int c) { return c == 0 ? rows.get(r).name() : rows.get(r).value(); }
        @Override public boolean isCellEditable(int r, int c) { return c == 1 && rows.get(r).edit() != null; }

        @Override
        public void setValueAt(Object v, int r, int c) {
            try {
                rows.get(r).edit().accept(v.toString());
            } catch (IllegalArgumentException e) {
                wb.log("Not changed: " + e.getMessage());
            }
        }
    }
}
