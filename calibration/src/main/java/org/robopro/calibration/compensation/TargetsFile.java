package org.robopro.calibration.compensation;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.regex.Pattern;
import org.robopro.kinematics.Pose;
import org.robopro.kinematics.Units;
import org.robopro.models.InputException;
import org.robopro.models.TextFiles;

/**
 * Targets for compensation (docs/calibration.md): CSV, mm, one target per line as
 * {@code x,y,z} or {@code x,y,z,qw,qx,qy,qz} (tool orientation, unit quaternion w first).
 * Optional: {@code # key: value} metadata lines ({@code frame: base} or {@code frame: world}),
 * other {@code #} comments, blank lines, and one header row naming the columns (which may add an
 * {@code id} column first). Every violation is an {@link InputException} with line and column.
 */
public final class TargetsFile {
    private static final Pattern NUMBER = Pattern.compile("[+-]?(\\d+\\.?\\d*|\\.\\d+)([eE][+-]?\\d+)?");

    /** One target: an id, the pose (m) and whether the file gave its orientation. */
    public record Target(String id, Pose pose, boolean hasOrientation, int line) { }

    /** The targets and the file's metadata (keys lower-case). */
    public record Targets(List<Target> targets, Map<String, String> metadata) {
        public String frame() { return metadata.getOrDefault("frame", "base"); }
    }

    private TargetsFile() { }

    public static Targets read(Path file, Pose defaultOrientation) throws IOException {
        return parse(file.toString(), TextFiles.readUtf8(file), defaultOrientation);
    }

    /** Parses targets; positions without orientation get {@code defaultOrientation}'s rotation. */
    public static Targets parse(String name, String text, Pose defaultOrientation) {
        String[] lines = text.split("\r\n|\n|\r", -1);
        Map<String, String> meta = new LinkedHashMap<>();
        List<Target> out = new ArrayList<>();
        boolean hasId = false, headerSeen = false;
        int expected = -1;
        for (int i = 0; i < lines.length; i++) {
            String l = lines[i].trim();
            int lineNo = i + 1;
            if (l.isEmpty()) continue;
            if (l.startsWith("#")) {
                int c = l.indexOf(':');
                if (c > 0) meta.put(l.substring(1, c).trim().toLowerCase(Locale.ROOT), l.substring(c + 1).trim());
                continue;
            }
            String[] f = l.split(",", -1);
            if (!headerSeen && out.isEmpty() && Character.isLetter(f[0].trim().isEmpty() ? '0' : f[0].trim().charAt(0))) {
                headerSeen = true;
                List<String> cols = new ArrayList<>();
                for (String s : f) cols.add(s.trim().toLowerCase(Locale.ROOT));
                hasId = !cols.isEmpty() && cols.get(0).equals("id");
                List<String> rest = cols.subList(hasId ? 1 : 0, cols.size());
                if (!rest.equals(List.of("x", "y", "z")) && !rest.equals(List.of("x", "y", "z", "qw", "qx", "qy", "qz")))
                    throw new InputException(name, lineNo, 1, null, "header must be [id,]x,y,z[,qw,qx,qy,qz], not '" + l + "'");
                expected = cols.size();
                continue;
            }
            int off = hasId ? 1 : 0;
            int n = f.length - off;
            if ((expected > 0 && f.length != expected) || (n != 3 && n != 7))
                throw new InputException(name, lineNo, 1, null, "a target has 3 (x,y,z) or 7 (x,y,z,qw,qx,qy,qz) values, this line has " + n);
            double[] v = new double[n];
            int col = 1;
            for (int k = 0; k < f.length; k++) {
                String s = f[k].trim();
                if (k >= off) {
                    if (!NUMBER.matcher(s).matches() || !Double.isFinite(Double.parseDouble(s)))
                        throw new InputException(name, lineNo, col + (f[k].length() - f[k].stripLeading().length()),
                                n == 3 ? new String[] {"x", "y", "z"}[k - off] : new String[] {"x", "y", "z", "qw", "qx", "qy", "qz"}[k - off],
                                "'" + s + "' is not a finite number");
                    v[k - off] = Double.parseDouble(s);
                }
                col += f[k].length() + 1;
            }
            String id = hasId ? f[0].trim() : Integer.toString(out.size() + 1);
            Pose p;
            if (n == 7) {
                double norm = Math.sqrt(v[3] * v[3] + v[4] * v[4] + v[5] * v[5] + v[6] * v[6]);
                if (!(Math.abs(norm - 1) <= 1e-3))
                    throw new InputException(name, lineNo, 0, "qw", String.format(Locale.ROOT, "quaternion length %.6g is not 1", norm));
                p = Pose.fromQuaternion(v[3], v[4], v[5], v[6], Units.mmToM(v[0]), Units.mmToM(v[1]), Units.mmToM(v[2]));
            } else {
                p = Pose.of(defaultOrientation.rotationRowMajor(), Units.mmToM(v[0]), Units.mmToM(v[1]), Units.mmToM(v[2]));
            }
            out.add(new Target(id, p, n == 7, lineNo));
        }
        if (out.isEmpty()) throw new InputException(name, 0, 0, null, "no targets");
        String frame = meta.getOrDefault("frame", "base").toLowerCase(Locale.ROOT);
        if (!frame.equals("base") && !frame.equals("world"))
            throw new InputException(name, 0, 0, "frame", "frame must be 'base' or 'world', not '" + frame + "'");
        return new Targets(Collections.unmodifiableList(out), Collections.unmodifiableMap(meta));
    }
}
