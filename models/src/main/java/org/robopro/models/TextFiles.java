package org.robopro.models;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;

/** Reads user files as text: the one place every reader of robot, cell, measurement, table and RAPID files goes through. */
public final class TextFiles {
    private TextFiles() { }

    /**
     * Reads a UTF-8 text file, refusing malformed UTF-8. A missing, unreadable or non-UTF-8 file is
     * an {@link InputException} naming the file, so every reader reports it the same way.
     */
    public static String readUtf8(Path file) {
        try {
            byte[] bytes = Files.readAllBytes(file);
            return StandardCharsets.UTF_8.newDecoder().onMalformedInput(CodingErrorAction.REPORT)
                    .onUnmappableCharacter(CodingErrorAction.REPORT).decode(ByteBuffer.wrap(bytes)).toString();
        } catch (NoSuchFileException e) {
            throw new InputException(file.toString(), 0, 0, null, "no such file");
        } catch (CharacterCodingException e) {
            throw new InputException(file.toString(), 0, 0, null, "not UTF-8 text", e);
        } catch (IOException e) {
            throw new InputException(file.toString(), 0, 0, null, "cannot read: " + e, e);
        }
    }
}
