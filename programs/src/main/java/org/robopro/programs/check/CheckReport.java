package org.robopro.programs.check;

import java.util.List;
import java.util.Locale;

/**
 * The result of checking a program along its path: every problem by instruction and target,
 * the joint values reached at the end of each motion, and the estimated cycle time.
 *
 * @param problems      every problem found, in program order
 * @param steps         per-step timing and end joint values
 * @param cycleTimeS    estimated cycle time, s (stop points at every target: an upper bound)
 * @param assumptions   how the estimate was made (acceleration assumption, ...)
 */
public record CheckReport(List<Problem> problems, List<StepResult> steps, double cycleTimeS, String assumptions) {
    public CheckReport {
        problems = List.copyOf(problems);
        steps = List.copyOf(steps);
    }

    /** One step's outcome: its label, target, duration (s) and the joint values (rad) at its end (null when unreachable). */
    public record StepResult(String step, String target, double durationS, double[] qEnd, int interpolationPoints) { }

    public boolean hasErrors() {
        return problems.stream().anyMatch(p -> p.severity() == Problem.Severity.ERROR);
    }

    /** The report as text, one problem a line. */
    public String format() {
        StringBuilder b = new StringBuilder();
        for (StepResult s : steps)
            b.append(String.format(Locale.ROOT, "%-40s %8.3f s  %d points%n", s.step(), s.durationS(), s.interpolationPoints()));
        b.append(String.format(Locale.ROOT, "cycle time estimate: %.3f s (%s)%n", cycleTimeS, assumptions));
        if (problems.isEmpty()) b.append("no problems found\n");
        for (Problem p : problems) b.append(p).append('\n');
        return b.toString();
    }
}
