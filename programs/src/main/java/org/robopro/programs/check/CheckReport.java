package org.robopro.programs.check;

import java.util.List;
import java.util.Locale;
import java.util.Optional;
import org.robopro.programs.rapid.SourcePos;

/**
 * The result of checking a program along its path: every problem by instruction and target,
 * the joint values reached at the end of each motion, and the estimated cycle time.
 *
 * @param problems      every problem found, in program order
 * @param steps         per-step timing and end joint values
 * @param cycleTimeS    estimated cycle time, s (stop points at every target: an upper bound)
 * @param assumptions   how the estimate was made (acceleration assumption, ...)
 * @param io            the I/O time line: every signal change (set by the program, by a trigger,
 *                      an input following an output, the arc) in time order
 * @param arcTimeS      time with the welding arc on, s
 * @param cycleTimeStopsS the cycle time if every target were a stop point (fine), s
 */
public record CheckReport(List<Problem> problems, List<StepResult> steps, double cycleTimeS, String assumptions, List<IoEvent> io,
                          double arcTimeS, double cycleTimeStopsS) {
    public CheckReport {
        problems = List.copyOf(problems);
        steps = List.copyOf(steps);
        io = List.copyOf(io);
    }

    public CheckReport(List<Problem> problems, List<StepResult> steps, double cycleTimeS, String assumptions) {
        this(problems, steps, cycleTimeS, assumptions, List.of(), 0, cycleTimeS);
    }

    /** A signal takes {@code value} at {@code timeS} after the cycle starts, because of {@code step}. */
    public record IoEvent(double timeS, String signal, double value, String step, Optional<SourcePos> source) {
        @Override public String toString() {
            return String.format(Locale.ROOT, "%9.3f s  %-16s = %-6s %s%s", timeS, signal, value == Math.rint(value) && Math.abs(value) < 1e15
                    ? String.valueOf((long) value) : String.valueOf(value), step, source.map(s -> " (" + s + ")").orElse(""));
        }
    }

    /**
     * One step's outcome: its label, target, duration (s), the joint values (rad) at its end (null
     * when unreachable), the number of interpolated points, and the joint values at those points
     * as checked (MoveL/MoveC; empty otherwise): playback shows exactly the path that was checked;
     * at a fly-by point, how far the blended corner passes from the target (m; 0 at stop points).
     */
    public record StepResult(String step, String target, double durationS, double[] qEnd, int interpolationPoints, List<double[]> samples,
                             double cornerDeviationM) {
        public StepResult {
            samples = List.copyOf(samples);
        }

        public StepResult(String step, String target, double durationS, double[] qEnd, int interpolationPoints, List<double[]> samples) {
            this(step, target, durationS, qEnd, interpolationPoints, samples, 0);
        }

        public StepResult(String step, String target, double durationS, double[] qEnd, int interpolationPoints) {
            this(step, target, durationS, qEnd, interpolationPoints, List.of());
        }
    }

    public boolean hasErrors() {
        return problems.stream().anyMatch(p -> p.severity() == Problem.Severity.ERROR);
    }

    /** The report as text, one problem a line. */
    public String format() {
        StringBuilder b = new StringBuilder();
        for (StepResult s : steps)
            b.append(String.format(Locale.ROOT, "%-40s %8.3f s  %d points%s%n", s.step(), s.durationS(), s.interpolationPoints(),
                    s.cornerDeviationM() > 0 ? String.format(Locale.ROOT, "  corner passes %.2f mm from the target", s.cornerDeviationM() * 1e3) : ""));
        b.append(String.format(Locale.ROOT, "cycle time estimate: %.3f s (%s)%n", cycleTimeS, assumptions));
        b.append(String.format(Locale.ROOT, "cycle time with a stop at every target: %.3f s%n", cycleTimeStopsS));
        if (!io.isEmpty()) {
            b.append("I/O time line:\n");
            for (IoEvent e : io) b.append(e).append('\n');
        }
        if (arcTimeS > 0) b.append(String.format(Locale.ROOT, "arc on: %.3f s of %.3f s%n", arcTimeS, cycleTimeS));
        if (problems.isEmpty()) b.append("no problems found\n");
        for (Problem p : problems) b.append(p).append('\n');
        return b.toString();
    }
}
