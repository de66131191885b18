package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.*;

import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.robopro.kinematics.KinematicModel;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;

class EffectSpecTest {
    private static final RobotDescription IRB = RobotLibrary.shipped("irb2000");
    private static final KinematicModel MODEL = KinematicModel.build(IRB);
    private static final GravityTorques G = new GravityTorques(MODEL, IRB.massModel().orElseThrow());

    @Test
    void parse_couplingWithArrow_targetAndSource() {
        EffectSpec s = EffectSpec.parse("joint-coupling:3<-2");
        assertEquals(Effect.Kind.COUPLING, s.kind());
        assertEquals(3, s.joint());
        assertEquals(2, s.source());
        assertEquals(List.of(3, 2), s.effect(MODEL, G).joints1());
        assertEquals(List.of(5, 1), EffectSpec.parse("Joint-Coupling : 5 <- 1").effect(MODEL, G).joints1());
    }

    @Test
    void parse_noJoint_controllerSimDefaults() {
        assertEquals(1, EffectSpec.parse("gear-periodic").joint());
        assertEquals(2, EffectSpec.parse("backlash").joint());
        assertEquals(2, EffectSpec.parse("joint-compliance").joint());
        assertEquals(3, EffectSpec.parse("joint-scale").joint());
        EffectSpec c = EffectSpec.parse("joint-coupling:4");
        assertEquals(4, c.joint());
        assertEquals(3, c.source(), "coupling from the joint before");
        assertEquals(0, EffectSpec.parse("thermal-expansion").joint());
    }

    @Test
    void toString_anySpec_parsesBackToEqualSpec() {
        for (String t : new String[] {"backlash:2", "gear-periodic:1=0.01", "joint-compliance:3=1500000", "thermal-expansion=1.6e-5",
                "joint-scale:1=-0.0002", "joint-coupling:3<-2=0.0005", "gear-periodic:5=0.01,0,0,0.002,0,0"}) {
            EffectSpec s = EffectSpec.parse(t);
            assertEquals(s, EffectSpec.parse(s.toString()), t + " -> " + s);
        }
    }

    @Test
    void parse_badSpecs_throwNamingTheSpec() {
        for (String t : new String[] {"backlush:2", "thermal-expansion:1", "backlash:x", "backlash:0", "backlash:2=abc",
                "joint-coupling:1", "joint-coupling:3<-3", "backlash:2<-1", "joint-scale:1=1,2", "backlash:2=-0.1",
                "joint-compliance:2=0"}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> EffectSpec.parse(t), t);
            assertTrue(e.getMessage().contains("'" + t + "'"), e.getMessage());
        }
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> EffectSpec.parse("backlash:7").effect(MODEL, G));
        assertTrue(e.getMessage().contains("1..6"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> EffectSpec.parse("joint-compliance:2").effect(MODEL, null));
    }

    @Test
    void draw_withValue_convertedToSi() {
        Random r = new Random(1);
        assertArrayEquals(new double[] {Math.toRadians(0.03)}, EffectSpec.parse("backlash:2=0.03").draw(MODEL, G, r).values(), 1e-15);
        assertArrayEquals(new double[] {1e-6}, EffectSpec.parse("joint-compliance:2=1e6").draw(MODEL, G, r).values(), 1e-18);
        assertArrayEquals(new double[] {-2e-4}, EffectSpec.parse("joint-scale:1=-2e-4").draw(MODEL, G, r).values(), 0);
        double[] p = EffectSpec.parse("gear-periodic:1=0.01").draw(MODEL, G, r).values();
        for (int h = 0; h < Effect.HARMONICS; h++)
            assertEquals(Math.toRadians(0.01), Math.hypot(p[2 * h], p[2 * h + 1]), 1e-15, "amplitude of harmonic " + (h + 1));
    }

    @Test
    void draw_noValue_withinIssue4RangesAndSeeded() {
        for (long seed = 0; seed < 50; seed++) {
            Random r = new Random(seed);
            double k = 1 / EffectSpec.parse("joint-compliance:2").draw(MODEL, G, r).values()[0];
            assertTrue(k >= 0.5e6 && k <= 2e6, "stiffness " + k);
            double b = Math.toDegrees(EffectSpec.parse("backlash:1").draw(MODEL, G, r).values()[0]);
            assertTrue(b >= 0.02 && b <= 0.05, "lost motion " + b);
            double[] p = EffectSpec.parse("gear-periodic:2").draw(MODEL, G, r).values();
            double a = Math.toDegrees(Math.hypot(p[0], p[1]));
            assertTrue(a >= 0.004 && a <= 0.01, "harmonic amplitude " + a);
            double[] w = EffectSpec.parse("gear-periodic:5").draw(MODEL, G, r).values();
            double aw = Math.toDegrees(Math.hypot(w[0], w[1]));
            assertTrue(aw >= 0.02 && aw <= 0.05, "wrist harmonic amplitude " + aw);
            double alpha = EffectSpec.parse("thermal-expansion").draw(MODEL, G, r).values()[0];
            assertTrue(alpha >= 12e-6 && alpha <= 23e-6, "alpha " + alpha);
            double eps = Math.abs(EffectSpec.parse("joint-scale:2").draw(MODEL, G, r).values()[0]);
            assertTrue(eps >= 1e-4 && eps <= 3e-4, "scale " + eps);
            double kappa = Math.abs(EffectSpec.parse("joint-coupling:3<-2").draw(MODEL, G, r).values()[0]);
            assertTrue(kappa >= 3e-4 && kappa <= 10e-4, "coupling " + kappa);
        }
        EffectSpec s = EffectSpec.parse("gear-periodic:1");
        assertArrayEquals(s.draw(MODEL, G, new Random(9)).values(), s.draw(MODEL, G, new Random(9)).values(), 0);
    }

    @Test
    void withSize_drawnValues_specReproducesThem() {
        for (String t : new String[] {"backlash:2", "gear-periodic:3", "joint-compliance:2", "thermal-expansion", "joint-scale:1",
                "joint-coupling:3<-2"}) {
            Effect.Term drawn = EffectSpec.parse(t).draw(MODEL, G, new Random(t.hashCode()));
            EffectSpec exact = EffectSpec.parse(EffectSpec.parse(t).withSize(drawn.values()).toString());
            double[] again = exact.draw(MODEL, G, new Random(0)).values();
            for (int i = 0; i < again.length; i++)
                assertEquals(drawn.values()[i], again[i], 1e-12 * Math.abs(drawn.values()[i]), t);
        }
    }
}
