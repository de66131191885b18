package org.robopro.app.cli;

import java.nio.file.Path;
import org.robopro.models.OutputSet;
import picocli.CommandLine.Option;

/**
 * Mixin {@code --out DIR [--force]} of the commands that write a folder of results (simulate,
 * calibrate, diagnose): existing files are replaced only with {@code --force} (AtomicFiles refuses
 * otherwise), so a user's earlier results are never overwritten silently.
 */
public final class OutputDirOptions {
    @Option(names = "--out", required = true, paramLabel = "DIR", description = "output folder")
    Path out;

    @Option(names = "--force", description = "replace existing files in DIR")
    boolean force;

    /** The file {@code name} in the output folder. */
    Path file(String name) { return out.resolve(name); }

    Path dir() { return out; }

    /** A result set for the folder: written whole or not at all (see {@link OutputSet}). */
    OutputSet set() { return OutputSet.in(out, force); }

    boolean force() { return force; }
}
