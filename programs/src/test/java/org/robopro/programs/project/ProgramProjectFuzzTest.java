package org.robopro.programs.project;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.nio.charset.StandardCharsets;
import org.robopro.models.InputException;
import org.robopro.programs.RapidModule;

/**
 * Fuzzes the reader of former "robopro-program" files: any text gives a module or an
 * {@link InputException} (file, line, column, field), never another exception.
 */
class ProgramProjectFuzzTest {
    @FuzzTest(maxDuration = "10s")
    void parse_anyText_onlyInputException(byte[] bytes) {
        String text = new String(bytes, StandardCharsets.UTF_8);
        RapidModule m;
        try {
            m = ProgramProject.parse(text, "fuzz.json");
        } catch (InputException expected) {
            return;
        }
        if (m.name().isEmpty()) throw new AssertionError("a module without a name");
    }
}
