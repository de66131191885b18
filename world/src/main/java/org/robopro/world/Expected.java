package org.robopro.world;

import java.util.List;
import java.util.Set;

/**
 * The answer a scenario expects from a diagnosis: the physical families it must name with their
 * joints, or that the structure is outside every family (it must be located, never named), or
 * that there is nothing to claim.
 */
public record Expected(Verdict verdict, List<Claim> claims) {
    public Expected {
        claims = List.copyOf(claims);
        if ((verdict == Verdict.NAMED) == claims.isEmpty()) throw new IllegalArgumentException(verdict + " with claims " + claims);
    }

    public enum Verdict {
        /** The listed families must be named, on their joints, and nothing else. */
        NAMED,
        /** A structure the catalogue does not hold: it must be located (where it lives), and no family named. */
        OUTSIDE,
        /** Only geometric errors and noise: nothing may be claimed. */
        NULL
    }

    /**
     * A physical family in words, and the names the diagnosis uses for it (calibration's effect
     * vocabulary: docs/diagnosis.md). The mapping lives here only, so that the world's physics and
     * the estimator's names meet in one place.
     */
    public enum Family {
        TRANSMISSION_ERROR("transmission error of a reducer (periodic in the joint angle)", Set.of("gear-periodic")),
        LOST_MOTION("lost motion (backlash) lagging the motor", Set.of("backlash")),
        GRAVITY_ELASTICITY("joint elasticity under gravity", Set.of("joint-compliance")),
        THERMAL_GROWTH("thermal growth of the links and instrument drift",
                Set.of("thermal-expansion", "thermal-link", "thermal-drift", "instrument-drift")),
        GEAR_RATIO("gear-ratio (joint scale) error", Set.of("joint-scale")),
        CROSS_COUPLING("cross-coupling between drives", Set.of("joint-coupling"));

        public final String words;
        public final Set<String> diagnosisNames;

        Family(String words, Set<String> diagnosisNames) {
            this.words = words;
            this.diagnosisNames = diagnosisNames;
        }

        /** The family a diagnosis effect name belongs to, or null for a name outside every family. */
        public static Family ofDiagnosisName(String name) {
            for (Family f : values()) if (f.diagnosisNames.contains(name)) return f;
            return null;
        }

        /**
         * The family a label names: its constant's name in any case with '-' or ' ' for '_'
         * ("lost-motion", "LOST_MOTION"), its words, or one of its diagnosis names ("backlash");
         * null when none matches.
         */
        public static Family parse(String text) {
            if (text == null) return null;
            String t = text.strip();
            for (Family f : values())
                if (f.name().equalsIgnoreCase(t.replace('-', '_').replace(' ', '_')) || f.words.equalsIgnoreCase(t)) return f;
            return ofDiagnosisName(t);
        }

        /** True for families that act on no particular joint (the claim's joints are not compared). */
        public boolean jointless() { return this == THERMAL_GROWTH; }
    }

    /** A family on its joints (1-based; empty when the family has none). For a coupling: target, then source. */
    public record Claim(Family family, List<Integer> joints) {
        public Claim { joints = List.copyOf(joints); }

        @Override public String toString() {
            return family.name().toLowerCase(java.util.Locale.ROOT).replace('_', '-') + (joints.isEmpty() ? "" : " j" + joints);
        }
    }

    public static Expected none() { return new Expected(Verdict.NULL, List.of()); }

    public static Expected outside() { return new Expected(Verdict.OUTSIDE, List.of()); }

    public static Expected named(Claim... c) { return new Expected(Verdict.NAMED, List.of(c)); }

    public static Claim claim(Family f, Integer... joints) { return new Claim(f, List.of(joints)); }
}
