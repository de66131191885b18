package org.robopro.kinematics.importers;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.nio.charset.StandardCharsets;
import org.robopro.models.InputException;

/**
 * Fuzzes the URDF importer: whatever the bytes, it returns a robot or throws an
 * {@link InputException}; anything else fails. Runs for a short bounded time in the "fuzz"
 * surefire execution (JAZZER_FUZZ=1, docs/testing.md); a plain run replays the seed corpus.
 */
class UrdfImporterFuzzTest {
    @FuzzTest(maxDuration = "15s")
    void parse_anyBytes_onlyInputException(byte[] bytes) {
        try {
            UrdfImporter.parse("fuzz.urdf", new String(bytes, StandardCharsets.UTF_8));
        } catch (InputException expected) {
            // the only acceptable failure
        }
    }
}
