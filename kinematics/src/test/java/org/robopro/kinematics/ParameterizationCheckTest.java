package org.robopro.kinematics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.models.JointDescription;
import org.robopro.models.RobotDescription;
import org.robopro.models.Vec3;

class ParameterizationCheckTest {

    @Test
    void check_irb2000PlainDh_singularAtParallelAxes2And3() {
        ParameterizationCheck.Result dh = ParameterizationCheck.check(KinematicModel.buildPlainDh(ReferenceRobots.irb2000()));
        ParameterizationCheck.TransformationCheck t23 = dh.transformations().get(2);
        assertEquals("j2 -> j3", t23.label());
        assertEquals("DH", t23.convention());
        assertTrue(t23.singular(), "rank " + t23.rank());
        assertTrue(t23.detJtJ() < 1e-20, "det " + t23.detJtJ());
        assertTrue(dh.identificationRank() < dh.parameterCount(), "rank " + dh.identificationRank());
        assertFalse(dh.warnings().isEmpty());
    }

    @Test
    void check_irb2000Table1_noSingularityAndWellConditioned() {
        ParameterizationCheck.Result r = ParameterizationCheck.check(KinematicModel.build(ReferenceRobots.irb2000()));
        ParameterizationCheck.TransformationCheck t23 = r.transformations().get(2);
        assertEquals("Hayati", t23.convention());
        for (ParameterizationCheck.TransformationCheck t : r.transformations())
            assertTrue(t.smallestSingularValue() > ParameterizationCheck.NEAR_SINGULAR, t.label() + " " + t.smallestSingularValue());
        assertEquals(30, r.identificationRank());
        assertTrue(r.conditionNumber() < ParameterizationCheck.ILL_CONDITIONED);
        assertTrue(r.warnings().isEmpty(), r.warnings().toString());
    }

    @Test
    void check_shippedRobots_noWarnings() {
        for (RobotDescription d : ReferenceRobots.all())
            assertTrue(ParameterizationCheck.check(KinematicModel.build(d)).warnings().isEmpty(), d.name());
    }

    @Test
    void check_hayatiNearPerpendicularAxes_warnsUser() {
        // A Table 1 model evaluated at values far from those it was built for: axis 3 tilted to
        // 89 deg from axis 2 while keeping the Hayati row (what an identification drifting off
        // would produce) must be reported as near-singular.
        KinematicModel m = KinematicModel.build(ReferenceRobots.irb2000());
        double[] p = m.parameterValues();
        p[m.parameterIndex("j2.alpha")] = Math.toRadians(89.9);
        ParameterizationCheck.Result r = ParameterizationCheck.check(m.withParameterValues(p));
        assertTrue(r.warnings().stream().anyMatch(w -> w.startsWith("j2 -> j3")), r.warnings().toString());
    }

    @Test
    void check_tableOneConventionChoice_staysFarFromSingularAtThe45DegreeSwitch() {
        // Two joints whose axes are 44 and 46 degrees apart: Hayati and DH respectively, both well conditioned.
        for (double deg : new double[] {44, 46}) {
            double a = Math.toRadians(deg);
            RobotDescription base = ReferenceRobots.irb2000();
            List<JointDescription> js = List.of(base.joints().get(0),
                    new JointDescription("j2", base.joints().get(0).type(), new Vec3(0.3, 0, 0.5),
                            new Vec3(Math.sin(a), 0, Math.cos(a)), -3, 3, 1));
            RobotDescription d = base.withJointsAndFlange(js, base.flange());
            d = new RobotDescription(d.name(), d.displayName(), d.joints(), d.flange(), List.of(), d.massModel(),
                    d.meshes(), d.effects(), d.source(), d.provenance());
            ParameterizationCheck.Result r = ParameterizationCheck.check(KinematicModel.build(d));
            ParameterizationCheck.TransformationCheck t = r.transformations().get(1);
            assertEquals(deg < 45 ? "Hayati" : "DH", t.convention());
            assertTrue(t.smallestSingularValue() > ParameterizationCheck.NEAR_SINGULAR, deg + " deg: " + t.smallestSingularValue());
        }
    }

    @Test
    void report_irb2000_listsFramesAndMarksIdentifiedParameters() {
        String s = ModelReport.of(KinematicModel.build(ReferenceRobots.irb2000()));
        assertTrue(s.contains("30 identified parameters"), s);
        assertTrue(s.contains("coupling: theta3 = q3 - q2"), s);
        assertTrue(s.contains("T_X(j2.a = 710*)"), s);
        assertTrue(s.contains("R_Z(j6.offset = 0)"), s);
        assertTrue(s.contains("flange  (1000.000, 0.000, 1615.000)"), s);
    }
}
