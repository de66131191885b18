package org.robopro.calibration.diagnosis;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.condition.EnabledIfEnvironmentVariable;

/** Runs {@link WorldProbe} when ROBOPRO_PROBE_SEEDS is set (development only). */
class WorldProbeTest {
    @Test
    @EnabledIfEnvironmentVariable(named = "ROBOPRO_PROBE_SEEDS", matches = "\\d+")
    void probe() { WorldProbe.main(new String[0]); }
}
