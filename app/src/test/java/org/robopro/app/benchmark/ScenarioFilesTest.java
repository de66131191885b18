package org.robopro.app.benchmark;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robopro.app.cli.CliHarness;
import org.robopro.world.Scenario;

/**
 * Campaign files supplied from outside, each with its truth label: the benchmark reads them as a
 * user's files and scores the diagnosis against the labels alone. A small set is written here by
 * the world simulator (as someone outside would write theirs), plus one campaign with a label
 * written by hand.
 */
class ScenarioFilesTest {
    @TempDir Path dir;

    static final List<String> SMALL = List.of("null irb2000, 50 poses", "lost motion j2, 50 poses", "outside: measured point sags with reach, 50 poses");

    @Test
    void scenariosDir_sameAnswersAsTheWorldRun_andTheLabelDecidesTheScore() throws Exception {
        Path set = dir.resolve("held-out");
        List<Scenario> ss = SMALL.stream().map(Scenario::named).toList();
        assertEquals(3, ScenarioFiles.write(ss, 1, 11, set, false));
        // A campaign labelled by hand, minimal fields, claiming lost motion on a joint other than the truth's (j2).
        String lost = "lost-motion-j2-50-poses-s11";
        Files.copy(set.resolve(lost + ".csv"), set.resolve("by-hand.csv"));
        Files.writeString(set.resolve("by-hand" + ScenarioFiles.LABEL),
                "{\"robot\": \"irb2000\", \"sigma_mm\": 0.02, \"expected\": {\"verdict\": \"named\", \"claims\": "
                        + "[{\"family\": \"lost-motion\", \"joints\": [3]}]}}\n");

        CliHarness h = new CliHarness();
        int code = h.run("diagnose-benchmark", "--scenarios", set.toString(), "--verbose", "--out", dir.resolve("table.md").toString());
        String table = Files.readString(dir.resolve("table.md"));
        System.out.println(h.err() + table);
        assertTrue(h.err().startsWith("4 campaign(s) from "), h.err());
        for (String name : SMALL) assertTrue(table.contains("| " + name + " | 1 |"), name + " row in\n" + table);
        assertTrue(table.contains("| by-hand | 1 | 0 | 1 |"), "the hand label's wrong joint makes the right answer a wrong name:\n" + table);
        assertEquals(1, code, "a run scored wrong gives exit code 1");

        // Each file gives what the same world trial gives when run in memory.
        List<DiagnosisBenchmark.Case> cases = ScenarioFiles.read(set);
        assertEquals(4, cases.size());
        for (Scenario s : ss) {
            DiagnosisBenchmark.Run mem = DiagnosisBenchmark.run(s, 11);
            DiagnosisBenchmark.Run file = DiagnosisBenchmark.run(cases.stream().filter(c -> c.name().equals(s.name())).findFirst().orElseThrow());
            assertEquals(mem.outcome(), file.outcome(), s.name());
            assertEquals(mem.named(), file.named(), s.name());
            assertEquals(mem.located(), file.located(), s.name());
            assertEquals(mem.finalRatio(), file.finalRatio(), 1e-9, s.name());
            assertEquals(mem.twinRatio(), file.twinRatio(), 1e-9, s.name() + ": the twin written beside the campaign");
            assertTrue(Files.exists(set.resolve(ScenarioFiles.stem(s.name(), 11) + ScenarioFiles.TWIN)), s.name());
            assertEquals(11, file.seed());
        }
        DiagnosisBenchmark.Case byHand = cases.stream().filter(c -> c.name().equals("by-hand")).findFirst().orElseThrow();
        assertEquals("held-out", byHand.group());
        assertEquals(DiagnosisBenchmark.Outcome.NAMED_WRONG, DiagnosisBenchmark.run(byHand).outcome());
    }

    @Test
    void badInput_oneLineNamingFileAndField_nothingRun() throws Exception {
        Path set = Files.createDirectories(dir.resolve("bad"));
        ScenarioFiles.write(List.of(Scenario.named("null irb2000, 50 poses")), 1, 3, set, false);
        Files.writeString(set.resolve("orphan.csv"), Files.readString(set.resolve("null-irb2000-50-poses-s3.csv")));
        CliHarness h = new CliHarness();
        assertEquals(2, h.run("diagnose-benchmark", "--scenarios", set.toString()));
        assertTrue(h.err().contains("orphan.csv") && h.err().contains("no truth label beside it: expected orphan.truth.json"), h.err());
        assertEquals(1, h.err().strip().lines().count(), h.err());

        String[][] labels = {
                {"{\"robot\": \"irb2000\", \"expected\": {\"verdict\": \"null\"}}", "field 'sigma_mm'"},
                {"{\"robot\": \"irb9999\", \"sigma_mm\": 0.02, \"expected\": {\"verdict\": \"null\"}}", "field 'robot'"},
                {"{\"robot\": \"irb2000\", \"sigma_mm\": 0.02, \"expected\": {\"verdict\": \"maybe\"}}", "field 'expected.verdict'"},
                {"{\"robot\": \"irb2000\", \"sigma_mm\": 0.02, \"expected\": {\"verdict\": \"named\", \"claims\": [{\"family\": \"rust\", "
                        + "\"joints\": [2]}]}}", "field 'expected.claims[0].family': unknown family 'rust'"},
                {"{\"robot\": \"irb2000\", \"sigma_mm\": 0.02, \"expected\": {\"verdict\": \"named\", \"claims\": [{\"family\": \"backlash\", "
                        + "\"joints\": [7]}]}}", "field 'expected.claims[0].joints': joint numbers run from 1 to 6"},
                {"{\"robot\": \"irb2000\", \"sigma_mm\": 0.02, \"expected\": {\"verdict\": \"named\"}}", "field 'expected.claims'"},
                {"{\"robot\": \"irb2000\", \"sigma_mm\": 0.02, \"expected\": {\"verdict\": \"null\"}, \"twin\": \"gone.twin.csv\"}",
                        "field 'twin': names no campaign file beside the label"},
                {"{\"robot\": \"irb2000\", \"sigma_mm\": 0.02,", "orphan.truth.json:1"},
                // Each refusal names the line (and column) of the offending value.
                {"{\"robot\": \"irb2000\",\n \"sigma_mm\": -1,\n \"expected\": {\"verdict\": \"null\"}}", "orphan.truth.json:2:14: field 'sigma_mm'"},
                {"{\"robot\": \"irb2000\", \"sigma_mm\": 0.02,\n \"expected\": {\"verdict\": \"named\", \"claims\": [\n {\"family\": \"backlash\", "
                        + "\"joints\": [2, 7]}]}}", "orphan.truth.json:3:39: field 'expected.claims[0].joints': joint numbers run from 1 to 6, not 7"},
                // A syntax error in plain words, located, without the parser's character codes.
                {"{\"robot\": \"irb2000\",\n \"sigma_mm\": 0.02, }", "orphan.truth.json:2:20: malformed JSON: unexpected character ('}')"},
                // Values of the wrong kind are refused, not coerced.
                {"{\"robot\": \"irb2000\", \"sigma_mm\": 0.02, \"expected\": {\"verdict\": \"null\"}, \"outlier_poses\": [\"17\", {\"id\": 83}]}",
                        "field 'outlier_poses[1]': a pose name (text or number) is required"},
                {"{\"robot\": \"irb2000\", \"sigma_mm\": 0.02, \"expected\": {\"verdict\": \"null\"}, \"seed\": 7.5}",
                        "field 'seed': the seed must be a whole number, got 7.5"},
                {"{\"robot\": \"irb2000\", \"sigma_mm\": 0.02, \"expected\": {\"verdict\": \"null\"}, \"seed\": \"7\"}",
                        "field 'seed': expected a number, got a string"},
                {"{\"robot\": \"irb2000\", \"sigma_mm\": 0.02, \"expected\": {\"verdict\": \"null\"}, \"scenario\": 3}",
                        "field 'scenario': expected a string, got a number"},
                {"{\"robot\": \"irb2000\", \"sigma_mm\": 0.02, \"expected\": {\"verdict\": \"null\"}, \"family\": [\"null\"]}",
                        "field 'family': expected a string, got an array"},
                {"{\"robot\": \"irb2000\", \"sigma_mm\": 0.02, \"expected\": {\"verdict\": \"null\"}, \"twin\": 1}",
                        "field 'twin': expected a string, got a number"},
                {"{\"robot\": \"irb2000\", \"sigma_mm\": 0.02, \"expected\": {\"verdict\": \"named\", \"claims\": [{\"family\": \"backlash\", "
                        + "\"joints\": [2.5]}]}}", "field 'expected.claims[0].joints': joint numbers run from 1 to 6, not 2.5"},
                {"{\"robot\": \"irb2000\", \"sigma_mm\": 0.02, \"expected\": {\"verdict\": \"named\", \"claims\": [{\"family\": \"thermal-growth\", "
                        + "\"joints\": 2}]}}", "field 'expected.claims[0].joints': must be a list of joint numbers"},
                {"{\"robot\": \"irb2000\", \"sigma_mm\": 0.02, \"expected\": {\"verdict\": \"named\", \"claims\": [\"backlash\"]}}",
                        "field 'expected.claims[0]': a claim must be an object"},
                {"{\"robot\": \"irb2000\", \"sigma_mm\": 0.02, \"sigma_mm\": 0.03, \"expected\": {\"verdict\": \"null\"}}",
                        "field 'sigma_mm': duplicate field"}};
        for (String[] l : labels) {
            Files.writeString(set.resolve("orphan.truth.json"), l[0]);
            CliHarness g = new CliHarness();
            assertEquals(2, g.run("diagnose-benchmark", "--scenarios", set.toString()), l[0]);
            assertTrue(g.err().contains("orphan.truth.json") && g.err().contains(l[1]), l[0] + " -> " + g.err());
            assertEquals(1, g.err().strip().lines().count(), l[0] + " -> " + g.err());
            assertFalse(g.out().contains("| null"), "nothing run: " + g.out());
        }
        // A bad measurement file, the campaign's or its twin's, is refused when the set is read, naming that file and its
        // line, before any campaign is diagnosed (the campaign sorted before it included).
        String good = Files.readString(set.resolve("null-irb2000-50-poses-s3.csv"));
        String bad = good.replaceFirst("\n([^\n]*)\n", "\n$1\nnot,a,row\n");
        int badLine = (int) good.substring(0, good.indexOf('\n', good.indexOf('\n') + 1)).lines().count() + 1;
        Files.writeString(set.resolve("orphan.truth.json"),
                "{\"robot\": \"irb2000\", \"sigma_mm\": 0.02, \"expected\": {\"verdict\": \"null\"}, \"twin\": \"orphan.twin.csv\"}");
        for (String f : List.of("orphan.twin.csv", "orphan.csv")) {
            Files.writeString(set.resolve("orphan.csv"), good);
            Files.writeString(set.resolve("orphan.twin.csv"), good);
            Files.writeString(set.resolve(f), bad);
            CliHarness g = new CliHarness();
            assertEquals(2, g.run("diagnose-benchmark", "--scenarios", set.toString(), "--verbose"), f);
            assertTrue(g.err().contains(set.resolve(f) + ":" + badLine + ":"), f + " -> " + g.err());
            assertEquals(1, g.err().strip().lines().count(), "one line, nothing diagnosed: " + g.err());
        }
        Files.delete(set.resolve("orphan.csv"));
        Files.delete(set.resolve("orphan.twin.csv"));
        Files.delete(set.resolve("orphan.truth.json"));

        // Writing refuses to replace a file without --force, and writes nothing then.
        CliHarness w = new CliHarness();
        assertEquals(2, w.run("diagnose-benchmark", "--write-scenarios", set.toString(), "--scenario", "null irb2000, 50 poses", "--seeds", "1",
                "--base-seed", "3"));
        assertTrue(w.err().contains("null-irb2000-50-poses-s3.csv"), w.err());
        assertEquals(0, w.run("diagnose-benchmark", "--write-scenarios", set.toString(), "--scenario", "null irb2000, 50 poses", "--seeds", "1",
                "--base-seed", "3", "--force"), w.err());
    }

    @Test
    void stems_everyScenarioOfTheCatalogueGetsItsOwnFile() {
        java.util.Set<String> stems = new java.util.HashSet<>();
        for (Scenario s : Scenario.catalogue()) assertTrue(stems.add(ScenarioFiles.stem(s.name(), 1)), "two scenarios share the file " + s.name());
        assertEquals("lost-motion-j2-directions-not-recorded-s5", ScenarioFiles.stem("lost motion j2, directions not recorded", 5));
    }
}
