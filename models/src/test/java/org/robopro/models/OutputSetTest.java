package org.robopro.models;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class OutputSetTest {
    @TempDir Path tmp;

    static List<String> list(Path dir) throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }

    @Test
    void commit_newFolder_appearsWithEveryFile() throws IOException {
        Path out = tmp.resolve("run");
        OutputSet.in(out, false).addString("a.json", "{}").addString("b.html", "<p>").commit();
        assertEquals(List.of("a.json", "b.html"), list(out));
        assertEquals(List.of("run"), list(tmp), "no temporary folder left beside it");
    }

    @Test
    void commit_oldFileOfTheSetPresent_refusesTheWholeSetNamingIt() throws IOException {
        Path out = Files.createDirectories(tmp.resolve("run"));
        Files.writeString(out.resolve("summary.json"), "old");
        FileAlreadyExistsException e = assertThrows(FileAlreadyExistsException.class, () -> OutputSet.in(out, false)
                .addString("calibrated.robot.json", "new").addString("summary.json", "new").commit());
        assertTrue(e.getMessage().contains("summary.json") && e.getMessage().contains("nothing was written"), e.getMessage());
        // The new calibrated file must not end up beside the old summary.
        assertEquals(List.of("summary.json"), list(out));
        assertEquals("old", Files.readString(out.resolve("summary.json")));
    }

    @Test
    void commit_withOverwrite_replacesEveryFileOfTheSet() throws IOException {
        Path out = Files.createDirectories(tmp.resolve("run"));
        Files.writeString(out.resolve("summary.json"), "old");
        Files.writeString(out.resolve("mine.txt"), "user's");
        OutputSet.in(out, true).addString("calibrated.robot.json", "new").addString("summary.json", "new").commit();
        assertEquals(List.of("calibrated.robot.json", "mine.txt", "summary.json"), list(out));
        assertEquals("new", Files.readString(out.resolve("summary.json")));
    }

    @Test
    void commit_writeFailsHalfWay_leavesTheFolderAsItWas() throws IOException {
        // A full disk: the second file cannot be written.
        Path out = Files.createDirectories(tmp.resolve("run"));
        Files.writeString(out.resolve("summary.json"), "old");
        int[] calls = {0};
        OutputSet set = OutputSet.in(out, true).addString("calibrated.robot.json", "new").addString("summary.json", "new")
                .writer((f, b) -> {
                    if (++calls[0] == 2) throw new IOException("No space left on device");
                    AtomicFiles.writeSynced(f, b);
                });
        IOException e = assertThrows(IOException.class, set::commit);
        assertTrue(e.getMessage().contains("summary.json") && e.getMessage().contains("no space left")
                && e.getMessage().contains("nothing was written"), e.getMessage());
        assertEquals(List.of("summary.json"), list(out), "nothing of the new set, no temporary folder");
        assertEquals("old", Files.readString(out.resolve("summary.json")));

        Path fresh = tmp.resolve("fresh");
        calls[0] = 0;
        assertThrows(IOException.class, OutputSet.in(fresh, false).addString("a", "1").addString("b", "2")
                .writer((f, b) -> {
                    if (++calls[0] == 2) throw new IOException("No space left on device");
                    AtomicFiles.writeSynced(f, b);
                })::commit);
        assertFalse(Files.exists(fresh));
        assertEquals(List.of("run"), list(tmp));
    }

    @Test
    void commit_outIsAFile_saysSo() throws IOException {
        Path f = Files.writeString(tmp.resolve("file"), "x");
        IOException e = assertThrows(IOException.class, () -> OutputSet.in(f, true).addString("a", "1").commit());
        assertTrue(e.getMessage().contains(f.toString()), e.getMessage());
    }

    @Test
    void writtenFiles_getTheSamePermissionsAsAnyNewFile_notPrivateOnes() throws IOException {
        Path control = Files.createFile(tmp.resolve("control"));
        Path out = tmp.resolve("run");
        OutputSet.in(out, false).addString("a.json", "{}").commit();
        AtomicFiles.writeString(tmp.resolve("b.json"), "{}", false);
        var expected = Files.getPosixFilePermissions(control);
        assertEquals(expected, Files.getPosixFilePermissions(out.resolve("a.json")));
        assertEquals(expected, Files.getPosixFilePermissions(tmp.resolve("b.json")));
    }

    @Test
    void staleTemporaryFilesOfKilledRuns_areCleanedOnTheNextWrite() throws IOException {
        long dead = ProcessHandle.allProcesses().mapToLong(ProcessHandle::pid).max().orElse(1) + 100_000;
        Path ours = Files.writeString(tmp.resolve(".summary.json." + dead + ".3.tmp"), "half");
        Path legacy = Files.writeString(tmp.resolve(".calibrated.robot.json.8412093715.tmp"), "half");
        Files.setLastModifiedTime(legacy, FileTime.fromMillis(System.currentTimeMillis() - 3_600_000));
        Path recentLegacy = Files.writeString(tmp.resolve(".x.json.123456789.tmp"), "maybe running");
        Path live = Files.writeString(tmp.resolve(".y.json." + ProcessHandle.current().pid() + ".999999.tmp"), "ours now");
        Path userFile = Files.writeString(tmp.resolve(".notes.tmp"), "user's");
        AtomicFiles.writeString(tmp.resolve("out.json"), "{}", false);
        assertFalse(Files.exists(ours));
        assertFalse(Files.exists(legacy));
        assertTrue(Files.exists(recentLegacy));
        assertTrue(Files.exists(live));
        assertTrue(Files.exists(userFile));
    }
}
