package org.robopro.models;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;

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

    public static void writeString(Path target, String text, boolean overwrite) throws IOException {
        write(target, text.getBytes(StandardCharsets.UTF_8), overwrite);
    }
}
