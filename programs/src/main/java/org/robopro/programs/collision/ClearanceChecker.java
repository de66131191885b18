package org.robopro.programs.collision;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Locale;
import java.util.Optional;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.CellObject;
import org.robopro.models.PoseDescription;
import org.robopro.models.Vec3;
import org.robopro.programs.check.CheckReport;
import org.robopro.programs.check.Problem;
import org.robopro.programs.rapid.SourcePos;
import org.robopro.programs.sim.MoveStep;
import org.robopro.programs.sim.ProgramStep;

/**
 * Collision and clearance along a checked program: the robot's links as capsules (between
 * consecutive joint origins with a guessed radius, or each link's own, e.g. fitted to its mesh
 * by {@link CapsuleFit}), the tool as a capsule from the flange to the TCP, the cell's
 * objects as boxes and cylinder hulls, compared by {@link Gjk} at every path sample the path
 * check solved (MoveL/MoveC, 5 mm / 2 deg) and at joint steps of at most
 * {@link Options#maxJointStepRad} for MoveJ/MoveAbsJ. Self-collision between links that are not
 * within two joints of each other and are not already within a link radius in the zero pose
 * (structural closeness, as an SRDF's "default" pairs). The base link is not compared with the
 * cell, nor the first link with an object the robot stands on (one touching the base or first
 * link in the zero pose: its pedestal).
 * Thread-safe.
 */
public final class ClearanceChecker {
    /**
     * @param linkRadiusM     capsule radius of the arm's links between their joint origins, m, when
     *                        {@code linkCapsules} is empty (a guess: the robot description carries no link geometry)
     * @param toolRadiusM     capsule radius of the tool, m
     * @param maxJointStepRad largest joint change between samples of a joint motion
     * @param warnClearanceM  a move passing closer than this is a warning
     * @param linkCapsules    one capsule per link (0 = base, then link 1 .. n) in base coordinates at the
     *                        zero position, e.g. fitted to the link meshes by {@link CapsuleFit}; each moves
     *                        with its link; empty: the joint-origin segments with {@code linkRadiusM}
     */
    public record Options(double linkRadiusM, double toolRadiusM, double maxJointStepRad, double warnClearanceM,
                          List<Convex.Capsule> linkCapsules) {
        public Options {
            linkCapsules = List.copyOf(linkCapsules);
        }

        public Options(double linkRadiusM, double toolRadiusM, double maxJointStepRad, double warnClearanceM) {
            this(linkRadiusM, toolRadiusM, maxJointStepRad, warnClearanceM, List.of());
        }

        /** Radii from the robot's size: links 6 % of its characteristic length, tool 25 mm, 1 deg steps, 10 mm warning. */
        public static Options forRobot(KinematicModel model) {
            return new Options(0.06 * model.characteristicLength(), 0.025, Math.toRadians(1), 0.010);
        }

        /** These options with the links' own capsules (base coordinates, zero position; base link first). */
        public Options withLinkCapsules(List<Convex.Capsule> capsules) {
            return new Options(linkRadiusM, toolRadiusM, maxJointStepRad, warnClearanceM, capsules);
        }

        /** The link shapes in words, for reports. */
        public String linkShapes() {
            return linkCapsules.isEmpty()
                    ? String.format(java.util.Locale.ROOT, "links: capsules between joint origins, radius %.0f mm (guessed from the robot's size)", linkRadiusM * 1e3)
                    : "links: capsules fitted to the link meshes";
        }
    }

    /** A named shape of the cell in base coordinates. */
    public record Obstacle(String name, Convex shape) { }

    /** The smallest clearance met along one move and between which two shapes. */
    public record MoveClearance(String step, Optional<SourcePos> source, double minClearanceM, String closestPair) { }

    /** Collisions (ERROR) and near misses (WARNING) by move, and each move's smallest clearance. */
    public record Result(List<Problem> problems, List<MoveClearance> moves) {
        public Result {
            problems = List.copyOf(problems);
            moves = List.copyOf(moves);
        }
    }

    /**
     * The robot at one joint position (for a live view): its closest pair and every pair in
     * contact, in words ("link 3 - table"), and the same by part: {@code closestParts} the two
     * parts of the closest pair and {@code partClearanceM} each part's smallest clearance to
     * anything it is compared with. Parts are named as the workbench picks them: "link:K" (capsule
     * K joins joint origins K and K+1, so it moves with link K; 0 is the base link), "tool",
     * "object:NAME" (the cell object's name).
     */
    public record Snapshot(double minClearanceM, String closestPair, List<String> colliding, List<String> closestParts,
                           Map<String, Double> partClearanceM) {
        public Snapshot {
            colliding = List.copyOf(colliding);
            closestParts = List.copyOf(closestParts);
            partClearanceM = Map.copyOf(partClearanceM);
        }

        /** Parts in contact with something (clearance 0). */
        public List<String> collidingParts() {
            return partClearanceM.entrySet().stream().filter(e -> e.getValue() <= 0).map(Map.Entry::getKey).sorted().toList();
        }
    }

    private final KinematicModel model;
    private final List<Obstacle> obstacles;
    private final Options opt;
    private final boolean[][] allowedSelf;
    /** Per obstacle: the robot stands on it (its base or first link touches it in the zero pose), so those two links are not compared with it. */
    private final boolean[] stand;
    /** Inverse of each link's frame at the zero position: a zero-position shape moves by frame(q) * this. */
    private final Pose[] zeroInverse;

    /**
     * @param worldTbase where the robot stands in the cell
     * @param objects    the cell's objects (world coordinates); meshes are not compared (no hull kept)
     */
    public ClearanceChecker(KinematicModel model, Pose worldTbase, List<CellObject> objects, Options options) {
        this.model = model;
        this.opt = options;
        Pose[] zero = model.linkFrames(new double[model.dof()]);
        if (!options.linkCapsules().isEmpty() && options.linkCapsules().size() != zero.length - 1)
            throw new IllegalArgumentException("need " + (zero.length - 1) + " link capsules (base and each link), got " + options.linkCapsules().size());
        zeroInverse = new Pose[zero.length];
        for (int k = 0; k < zero.length; k++) zeroInverse[k] = zero[k].inverse();
        Pose baseTworld = worldTbase.inverse();
        List<Obstacle> obs = new ArrayList<>();
        for (CellObject o : objects) {
            Convex c = shape(o, baseTworld);
            if (c != null) obs.add(new Obstacle(o.name(), c));
        }
        this.obstacles = List.copyOf(obs);
        Convex[] home = robot(new double[model.dof()], Pose.IDENTITY);
        stand = new boolean[obstacles.size()];
        for (int k = 0; k < obstacles.size(); k++)
            stand[k] = Gjk.distance(home[0], obstacles.get(k).shape()) <= 0 || Gjk.distance(home[1], obstacles.get(k).shape()) <= 0;
        allowedSelf = new boolean[home.length][home.length];
        for (int i = 0; i < home.length; i++)
            for (int j = 0; j < home.length; j++)
                allowedSelf[i][j] = Math.abs(i - j) < 3 || Gjk.distance(home[i], home[j]) < opt.linkRadiusM();
    }

    /** The cell object as a convex shape in base coordinates; null for meshes. */
    static Convex shape(CellObject o, Pose baseTworld) {
        Pose p = baseTworld.times(pose(o.worldTobject()));
        Vec3 s = o.size();
        return switch (o.kind()) {
            case BOX -> new Convex.Box(p, s.times(0.5));
            case CYLINDER -> {
                List<Vec3> rim = new ArrayList<>();
                for (int k = 0; k < 32; k++) {
                    double t = 2 * Math.PI * k / 32;
                    for (double z : new double[] {-s.z() / 2, s.z() / 2})
                        rim.add(p.apply(new Vec3(s.x() / 2 * Math.cos(t), s.y() / 2 * Math.sin(t), z)));
                }
                yield new Convex.Hull(rim);
            }
            case MESH -> null;
        };
    }

    /** A cell file's pose as a transform. */
    public static Pose pose(PoseDescription d) {
        return Pose.fromQuaternion(d.qw(), d.qx(), d.qy(), d.qz(), d.position().x(), d.position().y(), d.position().z());
    }

    /**
     * Shapes of the robot at q: capsule k moves with link k (by default it joins joint origin k
     * and k+1, the last one the flange); then the tool.
     */
    Convex[] robot(double[] q, Pose flangeTtcp) {
        Pose[] f = model.linkFrames(q);
        Convex[] out = new Convex[f.length];
        for (int k = 0; k + 1 < f.length; k++) {
            if (opt.linkCapsules().isEmpty()) out[k] = new Convex.Capsule(f[k].position(), f[k + 1].position(), opt.linkRadiusM());
            else {
                Convex.Capsule c = opt.linkCapsules().get(k);
                Pose move = f[k].times(zeroInverse[k]);
                out[k] = new Convex.Capsule(move.apply(c.a()), move.apply(c.b()), c.radius());
            }
        }
        Pose flange = f[f.length - 1];
        out[f.length - 1] = new Convex.Capsule(flange.position(), flange.times(flangeTtcp).position(), opt.toolRadiusM());
        return out;
    }

    /** The robot's collision shapes at {@code q} in base coordinates, by part ("link:K", "tool"), for drawing them. */
    public Map<String, Convex.Capsule> robotShapes(double[] q, Pose flangeTtcp) {
        Convex[] r = robot(q, flangeTtcp);
        Map<String, Convex.Capsule> out = new java.util.LinkedHashMap<>();
        for (int k = 0; k < r.length; k++) out.put(part(k, r.length), (Convex.Capsule) r[k]);
        return out;
    }

    private String name(int k, int n) { return k == n - 1 ? "tool" : k == 0 ? "base link" : "link " + k; }

    private static String part(int k, int n) { return k == n - 1 ? "tool" : "link:" + k; }

    /** Clearance of the robot at {@code q} with a tool {@code flangeTtcp}. */
    public Snapshot at(double[] q, Pose flangeTtcp) {
        Convex[] r = robot(q, flangeTtcp);
        double best = Double.POSITIVE_INFINITY;
        String pair = "";
        List<String> bestParts = List.of();
        List<String> hits = new ArrayList<>();
        Map<String, Double> parts = new HashMap<>();
        for (int k = 1; k < r.length; k++)
            for (int n = 0; n < obstacles.size(); n++) {
                if (stand[n] && k <= 1) continue;
                Obstacle o = obstacles.get(n);
                double d = Gjk.distance(r[k], o.shape());
                parts.merge(part(k, r.length), d, Math::min);
                parts.merge("object:" + o.name(), d, Math::min);
                if (d < best) { best = d; pair = name(k, r.length) + " - " + o.name(); bestParts = List.of(part(k, r.length), "object:" + o.name()); }
                if (d <= 0) hits.add(name(k, r.length) + " - " + o.name());
            }
        for (int i = 0; i < r.length; i++)
            for (int j = i + 3; j < r.length; j++) {
                if (allowedSelf[i][j]) continue;
                double d = Gjk.distance(r[i], r[j]);
                parts.merge(part(i, r.length), d, Math::min);
                parts.merge(part(j, r.length), d, Math::min);
                if (d < best) { best = d; pair = name(i, r.length) + " - " + name(j, r.length); bestParts = List.of(part(i, r.length), part(j, r.length)); }
                if (d <= 0) hits.add(name(i, r.length) + " - " + name(j, r.length));
            }
        return new Snapshot(best, pair, hits, bestParts, parts);
    }

    /**
     * Sweeps every move of a checked run ({@code steps} and the {@code report} the path check
     * made of them, step for step) and reports collisions and the smallest clearance per move.
     * Each move's sweep is kept (by its joint path and tool, compared exactly; the 4096 most
     * recent), so checking an edited program again sweeps only the moves whose path changed.
     */
    public Result check(List<ProgramStep> steps, CheckReport report, Optional<double[]> qStart) {
        List<Problem> problems = new ArrayList<>();
        List<MoveClearance> moves = new ArrayList<>();
        double[] q = qStart.map(double[]::clone).orElse(null);
        for (int i = 0; i < steps.size() && i < report.steps().size(); i++) {
            if (!(steps.get(i) instanceof MoveStep m)) continue;
            CheckReport.StepResult r = report.steps().get(i);
            if (r.qEnd() == null) continue;
            List<double[]> path = new ArrayList<>();
            if (q == null) path.add(r.qEnd());
            else if (!r.samples().isEmpty()) { path.add(q); path.addAll(r.samples()); }
            else {
                double span = 0;
                for (int j = 0; j < q.length; j++) span = Math.max(span, Math.abs(r.qEnd()[j] - q[j]));
                int n = Math.max(1, (int) Math.ceil(span / opt.maxJointStepRad()));
                for (int k = 0; k <= n; k++) {
                    double[] qk = new double[q.length];
                    for (int j = 0; j < q.length; j++) qk[j] = q[j] + (r.qEnd()[j] - q[j]) * k / n;
                    path.add(qk);
                }
            }
            Sweep sw = sweep(path, m.flangeTtcp());
            double best = sw.best;
            String pair = sw.pair;
            boolean hit = sw.hit != null;
            if (hit)
                problems.add(new Problem(Problem.Severity.ERROR, Problem.Kind.COLLISION, m.label(), m.targetName(), m.source(), sw.hit));
            if (!hit && best < opt.warnClearanceM())
                problems.add(new Problem(Problem.Severity.WARNING, Problem.Kind.COLLISION, m.label(), m.targetName(), m.source(),
                        String.format(Locale.ROOT, "passes %.1f mm from a collision (%s), closer than %.0f mm", best * 1e3, pair, opt.warnClearanceM() * 1e3)));
            moves.add(new MoveClearance(m.label(), m.source(), best, pair));
            q = r.qEnd();
        }
        return new Result(problems, moves);
    }

    /** One move's sweep: smallest clearance, its pair, and the first contact in words (null: none). */
    private record Sweep(double best, String pair, String hit) { }

    /** Sweeps already made by this checker (so for this cell), by path and tool: an edited program sweeps only its changed moves. */
    private final Map<SweepKey, Sweep> sweeps = new java.util.LinkedHashMap<>(256, 0.75f, true) {
        @Override protected boolean removeEldestEntry(Map.Entry<SweepKey, Sweep> eldest) { return size() > 4096; }
    };

    /** A swept path (joint values, compared exactly) and the tool. */
    private record SweepKey(List<double[]> path, Pose tool, int hash) {
        SweepKey(List<double[]> path, Pose tool) { this(path, tool, hashOf(path, tool)); }

        private static int hashOf(List<double[]> path, Pose tool) {
            int h = tool.hashCode();
            for (double[] q : path) h = 31 * h + java.util.Arrays.hashCode(q);
            return h;
        }

        @Override public int hashCode() { return hash; }

        @Override
        public boolean equals(Object o) {
            if (!(o instanceof SweepKey k) || k.hash != hash || k.path.size() != path.size() || !k.tool.equals(tool)) return false;
            for (int i = 0; i < path.size(); i++) if (!java.util.Arrays.equals(path.get(i), k.path.get(i))) return false;
            return true;
        }
    }

    private Sweep sweep(List<double[]> path, Pose tool) {
        SweepKey key = new SweepKey(path, tool);
        synchronized (sweeps) {
            Sweep s = sweeps.get(key);
            if (s != null) return s;
        }
        double best = Double.POSITIVE_INFINITY;
        String pair = "", hit = null;
        for (int k = 0; k < path.size(); k++) {
            Snapshot s = at(path.get(k), tool);
            if (s.minClearanceM() < best) { best = s.minClearanceM(); pair = s.closestPair(); }
            if (hit == null && !s.colliding().isEmpty())
                hit = String.format(Locale.ROOT, "collision %s at %.0f%% of the move", String.join(", ", s.colliding()),
                        path.size() == 1 ? 100.0 : 100.0 * k / (path.size() - 1));
        }
        Sweep out = new Sweep(best, pair, hit);
        synchronized (sweeps) { sweeps.put(key, out); }
        return out;
    }

    /**
     * Objects placed through one another: each pair whose shapes overlap by more than
     * {@code toleranceM} (objects resting on each other touch and are fine). Meshes are not compared.
     */
    public static List<String> placement(List<CellObject> objects, double toleranceM) {
        List<String> out = new ArrayList<>();
        List<Convex> shapes = new ArrayList<>();
        for (CellObject o : objects) {
            Convex c = shape(shrunk(o, toleranceM), Pose.IDENTITY);
            shapes.add(c);
        }
        for (int i = 0; i < objects.size(); i++)
            for (int j = i + 1; j < objects.size(); j++)
                if (shapes.get(i) != null && shapes.get(j) != null && Gjk.distance(shapes.get(i), shapes.get(j)) <= 0)
                    out.add(objects.get(i).name() + " is placed through " + objects.get(j).name());
        return out;
    }

    private static CellObject shrunk(CellObject o, double t) {
        if (o.kind() == CellObject.Kind.MESH) return o;
        Vec3 s = o.size();
        Vec3 smaller = new Vec3(Math.max(1e-9, s.x() - 2 * t), Math.max(1e-9, s.y() - 2 * t), Math.max(1e-9, s.z() - 2 * t));
        return new CellObject(o.name(), o.kind(), o.worldTobject(), smaller, o.colour(), o.meshPath(), o.meshScale());
    }

    /** The cell's shapes the robot is compared with (base coordinates). */
    public List<Obstacle> obstacles() { return obstacles; }
}
