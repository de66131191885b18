package org.robopro.app;

import org.robopro.app.cli.Failures;
import org.robopro.app.cli.RoboproCommand;
import picocli.CommandLine;

/** Entry point of the {@code robopro} command line and workbench. */
public final class Main {
    private Main() { }

    public static void main(String[] args) {
        System.exit(run(args));
    }

    /** Runs the command line and returns its exit code (tests call this). */
    public static int run(String... args) {
        CommandLine cl = RoboproCommand.commandLine();
        try {
            return cl.execute(args);
        } catch (Throwable t) { // errors (out of memory, stack) pass picocli's handler: still one line and a log
            return Failures.report(t, cl.getErr());
        } finally {
            // main() ends with System.exit: output a command print()ed without a newline must not be lost.
            cl.getOut().flush();
            cl.getErr().flush();
        }
    }
}
