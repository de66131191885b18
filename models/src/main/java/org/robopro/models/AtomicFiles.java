package org.robopro.models;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * Writes files atomically (temporary file in the same folder, then rename), so a crash never
 * leaves a half-written file, and refuses to replace an existing file unless asked to.
 */
public final class AtomicFiles {
    private AtomicFiles() { }

    /** Writes {@code bytes} to {@code target} atomically; {@code overwrite} false refuses an existing file. */
    public static void write(Path target, byte[] bytes, boolean overwrite) throws IOException {
        Path abs = target.toAbsolutePath();
        Path dir = abs.getParent();
        if (dir != null) Files.createDirectories(dir);
        if (!overwrite && Files.exists(abs))
            throw new FileAlreadyExistsException(abs.toString(), null, "exists; refusing to overwrite it");
        Path tmp = Files.createTempFile(dir, "." + abs.getFileName() + ".", ".tmp");
        try {
            Files.write(tmp, bytes);
            try {
                Files.move(tmp, abs, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(tmp, abs, StandardCopyOption.REPLACE_EXISTING);
            }
        } finally {
            Files.deleteIfExists(tmp);
        }
    }

    /**
     * Writes a set of files whole or not at all: every existing target is checked first
     * ({@code overwrite} false refuses before anything is written), every file is written to a
     * temporary file beside its target, and only when all are written are they renamed into place.
     * A failure while writing removes the temporary files and leaves the targets as they were.
     */
    public static void writeAll(Map<Path, byte[]> files, boolean overwrite) throws IOException {
        if (!overwrite)
            for (Path target : files.keySet())
                if (Files.exists(target)) throw new FileAlreadyExistsException(target.toAbsolutePath().toString(), null, "exists; refusing to overwrite it");
        List<Path[]> staged = new ArrayList<>();
        try {
            for (Map.Entry<Path, byte[]> e : files.entrySet()) {
                Path abs = e.getKey().toAbsolutePath();
                Path dir = abs.getParent();
                if (dir != null) Files.createDirectories(dir);
                Path tmp = Files.createTempFile(dir, "." + abs.getFileName() + ".", ".tmp");
                staged.add(new Path[] {tmp, abs});
                Files.write(tmp, e.getValue());
            }
            for (Path[] s : staged) {
                try {
                    Files.move(s[0], s[1], StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
                } catch (AtomicMoveNotSupportedException e) {
                    Files.move(s[0], s[1], StandardCopyOption.REPLACE_EXISTING);
                }
            }
        } finally {
            for (Path[] s : staged) Files.deleteIfExists(s[0]);
        }
    }

    public static void writeString(Path target, String text, boolean overwrite) throws IOException {
        write(target, text.getBytes(StandardCharsets.UTF_8), overwrite);
    }
}
