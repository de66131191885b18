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

    @Test
    void readUtf8_folder_saysSoNamingIt_withoutJavaText() throws Exception {
        InputException e = assertThrows(InputException.class, () -> TextFiles.readUtf8(dir));
        assertEquals(dir.toString(), e.file());
        assertTrue(e.problem().contains("is a folder"), e.getMessage());
        assertTrue(!e.getMessage().contains("Exception"), e.getMessage());
    }

    @Test
    void readUtf8_byteOrderMark_isDropped() throws Exception {
        Path f = dir.resolve("bom.json");
        Files.write(f, new byte[] {(byte) 0xEF, (byte) 0xBB, (byte) 0xBF, '{', '}'});
        assertEquals("{}", TextFiles.readUtf8(f));
    }

    @Test
    void readBytes_endlessDevice_isRefusedAfterTheLimitWithoutReadingOn() {
        Path zero = Path.of("/dev/zero");
        org.junit.jupiter.api.Assumptions.assumeTrue(Files.exists(zero));
        long t0 = System.nanoTime();
        InputException e = assertThrows(InputException.class, () -> TextFiles.readBytes(zero, 1 << 20, "mesh file"));
        assertTrue(e.problem().contains("without end") && e.problem().contains("mesh file"), e.getMessage());
        assertTrue(System.nanoTime() - t0 < 5e9);
    }

    @Test
    void readBytes_fileOverTheLimit_isRefusedBySize() throws Exception {
        Path f = Files.write(dir.resolve("big.stl"), new byte[2000]);
        InputException e = assertThrows(InputException.class, () -> TextFiles.readBytes(f, 1000, "mesh file"));
        assertTrue(e.problem().contains("more than"), e.getMessage());
    }
}
