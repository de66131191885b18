package org.robopro.app;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;

/** The launcher's class-data-sharing training run exercises every command it lists (none may fail silently). */
class StartupTrainingTest {
    @Test
    void run_everyTrainingCommandSucceeds() throws Exception {
        assertEquals(List.of(), StartupTraining.run());
    }
}
