package org.robopro.models;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.NotDirectoryException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A set of result files (calibrate, diagnose, simulate, compensate) written as a whole or not at
 * all. Files are collected with {@link #add}, then {@link #commit} checks every name first (an
 * existing file without {@code overwrite} refuses the whole set, naming each), writes every file
 * into a temporary folder beside the destination and syncs it, and only then moves the files into
 * place. A failure while writing (a full disk, a read-only folder) leaves the destination as it
 * was; the temporary folder is removed. A new destination folder appears with all its files at
 * once (one rename); into an existing folder the files are renamed one after the other, which
 * needs no space and cannot fail half-way for want of it.
 */
public final class OutputSet {
    /** How file contents reach the disk; replaced in tests to inject a failure (full disk). */
    interface Writer {
        void write(Path file, byte[] bytes) throws IOException;
    }

    private final Path dir;
    private final boolean overwrite;
    private final Map<String, byte[]> files = new LinkedHashMap<>();
    private Writer writer = AtomicFiles::writeSynced;

    private OutputSet(Path dir, boolean overwrite) {
        this.dir = dir.toAbsolutePath().normalize();
        this.overwrite = overwrite;
    }

    /** A set for folder {@code dir}; {@code overwrite} false refuses to replace any existing file. */
    public static OutputSet in(Path dir, boolean overwrite) {
        return new OutputSet(dir, overwrite);
    }

    public Path dir() { return dir; }

    /** Adds (or replaces) the file {@code name} (a plain file name, no folders). */
    public OutputSet add(String name, byte[] bytes) {
        if (name.isEmpty() || name.contains("/") || name.contains("\\") || name.startsWith("."))
            throw new IllegalArgumentException("not a plain file name: '" + name + "'");
        files.put(name, bytes.clone());
        return this;
    }

    public OutputSet addString(String name, String text) {
        return add(name, text.getBytes(StandardCharsets.UTF_8));
    }

    /** The names added so far, in order. */
    public List<String> names() { return List.copyOf(files.keySet()); }

    OutputSet writer(Writer w) {
        this.writer = w;
        return this;
    }

    /** Writes the whole set, or nothing (see the class comment). */
    public void commit() throws IOException {
        if (Files.exists(dir) && !Files.isDirectory(dir))
            throw new NotDirectoryException(dir + " exists and is not a folder");
        Path parent = dir.getParent();
        if (parent == null) throw new IOException(dir + ": cannot write results into the root folder");
        boolean fresh = !Files.exists(dir);
        if (!fresh) {
            AtomicFiles.cleanStale(dir);
            List<String> clash = new ArrayList<>();
            for (String n : files.keySet()) {
                Path t = dir.resolve(n);
                if (Files.isDirectory(t)) clash.add(n + " (a folder)");
                else if (!overwrite && Files.exists(t)) clash.add(n);
            }
            if (!clash.isEmpty())
                throw new FileAlreadyExistsException(dir.toString(), null, "holds " + String.join(", ", clash)
                        + " from an earlier run; nothing was written (choose another folder, or --force to replace them)");
        } else {
            Files.createDirectories(parent);
        }
        Path stageHome = fresh ? parent : dir;
        AtomicFiles.cleanStale(stageHome);
        Path stage = AtomicFiles.tempPath(stageHome, fresh ? dir.getFileName().toString() : "robopro-output");
        Files.createDirectory(stage);
        try {
            for (Map.Entry<String, byte[]> e : files.entrySet()) {
                try {
                    writer.write(stage.resolve(e.getKey()), e.getValue());
                } catch (IOException x) {
                    String why = x.getMessage() == null ? "input/output error" : x.getMessage();
                    if (x instanceof java.nio.file.FileSystemException f && f.getReason() != null) why = f.getReason();
                    throw new IOException(dir.resolve(e.getKey()) + ": cannot write: " + why.toLowerCase(java.util.Locale.ROOT)
                            + "; nothing was written", x);
                }
            }
            if (fresh) {
                AtomicFiles.move(stage, dir);
            } else {
                for (String n : files.keySet()) AtomicFiles.move(stage.resolve(n), dir.resolve(n));
            }
        } finally {
            if (Files.exists(stage)) AtomicFiles.deleteTree(stage);
        }
    }
}
