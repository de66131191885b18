package org.robopro.app.workbench;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import org.robopro.app.workbench.model.ShippedMeshes;
import org.robopro.app.workbench.model.WorkbenchModel;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.CellDescription;
import org.robopro.programs.collision.ClearanceChecker;
import org.robopro.programs.collision.Convex;

/**
 * Collision and clearance of the robot where it stands now, for the live view while jogging or
 * scrubbing: the programs module's {@link ClearanceChecker} (links and tool as capsules, the
 * cell's boxes and cylinders, self-collision) at the model's joint values. The checker is built
 * again only when the robot, its placement or the cell's objects change; a reading is computed
 * at most once per joint change (a few dozen GJK distance queries, well under a millisecond), so
 * the scene can ask every frame. Robots without a kinematics-module model have no reading.
 * Thread-safe.
 */
public final class LiveClearance {
    /** Parts closer than this to something are shown as near (amber); in contact, colliding (red). */
    public static final double NEAR_M = 0.050;

    /** How close a part is to a collision. */
    public enum Level { NEAR, COLLIDING }

    /** The robot at one joint position: the checker's snapshot and the parts to highlight. */
    public record Reading(double[] q, ClearanceChecker.Snapshot snapshot, List<String> placement) {
        public Reading { q = q.clone(); placement = List.copyOf(placement); }

        @Override public double[] q() { return q.clone(); }

        public boolean colliding() { return !snapshot.colliding().isEmpty(); }

        /** Parts ("link:K", "tool", "object:ID") in contact or within {@link #NEAR_M}, most severe first. */
        public Map<String, Level> highlights() {
            Map<String, Level> out = new LinkedHashMap<>();
            snapshot.partClearanceM().entrySet().stream().sorted(Map.Entry.comparingByValue()).forEach(e -> {
                if (e.getValue() <= 0) out.put(e.getKey(), Level.COLLIDING);
                else if (e.getValue() < NEAR_M) out.put(e.getKey(), Level.NEAR);
            });
            return out;
        }

        /**
         * One line for a status bar: the collision, or the smallest clearance and between what;
         * then the first cell object placed through another, if any.
         */
        public String text() {
            ClearanceChecker.Snapshot s = snapshot;
            String robot;
            if (!s.colliding().isEmpty()) robot = "COLLISION: " + String.join(", ", s.colliding());
            else if (!Double.isFinite(s.minClearanceM())) robot = "clearance: nothing to compare";
            else robot = String.format(Locale.ROOT, "clearance %.0f mm (%s)", s.minClearanceM() * 1e3, s.closestPair());
            if (placement.isEmpty()) return robot;
            return robot + " | WARNING: " + placement.get(0) + (placement.size() > 1 ? " (and " + (placement.size() - 1) + " more)" : "");
        }
    }

    private final WorkbenchModel model;
    private Object[] builtFor;
    private ClearanceChecker checker;
    private long readAt = -1;
    private Reading last;

    public LiveClearance(WorkbenchModel model) { this.model = model; }

    /** The reading at the model's current joints (computed once per joint or cell change); empty without a kinematic model. */
    public Optional<Reading> current() {
        long jv = model.jointVersion();
        synchronized (this) {
            Optional<ClearanceChecker> c = checker();
            if (c.isEmpty()) return Optional.empty();
            if (jv != readAt || last == null) {
                last = read(c.get(), model.q());
                readAt = jv;
            }
            return Optional.of(last);
        }
    }

    /** The reading at joint values {@code q} (rad) with the mounted tool; empty without a kinematic model. */
    public synchronized Optional<Reading> at(double[] q) {
        return checker().map(c -> read(c, q));
    }

    /** The robot's collision shapes ("link:K", "tool") at {@code q} in base coordinates; empty without a kinematic model. */
    public synchronized Map<String, Convex.Capsule> robotShapes(double[] q) {
        return checker().map(c -> c.robotShapes(q, model.tool().flangeTtcp())).orElse(Map.of());
    }

    private Reading read(ClearanceChecker c, double[] q) { return new Reading(q, c.at(q, model.tool().flangeTtcp()), placement); }

    /** Objects that overlap by more than this are placed through one another (resting objects touch). */
    private static final double PLACEMENT_TOLERANCE_M = 0.001;
    private List<String> placement = List.of();

    /**
     * The checker for the model's robot, placement and objects, built again when any of them
     * changed (the program check sweeps its moves with it); empty without a kinematic model.
     */
    public synchronized Optional<ClearanceChecker> checker() {
        var k = model.kinematics();
        Pose worldTbase = model.worldTbase();
        List<?> objects = model.objects();
        Object[] key = {k, worldTbase, objects};
        if (builtFor == null || builtFor[0] != key[0] || !builtFor[1].equals(key[1]) || !builtFor[2].equals(key[2])) {
            builtFor = key;
            last = null;
            Optional<KinematicModel> km = k.kinematicModel();
            CellDescription cell = ProjectStore.toCell(model.snapshot());
            placement = ClearanceChecker.placement(cell.objects(), PLACEMENT_TOLERANCE_M);
            checker = km.map(m -> new ClearanceChecker(m, worldTbase, cell.objects(), ShippedMeshes.collisionOptions(k.description(), m)))
                    .orElse(null);
        }
        return Optional.ofNullable(checker);
    }
}
