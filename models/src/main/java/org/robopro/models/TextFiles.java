package org.robopro.models;

import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;

/** Reads user files as text: the one place every reader of robot, cell, measurement, table and RAPID files goes through. */
public final class TextFiles {
    private TextFiles() { }

    /** Largest text file read (robot, cell, measurement, RAPID files): far beyond any real one. */
    public static final long MAX_TEXT_BYTES = 1L << 30;

    /**
     * Reads a UTF-8 text file, refusing malformed UTF-8; a leading byte-order mark is dropped (so
     * every format treats it alike). A missing, unreadable, non-UTF-8, endless or oversized file
     * is an {@link InputException} naming the file, so every reader reports it the same way.
     */
    public static String readUtf8(Path file) {
        byte[] bytes = readBytes(file, MAX_TEXT_BYTES, "text file");
        try {
            String text = StandardCharsets.UTF_8.newDecoder().onMalformedInput(CodingErrorAction.REPORT)
                    .onUnmappableCharacter(CodingErrorAction.REPORT).decode(ByteBuffer.wrap(bytes)).toString();
            return text.startsWith("\uFEFF") ? text.substring(1) : text;
        } catch (CharacterCodingException e) {
            throw new InputException(file.toString(), 0, 0, null, "not UTF-8 text", e);
        }
    }

    /**
     * Reads at most {@code maxBytes} of a file. A folder, a missing or unreadable file, and a file
     * larger than the limit (also one without end, such as /dev/zero or a pipe, which is noticed
     * after {@code maxBytes} without reading further) are an {@link InputException} naming it.
     */
    public static byte[] readBytes(Path file, long maxBytes, String what) {
        String name = file.toString();
        if (Files.isDirectory(file)) throw new InputException(name, 0, 0, null, "is a folder, not a " + what);
        try {
            if (Files.isRegularFile(file) && Files.size(file) > maxBytes)
                throw new InputException(name, 0, 0, null, String.format(java.util.Locale.ROOT,
                        "is %.1f MB, more than the %.0f MB a %s may have", Files.size(file) / 1e6, maxBytes / 1e6, what));
            try (InputStream in = Files.newInputStream(file)) {
                byte[] b = in.readNBytes((int) Math.min(Integer.MAX_VALUE - 8, maxBytes + 1));
                if (b.length > maxBytes)
                    throw new InputException(name, 0, 0, null, String.format(java.util.Locale.ROOT,
                            "has more than %.0f MB (a device or a pipe without end?); not a %s", maxBytes / 1e6, what));
                return b;
            }
        } catch (NoSuchFileException e) {
            throw new InputException(name, 0, 0, null, "no such file");
        } catch (AccessDeniedException e) {
            throw new InputException(name, 0, 0, null, "permission denied");
        } catch (FileSystemException e) {
            throw new InputException(name, 0, 0, null, "cannot read: "
                    + (e.getReason() != null ? e.getReason().toLowerCase(java.util.Locale.ROOT) : "input/output error"), e);
        } catch (IOException e) {
            throw new InputException(name, 0, 0, null, "cannot read: "
                    + (e.getMessage() != null ? e.getMessage() : "input/output error"), e);
        }
    }
}
