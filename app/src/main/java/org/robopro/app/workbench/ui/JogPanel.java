package org.robopro.app.workbench.ui;

import java.awt.BorderLayout;
import java.awt.GridBagConstraints;
import java.awt.GridBagLayout;
import java.awt.GridLayout;
import java.awt.Insets;
import java.util.List;
import java.util.Locale;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JComboBox;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JSlider;
import javax.swing.JSpinner;
import javax.swing.SpinnerNumberModel;
import org.robopro.app.workbench.WorkbenchSession;
import org.robopro.app.workbench.model.WorkbenchModel;
import org.robopro.kinematics.ConfData;
import org.robopro.kinematics.Pose;
import org.robopro.models.JointDescription;

/**
 * Jogging: one slider and spinner per joint (degrees, within the joint limits) and Cartesian
 * steps of the TCP in the world, base or tool frame (IK keeps the configuration), with the TCP
 * pose and configuration data shown.
 */
public final class JogPanel extends JPanel {
    private final WorkbenchSession wb;
    private final JPanel joints = new JPanel(new GridBagLayout());
    private JSlider[] sliders = new JSlider[0];
    private JSpinner[] spinners = new JSpinner[0];
    private final JComboBox<WorkbenchSession.JogFrame> frame = new JComboBox<>(WorkbenchSession.JogFrame.values());
    private final JSpinner stepMm = new JSpinner(new SpinnerNumberModel(10.0, 0.1, 500.0, 1.0));
    private final JSpinner stepDeg = new JSpinner(new SpinnerNumberModel(5.0, 0.1, 90.0, 1.0));
    private final JLabel tcp = new JLabel();
    private final JLabel conf = new JLabel();
    private boolean updating;

    public JogPanel(WorkbenchSession wb) {
        super(new BorderLayout(4, 4));
        this.wb = wb;
        setBorder(BorderFactory.createTitledBorder("Jog"));
        add(joints, BorderLayout.NORTH);
        JPanel cart = new JPanel(new BorderLayout(2, 2));
        JPanel opts = new JPanel(new GridLayout(1, 0, 4, 0));
        opts.add(frame);
        opts.add(labelled("mm", stepMm));
        opts.add(labelled("deg", stepDeg));
        cart.add(opts, BorderLayout.NORTH);
        JPanel grid = new JPanel(new GridLayout(2, 6, 2, 2));
        String[] axes = {"X", "Y", "Z", "Rx", "Ry", "Rz"};
        for (int sign : new int[] {-1, 1})
            for (int a = 0; a < 6; a++) {
                int axis = a;
                JButton b = new JButton(axes[a] + (sign < 0 ? "-" : "+"));
                b.setName("jog-" + axes[a] + (sign < 0 ? "-" : "+"));
                b.setMargin(new Insets(1, 2, 1, 2));
                b.addActionListener(e -> stepCartesian(axis, sign));
                grid.add(b);
            }
        JPanel read = new JPanel();
        read.setLayout(new javax.swing.BoxLayout(read, javax.swing.BoxLayout.Y_AXIS));
        read.add(tcp);
        read.add(conf);
        JPanel lower = new JPanel(new BorderLayout(2, 2));
        lower.add(grid, BorderLayout.NORTH);
        lower.add(read, BorderLayout.CENTER);
        tcp.setAlignmentX(0);
        conf.setAlignmentX(0);
        cart.add(lower, BorderLayout.CENTER);
        cart.setBorder(BorderFactory.createTitledBorder("Cartesian"));
        add(cart, BorderLayout.CENTER);
        rebuild();
    }

    private static JPanel labelled(String unit, JSpinner s) {
        JPanel p = new JPanel(new BorderLayout());
        p.add(s, BorderLayout.CENTER);
        p.add(new JLabel(" " + unit), BorderLayout.EAST);
        return p;
    }

    /** One Cartesian jog step along/about {@code axis} (0..5 = x y z rx ry rz) in the chosen frame. */
    public boolean stepCartesian(int axis, int sign) {
        double mm = ((Number) stepMm.getValue()).doubleValue() / 1000 * sign;
        double rad = Math.toRadians(((Number) stepDeg.getValue()).doubleValue()) * sign;
        double[] d = new double[6];
        d[axis] = axis < 3 ? mm : rad;
        return wb.jogCartesian((WorkbenchSession.JogFrame) frame.getSelectedItem(), d[0], d[1], d[2], d[3], d[4], d[5]);
    }

    public void setJogFrame(WorkbenchSession.JogFrame f) { frame.setSelectedItem(f); }

    /** Sets joint i's spinner as a user would; the change flows to the model. */
    public void setJointDegrees(int i, double deg) { spinners[i].setValue(deg); }

    /** Rebuilds the joint rows for the model's robot. */
    public void rebuild() {
        joints.removeAll();
        List<JointDescription> js = wb.model().robot().joints();
        sliders = new JSlider[js.size()];
        spinners = new JSpinner[js.size()];
        GridBagConstraints c = new GridBagConstraints();
        c.insets = new Insets(1, 2, 1, 2);
        c.fill = GridBagConstraints.HORIZONTAL;
        for (int i = 0; i < js.size(); i++) {
            int idx = i;
            JointDescription j = js.get(i);
            double lo = Math.toDegrees(j.min()), hi = Math.toDegrees(j.max());
            c.gridy = i;
            c.gridx = 0;
            c.weightx = 0;
            joints.add(new JLabel("J" + (i + 1)), c);
            JSlider s = new JSlider((int) Math.round(lo * 10), (int) Math.round(hi * 10), 0);
            s.setName("joint-slider-" + (i + 1));
            s.setToolTipText(String.format(Locale.ROOT, "%s: %.0f .. %.0f deg", j.name(), lo, hi));
            c.gridx = 1;
            c.weightx = 1;
            joints.add(s, c);
            JSpinner sp = new JSpinner(new SpinnerNumberModel(0.0, lo, hi, 1.0));
            sp.setName("joint-spinner-" + (i + 1));
            ((JSpinner.DefaultEditor) sp.getEditor()).getTextField().setColumns(5);
            c.gridx = 2;
            c.weightx = 0;
            joints.add(sp, c);
            s.addChangeListener(e -> {
                if (updating) return;
                wb.jogJointDeg(idx, s.getValue() / 10.0);
            });
            sp.addChangeListener(e -> {
                if (updating) return;
                wb.jogJointDeg(idx, ((Number) sp.getValue()).doubleValue());
            });
            sliders[i] = s;
            spinners[i] = sp;
        }
        refresh();
        revalidate();
    }

    /** v rounded to the displayed step, a value that rounds to zero as 0 (never "-0.0000"). */
    static double shown(double v, double step) {
        return Math.rint(v / step) * step + 0.0;
    }

    /** Shows the model's joint values and TCP. */
    public void refresh() {
        WorkbenchModel m = wb.model();
        double[] q = m.q();
        if (q.length != sliders.length) { rebuild(); return; }
        updating = true;
        try {
            for (int i = 0; i < q.length; i++) {
                double deg = Math.toDegrees(q[i]);
                sliders[i].setValue((int) Math.round(deg * 10));
                SpinnerNumberModel sm = (SpinnerNumberModel) spinners[i].getModel();
                double clamped = Math.max(((Number) sm.getMinimum()).doubleValue(), Math.min(((Number) sm.getMaximum()).doubleValue(), deg));
                spinners[i].setValue(Math.round(clamped * 100) / 100.0);
            }
        } finally {
            updating = false;
        }
        Pose p = m.worldTtcp(q);
        double[] qq = p.quaternion();
        tcp.setText(String.format(Locale.ROOT, "<html>TCP (world): <b>%.1f, %.1f, %.1f</b> mm<br>q: [%.4f, %.4f, %.4f, %.4f]</html>",
                shown(p.x() * 1000, 0.1), shown(p.y() * 1000, 0.1), shown(p.z() * 1000, 0.1),
                shown(qq[0], 1e-4), shown(qq[1], 1e-4), shown(qq[2], 1e-4), shown(qq[3], 1e-4)));
        ConfData c = m.kinematics().confOf(q);
        boolean ok = m.kinematics().withinLimits(q);
        conf.setText(String.format(Locale.ROOT, "<html>confdata [%d, %d, %d, %d] %s</html>", c.cf1(), c.cf4(), c.cf6(), c.cfx(),
                ok ? "" : "<font color='#d02020'>outside limits</font>"));
    }
}
