package org.robopro.kinematics;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import org.ejml.data.DMatrixRMaj;
import org.ejml.dense.row.CommonOps_DDRM;
import org.junit.jupiter.api.Test;
import org.robopro.models.RobotDescription;

/** The allocation-free fast paths checked against simple references (STYLE: fast path vs reference). */
class IkSolverTest {

    /**
     * Slow reference of solveAll for an exact closed form: closed-form angles, inverse coupling,
     * turn variants by list expansion, configuration data by {@link InverseKinematics#confOf}
     * (forward kinematics of each solution), limits by the model, within-limits first.
     */
    private static List<double[]> referenceSolutions(KinematicModel m, InverseKinematics ik, double[] target12) {
        double[][] th = new double[8][6];
        int count = ik.closedFormThetas(target12, th);
        double[][] c = m.couplingMatrix();
        List<double[]> out = new ArrayList<>();
        for (int s = 0; s < count; s++) {
            double[] q0 = m.q(th[s]);
            List<double[]> acc = new ArrayList<>();
            double[] w = q0.clone();
            boolean[] whole = new boolean[6];
            for (int j = 0; j < 6; j++) {
                whole[j] = true;
                for (int i = 0; i < 6; i++) if (c[i][j] != Math.rint(c[i][j])) whole[j] = false;
                if (whole[j]) w[j] = Math.IEEEremainder(w[j], 2 * Math.PI);
                if (w[j] <= -Math.PI) w[j] += 2 * Math.PI;
            }
            acc.add(w);
            boolean none = false;
            for (int j = 0; j < 6 && !none; j++) {
                if (!whole[j]) continue;
                List<double[]> next = new ArrayList<>();
                for (double[] a : acc)
                    for (int k = -2; k <= 2; k++) {
                        double v = a[j] + 2 * Math.PI * k;
                        if (v >= m.qMin(j) - 1e-9 && v <= m.qMax(j) + 1e-9) {
                            double[] b = a.clone();
                            b[j] = v;
                            next.add(b);
                        }
                    }
                if (next.isEmpty()) none = true;
                else acc = next;
            }
            if (none) acc = List.of(w);
            for (double[] q : acc) {
                boolean dup = false;
                for (double[] o : out) {
                    double d = 0;
                    for (int i = 0; i < 6; i++) d = Math.max(d, Math.abs(o[i] - q[i]));
                    if (d < 1e-7) dup = true;
                }
                if (!dup) out.add(q);
            }
        }
        List<double[]> sorted = new ArrayList<>();
        for (double[] q : out) if (m.withinLimits(q)) sorted.add(q);
        for (double[] q : out) if (!m.withinLimits(q)) sorted.add(q);
        return sorted;
    }

    /** |det| of the scaled geometric Jacobian by EJML: the reference for the manipulability. */
    private static double referenceManipulability(KinematicModel m, double[] q) {
        double[][] j = m.geometricJacobian(q);
        double len = m.characteristicLength();
        for (int r = 0; r < 3; r++) for (int c = 0; c < 6; c++) j[r][c] /= len;
        return Math.abs(CommonOps_DDRM.det(new DMatrixRMaj(j)));
    }

    @Test
    void solveAll_shippedRobots_matchesSlowReferenceInOrderConfAndLimits() {
        for (RobotDescription d : ReferenceRobots.all()) {
            KinematicModel m = KinematicModel.build(d);
            InverseKinematics ik = InverseKinematics.of(m);
            IkSolver solver = ik.newSolver();
            double[] target = new double[12], q = new double[6];
            int total = 0;
            for (double[] q0 : m.randomConfigurations(200, 31)) {
                m.flange(q0, m.newWorkspace(), target);
                List<double[]> ref = referenceSolutions(m, ik, target);
                int count = solver.solveAll(target);
                assertEquals(ref.size(), count, d.name());
                for (int i = 0; i < count; i++) {
                    solver.q(i, q);
                    assertArrayEquals(ref.get(i), q, 1e-12, d.name() + " solution " + i);
                    assertEquals(ik.confOf(q), new ConfData(solver.cf1(i), solver.cf4(i), solver.cf6(i), solver.cfx(i)),
                            d.name() + " conf of " + Arrays.toString(q));
                    assertEquals(m.withinLimits(q), solver.withinLimits(i));
                    double man = referenceManipulability(m, q);
                    assertEquals(man, solver.manipulability(i), 1e-9 * Math.max(1, man), d.name() + " manipulability");
                }
                total += count;
            }
            assertTrue(total >= 200, d.name() + ": " + total + " solutions");
        }
    }

    @Test
    void solveAll_convenienceApi_sameAsSolver() {
        KinematicModel m = KinematicModel.build(ReferenceRobots.irb2000());
        InverseKinematics ik = InverseKinematics.of(m);
        IkSolver solver = ik.newSolver();
        double[] target = new double[12];
        for (double[] q0 : m.randomConfigurations(20, 32)) {
            m.flange(q0, m.newWorkspace(), target);
            List<IkSolution> api = ik.solveAll(Se3.toPose(target));
            assertEquals(solver.solveAll(target), api.size());
            for (int i = 0; i < api.size(); i++) {
                IkSolution s = solver.solution(i);
                assertArrayEquals(s.q(), api.get(i).q(), 1e-9);
                assertEquals(s.conf(), api.get(i).conf());
                assertEquals(s.withinLimits(), api.get(i).withinLimits());
            }
        }
    }

    @Test
    void manipulability_randomConfigurations_matchesEjmlDeterminantAndVanishesAtSingularities() {
        KinematicModel m = KinematicModel.build(ReferenceRobots.irb2400());
        InverseKinematics ik = InverseKinematics.of(m);
        for (double[] q : m.randomConfigurations(50, 33)) {
            double ref = referenceManipulability(m, q);
            assertEquals(ref, ik.manipulability(q), 1e-12 * Math.max(1, ref));
        }
        double[] q = {0.1, 0.2, 0.1, 0.3, 0, 0.4}; // axis 5 at zero: axes 4 and 6 aligned
        assertTrue(ik.manipulability(q) < 1e-12, "wrist singular: " + ik.manipulability(q));
        assertTrue(ik.singularityMeasure(q) < 1e-9, "the SVD measure agrees");
        q[4] = 0.8;
        assertTrue(ik.manipulability(q) > 1e-3, "bent wrist: " + ik.manipulability(q));
    }

    @Test
    void solveNumerical_nearbySeed_convergesInFewIterationsAndMatchesConvenienceApi() {
        KinematicModel m = KinematicModel.build(ReferenceRobots.irb2000());
        InverseKinematics ik = InverseKinematics.of(m);
        IkSolver solver = ik.newSolver();
        Random rnd = new Random(34);
        double[] target = new double[12], q = new double[6];
        int maxIterations = 0;
        for (double[] q0 : m.randomConfigurations(30, 35)) {
            m.flange(q0, m.newWorkspace(), target);
            double[] seed = q0.clone();
            for (int i = 0; i < 6; i++) seed[i] += 0.05 * rnd.nextGaussian();
            if (!m.withinLimits(seed)) continue;
            assertTrue(solver.solveNumerical(target, seed, q), "from " + Arrays.toString(seed));
            assertTrue(solver.positionError() < 1e-9 && solver.orientationError() < 1e-9);
            maxIterations = Math.max(maxIterations, solver.iterations());
            Pose reached = m.flange(q), wanted = Se3.toPose(target);
            assertTrue(reached.distanceTo(wanted) < 1e-9 && reached.angleTo(wanted) < 1e-9);
            InverseKinematics.NumericalOutcome o = ik.solveNumerical(wanted, seed);
            assertTrue(o.diagnostics().converged());
            assertArrayEquals(q, o.diagnostics().q(), 1e-12);
            assertEquals(solver.iterations(), o.diagnostics().iterations());
        }
        assertTrue(maxIterations <= 8, "Levenberg-Marquardt from a 0.05 rad seed took " + maxIterations + " iterations");
    }

    @Test
    void solveNear_calibratedIrb2000_sameAsExhaustiveReference() {
        KinematicModel nominal = KinematicModel.build(ReferenceRobots.irb2000());
        Random rnd = new Random(36);
        double[] p = nominal.parameterValues();
        for (int i = 0; i < p.length; i++) p[i] += 2e-3 * rnd.nextGaussian();
        KinematicModel cal = KinematicModel.build(nominal.withParameterValues(p).toDescription());
        InverseKinematics ik = InverseKinematics.of(cal);
        IkSolver solver = ik.newSolver();
        double[] target = new double[12], q = new double[6];
        int compared = 0;
        for (double[] q0 : cal.randomConfigurations(25, 37)) {
            cal.flange(q0, cal.newWorkspace(), target);
            double[] seed = q0.clone();
            for (int i = 0; i < 6; i++) seed[i] += 0.5 * rnd.nextGaussian(); // often nearer another branch
            // reference: every refined branch with every turn variant, plus DLS from the seed
            List<IkSolution> candidates = new ArrayList<>(ik.solveAll(Se3.toPose(target)));
            ik.solveNumerical(Se3.toPose(target), seed).solution().ifPresent(candidates::add);
            double[] best = null;
            double bestD = Double.POSITIVE_INFINITY;
            for (IkSolution s : candidates) {
                if (!s.withinLimits()) continue;
                double d = 0;
                for (int i = 0; i < 6; i++) d += (s.q()[i] - seed[i]) * (s.q()[i] - seed[i]);
                if (d < bestD) { bestD = d; best = s.q(); }
            }
            boolean found = solver.solveNear(target, seed, q);
            assertEquals(best != null, found);
            if (found) {
                assertArrayEquals(best, q, 1e-8, "nearest to " + Arrays.toString(seed));
                compared++;
            }
        }
        assertTrue(compared >= 20, "compared " + compared);
    }
}
