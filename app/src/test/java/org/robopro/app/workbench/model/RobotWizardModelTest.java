package org.robopro.app.workbench.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.JointType;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;

class RobotWizardModelTest {
    @Test
    void build_fromShippedRobot_sameFramesAsTheShippedModel() {
        RobotDescription irb = RobotLibrary.shipped("irb2000");
        RobotWizardModel w = RobotWizardModel.from(irb);
        RobotWizardModel.Result r = w.build();
        assertTrue(r.ok(), r.error());
        Pose[] expected = KinematicModel.build(irb).linkFrames(new double[6]);
        Pose[] got = r.framesAtZero();
        assertEquals(expected.length, got.length);
        for (int i = 0; i < got.length; i++) assertEquals(0, expected[i].distanceTo(got[i]), 1e-9, "frame " + i);
        double[] q = {0.1, -0.2, 0.3, 0.4, -0.5, 0.6};
        assertEquals(0, KinematicModel.build(irb).flange(q).distanceTo(r.model().orElseThrow().flange(q)), 1e-9);
        assertTrue(r.report().contains("identified parameters"), r.report());
    }

    @Test
    void build_zeroAxis_errorNamesTheJointAndNothingThrows() {
        RobotWizardModel w = RobotWizardModel.from(RobotLibrary.shipped("irb2000"));
        RobotWizardModel.JointRow j = w.joint(1);
        w.setJoint(1, new RobotWizardModel.JointRow(j.name(), j.type(), j.pointMm(), new double[] {0, 0, 0}, j.minDeg(), j.maxDeg(), j.speedDegPerS()));
        RobotWizardModel.Result r = w.build();
        assertFalse(r.ok());
        assertTrue(r.error().contains("axis"), r.error());
        w.setFlange(w.flangeOriginMm(), new double[] {0, 0, 1}, new double[] {0, 0, 1});
        w.setJoint(1, j);
        RobotWizardModel.Result f = w.build();
        assertFalse(f.ok());
        assertTrue(f.error().contains("flange"), f.error());
    }

    @Test
    void addJoint_singleJointUpwards_buildsAndPrismaticMovesAlongItsAxis() {
        RobotWizardModel w = new RobotWizardModel();
        w.addJoint();
        RobotWizardModel.JointRow j = w.joint(0);
        w.setJoint(0, new RobotWizardModel.JointRow("slide", JointType.PRISMATIC, j.pointMm(), new double[] {1, 0, 0}, 0, 800, 500));
        w.setFlange(new double[] {0, 0, 500}, new double[] {1, 0, 0}, new double[] {0, 0, 1});
        RobotWizardModel.Result r = w.build();
        assertTrue(r.ok(), r.error());
        Pose f = r.model().orElseThrow().flange(new double[] {0.25});
        assertEquals(0.25, f.x(), 1e-12, "a prismatic joint in mm-limits moves the flange along x");
        assertEquals(0.5, f.z(), 1e-12);
        assertEquals(0.8, r.robot().orElseThrow().joints().get(0).max(), 1e-12, "prismatic limits typed in mm");
    }

    @Test
    void description_writtenAndReadBack_sameRobot(@TempDir Path dir) {
        RobotWizardModel w = RobotWizardModel.from(RobotLibrary.shipped("puma560"));
        w.setName("puma_copy");
        RobotDescription d = w.build().robot().orElseThrow();
        Path f = dir.resolve("puma_copy.robot.json");
        RobotLibrary.write(d, f, false);
        assertTrue(Files.exists(f));
        RobotDescription back = RobotLibrary.read(f);
        assertEquals("puma_copy", back.name());
        assertEquals(d.joints().size(), back.joints().size());
        for (int i = 0; i < d.joints().size(); i++)
            assertEquals(0, d.joints().get(i).point().minus(back.joints().get(i).point()).norm(), 1e-9);
    }
}
