package org.robopro.calibration.identification;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.ModelParameter;
import org.robopro.kinematics.Pose;
import org.robopro.kinematics.Se3;
import org.robopro.models.Vec3;

/**
 * The identification problem (seed paper §5, docs/calibration.md) as pluggable parameter blocks, each contributing
 * Jacobian columns per pose:
 * <ul>
 * <li><b>geometry</b>: the kinematic model's Table-1 parameters (analytic columns from
 *     {@link KinematicModel#poseJacobian});</li>
 * <li><b>tool</b>: the measured point on the flange (3; m) or, with orientations, the whole tool
 *     frame (3 + 3: translation, then a rotation vector perturbed on the left in flange axes);
 *     with P &gt; 1 measured points per pose, one point each ({@code tool1.x} ... {@code toolP.z});</li>
 * <li><b>instrument</b>: instrumentTbase (3 translation + 3 rotation, perturbed on the left in
 *     instrument axes), absent when the positions are in the base frame; for distance-only rows
 *     the anchor's position in the base frame instead ({@code anchor.x/y/z}, 3);</li>
 * <li><b>effects</b>: {@link EffectBlock}s (diagnosis), chained through the joint-angle Jacobian.</li>
 * </ul>
 * Prediction (instrument frame): p = R_ib (baseTflange(q + Δq) · t_ft + dp) + t_ib, and for 6-D
 * data R = R_ib R_bf R_ft. Residuals are (predicted − measured) / σ per row: positions first (3
 * per pose and point, points in order), then rotations Log(R_pred R_measᵀ) (3 per pose) when
 * orientations are measured; for a distance row one residual (|p − a| − d) / σ with a the anchor.
 * The layout (points per pose, distances) follows the rows: every row must have the first's shape.
 * Parameters in {@code fixed} keep their start value; the {@link LeastSquaresProblem} view sees
 * the free ones only. One problem per thread (it owns a workspace).
 */
public final class IdentificationProblem implements LeastSquaresProblem {
    /** Which block a parameter belongs to. */
    public enum Block { GEOMETRY, TOOL, INSTRUMENT, EFFECT }

    private final KinematicModel model;
    private final List<Measurement> rows;
    private final boolean sixD, instrument, distance, pairs;
    /** Distances between pairs of poses: the two ends of every row as position rows (no instrument), evaluated in metres. */
    private final IdentificationProblem ends;
    /** The residuals of {@link #ends} (its Jacobian goes to its own {@code jFull}), kept so that an evaluation allocates neither. */
    private final double[] endRes;
    private final int points;
    private final List<EffectBlock> effects;
    private final int nGeo, toolOff, toolSize, instOff, effOff, nFull;
    private final int[] effStart;
    private final List<String> names = new ArrayList<>();
    private final List<String> units = new ArrayList<>();
    private final List<Block> blocks = new ArrayList<>();
    private final double[] priority;
    private final double[] start;
    private final boolean[] fixed;
    private int[] free;
    private double sigmaPos = 1e-4, sigmaRot = 1e-4;
    private final int m;
    // work buffers
    private final KinematicModel.Workspace ws;
    private final double[] pose12 = new double[12], flange12 = new double[12], jg, jFull;
    private final double[][] cInvCols;

    /**
     * @param model       the model whose structure is identified (values come from the parameter vector)
     * @param rows        the measurements used
     * @param sixD        orientations are measured (every row has one)
     * @param instrument  positions are in an unknown instrument frame
     * @param effects     extra effect blocks (may be empty)
     * @param start       full start vector (see {@link #names()} for the layout)
     */
    public IdentificationProblem(KinematicModel model, List<Measurement> rows, boolean sixD, boolean instrument,
                                 List<EffectBlock> effects, double[] start) {
        this.model = model;
        this.rows = List.copyOf(rows);
        Measurement first = this.rows.isEmpty() ? null : this.rows.get(0);
        this.distance = first != null && first.isDistance();
        this.pairs = distance && first.isPair();
        this.points = first == null || distance ? 1 : first.points().size();
        for (Measurement r : this.rows)
            if (r.isDistance() != distance || r.isPair() != pairs || !distance && r.points().size() != points)
                throw new IllegalArgumentException("pose " + r.poseId() + " is not shaped like the first pose (points, distance, pair)");
        if (sixD && (points > 1 || distance))
            throw new IllegalArgumentException("orientations go with one measured point per pose");
        this.sixD = sixD;
        this.instrument = instrument && !distance;
        this.effects = List.copyOf(effects);
        List<ModelParameter> ps = model.parameters();
        nGeo = ps.size();
        for (ModelParameter p : ps) {
            names.add(p.name());
            units.add(p.unitSi());
            blocks.add(Block.GEOMETRY);
        }
        toolOff = nGeo;
        toolSize = sixD ? 6 : 3 * points;
        for (int k = 0; k < points; k++) {
            String t = points == 1 ? "tool." : "tool" + (k + 1) + ".";
            for (String s : new String[] {"x", "y", "z"}) { names.add(t + s); units.add("m"); blocks.add(Block.TOOL); }
        }
        if (sixD) for (String s : new String[] {"tool.rx", "tool.ry", "tool.rz"}) { names.add(s); units.add("rad"); blocks.add(Block.TOOL); }
        instOff = toolOff + toolSize;
        if (this.instrument) {
            for (String s : new String[] {"instrument.x", "instrument.y", "instrument.z"}) { names.add(s); units.add("m"); blocks.add(Block.INSTRUMENT); }
            for (String s : new String[] {"instrument.rx", "instrument.ry", "instrument.rz"}) { names.add(s); units.add("rad"); blocks.add(Block.INSTRUMENT); }
        }
        if (distance && !pairs)
            for (String s : new String[] {"anchor.x", "anchor.y", "anchor.z"}) { names.add(s); units.add("m"); blocks.add(Block.INSTRUMENT); }
        effOff = instOff + (this.instrument ? 6 : distance && !pairs ? 3 : 0);
        effStart = new int[this.effects.size() + 1];
        int off = effOff;
        for (int k = 0; k < this.effects.size(); k++) {
            effStart[k] = off;
            EffectBlock e = this.effects.get(k);
            for (int i = 0; i < e.parameterNames().size(); i++) {
                names.add(e.name() + "." + e.parameterNames().get(i));
                units.add(e.units().get(i));
                blocks.add(Block.EFFECT);
            }
            off += e.parameterNames().size();
        }
        effStart[this.effects.size()] = off;
        nFull = off;
        if (start.length != nFull) throw new IllegalArgumentException("start vector has " + start.length + " values, layout needs " + nFull);
        this.start = start.clone();
        priority = new double[nFull];
        for (int i = 0; i < nFull; i++)
            priority[i] = switch (blocks.get(i)) {
                case GEOMETRY -> 1.0;
                case TOOL -> 0.5;
                case INSTRUMENT -> 0.25;
                case EFFECT -> 1.0;
            };
        for (int k = 0; k < this.effects.size(); k++)
            for (int i = effStart[k]; i < effStart[k + 1]; i++) priority[i] = this.effects.get(k).fixPriority();
        fixed = new boolean[nFull];
        free = allIndices(nFull);
        if (pairs) {
            // The same measurement function at both ends of each length: the layout (geometry, tool, effects) is the same.
            List<Measurement> endRows = new ArrayList<>();
            for (Measurement r : this.rows) { endRows.add(r.firstPose()); endRows.add(r.secondPose()); }
            ends = new IdentificationProblem(model, endRows, false, false, this.effects, start);
            ends.setSigmas(1, 1);
            endRes = new double[ends.residualCount()];
        } else {
            ends = null;
            endRes = null;
        }
        m = this.rows.size() * rowsPerPose();
        ws = model.newWorkspace();
        jg = new double[6 * nGeo];
        jFull = new double[m * nFull];
        int dof = model.dof();
        cInvCols = new double[dof][];
        if (!this.effects.isEmpty())
            for (int j = 0; j < dof; j++) {
                double[] e = new double[dof];
                e[j] = 1;
                cInvCols[j] = model.q(e); // dq/dθ_j: q = C⁻¹ θ is linear
            }
    }

    private static int[] allIndices(int n) {
        int[] a = new int[n];
        for (int i = 0; i < n; i++) a[i] = i;
        return a;
    }

    /** The start vector for a model, a tool frame and (optionally) an instrument pose; effect values from the blocks. */
    public static double[] startVector(KinematicModel model, Pose flangeTtool, boolean sixD, Pose instrumentTbase,
                                       List<EffectBlock> effects) {
        return startVector(model, flangeTtool, List.of(), sixD, instrumentTbase, null, effects);
    }

    /**
     * The start vector with several measured points: {@code flangeTtool} for the first (and the
     * tool rotation with orientations), {@code morePoints} for points 2..P (flange coordinates, m);
     * {@code anchor} (base frame, m) for distance rows, else null.
     */
    public static double[] startVector(KinematicModel model, Pose flangeTtool, List<Vec3> morePoints, boolean sixD,
                                       Pose instrumentTbase, Vec3 anchor, List<EffectBlock> effects) {
        List<Double> v = new ArrayList<>();
        for (double p : model.parameterValues()) v.add(p);
        v.add(flangeTtool.x()); v.add(flangeTtool.y()); v.add(flangeTtool.z());
        for (Vec3 p : morePoints) { v.add(p.x()); v.add(p.y()); v.add(p.z()); }
        if (sixD) { var w = flangeTtool.rotationVector(); v.add(w.x()); v.add(w.y()); v.add(w.z()); }
        if (instrumentTbase != null) {
            v.add(instrumentTbase.x()); v.add(instrumentTbase.y()); v.add(instrumentTbase.z());
            var w = instrumentTbase.rotationVector();
            v.add(w.x()); v.add(w.y()); v.add(w.z());
        }
        if (anchor != null) { v.add(anchor.x()); v.add(anchor.y()); v.add(anchor.z()); }
        for (EffectBlock e : effects) for (double d : e.initialValues()) v.add(d);
        return v.stream().mapToDouble(Double::doubleValue).toArray();
    }

    // ------------------------------------------------------------------ layout

    public List<String> names() { return List.copyOf(names); }
    public List<String> unitsSi() { return List.copyOf(units); }
    public List<Block> blocks() { return List.copyOf(blocks); }
    public double[] fixPriorities() { return priority.clone(); }
    public int fullSize() { return nFull; }
    public int geometryCount() { return nGeo; }
    public int toolOffset() { return toolOff; }
    public int instrumentOffset() { return instrument ? instOff : -1; }
    public int effectOffset(int k) { return effStart[k]; }
    public boolean sixD() { return sixD; }
    public boolean hasInstrument() { return instrument; }
    /** Measured points per pose (1 for distance rows). */
    public int pointCount() { return points; }
    /** Distance-only rows: one residual per pose, an anchor block (none for pairs of poses). */
    public boolean distance() { return distance; }
    /** Distances between pairs of poses: no anchor. */
    public boolean pairs() { return pairs; }
    /** Full index of anchor.x, or -1 without distance rows to an anchor. */
    public int anchorOffset() { return distance && !pairs ? instOff : -1; }
    public List<Measurement> rows() { return rows; }
    public List<EffectBlock> effects() { return effects; }
    public double[] start() { return start.clone(); }
    public KinematicModel model() { return model; }

    /** Residual rows per pose: 3 per measured point, 6 with orientations, 1 for a distance. */
    public int rowsPerPose() { return distance ? 1 : sixD ? 6 : 3 * points; }

    /** Position (or distance) residual rows per pose, before any rotation rows: 3 per measured point, 1 for a distance. */
    public int positionRowsPerPose() { return distance ? 1 : 3 * points; }

    /** Components of one measurement's error: 3 for a point, 1 for a distance. */
    public int measurementSize() { return distance ? 1 : 3; }

    /** Measurements per pose: the measured points, or one distance. */
    public int measurementsPerPose() { return distance ? 1 : points; }

    /**
     * The error of every measurement from weighted residuals of this layout (pose by pose, points
     * in order): each point's position error norm, or a distance error's magnitude, in residual
     * units times {@code sigma} (the position σ the residuals were weighted with gives metres).
     */
    public double[] measurementErrors(double[] r, double sigma) {
        int rpp = rowsPerPose(), per = measurementsPerPose(), d = measurementSize();
        int poses = r.length / rpp;
        double[] out = new double[poses * per];
        for (int i = 0; i < poses; i++)
            for (int k = 0; k < per; k++) {
                double s = 0;
                for (int a = 0; a < d; a++) s += r[i * rpp + d * k + a] * r[i * rpp + d * k + a];
                out[i * per + k] = Math.sqrt(s) * sigma;
            }
        return out;
    }

    /** RMS of {@link #measurementErrors}: over every measured point, or every distance. */
    public double measurementRms(double[] r, double sigma) {
        double[] e = measurementErrors(r, sigma);
        double s = 0;
        for (double v : e) s += v * v;
        return Math.sqrt(s / Math.max(1, e.length));
    }

    /** Standard deviations that weight position (m) and rotation (rad) residuals. */
    public void setSigmas(double sigmaPosM, double sigmaRotRad) {
        if (!(sigmaPosM > 0) || !(sigmaRotRad > 0)) throw new IllegalArgumentException("sigmas must be > 0: " + sigmaPosM + ", " + sigmaRotRad);
        sigmaPos = sigmaPosM;
        sigmaRot = sigmaRotRad;
    }

    public double sigmaPos() { return sigmaPos; }
    public double sigmaRot() { return sigmaRot; }

    /** Fixes parameters (by full index) at their start values; the rest are free. */
    public void setFixed(boolean[] fix) {
        if (fix.length != nFull) throw new IllegalArgumentException("fixed mask has " + fix.length + " entries, need " + nFull);
        System.arraycopy(fix, 0, fixed, 0, nFull);
        int c = 0;
        for (boolean b : fix) if (!b) c++;
        free = new int[c];
        c = 0;
        for (int i = 0; i < nFull; i++) if (!fix[i]) free[c++] = i;
    }

    public boolean[] fixedMask() { return fixed.clone(); }
    public int[] freeIndices() { return free.clone(); }

    /** The free part of a full vector. */
    public double[] freeOf(double[] full) {
        double[] x = new double[free.length];
        for (int k = 0; k < free.length; k++) x[k] = full[free[k]];
        return x;
    }

    /** The full vector: start values with the free part replaced. */
    public double[] fullOf(double[] x) {
        double[] full = start.clone();
        for (int k = 0; k < free.length; k++) full[free[k]] = x[k];
        return full;
    }

    // ------------------------------------------------------------------ LeastSquaresProblem (free view)

    @Override public int parameterCount() { return free.length; }
    @Override public int residualCount() { return m; }

    @Override
    public void evaluate(double[] x, double[] residuals, double[] jacobian) {
        double[] full = fullOf(x);
        evaluateFull(full, residuals, jacobian == null ? null : jFull);
        if (jacobian != null) {
            int nf = free.length;
            for (int r = 0; r < m; r++) {
                int src = r * nFull, dst = r * nf;
                for (int k = 0; k < nf; k++) jacobian[dst + k] = jFull[src + free[k]];
            }
        }
    }

    @Override
    public void retract(double[] x, double[] step, double[] out) {
        for (int k = 0; k < x.length; k++) out[k] = x[k] + step[k];
        // Rotation-vector parameters move on SO(3): R' = Exp(step) R, not w + step.
        retractRotation(x, step, out, toolOff + 3 * points, sixD);
        retractRotation(x, step, out, instOff + 3, instrument);
    }

    private void retractRotation(double[] x, double[] step, double[] out, int fullIdx, boolean present) {
        if (!present) return;
        int k0 = Arrays.binarySearch(free, fullIdx);
        int k1 = Arrays.binarySearch(free, fullIdx + 1);
        int k2 = Arrays.binarySearch(free, fullIdx + 2);
        if (k0 < 0 || k1 < 0 || k2 < 0) return; // a partly fixed rotation stays additive (tiny steps only)
        double[] w = {x[k0], x[k1], x[k2]}, d = {step[k0], step[k1], step[k2]}, o = new double[3];
        Se3.rotLeftCompose(w, 0, d, 0, o, 0, new double[27]);
        out[k0] = o[0]; out[k1] = o[1]; out[k2] = o[2];
    }

    // ------------------------------------------------------------------ full evaluation

    /**
     * Residuals (weighted) and, when {@code jac} is not null, the full Jacobian (m x fullSize,
     * row-major) at the full parameter vector.
     */
    public void evaluateFull(double[] full, double[] res, double[] jac) {
        if (pairs) { evaluatePairs(full, res, jac); return; }
        Frames f = new Frames(full, jac != null);
        if (jac != null) Arrays.fill(jac, 0);
        // one method per pose and per point: each is compiled on its own, where one loop body holding them all was
        // compiled again (on the stack) whenever a call took a branch the earlier ones had not
        for (int i = 0; i < rows.size(); i++) evaluatePose(f, full, i, res, jac);
    }

    /** What every pose of one evaluation shares: the geometry's model, the tool, the instrument, weights and scratch. */
    private final class Frames {
        final KinematicModel mdl;
        final double[] rft = new double[9], rib = new double[9], tib = new double[3], anchor;
        final double[][] tools = new double[points][];
        final Pose[] flangeTtools = new Pose[points];
        final double wp = 1 / sigmaPos, wr = 1 / sigmaRot;
        final double[] pbKin = new double[3], pb = new double[3], rbt = new double[9], rbf = new double[9], rib_rbf = new double[9],
                rpred = new double[9], rmeas = new double[9], err = new double[9], e = new double[3];
        final double[] dTheta, dp = new double[3], dw = new double[3], turn = new double[9], turned = new double[9];
        // A distance row's point is evaluated as a position (3 rows) in scratch space, then projected.
        final double[] res3, jac3;

        Frames(double[] full, boolean withJacobian) {
            mdl = model.withParameterValues(Arrays.copyOf(full, nGeo));
            if (sixD) Se3.rotExp(full[toolOff + points * 3], full[toolOff + points * 3 + 1], full[toolOff + points * 3 + 2], rft);
            else rft[0] = rft[4] = rft[8] = 1;
            for (int k = 0; k < points; k++) {
                tools[k] = new double[] {full[toolOff + 3 * k], full[toolOff + 3 * k + 1], full[toolOff + 3 * k + 2]};
                flangeTtools[k] = sixD ? poseOf(rft, tools[k]) : Pose.translation(tools[k][0], tools[k][1], tools[k][2]);
            }
            if (instrument) {
                Se3.rotExp(full[instOff + 3], full[instOff + 4], full[instOff + 5], rib);
                tib[0] = full[instOff]; tib[1] = full[instOff + 1]; tib[2] = full[instOff + 2];
            } else rib[0] = rib[4] = rib[8] = 1;
            anchor = distance ? new double[] {full[instOff], full[instOff + 1], full[instOff + 2]} : null;
            dTheta = new double[model.dof()];
            res3 = distance ? new double[3] : null;
            jac3 = distance && withJacobian ? new double[3 * nFull] : null;
        }
    }

    /** Residuals (and Jacobian rows) of pose {@code i}: the effects' joint offsets, then every measured point. */
    private void evaluatePose(Frames f, double[] full, int i, double[] res, double[] jac) {
        Measurement row = rows.get(i);
        double[] q = row.q(), qEff = q;
        double[][] dThetaDv = null;
        if (!effects.isEmpty()) {
            int dof = model.dof();
            double[] dTheta = f.dTheta;
            Arrays.fill(dTheta, 0);
            dThetaDv = new double[effects.size()][];
            for (int k = 0; k < effects.size(); k++) {
                int size = effStart[k + 1] - effStart[k];
                double[] v = Arrays.copyOfRange(full, effStart[k], effStart[k + 1]);
                dThetaDv[k] = jac == null ? null : new double[dof * size];
                effects.get(k).jointDelta(v, row, dTheta, dThetaDv[k]);
            }
            double[] theta = f.mdl.theta(q);
            for (int j = 0; j < dof; j++) theta[j] += dTheta[j];
            qEff = f.mdl.q(theta);
        }
        // Residuals only: forward kinematics once per pose is enough (several times cheaper than the Jacobian).
        if (jac == null) f.mdl.flange(qEff, ws, flange12);
        for (int pt = 0; pt < points; pt++) evaluatePoint(f, full, row, i, pt, qEff, dThetaDv, res, jac);
    }

    /** Residuals (and Jacobian rows) of point {@code pt} of pose {@code i} at the joint values {@code qEff}. */
    private void evaluatePoint(Frames f, double[] full, Measurement row, int i, int pt, double[] qEff, double[][] dThetaDv,
                               double[] res, double[] jac) {
        double[] tool = f.tools[pt], rft = f.rft, rib = f.rib, tib = f.tib;
        double[] pb = f.pb, rbt = f.rbt, rbf = f.rbf, dp = f.dp, dw = f.dw, pbKin = f.pbKin, jac3 = f.jac3;
        double wp = f.wp, wr = f.wr;
        double[] rr = distance ? f.res3 : res, jj = distance ? jac3 : jac;
        int r0 = distance ? 0 : i * rowsPerPose() + 3 * pt;
        if (jac3 != null) Arrays.fill(jac3, 0);
        if (jac != null) f.mdl.poseJacobian(qEff, f.flangeTtools[pt], ws, pose12, jg);
        else {
            for (int a = 0; a < 3; a++) {
                double f0 = flange12[4 * a], f1 = flange12[4 * a + 1], f2 = flange12[4 * a + 2];
                for (int b = 0; b < 3; b++) pose12[4 * a + b] = f0 * rft[b] + f1 * rft[3 + b] + f2 * rft[6 + b];
                pose12[4 * a + 3] = f0 * tool[0] + f1 * tool[1] + f2 * tool[2] + flange12[4 * a + 3];
            }
        }
        pb[0] = pose12[3]; pb[1] = pose12[7]; pb[2] = pose12[11];
        rbt[0] = pose12[0]; rbt[1] = pose12[1]; rbt[2] = pose12[2];
        rbt[3] = pose12[4]; rbt[4] = pose12[5]; rbt[5] = pose12[6];
        rbt[6] = pose12[8]; rbt[7] = pose12[9]; rbt[8] = pose12[10];
        Se3.rotMulT(rbt, rft, rbf); // R_bf = R_bt R_ftᵀ
        double[][] dpDv = null, dwDv = null;
        double[] dpDpoint = null;
        if (!effects.isEmpty()) {
            Arrays.fill(dp, 0);
            Arrays.fill(dw, 0);
            dpDpoint = new double[9];
            dpDv = new double[effects.size()][];
            if (sixD) dwDv = new double[effects.size()][];
            for (int k = 0; k < effects.size(); k++) {
                int size = effStart[k + 1] - effStart[k];
                double[] v = Arrays.copyOfRange(full, effStart[k], effStart[k + 1]);
                dpDv[k] = jac == null ? null : new double[3 * size];
                effects.get(k).positionDelta(v, row, pb.clone(), dp, dpDv[k], dpDpoint);
                if (sixD) {
                    dwDv[k] = jac == null ? null : new double[3 * size];
                    effects.get(k).rotationDelta(v, row, pb, dw, dwDv[k]);
                }
            }
            if (sixD && (dw[0] != 0 || dw[1] != 0 || dw[2] != 0)) { // the measured frame turned in base coordinates
                Se3.rotExp(dw[0], dw[1], dw[2], f.turn);
                Se3.rotMul(f.turn, rbt, f.turned);
                System.arraycopy(f.turned, 0, rbt, 0, 9);
            }
            System.arraycopy(pb, 0, pbKin, 0, 3);
            pb[0] += dp[0]; pb[1] += dp[1]; pb[2] += dp[2];
        }
        double px = rib[0] * pb[0] + rib[1] * pb[1] + rib[2] * pb[2] + tib[0];
        double py = rib[3] * pb[0] + rib[4] * pb[1] + rib[5] * pb[2] + tib[1];
        double pz = rib[6] * pb[0] + rib[7] * pb[1] + rib[8] * pb[2] + tib[2];
        double ux = 0, uy = 0, uz = 0;
        if (distance) {
            // d_pred = |p - a|; residual (d_pred - d) / σ; ∂d_pred/∂p = uᵀ, u the unit vector from the anchor.
            double[] anchor = f.anchor;
            double dx = px - anchor[0], dy = py - anchor[1], dz = pz - anchor[2];
            double n = Math.sqrt(dx * dx + dy * dy + dz * dz);
            if (n > 0) { ux = dx / n; uy = dy / n; uz = dz / n; }
            res[i] = (n - row.distance()) * wp;
        } else {
            var meas = row.point(pt);
            rr[r0] = (px - meas.x()) * wp;
            rr[r0 + 1] = (py - meas.y()) * wp;
            rr[r0 + 2] = (pz - meas.z()) * wp;
        }
        if (sixD) {
            Se3.rotMul(rib, rbt, f.rpred);
            double[] oq = row.orientation();
            Se3.rotFromQuaternion(oq[0], oq[1], oq[2], oq[3], f.rmeas);
            Se3.rotMulT(f.rpred, f.rmeas, f.err);
            Se3.rotLog(f.err, f.e, 0);
            rr[r0 + 3] = f.e[0] * wr;
            rr[r0 + 4] = f.e[1] * wr;
            rr[r0 + 5] = f.e[2] * wr;
        }
        if (jac == null) return;
        jacobianRows(f, pt, qEff, dThetaDv, dpDv, dwDv, dpDpoint, px, py, pz, jj, r0);
        if (distance) {
            for (int c = 0; c < nFull; c++)
                jac[i * nFull + c] = ux * jac3[c] + uy * jac3[nFull + c] + uz * jac3[2 * nFull + c];
            jac[i * nFull + instOff] = -ux * wp;
            jac[i * nFull + instOff + 1] = -uy * wp;
            jac[i * nFull + instOff + 2] = -uz * wp;
        }
    }

    /**
     * The Jacobian rows of one point from row {@code r0} of {@code jj}: geometry (the pose Jacobian {@link #jg}
     * just evaluated), tool, instrument and effects, the rotation rows made exact for the residual's logarithm.
     * ({@code px, py, pz}: the predicted point in instrument axes.)
     */
    private void jacobianRows(Frames f, int pt, double[] qEff, double[][] dThetaDv, double[][] dpDv, double[][] dwDv, double[] dpDpoint,
                              double px, double py, double pz, double[] jj, int r0) {
        double[] rib = f.rib, tib = f.tib;
        double wp = f.wp, wr = f.wr;
        // geometry: R_ib * (∂p_base/∂k), R_ib * (∂ω_base/∂k)
        for (int c = 0; c < nGeo; c++) {
            double a0 = jg[c], a1 = jg[nGeo + c], a2 = jg[2 * nGeo + c];
            jj[r0 * nFull + c] = (rib[0] * a0 + rib[1] * a1 + rib[2] * a2) * wp;
            jj[(r0 + 1) * nFull + c] = (rib[3] * a0 + rib[4] * a1 + rib[5] * a2) * wp;
            jj[(r0 + 2) * nFull + c] = (rib[6] * a0 + rib[7] * a1 + rib[8] * a2) * wp;
            if (sixD) {
                double b0 = jg[3 * nGeo + c], b1 = jg[4 * nGeo + c], b2 = jg[5 * nGeo + c];
                jj[(r0 + 3) * nFull + c] = (rib[0] * b0 + rib[1] * b1 + rib[2] * b2) * wr;
                jj[(r0 + 4) * nFull + c] = (rib[3] * b0 + rib[4] * b1 + rib[5] * b2) * wr;
                jj[(r0 + 5) * nFull + c] = (rib[6] * b0 + rib[7] * b1 + rib[8] * b2) * wr;
            }
        }
        // tool point: ∂p/∂t_ft = R_ib R_bf; tool rotation (6-D): ∂ε/∂φ = R_ib R_bf
        double[] rib_rbf = f.rib_rbf;
        Se3.rotMul(rib, f.rbf, rib_rbf);
        int tc = toolOff + 3 * pt;
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++) {
                jj[(r0 + a) * nFull + tc + b] = rib_rbf[3 * a + b] * wp;
                if (sixD) jj[(r0 + 3 + a) * nFull + toolOff + 3 + b] = rib_rbf[3 * a + b] * wr;
            }
        if (instrument) {
            double qx = px - tib[0], qy = py - tib[1], qz = pz - tib[2]; // R_ib p_base
            for (int a = 0; a < 3; a++) jj[(r0 + a) * nFull + instOff + a] = wp;
            // ∂(Exp(δ) v)/∂δ = -[v]x
            int c = instOff + 3;
            jj[r0 * nFull + c + 1] = qz * wp;       jj[r0 * nFull + c + 2] = -qy * wp;
            jj[(r0 + 1) * nFull + c] = -qz * wp;    jj[(r0 + 1) * nFull + c + 2] = qx * wp;
            jj[(r0 + 2) * nFull + c] = qy * wp;     jj[(r0 + 2) * nFull + c + 1] = -qx * wp;
            if (sixD) for (int a = 0; a < 3; a++) jj[(r0 + 3 + a) * nFull + c + a] = wr;
        }
        if (!effects.isEmpty()) {
            // A position term that depends on the point itself scales every column that moves the point.
            double[] g = dpDpoint;
            boolean any = false;
            for (double v : g) any |= v != 0;
            if (any) {
                double[] a = new double[9], t = new double[9], ribT = new double[9];
                for (int u = 0; u < 9; u++) a[u] = g[u] + (u % 4 == 0 ? 1 : 0);
                // base-frame columns were mapped by R_ib; in instrument axes I + G becomes R_ib (I + G) R_ibᵀ
                Se3.rotMul(rib, a, t);
                Se3.rotMulT(t, rib, ribT);
                int instStart = instrument ? instOff : nFull, instEnd = instrument ? instOff + 6 : nFull;
                double[] col = new double[3];
                for (int cIdx = 0; cIdx < effOff; cIdx++) {
                    if (cIdx >= instStart && cIdx < instEnd) continue;
                    for (int u = 0; u < 3; u++) col[u] = jj[(r0 + u) * nFull + cIdx];
                    for (int u = 0; u < 3; u++)
                        jj[(r0 + u) * nFull + cIdx] = ribT[3 * u] * col[0] + ribT[3 * u + 1] * col[1] + ribT[3 * u + 2] * col[2];
                }
            }
            effectColumns(f.mdl, qEff, f.flangeTtools[pt], f.pbKin, rib, dThetaDv, dpDv, dwDv, g, jj, r0, wp, wr);
        }
        if (sixD) {
            // Exact rotation rows: Log(Exp(ε) E) = e + J_l⁻¹(e) ε + O(ε²).
            double[] jinv = new double[9];
            Se3.rotLeftJacobianInverse(f.e, jinv);
            double[] col = new double[3];
            for (int cIdx = 0; cIdx < nFull; cIdx++) {
                for (int u = 0; u < 3; u++) col[u] = jj[(r0 + 3 + u) * nFull + cIdx];
                for (int u = 0; u < 3; u++)
                    jj[(r0 + 3 + u) * nFull + cIdx] = jinv[3 * u] * col[0] + jinv[3 * u + 1] * col[1] + jinv[3 * u + 2] * col[2];
            }
        }
    }

    /**
     * Distances between pairs of poses: the measured point at both poses (the position rows of
     * {@link #ends}, in metres, with their Jacobian), d_pred = |p_b − p_a|, residual
     * (d_pred − d) / σ and ∂d_pred/∂k = uᵀ (∂p_b/∂k − ∂p_a/∂k) with u the unit vector from a to b.
     */
    private void evaluatePairs(double[] full, double[] res, double[] jac) { evaluatePairs(full, res, jac, null, null); }

    /**
     * Distances between pairs of poses: each length's Jacobian split by its two ends (m x fullSize
     * each, row-major, weighted like the residuals): {@code jacFirst} = −uᵀ ∂p_a/∂k / σ at the first
     * pose, {@code jacSecond} = uᵀ ∂p_b/∂k / σ at the second; their sum is {@link #evaluateFull}'s
     * Jacobian. A parameter that takes its own value at each pose (an error that is a function of
     * the pose's joints) changes the length by the two ends' columns, each times its own value.
     */
    public void evaluatePairEnds(double[] full, double[] jacFirst, double[] jacSecond) {
        if (!pairs) throw new IllegalStateException("not distances between pairs of poses");
        evaluatePairs(full, new double[m], null, jacFirst, jacSecond);
    }

    private void evaluatePairs(double[] full, double[] res, double[] jac, double[] jacFirst, double[] jacSecond) {
        int n = rows.size();
        boolean any = jac != null || jacFirst != null;
        // ends' evaluateFull writes every residual and zero-fills the Jacobian first, so its buffers can be reused.
        double[] r2 = endRes, j2 = any ? ends.jFull : null;
        ends.evaluateFull(full, r2, j2);
        double wp = 1 / sigmaPos;
        for (int i = 0; i < n; i++) {
            int a = 6 * i, b = 6 * i + 3;
            double dx = r2[b] - r2[a], dy = r2[b + 1] - r2[a + 1], dz = r2[b + 2] - r2[a + 2];
            double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
            double ux = len > 0 ? dx / len : 0, uy = len > 0 ? dy / len : 0, uz = len > 0 ? dz / len : 0;
            res[i] = (len - rows.get(i).distance()) * wp;
            if (!any) continue;
            for (int c = 0; c < nFull; c++) {
                double pa = (ux * j2[a * nFull + c] + uy * j2[(a + 1) * nFull + c] + uz * j2[(a + 2) * nFull + c]) * wp;
                double pb = (ux * j2[b * nFull + c] + uy * j2[(b + 1) * nFull + c] + uz * j2[(b + 2) * nFull + c]) * wp;
                if (jac != null) jac[i * nFull + c] = pb - pa;
                if (jacFirst != null) { jacFirst[i * nFull + c] = -pa; jacSecond[i * nFull + c] = pb; }
            }
        }
    }

    private void effectColumns(KinematicModel mdl, double[] qEff, Pose flangeTtool, double[] pb, double[] rib,
                               double[][] dThetaDv, double[][] dpDv, double[][] dwDv, double[] dpDpoint, double[] jac, int r0,
                               double wp, double wr) {
        int dof = mdl.dof();
        double[][] jq = mdl.geometricJacobian(qEff); // flange origin velocity and angular velocity per q
        Pose f = mdl.flange(qEff);
        double ox = pb[0] - f.x(), oy = pb[1] - f.y(), oz = pb[2] - f.z();
        // ∂(point, rotation)/∂θ_j = J_q · C⁻¹ e_j, with the point moved from the flange origin.
        double[][] dth = new double[6][dof];
        for (int j = 0; j < dof; j++) {
            double[] cj = cInvCols[j];
            double vx = 0, vy = 0, vz = 0, wx = 0, wy = 0, wz = 0;
            for (int k = 0; k < dof; k++) {
                double c = cj[k];
                if (c == 0) continue;
                vx += jq[0][k] * c; vy += jq[1][k] * c; vz += jq[2][k] * c;
                wx += jq[3][k] * c; wy += jq[4][k] * c; wz += jq[5][k] * c;
            }
            dth[0][j] = vx + wy * oz - wz * oy;
            dth[1][j] = vy + wz * ox - wx * oz;
            dth[2][j] = vz + wx * oy - wy * ox;
            dth[3][j] = wx; dth[4][j] = wy; dth[5][j] = wz;
        }
        for (int k = 0; k < effects.size(); k++) {
            int size = effStart[k + 1] - effStart[k];
            for (int c = 0; c < size; c++) {
                double[] col = new double[6];
                for (int a = 0; a < 6; a++) {
                    double s = 0;
                    for (int j = 0; j < dof; j++) s += dth[a][j] * dThetaDv[k][j * size + c];
                    col[a] = s;
                }
                double c0 = col[0], c1 = col[1], c2 = col[2];
                for (int a = 0; a < 3; a++)
                    col[a] += dpDpoint[3 * a] * c0 + dpDpoint[3 * a + 1] * c1 + dpDpoint[3 * a + 2] * c2 + dpDv[k][a * size + c];
                if (dwDv != null) for (int a = 0; a < 3; a++) col[3 + a] += dwDv[k][a * size + c];
                int colIdx = effStart[k] + c;
                for (int a = 0; a < 3; a++) {
                    jac[(r0 + a) * nFull + colIdx] = (rib[3 * a] * col[0] + rib[3 * a + 1] * col[1] + rib[3 * a + 2] * col[2]) * wp;
                    if (sixD)
                        jac[(r0 + 3 + a) * nFull + colIdx] = (rib[3 * a] * col[3] + rib[3 * a + 1] * col[4] + rib[3 * a + 2] * col[5]) * wr;
                }
            }
        }
    }

    // ------------------------------------------------------------------ reading a solution

    /** The kinematic model at a full parameter vector. */
    public KinematicModel modelOf(double[] full) { return model.withParameterValues(Arrays.copyOf(full, nGeo)); }

    /** Measured point k (0-based) on the flange at a full parameter vector, flange coordinates, m. */
    public Vec3 toolPointOf(double[] full, int k) {
        return new Vec3(full[toolOff + 3 * k], full[toolOff + 3 * k + 1], full[toolOff + 3 * k + 2]);
    }

    /** The anchor (base frame, m) at a full parameter vector, or null without distance rows. */
    public Vec3 anchorOf(double[] full) {
        return distance && !pairs ? new Vec3(full[instOff], full[instOff + 1], full[instOff + 2]) : null;
    }

    /** flangeTtool at a full parameter vector (identity rotation for position-only data; the first point's). */
    public Pose toolOf(double[] full) {
        double[] t = {full[toolOff], full[toolOff + 1], full[toolOff + 2]};
        if (!sixD) return Pose.translation(t[0], t[1], t[2]);
        double[] r = new double[9];
        Se3.rotExp(full[toolOff + 3], full[toolOff + 4], full[toolOff + 5], r);
        return poseOf(r, t);
    }

    /** instrumentTbase at a full parameter vector (identity when measuring in the base frame). */
    public Pose instrumentOf(double[] full) {
        if (!instrument) return Pose.IDENTITY;
        double[] r = new double[9];
        Se3.rotExp(full[instOff + 3], full[instOff + 4], full[instOff + 5], r);
        return poseOf(r, new double[] {full[instOff], full[instOff + 1], full[instOff + 2]});
    }

    static Pose poseOf(double[] r, double[] t) {
        // Re-orthonormalise against rounding before the checked constructor.
        return Pose.of(orthonormal(r), t[0], t[1], t[2]);
    }

    private static double[] orthonormal(double[] r) {
        double[] x = {r[0], r[3], r[6]}, y = {r[1], r[4], r[7]};
        double nx = Math.sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
        for (int i = 0; i < 3; i++) x[i] /= nx;
        double d = x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
        for (int i = 0; i < 3; i++) y[i] -= d * x[i];
        double ny = Math.sqrt(y[0] * y[0] + y[1] * y[1] + y[2] * y[2]);
        for (int i = 0; i < 3; i++) y[i] /= ny;
        double[] z = {x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
        return new double[] {x[0], y[0], z[0], x[1], y[1], z[1], x[2], y[2], z[2]};
    }
}
