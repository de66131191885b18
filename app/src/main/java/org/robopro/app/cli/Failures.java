package org.robopro.app.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.DirectoryNotEmptyException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.NotDirectoryException;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;
import java.util.Locale;
import org.robopro.models.InputException;

/**
 * Turns every failure of a command into one line for the user. Bad input and file problems get
 * their own words (naming the file); anything unexpected gets one line saying so plus a log
 * file holding the stack trace, so no Java text reaches the user and nothing is hidden.
 */
public final class Failures {
    /** Exit code of bad input or a file problem. */
    public static final int INPUT = 2;
    /** Exit code of an internal error (EX_SOFTWARE of sysexits.h). */
    public static final int INTERNAL = 70;

    private Failures() { }

    /** Prints the one line for {@code ex} to {@code err} and returns the exit code. */
    public static int report(Throwable ex, PrintWriter err) {
        String line = userLine(ex);
        if (line != null) {
            err.println("robopro: " + line);
            err.flush();
            return INPUT;
        }
        Path log = writeLog(ex);
        String what = ex instanceof OutOfMemoryError ? "ran out of memory (try a larger -Xmx, or a smaller input)"
                : ex instanceof StackOverflowError ? "ran out of stack (the input nests too deeply)"
                : "internal error (" + ex.getClass().getSimpleName() + ")";
        err.println("robopro: " + what + "; " + (log != null ? "the details are in " + log
                : "the details could not be written to a log file") + " - please report it");
        err.flush();
        return INTERNAL;
    }

    /** The user's words for an expected failure, or null when the failure is unexpected. */
    static String userLine(Throwable ex) {
        if (ex instanceof InputException) return ex.getMessage();
        if (ex instanceof UncheckedIOException u && u.getCause() != null) {
            String inner = io(u.getCause());
            String m = u.getMessage();
            // Our own wrappers say what was being done ("cannot write FILE: ..."): keep that context.
            if (m != null && m.startsWith("cannot ")) {
                int colon = m.indexOf(": ");
                return (colon > 0 ? m.substring(0, colon) : m) + ": " + reason(u.getCause());
            }
            return inner;
        }
        if (ex instanceof IOException io) return io(io);
        // Our own refusals of option values; Java's parse errors (NumberFormatException) are not words for users.
        if (ex instanceof IllegalArgumentException && !(ex instanceof NumberFormatException)
                && ex.getMessage() != null && !ex.getMessage().isBlank())
            return ex.getMessage();
        return null;
    }

    private static String io(IOException e) {
        if (e instanceof FileSystemException f && f.getFile() != null) {
            String other = f.getOtherFile() == null ? "" : " -> " + f.getOtherFile();
            return f.getFile() + other + ": " + reason(e);
        }
        return reason(e);
    }

    /** The reason of a file problem in words, without the file name. */
    private static String reason(Throwable e) {
        if (e instanceof NoSuchFileException) return "no such file or folder";
        if (e instanceof AccessDeniedException) return "permission denied";
        if (e instanceof NotDirectoryException) return e.getMessage() != null && e.getMessage().contains(" ")
                ? e.getMessage().substring(e.getMessage().indexOf(' ') + 1) : "not a folder";
        if (e instanceof DirectoryNotEmptyException) return "folder is not empty";
        if (e instanceof java.nio.charset.CharacterCodingException) return "not UTF-8 text";
        if (e instanceof FileAlreadyExistsException f)
            return f.getReason() != null ? f.getReason() : "exists; refusing to overwrite it (use --force to replace it)";
        if (e instanceof FileSystemException f && f.getReason() != null) return lower(f.getReason());
        String m = e.getMessage();
        return m == null || m.isBlank() ? "input/output error" : lower(m);
    }

    private static String lower(String s) {
        return s.length() > 1 && Character.isUpperCase(s.charAt(0)) && Character.isLowerCase(s.charAt(1))
                ? Character.toLowerCase(s.charAt(0)) + s.substring(1) : s;
    }

    /** Writes the trace to the user's robopro log folder (or the temporary folder); null if both fail. */
    static Path writeLog(Throwable ex) {
        StringWriter sw = new StringWriter();
        try (PrintWriter pw = new PrintWriter(sw)) {
            pw.println("robopro " + RoboproCommand.class.getPackage().getImplementationVersion());
            pw.println("java " + System.getProperty("java.version") + " on " + System.getProperty("os.name"));
            ex.printStackTrace(pw);
        }
        String name = "robopro-error-" + LocalDateTime.now().format(DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss", Locale.ROOT))
                + "-" + ProcessHandle.current().pid() + ".log";
        String home = System.getProperty("user.home");
        for (Path dir : new Path[] {home == null ? null : Path.of(home, ".robopro", "logs"), Path.of(System.getProperty("java.io.tmpdir"))}) {
            if (dir == null) continue;
            try {
                Files.createDirectories(dir);
                return Files.writeString(dir.resolve(name), sw.toString(), StandardCharsets.UTF_8);
            } catch (IOException | RuntimeException e) {
                // try the next place
            }
        }
        return null;
    }
}
