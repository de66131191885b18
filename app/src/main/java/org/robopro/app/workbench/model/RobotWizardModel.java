package org.robopro.app.workbench.model;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.ModelReport;
import org.robopro.kinematics.Pose;
import org.robopro.kinematics.Units;
import org.robopro.models.CouplingTerm;
import org.robopro.models.FrameDescription;
import org.robopro.models.InputException;
import org.robopro.models.JointDescription;
import org.robopro.models.JointType;
import org.robopro.models.RobotDescription;
import org.robopro.models.Vec3;

/**
 * The robot model construction wizard's state (seed paper §6, Fig. 7): joint by joint its type,
 * a point on its axis and the axis direction in base coordinates with all joints at zero, its
 * limits and speed, then the flange frame. Values are kept as the user typed them (mm, degrees);
 * {@link #build()} turns them into a robot description and a kinematic model (the kinematics
 * module's {@code KinematicModel.build}: the Table-1 parameterization) or an error message. Not
 * thread-safe: the wizard edits it on the Swing thread and hands immutable results on.
 */
public final class RobotWizardModel {
    /** One joint row, in the units the wizard shows. */
    public record JointRow(String name, JointType type, double[] pointMm, double[] axis, double minDeg, double maxDeg,
                           double speedDegPerS) {
        public JointRow {
            pointMm = pointMm.clone();
            axis = axis.clone();
        }

        @Override public double[] pointMm() { return pointMm.clone(); }
        @Override public double[] axis() { return axis.clone(); }
    }

    /** What building gave: the description and model, or the message of what is wrong. */
    public record Result(Optional<RobotDescription> robot, Optional<KinematicModel> model, String report, String error) {
        public boolean ok() { return model.isPresent(); }

        /** Link frames at the zero position (base, links, flange), or empty when the model failed. */
        public Pose[] framesAtZero() {
            return model.map(m -> m.linkFrames(new double[m.dof()])).orElse(new Pose[0]);
        }
    }

    private String name = "myrobot";
    private String displayName = "My robot";
    private final List<JointRow> joints = new ArrayList<>();
    private double[] flangeOriginMm = {0, 0, 0};
    private double[] flangeX = {1, 0, 0};
    private double[] flangeZ = {0, 0, 1};
    /** Joint coupling (theta = C q) kept from the template, e.g. the IRB-2000's parallel arm. */
    private List<CouplingTerm> coupling = List.of();

    /** Starts from a robot (e.g. a shipped one) as a template. */
    public static RobotWizardModel from(RobotDescription d) {
        RobotWizardModel w = new RobotWizardModel();
        w.name = d.name() + "_custom";
        w.displayName = d.displayName() + " (custom)";
        for (JointDescription j : d.joints()) {
            boolean rev = j.type() == JointType.REVOLUTE;
            w.joints.add(new JointRow(j.name(), j.type(), mm(j.point()), arr(j.axis()), rev ? Math.toDegrees(j.min()) : Units.mToMm(j.min()),
                    rev ? Math.toDegrees(j.max()) : Units.mToMm(j.max()), rev ? Math.toDegrees(j.maxSpeed()) : Units.mToMm(j.maxSpeed())));
        }
        w.flangeOriginMm = mm(d.flange().origin());
        w.flangeX = arr(d.flange().xAxis());
        w.flangeZ = arr(d.flange().zAxis());
        w.coupling = d.coupling();
        return w;
    }

    private static double[] mm(Vec3 v) { return new double[] {Units.mToMm(v.x()), Units.mToMm(v.y()), Units.mToMm(v.z())}; }
    private static double[] arr(Vec3 v) { return new double[] {v.x(), v.y(), v.z()}; }

    public String name() { return name; }
    public String displayName() { return displayName; }
    public void setName(String n) { name = n == null ? "" : n.trim(); }
    public void setDisplayName(String n) { displayName = n == null ? "" : n.trim(); }

    public List<JointRow> joints() { return List.copyOf(joints); }
    public int jointCount() { return joints.size(); }
    public JointRow joint(int i) { return joints.get(i); }
    public void setJoint(int i, JointRow r) { joints.set(i, r); }

    /**
     * Appends a joint: by default a revolute joint about z placed 300 mm above the last joint's
     * point (or the base), so each added joint gives a model that builds.
     */
    public JointRow addJoint() {
        double[] p = joints.isEmpty() ? new double[] {0, 0, 0} : joints.get(joints.size() - 1).pointMm();
        p[2] += 300;
        JointRow r = new JointRow("j" + (joints.size() + 1), JointType.REVOLUTE, p, new double[] {0, 0, 1}, -180, 180, 90);
        joints.add(r);
        return r;
    }

    /** Removes joint i; coupling terms naming a joint that no longer exists are dropped. */
    public void removeJoint(int i) {
        joints.remove(i);
        int n = joints.size();
        coupling = coupling.stream().filter(t -> t.joint() <= n && t.source() <= n).toList();
    }

    public List<CouplingTerm> coupling() { return coupling; }

    public double[] flangeOriginMm() { return flangeOriginMm.clone(); }
    public double[] flangeX() { return flangeX.clone(); }
    public double[] flangeZ() { return flangeZ.clone(); }

    public void setFlange(double[] originMm, double[] x, double[] z) {
        flangeOriginMm = originMm.clone();
        flangeX = x.clone();
        flangeZ = z.clone();
    }

    /**
     * Everything the wizard edits, as a value: the wizard's undo and redo keep these. Two states
     * are the same edit when their {@link #key()}s are equal.
     */
    public record State(String name, String displayName, List<JointRow> joints, double[] flangeOriginMm, double[] flangeX,
                        double[] flangeZ, List<CouplingTerm> coupling) {
        public State {
            joints = List.copyOf(joints);
            flangeOriginMm = flangeOriginMm.clone();
            flangeX = flangeX.clone();
            flangeZ = flangeZ.clone();
            coupling = List.copyOf(coupling);
        }

        /** The state's content as text (arrays by value). */
        public String key() {
            StringBuilder b = new StringBuilder(name).append('|').append(displayName);
            for (JointRow j : joints)
                b.append('|').append(j.name()).append(',').append(j.type()).append(',').append(java.util.Arrays.toString(j.pointMm()))
                 .append(java.util.Arrays.toString(j.axis())).append(j.minDeg()).append(',').append(j.maxDeg()).append(',').append(j.speedDegPerS());
            return b.append('|').append(java.util.Arrays.toString(flangeOriginMm)).append(java.util.Arrays.toString(flangeX))
                    .append(java.util.Arrays.toString(flangeZ)).append(coupling).toString();
        }
    }

    public State state() { return new State(name, displayName, joints, flangeOriginMm, flangeX, flangeZ, coupling); }

    /** Puts the wizard back to {@code s}. */
    public void restore(State s) {
        name = s.name();
        displayName = s.displayName();
        joints.clear();
        joints.addAll(s.joints());
        setFlange(s.flangeOriginMm(), s.flangeX(), s.flangeZ());
        coupling = s.coupling();
    }

    /** The robot description in SI units (throws IllegalArgumentException for empty names). */
    public RobotDescription description() {
        if (name.isEmpty() || !name.matches("[A-Za-z0-9_.-]+"))
            throw new IllegalArgumentException("robot name '" + name + "': use letters, digits, '_', '-', '.'");
        List<JointDescription> js = new ArrayList<>();
        for (JointRow r : joints) {
            boolean rev = r.type() == JointType.REVOLUTE;
            double[] p = r.pointMm(), a = r.axis();
            js.add(new JointDescription(r.name(), r.type(), new Vec3(Units.mmToM(p[0]), Units.mmToM(p[1]), Units.mmToM(p[2])),
                    new Vec3(a[0], a[1], a[2]), rev ? Math.toRadians(r.minDeg()) : Units.mmToM(r.minDeg()),
                    rev ? Math.toRadians(r.maxDeg()) : Units.mmToM(r.maxDeg()),
                    rev ? Math.toRadians(r.speedDegPerS()) : Units.mmToM(r.speedDegPerS())));
        }
        FrameDescription flange = new FrameDescription(
                new Vec3(Units.mmToM(flangeOriginMm[0]), Units.mmToM(flangeOriginMm[1]), Units.mmToM(flangeOriginMm[2])),
                new Vec3(flangeX[0], flangeX[1], flangeX[2]), new Vec3(flangeZ[0], flangeZ[1], flangeZ[2]));
        return new RobotDescription(name, displayName.isEmpty() ? name : displayName, js, flange, coupling, Optional.empty(),
                List.of(), List.of(), "robopro workbench robot model wizard", Map.of());
    }

    /**
     * Builds the model. Bad input never throws: the InputException / IllegalArgumentException
     * message comes back as {@link Result#error()} (with the joint it names, in the wizard's words).
     */
    public Result build() {
        RobotDescription d;
        try {
            d = description();
        } catch (IllegalArgumentException e) {
            return new Result(Optional.empty(), Optional.empty(), "", e.getMessage());
        }
        try {
            KinematicModel m = KinematicModel.build(d);
            return new Result(Optional.of(d), Optional.of(m), ModelReport.of(m), "");
        } catch (InputException e) {
            String where = e.field() == null || e.field().isEmpty() ? "" : e.field() + ": ";
            return new Result(Optional.of(d), Optional.empty(), "", where + e.problem());
        } catch (IllegalArgumentException | ArithmeticException e) {
            return new Result(Optional.of(d), Optional.empty(), "", String.valueOf(e.getMessage()));
        }
    }

    /** A short summary for a log line. */
    public String summary() {
        long r = joints.stream().filter(j -> j.type() == JointType.REVOLUTE).count();
        return String.format(Locale.ROOT, "%s: %d joints (%dR %dP)", name, joints.size(), r, joints.size() - r);
    }
}
