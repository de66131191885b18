package org.robopro.models;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.nio.charset.StandardCharsets;

/**
 * Fuzzes the robot-file reader: whatever the bytes, it either returns a robot or throws an
 * {@link InputException}; any other exception fails. Under {@code mvn verify} this runs for a
 * short bounded time in the "fuzz" surefire execution (JAZZER_FUZZ=1, docs/testing.md); in a
 * plain test run it replays the seed corpus in RobotFileFuzzTestInputs/.
 */
class RobotFileFuzzTest {
    @FuzzTest(maxDuration = "15s")
    void parse_anyBytes_onlyInputException(byte[] bytes) {
        String text = new String(bytes, StandardCharsets.UTF_8);
        try {
            RobotDescription r = RobotFile.parse("fuzz.robot.json", text);
            // A robot that was read must also write and read back to itself.
            RobotDescription again = RobotFile.parse("again", RobotFile.format(r));
            if (!again.equals(r) && r.joints().stream().allMatch(j -> Math.abs(j.axis().norm() - 1) < 1e-12))
                throw new AssertionError("round trip changed the robot:\n" + text);
        } catch (InputException expected) {
            // the only acceptable failure
        }
    }
}
