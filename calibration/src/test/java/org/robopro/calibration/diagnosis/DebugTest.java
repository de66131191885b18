package org.robopro.calibration.diagnosis;

import java.util.*;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.PoseConditions;
import org.robopro.models.*;

class DebugTest {
    @Test
    void debug() {
        RobotDescription robot = RobotLibrary.shipped("irb2000");
        String which = System.getProperty("case", "backlash j3");
        for (ConcealedEffectBenchmark.Case c : ConcealedEffectBenchmark.cases()) {
            if (!c.name().equals(which)) continue;
            var t = ConcealedEffectBenchmark.trial(robot, c, Long.getLong("seed", 434242L));
            System.out.println("truth " + t.truth().get(0).effect() + " " + Arrays.toString(t.truth().get(0).values()));
            var d = Diagnoser.diagnose(robot, t.campaign().measurements(), t.campaign().validation());
            System.out.println("outliers " + d.outliers().size() + " geo rms " + d.geometricTrainRmsM() + " sigma " + d.sigmaM());
            System.out.println("notident " + d.notIdentifiable());
            for (var f : d.effects()) System.out.println(f.words());
            for (var f : d.implausible()) System.out.println("IMPL " + f.words());
            System.out.println(d.recommendations());
            System.out.println(d.notes());
        }
    }
}
