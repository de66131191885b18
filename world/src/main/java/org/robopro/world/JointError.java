package org.robopro.world;

/**
 * An error of one drive: the angle its gearbox output really has differs from what the
 * controller reports, q_out = q + delta(q, dir). Applied on the controller's (motor-side) axis
 * values before the coupling theta = C q, as a drive's own error is (a parallel-arm linkage
 * passes it on to the model angles it feeds). Joints 0-based; angles rad.
 */
public sealed interface JointError {
    /** The drive (0-based) this error acts on. */
    int joint();

    /**
     * The error of the drive's output angle, rad.
     *
     * @param q   all controller values (rad or m)
     * @param dir the sign of each drive's last motion before the pose was reached (+1, -1)
     */
    double delta(double[] q, int[] dir);

    /**
     * Transmission error of a reducer: a sum of harmonics of the output angle,
     * sum a_i sin(k_i q + phi_i). A single-stage gear gives k = 1 (eccentricity); a multi-stage or
     * cycloidal reducer adds the tooth-meshing and stage harmonics (k up to tens per output turn).
     */
    record Harmonics(int joint, int[] k, double[] amplitude, double[] phase) implements JointError {
        public Harmonics {
            k = k.clone();
            amplitude = amplitude.clone();
            phase = phase.clone();
            if (k.length != amplitude.length || k.length != phase.length) throw new IllegalArgumentException("harmonic arrays differ in length");
        }

        @Override public int[] k() { return k.clone(); }
        @Override public double[] amplitude() { return amplitude.clone(); }
        @Override public double[] phase() { return phase.clone(); }

        @Override public double delta(double[] q, int[] dir) {
            double s = 0;
            for (int i = 0; i < k.length; i++) s += amplitude[i] * Math.sin(k[i] * q[joint] + phase[i]);
            return s;
        }
    }

    /**
     * Lost motion (backlash) of width b: the driven output lags its motor-side encoder by half the
     * play in the direction of the last motion, q_out = q - (b/2) dir. (The motor has to take up
     * the play before the output moves, so after a positive move the output sits b/2 short of
     * where the encoder says; after a negative move b/2 beyond. See e.g. Nordin &amp; Gutman,
     * "Controlling mechanical systems with backlash: a survey", Automatica 38 (2002), §2.)
     */
    record LostMotion(int joint, double width) implements JointError {
        @Override public double delta(double[] q, int[] dir) { return -0.5 * width * dir[joint]; }
    }

    /** Gear-ratio error: the output turns (1 + eps) times what the controller assumes. */
    record Scale(int joint, double eps) implements JointError {
        @Override public double delta(double[] q, int[] dir) { return eps * q[joint]; }
    }

    /** Cross-coupling error: the output of {@code joint} also follows another drive, kappa q_source. */
    record Coupling(int joint, int source, double kappa) implements JointError {
        @Override public double delta(double[] q, int[] dir) { return kappa * q[source]; }
    }

    /**
     * Outside every catalogue family: a smooth local bump of the output angle around one joint
     * angle (a damaged stretch of a gear, a cable pulling over part of the range), not periodic:
     * a exp(-((q - centre)/width)^2).
     */
    record Bump(int joint, double centre, double width, double amplitude) implements JointError {
        @Override public double delta(double[] q, int[] dir) {
            double u = (q[joint] - centre) / width;
            return amplitude * Math.exp(-u * u);
        }
    }

    /**
     * Outside every catalogue family: an error depending on two joints at once (a hose package
     * dragging on an axis with a force that depends on another axis): a sin(q_joint) sin(q_other).
     */
    record TwoJoint(int joint, int other, double amplitude) implements JointError {
        @Override public double delta(double[] q, int[] dir) {
            return amplitude * Math.sin(q[joint]) * Math.sin(q[other]);
        }
    }
}
