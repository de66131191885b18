package org.robopro.calibration.identification;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.simulation.Campaign;
import org.robopro.calibration.simulation.CampaignSimulator;
import org.robopro.calibration.simulation.SimulationSettings;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.RobotLibrary;

class IdentificationProblemTest {
    /** A test effect: θ_j grows by scale_j · θ_j (joint-scale), and lengths by strain (position term). */
    static final class ScaleAndStrain implements EffectBlock {
        public String name() { return "test"; }
        public List<String> parameterNames() { return List.of("j2.scale", "j3.scale", "strain"); }
        public List<String> units() { return List.of("1", "1", "1"); }
        public double[] initialValues() { return new double[] {2e-4, -3e-4, 1e-4}; }
        public void jointDelta(double[] v, Measurement row, double[] dTheta, double[] dThetaDv) {
            int dof = dTheta.length;
            dTheta[1] += v[0] * row.q(1);
            dTheta[2] += v[1] * row.q(2);
            if (dThetaDv != null) {
                java.util.Arrays.fill(dThetaDv, 0);
                dThetaDv[1 * 3] = row.q(1);
                dThetaDv[2 * 3 + 1] = row.q(2);
            }
            if (dof < 3) throw new IllegalStateException();
        }
        @Override
        public void positionDelta(double[] v, Measurement row, double[] p, double[] dp, double[] dpDv, double[] dpDpoint) {
            for (int a = 0; a < 3; a++) dp[a] += v[2] * p[a];
            if (dpDpoint != null) for (int a = 0; a < 3; a++) dpDpoint[4 * a] += v[2];
            if (dpDv != null) {
                java.util.Arrays.fill(dpDv, 0);
                for (int a = 0; a < 3; a++) dpDv[a * 3 + 2] = p[a];
            }
        }
    }

    @ParameterizedTest
    @CsvSource({"false, false, false", "true, false, false", "false, true, false", "true, true, true", "false, false, true"})
    void evaluate_analyticJacobian_matchesCentralDifferences(boolean sixD, boolean baseFrame, boolean effects) {
        KinematicModel nominal = KinematicModel.build(RobotLibrary.load("irb2000"));
        Campaign c = CampaignSimulator.simulate(nominal, SimulationSettings.defaults().withPoses(12).withSixD(sixD)
                .withBaseFrame(baseFrame).withSeed(5));
        List<EffectBlock> eff = effects ? List.of(new ScaleAndStrain()) : List.of();
        Pose inst = baseFrame ? null : c.truth().instrumentTbase().times(Pose.rotX(0.01));
        Pose tool = c.truth().flangeTtool().times(Pose.translation(0.001, 0, 0)).times(Pose.rotZ(sixD ? 0.02 : 0));
        double[] start = IdentificationProblem.startVector(nominal, tool, sixD, inst, eff);
        IdentificationProblem p = new IdentificationProblem(nominal, c.measurements().rows(), sixD, !baseFrame, eff, start);
        p.setSigmas(1e-4, 2e-4);
        int m = p.residualCount(), n = p.parameterCount();
        double[] x = p.freeOf(start), r = new double[m], j = new double[m * n];
        p.evaluate(x, r, j);
        double[] rp = new double[m], rm = new double[m], xp = new double[n], xm = new double[n];
        double worst = 0;
        for (int col = 0; col < n; col++) {
            double h = p.unitsSi().get(col).equals("m") ? 1e-6 : 1e-7;
            double[] step = new double[n];
            step[col] = h;
            p.retract(x, step, xp);
            step[col] = -h;
            p.retract(x, step, xm);
            p.evaluate(xp, rp, null);
            p.evaluate(xm, rm, null);
            double scale = 0;
            for (int i = 0; i < m; i++) scale = Math.max(scale, Math.abs(j[i * n + col]));
            for (int i = 0; i < m; i++) {
                double fd = (rp[i] - rm[i]) / (2 * h);
                double err = Math.abs(fd - j[i * n + col]) / Math.max(scale, 1e-3);
                worst = Math.max(worst, err);
                if (err > 1e-5)
                    throw new AssertionError("column " + p.names().get(col) + " row " + i + ": analytic " + j[i * n + col] + ", FD " + fd);
            }
        }
        assertTrue(worst < 1e-5, "worst relative Jacobian error " + worst);
    }

    @ParameterizedTest
    @CsvSource({"3, false, false", "3, true, true", "2, false, true", "0, false, false", "0, true, true"})
    void evaluate_severalPointsAndDistances_analyticJacobianMatchesCentralDifferences(int points, boolean baseFrame, boolean effects) {
        // points 0: distance rows to an unknown anchor
        KinematicModel nominal = KinematicModel.build(RobotLibrary.load("irb2000"));
        Campaign c = CampaignSimulator.simulate(nominal, SimulationSettings.defaults().withPoses(12).withSeed(6));
        List<Measurement> rows = new java.util.ArrayList<>();
        for (Measurement m : c.measurements().rows()) {
            var p0 = m.position();
            List<org.robopro.models.Vec3> pts = new java.util.ArrayList<>();
            for (int k = 0; k < points; k++) pts.add(p0.plus(new org.robopro.models.Vec3(0.05 * k, -0.03 * k * k, 0.01)));
            rows.add(points == 0 ? Measurement.ofDistance(m.poseId(), m.q(), 1.2 + 0.01 * rows.size())
                    : Measurement.ofPoints(m.poseId(), m.q(), pts));
        }
        List<EffectBlock> eff = effects ? List.of(new ScaleAndStrain()) : List.of();
        boolean inst = !baseFrame && points > 0;
        List<org.robopro.models.Vec3> more = new java.util.ArrayList<>();
        for (int k = 1; k < points; k++) more.add(new org.robopro.models.Vec3(0.04 * k, 0.02, 0.09 + 0.01 * k));
        double[] start = IdentificationProblem.startVector(nominal, Pose.translation(0.01, -0.02, 0.1), more, false,
                inst ? c.truth().instrumentTbase().times(Pose.rotX(0.01)) : null,
                points == 0 ? new org.robopro.models.Vec3(1.5, -0.3, 0.2) : null, eff);
        IdentificationProblem p = new IdentificationProblem(nominal, rows, false, inst, eff, start);
        assertEquals(points == 0 ? 1 : 3 * points, p.rowsPerPose());
        assertEquals(rows.size() * p.rowsPerPose(), p.residualCount());
        p.setSigmas(1e-4, 2e-4);
        int m = p.residualCount(), n = p.parameterCount();
        double[] x = p.freeOf(start), r = new double[m], j = new double[m * n];
        p.evaluate(x, r, j);
        double[] rp = new double[m], rm = new double[m], xp = new double[n], xm = new double[n];
        for (int col = 0; col < n; col++) {
            double h = p.unitsSi().get(col).equals("m") ? 1e-6 : 1e-7;
            double[] step = new double[n];
            step[col] = h;
            p.retract(x, step, xp);
            step[col] = -h;
            p.retract(x, step, xm);
            p.evaluate(xp, rp, null);
            p.evaluate(xm, rm, null);
            double scale = 0;
            for (int i = 0; i < m; i++) scale = Math.max(scale, Math.abs(j[i * n + col]));
            for (int i = 0; i < m; i++) {
                double fd = (rp[i] - rm[i]) / (2 * h);
                double err = Math.abs(fd - j[i * n + col]) / Math.max(scale, 1e-3);
                if (err > 1e-5)
                    throw new AssertionError("column " + p.names().get(col) + " row " + i + ": analytic " + j[i * n + col] + ", FD " + fd);
            }
        }
        // Residuals without the Jacobian are the same numbers.
        double[] r2 = new double[m];
        p.evaluate(x, r2, null);
        for (int i = 0; i < m; i++) assertEquals(r[i], r2[i], 1e-9 * Math.max(1, Math.abs(r[i])));
    }

    @ParameterizedTest
    @CsvSource({"false", "true"})
    void evaluateFull_atTruth_leavesOnlyNoise(boolean sixD) {
        KinematicModel nominal = KinematicModel.build(RobotLibrary.load("irb2400"));
        Campaign c = CampaignSimulator.simulate(nominal, SimulationSettings.defaults().withPoses(30).withSixD(sixD)
                .withSigma(0).withSigmaRot(0).withSeed(2));
        double[] start = IdentificationProblem.startVector(c.truth().model(), c.truth().flangeTtool(), sixD,
                c.truth().instrumentTbase(), List.of());
        IdentificationProblem p = new IdentificationProblem(nominal, c.measurements().rows(), sixD, true, List.of(), start);
        p.setSigmas(1, 1);
        double[] r = new double[p.residualCount()];
        p.evaluateFull(start, r, null);
        for (double v : r) assertEquals(0, v, 1e-9);
    }

    /**
     * The model family holds an independent robot's geometry: a robot of the world simulator
     * (product of exponentials from perturbed joint axes, its own code), measured without noise,
     * is calibrated down to rounding, and the calibrated model predicts the world's validation
     * poses to rounding. A parameterisation that missed an axis tilt, a zero or a link offset
     * would leave micrometres here.
     */
    @ParameterizedTest
    @CsvSource({"irb2000, false, 41", "irb2400, false, 42", "puma560, false, 43", "irb2000, true, 44"})
    void calibrate_noiseFreeWorldRobot_fitsToRounding(String robot, boolean sixD, long seed) {
        KinematicModel nominal = KinematicModel.build(RobotLibrary.load(robot));
        org.robopro.calibration.WorldCampaigns.Sim c = org.robopro.calibration.WorldCampaigns.geometric(nominal.description(), seed, false,
                plan -> plan.withPoses(60, 40).withSigma(0).withSigmaRot(0).withSixD(sixD).withDirColumns(false).withConditionColumns(false));
        CalibrationResult r = Calibrator.calibrate(nominal, c.train(), c.validation());
        double model = org.robopro.calibration.WorldCampaigns.modelErrorRms(c, r);
        System.out.printf("%s%s: noise-free world robot, train %.3g validate %.3g m, model vs truth %.3g m, angle %.3g rad%n", robot,
                sixD ? " 6-D" : "", r.trainRmsM(), r.validateRmsM(), model, org.robopro.calibration.WorldCampaigns.modelAngleRms(c, r));
        // The file holds 1e-5 mm: rounding of the written file, not of the model.
        assertTrue(r.trainRmsM() < 1e-7 && r.validateRmsM() < 1e-7, r.trainRmsM() + " / " + r.validateRmsM());
        assertTrue(model < 1e-7, "calibrated model vs the world's truth " + model);
        if (sixD) assertTrue(org.robopro.calibration.WorldCampaigns.modelAngleRms(c, r) < 1e-8, "orientation");
    }
}
