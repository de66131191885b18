package org.robopro.models;

import java.nio.file.Path;
import java.util.List;

/**
 * API STUB — to be implemented with the robot file format (issue 2).
 * The robots that ship with robopro (resources under /org/robopro/models/robots/NAME.robot.json)
 * and robot files on disk.
 */
public final class RobotLibrary {
    private RobotLibrary() { }

    /** Names of the shipped robots, e.g. irb2000, irb2400, puma560. */
    public static List<String> shippedNames() { throw new UnsupportedOperationException(); }

    /** A shipped robot by name, or a robot file by path (ROBOT arguments of the command line). */
    public static RobotDescription load(String nameOrPath) { throw new UnsupportedOperationException(); }

    public static RobotDescription read(Path file) { throw new UnsupportedOperationException(); }

    /** Writes a robot file atomically; refuses to overwrite unless asked. */
    public static void write(RobotDescription robot, Path file, boolean overwrite) { throw new UnsupportedOperationException(); }
}
