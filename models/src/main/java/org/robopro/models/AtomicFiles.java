package org.robopro.models;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.DirectoryStream;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.util.Comparator;
import java.util.concurrent.atomic.AtomicLong;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * Writes files atomically (temporary file in the same folder, synced, then renamed), so a crash
 * never leaves a half-written file, and refuses to replace an existing file unless asked to.
 * Temporary names are {@code .NAME.PID.N.tmp}; ones left by a process that no longer runs (a
 * killed run) are deleted the next time this class writes into that folder. Files are created
 * with the ordinary permissions (the process umask applies), not private ones.
 */
public final class AtomicFiles {
    private static final AtomicLong COUNTER = new AtomicLong();
    /** Our temporary names: .NAME.PID.N.tmp; and the older .NAME.DIGITS.tmp of Files.createTempFile. */
    private static final Pattern TEMP = Pattern.compile("\\..+\\.(\\d+)\\.(\\d+)\\.tmp");
    private static final Pattern LEGACY_TEMP = Pattern.compile("\\..+\\.\\d{6,}\\.tmp");
    /** Age after which a legacy temporary file (no process id in its name) counts as abandoned. */
    private static final long LEGACY_AGE_MS = 10 * 60_000L;

    private AtomicFiles() { }

    /** Writes {@code bytes} to {@code target} atomically; {@code overwrite} false refuses an existing file. */
    public static void write(Path target, byte[] bytes, boolean overwrite) throws IOException {
        Path abs = target.toAbsolutePath();
        Path dir = abs.getParent();
        if (dir != null) {
            if (Files.exists(dir) && !Files.isDirectory(dir))
                throw new java.nio.file.NotDirectoryException(dir + " (the folder for " + abs.getFileName() + ")");
            Files.createDirectories(dir);
            cleanStale(dir);
        }
        if (Files.isDirectory(abs)) throw new FileAlreadyExistsException(abs.toString(), null, "is a folder, not a file");
        if (!overwrite && Files.exists(abs))
            throw new FileAlreadyExistsException(abs.toString(), null, "exists; refusing to overwrite it");
        Path tmp = tempPath(dir, abs.getFileName().toString());
        try {
            writeSynced(tmp, bytes);
            move(tmp, abs);
        } finally {
            Files.deleteIfExists(tmp);
        }
    }

    public static void writeString(Path target, String text, boolean overwrite) throws IOException {
        write(target, text.getBytes(StandardCharsets.UTF_8), overwrite);
    }

    /** A fresh temporary path for {@code name} in {@code dir} ({@code .NAME.PID.N.tmp}); not created. */
    static Path tempPath(Path dir, String name) {
        return dir.resolve("." + name + "." + ProcessHandle.current().pid() + "." + COUNTER.incrementAndGet() + ".tmp");
    }

    /** Creates {@code file} (must not exist; umask applies), writes {@code bytes} and syncs them to disk. */
    static void writeSynced(Path file, byte[] bytes) throws IOException {
        try (FileChannel ch = FileChannel.open(file, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE)) {
            ByteBuffer b = ByteBuffer.wrap(bytes);
            while (b.hasRemaining()) ch.write(b);
            ch.force(true);
        }
    }

    /** Renames atomically where the file system can, else plainly (same folder: still one rename). */
    static void move(Path from, Path to) throws IOException {
        try {
            Files.move(from, to, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
        } catch (AtomicMoveNotSupportedException e) {
            Files.move(from, to, StandardCopyOption.REPLACE_EXISTING);
        }
    }

    /**
     * Deletes temporary files and folders in {@code dir} left by runs that were killed: ours whose
     * process id no longer runs, and legacy ones older than ten minutes. Returns how many were
     * deleted; problems (permissions, races with another process) are ignored.
     */
    public static int cleanStale(Path dir) {
        int n = 0;
        try (DirectoryStream<Path> ds = Files.newDirectoryStream(dir, ".*.tmp")) {
            for (Path p : ds) {
                String name = p.getFileName().toString();
                Matcher m = TEMP.matcher(name);
                boolean stale;
                if (m.matches()) {
                    long pid = Long.parseLong(m.group(1));
                    stale = pid != ProcessHandle.current().pid() && ProcessHandle.of(pid).map(h -> !h.isAlive()).orElse(true);
                } else {
                    stale = LEGACY_TEMP.matcher(name).matches()
                            && System.currentTimeMillis() - Files.getLastModifiedTime(p).toMillis() > LEGACY_AGE_MS;
                }
                if (stale && deleteTree(p)) n++;
            }
        } catch (IOException | UncheckedIOException | SecurityException e) {
            // Cleaning is a courtesy; the write itself reports real problems.
        }
        return n;
    }

    static boolean deleteTree(Path p) {
        try (Stream<Path> s = Files.walk(p)) {
            for (Path q : (Iterable<Path>) s.sorted(Comparator.reverseOrder())::iterator) Files.deleteIfExists(q);
            return true;
        } catch (IOException | UncheckedIOException e) {
            return false;
        }
    }
}
