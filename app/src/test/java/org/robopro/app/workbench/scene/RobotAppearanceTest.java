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
import org.robopro.app.workbench.model.ShippedMeshes;
import org.robopro.kinematics.Pose;
import org.robopro.models.JointDescription;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;

/**
 * The robots' looks against their robot files: every shipped link mesh sits on the joint axis
 * it turns about, the PUMA's forearm meets its wrist without a step, and the IRB 2000's procedural parallel arm stays a closed parallelogram at
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

    /**
     * The PUMA 560's forearm casting ends where its wrist starts: the cross-sections of link 3's
     * top and link 4's bottom (base coordinates at zero, both around the robot file's axis 4)
     * are centred within 2 mm of each other and of axis 4, and are about the same width.
     */
    @Test
    void puma560_forearmMeetsTheWristWithoutAStep() throws Exception {
        RobotDescription d = RobotLibrary.shipped("puma560");
        Vector3f axis4 = Shapes.v(d.joints().get(3).point());
        float[] top = slab(ShippedMeshes.triangles("puma560", part("link_3")).orElseThrow(), true);
        float[] bottom = slab(ShippedMeshes.triangles("puma560", part("link_4")).orElseThrow(), false);
        assertEquals(top[0], bottom[0], 0.002, "forearm top and wrist bottom centres in x");
        assertEquals(top[1], bottom[1], 0.002, "forearm top and wrist bottom centres in y");
        assertEquals(axis4.x, bottom[0], 0.002, "wrist on axis 4 (x)");
        assertEquals(axis4.y, bottom[1], 0.002, "wrist on axis 4 (y)");
        assertEquals(top[2], bottom[2], 0.006, "forearm top and wrist bottom widths in x");
    }

    private static ShippedMeshes.Part part(String file) {
        return ShippedMeshes.BY_ROBOT.get("puma560").stream().filter(p -> p.file().equals(file)).findFirst().orElseThrow();
    }

    /** Centre x, centre y and width in x of the vertices within 30 mm of a mesh's top (or bottom). */
    private static float[] slab(float[] tri, boolean top) {
        float end = top ? -Float.MAX_VALUE : Float.MAX_VALUE;
        for (int i = 2; i < tri.length; i += 3) end = top ? Math.max(end, tri[i]) : Math.min(end, tri[i]);
        float x0 = Float.MAX_VALUE, x1 = -Float.MAX_VALUE, y0 = Float.MAX_VALUE, y1 = -Float.MAX_VALUE;
        for (int i = 0; i < tri.length; i += 3) {
            if (Math.abs(tri[i + 2] - end) > 0.03f) continue;
            x0 = Math.min(x0, tri[i]); x1 = Math.max(x1, tri[i]);
            y0 = Math.min(y0, tri[i + 1]); y1 = Math.max(y1, tri[i + 1]);
        }
        return new float[] {(x0 + x1) / 2, (y0 + y1) / 2, x1 - x0};
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
