package org.robopro.programs.rapid;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.LinkedHashMap;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.robopro.programs.ProgramSamples;
import org.robopro.programs.RapidModule;
import org.robopro.programs.SameMeaning;
import org.robopro.programs.RapidParser;
import org.robopro.programs.RapidWriter;

class RapidRoundTripTest {

    @Test
    void exportParseExport_randomPrograms_textIdenticalAndModelSame() {
        Map<String, String> files = new LinkedHashMap<>();
        for (long seed = 1; seed <= 40; seed++) {
            RapidModule m = ProgramSamples.random(seed);
            RapidExport e1 = RapidWriter.export(m);
            assertTrue(e1.renames().isEmpty(), () -> "unexpected renames " + e1.renames());
            RapidModule parsed = RapidParser.parse(e1.text(), "seed" + seed + ".mod");
            SameMeaning.assertSame(m, parsed);
            RapidExport e2 = RapidWriter.export(parsed);
            assertEquals(e1.text(), e2.text(), "seed " + seed);
            if (seed <= 10) files.put("Prog" + seed + ".mod", e1.text());
        }
        RapidChecker.assertValid(files);
    }
}
