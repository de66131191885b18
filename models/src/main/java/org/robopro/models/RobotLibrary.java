package org.robopro.models;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * The robots that ship with robopro (resources under /org/robopro/models/robots/NAME.robot.json)
 * and robot files on disk (format: docs/robot-file.md, reader/writer: {@link RobotFile}).
 * Thread-safe; shipped robots are parsed once and shared (the records are immutable).
 */
public final class RobotLibrary {
    private static final String RESOURCE_DIR = "/org/robopro/models/robots/";
    private static final List<String> SHIPPED = List.of("irb2000", "irb2400", "puma560");
    private static final Map<String, RobotDescription> CACHE = new ConcurrentHashMap<>();

    private RobotLibrary() { }

    /** Names of the shipped robots, e.g. irb2000, irb2400, puma560. */
    public static List<String> shippedNames() { return SHIPPED; }

    /**
     * A shipped robot by name, or a robot file by path (ROBOT arguments of the command line).
     * A name of a shipped robot wins over a file of the same name in the working folder.
     *
     * @throws InputException if there is no such robot or the file is bad
     */
    public static RobotDescription load(String nameOrPath) {
        if (nameOrPath == null || nameOrPath.isBlank())
            throw new InputException(null, 0, 0, "robot", "no robot given");
        if (SHIPPED.contains(nameOrPath)) return shipped(nameOrPath);
        Path p;
        try {
            p = Path.of(nameOrPath);
        } catch (java.nio.file.InvalidPathException e) {
            throw new InputException(nameOrPath, 0, 0, "robot", "not a shipped robot (" + String.join(", ", SHIPPED)
                    + ") nor a valid path");
        }
        if (!Files.exists(p))
            throw new InputException(nameOrPath, 0, 0, "robot", "no shipped robot of this name ("
                    + String.join(", ", SHIPPED) + ") and no such file");
        return read(p);
    }

    /** A shipped robot by name. */
    public static RobotDescription shipped(String name) {
        if (!SHIPPED.contains(name))
            throw new InputException(null, 0, 0, "robot", "no shipped robot '" + name + "' (shipped: "
                    + String.join(", ", SHIPPED) + ")");
        return CACHE.computeIfAbsent(name, n -> RobotFile.parse("shipped:" + n + ".robot.json",
                resourceText(RESOURCE_DIR + n + ".robot.json")));
    }

    /** Reads a robot file; an unreadable or malformed file is an {@link InputException}. */
    public static RobotDescription read(Path file) { return RobotFile.read(file); }

    /**
     * Writes a robot file atomically; refuses to overwrite unless asked.
     *
     * @throws InputException if the file exists and {@code overwrite} is false
     * @throws UncheckedIOException if writing fails
     */
    public static void write(RobotDescription robot, Path file, boolean overwrite) {
        try {
            RobotFile.write(robot, file, overwrite);
        } catch (FileAlreadyExistsException e) {
            throw new InputException(file.toString(), 0, 0, null, "file exists; refusing to overwrite it");
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write " + file + ": " + e.getMessage(), e);
        }
    }

    static String resourceText(String resource) {
        try (InputStream in = RobotLibrary.class.getResourceAsStream(resource)) {
            if (in == null) throw new IllegalStateException("missing resource " + resource);
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
