package org.robopro.kinematics;

/**
 * Closed-form inverse kinematics of six-revolute arms with axis 2 perpendicular to axis 1,
 * axis 3 parallel to axis 2 and a spherical wrist (axes 4, 5, 6 meeting in one point): the
 * IRB-2000, IRB-2400 and PUMA 560 class. Every constant comes from the model's own joint axes
 * at the zero position, so calibrated models that still have this geometry are solved exactly;
 * models close to it (calibrated ones) get approximate solutions that seed the numerical solver.
 *
 * <p>Position: the wrist centre W (fixed in the flange) depends on theta1..3 only. theta1 puts W
 * in the arm plane at the shoulder offset s; in that plane (complex numbers z + i x, where a
 * rotation about the arm's y axis multiplies by e^(i angle)) D = e^(i theta2) (L2 + e^(i phi3) L3)
 * gives phi3 by the law of cosines and theta2 by division. Orientation:
 * R_Z(t4) A R_Z(t5) B R_Z(t6) C = R, with A and B split into Z-X-Z Euler angles.
 */
final class ClosedFormIk {
    private final KinematicModel model;
    final boolean exact;
    // arm frame at axis 1: origin o1, axes x0, y0, z0 (z0 = axis 1, y0 = axis 2 direction)
    private final double[] o1 = new double[3], x0 = new double[3], y0 = new double[3], z0 = new double[3];
    private final double s, a2z, a2x, l2z, l2x, l3z, l3x, sigma3, rho, psi, l2sq, l3sq;
    private final double[] wInFlange = new double[3];
    private final double a1, alpha4, a2b1, alpha5, b2; // wrist Euler constants
    private final double ca4, sa4, ca5, sa5, cpsi, spsi;
    private final double detScale; // |det C| / len^3
    private final double[] cT = new double[9]; // rotation of F6 transposed
    final double frontAxis1Sign, frontArmSign;

    private ClosedFormIk(KinematicModel m, boolean exact, double[][] f0) {
        this.model = m;
        this.exact = exact;
        Vec u1 = axis(f0[0]), u2 = axis(f0[1]), u3 = axis(f0[2]);
        Vec p1 = org(f0[0]), p2 = org(f0[1]), p3 = org(f0[2]);
        Vec w = closest(org(f0[3]), axis(f0[3]), org(f0[4]), axis(f0[4]));
        Vec zz = u1;
        Vec yy = u2.minus(zz.times(u2.dot(zz))).unit();
        Vec xx = yy.cross(zz);
        p1.copyTo(o1); xx.copyTo(x0); yy.copyTo(y0); zz.copyTo(z0);
        sigma3 = Math.signum(u3.dot(yy)) >= 0 ? 1 : -1;
        s = w.minus(p1).dot(yy);
        a2z = p2.minus(p1).dot(zz);
        a2x = p2.minus(p1).dot(xx);
        double a3z = p3.minus(p1).dot(zz), a3x = p3.minus(p1).dot(xx);
        double wz = w.minus(p1).dot(zz), wx = w.minus(p1).dot(xx);
        l2z = a3z - a2z; l2x = a3x - a2x;
        l3z = wz - a3z; l3x = wx - a3x;
        l2sq = l2z * l2z + l2x * l2x;
        l3sq = l3z * l3z + l3x * l3x;
        // conj(L2) * L3 = rho e^(i psi)
        double re = l2z * l3z + l2x * l3x, im = l2z * l3x - l2x * l3z;
        rho = Math.sqrt(re * re + im * im);
        psi = Math.atan2(im, re);
        // wrist centre in flange coordinates
        double[] fl = f0[6];
        double dx = w.x - fl[3], dy = w.y - fl[7], dz = w.z - fl[11];
        wInFlange[0] = fl[0] * dx + fl[4] * dy + fl[8] * dz;
        wInFlange[1] = fl[1] * dx + fl[5] * dy + fl[9] * dz;
        wInFlange[2] = fl[2] * dx + fl[6] * dy + fl[10] * dz;
        double[] fa = m.fixedPart(4), fb = m.fixedPart(5), fc = m.fixedPart(6);
        alpha4 = Math.acos(ModelBuilder.clamp(fa[10]));
        a1 = Math.atan2(fa[2], -fa[6]);
        double aPhi2 = Math.atan2(fa[8], fa[9]);
        alpha5 = Math.acos(ModelBuilder.clamp(fb[10]));
        double bPhi1 = Math.atan2(fb[2], -fb[6]);
        b2 = Math.atan2(fb[8], fb[9]);
        a2b1 = aPhi2 + bPhi1;
        for (int i = 0; i < 3; i++) for (int j = 0; j < 3; j++) cT[3 * i + j] = fc[4 * j + i];
        ca4 = Math.cos(alpha4); sa4 = Math.sin(alpha4); ca5 = Math.cos(alpha5); sa5 = Math.sin(alpha5);
        cpsi = Math.cos(psi); spsi = Math.sin(psi);
        double len = m.characteristicLength();
        detScale = Math.abs(det(m.couplingMatrix())) / (len * len * len);
        // which side is "front" (ABB confdata): the side the wrist centre is on at the zero position
        frontAxis1Sign = wx >= 0 ? 1 : -1;
        double cross0 = l2z * (wx - a2x) - l2x * (wz - a2z);
        frontArmSign = cross0 >= 0 ? 1 : -1;
    }

    /**
     * The solver for this model: exact when the geometry fits within 1e-9 (m, rad), approximate
     * within 0.05 rad and 10 mm (calibrated models), else null.
     */
    static ClosedFormIk of(KinematicModel m) {
        if (m.dof() != 6) return null;
        for (int i = 0; i < 6; i++) if (m.isPrismatic(i)) return null;
        double[][] f0 = m.jointFramesAtTheta(new double[6]);
        Vec u1 = axis(f0[0]), u2 = axis(f0[1]), u3 = axis(f0[2]), u4 = axis(f0[3]), u5 = axis(f0[4]), u6 = axis(f0[5]);
        double dev = Math.abs(u1.dot(u2));
        dev = Math.max(dev, u2.cross(u3).norm());
        // wrist axes must be far from parallel for the Z-X-Z split
        if (u4.cross(u5).norm() < 0.3 || u5.cross(u6).norm() < 0.3) return null;
        Vec w = closest(org(f0[3]), u4, org(f0[4]), u5);
        double len = Math.max(distToLine(w, org(f0[3]), u4), distToLine(w, org(f0[4]), u5));
        len = Math.max(len, distToLine(w, org(f0[5]), u6));
        if (dev < 1e-9 && len < 1e-9) return new ClosedFormIk(m, true, f0);
        if (dev < 0.05 && len < 0.01) return new ClosedFormIk(m, false, f0);
        return null;
    }

    /** Scratch length {@link #solve(double[], double[][], int[], double[], double[])} needs. */
    static final int SCRATCH = 33;

    /**
     * Writes up to 8 model-angle solutions (rows of 6) reaching baseTflange {@code target12};
     * returns how many. Angles wrapped to (-pi, pi]. Allocates its scratch; see the
     * five-argument form for the allocation-free one.
     */
    int solve(double[] target12, double[][] out) {
        return solve(target12, out, null, null, new double[SCRATCH]);
    }

    /**
     * Allocation-free closed form. Besides the angles it writes, per solution, ABB's cfx arm bits
     * ({@code armBits}: 4 = wrist centre behind axis 1, 2 = behind the lower arm; either array may
     * be null) and the unscaled factor |x_p| rho |sin elbow| sin(alpha4) sin(alpha5) |sin T5| of
     * |det J_theta| ({@code detFactor}, see {@link #manipulability}). {@code scratch} holds
     * {@link #SCRATCH} doubles.
     *
     * <p>Sines and cosines of theta1..3 come from the geometry itself (no trig calls); each
     * output angle costs one atan2/acos/asin, shared between branches where possible.
     */
    int solve(double[] t, double[][] out, int[] armBits, double[] detFactor, double[] scratch) {
        double[] frame1 = scratch, frame = scratch; // frame1 at 0..11, frame at 12..23, rtc at 24..32
        double wx = t[0] * wInFlange[0] + t[1] * wInFlange[1] + t[2] * wInFlange[2] + t[3] - o1[0];
        double wy = t[4] * wInFlange[0] + t[5] * wInFlange[1] + t[6] * wInFlange[2] + t[7] - o1[1];
        double wz = t[8] * wInFlange[0] + t[9] * wInFlange[1] + t[10] * wInFlange[2] + t[11] - o1[2];
        double cx = wx * x0[0] + wy * x0[1] + wz * x0[2];
        double cy = wx * y0[0] + wy * y0[1] + wz * y0[2];
        double cz = wx * z0[0] + wy * z0[1] + wz * z0[2];
        double r = Math.sqrt(cx * cx + cy * cy);
        if (r < Math.abs(s) - 1e-12) return 0;
        // theta1 = phi - asin(s / r) or phi - pi + asin(s / r), phi = atan2(cy, cx)
        double phi = r > 0 ? FastTrig.atan2(cy, cx) : 0;
        double cphi = r > 0 ? cx / r : 1, sphi = r > 0 ? cy / r : 0;
        double sa = r > 0 ? ModelBuilder.clamp(s / r) : 0, ca = Math.sqrt(1 - sa * sa);
        double as = FastTrig.asin(sa);
        // R_target C^T, shared by all branches (24..32)
        for (int l = 0; l < 3; l++)
            for (int j = 0; j < 3; j++)
                scratch[24 + 3 * l + j] = t[4 * l] * cT[j] + t[4 * l + 1] * cT[3 + j] + t[4 * l + 2] * cT[6 + j];
        int count = 0;
        for (int shoulder = 0; shoulder < 2; shoulder++) {
            double th1, c1, s1;
            if (shoulder == 0) { th1 = phi - as; c1 = cphi * ca + sphi * sa; s1 = sphi * ca - cphi * sa; }
            else { th1 = phi - Math.PI + as; c1 = -(cphi * ca - sphi * sa); s1 = -(sphi * ca + cphi * sa); }
            double xp = cx * c1 + cy * s1;
            double dz = cz - a2z, dx = xp - a2x;
            double k = (dz * dz + dx * dx - l2sq - l3sq) / 2;
            double ck = rho > 0 ? k / rho : 2;
            if (ck > 1 + 1e-9 || ck < -1 - 1e-9) continue;
            ck = ModelBuilder.clamp(ck);
            double ac = FastTrig.acos(ck), sac = Math.sqrt(1 - ck * ck);
            // frame after joint 1 and F1
            System.arraycopy(fixedF(0), 0, frame1, 0, 12);
            Se3.rotate(frame1, 2, c1, s1);
            Se3.mulInPlace(frame1, fixedF(1));
            for (int elbow = 0; elbow < 2; elbow++) {
                double se = elbow == 0 ? sac : -sac; // sin(+-ac)
                double phi3 = (elbow == 0 ? ac : -ac) - psi;
                double c3 = ck * cpsi + se * spsi, s3 = se * cpsi - ck * spsi; // cos, sin of phi3
                // L2 + e^(i phi3) L3 as z + i x
                double vz = l2z + c3 * l3z - s3 * l3x, vx = l2x + s3 * l3z + c3 * l3x;
                // e^(i theta2) = D conj(V) / |D conj(V)| with D = dz + i dx
                double re2 = dz * vz + dx * vx, im2 = dx * vz - dz * vx, h2 = Math.sqrt(re2 * re2 + im2 * im2);
                double th2 = FastTrig.atan2(im2, re2);
                double c2 = h2 > 0 ? re2 / h2 : 1, s2 = h2 > 0 ? im2 / h2 : 0;
                double th3 = sigma3 * phi3;
                // frame 4 (before joint 4) at theta1..3
                System.arraycopy(frame1, 0, frame, 12, 12);
                rotateZ(frame, 12, c2, s2);
                mulInPlace(frame, 12, fixedF(2));
                rotateZ(frame, 12, c3, sigma3 * s3);
                mulInPlace(frame, 12, fixedF(3));
                // M = R4^T (R_target C^T)
                double m0 = 0, m2 = 0, m3 = 0, m5 = 0, m6 = 0, m8 = 0;
                for (int l = 0; l < 3; l++) {
                    double f0 = frame[12 + 4 * l], f1 = frame[13 + 4 * l], f2 = frame[14 + 4 * l];
                    double r0 = scratch[24 + 3 * l], r2 = scratch[26 + 3 * l];
                    m0 += f0 * r0; m2 += f0 * r2;
                    m3 += f1 * r0; m5 += f1 * r2;
                    m6 += f2 * r0; m8 += f2 * r2;
                }
                double cT5 = (ca4 * ca5 - m8) / (sa4 * sa5);
                if (cT5 > 1 + 1e-9 || cT5 < -1 - 1e-9) continue;
                cT5 = ModelBuilder.clamp(cT5);
                double t5a = FastTrig.acos(cT5), st5 = Math.sqrt(1 - cT5 * cT5);
                int bits = 0;
                if (xp * frontAxis1Sign < 0) bits |= 4;
                double lz = c2 * l2z - s2 * l2x, lx = s2 * l2z + c2 * l2x; // lower arm e^(i theta2) L2
                if ((lz * dx - lx * dz) * frontArmSign < 0) bits |= 2;
                double armDet = Math.abs(xp) * rho * sac * sa4 * sa5 * st5;
                for (int wrist = 0; wrist < 2; wrist++) {
                    double T5 = wrist == 0 ? t5a : -t5a, sT5 = wrist == 0 ? st5 : -st5;
                    double p = sa5 * sT5, qv = -ca4 * sa5 * cT5 - sa4 * ca5;
                    // T4 = atan2(m5, m2) - atan2(qv, p) = arg((m2 + i m5) conj(p + i qv))
                    double T4, c4, s4;
                    if (p * p + qv * qv < 1e-24 || m2 * m2 + m5 * m5 < 1e-24) { T4 = 0; c4 = 1; s4 = 0; } // wrist singular
                    else {
                        double re4 = m2 * p + m5 * qv, im4 = m5 * p - m2 * qv, h4 = Math.sqrt(re4 * re4 + im4 * im4);
                        T4 = FastTrig.atan2(im4, re4); c4 = re4 / h4; s4 = im4 / h4;
                    }
                    // first two columns of G = R_Z(T4) R_X(a4) R_Z(T5) R_X(a5); N = G^T M, T6 = atan2(N10, N00)
                    double u0 = c4 * cT5 - s4 * ca4 * sT5, u1 = s4 * cT5 + c4 * ca4 * sT5, u2 = sa4 * sT5;
                    double k0 = -c4 * sT5 - s4 * ca4 * cT5, k1 = -s4 * sT5 + c4 * ca4 * cT5, k2 = sa4 * cT5;
                    double g01 = ca5 * k0 + sa5 * (s4 * sa4), g11 = ca5 * k1 - sa5 * (c4 * sa4), g21 = ca5 * k2 + sa5 * ca4;
                    double n00 = u0 * m0 + u1 * m3 + u2 * m6;
                    double n10 = g01 * m0 + g11 * m3 + g21 * m6;
                    double T6 = FastTrig.atan2(n10, n00);
                    if (armBits != null) armBits[count] = bits;
                    if (detFactor != null) detFactor[count] = armDet;
                    double[] o = out[count++];
                    o[0] = wrap(th1); o[1] = wrap(th2); o[2] = wrap(th3);
                    o[3] = wrap(T4 - a1); o[4] = wrap(T5 - a2b1); o[5] = wrap(T6 - b2);
                }
            }
        }
        return count;
    }

    /** m[off..off+11] = m * R_Z(c, s). */
    private static void rotateZ(double[] m, int off, double c, double s) {
        for (int i = off; i < off + 12; i += 4) {
            double ma = m[i], mb = m[i + 1];
            m[i] = c * ma + s * mb;
            m[i + 1] = -s * ma + c * mb;
        }
    }

    /** m[off..off+11] = m * f. */
    private static void mulInPlace(double[] m, int off, double[] f) {
        for (int i = off; i < off + 12; i += 4) {
            double r0 = m[i], r1 = m[i + 1], r2 = m[i + 2];
            m[i] = r0 * f[0] + r1 * f[4] + r2 * f[8];
            m[i + 1] = r0 * f[1] + r1 * f[5] + r2 * f[9];
            m[i + 2] = r0 * f[2] + r1 * f[6] + r2 * f[10];
            m[i + 3] += r0 * f[3] + r1 * f[7] + r2 * f[11];
        }
    }

    /**
     * |det J| of the geometric Jacobian (position rows divided by {@code len}) from the unscaled
     * factor of {@link #solve}: det J_q = det J_theta det C, and for this geometry
     * det J_theta = det(arm 3x3 at the wrist centre) det(wrist axes) = x_p rho sin(elbow)
     * * sin(alpha4) sin(alpha5) sin(T5), up to sign.
     */
    double manipulability(double detFactor) { return detFactor * detScale; }

    private double[] fixedF(int k) { return model.fixedRef(k); }

    /** ABB cfx bits: 4 = wrist centre behind axis 1, 2 = behind the lower arm (1 = axis 5 negative, added by the caller). */
    int cfxArmBits(double[] flange12, double theta1, double theta2) {
        double[] m = flange12;
        double dx = m[0] * wInFlange[0] + m[1] * wInFlange[1] + m[2] * wInFlange[2] + m[3] - o1[0];
        double dy = m[4] * wInFlange[0] + m[5] * wInFlange[1] + m[6] * wInFlange[2] + m[7] - o1[1];
        double dz = m[8] * wInFlange[0] + m[9] * wInFlange[1] + m[10] * wInFlange[2] + m[11] - o1[2];
        double cx = dx * x0[0] + dy * x0[1] + dz * x0[2], cy = dx * y0[0] + dy * y0[1] + dz * y0[2];
        double cz = dx * z0[0] + dy * z0[1] + dz * z0[2];
        double c1 = Math.cos(theta1), s1 = Math.sin(theta1);
        double xp = cx * c1 + cy * s1;
        int bits = xp * frontAxis1Sign < 0 ? 4 : 0;
        // lower arm direction e^(i theta2) L2 in the arm plane; cross with (W - axis 2)
        double c2 = Math.cos(theta2), s2 = Math.sin(theta2);
        double lz = c2 * l2z - s2 * l2x, lx = s2 * l2z + c2 * l2x;
        double cross = lz * (xp - a2x) - lx * (cz - a2z);
        if (cross * frontArmSign < 0) bits |= 2;
        return bits;
    }

    /** a wrapped to (-pi, pi]; a cheap branch for the usual |a| <= 3 pi, IEEEremainder otherwise. */
    static double wrap(double a) {
        if (a > -Math.PI && a <= Math.PI) return a;
        if (a > Math.PI && a <= 3 * Math.PI) return a - 2 * Math.PI;
        if (a <= -Math.PI && a > -3 * Math.PI) return a + 2 * Math.PI;
        double r = Math.IEEEremainder(a, 2 * Math.PI);
        return r <= -Math.PI ? r + 2 * Math.PI : r;
    }

    /** Determinant of a small square matrix by Gaussian elimination (constructor use). */
    private static double det(double[][] a0) {
        int n = a0.length;
        double[][] a = new double[n][];
        for (int i = 0; i < n; i++) a[i] = a0[i].clone();
        double d = 1;
        for (int c = 0; c < n; c++) {
            int piv = c;
            for (int r = c + 1; r < n; r++) if (Math.abs(a[r][c]) > Math.abs(a[piv][c])) piv = r;
            if (a[piv][c] == 0) return 0;
            if (piv != c) { double[] t = a[piv]; a[piv] = a[c]; a[c] = t; d = -d; }
            d *= a[c][c];
            for (int r = c + 1; r < n; r++) {
                double f = a[r][c] / a[c][c];
                for (int j = c; j < n; j++) a[r][j] -= f * a[c][j];
            }
        }
        return d;
    }

    // small vector helper for the constructor only
    private record Vec(double x, double y, double z) {
        Vec minus(Vec o) { return new Vec(x - o.x, y - o.y, z - o.z); }
        Vec plus(Vec o) { return new Vec(x + o.x, y + o.y, z + o.z); }
        Vec times(double k) { return new Vec(x * k, y * k, z * k); }
        double dot(Vec o) { return x * o.x + y * o.y + z * o.z; }
        Vec cross(Vec o) { return new Vec(y * o.z - z * o.y, z * o.x - x * o.z, x * o.y - y * o.x); }
        double norm() { return Math.sqrt(dot(this)); }
        Vec unit() { return times(1 / norm()); }
        void copyTo(double[] a) { a[0] = x; a[1] = y; a[2] = z; }
    }

    private static Vec axis(double[] f) { return new Vec(f[2], f[6], f[10]); }

    private static Vec org(double[] f) { return new Vec(f[3], f[7], f[11]); }

    /** Midpoint of the closest points of two lines (p + s u, q + t v). */
    private static Vec closest(Vec p, Vec u, Vec q, Vec v) {
        Vec w = p.minus(q);
        double b = u.dot(v), d = u.dot(w), e = v.dot(w), den = 1 - b * b;
        if (den < 1e-12) return q;
        double sp = (b * e - d) / den, tq = (e - b * d) / den;
        return p.plus(u.times(sp)).plus(q.plus(v.times(tq))).times(0.5);
    }

    private static double distToLine(Vec x, Vec p, Vec u) {
        Vec d = x.minus(p);
        return d.minus(u.times(d.dot(u))).norm();
    }
}
