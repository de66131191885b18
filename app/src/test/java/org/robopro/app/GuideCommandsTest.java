package org.robopro.app;

import java.io.IOException;
import java.nio.file.Path;
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;
import org.junit.jupiter.api.io.TempDir;

/** Every {@code sh} block of docs/guide.md runs and prints what the guide says ({@link DocCommands}). */
class GuideCommandsTest {
    @TempDir static Path work;

    @TestFactory
    Stream<DynamicTest> guide_everyShBlock_exitsZeroWithItsExpectedOutput() throws IOException {
        return DocCommands.tests("guide.md", work, 8);
    }
}
