package org.robopro.calibration.measurement;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.util.Collections;
import java.util.List;
import org.robopro.models.InputException;
import org.robopro.models.JointType;

/**
 * Fuzzes the measurement reader: any input either parses or fails with an InputException.
 * Without JAZZER_FUZZ=1 this runs the seed inputs only (regression mode, part of every build);
 * {@code JAZZER_FUZZ=1 ./mvnw -pl calibration -am test -Dtest=MeasurementReaderFuzzTest
 * -Dsurefire.failIfNoSpecifiedTests=false} fuzzes for the bounded time below.
 */
class MeasurementReaderFuzzTest {
    private static final List<JointType> SIX = Collections.nCopies(6, JointType.REVOLUTE);

    @FuzzTest(maxDuration = "15s")
    void parse_anyText_parsesOrRaisesInputException(String text) {
        if (text == null) return; // Jazzer also tries null, which is not text.
        parseOrInputError(text, SIX);
        parseOrInputError(text, null);
        // The spec example with a mutated data region exercises the row parser deeply.
        parseOrInputError(MeasurementReaderTest.GOOD + text, SIX);
        // Distances between two poses: the first pose's columns and mutated rows.
        parseOrInputError(PairDistanceTest.HEADER + text, SIX);
    }

    private static void parseOrInputError(String text, List<JointType> types) {
        try {
            MeasurementSet s = MeasurementReader.parse("fuzz.csv", text, types);
            if (s.size() == 0) throw new AssertionError("empty result returned instead of an error");
        } catch (InputException expected) {
            if (expected.getMessage() == null || expected.file() == null) throw new AssertionError("error without location", expected);
        }
    }
}
