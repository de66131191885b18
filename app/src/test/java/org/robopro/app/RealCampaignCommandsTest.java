package org.robopro.app;

import java.io.IOException;
import java.nio.file.Path;
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;
import org.junit.jupiter.api.io.TempDir;

/** Every {@code sh} block of the real-campaign tutorial (docs/real-campaign.md) runs and prints what it says ({@link DocCommands}). */
class RealCampaignCommandsTest {
    @TempDir static Path work;

    @TestFactory
    Stream<DynamicTest> realCampaign_everyShBlock_exitsZeroWithItsExpectedOutput() throws IOException {
        return DocCommands.tests("real-campaign.md", work, 5);
    }
}
