package org.robopro.programs.rapid;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.nio.charset.StandardCharsets;
import org.robopro.models.InputException;
import org.robopro.programs.RapidModule;
import org.robopro.programs.sim.MotionInterpreter;
import org.robopro.programs.RapidParser;
import org.robopro.programs.RapidWriter;

/**
 * Fuzzes the RAPID parser: whatever the text, it either returns a module or throws an
 * {@link InputException}; any other exception fails. A module that was read must write its
 * syntax tree back to text that reads as the same tree, export, read back to the same text, and run in the interpreter (again only InputException allowed).
 * With JAZZER_FUZZ=1 (the "fuzz" surefire execution) this fuzzes for a short bounded time; in
 * a plain test run it replays the seeds in RapidParserFuzzTestInputs/.
 */
class RapidParserFuzzTest {
    @FuzzTest(maxDuration = "20s")
    void parse_anyText_onlyInputException(byte[] bytes) {
        String text = new String(bytes, StandardCharsets.ISO_8859_1);
        RapidModule m;
        try {
            m = RapidParser.parse(text, "fuzz.mod");
        } catch (InputException expected) {
            return;
        }
        // The syntax tree written back reads as the same tree.
        RapidAst.Module tree = RapidAstParser.parse(text, "fuzz.mod").module();
        String written = RapidAstWriter.write(tree);
        RapidAst.Module again = RapidAstParser.parse(written, "written.mod").module();
        if (!tree.equals(again)) throw new AssertionError("tree round trip changed:\n" + written);
        String once = RapidWriter.export(m).text();
        String twice = RapidWriter.export(RapidParser.parse(once, "again.mod")).text();
        if (!once.equals(twice)) throw new AssertionError("export is not stable:\n" + once + "\n---\n" + twice);
        try {
            MotionInterpreter.of(m).run(m.procedures().isEmpty() ? "main" : m.procedures().get(0).name());
        } catch (InputException expected) {
            // unknown names, unsupported frames: reported clearly
        }
    }
}
