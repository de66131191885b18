package org.robopro.calibration.measurement;

import com.code_intelligence.jazzer.junit.FuzzTest;
import org.robopro.models.InputException;

/**
 * Fuzzes the point-list / joint-log join: any pair of inputs either joins or fails with an
 * InputException naming its file. Regression mode (seed inputs only) without JAZZER_FUZZ=1
 * (docs/testing.md).
 */
class MeasurementJoinFuzzTest {
    @FuzzTest(maxDuration = "15s")
    void join_anyText_joinsOrRaisesInputException(String text) {
        if (text == null) return;
        int cut = text.length() / 2;
        check(text.substring(0, cut), text.substring(cut));
        check(MeasurementJoinTest.POINTS + text, MeasurementJoinTest.LOG);
        check(MeasurementJoinTest.POINTS, MeasurementJoinTest.LOG + text);
        check("time,x,y,z\n" + text, "time,q1,q2,q3,q4,q5,q6\n0,0,0,0,0,0,0\n1,1,1,1,1,1,1\n");
        // Several reflectors per pose: a point column, by name and by time.
        check(MeasurementJoinTest.SMR_POINTS + text, MeasurementJoinTest.LOG);
        check("point,time,x,y,z\n" + text, "time,q1,q2,q3,q4,q5,q6\n0,0,0,0,0,0,0\n1,1,1,1,1,1,1\n");
    }

    private static void check(String points, String log) {
        try {
            MeasurementSet s = MeasurementJoin.join("p.csv", points, "l.csv", log, MeasurementJoinTest.SIX, 0.5);
            if (s.size() == 0) throw new AssertionError("empty result returned instead of an error");
        } catch (InputException expected) {
            if (expected.getMessage() == null || expected.file() == null) throw new AssertionError("error without location", expected);
        }
    }
}
