package org.robopro.kinematics.importers;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.robopro.models.InputException;

/** A table of 20,000 joints used to import and then exhaust memory in `model show`: refused at the row that is too many. */
class ImportLimitsTest {
    @Test
    void dhTableWithTwentyThousandJoints_isRefusedNamingTheLine() {
        StringBuilder sb = new StringBuilder("format: robopro-dh 1\nconvention: standard\nname: huge\nunits: length=m, angle=deg\n"
                + "joint, type, d, a, alpha, theta, min, max\n");
        for (int i = 1; i <= 20_000; i++) sb.append("j").append(i).append(", revolute, 0.1, 0.1, 90, 0, -90, 90\n");
        InputException e = assertThrows(InputException.class,
                () -> DhImporter.parse("huge.dh", sb.toString(), DhImporter.Convention.STANDARD, "huge"));
        assertEquals(5 + 65, e.line(), e.getMessage());
        assertTrue(e.getMessage().contains("at most 64"), e.getMessage());
    }
}
