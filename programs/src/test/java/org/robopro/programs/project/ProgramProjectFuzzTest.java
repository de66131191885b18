package org.robopro.programs.project;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.nio.charset.StandardCharsets;
import org.robopro.models.InputException;
import org.robopro.programs.RapidModule;

/**
 * Fuzzes the program project reader: any text gives a module or an {@link InputException}; a
 * module that was read writes and reads back as the same module.
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
        String once;
        try {
            once = ProgramProject.format(m, null);
        } catch (IllegalArgumentException cannot) {
            return; // not expected from a module read from a project, but not a reader failure either
        }
        RapidModule back = ProgramProject.parse(once, "again.json");
        if (!back.equals(m)) throw new AssertionError("project round trip changed the module:\n" + once);
    }
}
