package org.robopro.app.workbench.scene;

import com.jme3.material.Material;
import com.jme3.math.Quaternion;
import com.jme3.math.Vector3f;
import com.jme3.scene.Geometry;
import com.jme3.scene.Node;
import java.util.List;
import java.util.Locale;
import org.robopro.app.workbench.model.DefaultCell;
import org.robopro.models.JointDescription;
import org.robopro.models.RobotDescription;

/**
 * A procedural model of the ASEA/ABB IRB 2000, for which no public meshes exist: foot and base
 * casting, turntable with the frame's two cheeks and the axis 2 and 3 motors on the shoulder,
 * a box-section upper arm, the parallel-arm linkage (crank on the axis 3 motor, rod beside the
 * upper arm, crank on the forearm), the forearm with the wrist motors at its rear, the forearm
 * tube turning about axis 4, the wrist fork, the wrist and the flange. Every part is placed and
 * sized from the robot file's joint points (shoulder height, upper arm, elbow offset, forearm
 * and wrist lengths), so a calibrated or edited IRB 2000 is drawn to its own proportions.
 * Geometry is in base coordinates at the zero position, hung on the link nodes like a robot
 * file's meshes.
 */
final class Irb2000Model {
    private static final int ORANGE = DefaultCell.ABB_ORANGE;
    private static final int DARK = 0x3A3F47;
    private static final int MOTOR = 0x5B6169;
    private static final int STEEL = 0xA7ADB4;

    private final Node crank = new Node("linkage-crank");
    private final Node rod = new Node("linkage-rod");
    private final Vector3f shoulder;
    private final Vector3f crankVector;

    private Vector3f rodBottom;
    private Vector3f rodTop;

    private Irb2000Model(Vector3f shoulder, Vector3f crankVector) {
        this.shoulder = shoulder;
        this.crankVector = crankVector;
    }

    /** The rod's lower and upper pin at the zero position (base coordinates), for tests. */
    Vector3f rodBottomAtZero() { return rodBottom.clone(); }
    Vector3f rodTopAtZero() { return rodTop.clone(); }
    Node crankNode() { return crank; }
    Node rodNode() { return rod; }

    /** Whether the description is an IRB 2000 (by name, including calibrated and edited copies) with its six joints. */
    static boolean fits(RobotDescription d) {
        return d.dof() == 6 && d.name().toLowerCase(Locale.ROOT).startsWith("irb2000");
    }

    /** Whether axis 3 is the forearm's angle to the horizontal (theta3 = q3 - q2): the parallel-arm linkage. */
    private static boolean parallelArm(RobotDescription d) {
        double[][] c = d.couplingMatrix();
        return Math.abs(c[2][1] + 1) < 1e-9 && Math.abs(c[2][2] - 1) < 1e-9;
    }

    /** Builds the model onto {@code links} (0 = base ... 6); returns it for the linkage's per-frame pose. */
    static Irb2000Model build(RobotDescription d, Node[] links, Shapes shapes) {
        List<JointDescription> js = d.joints();
        Vector3f p1 = Shapes.v(js.get(0).point());
        Vector3f p2 = Shapes.v(js.get(1).point());
        Vector3f p3 = Shapes.v(js.get(2).point());
        Vector3f a2 = Shapes.v(js.get(1).axis()).normalizeLocal();
        Vector3f a4 = Shapes.v(js.get(3).axis()).normalizeLocal();
        Vector3f p5 = Shapes.v(js.get(4).point());
        Vector3f a5 = Shapes.v(js.get(4).axis()).normalizeLocal();
        Vector3f flange = Shapes.v(org.robopro.kinematics.Pose.fromFrame(d.flange()).position());
        Vector3f a6 = flange.subtract(p5);
        if (a6.length() < 1e-3f) a6 = a4.clone();
        a6.normalizeLocal();
        // The forearm axis (axis 4) where it passes over the elbow.
        Vector3f p4 = Shapes.v(js.get(3).point());
        Vector3f elbowOnAxis4 = p4.add(a4.mult(p3.subtract(p4).dot(a4)));
        float upper = p3.distance(p2);
        float k = Math.max(0.6f, Math.min(1.6f, upper / 0.71f));
        Vector3f up = Vector3f.UNIT_Z;
        Vector3f side = a2.clone(); // across the arm (y at zero)
        Material orange = shapes.lit(ORANGE), dark = shapes.lit(DARK), motor = shapes.lit(MOTOR), steel = shapes.lit(STEEL);

        // Link 0: foot plate and the base casting around axis 1.
        float zBase = Math.max(0.12f, 0.34f * p2.z);
        Vector3f foot = new Vector3f(p1.x, p1.y, 0);
        add(links[0], "base-foot", Loft.roundedRect(0.70f * k, 0.62f * k, 0.06f * k, 4), foot, foot.add(0, 0, 0.07f * k), Vector3f.UNIT_X, 1, dark);
        add(links[0], "base-casting", Loft.circle(0.26f * k, 40), foot.add(0, 0, 0.07f * k), foot.add(0, 0, zBase), Vector3f.UNIT_X, 0.88f, orange);

        // Link 1: turntable, lower frame, the two cheeks carrying the shoulder, axis 2 and 3 motors.
        Vector3f t0 = new Vector3f(p1.x, p1.y, zBase);
        add(links[1], "turntable", Loft.circle(0.235f * k, 40), t0, t0.add(0, 0, 0.04f * k), Vector3f.UNIT_X, 1, dark);
        Vector3f frameLo = t0.add(0, 0, 0.04f * k);
        Vector3f frameHi = frameLo.add(0, 0, 0.16f * k);
        Vector3f fc = new Vector3f(p2.x - 0.03f * k, p1.y, 0);
        add(links[1], "frame", Loft.roundedRect(0.42f * k, 0.48f * k, 0.08f * k, 4), new Vector3f(fc.x, fc.y, frameLo.z),
                new Vector3f(fc.x, fc.y, frameHi.z), Vector3f.UNIT_X, 0.92f, orange);
        float cheekIn = 0.16f * k, cheekT = 0.07f * k;
        for (int s = -1; s <= 1; s += 2) {
            Vector3f c0 = p2.add(side.mult(s * (cheekIn + cheekT / 2)));
            Vector3f lo = new Vector3f(c0.x - 0.02f * k, c0.y, frameHi.z - 0.02f * k);
            add(links[1], "frame-cheek" + (s < 0 ? "-a" : "-b"), Loft.roundedRect(cheekT, 0.30f * k, 0.03f * k, 3), lo,
                    new Vector3f(c0.x, c0.y, p2.z), side, 0.8f, orange);
            add(links[1], "shoulder-boss" + (s < 0 ? "-a" : "-b"), Loft.circle(0.13f * k, 36), p2.add(side.mult(s * cheekIn)),
                    p2.add(side.mult(s * (cheekIn + cheekT))), up, 1, orange);
            // Gearbox and motor on the shoulder axis, end cap dark.
            Vector3f g0 = p2.add(side.mult(s * (cheekIn + cheekT)));
            Vector3f g1 = g0.add(side.mult(s * 0.06f * k));
            Vector3f m1 = g1.add(side.mult(s * 0.17f * k));
            add(links[1], "motor-gear" + (s < 0 ? "-3" : "-2"), Loft.circle(0.10f * k, 32), g0, g1, up, 0.9f, orange);
            add(links[1], "motor" + (s < 0 ? "-3" : "-2"), Loft.roundedRect(0.15f * k, 0.15f * k, 0.05f * k, 4), g1, m1, up, 1, motor);
            add(links[1], "motor-cap" + (s < 0 ? "-3" : "-2"), Loft.circle(0.06f * k, 24), m1, m1.add(side.mult(s * 0.03f * k)), up, 0.8f, dark);
        }

        // Link 2: upper arm, a tapered box section between the shoulder and elbow hubs.
        float hubW = 0.075f * k;
        add(links[2], "upper-arm-hub", Loft.circle(0.12f * k, 36), p2.subtract(side.mult(hubW)), p2.add(side.mult(hubW)), up, 1, orange);
        add(links[2], "upper-arm", Loft.roundedRect(0.14f * k, 0.17f * k, 0.035f * k, 4), p2, p3, side, 0.72f, orange);
        add(links[2], "upper-arm-elbow", Loft.circle(0.085f * k, 32), p3.subtract(side.mult(hubW)), p3.add(side.mult(hubW)), up, 1, orange);

        // Link 3: the forearm's rear housing with the wrist motors, on the elbow.
        float houseW = 0.105f * k;
        add(links[3], "forearm-elbow", Loft.circle(0.10f * k, 32), p3.subtract(side.mult(houseW)), p3.add(side.mult(houseW)), up, 1, orange);
        add(links[3], "forearm-web", Loft.roundedRect(0.21f * k, 0.16f * k, 0.04f * k, 4), p3, elbowOnAxis4, side, 1, orange);
        Vector3f rear = elbowOnAxis4.subtract(a4.mult(0.36f * k));
        Vector3f front = elbowOnAxis4.add(a4.mult(0.12f * k));
        add(links[3], "forearm-housing", Loft.roundedRect(0.24f * k, 0.22f * k, 0.06f * k, 4), rear, front, side, 0.9f, orange);
        Vector3f vUp = a4.cross(side).normalizeLocal();
        if (vUp.z < 0) vUp.negateLocal();
        for (int i = 0; i < 3; i++) {
            Vector3f c = rear.add(side.mult((i - 1) * 0.075f * k)).addLocal(vUp.mult(i == 1 ? 0.04f * k : -0.02f * k));
            add(links[3], "wrist-motor-" + (i + 4), Loft.circle(0.04f * k, 20), c, c.subtract(a4.mult(0.12f * k)), side, 1, motor);
        }
        add(links[3], "forearm-bearing", Loft.circle(0.095f * k, 32), front, front.add(a4.mult(0.03f * k)), side, 1, dark);

        // Link 4: the forearm tube to the wrist fork.
        float wristR = 0.062f * k;
        Vector3f tube0 = front.add(a4.mult(0.03f * k));
        Vector3f tube1 = p5.subtract(a4.mult(0.13f * k));
        add(links[4], "forearm-tube", Loft.circle(0.08f * k, 36), tube0, tube1, side, 0.85f, orange);
        for (int s = -1; s <= 1; s += 2) {
            Vector3f c = p5.add(a5.mult(s * (wristR + 0.02f * k)));
            add(links[4], "wrist-fork" + (s < 0 ? "-a" : "-b"), Loft.roundedRect(0.03f * k, 0.11f * k, 0.012f * k, 3),
                    c.subtract(a4.mult(0.16f * k)), c, a5, 1, orange);
            add(links[4], "wrist-boss" + (s < 0 ? "-a" : "-b"), Loft.circle(0.055f * k, 24), c.subtract(a5.mult(0.015f * k)),
                    c.add(a5.mult(0.015f * k)), a4, 1, orange);
        }

        // Link 5: the wrist body on axis 5 and its nose toward the flange.
        add(links[5], "wrist", Loft.circle(wristR, 32), p5.subtract(a5.mult(wristR)), p5.add(a5.mult(wristR)), a4, 1, orange);
        Vector3f nose = p5.add(a6.mult(0.75f * flange.distance(p5)));
        add(links[5], "wrist-nose", Loft.circle(0.055f * k, 32), p5, nose, a5, 0.85f, orange);

        // Link 6: the flange.
        add(links[6], "flange-plate", Loft.circle(0.045f * k, 32), nose, flange, a5, 1, steel);

        if (!parallelArm(d)) return null;
        // Parallel arm: a crank on the axis 3 motor behind the shoulder, a rod parallel to the
        // upper arm, a crank on the forearm behind the elbow (a parallelogram).
        Vector3f back = a4.subtract(a2.mult(a4.dot(a2))).normalizeLocal().negateLocal();
        Vector3f c = back.mult(0.22f * k);
        Vector3f rodSide = side.mult(-(hubW + 0.035f * k));
        Irb2000Model m = new Irb2000Model(p2.clone(), c);
        m.rodBottom = p2.add(rodSide).add(c);
        m.rodTop = p3.add(rodSide).add(c);
        add(m.crank, "linkage-crank-shoulder", Loft.roundedRect(0.03f * k, 0.07f * k, 0.012f * k, 3),
                p2.add(rodSide), p2.add(rodSide).add(c), side, 0.8f, dark);
        add(m.rod, "linkage-rod", Loft.circle(0.022f * k, 20), p2.add(rodSide).add(c), p3.add(rodSide).add(c), side, 1, steel);
        add(links[3], "linkage-crank-elbow", Loft.roundedRect(0.03f * k, 0.06f * k, 0.012f * k, 3),
                p3.add(rodSide), p3.add(rodSide).add(c), side, 0.8f, dark);
        links[2].attachChild(m.crank);
        links[2].attachChild(m.rod);
        m.crank.setUserData("pick", "link:2");
        m.rod.setUserData("pick", "link:2");
        return m;
    }

    /**
     * Poses the linkage for the current joints: in the upper arm's frame the crank turns about
     * the shoulder axis with the forearm (the forearm's rotation relative to the upper arm), and
     * the rod moves with the crank's end, staying parallel to the upper arm.
     */
    void pose(Node forearm) {
        Quaternion r = forearm.getLocalRotation();
        crank.setLocalRotation(r);
        crank.setLocalTranslation(shoulder.subtract(r.mult(shoulder)));
        rod.setLocalTranslation(r.mult(crankVector).subtractLocal(crankVector));
    }

    private static void add(Node n, String name, float[][] profile, Vector3f a, Vector3f b, Vector3f across, float scaleB, Material m) {
        Geometry g = new Geometry(name, Loft.sweep(profile, a, b, across, scaleB));
        g.setMaterial(m);
        n.attachChild(g);
    }
}
