package org.robopro.programs.project;

import org.robopro.programs.rapid.RapidAst;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robopro.models.InputException;
import org.robopro.programs.Declaration;
import org.robopro.programs.ModuleItem;
import org.robopro.programs.Move;
import org.robopro.programs.Procedure;
import org.robopro.programs.ProgramSamples;
import org.robopro.programs.RapidModule;
import org.robopro.programs.Ref;
import org.robopro.programs.RobTarget;
import org.robopro.programs.SameMeaning;
import org.robopro.programs.Statement;
import org.robopro.programs.RapidParser;

class ProgramProjectTest {

    static final String PROJECT = String.join("\n",
            "{\"format\": \"robopro-program\", \"version\": 1, \"module\": \"Demo\",",
            " \"comments\": [\" cell 4\"],",
            " \"tools\": {\"tTorch\": {\"tframe\": {\"pos_mm\": [0, 0, 150], \"quat\": [0.7071067811865476, 0, 0.7071067811865476, 0]},",
            "                      \"load\": {\"mass_kg\": 2, \"cog_mm\": [0, 0, 50], \"inertia_kgm2\": [0.01, 0.01, 0.002]}}},",
            " \"wobjs\": {\"wTable\": {\"uframe\": {\"pos_mm\": [900, -200, 500]}, \"oframe\": {\"pos_mm\": [0.1, 0.2, 0.3]}, \"scope\": \"LOCAL\"}},",
            " \"speeds\": {\"vWeld\": {\"tcp_mm_s\": 10.3, \"ori_deg_s\": 45.7}},",
            " \"zones\": {\"zSoft\": {\"tcp_mm\": 5}, \"zOdd\": {\"tcp_mm\": 2, \"ori_deg\": 0.7}},",
            " \"jointtargets\": {\"jHome\": {\"joints_deg\": [0, 0.1, 0, 0, 30, 0], \"extax\": [120, 9E9, 9E9, 9E9, 9E9, 9E9]}},",
            " \"targets\": {\"pB\": {\"pos_mm\": [100.123, 0, 0.7], \"quat\": [0, 0, 1, 0], \"conf\": [0, -1, 2, 1], \"storage\": \"PERS\"}},",
            " \"data\": {\"nPasses\": {\"num\": 3}, \"sPart\": {\"string\": \"flange\"}},",
            " \"procedures\": {\"main\": [{\"move\": \"MoveAbsJ\", \"to\": \"jHome\", \"speed\": \"v1000\", \"zone\": \"fine\"},",
            "                         {\"move\": \"MoveL\", \"to\": \"pB\", \"speed\": \"vWeld\", \"zone\": \"zSoft\", \"tool\": \"tTorch\", \"wobj\": \"wTable\", \"v_mm_s\": 12.5, \"conc\": true},",
            "                         {\"move\": \"MoveC\", \"via\": \"pB\", \"to\": \"pB\", \"speed\": \"vWeld\", \"zone\": \"fine\", \"tool\": \"tTorch\", \"z_mm\": 0.3},",
            "                         {\"call\": \"other\"}, {\"wait_s\": 0.5}, {\"comment\": \" done\"}],",
            "                \"other\": []}}",
            "");

    @Test
    void formatParse_documentedFeatures_sameModuleAndStableText() {
        RapidModule a = ProgramProject.parse(PROJECT, "demo.json");
        String text = ProgramProject.format(a, null);
        RapidModule b = ProgramProject.parse(text, "again.json");
        assertEquals(a, b);
        assertEquals(text, ProgramProject.format(b, null));
        assertEquals(RapidAst.Scope.LOCAL, b.declaration("wTable").orElseThrow().scope());
        assertEquals(RapidAst.Storage.PERS, b.declaration("pB").orElseThrow().storage());
    }

    @Test
    void formatParse_randomModules_sameMeaningThenExact() {
        for (long seed = 1; seed <= 30; seed++) {
            RapidModule m = nameInlineTargets(ProgramSamples.random(seed));
            String text = ProgramProject.format(m, "irb2000");
            RapidModule back = ProgramProject.parse(text, "seed" + seed + ".json");
            // SI values made in code need not have an exact mm/degree double (x * 1e-3 skips some
            // doubles): the first trip keeps them to the last bit or so ...
            for (Declaration d : m.declarations())
                SameMeaning.assertSame(d, back.declaration(d.name()).orElseThrow());
            assertEquals(m.declarations().size(), back.declarations().size());
            SameMeaning.assertSame(m.procedures(), back.procedures());
            // ... and what was read from a project file is written and read back exactly.
            String again = ProgramProject.format(back, "irb2000");
            assertEquals(back, ProgramProject.parse(again, "again.json"), "seed " + seed);
            assertEquals(again, ProgramProject.format(ProgramProject.parse(again, "again.json"), "irb2000"), "seed " + seed);
        }
    }

    @Test
    void format_moduleWithSyntaxTreeItems_refusedNamingTheItem() {
        String rapid = "MODULE M\n  VAR num n{2};\n  PROC main()\n    n{1} := 2;\n  ENDPROC\nENDMODULE\n";
        RapidModule m = RapidParser.parse(rapid, "m.mod");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> ProgramProject.format(m, null));
        assertTrue(e.getMessage().contains("module M") && e.getMessage().contains("export it as RAPID"), e.getMessage());
    }

    @Test
    void write_existingFile_refusedUnlessOverwriteAndNoTempLeft(@TempDir Path dir) throws IOException {
        RapidModule m = ProgramProject.parse(PROJECT, "demo.json");
        Path f = dir.resolve("demo.json");
        ProgramProject.write(m, null, f, false);
        assertEquals(m, ProgramProject.read(f));
        Files.writeString(f, "user data");
        assertThrows(FileAlreadyExistsException.class, () -> ProgramProject.write(m, null, f, false));
        assertEquals("user data", Files.readString(f));
        ProgramProject.write(m, "irb2000", f, true);
        assertTrue(Files.readString(f).contains("\"robot\" : \"irb2000\""));
        try (Stream<Path> s = Files.list(dir)) {
            assertEquals(List.of(f), s.toList(), "no temporary files left");
        }
    }

    @Test
    void write_unwritableModule_fileNotCreated(@TempDir Path dir) {
        RapidModule m = RapidParser.parse("MODULE M\n  PERS pose pp := [[0,0,0],[1,0,0,0]];\nENDMODULE\n", "m.mod");
        Path f = dir.resolve("m.json");
        assertThrows(IllegalArgumentException.class, () -> ProgramProject.write(m, null, f, false));
        assertTrue(Files.notExists(f));
    }

    @Test
    void parse_badNumber_lineColumnAndField() {
        String bad = PROJECT.replace("\"tcp_mm_s\": 10.3", "\"tcp_mm_s\": \"fast\"");
        InputException e = assertThrows(InputException.class, () -> ProgramProject.parse(bad, "demo.json"));
        assertEquals(6, e.line());
        assertEquals("speeds.vWeld.tcp_mm_s", e.field());
        assertEquals(bad.split("\n")[5].indexOf("\"tcp_mm_s\"") + 1, e.column());
    }

    @Test
    void parse_missingField_enclosingObjectLocated() {
        String bad = PROJECT.replace("\"move\": \"MoveC\", \"via\": \"pB\", ", "\"move\": \"MoveC\", ");
        InputException e = assertThrows(InputException.class, () -> ProgramProject.parse(bad, "demo.json"));
        assertEquals("procedures.main[2].via", e.field());
        assertEquals(13, e.line());
        assertEquals(bad.split("\n")[12].indexOf('{') + 1, e.column());
    }

    @Test
    void parse_badMoveKindDuplicateKeyAndBrokenJson_located() {
        InputException kind = assertThrows(InputException.class,
                () -> ProgramProject.parse(PROJECT.replace("\"MoveAbsJ\"", "\"MoveX\""), "demo.json"));
        assertEquals("procedures.main[0].move", kind.field());
        assertEquals(11, kind.line());
        InputException dup = assertThrows(InputException.class,
                () -> ProgramProject.parse(PROJECT.replace("\"zSoft\": {\"tcp_mm\": 5}", "\"zSoft\": {\"tcp_mm\": 5, \"tcp_mm\": 6}"), "demo.json"));
        assertEquals("zones.zSoft.tcp_mm", dup.field());
        assertEquals(7, dup.line());
        InputException json = assertThrows(InputException.class,
                () -> ProgramProject.parse(PROJECT.replace("\"quat\": [0, 0, 1, 0],", "\"quat\": [0, 0, 1, 0]"), "demo.json"));
        assertEquals(9, json.line());
        InputException quat = assertThrows(InputException.class,
                () -> ProgramProject.parse(PROJECT.replace("[0, 0, 1, 0]", "[0, 0, 0, 0]"), "demo.json"));
        assertEquals("targets.pB.quat", quat.field());
        assertEquals(9, quat.line());
    }

    /** Inline ("*") targets have no name in a project: declare each as CONST pInlN. */
    private static RapidModule nameInlineTargets(RapidModule m) {
        List<ModuleItem> decls = new ArrayList<>();
        List<ModuleItem> rest = new ArrayList<>();
        int[] n = {0};
        for (ModuleItem it : m.items()) {
            if (!(it instanceof Procedure p)) { decls.add(it); continue; }
            List<Statement> body = new ArrayList<>();
            for (Statement s : p.body()) {
                if (s instanceof Move mv && mv.toPoint() instanceof Ref.Inline<?> in) {
                    String name = "pInl" + (++n[0]);
                    decls.add(Declaration.constant(name, (RobTarget) in.value()));
                    s = mv.withToPoint(Ref.to(name));
                }
                body.add(s);
            }
            rest.add(p.withBody(body));
        }
        decls.addAll(rest);
        return m.withItems(decls);
    }
}
