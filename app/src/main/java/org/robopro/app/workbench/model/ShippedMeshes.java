package org.robopro.app.workbench.model;

import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.InputException;
import org.robopro.models.RobotDescription;
import org.robopro.programs.collision.CapsuleFit;
import org.robopro.programs.collision.ClearanceChecker;
import org.robopro.programs.collision.Convex;

/**
 * The link meshes robopro ships for robots whose files name none (resources beside their
 * licence and attribution): the IRB 2400 from ROS-Industrial (meshes/irb2400/ATTRIBUTION.md),
 * the PUMA 560 from the Robotics Toolbox for Python (meshes/puma560/ATTRIBUTION.md), each in
 * base coordinates at the zero position; and the STL reading they (and any STL) go through.
 * The 3D view draws them; the collision check fits its link capsules to them.
 */
public final class ShippedMeshes {
    private ShippedMeshes() { }

    /** A shipped mesh file of one link, drawn in one colour. */
    public record Part(int link, String file, int rgb) { }

    private static final int PUMA_BODY = 0xD9D5CB;
    private static final int PUMA_DARK = 0x33363B;
    private static final int PUMA_RED = 0xB3261E;

    /** By robot-name prefix. */
    public static final Map<String, List<Part>> BY_ROBOT = Map.of(
            "irb2400", List.of(new Part(0, "base_link", DefaultCell.ABB_ORANGE), new Part(1, "link_1", DefaultCell.ABB_ORANGE),
                    new Part(2, "link_2", DefaultCell.ABB_ORANGE), new Part(3, "link_3", DefaultCell.ABB_ORANGE),
                    new Part(4, "link_4", DefaultCell.ABB_ORANGE), new Part(5, "link_5", DefaultCell.ABB_ORANGE),
                    new Part(6, "link_6", DefaultCell.ABB_ORANGE)),
            "puma560", List.of(new Part(0, "link_0", PUMA_BODY), new Part(1, "link_1", PUMA_BODY),
                    new Part(2, "link_2", PUMA_BODY), new Part(2, "link_2-dark", PUMA_DARK),
                    new Part(2, "link_2-red", PUMA_RED), new Part(3, "link_3", PUMA_BODY),
                    new Part(4, "link_4", PUMA_BODY), new Part(5, "link_5-dark", PUMA_DARK),
                    new Part(6, "link_6", PUMA_BODY)));

    /** The robot-name prefix whose meshes fit {@code d} (six axes, name starting with it), if any. */
    public static Optional<String> robotOf(RobotDescription d) {
        if (d.dof() != 6) return Optional.empty();
        String name = d.name().toLowerCase(Locale.ROOT);
        return BY_ROBOT.keySet().stream().filter(name::startsWith).findFirst();
    }

    /** The class-path resource of a part. */
    public static String resource(String robot, Part part) {
        return "/org/robopro/app/workbench/meshes/" + robot + "/" + part.file() + ".stl";
    }

    /** A part's triangles (x, y, z of three corners each, metres), or empty when the resource is missing. */
    public static Optional<float[]> triangles(String robot, Part part) throws IOException {
        String res = resource(robot, part);
        try (InputStream in = ShippedMeshes.class.getResourceAsStream(res)) {
            if (in == null) return Optional.empty();
            return Optional.of(stlTriangles(in.readAllBytes(), Path.of(res)));
        }
    }

    private static final Map<List<Object>, List<Convex.Capsule>> FITTED = new java.util.concurrent.ConcurrentHashMap<>();

    /**
     * The collision check's options for a robot: link capsules fitted to its shipped meshes
     * ({@link CapsuleFit}: each link's vertices, around its joint-origin segment or its own axis,
     * whichever encloses them in less volume), else the guessed radius of
     * {@link ClearanceChecker.Options#forRobot}.
     */
    public static ClearanceChecker.Options collisionOptions(RobotDescription d, KinematicModel m) {
        ClearanceChecker.Options o = ClearanceChecker.Options.forRobot(m);
        return linkCapsules(d, m).map(o::withLinkCapsules).orElse(o);
    }

    /** One capsule per link (base first) fitted to the robot's shipped meshes, base coordinates at zero; empty without meshes. */
    public static Optional<List<Convex.Capsule>> linkCapsules(RobotDescription d, KinematicModel m) {
        Optional<String> robot = robotOf(d);
        if (robot.isEmpty()) return Optional.empty();
        Pose[] f = m.linkFrames(new double[m.dof()]);
        List<Object> key = new ArrayList<>(List.of(robot.get()));
        for (Pose p : f) key.add(p.position());
        List<Convex.Capsule> fitted = FITTED.computeIfAbsent(key, k -> fit(robot.get(), f));
        return fitted.isEmpty() ? Optional.empty() : Optional.of(fitted);
    }

    private static List<Convex.Capsule> fit(String robot, Pose[] f) {
        List<Convex.Capsule> out = new ArrayList<>();
        try {
            for (int link = 0; link + 1 < f.length; link++) {
                List<float[]> parts = new ArrayList<>();
                for (Part p : BY_ROBOT.get(robot)) if (p.link() == link) triangles(robot, p).ifPresent(parts::add);
                if (parts.isEmpty()) return List.of(); // a link without a mesh: no fit for this robot
                int n = 0;
                for (float[] t : parts) n += t.length;
                float[] all = new float[n];
                int o = 0;
                for (float[] t : parts) { System.arraycopy(t, 0, all, o, t.length); o += t.length; }
                out.add(CapsuleFit.bound(all, f[link].position(), f[link + 1].position()));
            }
        } catch (IOException e) {
            return List.of();
        }
        return List.copyOf(out);
    }

    /**
     * The triangles of an STL file's bytes (binary or ASCII): nine floats per triangle, in the
     * file's units; {@code file} names it in error messages.
     */
    public static float[] stlTriangles(byte[] b, Path file) {
        return isBinary(b) ? binary(b) : ascii(new String(b, StandardCharsets.US_ASCII), file);
    }

    private static boolean isBinary(byte[] b) {
        if (b.length < 84) return false;
        long n = ByteBuffer.wrap(b, 80, 4).order(ByteOrder.LITTLE_ENDIAN).getInt() & 0xffffffffL;
        return 84 + 50 * n == b.length;
    }

    private static float[] binary(byte[] b) {
        ByteBuffer bb = ByteBuffer.wrap(b).order(ByteOrder.LITTLE_ENDIAN);
        int n = bb.getInt(80);
        float[] out = new float[n * 9];
        for (int t = 0; t < n; t++) {
            int o = 84 + 50 * t + 12;
            for (int k = 0; k < 9; k++) out[t * 9 + k] = bb.getFloat(o + 4 * k);
        }
        return out;
    }

    private static float[] ascii(String s, Path file) {
        List<Float> v = new ArrayList<>();
        String[] lines = s.split("\n");
        for (int i = 0; i < lines.length; i++) {
            String l = lines[i].trim();
            if (!l.toLowerCase(Locale.ROOT).startsWith("vertex")) continue;
            String[] p = l.split("\\s+");
            if (p.length != 4) throw new InputException(file.toString(), i + 1, 1, "vertex", "expected 'vertex x y z'");
            try {
                for (int k = 1; k <= 3; k++) v.add(Float.parseFloat(p[k]));
            } catch (NumberFormatException e) {
                throw new InputException(file.toString(), i + 1, 1, "vertex", "not a number: " + l);
            }
        }
        if (v.isEmpty() || v.size() % 9 != 0)
            throw new InputException(file.toString(), 0, 0, "facet", "no complete triangles (is this an STL file?)");
        float[] out = new float[v.size()];
        for (int i = 0; i < out.length; i++) out[i] = v.get(i);
        return out;
    }
}
