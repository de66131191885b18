package org.robopro.programs.sim;

import java.util.List;
import java.util.Optional;
import org.robopro.programs.rapid.SourcePos;

/**
 * The outcome of simulating a procedure: its motion, wait and I/O steps, a log of instructions
 * run as no-ops (TPWrite, ...), and notices: what the simulation could not do (an instruction it
 * does not know, kept in the program and reported once) or had to assume.
 */
public record Simulation(List<ProgramStep> steps, List<String> log, List<Notice> notices) {
    public Simulation {
        steps = List.copyOf(steps);
        log = List.copyOf(log);
        notices = List.copyOf(notices);
    }

    public Simulation(List<ProgramStep> steps, List<String> log) { this(steps, log, List.of()); }

    /** Something the simulation did not do or assumed, at the statement that caused it. */
    public record Notice(String step, Optional<SourcePos> source, String message) {
        @Override public String toString() { return step + source.map(s -> " (" + s + ")").orElse("") + ": " + message; }
    }
}
