package org.robopro.world;

import java.util.List;
import java.util.Random;
import org.robopro.models.JointDescription;
import org.robopro.models.JointType;
import org.robopro.models.RobotDescription;
import org.robopro.models.Vec3;

/**
 * The geometry of an arm as a product of exponentials (Lynch &amp; Park, "Modern Robotics",
 * 2017, §4.1, space form): T(theta) = e^[S1]theta1 ... e^[Sn]thetan M, with S_i the screw axis of
 * joint i at the zero position (a point on the axis and its direction, base coordinates) and M the
 * flange frame at zero. This is the robot file's own description of a robot, read directly, so
 * nothing of the estimator's model construction is used. SI units. Immutable.
 *
 * @param prismatic  per joint: true for a prismatic joint
 * @param points     a point on each joint axis at zero, m
 * @param axes       unit direction of each joint axis at zero
 * @param flange     flange frame at zero
 */
public record Arm(boolean[] prismatic, double[][] points, double[][] axes, Rigid flange) {
    public Arm {
        prismatic = prismatic.clone();
        points = deep(points);
        axes = deep(axes);
    }

    @Override public boolean[] prismatic() { return prismatic.clone(); }

    @Override public double[][] points() { return deep(points); }

    @Override public double[][] axes() { return deep(axes); }

    public int dof() { return points.length; }

    /** The nominal arm of a robot file. */
    public static Arm of(RobotDescription robot) {
        List<JointDescription> js = robot.joints();
        int n = js.size();
        boolean[] pr = new boolean[n];
        double[][] pts = new double[n][], ax = new double[n][];
        for (int i = 0; i < n; i++) {
            JointDescription j = js.get(i);
            pr[i] = j.type() == JointType.PRISMATIC;
            pts[i] = j.point().toArray();
            ax[i] = Rigid.unit(j.axis().toArray());
        }
        var f = robot.flange();
        return new Arm(pr, pts, ax, Rigid.frame(f.origin().toArray(), Rigid.unit(f.xAxis().toArray()),
                Rigid.unit(f.zAxis().toArray())));
    }

    /** e^[S_i] theta_i: rotation about the joint's axis line, or translation along it. */
    public Rigid joint(int i, double theta) {
        if (prismatic[i]) return Rigid.translation(axes[i][0] * theta, axes[i][1] * theta, axes[i][2] * theta);
        return Rigid.rotation(axes[i], theta, points[i]);
    }

    /**
     * The transforms of the moving bodies: element k = e^[S1]theta1 ... e^[S(k+1)]theta(k+1), which
     * carries any point of body k+1 (the link moved by joint k+1) from its zero-position place to
     * its place at theta.
     */
    public Rigid[] bodies(double[] theta) {
        Rigid[] out = new Rigid[dof()];
        Rigid t = Rigid.IDENTITY;
        for (int i = 0; i < dof(); i++) {
            t = t.times(joint(i, theta[i]));
            out[i] = t;
        }
        return out;
    }

    /** The flange frame in base coordinates at model angles theta. */
    public Rigid flange(double[] theta) {
        Rigid[] b = bodies(theta);
        return (b.length == 0 ? Rigid.IDENTITY : b[b.length - 1]).times(flange);
    }

    /**
     * The flange frame when joint i's factor is preceded by {@code pre[i]} (null: nothing), a
     * transform in the zero-position coordinates of the chain at that joint (e.g. a tilt of its
     * axis about the axis point): T = ... pre_i e^[S_i]theta_i ... M.
     */
    public Rigid flange(double[] theta, Rigid[] pre) {
        Rigid t = Rigid.IDENTITY;
        for (int i = 0; i < dof(); i++) {
            if (pre[i] != null) t = t.times(pre[i]);
            t = t.times(joint(i, theta[i]));
        }
        return t.times(flange);
    }

    /**
     * The arm with each link grown by its own strain: the pedestal (base origin to the first joint
     * point) by {@code strain[0]}, the link from joint point i to joint point i+1 by
     * {@code strain[i+1]} (0-based i), the last link (last joint point to the flange origin) by
     * {@code strain[n]}. Uniform expansion of a link scales every vector fixed in it, so the
     * segment between two points of the same link scales by (1 + strain); the axis directions do
     * not change. Points inboard of a link move with it (the chain is rebuilt from the base out).
     */
    public Arm grown(double[] strain) {
        int n = dof();
        double[][] pts = new double[n][];
        double[] prevOld = new double[3], prevNew = new double[3];
        for (int i = 0; i < n; i++) {
            double[] seg = Rigid.minus(points[i], prevOld);
            pts[i] = Rigid.plus(prevNew, Rigid.scale(seg, 1 + strain[i]));
            prevOld = points[i];
            prevNew = pts[i];
        }
        double[] fo = flange.p();
        double[] origin = Rigid.plus(prevNew, Rigid.scale(Rigid.minus(fo, prevOld), 1 + strain[n]));
        return new Arm(prismatic, pts, axes, new Rigid(flange.r(), origin));
    }

    /**
     * The arm with random geometric errors: each axis point moved by N(0, pointM) per component,
     * each axis tilted by N(0, axisRad) about two directions perpendicular to it, the flange frame
     * moved by N(0, pointM) and turned by N(0, axisRad) about each base axis.
     */
    public Arm perturbed(Random rng, double pointM, double axisRad) {
        int n = dof();
        double[][] pts = new double[n][], ax = new double[n][];
        for (int i = 0; i < n; i++) {
            pts[i] = Rigid.plus(points[i], gauss(rng, pointM));
            double[] tilt = gauss(rng, axisRad);
            double[] perp = Rigid.minus(tilt, Rigid.scale(axes[i], Rigid.dot(tilt, axes[i])));
            ax[i] = Rigid.unit(Rigid.plus(axes[i], perp));
        }
        double[] rot = gauss(rng, axisRad);
        double angle = Rigid.norm(rot);
        Rigid turn = angle > 0 ? Rigid.rotation(Rigid.unit(rot), angle, new double[3]) : Rigid.IDENTITY;
        Rigid f = new Rigid(turn.times(flange).r(), Rigid.plus(flange.p(), gauss(rng, pointM)));
        return new Arm(prismatic, pts, ax, f);
    }

    static double[] gauss(Random rng, double s) {
        return new double[] {s * rng.nextGaussian(), s * rng.nextGaussian(), s * rng.nextGaussian()};
    }

    static double[] vec(Vec3 v) { return v.toArray(); }

    private static double[][] deep(double[][] a) {
        double[][] out = new double[a.length][];
        for (int i = 0; i < a.length; i++) out[i] = a[i].clone();
        return out;
    }
}
