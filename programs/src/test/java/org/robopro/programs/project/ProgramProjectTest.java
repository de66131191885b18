package org.robopro.programs.project;

import org.robopro.programs.rapid.RapidAst;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.models.InputException;
import org.robopro.programs.Move;
import org.robopro.programs.RapidModule;
import org.robopro.programs.RobTarget;
import org.robopro.programs.SameMeaning;
import org.robopro.programs.Statement;
import org.robopro.programs.RapidParser;
import org.robopro.programs.RapidWriter;
import org.robopro.programs.JointTarget;
import org.robopro.programs.SpeedData;
import org.robopro.programs.ZoneData;

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
    void parse_documentedFeatures_valuesInSi() {
        RapidModule m = ProgramProject.parse(PROJECT, "demo.json");
        assertEquals("Demo", m.name());
        assertEquals(RapidAst.Scope.LOCAL, m.declaration("wTable").orElseThrow().scope());
        assertEquals(RapidAst.Storage.PERS, m.declaration("pB").orElseThrow().storage());
        RobTarget pB = (RobTarget) m.declaration("pB").orElseThrow().value();
        assertEquals(0.100123, pB.trans().x(), 1e-15);
        assertEquals(0.0007, pB.trans().z(), 1e-15);
        assertEquals(-1, pB.robconf().cf4());
        assertEquals(0.0103, ((SpeedData) m.declaration("vWeld").orElseThrow().value()).vTcp(), 1e-15);
        assertEquals(Math.toRadians(45.7), ((SpeedData) m.declaration("vWeld").orElseThrow().value()).vOri(), 1e-15);
        assertEquals(0.005, ((ZoneData) m.declaration("zSoft").orElseThrow().value()).pzoneTcp(), 1e-15);
        JointTarget home = (JointTarget) m.declaration("jHome").orElseThrow().value();
        assertEquals(Math.toRadians(0.1), home.robax(1), 1e-15);
        assertEquals(120, home.extax().get(0));
        List<Statement> main = m.procedure("main").orElseThrow().body();
        assertEquals(6, main.size());
        Move l = (Move) main.get(1);
        assertEquals(0.0125, l.v().getAsDouble(), 1e-15);
        assertTrue(l.conc());
        assertEquals(0.0003, ((Move) main.get(2)).z().getAsDouble(), 1e-15);
    }

    @Test
    void parse_exportedAsRapid_sameMeaning() {
        // program export's path for these files: the module read here, written as RAPID and read back.
        RapidModule m = ProgramProject.parse(PROJECT, "demo.json");
        RapidModule back = RapidParser.parse(RapidWriter.export(m).text(), "demo.mod");
        SameMeaning.assertSame(m.declarations(), back.declarations());
        SameMeaning.assertSame(m.procedures(), back.procedures());
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
}
