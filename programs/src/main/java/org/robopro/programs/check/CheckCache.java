package org.robopro.programs.check;

import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import org.robopro.kinematics.ConfData;
import org.robopro.kinematics.Pose;
import org.robopro.programs.Move;
import org.robopro.programs.SpeedData;
import org.robopro.programs.sim.MoveStep;

/**
 * What earlier path checks found for each motion, so that checking an edited program solves
 * again only the motions whose inputs changed. A motion's checked path, duration and problems
 * depend only on the joint values it starts from and on the motion itself as resolved by the
 * interpreter (kind, target and circle poses in base coordinates, so the tool and work object
 * are in them, confdata, MoveAbsJ joints, speed, tool frame, target names), and on the checker
 * (robot model and options): that is the key, compared exactly (bit for bit), so a check with
 * the cache gives the same report as one without. An edit changes the key of the edited motion;
 * the motions after it hit the cache again as soon as the start state they see is the one they
 * saw before (a MoveJ or a target solved with its confdata ends where it ended, whatever came
 * before). Joint-space corners are kept too, keyed by the two motions' cached outcomes; Cartesian
 * corners, the time line and I/O are recomputed on every check (they are cheap and depend on
 * neighbours). Labels and source positions are not part of the key: a motion moved
 * to another line reuses its result with its new label.
 *
 * <p>Bounded: the least recently used motions are dropped beyond twice the longest program
 * checked (at least 1024). Thread-safe; one cache per checker is the intended use (a cache
 * used with another robot model or other options starts empty).
 */
public final class CheckCache {
    private final Map<Key, Entry> map = new LinkedHashMap<>(256, 0.75f, true) {
        @Override protected boolean removeEldestEntry(Map.Entry<Key, Entry> eldest) { return size() > capacity; }
    };
    private final Map<CornerKey, double[]> corners = new LinkedHashMap<>(256, 0.75f, true) {
        @Override protected boolean removeEldestEntry(Map.Entry<CornerKey, double[]> eldest) { return size() > capacity; }
    };
    private int capacity = 1024;
    private Object owner;
    private long hits, misses;

    /** A cached motion: its outcome and the problems found, labelled as when first checked. */
    record Entry(PathChecker.Outcome outcome, List<Problem> problems) {
        Entry { problems = List.copyOf(problems); }
    }

    /** Motions found in the cache, over every check made with it. */
    public synchronized long hits() { return hits; }

    /** Motions solved because they were not in the cache, over every check made with it. */
    public synchronized long misses() { return misses; }

    /** Forgets everything (a robot or option change does this by itself). */
    public synchronized void clear() {
        map.clear();
        corners.clear();
    }

    /** Cached motions. */
    public synchronized int size() { return map.size(); }

    synchronized void begin(Object checker, int motions) {
        if (!Objects.equals(owner, checker)) {
            map.clear();
            corners.clear();
            owner = checker;
        }
        capacity = Math.max(capacity, 2 * motions);
    }

    synchronized Entry get(Key k) {
        Entry e = map.get(k);
        if (e == null) misses++;
        else hits++;
        return e;
    }

    synchronized void put(Key k, Entry e) { map.put(k, e); }

    synchronized double[] corner(CornerKey k) { return corners.get(k); }

    synchronized void putCorner(CornerKey k, double[] c) { corners.put(k, c); }

    /**
     * A joint-space corner: the two motions' outcomes by identity (a check that found both in the
     * cache hands over the same objects, a motion solved again a new one), where the first starts,
     * and what of the motions the corner reads (zone, tools, kinds).
     */
    static final class CornerKey {
        private final Object a, b;
        private final double[] q0;
        private final Object zone, toolA, toolB, kindA, kindB;
        private final int hash;

        CornerKey(Object a, Object b, double[] q0, MoveStep m, MoveStep n) {
            this.a = a;
            this.b = b;
            this.q0 = q0.clone();
            zone = m.zone();
            toolA = m.flangeTtcp();
            toolB = n.flangeTtcp();
            kindA = m.kind();
            kindB = n.kind();
            hash = Objects.hash(System.identityHashCode(a), System.identityHashCode(b), Arrays.hashCode(this.q0), zone, toolA, toolB, kindA, kindB);
        }

        @Override public int hashCode() { return hash; }

        @Override
        public boolean equals(Object o) {
            return o instanceof CornerKey k && hash == k.hash && a == k.a && b == k.b && Arrays.equals(q0, k.q0) && zone.equals(k.zone)
                    && toolA.equals(k.toolA) && toolB.equals(k.toolB) && kindA == k.kindA && kindB == k.kindB;
        }
    }

    /** Everything a motion's check reads, compared exactly. */
    static final class Key {
        private final double[] qStart;
        private final Move.Kind kind;
        private final String target;
        private final Optional<String> circ;
        private final Optional<Pose> flange, tcp, flangeCirc, tcpCirc;
        private final Optional<ConfData> conf;
        private final double[] absJ;
        private final SpeedData speed;
        private final Pose flangeTtcp;
        private final int hash;

        Key(MoveStep m, double[] qStart) {
            this.qStart = qStart == null ? null : qStart.clone();
            kind = m.kind();
            target = m.targetName();
            circ = m.circName();
            flange = m.baseTflange();
            tcp = m.baseTtcp();
            flangeCirc = m.baseTflangeCirc();
            tcpCirc = m.baseTtcpCirc();
            conf = m.conf();
            absJ = m.q().orElse(null);
            speed = m.speed();
            flangeTtcp = m.flangeTtcp();
            hash = Objects.hash(Arrays.hashCode(this.qStart), kind, target, circ, flange, tcp, flangeCirc, tcpCirc, conf,
                    Arrays.hashCode(absJ), speed, flangeTtcp);
        }

        @Override public int hashCode() { return hash; }

        @Override
        public boolean equals(Object o) {
            return o instanceof Key k && hash == k.hash && Arrays.equals(qStart, k.qStart) && kind == k.kind && target.equals(k.target)
                    && circ.equals(k.circ) && flange.equals(k.flange) && tcp.equals(k.tcp) && flangeCirc.equals(k.flangeCirc)
                    && tcpCirc.equals(k.tcpCirc) && conf.equals(k.conf) && Arrays.equals(absJ, k.absJ) && speed.equals(k.speed)
                    && flangeTtcp.equals(k.flangeTtcp);
        }
    }
}
