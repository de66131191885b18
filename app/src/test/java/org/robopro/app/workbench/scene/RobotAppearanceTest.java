package org.robopro.app.workbench.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.asset.DesktopAssetManager;
import com.jme3.bounding.BoundingBox;
import com.jme3.math.Vector3f;
import com.jme3.scene.Node;
import java.io.InputStream;
import java.nio.file.Path;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.robopro.app.workbench.model.RobotKinematics;
import org.robopro.kinematics.Pose;
import org.robopro.models.JointDescription;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;

/**
 * The robots' looks against their robot files: every shipped link mesh sits on the joint axis
 * it turns about, and the IRB 2000's procedural parallel arm stays a closed parallelogram at
 * any pose (the rod's pins stay on both cranks).
 */
class RobotAppearanceTest {

    @Test
    void shippedMeshes_eachLinkMeshSurroundsItsJointAxis() throws Exception {
        for (var e : org.robopro.app.workbench.model.ShippedMeshes.BY_ROBOT.entrySet()) {
            RobotDescription d = RobotLibrary.shipped(e.getKey());
            for (org.robopro.app.workbench.model.ShippedMeshes.Part part : e.getValue()) {
                String res = org.robopro.app.workbench.model.ShippedMeshes.resource(e.getKey(), part);
                BoundingBox b;
                try (InputStream in = RobotState.class.getResourceAsStream(res)) {
                    assertNotNull(in, res);
                    b = (BoundingBox) StlReader.read(in.readAllBytes(), Path.of(res), 1f).getBound();
                }
                assertTrue(b.getXExtent() > 0.005f && b.getZExtent() > 0.002f, res + " is empty");
                if (part.link() == 0) {
                    assertEquals(0, b.getCenter().z - b.getZExtent(), 0.01, res + ": the base stands on the base frame's floor");
                    continue;
                }
                if (part.file().endsWith("-red")) continue; // a painted mark, not a casting around the axis
                JointDescription j = d.joints().get(part.link() - 1);
                Vector3f p = Shapes.v(j.point()), a = Shapes.v(j.axis()).normalizeLocal();
                Vector3f c = b.getCenter();
                Vector3f nearest = p.add(a.mult(c.subtract(p).dot(a)));
                float slack = 0.005f;
                assertTrue(Math.abs(nearest.x - c.x) <= b.getXExtent() + slack && Math.abs(nearest.y - c.y) <= b.getYExtent() + slack
                        && Math.abs(nearest.z - c.z) <= b.getZExtent() + slack,
                        res + ": joint " + part.link() + " axis misses the mesh (box centre " + c + ", nearest axis point " + nearest + ")");
            }
        }
    }

    @Test
    void irb2000_parallelArm_rodPinsStayOnBothCranksAtAnyPose() {
        RobotDescription d = RobotLibrary.shipped("irb2000");
        RobotKinematics k = RobotKinematics.of(d);
        Node root = new Node("robot");
        Node[] links = new Node[7];
        Node prev = root;
        for (int i = 0; i < links.length; i++) {
            links[i] = new Node("link" + i);
            prev.attachChild(links[i]);
            prev = links[i];
        }
        Shapes shapes = new Shapes(new DesktopAssetManager(true));
        assertTrue(Irb2000Model.fits(d));
        Irb2000Model m = Irb2000Model.build(d, links, shapes);
        assertNotNull(m, "the IRB 2000's coupling theta3 = q3 - q2 is a parallel arm");
        for (int i = 0; i < links.length; i++) assertTrue(links[i].getQuantity() > 0, "link " + i + " has no parts");
        Random rnd = new Random(7);
        for (int trial = 0; trial < 20; trial++) {
            double[] q = new double[6];
            for (int j = 0; j < 6; j++) {
                JointDescription jd = d.joints().get(j);
                q[j] = jd.min() + rnd.nextDouble() * (jd.max() - jd.min());
            }
            Pose[] disp = k.linkDisplacements(q);
            for (int i = 1; i < links.length; i++) Shapes.apply(disp[i - 1].inverse().times(disp[i]), links[i]);
            m.pose(links[3]);
            root.updateGeometricState();
            Vector3f bottom = m.rodBottomAtZero(), top = m.rodTopAtZero();
            Vector3f rodBottom = m.rodNode().getWorldTransform().transformVector(bottom, null);
            Vector3f rodTop = m.rodNode().getWorldTransform().transformVector(top, null);
            Vector3f crankEnd = m.crankNode().getWorldTransform().transformVector(bottom, null);
            Vector3f forearmCrankEnd = links[3].getWorldTransform().transformVector(top, null);
            String at = "q = " + java.util.Arrays.toString(q);
            assertEquals(0, rodBottom.distance(crankEnd), 1e-4, "rod left the shoulder crank at " + at);
            assertEquals(0, rodTop.distance(forearmCrankEnd), 1e-4, "rod left the forearm crank at " + at);
            // The crank turns with axis 3 (the forearm's angle to the horizontal), not with the upper arm.
            Vector3f crankDir = crankEnd.subtract(links[2].getWorldTransform().transformVector(Shapes.v(d.joints().get(1).point()), null));
            Vector3f a2 = links[2].getWorldRotation().mult(Shapes.v(d.joints().get(1).axis())).normalizeLocal();
            crankDir.subtractLocal(a2.mult(crankDir.dot(a2)));
            Vector3f forearmDir = links[3].getWorldRotation().mult(Vector3f.UNIT_X);
            float cosAngle = crankDir.normalize().dot(forearmDir.normalize());
            assertEquals(-1, cosAngle, 0.02, "the shoulder crank points away from the forearm at " + at);
        }
    }
}
