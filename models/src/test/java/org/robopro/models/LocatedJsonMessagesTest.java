package org.robopro.models;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** Malformed JSON is reported in words, with file, line and column, and no parser internals. */
class LocatedJsonMessagesTest {
    static String message(String text) {
        return assertThrows(InputException.class, () -> LocatedJson.parse("r.json", text)).getMessage();
    }

    @Test
    void nanSingleQuotesAndControlCharacters_noJacksonText() {
        for (String text : new String[] {"{\"a\": NaN}", "{'a': 1}", "{\"a\": 1,}", "{\"a\": \"x\ty\"}", "{\"a\": tru}", "{\"a\": [1, 2"}) {
            String m = message(text);
            assertTrue(m.startsWith("r.json:1:"), m);
            for (String leak : new String[] {"JsonReadFeature", "enable", "code ", "CTRL-CHAR", "Object starting", "JSON String, Number"})
                assertFalse(m.contains(leak), text + " -> " + m);
        }
        assertTrue(message("{\"a\": NaN}").contains("no NaN"), message("{\"a\": NaN}"));
    }

    @Test
    void robotFile_absurdCoordinateOrJointCount_refusedWithLineAndField() {
        String robot = """
                {"format": "robopro-robot 1", "name": "r", "joints": [
                  {"name": "j1", "type": "revolute", "point": [0, 0, 1e300], "axis": [0, 0, 1]}],
                 "flange": {"origin": [0, 0, 100], "z_axis": [0, 0, 1], "x_axis": [1, 0, 0]}}
                """;
        InputException e = assertThrows(InputException.class, () -> RobotFile.parse("r.json", robot));
        assertTrue(e.line() == 2 && e.getMessage().contains("not a dimension"), e.getMessage());
        StringBuilder many = new StringBuilder("{\"format\": \"robopro-robot 1\", \"name\": \"r\", \"joints\": [");
        for (int i = 0; i < 20_000; i++)
            many.append(i == 0 ? "" : ",").append("{\"name\": \"j").append(i).append("\", \"type\": \"revolute\", \"point\": [0, 0, 0], \"axis\": [0, 0, 1]}");
        many.append("], \"flange\": {\"origin\": [0, 0, 100], \"z_axis\": [0, 0, 1], \"x_axis\": [1, 0, 0]}}");
        e = assertThrows(InputException.class, () -> RobotFile.parse("r.json", many.toString()));
        assertTrue(e.getMessage().contains("at most 64"), e.getMessage());
    }
}
