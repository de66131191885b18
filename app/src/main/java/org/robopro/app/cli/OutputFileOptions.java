package org.robopro.app.cli;

import java.nio.file.Path;
import picocli.CommandLine.Option;

/**
 * Mixin {@code --out FILE [--force]} of the commands that write one file (compensate, program
 * export/compensate, model import): an existing FILE is replaced only with {@code --force}.
 */
public final class OutputFileOptions {
    @Option(names = "--out", required = true, paramLabel = "FILE", description = "file to write")
    Path out;

    @Option(names = "--force", description = "replace FILE if it exists")
    boolean force;

    Path file() { return out; }

    boolean force() { return force; }
}
