package org.robopro.models;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class TextFilesTest {
    @TempDir Path dir;

    @Test
    void readUtf8_utf8Text_returnsIt() throws Exception {
        Path f = dir.resolve("a.txt");
        Files.writeString(f, "x = 1 ° ü\n");
        assertEquals("x = 1 ° ü\n", TextFiles.readUtf8(f));
    }

    @Test
    void readUtf8_missingFile_inputExceptionNamingTheFile() {
        Path f = dir.resolve("nope.csv");
        InputException e = assertThrows(InputException.class, () -> TextFiles.readUtf8(f));
        assertEquals(f.toString(), e.file());
        assertTrue(e.problem().contains("no such file"), e.getMessage());
    }

    @Test
    void readUtf8_latin1Bytes_refusedAsNotUtf8() throws Exception {
        Path f = dir.resolve("latin1.csv");
        Files.write(f, new byte[] {'a', (byte) 0xE9, 'b'});
        InputException e = assertThrows(InputException.class, () -> TextFiles.readUtf8(f));
        assertTrue(e.problem().contains("not UTF-8"), e.getMessage());
    }
}
