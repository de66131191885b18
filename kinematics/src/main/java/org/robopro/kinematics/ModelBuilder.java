package org.robopro.kinematics;

import java.util.ArrayList;
import java.util.List;
import org.robopro.models.FrameDescription;
import org.robopro.models.InputException;
import org.robopro.models.JointDescription;
import org.robopro.models.JointType;
import org.robopro.models.RobotDescription;
import org.robopro.models.Vec3;

/**
 * Builds the elementary transformations of a robot from its joint axes at the zero position
 * (seed paper §4 frame assignment, Table 1 parameterizations). See docs/kinematics.md.
 *
 * <p>Frame k lies on joint axis k (z_k along the axis in its positive sense). Its origin is the
 * point where the transformation arriving from frame k-1 meets axis k (the foot of the common
 * normal, the axes' intersection, or for parallel axes the point where axis k crosses the plane
 * through the previous origin normal to the previous axis); so every trailing T_Z(e) of Table 1
 * is zero and fixed, and the one identified translation along an axis is the outgoing d.
 */
final class ModelBuilder {
    /**
     * Axes closer than this to parallel use Hayati, others DH. DH is singular for parallel axes
     * (0 deg), Hayati for perpendicular ones (90 deg): 45 deg keeps each as far from its own
     * singular manifold as the other can be (§3, Eqs. 4b and 7).
     */
    static final double PARALLEL_THRESHOLD = Math.toRadians(45);
    /** Below this (m) a length is treated as zero when choosing directions; keeps choices stable. */
    private static final double LENGTH_EPS = 1e-9;

    enum Convention { TABLE1, PLAIN_DH }

    private ModelBuilder() { }

    /** Checks what the model construction needs; bad input names the robot and the field. */
    static void validate(RobotDescription d) {
        String file = d.name() == null ? "<robot>" : d.name();
        if (d.joints().isEmpty()) throw new InputException(file, 0, 0, "joints", "a robot needs at least one joint");
        for (int i = 0; i < d.dof(); i++) {
            JointDescription j = d.joints().get(i);
            String f = "joints[" + (i + 1) + "]";
            if (!j.point().isFinite()) throw new InputException(file, 0, 0, f + ".point", "not finite: " + j.point());
            if (!j.axis().isFinite() || j.axis().norm() < 1e-9)
                throw new InputException(file, 0, 0, f + ".axis", "zero or non-finite axis " + j.axis());
            if (!(j.min() <= j.max())) throw new InputException(file, 0, 0, f + ".limits", "min " + j.min() + " > max " + j.max());
        }
        FrameDescription fl = d.flange();
        if (fl == null || !fl.origin().isFinite() || !fl.xAxis().isFinite() || !fl.zAxis().isFinite()
                || fl.xAxis().norm() < 1e-9 || fl.zAxis().norm() < 1e-9
                || fl.xAxis().cross(fl.zAxis()).norm() < 1e-6 * fl.xAxis().norm() * fl.zAxis().norm())
            throw new InputException(file, 0, 0, "flange", "flange needs a finite origin and non-parallel x and z axes");
        for (var t : d.coupling())
            if (t.joint() < 1 || t.joint() > d.dof() || t.source() < 1 || t.source() > d.dof() || !Double.isFinite(t.factor()))
                throw new InputException(file, 0, 0, "coupling", "term names a missing joint or is not finite: " + t);
    }

    /** A frame during construction: origin and orthonormal axes in base coordinates. */
    private record Frame(Vec3 o, Vec3 x, Vec3 y, Vec3 z) {
        Frame rotX(double a) {
            double c = Math.cos(a), s = Math.sin(a);
            return new Frame(o, x, y.times(c).plus(z.times(s)), z.times(c).minus(y.times(s)));
        }

        Frame rotY(double a) {
            double c = Math.cos(a), s = Math.sin(a);
            return new Frame(o, x.times(c).minus(z.times(s)), y, z.times(c).plus(x.times(s)));
        }
    }

    static List<Transformation> build(RobotDescription d, Convention conv) {
        validate(d);
        int n = d.dof();
        List<Transformation> out = new ArrayList<>(n + 1);
        JointDescription j1 = d.joints().get(0);
        Vec3 u1 = j1.axis().normalized();

        // Base -> J1 (Table 1 row B): base axis k most aligned with u1; translations to where
        // axis 1 pierces coord_k = 0; a constant rotation e_z -> e_k; then small tilts R_X, R_Y.
        int k = 0;
        double[] ua = {Math.abs(u1.x()), Math.abs(u1.y()), Math.abs(u1.z())};
        if (ua[1] > ua[k]) k = 1;
        if (ua[2] > ua[k]) k = 2;
        double[] p = j1.point().toArray(), u = u1.toArray();
        double t = -p[k] / u[k];
        Vec3 pierce = j1.point().plus(u1.times(t));
        double[] pc = pierce.toArray();
        pc[k] = 0;
        pierce = Vec3.of(pc);
        boolean revolute1 = j1.type() == JointType.REVOLUTE;
        List<Elementary> base = new ArrayList<>();
        Frame f;
        String[] names = {"x", "y", "z"};
        for (int a = 0; a < 3; a++)
            if (a != k) base.add(new Elementary(Elementary.Op.values()[a], "base.t" + names[a], pc[a], revolute1));
        Frame basis = new Frame(pierce, Vec3.X, Vec3.Y, Vec3.Z);
        if (k == 0) {
            base.add(new Elementary(Elementary.Op.RY, "base.r0", Math.PI / 2, false));
            basis = basis.rotY(Math.PI / 2);
        } else if (k == 1) {
            base.add(new Elementary(Elementary.Op.RX, "base.r0", -Math.PI / 2, false));
            basis = basis.rotX(-Math.PI / 2);
        }
        // u1 in the basis: (sin b, -sin a cos b, cos a cos b) for R_X(a) R_Y(b) e_z.
        double vx = u1.dot(basis.x), vy = u1.dot(basis.y), vz = u1.dot(basis.z);
        double beta = Math.asin(clamp(vx)), alpha = Math.atan2(-vy, vz);
        base.add(new Elementary(Elementary.Op.RX, "base.rx", alpha, true));
        base.add(new Elementary(Elementary.Op.RY, "base.ry", beta, true));
        f = basis.rotX(alpha).rotY(beta);
        out.add(new Transformation(0, "base -> j1", "base-" + names[k], Double.NaN, base));

        for (int i = 0; i < n; i++) {
            String jn = "j" + (i + 1);
            if (i == n - 1) {
                out.add(flangeRow(i + 1, jn, f, d.flange()));
                break;
            }
            JointDescription jn1 = d.joints().get(i + 1);
            boolean prismNext = jn1.type() == JointType.PRISMATIC;
            Vec3 un = jn1.axis().normalized();
            double angle = Math.acos(Math.min(1, Math.abs(f.z.dot(un))));
            boolean hayati = conv == Convention.TABLE1 && angle < PARALLEL_THRESHOLD;
            List<Elementary> el = new ArrayList<>();
            String label = jn + " -> j" + (i + 2);
            if (!hayati) {
                // DH (Eq. 5) plus trailing T_Z: x along the common normal z_k x u (always defined
                // for non-parallel axes, so continuous through intersecting axes).
                Vec3 w = f.o.minus(jn1.point());
                double b = f.z.dot(un), dd = f.z.dot(w), e = un.dot(w), den = 1 - b * b;
                Vec3 xn;
                double s, tt;
                if (den > 1e-18) {
                    s = (b * e - dd) / den;
                    tt = (e - b * dd) / den;
                    xn = f.z.cross(un).normalized();
                } else { // exactly parallel (plain DH only): common normal through the origin
                    s = 0;
                    tt = -e;
                    Vec3 g = jn1.point().plus(un.times(tt)).minus(f.o);
                    xn = g.norm() > LENGTH_EPS ? g.normalized() : f.x;
                }
                Vec3 footK = f.o.plus(f.z.times(s)), footN = jn1.point().plus(un.times(tt));
                double a = footN.minus(footK).dot(xn);
                // sign of x: a >= 0; for intersecting axes, the one closer to x_k (small offset)
                if (a < -LENGTH_EPS || (Math.abs(a) <= LENGTH_EPS && xn.dot(f.x) < -1e-12)) {
                    xn = xn.times(-1);
                    a = -a;
                }
                double off = Math.atan2(xn.dot(f.y), xn.dot(f.x));
                Vec3 yn = f.z.cross(xn);
                double alpha2 = Math.atan2(-un.dot(yn), un.dot(f.z));
                // Into a prismatic joint only its direction counts (d, a fixed); out of one, the
                // joint's own translation makes d redundant with the fixed arrival translations.
                el.add(new Elementary(Elementary.Op.RZ, jn + ".offset", off, true));
                el.add(new Elementary(Elementary.Op.TZ, jn + ".d", s, !prismNext));
                el.add(new Elementary(Elementary.Op.TX, jn + ".a", a, !prismNext));
                el.add(new Elementary(Elementary.Op.RX, jn + ".alpha", alpha2, true));
                el.add(new Elementary(Elementary.Op.TZ, jn + ".e", 0.0, false));
                Vec3 zN = un, xN = xn;
                f = new Frame(footN, xN, zN.cross(xN), zN);
                out.add(new Transformation(i + 1, label, "DH", angle, el));
            } else {
                // Hayati (Eq. 6) plus trailing T_Z: x toward where axis k+1 crosses the plane
                // through the origin normal to z_k.
                double tt = f.o.minus(jn1.point()).dot(f.z) / un.dot(f.z);
                Vec3 pp = jn1.point().plus(un.times(tt));
                Vec3 v = pp.minus(f.o);
                double a = v.norm();
                Vec3 xn = a > LENGTH_EPS ? v.times(1 / a) : f.x;
                if (a <= LENGTH_EPS) { a = 0; pp = f.o; }
                double off = Math.atan2(xn.dot(f.y), xn.dot(f.x));
                Vec3 yn = f.z.cross(xn);
                double bx = un.dot(xn), by = un.dot(yn), bz = un.dot(f.z);
                double beta2 = Math.asin(clamp(bx)), alpha2 = Math.atan2(-by, bz);
                el.add(new Elementary(Elementary.Op.RZ, jn + ".offset", off, !prismNext));
                el.add(new Elementary(Elementary.Op.TX, jn + ".a", a, !prismNext));
                el.add(new Elementary(Elementary.Op.RX, jn + ".alpha", alpha2, true));
                el.add(new Elementary(Elementary.Op.RY, jn + ".beta", beta2, true));
                el.add(new Elementary(Elementary.Op.TZ, jn + ".e", 0.0, false));
                Frame g = new Frame(pp, xn, yn, f.z).rotX(alpha2).rotY(beta2);
                f = g;
                out.add(new Transformation(i + 1, label, "Hayati", angle, el));
            }
        }
        return out;
    }

    /** Last joint -> flange (Table 1 TCP row): R_Z (fixed), T_X, T_Y, T_Z, then three rotations. */
    private static Transformation flangeRow(int index, String jn, Frame f, FrameDescription flange) {
        Pose fl = Pose.fromFrame(flange);
        Pose frame = Pose.of(new double[] {f.x.x(), f.y.x(), f.z.x(), f.x.y(), f.y.y(), f.z.y(), f.x.z(), f.y.z(), f.z.z()},
                f.o.x(), f.o.y(), f.o.z());
        Pose g = frame.inverse().times(fl);
        List<Elementary> el = new ArrayList<>();
        // The last joint's offset is redundant with the flange's own R_Z: fixed at zero.
        el.add(new Elementary(Elementary.Op.RZ, jn + ".offset", 0.0, false));
        el.add(new Elementary(Elementary.Op.TX, "flange.tx", g.x(), true));
        el.add(new Elementary(Elementary.Op.TY, "flange.ty", g.y(), true));
        el.add(new Elementary(Elementary.Op.TZ, "flange.tz", g.z(), true));
        double angle = Math.acos(clamp(g.rot(2, 2)));
        String conv;
        if (angle < PARALLEL_THRESHOLD) {
            // R_Z R_Y R_X: singular only when the flange x axis is along z_n, here >= 45 deg away.
            conv = "TCP-ZYX";
            el.add(new Elementary(Elementary.Op.RZ, "flange.rz", Math.atan2(g.rot(1, 0), g.rot(0, 0)), true));
            el.add(new Elementary(Elementary.Op.RY, "flange.ry", -Math.asin(clamp(g.rot(2, 0))), true));
            el.add(new Elementary(Elementary.Op.RX, "flange.rx", Math.atan2(g.rot(2, 1), g.rot(2, 2)), true));
        } else {
            // R_Z R_Y R_Z: singular only when the flange z axis is along z_n, here >= 45 deg away.
            conv = "TCP-ZYZ";
            el.add(new Elementary(Elementary.Op.RZ, "flange.rz", Math.atan2(g.rot(1, 2), g.rot(0, 2)), true));
            el.add(new Elementary(Elementary.Op.RY, "flange.ry", angle, true));
            el.add(new Elementary(Elementary.Op.RZ, "flange.rz2", Math.atan2(g.rot(2, 1), -g.rot(2, 0)), true));
        }
        return new Transformation(index, jn + " -> flange", conv, angle, el);
    }

    static double clamp(double v) { return Math.max(-1, Math.min(1, v)); }
}
