package org.robopro.app.cli;

import java.io.PrintWriter;
import java.io.StringWriter;
import picocli.CommandLine;

/**
 * Runs the robopro command line in-process, as {@code Main.run} does, and keeps what it printed.
 * By default output accumulates over runs; {@code freshPerRun} keeps only the last run's.
 */
public final class CliHarness {
    private final boolean freshPerRun;
    private StringWriter out = new StringWriter(), err = new StringWriter();

    public CliHarness() { this(false); }

    public CliHarness(boolean freshPerRun) { this.freshPerRun = freshPerRun; }

    /** Runs {@code robopro args...} and returns its exit code. */
    public int run(String... args) {
        if (freshPerRun) {
            out = new StringWriter();
            err = new StringWriter();
        }
        CommandLine cl = RoboproCommand.commandLine();
        cl.setOut(new PrintWriter(out, true));
        cl.setErr(new PrintWriter(err, true));
        return cl.execute(args);
    }

    /** Standard output so far. */
    public String out() { return out.toString(); }

    /** Standard error so far. */
    public String err() { return err.toString(); }
}
