package org.robopro.kinematics.importers;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;
import java.util.HashMap;
import java.util.Map;
import java.util.Random;
import javax.xml.parsers.DocumentBuilderFactory;
import org.junit.jupiter.api.Test;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.Vec3;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;

/**
 * A URDF mimic joint is imported as the coupling it is: the imported model's flange equals the
 * URDF's own kinematics, evaluated here independently of the importer (ROS URDF spec: a joint's
 * child frame is parent * origin(xyz, rpy) * motion(axis, value); rpy are fixed-axis roll, pitch,
 * yaw, R = Rz(yaw) Ry(pitch) Rx(roll); a mimic joint's value is multiplier * value_of_joint + offset).
 */
class UrdfMimicTest {
    /** tool0 of the URDF for the given values of the non-mimic joints, by walking the XML from tool0 up. */
    static Pose urdfTool0(String urdf, Map<String, Double> values) throws Exception {
        Document d = DocumentBuilderFactory.newInstance().newDocumentBuilder()
                .parse(new ByteArrayInputStream(urdf.getBytes(StandardCharsets.UTF_8)));
        NodeList js = d.getElementsByTagName("joint");
        Map<String, Element> byChild = new HashMap<>(), byName = new HashMap<>();
        for (int i = 0; i < js.getLength(); i++) {
            Element j = (Element) js.item(i);
            byChild.put(((Element) j.getElementsByTagName("child").item(0)).getAttribute("link"), j);
            byName.put(j.getAttribute("name"), j);
        }
        Pose t = Pose.IDENTITY;
        String link = "tool0";
        while (byChild.containsKey(link)) {
            Element j = byChild.get(link);
            Pose step = origin(j);
            String type = j.getAttribute("type");
            if (!type.equals("fixed")) {
                double v = value(j, byName, values);
                Vec3 axis = vec(((Element) j.getElementsByTagName("axis").item(0)).getAttribute("xyz"));
                step = step.times(type.equals("prismatic") ? Pose.translation(axis.times(v)) : Pose.rotAxis(axis, v));
            }
            t = step.times(t);
            link = ((Element) j.getElementsByTagName("parent").item(0)).getAttribute("link");
        }
        return t;
    }

    static double value(Element j, Map<String, Element> byName, Map<String, Double> values) {
        NodeList m = j.getElementsByTagName("mimic");
        if (m.getLength() == 0) return values.get(j.getAttribute("name"));
        Element e = (Element) m.item(0);
        double mult = e.hasAttribute("multiplier") ? Double.parseDouble(e.getAttribute("multiplier")) : 1;
        double off = e.hasAttribute("offset") ? Double.parseDouble(e.getAttribute("offset")) : 0;
        return mult * value(byName.get(e.getAttribute("joint")), byName, values) + off;
    }

    static Pose origin(Element j) {
        NodeList o = j.getElementsByTagName("origin");
        if (o.getLength() == 0) return Pose.IDENTITY;
        Element e = (Element) o.item(0);
        Vec3 xyz = e.hasAttribute("xyz") ? vec(e.getAttribute("xyz")) : Vec3.ZERO;
        Vec3 rpy = e.hasAttribute("rpy") ? vec(e.getAttribute("rpy")) : Vec3.ZERO;
        return Pose.translation(xyz).times(Pose.rotZ(rpy.z())).times(Pose.rotY(rpy.y())).times(Pose.rotX(rpy.x()));
    }

    static Vec3 vec(String s) {
        String[] p = s.trim().split("\\s+");
        return new Vec3(Double.parseDouble(p[0]), Double.parseDouble(p[1]), Double.parseDouble(p[2]));
    }

    static void check(String urdf) throws Exception {
        KinematicModel m = KinematicModel.build(UrdfImporter.parse("small-arm.urdf", urdf));
        Random rnd = new Random(3);
        for (int k = 0; k < 50; k++) {
            double w = rnd.nextDouble() * 6 - 3, lift = rnd.nextDouble() * 0.5, wr = rnd.nextDouble() * 4 - 2;
            Pose ours = m.flange(new double[] {w, lift, wr, 0});
            Pose theirs = urdfTool0(urdf, Map.of("waist_joint", w, "lift", lift, "wrist_joint", wr));
            assertTrue(ours.position().minus(theirs.position()).norm() < 1e-12 && ours.angleTo(theirs) < 1e-12,
                    "q = " + w + ", " + lift + ", " + wr + ": " + ours + " vs URDF " + theirs);
        }
    }

    @Test
    void mimicJoint_importedAsCoupling_flangeEqualsTheUrdfsOwnKinematics() throws Exception {
        check(DhImporterTest.resource("small-arm.urdf"));
    }

    @Test
    void mimicWithOffsetAndPrismaticMimic_flangeEqualsTheUrdfsOwnKinematics() throws Exception {
        String urdf = DhImporterTest.resource("small-arm.urdf");
        check(urdf.replace("<mimic joint=\"wrist_joint\" multiplier=\"0.5\"/>", "<mimic joint=\"wrist_joint\" multiplier=\"-1.5\" offset=\"0.3\"/>"));
        check(urdf.replace("<mimic joint=\"wrist_joint\" multiplier=\"0.5\"/>", "<mimic joint=\"lift\" multiplier=\"2\" offset=\"-0.2\"/>"));
    }
}
