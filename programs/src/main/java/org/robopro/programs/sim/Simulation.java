package org.robopro.programs.sim;

import java.util.List;

/** The outcome of simulating a procedure: its motion and wait steps and a log of instructions run as no-ops (TPWrite, ...). */
public record Simulation(List<ProgramStep> steps, List<String> log) {
    public Simulation {
        steps = List.copyOf(steps);
        log = List.copyOf(log);
    }
}
