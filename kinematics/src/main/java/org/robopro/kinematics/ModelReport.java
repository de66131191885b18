package org.robopro.kinematics;

import java.util.Locale;
import org.robopro.models.RobotDescription;

/**
 * A printed model report like the seed paper's Fig. 8: the frames at the zero position and every
 * transformation's elementary list with values (mm, deg), identified ones marked.
 */
public final class ModelReport {
    private ModelReport() { }

    public static String of(KinematicModel m) {
        StringBuilder sb = new StringBuilder();
        RobotDescription d = m.description();
        sb.append(String.format(Locale.ROOT, "%s (%s): %d joints, %d identified parameters (4R + 2P + 6 = %d)%n",
                d.name(), d.displayName(), m.dof(), m.parameters().size(), m.expectedParameterCount()));
        if (d.source() != null && !d.source().isBlank()) sb.append("source: ").append(d.source()).append('\n');
        double[][] c = m.couplingMatrix();
        for (int i = 0; i < m.dof(); i++) {
            StringBuilder row = new StringBuilder();
            boolean plain = true;
            for (int jj = -1; jj < m.dof(); jj++) {
                int j = jj < 0 ? i : jj; // the joint's own term first
                if (c[i][j] == 0 || (jj >= 0 && jj == i)) continue;
                if (i != j || c[i][j] != 1) plain = false;
                row.append(row.length() == 0 ? "" : (c[i][j] < 0 ? " - " : " + "));
                double a = row.length() == 0 ? c[i][j] : Math.abs(c[i][j]);
                row.append(a == 1 ? "" : a == -1 ? "-" : fmt(a) + " ").append("q").append(j + 1);
            }
            if (!plain) sb.append("coupling: theta").append(i + 1).append(" = ").append(row).append('\n');
        }
        sb.append("\nFrames at the zero position (base coordinates; origin mm, axes unit):\n");
        sb.append(String.format(Locale.ROOT, "  %-7s %-30s %-24s %-24s%n", "frame", "origin", "x axis", "z axis"));
        Pose[] f = m.linkFrames(new double[m.dof()]);
        for (int i = 0; i < f.length; i++) {
            String name = i == 0 ? "base" : i == f.length - 1 ? "flange" : String.valueOf(i);
            sb.append(String.format(Locale.ROOT, "  %-7s %-30s %-24s %-24s%n", name,
                    vec(f[i].position().x() * 1e3, f[i].position().y() * 1e3, f[i].position().z() * 1e3, "%.3f"),
                    vec(f[i].xAxis().x(), f[i].xAxis().y(), f[i].xAxis().z(), "%.4f"),
                    vec(f[i].zAxis().x(), f[i].zAxis().y(), f[i].zAxis().z(), "%.4f")));
        }
        sb.append("\nTransformations (* = identified; lengths mm, angles deg):\n");
        for (Transformation t : m.transformations()) {
            sb.append("  ").append(t.label()).append("  [").append(t.convention());
            if (!Double.isNaN(t.axisAngle())) sb.append(String.format(Locale.ROOT, ", axes %.1f deg apart", Math.toDegrees(t.axisAngle())));
            sb.append("]\n    ");
            if (t.index() > 0) sb.append(m.isPrismatic(t.index() - 1) ? "T_Z(q" : "R_Z(theta").append(t.index()).append(")  ");
            for (Elementary e : t.elements()) {
                double v = e.op().isRotation() ? Math.toDegrees(e.value()) : e.value() * 1e3;
                sb.append(e.op().symbol()).append('(').append(e.name()).append(" = ").append(fmt(v))
                        .append(e.identified() ? "*" : "").append(")  ");
            }
            sb.setLength(sb.length() - 2);
            sb.append('\n');
        }
        if (!m.identifiabilityNote().isEmpty() && !m.isPlainDh()) sb.append("\nnote: ").append(m.identifiabilityNote()).append('\n');
        return sb.toString();
    }

    private static String vec(double x, double y, double z, String f) {
        return String.format(Locale.ROOT, "(" + f + ", " + f + ", " + f + ")", clean(x), clean(y), clean(z));
    }

    private static double clean(double v) { return Math.abs(v) < 5e-13 ? 0 : v; }

    private static String fmt(double v) {
        v = clean(Math.abs(v) < 5e-10 ? 0 : v);
        return String.format(Locale.ROOT, "%.4f", v).replaceAll("0+$", "").replaceAll("\\.$", "");
    }
}
