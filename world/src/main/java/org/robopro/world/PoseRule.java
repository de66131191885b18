package org.robopro.world;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.robopro.models.JointDescription;
import org.robopro.models.RobotDescription;

/**
 * Where a person planning a campaign would put the robot, knowing only its robot file: each
 * controller value uniform in the inner 90 % of its range; a pose is refused when the flange is
 * below the base plane, within 0.25 m of the first axis (inside the robot's own column), or close
 * to a singularity (smallest singular value of the space Jacobian, positions divided by the
 * reach, below 0.05); on request, also where a linkage's joint leaves its limits as the arm's own
 * angle. The Jacobian columns are the joint twists carried to the pose (Lynch &amp;
 * Park, Modern Robotics, §5.1.1), written here from the robot file's axes.
 */
final class PoseRule {
    private final RobotDescription robot;
    private final Arm arm;
    private final double[][] coupling;
    private final double reach;
    /** Per joint: kept within its limits as the arm's angle θ_j too (a linkage's joint, when asked); else false. */
    private final boolean[] armAngleLimited;

    PoseRule(RobotDescription robot) { this(robot, false); }

    /**
     * With {@code linkageRange}, a pose is also refused where a joint its linkage couples (θ_j = Σ C[j][l] q_l
     * with other drives in it: θ3 = q3 − q2 on a parallel arm) has its arm angle θ_j outside the joint's limits.
     */
    PoseRule(RobotDescription robot, boolean linkageRange) {
        this.robot = robot;
        this.arm = Arm.of(robot);
        this.coupling = robot.couplingMatrix();
        this.armAngleLimited = new boolean[coupling.length];
        for (int j = 0; linkageRange && j < coupling.length; j++)
            for (int l = 0; l < coupling.length; l++) armAngleLimited[j] |= l != j && coupling[j][l] != 0;
        double[] zero = arm.flange(new double[robot.dof()]).p();
        double r = 0.1;
        for (double[] p : arm.points()) r = Math.max(r, Rigid.norm(Rigid.minus(p, zero)));
        this.reach = r;
    }

    List<double[]> sample(int n, Random rng) {
        List<double[]> out = new ArrayList<>(n);
        int tries = 0;
        while (out.size() < n) {
            if (++tries > 200 * n + 1000) throw new IllegalStateException("no acceptable poses for " + robot.name());
            double[] q = new double[robot.dof()];
            for (int i = 0; i < q.length; i++) q[i] = draw(i, rng);
            if (acceptable(q)) out.add(q);
        }
        return out;
    }

    /**
     * A sequence of n poses that moves only {@code moved} joints at a time (a campaign planned joint
     * by joint): the first pose is drawn whole; each next one redraws that many joints, chosen at
     * random, in the inner 90 % of their ranges and keeps the others where they were.
     */
    List<double[]> walk(int n, int moved, Random rng) {
        List<double[]> out = new ArrayList<>(sample(1, rng));
        double[] at = out.get(0);
        int dof = robot.dof();
        while (out.size() < n) {
            double[] q = null;
            for (int tries = 0; q == null; tries++) {
                if (tries > 100_000) throw new IllegalStateException("no acceptable walk for " + robot.name());
                double[] c = at.clone();
                List<Integer> joints = new ArrayList<>();
                for (int i = 0; i < dof; i++) joints.add(i);
                java.util.Collections.shuffle(joints, rng);
                for (int k = 0; k < Math.min(dof, tries < 200 ? moved : dof); k++) c[joints.get(k)] = draw(joints.get(k), rng);
                if (acceptable(c)) q = c;
            }
            out.add(q);
            at = q;
        }
        return out;
    }

    /** Joint i's value uniform in the inner 90 % of its range (±180° when the file gives none). */
    private double draw(int i, Random rng) {
        JointDescription j = robot.joints().get(i);
        double lo = j.min(), hi = j.max();
        if (!(hi > lo) || !Double.isFinite(lo) || !Double.isFinite(hi)) { lo = -Math.PI; hi = Math.PI; }
        return 0.5 * (lo + hi) + 0.45 * (hi - lo) * (2 * rng.nextDouble() - 1);
    }

    boolean acceptable(double[] q) {
        double[] theta = WorldRobot.times(coupling, q);
        for (int j = 0; j < theta.length; j++) {
            JointDescription jd = robot.joints().get(j);
            if (armAngleLimited[j] && (theta[j] < jd.min() || theta[j] > jd.max())) return false;
        }
        Rigid[] body = arm.bodies(theta);
        double[] f = body[body.length - 1].times(arm.flange()).p();
        if (f[2] < 0) return false;
        double[] w0 = arm.axes()[0], d = Rigid.minus(f, arm.points()[0]);
        if (Rigid.norm(Rigid.minus(d, Rigid.scale(w0, Rigid.dot(d, w0)))) < 0.25) return false;
        return smallestSingular(body, f) >= 0.05;
    }

    private double smallestSingular(Rigid[] body, double[] f) {
        int n = body.length;
        double[][] jac = new double[6][n];
        boolean[] prismatic = arm.prismatic();
        double[][] pts = arm.points(), axes = arm.axes();
        for (int i = 0; i < n; i++) {
            Rigid before = i == 0 ? Rigid.IDENTITY : body[i - 1];
            double[] w = before.rotate(axes[i]), p = before.apply(pts[i]);
            double[] v = prismatic[i] ? w : Rigid.cross(w, Rigid.minus(f, p));
            for (int k = 0; k < 3; k++) {
                jac[k][i] = v[k] / reach;
                jac[3 + k][i] = prismatic[i] ? 0 : w[k];
            }
        }
        // Smallest eigenvalue of J^T J (n x n) by cyclic Jacobi rotations; its root is the smallest singular value.
        double[][] a = new double[n][n];
        for (int i = 0; i < n; i++) for (int j = 0; j < n; j++) for (int k = 0; k < 6; k++) a[i][j] += jac[k][i] * jac[k][j];
        for (int sweep = 0; sweep < 50; sweep++) {
            double off = 0;
            for (int i = 0; i < n; i++) for (int j = i + 1; j < n; j++) off += a[i][j] * a[i][j];
            if (off < 1e-24) break;
            for (int p = 0; p < n; p++)
                for (int r = p + 1; r < n; r++) {
                    if (Math.abs(a[p][r]) < 1e-300) continue;
                    double th = 0.5 * Math.atan2(2 * a[p][r], a[r][r] - a[p][p]);
                    double c = Math.cos(th), s = Math.sin(th);
                    for (int k = 0; k < n; k++) {
                        double akp = a[k][p], akr = a[k][r];
                        a[k][p] = c * akp - s * akr;
                        a[k][r] = s * akp + c * akr;
                    }
                    for (int k = 0; k < n; k++) {
                        double apk = a[p][k], ark = a[r][k];
                        a[p][k] = c * apk - s * ark;
                        a[r][k] = s * apk + c * ark;
                    }
                }
        }
        double min = Double.MAX_VALUE;
        for (int i = 0; i < n; i++) min = Math.min(min, a[i][i]);
        return Math.sqrt(Math.max(0, min));
    }
}
